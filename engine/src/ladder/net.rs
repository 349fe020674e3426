//! A rung as logic: a series-parallel network of contacts and in-line
//! boxes from the left rail to one or more outputs. [`analyse`] reads it
//! off the grid (checking the wiring); [`layout`] draws it back.

use std::collections::{BTreeMap, BTreeSet};

use super::element::Element;
use super::grid::{LadderError, Link, Pos, Rung};

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
        self.collect(&mut out);
        out
    }

    fn collect<'a>(&'a self, out: &mut Vec<(&'a Element, Pos)>) {
        match self {
            Net::Leaf(e, p) => out.push((e, *p)),
            Net::Series(v) | Net::Parallel(v) => v.iter().for_each(|n| n.collect(out)),
        }
    }

    /// The first cell of the network (for error messages).
    pub fn first_pos(&self) -> Pos {
        match self {
            Net::Leaf(_, p) => *p,
            Net::Series(v) | Net::Parallel(v) => v.first().map_or(Pos::new(0, 0), Net::first_pos),
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

/// A rung's meaning: one condition driving its outputs, top to bottom.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RungLogic {
    /// The network from the left rail to the outputs.
    pub condition: Net,
    /// The outputs, all driven by the condition, top first.
    pub outputs: Vec<(Element, Pos)>,
    /// The rung comment.
    pub comment: String,
}

/// Reads the logic of rung index `index` off its grid. An empty rung
/// gives `Ok(None)`. Every wiring problem is reported at its cell.
pub fn analyse(rung: &Rung, index: usize) -> Result<Option<RungLogic>, Vec<LadderError>> {
    if rung.is_empty() {
        return Ok(None);
    }
    let err = |pos: Pos, m: &str| LadderError::at(index, pos, m);
    let rows = rung.cells.len();
    let width = rung.width();
    let mut errors = Vec::new();

    // The output column: every output stands in it, nothing to its right.
    let outputs: Vec<(Element, Pos)> = rung
        .elements()
        .filter(|(_, e)| e.is_output())
        .map(|(p, e)| (e.clone(), p))
        .collect();
    let Some(out_col) = outputs.iter().map(|(_, p)| p.col).max() else {
        return Err(vec![LadderError::rung(
            index,
            "the rung has no output: end it with a coil or an output box",
        )]);
    };
    for (p, e) in rung.elements() {
        if e.is_output() && p.col != out_col {
            errors.push(err(
                p,
                "outputs must line up in the rung's last column: move this one right",
            ));
        } else if !e.is_output() && p.col >= out_col {
            errors.push(err(
                p,
                "nothing may follow an output: coils and output boxes end the rung",
            ));
        }
    }

    // Electrical points: (row, edge) for edge 0..=width; edge 0 is the rail.
    let node = |r: usize, b: usize| r * (width + 1) + b;
    let mut uf = UnionFind::new(rows * (width + 1));
    for r in 1..rows {
        uf.union(node(0, 0), node(r, 0));
    }
    for link in &rung.links {
        if link.row + 1 >= rows || link.col > width {
            errors.push(err(
                Pos::new(link.row, link.col),
                "a vertical link reaches past the rung's last row or column",
            ));
            continue;
        }
        uf.union(node(link.row, link.col), node(link.row + 1, link.col));
    }
    for (p, e) in rung.elements() {
        if matches!(e, Element::Wire) {
            uf.union(node(p.row, p.col), node(p.row, p.col + 1));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let rail = uf.find(node(0, 0));

    // The outputs share one driving point.
    let bus = uf.find(node(outputs[0].1.row, out_col));
    for (_, p) in &outputs[1..] {
        if uf.find(node(p.row, out_col)) != bus {
            errors.push(err(
                *p,
                "this output is not joined to the first output's condition: give it its own rung or link it",
            ));
        }
    }
    if bus == rail {
        errors.push(err(
            outputs[0].1,
            "the output is wired straight to the left rail: put a contact before it",
        ));
    }

    // Edges: every contact and in-line box, left point to right point.
    let mut edges = Vec::new();
    for (p, e) in rung.elements() {
        if e.is_output() || matches!(e, Element::Wire) {
            continue;
        }
        let (a, b) = (uf.find(node(p.row, p.col)), uf.find(node(p.row, p.col + 1)));
        if a == b {
            errors.push(err(
                p,
                "short circuit: a wire joins both sides of this element",
            ));
            continue;
        }
        edges.push(Edge {
            from: a,
            to: b,
            net: Net::Leaf(e.clone(), p),
            key: p,
        });
    }
    if !errors.is_empty() {
        return Err(errors);
    }

    // Only what lies on a path from the rail to the outputs counts; an
    // element or wire that does not is dangling.
    let forward = reach(&edges, rail, |e| (e.from, e.to));
    let backward = reach(&edges, bus, |e| (e.to, e.from));
    let useful = |n: usize| forward.contains(&n) && backward.contains(&n);
    for e in &edges {
        if !(useful(e.from) && useful(e.to)) {
            errors.push(err(
                e.key,
                "dangling: this element is not on a path from the left rail to the outputs",
            ));
        }
    }
    for (p, e) in rung.elements() {
        if matches!(e, Element::Wire) && !useful(uf.find(node(p.row, p.col))) {
            errors.push(err(
                p,
                "dangling wire: it does not join the left rail to the outputs",
            ));
        }
    }
    if !useful(bus) && errors.is_empty() {
        errors.push(err(
            outputs[0].1,
            "no path of contacts joins the left rail to this output",
        ));
    }
    if !errors.is_empty() {
        return Err(errors);
    }

    let condition = reduce(edges, rail, bus).map_err(|pos| {
        vec![err(
            pos,
            "this network is not series-parallel (a bridge between branches): redraw it as series and parallel blocks",
        )]
    })?;
    Ok(Some(RungLogic {
        condition: condition.normalised(),
        outputs,
        comment: rung.comment.clone(),
    }))
}

/// The series-parallel network between `rail` and `bus` in a graph of
/// elements (`from` point, `to` point, leaf): only the edges on a path
/// from one to the other count. `Err` holds a cell of a part that is not
/// series-parallel, or `None` when no path joins them.
pub(crate) fn network(
    edges: Vec<(usize, usize, Net)>,
    rail: usize,
    bus: usize,
) -> Result<Net, Option<Pos>> {
    let edges: Vec<Edge> = edges
        .into_iter()
        .map(|(from, to, net)| Edge {
            from,
            to,
            key: net.top_left(),
            net,
        })
        .collect();
    let forward = reach(&edges, rail, |e| (e.from, e.to));
    let backward = reach(&edges, bus, |e| (e.to, e.from));
    let useful: Vec<Edge> = edges
        .into_iter()
        .filter(|e| forward.contains(&e.from) && backward.contains(&e.to))
        .collect();
    if useful.is_empty() {
        return Err(None);
    }
    reduce(useful, rail, bus).map(Net::normalised).map_err(Some)
}

struct Edge {
    from: usize,
    to: usize,
    net: Net,
    key: Pos,
}

fn reach(edges: &[Edge], start: usize, dir: impl Fn(&Edge) -> (usize, usize)) -> BTreeSet<usize> {
    let mut seen = BTreeSet::from([start]);
    let mut todo = vec![start];
    while let Some(n) = todo.pop() {
        for e in edges {
            let (a, b) = dir(e);
            if a == n && seen.insert(b) {
                todo.push(b);
            }
        }
    }
    seen
}

/// Series-parallel reduction; on failure, a cell of the part that would
/// not reduce.
fn reduce(mut edges: Vec<Edge>, rail: usize, bus: usize) -> Result<Net, Pos> {
    loop {
        let before = edges.len();
        // Parallel: edges with the same ends merge, top branch first.
        let mut groups: BTreeMap<(usize, usize), Vec<Edge>> = BTreeMap::new();
        for e in edges.drain(..) {
            groups.entry((e.from, e.to)).or_default().push(e);
        }
        for ((from, to), group) in groups {
            if group.len() == 1 {
                edges.extend(group);
                continue;
            }
            // Branches merged earlier are spread out again so that all
            // of them sort top to bottom together.
            let key = group.iter().map(|e| e.key).min().unwrap_or(Pos::new(0, 0));
            let mut branches: Vec<Net> = Vec::new();
            for e in group {
                match e.net {
                    Net::Parallel(v) => branches.extend(v),
                    other => branches.push(other),
                }
            }
            branches.sort_by_key(Net::top_left);
            edges.push(Edge {
                from,
                to,
                net: Net::Parallel(branches),
                key,
            });
        }
        // Series: a point with one edge in and one out joins them.
        let mut degree: BTreeMap<usize, (usize, usize)> = BTreeMap::new();
        for e in &edges {
            degree.entry(e.from).or_default().1 += 1;
            degree.entry(e.to).or_default().0 += 1;
        }
        if let Some((&mid, _)) = degree
            .iter()
            .find(|(&n, &d)| n != rail && n != bus && d == (1, 1))
        {
            let i = edges.iter().position(|e| e.to == mid).unwrap_or(0);
            let left = edges.swap_remove(i);
            let j = edges.iter().position(|e| e.from == mid).unwrap_or(0);
            let right = edges.swap_remove(j);
            edges.push(Edge {
                from: left.from,
                to: right.to,
                key: left.key.min(right.key),
                net: Net::Series(vec![left.net, right.net]),
            });
        }
        if edges.len() == 1 && edges[0].from == rail && edges[0].to == bus {
            return Ok(edges.remove(0).net);
        }
        if edges.len() == before {
            let stuck = edges
                .iter()
                .find(|e| e.from != rail || e.to != bus)
                .or(edges.first())
                .map_or(Pos::new(0, 0), |e| e.net.first_pos());
            return Err(stuck);
        }
    }
}

struct UnionFind(Vec<usize>);

impl UnionFind {
    fn new(n: usize) -> UnionFind {
        UnionFind((0..n).collect())
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

/// Draws a rung's logic on a grid: series left to right, parallel
/// branches below each other, outputs in the last column.
pub fn layout(logic: &RungLogic) -> Rung {
    let mut rung = Rung {
        comment: logic.comment.clone(),
        ..Rung::default()
    };
    let (width, _) = place(&logic.condition, &mut rung, 0, 0);
    for (i, (e, _)) in logic.outputs.iter().enumerate() {
        rung.set(Pos::new(i, width), Some(e.clone()));
        if i > 0 {
            rung.links.push(Link {
                row: i - 1,
                col: width,
            });
        }
    }
    rung.links.sort();
    rung.links.dedup();
    rung
}

/// The (width, height) a network takes.
fn measure(net: &Net) -> (usize, usize) {
    match net {
        Net::Leaf(..) => (1, 1),
        Net::Series(v) => v
            .iter()
            .map(measure)
            .fold((0, 1), |(w, h), (cw, ch)| (w + cw, h.max(ch))),
        Net::Parallel(v) => v
            .iter()
            .map(measure)
            .fold((0, 0), |(w, h), (cw, ch)| (w.max(cw), h + ch)),
    }
}

fn place(net: &Net, rung: &mut Rung, row: usize, col: usize) -> (usize, usize) {
    match net {
        Net::Leaf(e, _) => {
            rung.set(Pos::new(row, col), Some(e.clone()));
            (1, 1)
        }
        Net::Series(v) => {
            let (mut x, mut h) = (col, 1);
            for n in v {
                let (w, nh) = place(n, rung, row, x);
                x += w;
                h = h.max(nh);
            }
            (x - col, h)
        }
        Net::Parallel(v) => {
            let (width, _) = measure(net);
            let mut r = row;
            let mut last_top = row;
            for n in v {
                let (w, h) = place(n, rung, r, col);
                for c in col + w..col + width {
                    rung.set(Pos::new(r, c), Some(Element::Wire));
                }
                last_top = r;
                r += h;
            }
            for k in row..last_top {
                if col > 0 {
                    rung.links.push(Link { row: k, col });
                }
                rung.links.push(Link {
                    row: k,
                    col: col + width,
                });
            }
            (width, r - row)
        }
    }
}
