//! Why an instruction's types or a call do not fit, as kinds with their
//! arguments (`LoadError::Type`, `LoadError::Call`): the command line
//! says them in English (`Display`), the page in its own language.

use std::fmt;

use crate::iec::data::DataType;
use crate::iec::LiteralError;
use crate::runtime::ldmicro::format::FormatError;
use crate::runtime::ldmicro::printf::PrintfError;
use crate::softplc::program::user::{
    MAX_BLOCK_NESTING, MAX_BODY_STEPS, MAX_INSTANCES, MAX_INSTANCE_VARIABLES,
};

/// The current result or an operand of a type the instruction does not
/// take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TypeWhy {
    /// NEG of a BOOL or a STRING.
    NegNumber,
    /// A shift or rotation of something that is no integer.
    ShiftIntegers,
    /// A conversion to or from STRING.
    StringConversion,
    /// A conversion `from` a type the current result (`current`) is not.
    Convert {
        /// The current result's type.
        current: DataType,
        /// The type the conversion converts from.
        from: DataType,
    },
    /// SEL after a current result that is no BOOL.
    SelectBool,
    /// SEL's two values of two types.
    SelectOneType,
    /// A block's text input (`FMT`) given something that is no text.
    TextInput {
        /// The block's type.
        block: String,
        /// The input.
        pin: String,
    },
    /// A block's parameter given or taken as another type.
    Pin {
        /// The block's type.
        block: String,
        /// The parameter, as written.
        pin: String,
        /// Its type.
        is: DataType,
    },
    /// `name.pin` where `name` is no block instance.
    NotInstance {
        /// The name before the dot.
        name: String,
        /// The name after it.
        pin: String,
    },
    /// A block's output stored to (the operand as written).
    ReadOnly(String),
    /// A jump back to a label whose instruction used the current result
    /// as another type (`brings` none: not known).
    JumpBrings {
        /// The line of the label's instruction.
        line: usize,
        /// The label.
        label: String,
        /// The type used there.
        used: DataType,
        /// The type the jump brings.
        brings: Option<DataType>,
    },
    /// The ways to a label bring two types.
    LabelTypes {
        /// The label.
        label: String,
        /// One way's type and another's.
        types: (DataType, DataType),
    },
    /// A text literal that is no STRING.
    Text(LiteralError),
    /// A block instance used as a value (its name).
    BlockAsValue(String),
    /// ST, S or R to a literal.
    StoreLiteral,
    /// S or R (`op`) of something that is no BOOL.
    SetBool {
        /// The operator.
        op: String,
        /// The operand, as written.
        what: String,
        /// Its type.
        is: DataType,
    },
    /// ST of a current result of another type than the variable's.
    Store {
        /// The current result's type.
        current: DataType,
        /// The operand, as written.
        what: String,
        /// Its type.
        needs: DataType,
    },
}

/// A call that does not fit: what is called, its texts, and the
/// program's own blocks' limits (docs/limits.md).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CallWhy {
    /// CAL of no name.
    NeedsInstance,
    /// A block's C format (`LD_STRING`'s `FMT`) refused.
    Printf {
        /// The input.
        pin: String,
        /// Why.
        error: PrintfError,
    },
    /// A block's formatted string (`LD_FMTSTR`'s `FMT`) refused.
    Format {
        /// The input.
        pin: String,
        /// Why.
        error: FormatError,
    },
    /// A second text for one instance.
    TextTwice {
        /// The instance.
        instance: String,
        /// The input.
        pin: String,
    },
    /// An output given to something that is no variable.
    NotVariable(String),
    /// A block's input read as an output.
    InputRead {
        /// The instance.
        instance: String,
        /// The input.
        pin: String,
        /// The block's type.
        block: String,
    },
    /// More instances of the program's own blocks than the limit (the
    /// declaration or instance that passes it).
    Instances(String),
    /// Instances nested deeper than the limit (the declaration; the
    /// block that may hold itself, when one is found).
    Nesting {
        /// The declaration or instance.
        name: String,
        /// The block that holds itself, when known.
        holds: Option<String>,
    },
    /// The blocks' bodies' steps for their instances past the limit.
    BodySteps,
    /// The instances' variables past the limit (the declaration).
    Variables(String),
}

impl fmt::Display for TypeWhy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use TypeWhy as T;
        match self {
            T::NegNumber => f.write_str("NEG needs a number"),
            T::ShiftIntegers => {
                f.write_str("SHL, SHR, ROL and ROR shift an integer by an integer")
            }
            T::StringConversion => {
                f.write_str("conversions to and from STRING do not run on the soft PLC yet")
            }
            T::Convert { current, from } => write!(
                f,
                "the current result is {}, not {}",
                current.name(),
                from.name()
            ),
            T::SelectBool => f.write_str("SEL's first input (the current result) is a BOOL"),
            T::SelectOneType => f.write_str("SEL's two values have one type"),
            T::TextInput { block, pin } => write!(f, "{block}'s {pin} is a text: '…'"),
            T::Pin { block, pin, is } => write!(f, "{block}'s {pin} is a {}", is.name()),
            T::NotInstance { name, pin } => write!(
                f,
                "`{name}` is not a block instance: `{name}.{pin}` reads a block's output"
            ),
            T::ReadOnly(what) => write!(f, "`{what}` is a block's output: it is read, not written"),
            T::JumpBrings {
                line,
                label,
                used,
                brings,
            } => write!(
                f,
                "line {line}, after the label `{label}`, uses the current result as {}; this jump brings {}: make them one type or start there with LD",
                used.name(),
                brings.map_or("not known", DataType::name)
            ),
            T::LabelTypes { label, types } => write!(
                f,
                "the current result reaches the label `{label}` as {} and as {}: make them one type (*_TO_*) or start with LD",
                types.0.name(),
                types.1.name()
            ),
            T::Text(e) => e.fmt(f),
            T::BlockAsValue(n) => write!(
                f,
                "`{n}` is a block instance, not a value: read one of its outputs (`{n}.Q`)"
            ),
            T::StoreLiteral => f.write_str("a value is stored in a variable, not a literal"),
            T::SetBool { op, what, is } => {
                write!(f, "{op} sets or resets a BOOL: {what} is {}", is.name())
            }
            T::Store {
                current,
                what,
                needs,
            } => write!(
                f,
                "the current result is {}, {what} needs {}",
                current.name(),
                needs.name()
            ),
        }
    }
}

impl fmt::Display for CallWhy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use CallWhy as C;
        match self {
            C::NeedsInstance => f.write_str("CAL needs a block instance"),
            C::Printf { pin, error } => write!(f, "{pin}: {error}"),
            C::Format { pin, error } => write!(f, "{pin}: {error}"),
            C::TextTwice { instance, pin } => write!(
                f,
                "{instance} already has another text: one {pin} for each instance"
            ),
            C::NotVariable(target) => write!(f, "`{target}` is not a variable"),
            C::InputRead {
                instance,
                pin,
                block,
            } => write!(
                f,
                "`{instance}.{pin}`: {pin} is an input of {block}; the soft PLC gives a block's inputs in its CAL (CAL {instance}({pin} := …)) and reads only its outputs"
            ),
            C::Instances(name) => write!(
                f,
                "{name}: more than {MAX_INSTANCES} instances of the program's own blocks (docs/limits.md)"
            ),
            C::Nesting { name, holds } => {
                write!(
                    f,
                    "{name}: function blocks hold instances more than {MAX_BLOCK_NESTING} deep"
                )?;
                match holds {
                    Some(t) => write!(f, " (does {t} hold itself?)"),
                    None => Ok(()),
                }
            }
            C::BodySteps => write!(
                f,
                "the blocks' bodies need more than {MAX_BODY_STEPS} steps for their instances (docs/limits.md)"
            ),
            C::Variables(name) => write!(
                f,
                "{name}: the instances of the program's own blocks would hold more than {MAX_INSTANCE_VARIABLES} variables (docs/limits.md)"
            ),
        }
    }
}
