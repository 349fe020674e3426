//! Why a PLCopen file could not be read or imported, each at its line
//! (`Located<ImportError>`).

use std::fmt;

use super::{NS_V10, NS_V201};
use crate::error::shown;
use crate::ladder::net::{NetError, TooLarge};
use crate::ladder::target::ElementError;
use crate::limits::{MAX_GATE_WORK, MAX_RUNGS};

pub use super::dom::XmlError;

/// Why a block could not be lowered to ladder (the lowering phase's
/// error; [`ImportError::Gate`] names the block).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LowerError {
    /// A pin the block needs is missing.
    NoPin(&'static str),
    /// An XOR of more than two inputs.
    XorInputs,
    /// A flip-flop without both S and R.
    FlipPins,
    /// A comparison on a machine without IO86A's CMP.
    NoCompare,
    /// A count gate on something that is not a counter.
    NotCounter,
    /// A spare relay is needed and none is free.
    NoRelay,
    /// A contact that cannot become the kind needed (why).
    Contact(&'static str),
    /// An OR left for the one-by-one lowering (ORs are joined first).
    OrNotJoined,
    /// Lowering would pass [`MAX_GATE_WORK`].
    TooMuchWork,
}

impl fmt::Display for LowerError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LowerError::NoPin(pin) => write!(f, "no {pin}"),
            LowerError::XorInputs => f.write_str("XOR of more than two inputs: draw the branches"),
            LowerError::FlipPins => f.write_str("a flip-flop has S and R"),
            LowerError::NoCompare => {
                f.write_str("comparisons need IO86A's CMP and its flags M60-M62")
            }
            LowerError::NotCounter => f.write_str("not a counter"),
            LowerError::NoRelay => f.write_str(
                "a relay must hold part of it and none is free: map fewer names to relays",
            ),
            LowerError::Contact(why) => f.write_str(why),
            LowerError::OrNotJoined => f.write_str("an OR is lowered with the joins of wires"),
            LowerError::TooMuchWork => write!(
                f,
                "the file's blocks take more than {MAX_GATE_WORK} steps to lower (docs/limits.md)"
            ),
        }
    }
}

impl std::error::Error for LowerError {}

/// Every problem of an import, each at its line.
pub(super) type Errors = Vec<crate::error::Located<ImportError>>;

/// What is wrong with an element's input connection.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Connection {
    /// A `<connection>` with no `refLocalId`.
    NoRef,
    /// It names a `localId` no element has.
    Missing(String),
    /// It takes power from a variable box (`inVariable`).
    FromVariable(String),
    /// Nothing is connected.
    Unconnected,
    /// A continuation names a connector that is not drawn (its name).
    NoConnector(String),
    /// Connectors that feed themselves through continuations (a name).
    ConnectorLoop(String),
    /// More connectors in a row than [`crate::limits::MAX_CONNECTOR_CHAIN`]
    /// (the one past it).
    ConnectorChain(String),
    /// A wire from an output a standard block does not have.
    NoOutput {
        /// The block (`TON block t0`).
        block: String,
        /// The pin the wire names.
        pin: String,
        /// The outputs it has.
        has: String,
    },
}

/// Why a PLCopen file could not be imported.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ImportError {
    /// Not XML the reader takes.
    Xml(XmlError),
    /// The root element is not `<project>` (its name).
    NotAProject(String),
    /// A namespace that is not PLCopen TC6's.
    Namespace(String),
    /// No POU has an LD or FBD body (each POU in its language).
    NoDrawnBody(String),
    /// More rungs than [`MAX_RUNGS`].
    TooManyRungs,
    /// A rung too large to draw.
    Drawing(TooLarge),
    /// An element without `localId` (its name).
    NoLocalId(String),
    /// A `localId` given twice.
    DuplicateLocalId {
        /// The id.
        id: String,
        /// The line of its first use.
        first: usize,
    },
    /// A connector name drawn twice in one body.
    DuplicateConnector {
        /// The name.
        name: String,
        /// The line of its first connector.
        first: usize,
    },
    /// A bad input connection of `what`.
    Connection {
        /// The element (`contact X00`, `TON block T1`).
        what: String,
        /// What is wrong.
        problem: Connection,
    },
    /// A contact or coil (`kind`) without a variable.
    NoVariable(&'static str),
    /// A declared variable with no device (the declarations' words).
    Variable(super::declare::NameError),
    /// A boolean block that cannot be lowered (the block, why).
    Gate(String, super::gate_why::GateWhy),
    /// A block that could not be lowered (`AND block`, why).
    Lower(String, LowerError),
    /// `--pou` names no POU of the file (the name, the file's POUs).
    NoSuchPou(String, String),
    /// The programs that run have no LD or FBD body (theirs, the POUs
    /// with one).
    NoDrawnInPrograms(String, String),
    /// A negated edge contact (its device).
    NegatedEdge(String),
    /// A coil mixing negated / storage / edge (its device).
    CoilMix(String),
    /// `negated=` that is not an XML boolean (as written).
    NotBoolean(String),
    /// `edge=` that is not none, rising or falling.
    BadEdge(String),
    /// `storage=` that is not none, set or reset.
    BadStorage(String),
    /// `outVariable` / `inOutVariable` (its name).
    WordOutput(String),
    /// An element Hashigo does not import (its name).
    Unsupported(String),
    /// A vendor element that carries logic (why it is taken to).
    VendorLogic(String),
    /// Part of the project the soft PLC does not run.
    Soft(super::soft::error::SoftError),
    /// A block type Hashigo does not import.
    UnsupportedBlock(String),
    /// A block the soft PLC's page cannot draw as a box (the block, why).
    SoftBox(String, super::BoxProblem),
    /// A declaration the soft PLC ladder's variables cannot hold.
    SoftVariable(crate::ladder::variables::VariableError),
    /// A name declared twice with different types.
    SoftVariableTwice {
        /// The name.
        name: String,
        /// The line of its first declaration.
        first: usize,
        /// The first type and this one.
        types: (String, String),
    },
    /// A block that calls one of the project's own POUs (its name and
    /// the language of its body).
    ProjectBlock(String, String),
    /// A block pin with nothing connected (block, pin).
    PinNotConnected(String, &'static str),
    /// A block pin not fed by a literal (block, pin).
    PinNotLiteral(String, &'static str),
    /// A PT that is not a time literal (block, text).
    BadTimeLiteral(String, String),
    /// A PV that is not 0..32767 (block, text).
    BadCounterPreset(String, String),
    /// A CTU whose Q feeds other elements (its instance).
    CounterQWired(String),
    /// A TON used as a timer coil, named unlike T00-T31.
    TimerName(String),
    /// A timer coil's time not a whole number of its units.
    TimerUnits {
        /// The timer.
        name: String,
        /// The time in ms.
        ms: u32,
        /// Its unit in ms.
        base: u32,
    },
    /// A timer coil's time above K32767 units (name, ms).
    TimerTooLong(String, u32),
    /// The machine cannot take an element.
    Element(ElementError),
    /// An output wired straight to the rail (the element).
    OnRail(String),
    /// An output no path reaches (the element).
    NoPath(String),
    /// The network is not series-parallel, or too deep.
    Net(NetError),
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use ImportError as E;
        match self {
            E::Xml(e) => e.fmt(f),
            E::NotAProject(root) => {
                write!(f, "not a PLCopen project: the root element is <{root}>")
            }
            E::Namespace(ns) => write!(
                f,
                "namespace {} is not PLCopen TC6 ({NS_V201} or {NS_V10})",
                shown(ns)
            ),
            E::NoDrawnBody(pous) => write!(
                f,
                "the project has no POU with an LD or FBD body ({pous}): Hashigo imports ladder (LD) and function block diagram (FBD) bodies"
            ),
            E::TooManyRungs => {
                write!(f, "the project has more than {MAX_RUNGS} rungs (docs/limits.md)")
            }
            E::Drawing(e) => e.fmt(f),
            E::NoLocalId(el) => write!(f, "<{el}> has no localId"),
            E::DuplicateLocalId { id, first } => write!(
                f,
                "localId {} is used again (first on line {first}): every element needs its own",
                shown(id)
            ),
            E::DuplicateConnector { name, first } => write!(
                f,
                "connector {} is drawn again (first on line {first}): a continuation must name one",
                shown(name)
            ),
            E::Connection { what, problem } => connection(f, what, problem),
            E::NoVariable(kind) => write!(f, "a {kind} with no variable"),
            E::Variable(why) => why.fmt(f),
            E::Gate(what, why) => write!(f, "{what}: {why}"),
            E::Lower(what, why) => write!(f, "{what}: {why}"),
            E::NoSuchPou(name, all) => write!(f, "no POU is named {name}: the file has {all}"),
            E::NoDrawnInPrograms(run, ld) => write!(
                f,
                "the programs the tasks run ({run}) have no LD or FBD body: Hashigo imports ladder (LD) and function block diagram (FBD) bodies; these POUs have one: {ld} (--pou NAME imports one)"
            ),
            E::NegatedEdge(d) => write!(
                f,
                "contact {d}: a negated edge contact has no ladder form here"
            ),
            E::CoilMix(d) => write!(
                f,
                "coil {d}: this mix of negated / storage / edge has no ladder form here"
            ),
            E::NotBoolean(v) => write!(
                f,
                "negated={} is not a boolean: true, false, 1 or 0",
                shown(v)
            ),
            E::BadEdge(v) => write!(f, "edge={} is not none, rising or falling", shown(v)),
            E::BadStorage(v) => write!(f, "storage={} is not none, set or reset", shown(v)),
            E::WordOutput(el) => write!(
                f,
                "<{el}> is not imported: Hashigo's ladders have no word outputs from blocks"
            ),
            E::Unsupported(el) => write!(f, "<{el}> is not supported in LD or FBD bodies here"),
            E::VendorLogic(why) => f.write_str(&super::vendor::logic_refused(why)),
            E::Soft(e) => e.fmt(f),
            E::UnsupportedBlock(ty) => write!(
                f,
                "block {} is not supported: Hashigo imports {} and the comparisons {}",
                shown(ty).trim_matches('"'),
                super::kinds::names(false),
                super::kinds::names(true)
            ),
            E::SoftBox(what, problem) => write!(f, "{what}: {problem}"),
            E::SoftVariable(e) => write!(f, "variable {e}"),
            E::SoftVariableTwice { name, first, types } => write!(
                f,
                "{name} is declared as {} here and as {} at line {first}: the ladder's variables are one set",
                types.1, types.0
            ),
            E::ProjectBlock(name, language) => write!(
                f,
                "block {name} calls the project's own {language} function block: a ladder's box is one of the project's Structured Text blocks (its pins of elementary types, none in-out) (import it alone with --pou {name} if it is LD or FBD)"
            ),
            E::PinNotConnected(what, pin) => {
                write!(f, "{what}: its {pin} input is not connected")
            }
            E::PinNotLiteral(what, pin) => write!(
                f,
                "{what}: its {pin} input must come from a literal (an inVariable)"
            ),
            E::BadTimeLiteral(what, expr) => write!(
                f,
                "{what}: PT {} is not a time literal like T#500ms",
                shown(expr)
            ),
            E::BadCounterPreset(what, expr) => write!(
                f,
                "{what}: PV {} is not a whole number 1..32767 (a counter done from the start, PV 0, has no ladder form here)",
                shown(expr)
            ),
            E::CounterQWired(d) => write!(
                f,
                "CTU {d}: read the counter with a contact on {d} instead of wiring its Q on"
            ),
            E::TimerName(name) => write!(
                f,
                "TON {name}: its Q drives nothing, which makes it a timer coil, and then it must be named like a timer (T00-T31)"
            ),
            E::TimerUnits { name, ms, base } => write!(
                f,
                "TON {name}: {ms} ms is not a whole number of {name}'s {base} ms units"
            ),
            E::TimerTooLong(name, ms) => write!(f, "TON {name}: {ms} ms is too long"),
            E::Element(e) => e.fmt(f),
            E::OnRail(el) => write!(
                f,
                "{el} is wired straight to the left rail: put a contact before it"
            ),
            E::NoPath(el) => write!(f, "no path joins the left rail to {el}"),
            E::Net(NetError::NotSeriesParallel(_)) => f.write_str(
                "this network is not series-parallel: Hashigo's ladders are series and parallel blocks",
            ),
            E::Net(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for ImportError {}

impl ImportError {
    /// The error as the page says it: the command line's advice (`--pou
    /// NAME`) becomes the page's (its import dialog's Program picker),
    /// since a page user has no command line (issue #49). The CLI says
    /// [`fmt::Display`]'s words.
    pub fn in_page(&self) -> String {
        match self {
            ImportError::NoDrawnInPrograms(run, ld) => format!(
                "the programs the tasks run ({run}) have no LD or FBD body: Hashigo imports ladder (LD) and function block diagram (FBD) bodies; these POUs have one: {ld} (choose one under Program)"
            ),
            ImportError::ProjectBlock(name, language) => format!(
                "block {name} calls the project's own {language} function block: a ladder's box is one of the project's Structured Text blocks (its pins of elementary types, none in-out) (choose {name} under Program if it is LD or FBD)"
            ),
            other => other.to_string(),
        }
    }
}

impl From<XmlError> for ImportError {
    fn from(e: XmlError) -> Self {
        ImportError::Xml(e)
    }
}

/// A [`Connection`] problem of `what` in words.
fn connection(f: &mut fmt::Formatter<'_>, what: &str, problem: &Connection) -> fmt::Result {
    match problem {
        Connection::NoRef => write!(f, "a connection of the {what} has no refLocalId"),
        Connection::Missing(r) => write!(
            f,
            "the {what} connects to localId {}, which does not exist",
            shown(r)
        ),
        Connection::FromVariable(r) => write!(
            f,
            "the {what} takes power from a variable box (localId {}): wire it from the rail through a contact",
            shown(r)
        ),
        Connection::Unconnected => write!(f, "the {what} is not connected on its left"),
        Connection::NoConnector(name) => write!(
            f,
            "the {what} takes power from continuation {}, whose connector is not drawn",
            shown(name)
        ),
        Connection::ConnectorChain(name) => write!(
            f,
            "the {what} passes through more than {} connectors in a row (at {}; docs/limits.md)",
            crate::limits::MAX_CONNECTOR_CHAIN,
            shown(name)
        ),
        Connection::ConnectorLoop(name) => write!(
            f,
            "the {what} takes power from connector {}, which feeds itself through its continuations",
            shown(name)
        ),
        Connection::NoOutput { block, pin, has } => write!(
            f,
            "{what} is wired from {block}'s `{}`, an output the block does not have (its outputs: {has})",
            shown(pin).trim_matches('"')
        ),
    }
}
