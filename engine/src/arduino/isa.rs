//! The Arduino PLC sketch's words (machines.md §4): opcode in bits 15-12,
//! operand in the low byte; and its mnemonic text.

use std::fmt;

use crate::error::Located;

/// The opcodes the sketch defines.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    /// 0: end of program; the scan restarts at step 0.
    End,
    /// 1: pop the top of the bit stack into an output.
    Out,
    /// 2: push an input or output.
    Ld,
    /// 3: push its inverse.
    Ldn,
    /// 4: top &= operand.
    And,
    /// 5: top &= !operand.
    Andn,
    /// 6: top |= operand.
    Or,
    /// 7: top |= !operand.
    Orn,
    /// 8: pop two, push their AND.
    Andb,
    /// 9: pop two, push their OR.
    Orb,
    /// 15: continue at the step in the operand.
    Jump,
}

impl Op {
    /// The opcode in bits 15-12 of `word`; `None` for 10-14 (undefined,
    /// the sketch does nothing for them).
    // Inlined by force: the interpreter calls it per step, and the page is
    // built for size (opt-level z; docs/performance.md, "First visit").
    #[inline(always)]
    pub const fn decode(word: u16) -> Option<Op> {
        Some(match word >> 12 {
            0 => Op::End,
            1 => Op::Out,
            2 => Op::Ld,
            3 => Op::Ldn,
            4 => Op::And,
            5 => Op::Andn,
            6 => Op::Or,
            7 => Op::Orn,
            8 => Op::Andb,
            9 => Op::Orb,
            15 => Op::Jump,
            _ => return None,
        })
    }

    /// The four opcode bits.
    pub const fn code(self) -> u16 {
        match self {
            Op::End => 0,
            Op::Out => 1,
            Op::Ld => 2,
            Op::Ldn => 3,
            Op::And => 4,
            Op::Andn => 5,
            Op::Or => 6,
            Op::Orn => 7,
            Op::Andb => 8,
            Op::Orb => 9,
            Op::Jump => 15,
        }
    }

    /// The mnemonic.
    pub const fn mnemonic(self) -> &'static str {
        match self {
            Op::End => "END",
            Op::Out => "OUT",
            Op::Ld => "LD",
            Op::Ldn => "LDN",
            Op::And => "AND",
            Op::Andn => "ANDN",
            Op::Or => "OR",
            Op::Orn => "ORN",
            Op::Andb => "ANDB",
            Op::Orb => "ORB",
            Op::Jump => "JUMP",
        }
    }

    const ALL: [Op; 11] = [
        Op::End,
        Op::Out,
        Op::Ld,
        Op::Ldn,
        Op::And,
        Op::Andn,
        Op::Or,
        Op::Orn,
        Op::Andb,
        Op::Orb,
        Op::Jump,
    ];

    /// The opcode a mnemonic names, in any letter case.
    pub fn parse(text: &str) -> Option<Op> {
        Op::ALL
            .into_iter()
            .find(|op| op.mnemonic().eq_ignore_ascii_case(text))
    }

    /// What the operand is.
    const fn operand(self) -> Operand {
        match self {
            Op::End | Op::Andb | Op::Orb => Operand::None,
            Op::Out => Operand::Output,
            Op::Jump => Operand::Step,
            _ => Operand::Io,
        }
    }
}

enum Operand {
    None,
    Io,
    Output,
    Step,
}

/// `X000`-`X005` → 0..=5, `Y000`-`Y005` → 8..=13.
pub fn parse_io(text: &str) -> Option<u8> {
    let upper = text.to_ascii_uppercase();
    let mut chars = upper.chars();
    let kind = chars.next()?;
    let digits = chars.as_str();
    if digits.len() != 3 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let n: u8 = digits.parse().ok()?;
    match (kind, n) {
        ('X', 0..=5) => Some(n),
        ('Y', 0..=5) => Some(8 + n),
        _ => None,
    }
}

/// The name of an I/O operand, as the sketch's `show_io` prints it; empty
/// for other values (the sketch prints nothing for them).
pub fn io_name(operand: u8) -> String {
    match operand {
        0..=5 => format!("X{operand:03}"),
        8..=13 => format!("Y{:03}", operand - 8),
        _ => String::new(),
    }
}

/// A word as the sketch's `l` command shows it: `LD X000`, `JUMP 000`.
pub fn disassemble(word: u16) -> String {
    let operand = (word & 0xFF) as u8;
    match Op::decode(word) {
        Some(op @ (Op::End | Op::Andb | Op::Orb)) => op.mnemonic().to_string(),
        Some(Op::Jump) => format!("JUMP {operand:03}"),
        Some(op) => format!("{} {}", op.mnemonic(), io_name(operand)),
        None => String::new(),
    }
}

/// Parses `MNEMONIC [OPERAND]` into a word.
pub fn assemble(mnemonic: &str, operand: Option<&str>) -> Result<u16, AsmError> {
    let op = Op::parse(mnemonic).ok_or_else(|| AsmError::UnknownMnemonic(mnemonic.to_string()))?;
    let value: u16 = match (op.operand(), operand) {
        (Operand::None, None) => 0,
        (Operand::None, Some(extra)) => return Err(AsmError::Unexpected(extra.to_string())),
        (_, None) => return Err(AsmError::MissingOperand(op.mnemonic())),
        (Operand::Io, Some(o)) => parse_io(o)
            .ok_or_else(|| AsmError::BadOperand(o.to_string()))?
            .into(),
        (Operand::Output, Some(o)) => match parse_io(o) {
            Some(v @ 8..=13) => v.into(),
            Some(_) => return Err(AsmError::OutToInput(o.to_string())),
            None => return Err(AsmError::BadOperand(o.to_string())),
        },
        (Operand::Step, Some(o)) => o
            .parse::<u8>()
            .map_err(|_| AsmError::BadStep(o.to_string()))?
            .into(),
    };
    Ok(op.code() << 12 | value)
}

/// A program: EEPROM words from step 0; the rest of EEPROM stays erased.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Program {
    words: Vec<u16>,
}

impl Program {
    /// The words the text defined (erased gaps are 0xFFFF).
    pub fn words(&self) -> &[u16] {
        &self.words
    }

    /// Parses the mnemonic listing: `[STEP] MNEMONIC [OPERAND]` a line,
    /// `;` comments. A step number places the word at that step (gaps stay
    /// erased); numbers must increase. `capacity` is 256 or 512.
    pub fn parse(text: &str, capacity: usize) -> Result<Program, Vec<Located<AsmError>>> {
        crate::limits::check_program_lines(text)
            .map_err(|(line, n)| vec![Located::new(line, AsmError::TooManyLines(n))])?;
        let mut words: Vec<u16> = Vec::new();
        let mut errors = Vec::new();
        for (index, raw) in text.lines().enumerate() {
            let line = index + 1;
            let code = raw.split(';').next().unwrap_or("").trim();
            if code.is_empty() {
                continue;
            }
            let mut parts: Vec<&str> = code.split_whitespace().collect();
            let mut step = words.len();
            if parts[0].bytes().all(|b| b.is_ascii_digit()) {
                match parts[0].parse::<usize>() {
                    Ok(n) if n >= words.len() => step = n,
                    _ => {
                        errors.push(Located::new(
                            line,
                            AsmError::StepOrder {
                                found: parts[0].to_string(),
                                next: words.len(),
                            },
                        ));
                        continue;
                    }
                }
                parts.remove(0);
            }
            if step >= capacity {
                errors.push(Located::new(
                    line,
                    AsmError::TooManySteps { step, capacity },
                ));
                break;
            }
            let result = match parts.as_slice() {
                [] => Err(AsmError::MissingMnemonic),
                [m] => assemble(m, None),
                [m, o] => assemble(m, Some(o)),
                [_, _, rest @ ..] => Err(AsmError::Unexpected(rest.join(" "))),
            };
            match result {
                Ok(word) => {
                    words.resize(step, ERASED);
                    words.push(word);
                }
                Err(e) => errors.push(Located::new(line, e)),
            }
        }
        if errors.is_empty() {
            Ok(Program { words })
        } else {
            Err(errors)
        }
    }

    /// The listing that reads back to the same words.
    pub fn to_text(&self) -> String {
        self.words
            .iter()
            .enumerate()
            .filter(|(_, &w)| w != ERASED)
            .map(|(step, &w)| format!("{step} {}\n", disassemble(w)))
            .collect()
    }
}

/// An erased EEPROM word: decodes as `JUMP 255`.
pub const ERASED: u16 = 0xFFFF;

/// A problem with one line of an Arduino PLC listing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AsmError {
    /// More lines than [`crate::limits::MAX_PROGRAM_LINES`] (how many).
    TooManyLines(usize),
    /// Not one of END OUT LD LDN AND ANDN OR ORN ANDB ORB JUMP.
    UnknownMnemonic(String),
    /// The instruction needs an operand.
    MissingOperand(&'static str),
    /// Not `X000`-`X005` or `Y000`-`Y005`.
    BadOperand(String),
    /// OUT to an input.
    OutToInput(String),
    /// A JUMP target that is not 0..=255.
    BadStep(String),
    /// Words after the operand.
    Unexpected(String),
    /// A step number and nothing else.
    MissingMnemonic,
    /// A step number that does not increase.
    StepOrder {
        /// As written.
        found: String,
        /// The next free step.
        next: usize,
    },
    /// A step beyond the EEPROM.
    TooManySteps {
        /// The step.
        step: usize,
        /// 256 or 512.
        capacity: usize,
    },
}

impl fmt::Display for AsmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AsmError::TooManyLines(n) => write!(
                f,
                "the program has {n} lines, more than the {} a program may have (docs/limits.md)",
                crate::limits::MAX_PROGRAM_LINES
            ),
            AsmError::UnknownMnemonic(m) => write!(
                f,
                "unknown instruction {}: the sketch has END OUT LD LDN AND ANDN OR ORN ANDB ORB JUMP", crate::error::shown(m)
            ),
            AsmError::MissingOperand(m) => write!(f, "{m} needs an operand"),
            AsmError::BadOperand(o) => write!(f, "bad operand {}: X000-X005 or Y000-Y005", crate::error::shown(o)),
            AsmError::OutToInput(o) => write!(f, "OUT {o}: outputs are Y000-Y005"),
            AsmError::BadStep(s) => write!(f, "bad step {}: JUMP takes 0..255", crate::error::shown(s)),
            AsmError::Unexpected(w) => write!(f, "unexpected {}", crate::error::shown(w)),
            AsmError::MissingMnemonic => f.write_str("a step number without an instruction"),
            AsmError::StepOrder { found, next } => {
                write!(f, "step {found} is out of order: the next step is {next} or later")
            }
            AsmError::TooManySteps { step, capacity } => {
                write!(f, "step {step} is beyond the EEPROM: this chip holds {capacity} steps")
            }
        }
    }
}

impl std::error::Error for AsmError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_seeds_example_assembles() {
        let p = Program::parse(
            "0 LD X000\n1 OR Y000\n2 ANDN X001\n3 OUT Y000\n4 JUMP 0\n",
            256,
        )
        .unwrap();
        assert_eq!(p.words(), [0x2000, 0x6008, 0x5001, 0x1008, 0xF000]);
        assert_eq!(Program::parse(&p.to_text(), 256).unwrap(), p);
        assert_eq!(disassemble(0xF000), "JUMP 000");
        assert_eq!(disassemble(0xFFFF), "JUMP 255");
    }

    #[test]
    fn bad_lines_are_located() {
        let errors =
            Program::parse("LD X006\nOUT X000\nFOO\nJUMP 300\nORB Y000\n", 256).unwrap_err();
        let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, [1, 2, 3, 4, 5]);
        assert!(matches!(errors[1].error, AsmError::OutToInput(_)));
        let over = Program::parse("300 END\n", 256).unwrap_err();
        assert_eq!(
            over[0].error,
            AsmError::TooManySteps {
                step: 300,
                capacity: 256
            }
        );
        assert!(Program::parse("300 END\n", 512).is_ok());
    }
}
