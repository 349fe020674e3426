//! Why a boolean, counter or compare block cannot be lowered for a bit
//! machine, typed (issue #49: the page says it in its own language); its
//! `Display` is the command line's English.

use std::fmt;

/// The input pins of a comparison Hashigo reads, in order (IEC extends
/// GT, GE, EQ, LE and LT to more inputs).
pub const COMPARED: [&str; 8] = ["IN1", "IN2", "IN3", "IN4", "IN5", "IN6", "IN7", "IN8"];

/// The reason of an [`super::ImportError::Gate`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GateWhy {
    /// An SR or RS block's state needs a relay (the variable it writes).
    NeedsRelay(String),
    /// A pin marked negated (the pin).
    Negated(String),
    /// A pin marked with an edge (the pin, `rising` or `falling`).
    Edge(String, &'static str),
    /// An input the block does not have (the pin, the inputs it has).
    NoInput(String, String),
    /// EN is wired.
    EnableWired,
    /// A gate with fewer than two inputs.
    NeedsTwo,
    /// A CTUD's CD or LD is wired (the pin).
    CounterWired(&'static str),
    /// A compare with a wrong number of inputs (how many, the block's
    /// type, whether it takes exactly two).
    Inputs(usize, String, bool),
    /// A compare's inputs not IN1, IN2, … in order (as written).
    InputsOrder(String),
    /// A compared operand that is no word (the pin, the text, why).
    Operand(&'static str, String, OperandWhy),
}

/// Why a compared operand is no word of the machine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OperandWhy {
    /// Neither a whole number 0..32767 nor a variable.
    NotNumber,
    /// A variable of another type (the type).
    Declared(String),
    /// A variable with no word device (its name).
    NoWord(String),
}

impl fmt::Display for GateWhy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use GateWhy as G;
        match self {
            G::NeedsRelay(w) => write!(f, "its state needs a relay: map it (--map {w},M10)"),
            G::Negated(pin) => write!(f, "its pin {pin} is negated: put a NOT block on it instead"),
            G::Edge(pin, e) => write!(
                f,
                "its pin {pin} is marked {e}: put an R_TRIG or F_TRIG block on it instead"
            ),
            G::NoInput(pin, has) => write!(f, "it has no input `{pin}` (its inputs: {has})"),
            G::EnableWired => f.write_str(
                "its EN is wired: Hashigo's blocks always run; connect EN to the left rail or leave it open",
            ),
            G::NeedsTwo => f.write_str("it needs two inputs"),
            G::CounterWired(pin) => write!(
                f,
                "its {pin} is wired: the machine's counters count up only and cannot be loaded; Hashigo takes a CTUD whose CD and LD are unused"
            ),
            G::Inputs(n, ty, two) => {
                let takes = if *two { "two" } else { "two or more" };
                write!(f, "it has {n} inputs: {ty} compares {takes}")
            }
            G::InputsOrder(pins) => write!(
                f,
                "its inputs are {pins}: Hashigo reads IN1, IN2, … up to IN{}, in order",
                COMPARED.len()
            ),
            G::Operand(pin, expr, why) => {
                write!(f, "{pin} {}: ", crate::shown(expr))?;
                match why {
                    OperandWhy::NotNumber => {
                        f.write_str("is not a whole number 0..32767 or a variable")
                    }
                    OperandWhy::Declared(ty) => write!(
                        f,
                        "is declared {ty}: a comparison takes numbers (IEC compares values of one type)"
                    ),
                    OperandWhy::NoWord(expr) => write!(
                        f,
                        "is no word: map it to a data register (--map {},D00)",
                        expr.trim()
                    ),
                }
            }
        }
    }
}
