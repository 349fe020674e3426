//! What a PLCopen import drops or changes without refusing the file,
//! typed (issue #49: the page says each in its own language); its
//! `Display` is the command line's English.

use std::fmt;

/// One warning of an import, said at its line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ImportWarning {
    /// A block's `ET` or `CV` feeds only a variable: dropped (the pin,
    /// the variable as written).
    WordOutputDropped(String, String),
    /// A vendor element with no logic, skipped (what it says it is).
    VendorSkipped(String),
    /// A name used on a contact or coil that nothing declares: taken as
    /// a BOOL variable.
    TakenAsBool(String),
    /// A compared variable that is IO86A's analog register (the variable,
    /// the register, the analog input).
    AnalogRange {
        /// The file's variable.
        expr: String,
        /// The data register, D06 or D07.
        register: String,
        /// The analog input behind it, X04 or X05.
        input: String,
    },
    /// A compared variable is a constant register holding the value the
    /// file declares (the block, its pin, the register, the variable).
    DeclaredValue {
        /// The compare block.
        what: String,
        /// Its pin.
        pin: &'static str,
        /// The data register given the value.
        register: String,
        /// The file's variable.
        expr: String,
    },
    /// A relay the import took to hold an intermediate value (the relay,
    /// what it holds).
    Helper(String, String),
    /// A variable that starts on in the file but off on the machine (its
    /// name, the value, the machine's name, the device).
    StartsOff {
        /// The file's variable.
        name: String,
        /// Its initial value as written.
        value: String,
        /// The machine's name.
        machine: String,
        /// The device it took.
        device: String,
    },
    /// A POU no task runs, skipped (its kind, its name).
    NoTask(String, String),
    /// An element that leads to no coil, dropped (as drawn).
    LeadsNowhere(String),
}

impl fmt::Display for ImportWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ImportWarning as W;
        match self {
            W::WordOutputDropped(pin, expr) => write!(
                f,
                "the block's {pin} feeds only the variable {}: dropped (Hashigo's ladders carry no word outputs)",
                crate::shown(expr)
            ),
            W::VendorSkipped(what) => write!(f, "{what} skipped: a vendor's own element"),
            W::TakenAsBool(name) => write!(f, "{name} is not declared: taken as a BOOL variable"),
            W::AnalogRange {
                expr,
                register,
                input,
            } => write!(
                f,
                "{expr} is {register}, {input}'s analog value: set {input}'s analog range ({input}A:n1:n2) so that it counts in the file's units"
            ),
            W::DeclaredValue {
                what,
                pin,
                register,
                expr,
            } => write!(
                f,
                "{what}'s {pin} is {register}, the value {expr} is declared with (nothing in the program writes it)"
            ),
            W::Helper(relay, what) => {
                write!(f, "{relay} holds {what} (a relay the file does not use)")
            }
            W::StartsOff {
                name,
                value,
                machine,
                device,
            } => write!(
                f,
                "{name} starts at {value} in the file, but {machine} starts {device} off at power-up"
            ),
            W::NoTask(kind, name) => write!(
                f,
                "{kind} {name} skipped: no task runs it (--pou {name} imports it alone)"
            ),
            W::LeadsNowhere(leaf) => write!(f, "{leaf} leads to no coil: dropped"),
        }
    }
}
