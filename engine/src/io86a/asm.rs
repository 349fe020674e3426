//! PLC-IO86A's mnemonic listing: one step a line, an optional leading step
//! number (from 1), `;` comments. Operands of OUT T/C, MOV, CMP, INC, DEC
//! may stand inline (`INC D0`) or on lines of their own (`MOV` / `K10` /
//! `D00`); each line written is one step, as the manual numbers them.

use std::fmt;

use super::isa::{parse_bit, parse_word, Bit, Instruction, OperandError, Word};
use crate::error::Located;

/// Program capacity in steps.
pub const MAX_STEPS: usize = 511;

/// A parsed program: its instructions and its steps as the `L` command
/// lists them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Program {
    instructions: Vec<Instruction>,
    listing: Vec<String>,
    /// Each instruction's first step (0-based): `MOV` / `K10` / `D00` is
    /// one instruction on three steps.
    first_steps: Vec<usize>,
}

impl Program {
    /// The instructions in order (up to and including the first `END`,
    /// and any after it: they are kept but do not run).
    pub fn instructions(&self) -> &[Instruction] {
        &self.instructions
    }

    /// The first step (0-based) of instruction `index`.
    pub fn first_step(&self, index: usize) -> usize {
        self.first_steps.get(index).copied().unwrap_or(index)
    }

    /// The number of steps.
    pub fn steps(&self) -> usize {
        self.listing.len()
    }

    /// The numbered listing as the `L` command prints it: `1 LD X00`.
    pub fn listing(&self) -> String {
        self.listing
            .iter()
            .enumerate()
            .map(|(n, text)| format!("{} {text}\n", n + 1))
            .collect()
    }

    /// Parses a listing; every bad line is reported, nothing is returned
    /// unless all of it is good.
    pub fn parse(text: &str) -> Result<Program, Vec<Located<AsmError>>> {
        crate::limits::check_program_lines(text)
            .map_err(|(line, n)| vec![Located::new(line, AsmError::TooManyLines(n))])?;
        let mut parser = Parser::default();
        for (index, raw) in text.lines().enumerate() {
            let code = raw.split(';').next().unwrap_or("").trim();
            if !code.is_empty() {
                parser.line(index + 1, code);
            }
        }
        parser.finish()
    }
}

/// An instruction whose operands are still to come on later lines.
struct Pending {
    line: usize,
    /// The step of its mnemonic.
    step: usize,
    mnemonic: &'static str,
    head: Option<Bit>,
    words: Vec<Word>,
    needed: usize,
}

#[derive(Default)]
struct Parser {
    instructions: Vec<Instruction>,
    listing: Vec<String>,
    first_steps: Vec<usize>,
    /// The first step of the instruction being completed from later lines.
    pending_step: Option<usize>,
    errors: Vec<Located<AsmError>>,
    pending: Option<Pending>,
    blocks: BlockCheck,
}

/// The block stack as the program builds it: LD/LDI open a block; ORB/ANB
/// join the last two; an output ends the rung, so the next LD starts anew.
#[derive(Default)]
struct BlockCheck {
    depth: usize,
    after_output: bool,
}

const MNEMONICS: [&str; 20] = [
    "LD", "LDI", "AND", "ANI", "OR", "ORI", "ORB", "ANB", "OUT", "PLS", "PLF", "SET", "RST",
    "SETS", "RSTS", "CMP", "MOV", "INC", "DEC", "END",
];

impl Parser {
    fn error(&mut self, line: usize, error: AsmError) {
        self.errors.push(Located::new(line, error));
    }

    fn line(&mut self, line: usize, code: &str) {
        let mut words: Vec<&str> = code.split_whitespace().collect();
        if words[0].bytes().all(|b| b.is_ascii_digit()) {
            let expected = self.listing.len() + 1;
            match words[0].parse::<usize>() {
                Ok(n) if n == expected => {}
                _ => self.error(
                    line,
                    AsmError::StepNumber {
                        found: words[0].to_string(),
                        expected,
                    },
                ),
            }
            words.remove(0);
            if words.is_empty() {
                return self.error(line, AsmError::MissingInstruction);
            }
        }
        let first = words[0].to_ascii_uppercase();
        let is_mnemonic = MNEMONICS.contains(&first.as_str());
        if !is_mnemonic && self.pending.is_some() {
            return self.operand_line(line, &words);
        }
        if let Some(p) = self.pending.take() {
            self.error(p.line, AsmError::MissingOperand(p.mnemonic, p.needed));
        }
        if !is_mnemonic {
            let error = if parse_word(words[0]).is_ok() {
                AsmError::StrayOperand(words[0].to_string())
            } else {
                AsmError::UnknownMnemonic(words[0].to_string())
            };
            return self.error(line, error);
        }
        self.push_step(line, words.join(" "));
        if let Err(e) = self.instruction(line, &first, &words[1..]) {
            self.error(line, e);
        }
    }

    fn push_step(&mut self, line: usize, text: String) {
        self.listing.push(text.to_ascii_uppercase());
        if self.listing.len() == MAX_STEPS + 1 {
            self.error(line, AsmError::TooManySteps(self.listing.len()));
        }
    }

    fn operand_line(&mut self, line: usize, words: &[&str]) {
        self.push_step(line, words.join(" "));
        if words.len() > 1 {
            return self.error(line, AsmError::Unexpected(words[1..].join(" ")));
        }
        let result = parse_word(words[0]).map_err(AsmError::Operand);
        match result {
            Ok(word) => {
                if let Some(p) = self.pending.as_mut() {
                    p.words.push(word);
                    if p.words.len() == p.needed {
                        if let Some(p) = self.pending.take() {
                            self.complete(p);
                        }
                    }
                }
            }
            Err(e) => {
                self.pending = None;
                self.error(line, e);
            }
        }
    }

    /// Parses one instruction line (its mnemonic and any inline operands).
    fn instruction(&mut self, line: usize, mnemonic: &str, ops: &[&str]) -> Result<(), AsmError> {
        let mnemonic: &'static str = MNEMONICS
            .iter()
            .find(|m| **m == mnemonic)
            .copied()
            .ok_or_else(|| AsmError::UnknownMnemonic(mnemonic.to_string()))?;
        let bit = |i: usize| -> Result<Bit, AsmError> {
            let op = ops.get(i).ok_or(AsmError::MissingOperand(mnemonic, 1))?;
            parse_bit(op).map_err(AsmError::Operand)
        };
        let no_more = |n: usize| -> Result<(), AsmError> {
            match ops.get(n..) {
                Some(rest) if !rest.is_empty() => Err(AsmError::Unexpected(rest.join(" "))),
                _ => Ok(()),
            }
        };
        let (head, needed) = match mnemonic {
            "LD" | "LDI" | "AND" | "ANI" | "OR" | "ORI" => {
                let b = bit(0)?;
                no_more(1)?;
                return self.contact(line, mnemonic, b);
            }
            "ORB" | "ANB" | "END" => {
                no_more(0)?;
                let instruction = match mnemonic {
                    "ORB" => Instruction::Orb,
                    "ANB" => Instruction::Anb,
                    _ => Instruction::End,
                };
                return self.emit(line, instruction);
            }
            "OUT" => {
                let b = bit(0)?;
                match b {
                    Bit::T(_) | Bit::C(_) => (Some(b), 1),
                    _ => {
                        no_more(1)?;
                        check_coil(mnemonic, b, CoilKinds::OUT)?;
                        return self.emit(line, Instruction::Out(b));
                    }
                }
            }
            "PLS" | "PLF" | "SET" | "RST" | "SETS" | "RSTS" => {
                let b = bit(0)?;
                no_more(1)?;
                let (kinds, instruction) = match mnemonic {
                    "PLS" => (CoilKinds::OUT, Instruction::Pls(b)),
                    "PLF" => (CoilKinds::OUT, Instruction::Plf(b)),
                    "SET" => (CoilKinds::SET, Instruction::Set(b)),
                    "RST" => (CoilKinds::SET, Instruction::Rst(b)),
                    "SETS" => (CoilKinds::LINK, Instruction::Sets(b)),
                    _ => (CoilKinds::LINK, Instruction::Rsts(b)),
                };
                check_coil(mnemonic, b, kinds)?;
                return self.emit(line, instruction);
            }
            "CMP" | "MOV" => (None, 2),
            _ => (None, 1), // INC, DEC
        };
        let inline = if head.is_some() { &ops[1..] } else { ops };
        let mut pending = Pending {
            line,
            step: self.listing.len().saturating_sub(1),
            mnemonic,
            head,
            words: Vec::new(),
            needed,
        };
        if inline.len() > needed {
            return Err(AsmError::Unexpected(inline[needed..].join(" ")));
        }
        for op in inline {
            pending
                .words
                .push(parse_word(op).map_err(AsmError::Operand)?);
        }
        if pending.words.len() == needed {
            self.complete(pending);
        } else {
            self.pending = Some(pending);
        }
        Ok(())
    }

    /// Builds an instruction once all its operands are there.
    fn complete(&mut self, p: Pending) {
        self.pending_step = Some(p.step);
        let built = match (p.mnemonic, p.head, p.words.as_slice()) {
            ("OUT", Some(Bit::T(n)), [preset]) => {
                preset_of(*preset).map(|w| Instruction::OutTimer(n, w))
            }
            ("OUT", Some(Bit::C(n)), [preset]) => {
                preset_of(*preset).map(|w| Instruction::OutCounter(n, w))
            }
            ("CMP", _, [a, b]) => Ok(Instruction::Cmp(*a, *b)),
            ("MOV", _, [a, Word::D(d)]) => Ok(Instruction::Mov(*a, *d)),
            ("MOV", _, [_, other]) => Err(AsmError::NotARegister("MOV", other.to_string())),
            ("INC", _, [Word::D(d)]) => Ok(Instruction::Inc(*d)),
            ("DEC", _, [Word::D(d)]) => Ok(Instruction::Dec(*d)),
            (m, _, [other]) => Err(AsmError::NotARegister(m, other.to_string())),
            (m, _, _) => Err(AsmError::MissingOperand(m, p.needed)),
        };
        match built {
            Ok(instruction) => {
                if let Err(e) = self.emit(p.line, instruction) {
                    self.error(p.line, e);
                }
            }
            Err(e) => self.error(p.line, e),
        }
    }

    fn contact(&mut self, line: usize, mnemonic: &'static str, bit: Bit) -> Result<(), AsmError> {
        let instruction = match mnemonic {
            "LD" => Instruction::Ld(bit),
            "LDI" => Instruction::Ldi(bit),
            "AND" => Instruction::And(bit),
            "ANI" => Instruction::Ani(bit),
            "OR" => Instruction::Or(bit),
            _ => Instruction::Ori(bit),
        };
        self.emit(line, instruction)
    }

    /// Appends an instruction after checking the block stack.
    fn emit(&mut self, _line: usize, instruction: Instruction) -> Result<(), AsmError> {
        let b = &mut self.blocks;
        match instruction {
            Instruction::Ld(_) | Instruction::Ldi(_) => {
                if b.after_output || b.depth == 0 {
                    b.depth = 1;
                    b.after_output = false;
                } else {
                    b.depth += 1;
                }
            }
            Instruction::Orb | Instruction::Anb => {
                if b.after_output || b.depth < 2 {
                    return Err(AsmError::NoBlockToJoin(
                        if instruction == Instruction::Orb {
                            "ORB"
                        } else {
                            "ANB"
                        },
                    ));
                }
                b.depth -= 1;
            }
            Instruction::End => {
                b.depth = 0;
                b.after_output = false;
            }
            Instruction::And(_)
            | Instruction::Ani(_)
            | Instruction::Or(_)
            | Instruction::Ori(_) => {
                if b.depth == 0 {
                    return Err(AsmError::NoRung);
                }
            }
            _ => {
                if b.depth == 0 {
                    return Err(AsmError::NoRung);
                }
                b.after_output = true;
            }
        }
        let step = self
            .pending_step
            .take()
            .unwrap_or_else(|| self.listing.len().saturating_sub(1));
        self.instructions.push(instruction);
        self.first_steps.push(step);
        Ok(())
    }

    fn finish(mut self) -> Result<Program, Vec<Located<AsmError>>> {
        if let Some(p) = self.pending.take() {
            self.error(p.line, AsmError::MissingOperand(p.mnemonic, p.needed));
        }
        if self.errors.is_empty() {
            Ok(Program {
                instructions: self.instructions,
                listing: self.listing,
                first_steps: self.first_steps,
            })
        } else {
            crate::sort::by_key(&mut self.errors, |e| e.line);
            Err(self.errors)
        }
    }
}

/// A timer or counter set value: `K` or `D` only.
fn preset_of(word: Word) -> Result<Word, AsmError> {
    match word {
        Word::K(_) | Word::D(_) => Ok(word),
        other => Err(AsmError::BadPreset(other.to_string())),
    }
}

/// Which devices a coil-like instruction may drive.
#[derive(Clone, Copy)]
struct CoilKinds {
    y: bool,
    m: bool,
    s: bool,
    c: bool,
}

impl CoilKinds {
    /// OUT, PLS, PLF: Y, M, S (OUT T/C are handled with their presets).
    const OUT: CoilKinds = CoilKinds {
        y: true,
        m: true,
        s: true,
        c: false,
    };
    /// SET, RST: Y, M, S, C.
    const SET: CoilKinds = CoilKinds {
        y: true,
        m: true,
        s: true,
        c: true,
    };
    /// SETS, RSTS: Y and M of the linked device.
    const LINK: CoilKinds = CoilKinds {
        y: true,
        m: true,
        s: false,
        c: false,
    };
}

/// M56-M59 and M63 are driven by the system; M60-M62 may be reset.
fn check_coil(mnemonic: &'static str, bit: Bit, kinds: CoilKinds) -> Result<(), AsmError> {
    let ok = match bit {
        Bit::X(_) => return Err(AsmError::OutputToInput(mnemonic, bit)),
        Bit::Y(_) => kinds.y,
        Bit::M(n) if (56..=59).contains(&n) || n == 63 => {
            return Err(AsmError::SystemRelay(mnemonic, bit));
        }
        Bit::M(60..=62) => kinds.m && mnemonic != "OUT",
        Bit::M(_) => kinds.m,
        Bit::S(_) => kinds.s,
        Bit::C(_) => kinds.c,
        Bit::T(_) => false,
    };
    if ok {
        Ok(())
    } else {
        Err(AsmError::NotAllowed(mnemonic, bit))
    }
}

/// A problem with one line of an IO86A listing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AsmError {
    /// More lines than [`crate::limits::MAX_PROGRAM_LINES`] (how many).
    TooManyLines(usize),
    /// A written step number that is not this step's.
    StepNumber {
        /// As written.
        found: String,
        /// This step's number.
        expected: usize,
    },
    /// A step number and nothing else.
    MissingInstruction,
    /// Not one of the IO86A's mnemonics.
    UnknownMnemonic(String),
    /// The instruction lacks operands (how many it takes).
    MissingOperand(&'static str, usize),
    /// Words after the operands.
    Unexpected(String),
    /// An operand line with no instruction waiting for it.
    StrayOperand(String),
    /// A bad operand.
    Operand(OperandError),
    /// OUT, SET, … to an input.
    OutputToInput(&'static str, Bit),
    /// A system relay (M56-M59, M63) as a coil.
    SystemRelay(&'static str, Bit),
    /// A device this instruction cannot drive.
    NotAllowed(&'static str, Bit),
    /// A timer or counter set value that is not K or D.
    BadPreset(String),
    /// A destination that must be a D register.
    NotARegister(&'static str, String),
    /// ORB / ANB with fewer than two blocks.
    NoBlockToJoin(&'static str),
    /// A contact or output with no LD/LDI starting its rung.
    NoRung,
    /// Over 511 steps (the count reached).
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
            AsmError::StepNumber { found, expected } => {
                write!(f, "step number {found} does not match: this is step {expected}")
            }
            AsmError::MissingInstruction => f.write_str("a step number without an instruction"),
            AsmError::UnknownMnemonic(m) => write!(
                f,
                "unknown instruction {}: PLC-IO86A has LD LDI AND ANI OR ORI ORB ANB OUT PLS PLF SET RST SETS RSTS CMP MOV INC DEC END", crate::error::shown(m)
            ),
            AsmError::MissingOperand(m, n) => match *m {
                "OUT" => f.write_str("OUT T/C needs its set value on the next step, e.g. K10"),
                _ => write!(f, "{m} needs {n} operand(s)"),
            },
            AsmError::Unexpected(w) => write!(f, "unexpected {}", crate::error::shown(w)),
            AsmError::StrayOperand(w) => {
                write!(f, "operand {w} has no instruction waiting for it (OUT T/C, MOV, CMP, INC, DEC)")
            }
            AsmError::Operand(e) => e.fmt(f),
            AsmError::OutputToInput(m, b) => write!(f, "{m} {b}: {b} is an input and cannot be driven"),
            AsmError::SystemRelay(m, b) => {
                write!(f, "{m} {b}: {b} is a system relay driven by the PLC itself")
            }
            AsmError::NotAllowed(m, b) => write!(f, "{m} cannot drive {b}"),
            AsmError::BadPreset(w) => write!(f, "set value {w}: a timer or counter takes K or D"),
            AsmError::NotARegister(m, w) => write!(f, "{m}: the destination {w} must be a D register"),
            AsmError::NoBlockToJoin(m) => write!(f, "{m} needs two blocks, each started by LD or LDI"),
            AsmError::NoRung => f.write_str("no LD or LDI starts this rung"),
            AsmError::TooManySteps(n) => write!(f, "too many steps: {n}, PLC-IO86A holds {MAX_STEPS}"),
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
    fn the_manuals_first_example_parses_with_its_numbers() {
        let text = "1 LD X00\n2 OUT Y00\n3 LDI X01\n4 OUT M00\n5 OUT T00\n6 K19\n7 LD T00\n8 OUT Y01\n9 END\n";
        let p = Program::parse(text).unwrap();
        assert_eq!(p.steps(), 9);
        assert_eq!(p.instructions()[4], Instruction::OutTimer(0, Word::K(19)));
        assert_eq!(p.listing(), text);
    }

    #[test]
    fn operands_inline_or_on_their_own_lines() {
        let a = Program::parse("LD X00\nMOV\nK10\nD00\nINC D0\nCMP D00 T03\nEND\n").unwrap();
        assert_eq!(
            a.instructions()[1..4],
            [
                Instruction::Mov(Word::K(10), 0),
                Instruction::Inc(0),
                Instruction::Cmp(Word::D(0), Word::T(3))
            ]
        );
        assert_eq!(a.steps(), 7);
    }

    #[test]
    fn bad_lines_are_located() {
        assert_eq!(
            errors("LD X00\nOUT T00\nLD X01\n"),
            vec![(2, AsmError::MissingOperand("OUT", 1))]
        );
        assert_eq!(
            errors("LD X00\nOUT X01\n"),
            vec![(2, AsmError::OutputToInput("OUT", Bit::X(1)))]
        );
        let found = errors("LD X09\nFOO\nK5\nLD X00\nORB\nOUT M57\n3 END\n");
        let lines: Vec<usize> = found.iter().map(|e| e.0).collect();
        assert_eq!(lines, vec![1, 2, 3, 5, 6, 7]);
        assert!(matches!(
            found[0].1,
            AsmError::Operand(OperandError::UnknownDevice(_))
        ));
        assert!(matches!(found[1].1, AsmError::UnknownMnemonic(_)));
        assert!(matches!(found[2].1, AsmError::StrayOperand(_)));
        assert_eq!(found[3].1, AsmError::NoBlockToJoin("ORB"));
        assert!(matches!(
            found[4].1,
            AsmError::SystemRelay("OUT", Bit::M(57))
        ));
        assert!(matches!(found[5].1, AsmError::StepNumber { .. }));
    }

    #[test]
    fn over_511_steps_is_an_error_on_step_512() {
        let ok = "LD X00\n".repeat(511);
        assert!(Program::parse(&ok).is_ok());
        let over = "LD X00\n".repeat(512);
        assert_eq!(errors(&over), vec![(512, AsmError::TooManySteps(512))]);
    }
}
