//! PLC-IO86A as a ladder target: FX-style X/Y/M/S/T/C/D devices, PLS/PLF,
//! `OUT T K` / `OUT C K` and the data boxes, compiled by the block-stack
//! compiler.

use super::isa::{parse_bit, parse_word, K_MAX};
use super::{Bit, Program, Word};
use crate::ladder::compile::stack::{self, Dialect};
use crate::ladder::compile::{Mapped, Options};
use crate::ladder::decompile::TextError;
use crate::ladder::element::CoilKind;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::machine_target::{DevicePools, LadderTarget, LocatedError, MachineCompiler};
use crate::ladder::net::RungLogic;
use crate::ladder::target::Drivable;
use crate::ladder::target::{Capabilities, ElementError, Role, ALL_COILS, ALL_CONTACTS};
use crate::ladder::variables::Variable;
use crate::plc::problems;
use crate::MachineId;

/// PLC-IO86A's ladder target.
pub struct Io86aTarget;

impl LadderTarget for Io86aTarget {
    fn id(&self) -> MachineId {
        MachineId::Io86a
    }

    fn product_name(&self) -> &'static str {
        "PLC-IO86A"
    }

    fn share_code(&self) -> u8 {
        1
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            contacts: ALL_CONTACTS,
            coils: ALL_COILS,
            inline_boxes: false,
            pulse_outputs: true,
            timer_counter_coils: true,
            data_boxes: true,
            word_boxes: false,
            devices: "X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07, K",
            starter: ["X00", "X01", "Y00"],
        }
    }

    fn canonical(&self, device: &str, role: Role) -> Result<String, ElementError> {
        io86a_canonical(device.trim(), role)
    }

    fn check_coil(&self, kind: CoilKind, device: &str) -> Result<(), ElementError> {
        io86a_coil(kind, device)
    }

    fn max_preset(&self) -> u16 {
        K_MAX as u16
    }

    fn located_bit(&self, area: char, n: u32) -> Result<String, LocatedError> {
        match area {
            'I' => Ok(format!("X{n:02}")),
            'Q' => Ok(format!("Y{n:02}")),
            'M' => Ok(format!("M{n:02}")),
            _ => Err(LocatedError::NotThere),
        }
    }

    /// It reads X04 / X05 as analog words into D06 / D07.
    fn located_word(&self, area: char, rest: &str) -> Option<String> {
        match (area, rest) {
            ('I', "W0") => Some("D06".to_string()),
            ('I', "W1") => Some("D07".to_string()),
            _ => None,
        }
    }

    /// M57 (ON) is always on.
    fn always_on(&self) -> Option<&'static str> {
        Some("M57")
    }

    fn pools(&self) -> DevicePools {
        let range = DevicePools::range;
        DevicePools {
            inputs: range("X", 2, 0..8),
            outputs: range("Y", 2, 0..6),
            // M56-M63 are the special relays.
            relays: range("M", 2, 0..56),
            timers: range("T", 2, 0..32),
            counters: range("C", 2, 0..8),
        }
    }
}

impl MachineCompiler for Io86aTarget {
    fn compile(
        &self,
        rungs: &[RungLogic],
        _variables: &[Variable],
        _options: Options,
    ) -> Result<Mapped, Vec<LadderError>> {
        stack::compile_mapped(rungs, self.id(), Dialect::Io86a)
    }

    fn decompile_text(&self, text: &str, _options: Options) -> Result<Ladder, TextError> {
        let p = Program::parse(text).map_err(|e| TextError::Program(problems(e)))?;
        super::decompile::decompile(&p).map_err(TextError::Decompile)
    }
}

fn io86a_canonical(device: &str, role: Role) -> Result<String, ElementError> {
    if matches!(role, Role::WordSource | Role::WordTarget) {
        let w = parse_word(device).map_err(ElementError::Io86a)?;
        if role == Role::WordTarget && !matches!(w, Word::D(_)) {
            return Err(ElementError::NotADataRegister(device.to_string()));
        }
        return Ok(match w {
            Word::K(k) => format!("K{k}"),
            Word::D(n) => format!("D{n:02}"),
            Word::T(n) => format!("T{n:02}"),
            Word::C(n) => format!("C{n:02}"),
        });
    }
    let b = parse_bit(device).map_err(ElementError::Io86a)?;
    let ok = matches!(
        (role, b),
        (Role::Read, _)
            | (Role::Write, Bit::Y(_) | Bit::M(_) | Bit::S(_) | Bit::C(_))
            | (Role::Timer, Bit::T(_))
            | (Role::Counter, Bit::C(_))
    );
    if !ok {
        let want = match role {
            Role::Timer => Drivable::Timer,
            Role::Counter => Drivable::Counter,
            _ => Drivable::Output,
        };
        return Err(ElementError::CannotDrive {
            device: b.to_string(),
            want,
        });
    }
    Ok(b.to_string())
}

/// An IO86A counter is driven by a counter coil with its set value
/// (`OUT C07 K10`); a plain or inverted coil would compile to `OUT C07`
/// with no `K`, which the machine refuses.
fn io86a_coil(kind: CoilKind, device: &str) -> Result<(), ElementError> {
    if matches!(kind, CoilKind::Normal | CoilKind::Inverted) && device.starts_with('C') {
        return Err(ElementError::Io86aCounterCoil(device.to_string()));
    }
    Ok(())
}
