//! An LDmicro file as read: its settings, its variable and I/O lists, and
//! its rungs as the series and parallel groups LDmicro nests.

use super::element::Element;

/// Which format version the file says it is. LDmicro 4.x reads anything
/// but `LDmicro0.1` as 0.2, a bare `LDmicro` too, and so does Hashigo.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Version {
    /// `LDmicro0.1`: written by LDmicro 1.x and 2.x (and 4.x's "save as
    /// 0.1"); a timer without an adjust is one cycle shorter.
    V01,
    /// `LDmicro0.2` (or a bare `LDmicro`): written by LDmicro 4.x.
    V02,
}

/// One entry of the `VAR LIST`: a variable's size in bytes.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VarSize {
    /// The variable.
    pub name: String,
    /// Its size: 1 to 4 bytes for a number (signed, wrapping in that
    /// width); more for a table or string LDmicro keeps in memory.
    pub bytes: u16,
    /// The rest of the line (LDmicro keeps a note there).
    pub note: String,
    /// Its line.
    pub line: usize,
}

/// One entry of the `IO LIST` or `PULL-UP LIST`: a name and the rest of
/// its line as written (`at 21`, Modbus fields), kept as a comment.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct IoEntry {
    /// The I/O name (`Xbutton`).
    pub name: String,
    /// The rest of the line (`at 21 0 0`).
    pub rest: String,
    /// Its line.
    pub line: usize,
}

/// A rung's contents: elements and groups in series, or branches in
/// parallel, each at its line.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// One element line.
    Leaf(Element, usize),
    /// `SERIES` … `END`: left to right.
    Series(Vec<Node>, usize),
    /// `PARALLEL` … `END`: top to bottom.
    Parallel(Vec<Node>, usize),
}

impl Node {
    /// The line it starts at.
    pub fn line(&self) -> usize {
        match self {
            Node::Leaf(_, l) | Node::Series(_, l) | Node::Parallel(_, l) => *l,
        }
    }

    /// Every element under it, in file order, with its line.
    pub fn elements(&self) -> Vec<(&Element, usize)> {
        let mut out = Vec::new();
        let mut todo = vec![self];
        while let Some(n) = todo.pop() {
            match n {
                Node::Leaf(e, l) => out.push((e, *l)),
                Node::Series(v, _) | Node::Parallel(v, _) => todo.extend(v.iter().rev()),
            }
        }
        out
    }
}

/// One `RUNG` … `END`: its elements in series.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct LdRung {
    /// The `RUNG` line.
    pub line: usize,
    /// Its contents, left to right.
    pub series: Vec<Node>,
}

/// A whole `.ld` file.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct LdFile {
    /// The format version.
    pub version: Version,
    /// `MICRO=`: the target microcontroller, as named.
    pub micro: String,
    /// `CYCLE=`: the scan's period in µs (LDmicro's default 10 000).
    pub cycle_us: u64,
    /// `CRYSTAL=`: the clock in Hz (0 when not given).
    pub crystal_hz: u64,
    /// `BAUD=`: the UART's rate (0 when not given).
    pub baud: u64,
    /// `COMPILED=`: where LDmicro last wrote its output.
    pub compiled: String,
    /// `COMPILER=`: which of LDmicro's compilers.
    pub compiler: String,
    /// The `VAR LIST`.
    pub vars: Vec<VarSize>,
    /// The `IO LIST`.
    pub io: Vec<IoEntry>,
    /// The `PULL-UP LIST`.
    pub pull_ups: Vec<IoEntry>,
    /// The rungs, top to bottom.
    pub rungs: Vec<LdRung>,
}

impl LdFile {
    /// Every element of every rung, in file order, with its line.
    pub fn elements(&self) -> impl Iterator<Item = (&Element, usize)> {
        self.rungs
            .iter()
            .flat_map(|r| r.series.iter().flat_map(Node::elements))
    }

    /// The size in bytes the `VAR LIST` gives `name` (16-bit where it
    /// says nothing, as LDmicro's default).
    pub fn size_of(&self, name: &str) -> u16 {
        self.vars
            .iter()
            .find(|v| v.name == name)
            .map_or(2, |v| v.bytes)
    }
}
