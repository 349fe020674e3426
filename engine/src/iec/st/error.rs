//! Why a Structured Text source is refused: one flat list of kinds, each
//! shown in plain English after the line and column it is found at.

use std::fmt;

use super::ast::{Elementary, Span};
use crate::iec::address::AddressError;
use crate::iec::literal::LiteralError;

/// The deepest nesting of parentheses, calls and statements the parser
/// follows; deeper text is refused rather than risk the stack.
pub const MAX_DEPTH: usize = 64;

/// A refusal and where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StError {
    /// Where the problem starts.
    pub span: Span,
    /// What it is.
    pub kind: StErrorKind,
}

/// What is wrong with a Structured Text source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StErrorKind {
    /// A character no token starts with.
    UnexpectedChar(char),
    /// A `(*` comment never closed.
    UnclosedComment,
    /// A `'…'` string never closed on its line.
    UnclosedString,
    /// A literal that is not one (the text and why).
    BadLiteral(String, LiteralError),
    /// A typed literal outside its type's range (the text and the type).
    LiteralOutOfRange(String, Elementary),
    /// A direct address (`%IX0.0`) that is not one.
    BadAddress(AddressError),
    /// A typed literal whose type prefix is not a type a literal can
    /// have (`FOO#1`).
    BadLiteralType(String),
    /// Something else was needed here: what, after what, and the token
    /// found instead.
    Expected {
        /// What was needed (`THEN`, `an expression`).
        what: &'static str,
        /// Where, in words (`after the IF condition`).
        context: &'static str,
        /// The token found, as written (or `the end of the text`).
        found: String,
    },
    /// A feature Hashigo's Structured Text leaves out (named).
    Unsupported(&'static str),
    /// Something that parses and checks but does not run on the soft
    /// PLC yet (named).
    NotYet(String),
    /// A VAR_IN_OUT given an expression, not a variable (the pin).
    InOutArgument(String),
    /// A keyword used where a name is needed.
    ReservedWord(String),
    /// Nesting deeper than [`MAX_DEPTH`].
    TooDeep,
    /// A STRING's length below 1 or a negative repeat count.
    BadBound(String),
    /// An array's dimension whose low bound is above its high one.
    EmptyRange(i128, i128),
    /// A positional argument after a named one.
    PositionalAfterNamed,
    /// A name no declaration in scope gives.
    UnknownName(String),
    /// A type name that is neither elementary, declared nor a block.
    UnknownType(String),
    /// A name declared twice in one scope.
    DuplicateName(String),
    /// `x.m` where `x`'s type (given) has no member `m`.
    NoMember {
        /// The member asked for.
        member: String,
        /// The type of what it is asked of.
        of: String,
    },
    /// `x[i]` where `x` is no array (`dims` 0), or with another number
    /// of indices than its dimensions.
    BadIndex {
        /// The variable indexed.
        name: String,
        /// Its dimensions (0: not an array).
        dims: usize,
        /// The indices written.
        given: usize,
    },
    /// An element at a constant index outside its array's bounds (the
    /// element as written, upper-case).
    IndexOutOfRange(String),
    /// A value of one type where another is needed: where, the type
    /// needed and the type found.
    Mismatch {
        /// Where, in words (`the IF condition`).
        place: &'static str,
        /// What is needed.
        want: String,
        /// What was found.
        found: String,
    },
    /// `EXIT` outside any loop.
    ExitOutsideLoop,
    /// A constant, or a block instance's output, assigned (as written).
    ReadOnly(String),
    /// A call of something that is neither a function nor a block
    /// instance.
    NotCallable(String),
    /// A call's argument the callee has no input or output of.
    NoSuchArg {
        /// The callee.
        callee: String,
        /// The argument's name.
        arg: String,
    },
}

impl fmt::Display for StError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "line {}, column {}: {}",
            self.span.line, self.span.column, self.kind
        )
    }
}

impl fmt::Display for StErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StErrorKind::UnexpectedChar(c) => write!(f, "unexpected character '{c}'"),
            StErrorKind::UnclosedComment => write!(f, "this (* comment is never closed with *)"),
            StErrorKind::UnclosedString => write!(f, "this string is not closed on its line"),
            StErrorKind::BadLiteral(text, why) => write!(f, "bad literal `{text}`: {why}"),
            StErrorKind::LiteralOutOfRange(text, t) => match t.range() {
                Some((lo, hi)) => {
                    write!(f, "`{text}` is out of range for {} ({lo} … {hi})", t.name())
                }
                None => write!(f, "`{text}` is not a {} value", t.name()),
            },
            StErrorKind::BadAddress(e) => write!(f, "{e}"),
            StErrorKind::BadLiteralType(t) => write!(f, "`{t}#` is not a type a literal can have"),
            StErrorKind::Expected {
                what,
                context,
                found,
            } => write!(f, "expected {what} {context}, found {found}"),
            StErrorKind::InOutArgument(pin) => write!(f, "the VAR_IN_OUT {pin} takes a variable"),
            StErrorKind::NotYet(what) => write!(f, "{what} does not run on the soft PLC yet"),
            StErrorKind::Unsupported(what) => {
                write!(f, "{what} not supported by Hashigo's Structured Text")
            }
            StErrorKind::ReservedWord(w) => {
                write!(f, "`{w}` is a keyword and cannot be used as a name")
            }
            StErrorKind::TooDeep => write!(
                f,
                "nested more than {MAX_DEPTH} levels deep (parentheses, calls or statements)"
            ),
            StErrorKind::BadBound(t) => write!(
                f,
                "`{t}` cannot be a length or a count (a STRING's length is 1 or more, a repeat count 0 or more)"
            ),
            StErrorKind::EmptyRange(low, high) => write!(
                f,
                "the range {low}..{high} is empty: its low bound is above its high one"
            ),
            StErrorKind::PositionalAfterNamed => write!(
                f,
                "a positional argument cannot follow a named one (name every argument or none)"
            ),
            StErrorKind::UnknownName(n) => write!(f, "`{n}` is not declared"),
            StErrorKind::UnknownType(n) => write!(
                f,
                "`{n}` is not a type (an elementary type, a TYPE, a function block)"
            ),
            StErrorKind::DuplicateName(n) => write!(f, "`{n}` is declared twice"),
            StErrorKind::NoMember { member, of } => write!(f, "{of} has no member `{member}`"),
            StErrorKind::BadIndex { name, dims: 0, .. } => write!(f, "`{name}` is not an array"),
            StErrorKind::BadIndex { name, dims, given } => {
                write!(
                    f,
                    "`{name}` has {dims} dimension(s); {given} index(es) given"
                )
            }
            StErrorKind::IndexOutOfRange(e) => write!(f, "`{e}` is outside the array's bounds"),
            StErrorKind::Mismatch { place, want, found } => {
                write!(f, "{place} must be {want}, not {found}")
            }
            StErrorKind::ExitOutsideLoop => write!(f, "EXIT is only allowed inside a loop"),
            StErrorKind::ReadOnly(n) => write!(
                f,
                "`{n}` cannot be assigned (a constant, or a block's output, which only the block writes)"
            ),
            StErrorKind::NotCallable(n) => {
                write!(
                    f,
                    "`{n}` is neither a function nor a function block instance"
                )
            }
            StErrorKind::NoSuchArg { callee, arg } => {
                write!(f, "`{callee}` has no input or output `{arg}`")
            }
        }
    }
}

impl std::error::Error for StError {}
