//! The order a drawn body's elements run in: each after the elements
//! that feed it (through connectors too), else top to bottom and left to
//! right as the file draws them.

use std::collections::BTreeSet;

use super::{Element, Graph, Kind, Source};

/// The elements that run, each after the elements feeding it (through
/// connectors too), else top to bottom and left to right; an element in
/// a loop of wires runs when nothing else can, reading what the loop's
/// other elements left in the last scan.
pub(in crate::formats::plcopen) fn order(g: &Graph) -> Vec<usize> {
    let runs = |e: &Element| {
        matches!(
            e.kind,
            Kind::Contact { .. }
                | Kind::Coil { .. }
                | Kind::Block { .. }
                | Kind::OutVariable(_)
                | Kind::InOutVariable(_)
        )
    };
    let deps: Vec<Vec<usize>> = g
        .elements
        .iter()
        .map(|e| {
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
                    _ if runs(&g.elements[i]) => out.push(i),
                    _ => {}
                }
            }
            out
        })
        .collect();
    let n = g.elements.len();
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut waits = vec![0usize; n];
    for (i, d) in deps.iter().enumerate() {
        let mut d = d.clone();
        crate::sort::all(&mut d);
        d.dedup();
        for &j in d.iter().filter(|&&j| j != i) {
            users[j].push(i);
            waits[i] += 1;
        }
    }
    let key = |i: usize| (g.elements[i].y, g.elements[i].x, i);
    let mut left: BTreeSet<(i64, i64, usize)> =
        (0..n).filter(|&i| runs(&g.elements[i])).map(key).collect();
    let mut ready: BTreeSet<(i64, i64, usize)> =
        left.iter().copied().filter(|k| waits[k.2] == 0).collect();
    let mut out = Vec::new();
    // A loop of wires: its first element runs when nothing else can.
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
