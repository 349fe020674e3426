//! Series-parallel reduction of a two-terminal graph of elements, in
//! O(n log n): parallel edges merge through a map keyed by their ends,
//! points with one edge in and one out join their edges in series, each
//! point is visited only when its degree changes. Intermediate networks
//! live in an arena and become a [`Net`] once, at the end, by an explicit
//! stack (no recursion over anything the input can make deep).

use std::collections::HashMap;

use super::{Net, NetError};
use crate::ladder::grid::Pos;
use crate::limits::MAX_NESTING;

/// An element between two electrical points, left (`from`) to right (`to`).
pub(crate) struct Edge {
    /// The point on its left.
    pub from: usize,
    /// The point on its right.
    pub to: usize,
    /// The leaf (or a network already built).
    pub net: Net,
}

/// A network under construction: arena indices instead of owned children.
enum Part {
    Done(Net),
    Series(usize, usize),
    Parallel(Vec<usize>),
}

/// An arena node: the part and its top-left cell (the order key of
/// parallel branches and the place errors point at).
struct Node {
    part: Part,
    key: Pos,
}

#[derive(Clone, Copy)]
struct Live {
    from: usize,
    to: usize,
    node: usize,
}

struct Graph {
    arena: Vec<Node>,
    edges: Vec<Option<Live>>,
    outs: Vec<Vec<usize>>,
    ins: Vec<Vec<usize>>,
    out_degree: Vec<usize>,
    in_degree: Vec<usize>,
    by_ends: HashMap<(usize, usize), usize>,
    live: usize,
    todo: Vec<usize>,
}

impl Graph {
    fn new(points: usize) -> Graph {
        Graph {
            arena: Vec::new(),
            edges: Vec::new(),
            outs: vec![Vec::new(); points],
            ins: vec![Vec::new(); points],
            out_degree: vec![0; points],
            in_degree: vec![0; points],
            by_ends: HashMap::new(),
            live: 0,
            todo: Vec::new(),
        }
    }

    /// Adds an edge; one with the same ends as a live one merges with it
    /// in parallel.
    fn add(&mut self, from: usize, to: usize, node: usize) {
        if let Some(&other) = self.by_ends.get(&(from, to)) {
            if let Some(existing) = self.edges[other] {
                let merged = self.parallel(existing.node, node);
                self.edges[other] = Some(Live {
                    node: merged,
                    ..existing
                });
                self.todo.extend([from, to]);
                return;
            }
        }
        let id = self.edges.len();
        self.edges.push(Some(Live { from, to, node }));
        self.by_ends.insert((from, to), id);
        self.outs[from].push(id);
        self.ins[to].push(id);
        self.out_degree[from] += 1;
        self.in_degree[to] += 1;
        self.live += 1;
    }

    fn remove(&mut self, id: usize) -> Option<Live> {
        let e = self.edges.get_mut(id)?.take()?;
        self.by_ends.remove(&(e.from, e.to));
        self.out_degree[e.from] -= 1;
        self.in_degree[e.to] -= 1;
        self.live -= 1;
        Some(e)
    }

    /// A parallel part of `a` and `b`; a parallel operand is spread into
    /// it (the larger list keeps its allocation).
    fn parallel(&mut self, a: usize, b: usize) -> usize {
        let key = self.arena[a].key.min(self.arena[b].key);
        let mut branches = self.take_branches(a);
        let mut more = self.take_branches(b);
        if more.len() > branches.len() {
            std::mem::swap(&mut branches, &mut more);
        }
        branches.append(&mut more);
        self.push(Part::Parallel(branches), key)
    }

    fn take_branches(&mut self, node: usize) -> Vec<usize> {
        match &mut self.arena[node].part {
            Part::Parallel(v) => std::mem::take(v),
            _ => vec![node],
        }
    }

    fn push(&mut self, part: Part, key: Pos) -> usize {
        self.arena.push(Node { part, key });
        self.arena.len() - 1
    }

    /// The one live edge in `list` that still ends (or starts) at `point`.
    fn only(&self, list: &[usize], point: usize, incoming: bool) -> Option<usize> {
        list.iter().copied().find(|&id| {
            self.edges[id].is_some_and(|e| {
                if incoming {
                    e.to == point
                } else {
                    e.from == point
                }
            })
        })
    }

    /// Joins the edge into `point` with the edge out of it, when it has
    /// exactly one of each.
    fn series_at(&mut self, point: usize) {
        if self.in_degree[point] != 1 || self.out_degree[point] != 1 {
            return;
        }
        let (Some(left), Some(right)) = (
            self.only(&self.ins[point], point, true),
            self.only(&self.outs[point], point, false),
        ) else {
            return;
        };
        if left == right {
            return; // a loop on one point: no series form
        }
        let (Some(l), Some(r)) = (self.remove(left), self.remove(right)) else {
            return;
        };
        let key = self.arena[l.node].key.min(self.arena[r.node].key);
        let node = self.push(Part::Series(l.node, r.node), key);
        self.add(l.from, r.to, node);
        self.todo.extend([l.from, r.to]);
    }
}

/// Reduces the edges between `rail` and `bus` (points numbered below
/// `points`) to one series-parallel network, normalised: series in series
/// and parallel in parallel merged, parallel branches top-left first.
/// Every edge must lie on a path from `rail` to `bus`.
pub(crate) fn reduce(
    edges: Vec<Edge>,
    points: usize,
    rail: usize,
    bus: usize,
) -> Result<Net, NetError> {
    let mut g = Graph::new(points);
    for e in edges {
        let key = e.net.top_left();
        let node = g.push(Part::Done(e.net), key);
        g.add(e.from, e.to, node);
    }
    g.todo.extend(0..points);
    while let Some(point) = g.todo.pop() {
        if point != rail && point != bus {
            g.series_at(point);
        }
    }
    let mut remaining = g.edges.iter().flatten();
    match (remaining.next(), g.live) {
        (Some(e), 1) if e.from == rail && e.to == bus => {
            let root = e.node;
            build(g.arena, root)
        }
        _ => {
            let stuck = g
                .edges
                .iter()
                .flatten()
                .filter(|e| e.from != rail || e.to != bus)
                .map(|e| g.arena[e.node].key)
                .min()
                .unwrap_or(Pos::new(0, 0));
            Err(NetError::NotSeriesParallel(stuck))
        }
    }
}

/// Turns the arena below `root` into a normalised [`Net`], children
/// before parents, refusing nesting past [`MAX_NESTING`]. A series part
/// inside a series part is not built on its own: its top-most series
/// ancestor collects the whole run in one walk (building each level would
/// copy a long chain once per contact).
fn build(mut arena: Vec<Node>, root: usize) -> Result<Net, NetError> {
    // Each finished part: its net, its depth.
    let mut done: Vec<Option<(Net, usize)>> = Vec::new();
    done.resize_with(arena.len(), || None);
    // (part, its children are done, it sits directly inside a series part)
    let mut stack = vec![(root, false, false)];
    while let Some((i, children_done, in_series)) = stack.pop() {
        let children: Vec<usize> = match &arena[i].part {
            Part::Done(_) => Vec::new(),
            Part::Series(a, b) => vec![*a, *b],
            Part::Parallel(v) => v.clone(),
        };
        let series = matches!(arena[i].part, Part::Series(..));
        if !children_done && !children.is_empty() {
            stack.push((i, true, in_series));
            stack.extend(children.iter().map(|&c| (c, false, series)));
            continue;
        }
        if series && in_series {
            continue; // collected by the series part above
        }
        let key = arena[i].key;
        let finished = match std::mem::replace(&mut arena[i].part, Part::Parallel(Vec::new())) {
            Part::Done(net) => {
                let depth = net.depth();
                (net, depth)
            }
            Part::Series(a, b) => joined_series(&arena, &mut done, (a, b)),
            Part::Parallel(_) => joined_parallel(&arena, &mut done, children),
        };
        if finished.1 > MAX_NESTING {
            return Err(NetError::TooDeep(key));
        }
        done[i] = Some(finished);
    }
    done[root]
        .take()
        .map(|(net, _)| net)
        .ok_or(NetError::NotSeriesParallel(Pos::new(0, 0)))
}

/// A finished part with its depth, as [`build`] keeps them.
type Finished = Option<(Net, usize)>;

/// A series part's finished net: its nested series parts flattened, left
/// to right.
fn joined_series(arena: &[Node], done: &mut [Finished], (a, b): (usize, usize)) -> (Net, usize) {
    let mut items = Vec::new();
    let mut depth = 0;
    // Left to right through the nested series parts.
    let mut walk = vec![b, a];
    while let Some(c) = walk.pop() {
        if let Part::Series(l, r) = arena[c].part {
            walk.extend([r, l]);
            continue;
        }
        let Some((net, d)) = done[c].take() else {
            continue;
        };
        match net {
            Net::Series(v) => {
                depth = depth.max(d);
                items.extend(v);
            }
            other => {
                depth = depth.max(d + 1);
                items.push(other);
            }
        }
    }
    (Net::Series(items), depth)
}

/// A parallel part's finished net: branches of parallel branches sorted
/// with the rest, top to bottom.
fn joined_parallel(arena: &[Node], done: &mut [Finished], children: Vec<usize>) -> (Net, usize) {
    let mut items = Vec::new();
    let mut depth = 0;
    for c in children {
        let Some((net, d)) = done[c].take() else {
            continue;
        };
        match net {
            // Branches of a parallel branch sort with the rest.
            Net::Parallel(v) => {
                depth = depth.max(d);
                items.extend(v.into_iter().map(|n| (n.top_left(), n)));
            }
            other => {
                depth = depth.max(d + 1);
                items.push((arena[c].key, other));
            }
        }
    }
    crate::sort::by_key(&mut items, |(k, _)| *k);
    let items = items.into_iter().map(|(_, n)| n).collect();
    (Net::Parallel(items), depth)
}

/// The points reachable from `start` along the edges, in `forward`
/// direction or against it: O(points + edges).
pub(crate) fn reach(
    ends: &[(usize, usize)],
    points: usize,
    start: usize,
    forward: bool,
) -> Vec<bool> {
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); points];
    for &(a, b) in ends {
        if forward {
            adjacent[a].push(b);
        } else {
            adjacent[b].push(a);
        }
    }
    let mut seen = vec![false; points];
    seen[start] = true;
    let mut todo = vec![start];
    while let Some(n) = todo.pop() {
        for &m in &adjacent[n] {
            if !seen[m] {
                seen[m] = true;
                todo.push(m);
            }
        }
    }
    seen
}
