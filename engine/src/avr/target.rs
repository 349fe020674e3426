//! The AVR PLC as a ladder target: register bits R0.0-R31.7, in-line
//! NOT / edge / TON-TOF-TP boxes counted in scans, compiled by the
//! accumulator compiler; it has no RUN switch.

use super::{parse_register_bit, Program};
use crate::ladder::compile::accumulator::{self, Dialect};
use crate::ladder::compile::{Mapped, Options};
use crate::ladder::decompile::TextError;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::machine_target::{DevicePools, LadderTarget, LocatedError, MachineCompiler};
use crate::ladder::net::RungLogic;
use crate::ladder::target::{Capabilities, ElementError, Role, ALL_COILS, ALL_CONTACTS};
use crate::ladder::variables::Variable;
use crate::plc::problems;
use crate::MachineId;

/// The registers a located input, output or relay stands for (see
/// `located_bit`).
const INPUTS: std::ops::Range<u8> = 4..5;
const OUTPUTS: std::ops::Range<u8> = 5..6;
const RELAYS: std::ops::Range<u8> = 6..16;

/// The AVR PLC's ladder target.
pub struct AvrTarget;

impl LadderTarget for AvrTarget {
    fn id(&self) -> MachineId {
        MachineId::AvrPlc
    }

    fn product_name(&self) -> &'static str {
        "AVR PLC"
    }

    fn share_code(&self) -> u8 {
        2
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: true,
            pulse_outputs: false,
            timer_counter_coils: false,
            data_boxes: false,
            word_boxes: false,
            devices: "R0.0-R31.7",
            starter: ["R0.0", "R0.1", "R1.0"],
        }
    }

    fn canonical(&self, device: &str, _role: Role) -> Result<String, ElementError> {
        let device = device.trim();
        parse_register_bit(device)
            .map(|b| b.to_string())
            .ok_or_else(|| ElementError::UnknownDevice {
                machine: MachineId::AvrPlc,
                device: device.to_string(),
            })
    }

    fn devices_help(&self) -> &'static str {
        "avr-plc ladders name bits R0.0-R31.7"
    }

    /// It has no fixed inputs or outputs (any register bit may be
    /// either); Hashigo follows the seed's own program, inputs in R4 and
    /// coils in R5, relays after them, and leaves R16-R25 to the
    /// compiler's temporaries: `%IX0.n` → R4.n, `%QX0.n` → R5.n,
    /// `%MXb.n` → R(6+b).n up to R15.7.
    fn located_bit(&self, area: char, n: u32) -> Result<String, LocatedError> {
        let (registers, what) = match area {
            'I' => (INPUTS, "inputs"),
            'Q' => (OUTPUTS, "outputs"),
            'M' => (RELAYS, "relays"),
            _ => return Err(LocatedError::NotThere),
        };
        if n >= registers.len() as u32 * 8 {
            let (first, last) = (registers.start, registers.end - 1);
            return Err(LocatedError::Past { what, first, last });
        }
        Ok(format!("R{}.{}", registers.start as u32 + n / 8, n % 8))
    }

    /// [`Self::located_bit`]'s registers; timers are named in-line boxes
    /// (an instance keeps its name), and there are no counters.
    fn pools(&self) -> DevicePools {
        let bits = |registers: std::ops::Range<u8>| -> Vec<String> {
            registers
                .flat_map(|r| (0..8).map(move |b| format!("R{r}.{b}")))
                .collect()
        };
        DevicePools {
            inputs: bits(INPUTS),
            outputs: bits(OUTPUTS),
            relays: bits(RELAYS),
            ..DevicePools::default()
        }
    }

    fn scan_in_program(&self) -> bool {
        true
    }

    /// It runs from power-up: no RUN switch.
    fn stoppable(&self) -> bool {
        false
    }
}

impl MachineCompiler for AvrTarget {
    fn compile(
        &self,
        rungs: &[RungLogic],
        _variables: &[Variable],
        options: Options,
    ) -> Result<Mapped, Vec<LadderError>> {
        accumulator::compile_mapped(rungs, self.id(), Dialect::Avr, options)
    }

    fn decompile_text(&self, text: &str, options: Options) -> Result<Ladder, TextError> {
        let scan_ms = options.avr_scan_ms;
        let p = Program::parse(text, i64::from(scan_ms))
            .map_err(|e| TextError::Program(problems(e)))?;
        super::decompile::decompile(&p, scan_ms).map_err(TextError::Decompile)
    }

    /// Its steps are the `.db` lines of the assembler source.
    fn is_step(&self, line: &str) -> bool {
        line.trim().starts_with(".db")
    }
}
