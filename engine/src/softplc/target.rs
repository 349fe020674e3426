//! The soft PLC as a ladder target: IEC bits (`%IX0.0`, `%QX0.0`,
//! `%MX0.0`) or variables by name, in-line boxes, functions and blocks on
//! words, compiled to IEC Instruction List and checked by loading it.

use super::Program;
use crate::ladder::compile::{Mapped, Options};
use crate::ladder::decompile::TextError;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::machine_target::{LadderTarget, MachineCompiler};
use crate::ladder::net::RungLogic;
use crate::ladder::target::{Capabilities, ElementError, Role, ALL_COILS, ALL_CONTACTS};
use crate::ladder::variables::Variable;
use crate::plc::problems;
use crate::MachineId;

/// The soft PLC's ladder target.
pub struct SoftTarget;

impl LadderTarget for SoftTarget {
    fn id(&self) -> MachineId {
        MachineId::SoftPlc
    }

    fn product_name(&self) -> &'static str {
        "Soft PLC (IEC 61131-3)"
    }

    fn share_code(&self) -> u8 {
        4
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: true,
            pulse_outputs: true,
            timer_counter_coils: false,
            data_boxes: false,
            word_boxes: true,
            devices: "%IX0.0, %QX0.0, %MX0.0 or a name",
            starter: ["%IX0.0", "%IX0.1", "%QX0.0"],
        }
    }

    fn canonical(&self, device: &str, role: Role) -> Result<String, ElementError> {
        let device = device.trim();
        let name = soft_canonical(device).ok_or_else(|| ElementError::UnknownDevice {
            machine: MachineId::SoftPlc,
            device: device.to_string(),
        })?;
        if role == Role::Write && name.starts_with("%I") {
            return Err(ElementError::InputAsCoil(name));
        }
        Ok(name)
    }

    fn devices_help(&self) -> &'static str {
        "soft-plc ladders name bits as %IX0.0, %QX0.0, %MX0.0 or a variable name"
    }

    /// Any name is a BOOL: helpers of its own, `_h0` popped first.
    fn spare_bits(&self) -> Vec<String> {
        (0..crate::limits::MAX_SOFT_HELPERS)
            .rev()
            .map(|n| format!("_h{n}"))
            .collect()
    }
}

impl MachineCompiler for SoftTarget {
    /// The IL, then what the soft PLC says of it when it loads it (a type
    /// that does not fit), each problem at its cell.
    fn compile(
        &self,
        rungs: &[RungLogic],
        variables: &[Variable],
        _options: Options,
    ) -> Result<Mapped, Vec<LadderError>> {
        // The project's own ST blocks (`ladder::user_blocks`) follow the
        // ladder's steps, so its boxes call them; line numbers of the
        // ladder's part stay as they were.
        let own = crate::ladder::user_blocks::code();
        let mut mapped = crate::ladder::compile::il::compile_mapped(rungs, variables, &|text| {
            Program::load(&format!("{text}{own}"))
                .err()
                .map_or_else(Vec::new, |errors| {
                    errors
                        .into_iter()
                        .map(|e| (e.line, e.error.to_string()))
                        .collect()
                })
        })?;
        mapped.text.push_str(&own);
        Ok(mapped)
    }

    fn decompile_text(&self, text: &str, _options: Options) -> Result<Ladder, TextError> {
        let p = Program::load(text).map_err(|e| TextError::Program(problems(e)))?;
        crate::ladder::decompile::il_ladder(&p).map_err(TextError::Decompile)
    }

    /// Its steps follow its declarations.
    fn code_start(&self, text: &str) -> usize {
        text.lines()
            .position(|l| l.trim().eq_ignore_ascii_case("END_VAR"))
            .map_or(0, |i| i + 1)
    }

    /// Every line but comments is a step.
    fn is_step(&self, line: &str) -> bool {
        let line = line.trim();
        !line.is_empty() && !line.starts_with("(*")
    }

    /// Its program has no END step.
    fn end_steps(&self) -> usize {
        0
    }
}

/// A soft PLC bit: an address (`%IX0.0`; `%I0.0` is written `%IX0.0`)
/// or a variable's name.
fn soft_canonical(device: &str) -> Option<String> {
    use crate::iec::{Address, Size};
    if device.starts_with('%') {
        let a = Address::parse(device).ok()?;
        return (a.size == Size::Bit).then(|| a.to_string());
    }
    crate::iec::is_identifier(device).then(|| device.to_string())
}
