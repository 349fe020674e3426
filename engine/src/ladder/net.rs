//! A rung as logic: a series-parallel network of contacts and in-line
//! boxes from the left rail to one or more outputs. [`analyse`] reads it
//! off the grid (checking the wiring); [`layout`] draws it back.
//!
//! Grids come from other people's files, so every step here is linear or
//! n log n in the rung's size, and nothing recurses deeper than
//! [`MAX_NESTING`] (docs/limits.md).

mod layout;
mod reduce;
mod sides;

use std::fmt;

pub use layout::{layout, sides_fit, try_layout, TooLarge};
pub(crate) use reduce::Edge;
pub use sides::{attach_sides, carrier, Side};

use super::element::Element;
use super::grid::{LadderError, LadderErrorKind, Pos, Rung};
use super::problem::RungProblem;
use crate::limits::{MAX_NESTING, MAX_RUNG_CELLS};

/// A series-parallel network; leaves keep the cell they came from.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Net {
    /// One contact or in-line box.
    Leaf(Element, Pos),
    /// Left to right, two or more.
    Series(Vec<Net>),
    /// Top to bottom, two or more.
    Parallel(Vec<Net>),
}

impl Net {
    /// Every leaf, left to right and top to bottom.
    pub fn leaves(&self) -> Vec<(&Element, Pos)> {
        let mut out = Vec::new();
        let mut todo = vec![self];
        while let Some(n) = todo.pop() {
            match n {
                Net::Leaf(e, p) => out.push((e, *p)),
                Net::Series(v) | Net::Parallel(v) => todo.extend(v.iter().rev()),
            }
        }
        out
    }

    /// How deeply series and parallel groups nest: 0 for a leaf.
    pub fn depth(&self) -> usize {
        let mut deepest = 0;
        let mut todo = vec![(self, 0)];
        while let Some((n, d)) = todo.pop() {
            deepest = deepest.max(d);
            if let Net::Series(v) | Net::Parallel(v) = n {
                todo.extend(v.iter().map(|c| (c, d + 1)));
            }
        }
        deepest
    }

    /// `a` then `b` in series, flattened one level (both already normal).
    pub fn series(a: Net, b: Net) -> Net {
        Net::join(a, b, true)
    }

    /// `a` above `b` in parallel, flattened one level (both already normal).
    pub fn parallel(a: Net, b: Net) -> Net {
        Net::join(a, b, false)
    }

    fn join(a: Net, b: Net, series: bool) -> Net {
        let open = |n: Net| match n {
            Net::Series(v) if series => v,
            Net::Parallel(v) if !series => v,
            other => vec![other],
        };
        let mut items = open(a);
        items.extend(open(b));
        if series {
            Net::Series(items)
        } else {
            Net::Parallel(items)
        }
    }

    /// The first cell of the network (for error messages).
    pub fn first_pos(&self) -> Pos {
        let mut n = self;
        loop {
            match n {
                Net::Leaf(_, p) => return *p,
                Net::Series(v) | Net::Parallel(v) => match v.first() {
                    Some(first) => n = first,
                    None => return Pos::new(0, 0),
                },
            }
        }
    }

    /// The top-most, then left-most cell of the network.
    pub fn top_left(&self) -> Pos {
        self.leaves()
            .iter()
            .map(|(_, p)| *p)
            .min()
            .unwrap_or(Pos::new(0, 0))
    }

    /// Series of series and parallel of parallel merged; one-item groups
    /// unwrapped. Two networks that mean the same wiring compare equal.
    pub fn normalised(self) -> Net {
        match self {
            Net::Leaf(..) => self,
            Net::Series(v) => group(v, true),
            Net::Parallel(v) => group(v, false),
        }
    }

    /// The same network with every leaf's position replaced (for comparing
    /// shapes regardless of where they were drawn).
    pub fn without_positions(&self) -> Net {
        match self {
            Net::Leaf(e, _) => Net::Leaf(e.clone(), Pos::new(0, 0)),
            Net::Series(v) => Net::Series(v.iter().map(Net::without_positions).collect()),
            Net::Parallel(v) => Net::Parallel(v.iter().map(Net::without_positions).collect()),
        }
    }
}

fn group(items: Vec<Net>, series: bool) -> Net {
    let mut flat = Vec::new();
    for n in items.into_iter().map(Net::normalised) {
        match n {
            Net::Series(v) if series => flat.extend(v),
            Net::Parallel(v) if !series => flat.extend(v),
            other => flat.push(other),
        }
    }
    if flat.len() == 1 {
        flat.remove(0)
    } else if series {
        Net::Series(flat)
    } else {
        Net::Parallel(flat)
    }
}

/// Why a set of elements is not one series-parallel network.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NetError {
    /// A bridge between branches (or a loop): a cell of the part that
    /// would not reduce.
    NotSeriesParallel(Pos),
    /// Series and parallel blocks nest deeper than [`MAX_NESTING`]: a cell
    /// of the innermost part that does.
    TooDeep(Pos),
    /// No path joins the rail to the outputs.
    NoPath,
}

impl fmt::Display for NetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NetError::NotSeriesParallel(_) => f.write_str(
                "this network is not series-parallel (a bridge between branches): redraw it as series and parallel blocks",
            ),
            NetError::TooDeep(_) => write!(
                f,
                "series and parallel blocks nest more than {MAX_NESTING} deep here (docs/limits.md)"
            ),
            NetError::NoPath => f.write_str("no path of contacts joins the left rail to this output"),
        }
    }
}

/// A rung's meaning: one condition driving its outputs, top to bottom.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RungLogic {
    /// The network from the left rail to the outputs.
    pub condition: Net,
    /// The outputs, all driven by the condition, top first.
    pub outputs: Vec<(Element, Pos)>,
    /// The rung comment.
    pub comment: String,
    /// Soft PLC box inputs wired as networks of their own (computed
    /// before the condition; see [`Side`]).
    pub sides: Vec<Side>,
}

impl RungLogic {
    /// Every leaf: the condition's, then each box input network's, in
    /// the order the compiler emits them and the live ladder reads them.
    pub fn leaves(&self) -> Vec<(&Element, Pos)> {
        let mut all = self.condition.leaves();
        for side in &self.sides {
            all.extend(side.net.leaves());
        }
        all
    }
}

/// Reads the logic of rung index `index` off its grid. An empty rung
/// gives `Ok(None)`. Every wiring problem is reported at its cell.
pub fn analyse(rung: &Rung, index: usize) -> Result<Option<RungLogic>, Vec<LadderError>> {
    if rung.is_empty() {
        return Ok(None);
    }
    // A box's other inputs' networks come off first (soft PLC).
    let split = sides::split(rung, index)?;
    let (rung, sides) = match &split {
        Some((main, sides)) => (main, sides.clone()),
        None => (rung, Vec::new()),
    };
    let grid = Grid::new(rung, index)?;
    let outputs = grid.outputs()?;
    let mut points = grid.points()?;
    let (edges, rail, bus) = grid.edges(&mut points, &outputs)?;
    if rail == bus {
        // Output boxes on the rail (`Grid::edges`): always powered, as a
        // wire from the rail into the first of them.
        return Ok(Some(RungLogic {
            condition: Net::Leaf(Element::Wire, outputs[0].1),
            outputs,
            comment: rung.comment.clone(),
            sides,
        }));
    }
    grid.reaches(&edges, &mut points, rail, bus, &outputs)?;
    let condition = reduce::reduce(edges, points.len(), rail, bus).map_err(|e| {
        let (pos, kind) = match e {
            NetError::NotSeriesParallel(p) => (p, LadderErrorKind::NotSeriesParallel),
            NetError::TooDeep(p) => (p, LadderErrorKind::Limit),
            NetError::NoPath => (outputs[0].1, LadderErrorKind::Wiring),
        };
        let problem = match e {
            NetError::NotSeriesParallel(_) => RungProblem::NotSeriesParallel,
            NetError::TooDeep(_) => RungProblem::TooDeep,
            NetError::NoPath => RungProblem::NoPath,
        };
        vec![grid.err(pos, kind, problem)]
    })?;
    Ok(Some(RungLogic {
        condition,
        outputs,
        comment: rung.comment.clone(),
        sides,
    }))
}

/// A rung's grid being read: its size and where errors go.
struct Grid<'a> {
    rung: &'a Rung,
    index: usize,
    rows: usize,
    width: usize,
}

impl<'a> Grid<'a> {
    /// The grid, refused past [`MAX_RUNG_CELLS`] before any work.
    fn new(rung: &'a Rung, index: usize) -> Result<Grid<'a>, Vec<LadderError>> {
        let (rows, width) = (rung.cells.len(), rung.width());
        if (rows as u128) * (width as u128 + 1) > MAX_RUNG_CELLS as u128 {
            return Err(vec![LadderError::wiring(
                index,
                None,
                LadderErrorKind::Limit,
                RungProblem::TooLarge { rows, width },
            )]);
        }
        Ok(Grid {
            rung,
            index,
            rows,
            width,
        })
    }

    fn err(&self, pos: Pos, kind: LadderErrorKind, problem: RungProblem) -> LadderError {
        LadderError::wiring(self.index, Some(pos), kind, problem)
    }

    /// The electrical point at the left edge of column `b` in row `r`
    /// (edge 0 is the rail).
    fn node(&self, r: usize, b: usize) -> usize {
        r * (self.width + 1) + b
    }

    /// The outputs, checked to stand in one column with nothing after
    /// them.
    fn outputs(&self) -> Result<Vec<(Element, Pos)>, Vec<LadderError>> {
        let outputs: Vec<(Element, Pos)> = self
            .rung
            .elements()
            .filter(|(_, e)| e.is_output())
            .map(|(p, e)| (e.clone(), p))
            .collect();
        let Some(out_col) = outputs.iter().map(|(_, p)| p.col).max() else {
            return Err(vec![LadderError::wiring(
                self.index,
                None,
                LadderErrorKind::NoOutput,
                RungProblem::NoOutput,
            )]);
        };
        let mut errors = Vec::new();
        for (p, e) in self.rung.elements() {
            if e.is_output() && p.col != out_col {
                errors.push(self.err(p, LadderErrorKind::Placement, RungProblem::OutputNotLast));
            } else if !e.is_output() && p.col >= out_col {
                errors.push(self.err(p, LadderErrorKind::Placement, RungProblem::AfterOutput));
            }
        }
        if errors.is_empty() {
            Ok(outputs)
        } else {
            Err(errors)
        }
    }

    /// The points joined by the rail, the links and the wires.
    fn points(&self) -> Result<UnionFind, Vec<LadderError>> {
        let mut uf = UnionFind::new(self.rows * (self.width + 1));
        for r in 1..self.rows {
            uf.union(self.node(0, 0), self.node(r, 0));
        }
        let mut errors = Vec::new();
        for link in &self.rung.links {
            // Checked: a link's numbers come straight from the file.
            let below = link.row.checked_add(1).filter(|&b| b < self.rows);
            match below {
                Some(below) if link.col <= self.width => {
                    uf.union(self.node(link.row, link.col), self.node(below, link.col));
                }
                _ => errors.push(self.err(
                    Pos::new(link.row, link.col),
                    LadderErrorKind::Wiring,
                    RungProblem::LinkPastRung,
                )),
            }
        }
        for (p, e) in self.rung.elements() {
            if matches!(e, Element::Wire) {
                uf.union(self.node(p.row, p.col), self.node(p.row, p.col + 1));
            }
        }
        if errors.is_empty() {
            Ok(uf)
        } else {
            Err(errors)
        }
    }

    /// Every contact and in-line box as an edge from its left point to its
    /// right point; the rail's and the outputs' points.
    fn edges(
        &self,
        uf: &mut UnionFind,
        outputs: &[(Element, Pos)],
    ) -> Result<(Vec<Edge>, usize, usize), Vec<LadderError>> {
        let rail = uf.find(self.node(0, 0));
        let out_col = outputs[0].1.col;
        let bus = uf.find(self.node(outputs[0].1.row, out_col));
        let mut errors = Vec::new();
        for (_, p) in &outputs[1..] {
            if uf.find(self.node(p.row, out_col)) != bus {
                errors.push(self.err(*p, LadderErrorKind::Wiring, RungProblem::OutputNotJoined));
            }
        }
        let mut edges = Vec::new();
        let mut shorted = false;
        for (p, e) in self.rung.elements() {
            if e.is_output() || matches!(e, Element::Wire) {
                continue;
            }
            let (a, b) = (
                uf.find(self.node(p.row, p.col)),
                uf.find(self.node(p.row, p.col + 1)),
            );
            if a == b {
                errors.push(self.err(p, LadderErrorKind::Wiring, RungProblem::ShortCircuit));
                shorted = true;
                continue;
            }
            edges.push(Edge {
                from: a,
                to: b,
                net: Net::Leaf(e.clone(), p),
            });
        }
        // A shorted contact is the cause when the output also sits on the
        // rail; only without one is the output itself the problem. Soft
        // PLC output boxes may stand on it (EN on the rail: they always
        // run, as IEC has it) when nothing but wires leads to them.
        let boxes_on_rail = outputs
            .iter()
            .all(|(e, _)| matches!(e, Element::OutputBlock(_)))
            && edges.is_empty();
        if bus == rail && !shorted && !boxes_on_rail {
            errors.push(self.err(
                outputs[0].1,
                LadderErrorKind::Wiring,
                RungProblem::OutputOnRail,
            ));
        }
        if errors.is_empty() {
            Ok((edges, rail, bus))
        } else {
            Err(errors)
        }
    }

    /// Checks that every element and wire lies on a path from the rail to
    /// the outputs (one that does not is dangling).
    fn reaches(
        &self,
        edges: &[Edge],
        uf: &mut UnionFind,
        rail: usize,
        bus: usize,
        outputs: &[(Element, Pos)],
    ) -> Result<(), Vec<LadderError>> {
        let ends: Vec<(usize, usize)> = edges.iter().map(|e| (e.from, e.to)).collect();
        let forward = reduce::reach(&ends, uf.len(), rail, true);
        let backward = reduce::reach(&ends, uf.len(), bus, false);
        let useful = |n: usize| forward[n] && backward[n];
        let mut errors = Vec::new();
        for e in edges {
            if !(useful(e.from) && useful(e.to)) {
                errors.push(self.err(
                    e.net.first_pos(),
                    LadderErrorKind::Dangling,
                    RungProblem::Dangling,
                ));
            }
        }
        for (p, e) in self.rung.elements() {
            if matches!(e, Element::Wire) && !useful(uf.find(self.node(p.row, p.col))) {
                errors.push(self.err(p, LadderErrorKind::Dangling, RungProblem::DanglingWire));
            }
        }
        if !useful(bus) && errors.is_empty() {
            errors.push(self.err(outputs[0].1, LadderErrorKind::Wiring, RungProblem::NoPath));
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }
}

/// The network between `rail` and each of `buses` in one graph of
/// elements over `points` points (PLCopen bodies feed many coils from one
/// rail). Each is reduced from only the part of the graph on a path from
/// the rail to its bus, so the work is the sum of those parts, not the
/// whole graph once per bus.
pub(crate) fn reduce_all(
    edges: &[Edge],
    points: usize,
    rail: usize,
    buses: &[usize],
) -> Vec<Result<Net, NetError>> {
    let ends: Vec<(usize, usize)> = edges.iter().map(|e| (e.from, e.to)).collect();
    let forward = reduce::reach(&ends, points, rail, true);
    let mut entering: Vec<Vec<usize>> = vec![Vec::new(); points];
    for (i, &(from, to)) in ends.iter().enumerate() {
        if forward[from] {
            entering[to].push(i);
        }
    }
    buses
        .iter()
        .map(|&bus| {
            // Backwards from the bus: the edges that lead to it from the rail.
            let mut local: std::collections::HashMap<usize, usize> = Default::default();
            local.insert(bus, 0);
            let mut todo = vec![bus];
            let mut part = Vec::new();
            while let Some(n) = todo.pop() {
                for &i in &entering[n] {
                    let from = ends[i].0;
                    let next = local.len();
                    local.entry(from).or_insert_with(|| {
                        todo.push(from);
                        next
                    });
                    part.push(i);
                }
            }
            let Some(&local_rail) = local.get(&rail) else {
                return Err(NetError::NoPath);
            };
            let part = part
                .into_iter()
                .map(|i| Edge {
                    from: local[&ends[i].0],
                    to: local[&ends[i].1],
                    net: edges[i].net.clone(),
                })
                .collect();
            reduce::reduce(part, local.len(), local_rail, 0)
        })
        .collect()
}

struct UnionFind(Vec<usize>);

impl UnionFind {
    fn new(n: usize) -> UnionFind {
        UnionFind((0..n).collect())
    }

    fn len(&self) -> usize {
        self.0.len()
    }

    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }

    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        // The smaller index wins so that the rail (point 0) stays the root.
        if a < b {
            self.0[b] = a;
        } else {
            self.0[a] = b;
        }
    }
}
