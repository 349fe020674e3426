//! MINASEC-U as a ladder target: four contact and coil kinds on its
//! X/Y/M/T/C devices, the wired T0/T1/C0 that take no latch, compiled by
//! the accumulator compiler into its 32 steps.

use super::isa::Device;
use super::{Address, Program};
use crate::ladder::compile::accumulator::{self, Dialect};
use crate::ladder::compile::{Mapped, Options};
use crate::ladder::decompile::TextError;
use crate::ladder::element::CoilKind;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::machine_target::{DevicePools, LadderTarget, LocatedError, MachineCompiler};
use crate::ladder::net::RungLogic;
use crate::ladder::target::Latch;
use crate::ladder::target::{
    Capabilities, ElementError, LackReason, Role, ALL_COILS, ALL_CONTACTS,
};
use crate::ladder::variables::Variable;
use crate::plc::problems;
use crate::MachineId;

/// MINASEC-U's ladder target.
pub struct MinasecTarget;

impl LadderTarget for MinasecTarget {
    fn id(&self) -> MachineId {
        MachineId::MinasecU
    }

    fn product_name(&self) -> &'static str {
        "MINASEC-U"
    }

    fn share_code(&self) -> u8 {
        0
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            word_boxes: false,
            devices: "X00-X07, Y00-Y07, M00-M07, M10-M13, T0, T1, C0, C0R",
            starter: ["X00", "X01", "Y00"],
        }
    }

    fn canonical(&self, device: &str, role: Role) -> Result<String, ElementError> {
        let a = Address::parse(device.trim()).map_err(ElementError::Minasec)?;
        if role == Role::Write && matches!(a.device(), Device::Input(_)) {
            return Err(ElementError::InputAsCoil(a.to_string()));
        }
        Ok(a.to_string())
    }

    fn check_coil(&self, kind: CoilKind, device: &str) -> Result<(), ElementError> {
        minasec_coil(kind, device)
    }

    fn lacks_timer_counter_coils(&self) -> LackReason {
        LackReason::MinasecPanelTimers
    }

    fn located_bit(&self, area: char, n: u32) -> Result<String, LocatedError> {
        match area {
            'I' => Ok(format!("X{n:02}")),
            'Q' => Ok(format!("Y{n:02}")),
            // Its relays are M00-M07 and M10-M13.
            'M' => Ok(format!("M{}{}", n / 8, n % 8)),
            _ => Err(LocatedError::NotThere),
        }
    }

    fn pools(&self) -> DevicePools {
        let range = DevicePools::range;
        DevicePools {
            inputs: range("X", 2, 0..8),
            outputs: range("Y", 2, 0..8),
            relays: [range("M", 2, 0..8), range("M1", 1, 0..4)].concat(),
            timers: vec!["T0".into(), "T1".into()],
            counters: vec!["C0".into()],
        }
    }

    fn steps_clocks(&self) -> bool {
        true
    }
}

impl MachineCompiler for MinasecTarget {
    fn compile(
        &self,
        rungs: &[RungLogic],
        _variables: &[Variable],
        options: Options,
    ) -> Result<Mapped, Vec<LadderError>> {
        accumulator::compile_mapped(rungs, self.id(), Dialect::Minasec, options)
    }

    fn decompile_text(&self, text: &str, _options: Options) -> Result<Ladder, TextError> {
        let p = Program::parse(text).map_err(|e| TextError::Program(problems(e)))?;
        super::decompile::decompile(&p).map_err(TextError::Decompile)
    }

    /// Its listing has no END step: the program counter wraps.
    fn end_steps(&self) -> usize {
        0
    }
}

/// MINASEC-U's T0 / T1 / C0 / C0R are wired, not latched: a set or reset
/// coil on them has no meaning, except reset on C0, which is `ST C0R`.
fn minasec_coil(kind: CoilKind, device: &str) -> Result<(), ElementError> {
    let special = matches!(device, "T0" | "T1" | "C0" | "C0R");
    let latch = match kind {
        CoilKind::Set => Latch::Set,
        CoilKind::Reset if device != "C0" => Latch::Reset,
        _ => return Ok(()),
    };
    if special {
        return Err(ElementError::MinasecLatch {
            kind: latch,
            device: device.to_string(),
        });
    }
    Ok(())
}
