//! The Arduino PLC sketch as a ladder target: X000-X005 and Y000-Y005,
//! NO/NC contacts, no timers, compiled by the block-stack compiler.

use super::isa::{io_name, parse_io};
use super::{Chip, Program};
use crate::ladder::compile::stack::{self, Dialect};
use crate::ladder::compile::{Mapped, Options};
use crate::ladder::decompile::TextError;
use crate::ladder::element::ContactKind;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::machine_target::{DevicePools, LadderTarget, LocatedError, MachineCompiler};
use crate::ladder::net::RungLogic;
use crate::ladder::target::{Capabilities, ElementError, LackReason, Role, ALL_COILS};
use crate::ladder::variables::Variable;
use crate::plc::problems;
use crate::MachineId;

/// The Arduino PLC's ladder target.
pub struct ArduinoTarget;

impl LadderTarget for ArduinoTarget {
    fn id(&self) -> MachineId {
        MachineId::ArduinoPlc
    }

    fn product_name(&self) -> &'static str {
        "Arduino PLC"
    }

    fn share_code(&self) -> u8 {
        3
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            contacts: &[ContactKind::No, ContactKind::Nc],
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            word_boxes: false,
            devices: "X000-X005, Y000-Y005",
            starter: ["X000", "X001", "Y000"],
        }
    }

    fn canonical(&self, device: &str, role: Role) -> Result<String, ElementError> {
        let device = device.trim();
        let n = parse_io(device).ok_or_else(|| ElementError::UnknownDevice {
            machine: MachineId::ArduinoPlc,
            device: device.to_string(),
        })?;
        if role == Role::Write && n < 8 {
            return Err(ElementError::InputAsCoil(io_name(n)));
        }
        Ok(io_name(n))
    }

    fn lacks_inline_boxes(&self) -> LackReason {
        LackReason::ArduinoNoTimers
    }

    fn lacks_timer_counter_coils(&self) -> LackReason {
        LackReason::ArduinoNoTimersOrCounters
    }

    fn devices_help(&self) -> &'static str {
        "arduino-plc has X000-X005 and Y000-Y005"
    }

    fn located_bit(&self, area: char, n: u32) -> Result<String, LocatedError> {
        match area {
            'I' => Ok(format!("X{n:03}")),
            'Q' => Ok(format!("Y{n:03}")),
            'M' => Err(LocatedError::NoRelays),
            _ => Err(LocatedError::NotThere),
        }
    }

    fn pools(&self) -> DevicePools {
        DevicePools {
            inputs: DevicePools::range("X", 3, 0..6),
            outputs: DevicePools::range("Y", 3, 0..6),
            ..DevicePools::default()
        }
    }
}

impl MachineCompiler for ArduinoTarget {
    fn compile(
        &self,
        rungs: &[RungLogic],
        _variables: &[Variable],
        _options: Options,
    ) -> Result<Mapped, Vec<LadderError>> {
        stack::compile_mapped(rungs, self.id(), Dialect::Arduino)
    }

    fn decompile_text(&self, text: &str, _options: Options) -> Result<Ladder, TextError> {
        let p = Program::parse(text, Chip::Atmega328.capacity())
            .map_err(|e| TextError::Program(problems(e)))?;
        super::decompile::decompile(&p).map_err(TextError::Decompile)
    }
}
