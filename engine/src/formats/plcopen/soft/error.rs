//! Why part of a PLCopen project does not run on the soft PLC, in the
//! file's terms (each at its line, as `ImportError::Soft`).

use std::fmt;

use crate::iec::{AddressError, LiteralError};

/// Why part of a project does not run on the soft PLC.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SoftError {
    /// A declaration the soft PLC cannot hold (name, why).
    Declaration(String, DeclarationWhy),
    /// An element of a drawn body it does not run (its XML name).
    Element(String),
    /// An element without a `localId` (its XML name).
    NoLocalId(String),
    /// A `localId` used twice.
    DuplicateId(String),
    /// A connection to an element that is not there.
    Missing(String),
    /// An input that needs a connection and has none (what).
    Unconnected(String),
    /// Connectors that feed themselves (a name).
    ConnectorLoop(String),
    /// A loop of wires through a block whose output type is not known
    /// yet (its type).
    Feedback(String),
    /// An expression that is no variable, address or literal.
    Expression(String),
    /// A name no declaration gives.
    Undeclared(String),
    /// A contact or coil on something that is not a BOOL variable.
    NotABit(String),
    /// A block instance declared as another type (instance, type).
    Instance(String, String),
    /// A function called with inputs it does not take (its type, why).
    Function(String, crate::iec::functions::FunctionError),
    /// A call of one of the project's own POUs.
    ProjectBlock(String, String),
    /// A block type the soft PLC does not have.
    Block(String),
    /// No program the tasks run has a drawn body: each POU and its
    /// language.
    NotDrawn(String),
    /// The generated program does not load (the loader's reason).
    Load(crate::softplc::LoadError),
    /// A section's word (`VAR_INPUT`, `END_PROGRAM` …) in an IL body.
    BodySection(String),
    /// A block input the block does not have (the block, the pin, the
    /// inputs it has).
    NoInput(String, String, String),
    /// A wire from a block output the block does not have (what the wire
    /// feeds, the block, the pin, the outputs it has).
    NoOutput(String, String, String, String),
    /// An element fed by one already refused: never shown, the first
    /// refusal says what is wrong (it was called a loop of wires).
    Follows,
    /// A vendor element that carries logic (why it is taken to).
    VendorLogic(String),
    /// An instance of the project's own function block that no variable
    /// declares (instance, type).
    UndeclaredInstance(String, String),
    /// A Structured Text body's or EXECUTE block's problem: its column
    /// in the ST line, and why.
    St(usize, crate::iec::st::StErrorKind),
    /// A call of the project's own block or function whose external
    /// variable the calling POU has no variable for (the callee's type,
    /// the external's name, the calling POU).
    NoGlobal(String, String, String),
}

impl fmt::Display for SoftError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SoftError::Declaration(name, why) => write!(f, "variable {name}: {why}"),
            SoftError::Element(e) => {
                let what = match e.as_str() {
                    "vendorElement" => " (an element of the tool that wrote the file)",
                    "jump" | "label" | "return" => " (jumps are not run yet)",
                    "actionBlock"
                    | "step"
                    | "transition"
                    | "selectionDivergence"
                    | "selectionConvergence"
                    | "simultaneousDivergence"
                    | "simultaneousConvergence"
                    | "macroStep" => " (SFC is not run)",
                    _ => "",
                };
                write!(f, "<{e}> does not run on the soft PLC{what}")
            }
            SoftError::NoLocalId(e) => write!(f, "<{e}> has no localId"),
            SoftError::DuplicateId(id) => write!(f, "localId {id} is used twice"),
            SoftError::Missing(id) => write!(f, "a connection to {id}, which is not drawn"),
            SoftError::Unconnected(what) => write!(f, "{what} is not connected"),
            SoftError::ConnectorLoop(name) => write!(f, "connector {name} feeds itself"),
            SoftError::Feedback(ty) => write!(
                f,
                "{ty} block: a loop of wires through it whose type nothing gives: type a literal in the loop (INT#1) or break it with a variable"
            ),
            SoftError::Expression(x) => {
                write!(f, "`{x}` is not a variable, an address or a literal")
            }
            SoftError::Undeclared(name) => write!(f, "`{name}` is not declared"),
            SoftError::NotABit(name) => write!(f, "{name} is not a BOOL variable"),
            SoftError::Instance(name, ty) => {
                write!(f, "{name} is not declared as a {ty} instance")
            }
            SoftError::Function(ty, why) => write!(f, "{ty}: {why}"),
            SoftError::ProjectBlock(name, how) => write!(
                f,
                "{name} is the project's own {how}: the soft PLC runs the project's function blocks drawn in LD or FBD or written in IL or ST"
            ),
            SoftError::Block(name) if name.eq_ignore_ascii_case("EXECUTE") => write!(
                f,
                "{name} is CODESYS's block of in-line ST, and this one holds none (no STCode)"
            ),
            SoftError::Block(name) => write!(
                f,
                "{name} is not a standard block the soft PLC has (a vendor's or a library's block)"
            ),
            SoftError::NotDrawn(pous) => {
                write!(
                    f,
                    "no program the tasks run is drawn in LD or FBD or written in IL or ST: {pous}"
                )
            }
            SoftError::Load(why) => why.fmt(f),
            SoftError::BodySection(word) => write!(
                f,
                "`{word}` in an IL body: the body holds instructions alone, its variables are the POU's interface"
            ),
            SoftError::NoInput(block, pin, has) => {
                write!(f, "{block} has no input `{pin}` (its inputs: {has})")
            }
            SoftError::NoOutput(reader, block, pin, has) => write!(
                f,
                "{reader} is wired from {block}'s `{pin}`, an output the block does not have (its outputs: {has})"
            ),
            SoftError::VendorLogic(why) => {
                f.write_str(&crate::formats::plcopen::vendor::logic_refused(why))
            }
            SoftError::Follows => f.write_str("fed by an element refused above"),
            SoftError::St(column, why) => write!(f, "ST, column {column}: {why}"),
            SoftError::NoGlobal(ty, name, pou) => no_global(f, ty, name, pou),
            SoftError::UndeclaredInstance(name, ty) => write!(
                f,
                "{name} is not declared: declare it as a {ty} instance (`{name} : {ty};`) among the POU's variables"
            ),
        }
    }
}

/// [`SoftError::NoGlobal`]'s message.
fn no_global(f: &mut fmt::Formatter<'_>, ty: &str, name: &str, pou: &str) -> fmt::Result {
    write!(
        f,
        "{ty} reaches `{name}` as an external variable, and {pou} has no `{name}` to give it: declare `{name}` among the configuration's or resource's globalVars (and as an external variable of a block that calls {ty})"
    )
}

impl std::error::Error for SoftError {}

/// Why the soft PLC cannot hold a declaration.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DeclarationWhy {
    /// Its name is no IEC name.
    NotIecName,
    /// It has no type.
    NoType,
    /// A type the soft PLC has not (its name, upper case).
    UnknownType(String),
    /// Its address refused.
    Address(AddressError),
    /// Its initial value refused.
    Initial(LiteralError),
    /// Variables of a kind a function block cannot have yet (the
    /// section's XML name: `inOutVars`).
    Section(String),
    /// An external variable of a function block that holds a block
    /// instance (a global TON): only values are copied into a block.
    ExternalBlock,
}

impl fmt::Display for DeclarationWhy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DeclarationWhy::NotIecName => f.write_str("not an IEC name"),
            DeclarationWhy::NoType => f.write_str("no type"),
            DeclarationWhy::UnknownType(t) => {
                write!(f, "type {t} is not one the soft PLC has (docs/soft-plc.md)")
            }
            DeclarationWhy::Address(e) => e.fmt(f),
            DeclarationWhy::Initial(e) => e.fmt(f),
            DeclarationWhy::Section(scope) => {
                write!(f, "{scope} in a function block is not supported yet")
            }
            DeclarationWhy::ExternalBlock => f.write_str(
                "a block instance as a function block's external variable does not run yet (a block's externals are values, copied in at each call)",
            ),
        }
    }
}
