//! The order a drawn body's elements run in: each after the elements
//! that feed it (through connectors too), else top to bottom and left to
//! right as the file draws them. A loop of wires through an
//! `inOutVariable` is broken at the variable's readers in the loop: they
//! read the value the last scan left, everything else reads the variable
//! after the loop writes it (IEC 61131-3: an element runs when all its
//! inputs are evaluated; a feedback variable holds the last evaluation's
//! value). Only a loop with no variable in it is broken where it is
//! drawn first.

use std::collections::{BTreeSet, HashMap};

use super::{Element, Graph, Kind, Source};

/// An element's place in the running order: drawn position, then file
/// order.
type Key = (i64, i64, usize);

/// Whether element `e` runs (the others only carry values: rails,
/// input variables, connectors).
fn runs(e: &Element) -> bool {
    matches!(
        e.kind,
        Kind::Contact { .. }
            | Kind::Coil { .. }
            | Kind::Block { .. }
            | Kind::OutVariable(_)
            | Kind::InOutVariable(_)
    )
}

/// The running elements feeding each element (through connectors),
/// sorted, each once, never the element itself.
fn feeders(g: &Graph) -> Vec<Vec<usize>> {
    let mut all = Vec::with_capacity(g.elements.len());
    for (at, e) in g.elements.iter().enumerate() {
        let mut out = Vec::new();
        let mut todo: Vec<&Source> = e.inputs.iter().flat_map(|(_, s)| s).collect();
        let mut seen = 0;
        while let Some(s) = todo.pop() {
            seen += 1;
            if seen > 10_000 {
                break;
            }
            let Some(&i) = g.by_id.get(&s.from) else {
                continue;
            };
            match &g.elements[i].kind {
                Kind::Continuation(name) => {
                    if let Some(&c) = g.connectors.get(&name.to_ascii_lowercase()) {
                        todo.extend(g.elements[c].inputs.iter().flat_map(|(_, s)| s));
                    }
                }
                _ if runs(&g.elements[i]) && i != at => out.push(i),
                _ => {}
            }
        }
        crate::sort::all(&mut out);
        out.dedup();
        all.push(out);
    }
    all
}

/// The parts of the graph among `nodes` in which every element feeds
/// every other (its loops of wires), each with more than one element:
/// Kosaraju's two walks, without recursion (a drawing can be deep);
/// `work` counts the elements and wires looked at.
fn loops(
    users: &[Vec<usize>],
    feeders: &[Vec<usize>],
    nodes: &[usize],
    work: &mut usize,
) -> Vec<Vec<usize>> {
    *work += nodes.len();
    for &i in nodes {
        *work += users[i].len() + feeders[i].len();
    }
    // Each element's place in `nodes`: the walks cost the part, not the
    // body, however many parts are looked at.
    let local: HashMap<usize, usize> = (nodes.iter().enumerate()).map(|(k, &i)| (i, k)).collect();
    let mut seen = vec![false; nodes.len()];
    let mut finished = Vec::with_capacity(nodes.len());
    for (k, &start) in nodes.iter().enumerate() {
        if seen[k] {
            continue;
        }
        seen[k] = true;
        let mut stack = vec![(start, 0usize)];
        while let Some((v, next)) = stack.last_mut() {
            if let Some(&w) = users[*v].get(*next) {
                *next += 1;
                if let Some(&lw) = local.get(&w).filter(|&&lw| !seen[lw]) {
                    seen[lw] = true;
                    stack.push((w, 0));
                }
            } else {
                finished.push(*v);
                stack.pop();
            }
        }
    }
    let mut placed = vec![false; nodes.len()];
    let mut parts = Vec::new();
    for &start in finished.iter().rev() {
        let Some(&k) = local.get(&start).filter(|&&k| !placed[k]) else {
            continue;
        };
        placed[k] = true;
        let mut part = vec![start];
        let mut todo = vec![start];
        while let Some(v) = todo.pop() {
            for &w in &feeders[v] {
                if let Some(&lw) = local.get(&w).filter(|&&lw| !placed[lw]) {
                    placed[lw] = true;
                    part.push(w);
                    todo.push(w);
                }
            }
        }
        if part.len() > 1 {
            parts.push(part);
        }
    }
    parts
}

/// Elements and wires [`break_at_variables`] may look at: a real
/// drawing takes a few hundred; a hostile one (thousands of variables in
/// one loop, each breaking a little of it) would take minutes.
const MAX_LOOP_WORK: usize = 2_000_000;

/// Stops `part`'s readers of `v` waiting for it; `inside`: `part`'s
/// elements.
fn cut_readers(v: usize, inside: &[bool], feeders: &mut [Vec<usize>], users: &mut [Vec<usize>]) {
    let readers: Vec<usize> = (users[v].iter().copied()).filter(|&u| inside[u]).collect();
    users[v].retain(|&u| !inside[u]);
    for u in readers {
        feeders[u].retain(|&f| f != v);
    }
}

/// Breaks every loop of wires through an `inOutVariable` at the readers
/// of its first such variable (as drawn) in the loop: they stop waiting
/// for it and read what the last scan left. What is left of the loop is
/// looked at again (another variable may break it); a loop with no
/// variable is left whole. Past [`MAX_LOOP_WORK`] the loops left are
/// broken at every variable in them at once.
fn break_at_variables(g: &Graph, feeders: &mut [Vec<usize>], users: &mut [Vec<usize>]) {
    let key = |i: usize| (g.elements[i].y, g.elements[i].x, i);
    let is_variable = |i: &usize| matches!(g.elements[*i].kind, Kind::InOutVariable(_));
    let running: Vec<usize> = (0..g.elements.len())
        .filter(|&i| runs(&g.elements[i]))
        .collect();
    let mut work = 0;
    let mut todo = loops(users, feeders, &running, &mut work);
    let mut inside = vec![false; users.len()];
    // Each part looked at loses a wire or is dropped: this ends.
    while let Some(part) = todo.pop() {
        for &i in &part {
            inside[i] = true;
        }
        let mut variables: Vec<usize> = part.iter().copied().filter(is_variable).collect();
        crate::sort::by_key(&mut variables, |&i| key(i));
        if work > MAX_LOOP_WORK {
            for &v in &variables {
                cut_readers(v, &inside, feeders, users);
            }
        } else if let Some(&v) = variables.first() {
            cut_readers(v, &inside, feeders, users);
            todo.extend(loops(users, feeders, &part, &mut work));
        }
        for &i in &part {
            inside[i] = false;
        }
    }
}

/// The elements that run, each after the elements feeding it (through
/// connectors too), else top to bottom and left to right; a loop of
/// wires through an `inOutVariable` is broken at the variable's readers
/// in it, any other loop at its first element as drawn, which reads what
/// the loop's other elements left in the last scan.
pub(in crate::formats::plcopen) fn order(g: &Graph) -> Vec<usize> {
    let mut feeders = feeders(g);
    let n = g.elements.len();
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, d) in feeders.iter().enumerate() {
        for &j in d {
            users[j].push(i);
        }
    }
    break_at_variables(g, &mut feeders, &mut users);
    let mut waits: Vec<usize> = feeders.iter().map(Vec::len).collect();
    let key = |i: usize| (g.elements[i].y, g.elements[i].x, i);
    let mut left: BTreeSet<Key> = (0..n).filter(|&i| runs(&g.elements[i])).map(key).collect();
    let mut ready: BTreeSet<Key> = left.iter().copied().filter(|k| waits[k.2] == 0).collect();
    let mut out = Vec::new();
    // A loop with no variable: its first element runs when nothing else
    // can.
    while let Some(k) = ready.pop_first().or_else(|| left.first().copied()) {
        if !left.remove(&k) {
            continue;
        }
        ready.remove(&k);
        out.push(k.2);
        for &u in &users[k.2] {
            waits[u] = waits[u].saturating_sub(1);
            if waits[u] == 0 && left.contains(&key(u)) {
                ready.insert(key(u));
            }
        }
    }
    out
}
