//! MINASEC-U's text formats: the mnemonic listing (`LD X00`, optional step
//! numbers, `;` comments) and the seed's programming sheet
//! (`ADDR OPCODE OPERAND BINARY`).

use std::fmt;

use super::isa::{Address, Instruction, Opcode, OperandError};
use crate::error::Located;

/// Program memory holds 256 steps; the PC wraps after the last.
pub const STEPS: usize = 256;

/// A MINASEC-U program: the 256 bytes of program memory and how many of
/// them the source defined (the rest are erased, `0x00` = `LD X00`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Program {
    bytes: [u8; STEPS],
    len: usize,
}

impl Default for Program {
    fn default() -> Self {
        Program::erased()
    }
}

impl Program {
    /// Erased memory: every step `LD X00`, no step defined.
    pub const fn erased() -> Program {
        Program {
            bytes: [0; STEPS],
            len: 0,
        }
    }

    /// A program from whole memory contents; every step counts as defined.
    pub const fn from_bytes(bytes: [u8; STEPS]) -> Program {
        Program { bytes, len: STEPS }
    }

    /// The whole of program memory.
    pub const fn bytes(&self) -> &[u8; STEPS] {
        &self.bytes
    }

    /// How many steps the source defined (trailing memory is erased).
    pub const fn len(&self) -> usize {
        self.len
    }

    /// True when the source defined no step.
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The defined steps, in address order.
    pub fn instructions(&self) -> impl Iterator<Item = Instruction> + '_ {
        self.bytes[..self.len]
            .iter()
            .map(|&b| Instruction::decode(b))
    }

    /// Parses the mnemonic listing. Every problem is reported with its line
    /// (1-based); nothing is returned unless the whole text is good.
    ///
    /// A line is `[STEP] OPCODE OPERAND [BINARY]` with an optional `;`
    /// comment. A step number places the step at that address (later steps
    /// follow it); skipped addresses stay erased. A trailing binary column
    /// (`100 01000`, as on the programming sheet) must agree with the step.
    pub fn parse(text: &str) -> Result<Program, Vec<Located<AsmError>>> {
        crate::limits::check_program_lines(text)
            .map_err(|(line, n)| vec![Located::new(line, AsmError::TooManyLines(n))])?;
        let mut program = Program::erased();
        let mut errors = Vec::new();
        let mut next: usize = 0;
        for (index, raw) in text.lines().enumerate() {
            let line = index + 1;
            let code = raw.split(';').next().unwrap_or("").trim();
            if code.is_empty() {
                continue;
            }
            match parse_line(code, next) {
                Ok((step, instruction)) => {
                    if step >= STEPS {
                        errors.push(Located::new(line, AsmError::TooManySteps(step + 1)));
                        // Report the overflow once, not for every later line.
                        break;
                    }
                    program.bytes[step] = instruction.encode();
                    next = step + 1;
                    program.len = next;
                }
                Err(error) => errors.push(Located::new(line, error)),
            }
        }
        if errors.is_empty() {
            Ok(program)
        } else {
            Err(errors)
        }
    }

    /// The listing: one `LD X00`-style line per defined step, which
    /// [`Program::parse`] reads back to the same memory.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        for step in self.instructions() {
            out.push_str(&format!("{:<4} {}\n", step.opcode.mnemonic(), step.address));
        }
        out
    }

    /// The seed's programming sheet, one row per defined step.
    pub fn sheet(&self) -> ProgrammingSheet {
        ProgrammingSheet {
            rows: self
                .instructions()
                .enumerate()
                .map(|(address, instruction)| SheetRow {
                    address: address as u8,
                    instruction,
                })
                .collect(),
        }
    }
}

/// Parses one non-empty line whose step defaults to `next`.
fn parse_line(code: &str, next: usize) -> Result<(usize, Instruction), AsmError> {
    let mut words: Vec<&str> = code.split_whitespace().collect();
    let mut step = next;
    if words[0].bytes().all(|b| b.is_ascii_digit()) {
        let number: usize = words[0]
            .parse()
            .map_err(|_| AsmError::BadStepNumber(words[0].to_string()))?;
        if number >= STEPS {
            return Err(AsmError::BadStepNumber(words[0].to_string()));
        }
        if number < next {
            return Err(AsmError::StepOutOfOrder {
                found: number,
                expected: next,
            });
        }
        step = number;
        words.remove(0);
    }
    let Some((&mnemonic, rest)) = words.split_first() else {
        return Err(AsmError::MissingOpcode);
    };
    let opcode =
        Opcode::parse(mnemonic).ok_or_else(|| AsmError::UnknownOpcode(mnemonic.to_string()))?;
    let Some((&operand, binary)) = rest.split_first() else {
        return Err(AsmError::MissingOperand(opcode));
    };
    let address = Address::parse(operand).map_err(AsmError::Operand)?;
    let instruction = Instruction { opcode, address };
    if !binary.is_empty() {
        check_binary(instruction, binary)?;
    }
    Ok((step, instruction))
}

/// Checks a sheet's binary column (`100 01000` or `10001000`).
fn check_binary(instruction: Instruction, words: &[&str]) -> Result<(), AsmError> {
    let joined: String = words.concat();
    if joined.len() != 8 || !joined.bytes().all(|b| b == b'0' || b == b'1') {
        return Err(AsmError::Unexpected(words.join(" ")));
    }
    let byte = u8::from_str_radix(&joined, 2).map_err(|_| AsmError::Unexpected(words.join(" ")))?;
    if byte != instruction.encode() {
        return Err(AsmError::BinaryMismatch {
            written: words.join(" "),
            expected: instruction.binary(),
        });
    }
    Ok(())
}

/// The seed's programming sheet: what a user keys in on the DIP switches.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProgrammingSheet {
    /// One row per step, in address order.
    pub rows: Vec<SheetRow>,
}

/// One row of the programming sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SheetRow {
    /// The step's address (the PC value when it is written).
    pub address: u8,
    /// The step.
    pub instruction: Instruction,
}

impl fmt::Display for SheetRow {
    /// `001 OR Y00 100 01000`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:03} {} {} {}",
            self.address,
            self.instruction.opcode,
            self.instruction.address,
            self.instruction.binary()
        )
    }
}

impl fmt::Display for ProgrammingSheet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for row in &self.rows {
            writeln!(f, "{row}")?;
        }
        Ok(())
    }
}

/// A problem with one line of a MINASEC-U listing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AsmError {
    /// More lines than [`crate::limits::MAX_PROGRAM_LINES`] (how many).
    TooManyLines(usize),
    /// A step number is above 255 or malformed.
    BadStepNumber(String),
    /// A step number goes backwards or repeats an earlier step.
    StepOutOfOrder {
        /// The number written.
        found: usize,
        /// The lowest number allowed here.
        expected: usize,
    },
    /// The line has a step number and nothing else.
    MissingOpcode,
    /// The word is not one of the eight mnemonics.
    UnknownOpcode(String),
    /// The opcode has no operand after it.
    MissingOperand(Opcode),
    /// The operand is not a device or raw address.
    Operand(OperandError),
    /// Words after the operand that are not an 8-bit binary column.
    Unexpected(String),
    /// The binary column disagrees with the mnemonic.
    BinaryMismatch {
        /// The binary as written.
        written: String,
        /// The binary of the mnemonic.
        expected: String,
    },
    /// The program needs more than 256 steps (the count it reached).
    TooManySteps(usize),
}

impl fmt::Display for AsmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AsmError::TooManyLines(n) => write!(
                f,
                "the program has {n} lines, more than the {} a program may have (docs/limits.md)",
                crate::limits::MAX_PROGRAM_LINES
            ),
            AsmError::BadStepNumber(n) => write!(
                f,
                "bad step number {}: steps are 0..255",
                crate::error::shown(n)
            ),
            AsmError::StepOutOfOrder { found, expected } => write!(
                f,
                "step {found} is out of order: the next step here is {expected} or later"
            ),
            AsmError::MissingOpcode => f.write_str("a step number without an instruction"),
            AsmError::UnknownOpcode(w) => write!(
                f,
                "unknown opcode {}: MINASEC-U has LD LDI AND ANDI OR ORI ST STI",
                crate::error::shown(w)
            ),
            AsmError::MissingOperand(op) => write!(f, "{op} needs an operand, e.g. {op} X00"),
            AsmError::Operand(e) => e.fmt(f),
            AsmError::Unexpected(w) => write!(
                f,
                "unexpected {} after the operand (a binary column is 8 bits, e.g. 100 01000)",
                crate::error::shown(w)
            ),
            AsmError::BinaryMismatch { written, expected } => write!(
                f,
                "binary {written} does not match the instruction, which is {expected}"
            ),
            AsmError::TooManySteps(n) => write!(
                f,
                "too many steps: the program needs {n} but MINASEC-U has {STEPS}"
            ),
        }
    }
}

impl std::error::Error for AsmError {}

#[cfg(test)]
mod tests {
    use super::*;

    fn errors(text: &str) -> Vec<(usize, AsmError)> {
        Program::parse(text)
            .expect_err("should fail")
            .into_iter()
            .map(|e| (e.line, e.error))
            .collect()
    }

    #[test]
    fn parses_mnemonics_numbers_comments_and_case() {
        let p =
            Program::parse("; start\n000 LD X00\n  or y00 ; hold\n\n2 ANDI X01\nST Y00\n").unwrap();
        assert_eq!(p.len(), 4);
        assert_eq!(p.bytes()[1], 0b100_01000);
        assert_eq!(p.bytes()[2], 0b011_00001);
        assert_eq!(p.bytes()[3], 0b110_01000);
        assert!(p.bytes()[4..].iter().all(|&b| b == 0));
    }

    #[test]
    fn step_numbers_may_skip_but_not_go_back() {
        let p = Program::parse("LD X01\n10 ST Y00\nST Y01\n").unwrap();
        assert_eq!(p.len(), 12);
        assert_eq!(p.bytes()[1], 0, "skipped steps stay erased");
        assert_eq!(p.bytes()[10], 0b110_01000);
        assert_eq!(
            errors("5 LD X00\n3 ST Y00\n"),
            vec![(
                2,
                AsmError::StepOutOfOrder {
                    found: 3,
                    expected: 6
                }
            )]
        );
    }

    #[test]
    fn printer_and_sheet_round_trip() {
        let text = "LD X00\nOR Y00\nANDI X01\nST Y00\nLDI %11101\nSTI $1F\n";
        let p = Program::parse(text).unwrap();
        assert_eq!(Program::parse(&p.to_text()).unwrap(), p);
        let sheet = p.sheet().to_string();
        assert!(
            sheet.starts_with("000 LD X00 000 00000\n001 OR Y00 100 01000\n"),
            "{sheet}"
        );
        assert!(sheet.contains("004 LDI T1 001 11101\n005 STI C0R 111 11111\n"));
        // The sheet itself is a valid listing that checks its binary column.
        assert_eq!(Program::parse(&sheet).unwrap(), p);
    }

    #[test]
    fn every_bad_line_is_located() {
        let text =
            "LD X00\nFOO X00\nLD X08\nST\n300 LD X00\nLD X00 100 01000\nLD X00 junk\n7\nLD $40\n";
        let found = errors(text);
        let lines: Vec<usize> = found.iter().map(|(l, _)| *l).collect();
        assert_eq!(lines, vec![2, 3, 4, 5, 6, 7, 8, 9]);
        assert!(matches!(found[0].1, AsmError::UnknownOpcode(_)));
        assert!(matches!(
            found[1].1,
            AsmError::Operand(OperandError::UnknownDevice(_))
        ));
        assert_eq!(found[2].1, AsmError::MissingOperand(Opcode::St));
        assert!(matches!(found[3].1, AsmError::BadStepNumber(_)));
        assert!(matches!(found[4].1, AsmError::BinaryMismatch { .. }));
        assert!(matches!(found[5].1, AsmError::Unexpected(_)));
        assert_eq!(found[6].1, AsmError::MissingOpcode);
        assert!(matches!(
            found[7].1,
            AsmError::Operand(OperandError::BadRawAddress(_))
        ));
    }

    #[test]
    fn too_many_steps_is_reported_on_the_first_extra_line() {
        let text = "LD X00\n".repeat(257);
        assert_eq!(errors(&text), vec![(257, AsmError::TooManySteps(257))]);
        assert!(Program::parse(&"LD X00\n".repeat(256)).is_ok());
        assert!(Program::parse("255 ST Y00\n").is_ok());
        assert_eq!(
            errors("255 ST Y00\nST Y01\n"),
            vec![(2, AsmError::TooManySteps(257))]
        );
    }
}
