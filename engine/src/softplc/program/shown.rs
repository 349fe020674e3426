//! How a load error is said in English.

use std::fmt;

use super::LoadError;

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Var(e) => e.fmt(f),
            LoadError::Il(e) => e.fmt(f),
            LoadError::Undeclared(n) => write!(f, "`{n}` is not declared"),
            LoadError::UntypedAddress(a) => {
                write!(f, "{a}: the soft PLC has no byte type")
            }
            LoadError::NoLabel(l) => write!(f, "no line has the label `{l}`"),
            LoadError::Type(why) => why.fmt(f),
            LoadError::Call(why) => why.fmt(f),
            LoadError::UnknownResult => f.write_str(
                "the current result is not known here (after a label or a jump): start with LD",
            ),
            LoadError::Unbalanced => f.write_str("`(` and `)` do not pair"),
            LoadError::Unclosed => f.write_str("this `(` is never closed with `)`"),
            LoadError::Pou(e) => e.fmt(f),
            LoadError::Mix(a, b) => write!(
                f,
                "{} and {} do not mix: convert one (*_TO_*)",
                a.name(),
                b.name()
            ),
            LoadError::NotBits(op, t) => {
                write!(f, "{op} needs a BOOL or a bit string, not {}", t.name())
            }
            LoadError::NotFor(t) => write!(f, "this operation does not apply to {}", t.name()),
            LoadError::NeedsBool(op) => write!(f, "{op} needs a BOOL current result"),
            LoadError::NoPin { block, pin, output } => {
                let side = if *output { "output" } else { "input" };
                write!(f, "{block} has no {side} `{pin}`")
            }
            LoadError::NotAnInstance(n) => write!(f, "`{n}` is not a block instance"),
            LoadError::BadElement(e) => write!(
                f,
                "`{e}`: an element operand is LD's or ST's, each index an integer variable, its elements declared and of one type"
            ),
        }
    }
}
