//! One body as a graph: electrical points joined by edges (contacts,
//! in-line boxes), the outputs fed from points, and the boolean blocks
//! waiting to be lowered. Reading ([`super::read`]), lowering
//! ([`super::gates`], [`super::blocks`]) and laying out
//! ([`crate::formats::plcopen::rungs`]) each add their methods; this file holds the data
//! and the union-find over points.

use std::collections::{HashMap, HashSet};

use crate::error::Located;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::error::Errors;
use crate::formats::plcopen::warning::ImportWarning;
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;
use crate::MachineId;

/// One LD body as a graph of points.
#[derive(Default)]
pub(in crate::formats::plcopen) struct Body {
    pub(in crate::formats::plcopen) parent: Vec<usize>,
    pub(in crate::formats::plcopen) points: HashMap<(String, String), usize>,
    pub(in crate::formats::plcopen) rails: HashSet<String>,
    /// Each element's kind (its XML name) and line, by localId.
    pub(in crate::formats::plcopen) kinds: HashMap<String, Lined<String>>,
    /// Named connectors' inputs (by lower-case name) and lines; a
    /// continuation of the same name carries what feeds them.
    pub(in crate::formats::plcopen) connectors: HashMap<String, Lined<Node>>,
    /// Each continuation's connector name (lower case), by localId.
    pub(in crate::formats::plcopen) continuations: HashMap<String, String>,
    /// The connectors being followed (a loop of them is refused).
    pub(in crate::formats::plcopen) following: HashSet<String>,
    /// Each variable box's expression and line, by localId.
    pub(in crate::formats::plcopen) literals: HashMap<String, Lined<String>>,
    /// Each block's EN connections, by localId.
    pub(in crate::formats::plcopen) enables: HashMap<String, Vec<PinRef>>,
    /// Variable boxes that feed power: a contact of their device from
    /// the rail, NC when the box is negated (or why the variable has no
    /// device; its place).
    pub(in crate::formats::plcopen) variables: HashMap<String, VariableBox>,
    /// Contacts and in-line blocks between points.
    pub(in crate::formats::plcopen) edges: Vec<ElementEdge>,
    /// Outputs, each on the point feeding it.
    pub(in crate::formats::plcopen) outputs: Vec<Output>,
    /// Points some element takes power from (not the right rail).
    pub(in crate::formats::plcopen) consumed: Vec<usize>,
    /// Boolean blocks to lower once every element is read, and the steps
    /// lowering them has taken ([`crate::limits::MAX_GATE_WORK`]).
    pub(in crate::formats::plcopen) gates: Vec<Gate>,
    pub(in crate::formats::plcopen) gate_work: usize,
    /// The element being read (its place and line), for the OR a join of
    /// wires at one of its inputs makes ([`Body::join`]).
    pub(in crate::formats::plcopen) reading: Lined<Pos>,
    /// Comment boxes.
    pub(in crate::formats::plcopen) comments: Vec<CommentBox>,
    /// Relays free to hold a network's power (the next is popped), and
    /// those taken: (relay, what it holds, line).
    pub(in crate::formats::plcopen) spares: Vec<String>,
    pub(in crate::formats::plcopen) helpers: Vec<Helper>,
    /// Devices a block writes whose rungs run before any rung reading
    /// them (counters, split timers; helpers too), as the origin tool
    /// runs a block before what its outputs feed.
    pub(in crate::formats::plcopen) ordered: Vec<String>,
    /// Each comparison's `CMP` (its place), the relay its result is
    /// copied to (the copy runs right after the CMP) and its operands
    /// (what writes them runs before it).
    pub(in crate::formats::plcopen) compares: Vec<CompareCopy>,
    /// The machine the body is read for.
    pub(in crate::formats::plcopen) machine: Option<MachineId>,
    /// Soft PLC: each block's type (upper case), by localId.
    pub(in crate::formats::plcopen) block_types: HashMap<String, String>,
    /// Every block's type and instance as written, by localId (a wire
    /// from an output it lacks is said by name).
    pub(in crate::formats::plcopen) block_names: HashMap<String, (String, String)>,
    /// Soft PLC: the outVariables fed from a block's pin.
    pub(in crate::formats::plcopen) block_outs: Vec<BlockOut>,
    /// Soft PLC: the (block, pin) other elements take power from.
    pub(in crate::formats::plcopen) wired_pins: HashSet<(String, String)>,
    /// Soft PLC: the negated inVariables, by localId.
    pub(in crate::formats::plcopen) negated_variables: HashSet<String>,
    /// Soft PLC: the (block, pin) another box's data input reads, and
    /// the variables made to carry them ([`Temp`]).
    pub(in crate::formats::plcopen) chained: HashSet<(String, String)>,
    pub(in crate::formats::plcopen) temps: Vec<Temp>,
    /// What is worth saying but does not stop the import.
    pub(in crate::formats::plcopen) warnings: Vec<Located<ImportWarning>>,
    pub(in crate::formats::plcopen) errors: Errors,
}

pub(in crate::formats::plcopen) const RAIL: usize = 0;

/// An outVariable fed from a block's pin: the block, the pin (upper
/// case) and the variable.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct BlockOut {
    pub(in crate::formats::plcopen) block: String,
    pub(in crate::formats::plcopen) pin: String,
    pub(in crate::formats::plcopen) variable: String,
}

/// A variable made to carry one box's output into another's input: its
/// name, and the box output it holds (kind, pin, the box's operands).
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Temp {
    pub(in crate::formats::plcopen) name: String,
    pub(in crate::formats::plcopen) kind: String,
    pub(in crate::formats::plcopen) pin: String,
    pub(in crate::formats::plcopen) inputs: Vec<(String, String)>,
}

/// A value read from the file and the line it was read at.
#[derive(Clone, Debug, Default)]
pub(in crate::formats::plcopen) struct Lined<T> {
    /// The value.
    pub(in crate::formats::plcopen) value: T,
    /// Its line.
    pub(in crate::formats::plcopen) line: usize,
}

/// A connection to another element's pin (`refLocalId`,
/// `formalParameter`).
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct PinRef {
    /// The element's localId.
    pub(in crate::formats::plcopen) id: String,
    /// Its pin (empty for an element with one output).
    pub(in crate::formats::plcopen) pin: String,
}

/// A variable box that feeds power: a contact of its device from the
/// rail, NC when the box is negated (or why the variable has no device),
/// and its place.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct VariableBox {
    pub(in crate::formats::plcopen) contact:
        Result<Element, crate::formats::plcopen::declare::NameError>,
    pub(in crate::formats::plcopen) pos: Pos,
}

/// A comment box: where it is drawn and its text.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct CommentBox {
    pub(in crate::formats::plcopen) row: usize,
    pub(in crate::formats::plcopen) col: usize,
    pub(in crate::formats::plcopen) text: String,
    /// Its line: among rungs as near, it goes to the first one after
    /// it in the file (CODESYS draws every element at 0,0).
    pub(in crate::formats::plcopen) line: usize,
}

/// A spare relay taken: the relay, what it holds, the line needing it.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Helper {
    pub(in crate::formats::plcopen) relay: String,
    pub(in crate::formats::plcopen) what: String,
    pub(in crate::formats::plcopen) line: usize,
}

/// A comparison's `CMP` (its place), the relay its result is copied to,
/// and its two operands.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct CompareCopy {
    pub(in crate::formats::plcopen) at: Pos,
    pub(in crate::formats::plcopen) relay: String,
    pub(in crate::formats::plcopen) operands: [String; 2],
}

/// A contact or an in-line box between two points of the body.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct ElementEdge {
    /// The point it takes power from.
    pub(in crate::formats::plcopen) from: usize,
    /// The point it gives power to.
    pub(in crate::formats::plcopen) to: usize,
    /// The element (a leaf) and its place.
    pub(in crate::formats::plcopen) net: Net,
    /// Its line in the file.
    pub(in crate::formats::plcopen) line: usize,
}

/// An output (coil, timer or counter coil) on a point of the body.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Output {
    /// The point feeding it.
    pub(in crate::formats::plcopen) from: usize,
    /// The output.
    pub(in crate::formats::plcopen) element: Element,
    /// Its place.
    pub(in crate::formats::plcopen) pos: Pos,
    /// Its line in the file.
    pub(in crate::formats::plcopen) line: usize,
}

/// A boolean block waiting to be lowered.
#[derive(Clone, Debug)]
pub(in crate::formats::plcopen) struct Gate {
    pub kind: GateKind,
    /// The points its inputs take power from, in pin order.
    pub inputs: Vec<usize>,
    /// Its output's point.
    pub out: usize,
    /// Its place and line.
    pub pos: Pos,
    pub line: usize,
    /// `AND block`, `SR block SR0`: for messages.
    pub what: String,
}

/// Which block.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(in crate::formats::plcopen) enum GateKind {
    And,
    Or,
    Xor,
    /// A flip-flop on a relay; set wins (SR) or reset wins (RS).
    Flip {
        relay: String,
        set_wins: bool,
    },
    /// A counter's reset coil on its R's power (through a spare relay
    /// when R's point feeds more: the reset then has a rung of its own,
    /// which runs after the counting one).
    Reset(Element),
    /// A comparison of two words (one pair of a longer comparison's
    /// inputs): `CMP a b` (fed by M57, always on) and
    /// a relay that holds its result while later comparisons run: the
    /// flag (M60-M62) on, or (`on` false) off.
    Compare {
        a: String,
        b: String,
        flag: &'static str,
        on: bool,
    },
    /// A CTD (`load`: its LD; Q while CV <= 0) or a CTUD (`reset`: its R;
    /// `empty`: its QD's point, the count compared with 0; QU is `out`)
    /// on the machine's up-counter `counter` (`OUT C K`, counting CD's or
    /// CU's rises): the counter counts what CTD takes off PV, and LD
    /// clears it.
    Count {
        counter: Element,
        load: Option<usize>,
        reset: Option<usize>,
        empty: Option<usize>,
    },
    /// A TOF (or, `pulse`, a TP) from an on-delay timer coil and a relay
    /// that holds its output.
    Delay {
        coil: Element,
        timer: String,
        relay: String,
        pulse: bool,
    },
}

impl Body {
    /// Adds a contact or in-line box from point `from` to `to`.
    pub(in crate::formats::plcopen) fn wire(
        &mut self,
        from: usize,
        to: usize,
        net: Net,
        line: usize,
    ) {
        self.edges.push(ElementEdge {
            from,
            to,
            net,
            line,
        });
    }

    /// Adds an output fed from point `from`.
    pub(in crate::formats::plcopen) fn output(
        &mut self,
        from: usize,
        element: Element,
        pos: Pos,
        line: usize,
    ) {
        self.outputs.push(Output {
            from,
            element,
            pos,
            line,
        });
    }

    pub(in crate::formats::plcopen) fn point(&mut self, id: &str, pin: &str) -> usize {
        if self.rails.contains(id) {
            return RAIL;
        }
        let key = (id.to_string(), pin.to_string());
        if let Some(&p) = self.points.get(&key) {
            return p;
        }
        let p = self.parent.len();
        self.parent.push(p);
        self.points.insert(key, p);
        p
    }

    /// A point fed from the rail by variable box `id`'s `contact`, one
    /// for each wire leaving the box: reading a variable has no side
    /// effect, so a box feeding two blocks reads as two contacts rather
    /// than one shared point that would need a spare relay.
    pub(in crate::formats::plcopen) fn variable_point(
        &mut self,
        id: &str,
        contact: Element,
        at: Pos,
    ) -> usize {
        let p = self.fresh();
        let line = self.kinds.get(id).map_or(1, |k| k.line);
        self.consumed.push(RAIL);
        self.wire(RAIL, p, Net::Leaf(contact, at), line);
        p
    }

    pub(in crate::formats::plcopen) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    pub(in crate::formats::plcopen) fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a < b {
            self.parent[b] = a;
        } else {
            self.parent[a] = b;
        }
    }
}
