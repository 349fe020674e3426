//! The simplified PLC's four-byte records (`opcode, register, bit pattern,
//! 0`, timers `code, LOW(RAM address), LOW(preset), HIGH(preset)`) decoded
//! into instructions, and the bit names the source defines.

use std::fmt;

use super::asm::{assemble, AsmError, Assembly};
use crate::error::Located;

/// A bit: register number (R0-R31) and bit number (0-7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BitRef {
    /// The register.
    pub register: u8,
    /// The bit within it.
    pub bit: u8,
}

impl fmt::Display for BitRef {
    /// `R4.2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "R{}.{}", self.register, self.bit)
    }
}

/// The three timer kinds (shared with the ladder model).
pub use crate::scan_timer::TimerKind;

/// One decoded record.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Instruction {
    /// 1 / 2: load a NO / NC contact.
    Load(BitRef, bool),
    /// 3 / 4: series NO / NC contact.
    And(BitRef, bool),
    /// 5 / 6: parallel NO / NC contact (one contact per OR line).
    Or(BitRef, bool),
    /// 7 / 8: coil / inverted coil.
    Coil(BitRef, bool),
    /// 9: set coil.
    Set(BitRef),
    /// 10: reset coil.
    Reset(BitRef),
    /// 11-13: a timer in series: IN = the running result, which becomes Q.
    Timer {
        /// TON, TOF or TP.
        kind: TimerKind,
        /// Which 2-byte RAM word after `PLC_Timer_Top`.
        index: usize,
        /// The set value in scans.
        preset: u16,
    },
    /// 14: inverter.
    Not,
    /// 15 / 16: rising / falling edge; the bit keeps last scan's state.
    Pulse(BitRef, bool),
    /// $FF: end.
    End,
}

/// An assembled and decoded program.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Program {
    instructions: Vec<Instruction>,
    /// The records' bytes, for `hashigo asm`.
    records: Vec<[u8; 4]>,
    /// Names from `NAME_R` / `NAME_B` pairs.
    names: Vec<(String, BitRef)>,
    /// Timer labels after `PLC_Timer_Top`, by index.
    timer_names: Vec<(String, usize)>,
    timers: usize,
}

impl Program {
    /// Assembles and decodes `text`; `scan_ms` is the `Scan` symbol.
    pub fn parse(text: &str, scan_ms: i64) -> Result<Program, Vec<Located<ProgramError>>> {
        let assembly = assemble(text, scan_ms).map_err(|errors| {
            errors
                .into_iter()
                .map(|e| Located::new(e.line, ProgramError::Asm(e.error)))
                .collect::<Vec<_>>()
        })?;
        decode(&assembly)
    }

    /// The instructions up to and including `End_PLC`.
    pub fn instructions(&self) -> &[Instruction] {
        &self.instructions
    }

    /// How many timer words the program uses.
    pub fn timer_count(&self) -> usize {
        self.timers
    }

    /// The bit named `name` (`NAME` of a `NAME_R`/`NAME_B` pair, or
    /// `R4.2`), ignoring letter case.
    pub fn bit(&self, name: &str) -> Option<BitRef> {
        if let Some(b) = parse_register_bit(name) {
            return Some(b);
        }
        self.names
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, b)| b)
    }

    /// The named bits, in the order the source defines them.
    pub fn names(&self) -> &[(String, BitRef)] {
        &self.names
    }

    /// Every bit the program names or uses: the named bits first, in the
    /// source's order, then each bit an instruction reads or writes that
    /// no name covers, named as a register bit (`R0.0`), in program order.
    /// A ladder compiled for the AVR names none, so its panel shows these.
    pub fn bits_in_use(&self) -> Vec<(String, BitRef)> {
        let mut bits = self.names.clone();
        for i in &self.instructions {
            let bit = match *i {
                Instruction::Load(b, _)
                | Instruction::And(b, _)
                | Instruction::Or(b, _)
                | Instruction::Coil(b, _)
                | Instruction::Set(b)
                | Instruction::Reset(b)
                | Instruction::Pulse(b, _) => b,
                Instruction::Timer { .. } | Instruction::Not | Instruction::End => continue,
            };
            if !bits.iter().any(|(_, known)| *known == bit) {
                bits.push((bit.to_string(), bit));
            }
        }
        bits
    }

    /// The timer word a label names.
    pub fn timer(&self, name: &str) -> Option<usize> {
        self.timer_names
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, i)| i)
    }

    /// The label of timer word `index`, as the program defines it.
    pub fn timer_name(&self, index: usize) -> Option<&str> {
        self.timer_names
            .iter()
            .find(|&&(_, i)| i == index)
            .map(|(n, _)| n.as_str())
    }

    /// The records as `.db` lines with numeric bytes.
    pub fn listing(&self) -> String {
        self.records
            .iter()
            .map(|r| format!(".db {},{},{},{}\n", r[0], r[1], r[2], r[3]))
            .collect()
    }
}

/// `R4.2` → register 4, bit 2.
pub fn parse_register_bit(name: &str) -> Option<BitRef> {
    let rest = name.strip_prefix(['R', 'r'])?;
    let (register, bit) = rest.split_once('.')?;
    let register: u8 = register.parse().ok().filter(|&r| r < 32)?;
    let bit: u8 = bit.parse().ok().filter(|&b| b < 8)?;
    Some(BitRef { register, bit })
}

fn decode(a: &Assembly) -> Result<Program, Vec<Located<ProgramError>>> {
    let mut p = Program::default();
    let mut errors = Vec::new();
    // Names: every NAME_R with a NAME_B.
    for (name, register) in &a.equs {
        let Some(base) = name.strip_suffix("_R").or_else(|| name.strip_suffix("_r")) else {
            continue;
        };
        let Some(pattern) = a.symbol(&format!("{base}_B")) else {
            continue;
        };
        if let (Ok(register), Some(bit)) = (u8::try_from(*register), single_bit(pattern)) {
            if register < 32 {
                p.names.push((base.to_string(), BitRef { register, bit }));
            }
        }
    }
    let timer_top = a.symbol("PLC_Timer_Top");
    if let Some(top) = timer_top {
        for (name, address) in &a.labels {
            if *address >= top
                && (address - top) % 2 == 0
                && !name.eq_ignore_ascii_case("PLC_Timer_Top")
            {
                p.timer_names
                    .push((name.clone(), ((address - top) / 2) as usize));
            }
        }
    }

    let mut ended = false;
    for chunk in a.code.chunks(4) {
        if ended {
            break;
        }
        let line = chunk[0].1;
        let bytes: Vec<u8> = chunk.iter().map(|b| b.0).collect();
        if bytes[0] == 0xFF {
            p.instructions.push(Instruction::End);
            p.records.push([
                0xFF,
                *bytes.get(1).unwrap_or(&0),
                *bytes.get(2).unwrap_or(&0),
                *bytes.get(3).unwrap_or(&0),
            ]);
            ended = true;
            break;
        }
        if bytes.len() < 4 {
            errors.push(Located::new(line, ProgramError::ShortRecord(bytes.len())));
            break;
        }
        let record = [bytes[0], bytes[1], bytes[2], bytes[3]];
        match instruction(record, timer_top) {
            Ok(i) => {
                if let Instruction::Timer { index, .. } = i {
                    p.timers = p.timers.max(index + 1);
                }
                p.instructions.push(i);
                p.records.push(record);
            }
            Err(e) => errors.push(Located::new(line, e)),
        }
    }
    if !ended && errors.is_empty() {
        let line = a.code.last().map_or(1, |b| b.1);
        errors.push(Located::new(line, ProgramError::NoEnd));
    }
    if errors.is_empty() {
        Ok(p)
    } else {
        Err(errors)
    }
}

/// The bit number of a one-bit pattern (`$04` → 2).
fn single_bit(pattern: i64) -> Option<u8> {
    (pattern > 0 && pattern <= 0x80 && pattern & (pattern - 1) == 0)
        .then(|| pattern.trailing_zeros() as u8)
}

fn instruction(r: [u8; 4], timer_top: Option<i64>) -> Result<Instruction, ProgramError> {
    let bit = || -> Result<BitRef, ProgramError> {
        if r[1] >= 32 {
            return Err(ProgramError::Register(r[1]));
        }
        let bit = single_bit(i64::from(r[2])).ok_or(ProgramError::Pattern(r[2]))?;
        Ok(BitRef {
            register: r[1],
            bit,
        })
    };
    Ok(match r[0] {
        1 | 2 => Instruction::Load(bit()?, r[0] == 2),
        3 | 4 => Instruction::And(bit()?, r[0] == 4),
        5 | 6 => Instruction::Or(bit()?, r[0] == 6),
        7 | 8 => Instruction::Coil(bit()?, r[0] == 8),
        9 => Instruction::Set(bit()?),
        10 => Instruction::Reset(bit()?),
        11..=13 => {
            let top = timer_top.ok_or(ProgramError::NoTimerTop)? & 0xFF;
            let offset = i64::from(r[1]) - top;
            if offset < 0 || offset % 2 != 0 {
                return Err(ProgramError::TimerAddress(r[1]));
            }
            let kind = match r[0] {
                11 => TimerKind::Ton,
                12 => TimerKind::Tof,
                _ => TimerKind::Tp,
            };
            Instruction::Timer {
                kind,
                index: (offset / 2) as usize,
                preset: u16::from_le_bytes([r[2], r[3]]),
            }
        }
        14 => {
            if r[1] != 0 || r[2] != 0 || r[3] != 0 {
                return Err(ProgramError::NotOperand);
            }
            Instruction::Not
        }
        15 | 16 => Instruction::Pulse(bit()?, r[0] == 16),
        other => return Err(ProgramError::UnknownCode(other)),
    })
}

/// A problem with AVR PLC source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProgramError {
    /// An assembler error.
    Asm(AsmError),
    /// An instruction code that is not 1-16 or $FF.
    UnknownCode(u8),
    /// A register number above 31.
    Register(u8),
    /// A bit pattern that is not one bit ($01, $02, … $80).
    Pattern(u8),
    /// A timer whose RAM address is not a word after `PLC_Timer_Top`.
    TimerAddress(u8),
    /// A timer with no `PLC_Timer_Top` label.
    NoTimerTop,
    /// `Not` with operand bytes that are not 0.
    NotOperand,
    /// A record cut short (its byte count).
    ShortRecord(usize),
    /// No `End_PLC` record.
    NoEnd,
}

impl fmt::Display for ProgramError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProgramError::Asm(e) => e.fmt(f),
            ProgramError::UnknownCode(c) => {
                write!(f, "instruction code {c} is not one of 1-16 or $FF")
            }
            ProgramError::Register(r) => write!(f, "register {r} does not exist: R0-R31"),
            ProgramError::Pattern(p) => write!(
                f,
                "bit pattern ${p:02X} is not a single bit: use $01, $02, $04 … $80 (Bit0..Bit7)"
            ),
            ProgramError::TimerAddress(a) => {
                write!(
                    f,
                    "timer RAM address ${a:02X} is not a 2-byte word after PLC_Timer_Top"
                )
            }
            ProgramError::NoTimerTop => {
                f.write_str("timers need their RAM after a PLC_Timer_Top label in .dseg")
            }
            ProgramError::NotOperand => f.write_str("Not takes no operand: its other bytes are 0"),
            ProgramError::ShortRecord(n) => write!(f, "a record has {n} bytes: each is 4"),
            ProgramError::NoEnd => f.write_str("the program has no End_PLC record"),
        }
    }
}

impl std::error::Error for ProgramError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_no_name_covers_are_in_use_as_register_bits() {
        let p = Program::parse(
            ".equ Start_R=0\n.equ Start_B=Bit0\n.db Load_A,Start_R,Start_B,0\n\
             .db And_B,0,Bit1,0\n.db Coil_A,1,Bit0,0\n.db Coil_A,1,Bit0,0\n.db End_PLC,0,0,0\n",
            10,
        )
        .expect("assembles");
        let names: Vec<String> = p.bits_in_use().into_iter().map(|(n, _)| n).collect();
        assert_eq!(names, ["Start", "R0.1", "R1.0"]);
    }
}
