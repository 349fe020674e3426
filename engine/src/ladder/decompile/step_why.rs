//! Why a step of a program has no ladder form, as kinds with their
//! arguments ([`super::StepError`]): the command line says them in
//! English (`Display`), the page in its own language.

use std::fmt;

use crate::limits::MAX_NESTING;

/// Why a step has no ladder form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StepWhy {
    /// The rung goes on after outputs, none of which holds its result.
    AfterOutputs,
    /// The accumulator's result used again after such outputs.
    UsedAgain,
    /// A step that needs a result with no LD before it.
    NoLoad,
    /// ORB or ANB with fewer than two blocks.
    TwoBlocks,
    /// Blocks nested past the ladder's limit (docs/limits.md).
    TooDeep,
    /// An output with no LD before it.
    OutputFirst,
    /// A label or a conditional operator (IL).
    Labels,
    /// A `)` with no `(` (IL).
    NoOpen,
    /// An IL line the ladder has no element for (the line, as written).
    Line(String),
    /// A rung that ends with a box and no output (IL).
    BoxWithoutOutput,
    /// A box in a parallel branch (IL).
    ParallelBox,
    /// A call with no power out (`Q =>`, IL).
    NoPowerOut,
    /// An edge block on a literal (IL).
    EdgeOnLiteral,
    /// A timer whose PT is no `T#` literal (IL).
    TimerPreset,
    /// A call of a block the ladder does not draw so (the instance).
    Call(String),
    /// A jump to a label no line has (IL).
    NoLabel,
    /// A function's result no box reads (IL).
    NoBoxReads,
    /// A JUMP other than a final JUMP 0 (the Arduino PLC; its operand).
    Jump(u8),
    /// A word that is no instruction (the Arduino PLC).
    Word(u16),
    /// A timer's or counter's set value from a data register (IO86A).
    RegisterValue,
    /// SETS / RSTS (IO86A).
    SecondDevice,
}

impl fmt::Display for StepWhy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use StepWhy as S;
        match self {
            S::AfterOutputs => {
                f.write_str("the rung goes on after outputs none of which holds its result")
            }
            S::UsedAgain => f.write_str(
                "the result is used again after outputs none of which holds it: store it in a relay first",
            ),
            S::NoLoad => f.write_str("no LD before this step"),
            S::TwoBlocks => f.write_str("ORB / ANB needs two blocks"),
            S::TooDeep => write!(
                f,
                "blocks nest more than {MAX_NESTING} deep here: a ladder cannot draw it (docs/limits.md)"
            ),
            S::OutputFirst => f.write_str("an output with no LD before it"),
            S::Labels => f.write_str("labels and conditional operators have no ladder form"),
            S::NoOpen => f.write_str("`)` with no `(`"),
            S::Line(line) => write!(f, "`{line}` has no ladder form yet"),
            S::BoxWithoutOutput => f.write_str(
                "a rung before this step ends with a box and no output: a ladder cannot draw it so (end the rung with LD of its power, as the compiler writes an output box, or with a coil)",
            ),
            S::ParallelBox => f.write_str("a box in a parallel branch has no ladder form here"),
            S::NoPowerOut => f.write_str("a call with no power out (Q =>) has no ladder form"),
            S::EdgeOnLiteral => f.write_str("an edge on a literal has no ladder form"),
            S::TimerPreset => {
                f.write_str("a timer's PT other than a T# literal has no ladder form here")
            }
            S::Call(block) => write!(f, "CAL {block} has no ladder form yet"),
            S::NoLabel => f.write_str("a jump to no label"),
            S::NoBoxReads => f.write_str("no box reads so"),
            S::Jump(operand) => write!(
                f,
                "JUMP {operand} has no ladder form: only a final JUMP 0 (or END)"
            ),
            S::Word(w) => write!(f, "word {w:04X} is no instruction"),
            S::RegisterValue => f.write_str(
                "a set value from a data register has no ladder form here: use a K constant",
            ),
            S::SecondDevice => {
                f.write_str("SETS / RSTS drive a second device: they have no ladder form here")
            }
        }
    }
}
