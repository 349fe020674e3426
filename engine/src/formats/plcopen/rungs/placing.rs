//! Where the rungs go: a block's helper rungs before their readers (as
//! the origin tool runs a block before what its outputs feed), each
//! comparison's `CMP` right before the copy of its flag, and each comment
//! box on the rung below it.

use std::collections::BTreeMap;

use crate::formats::plcopen::lower::body::{Body, CommentBox, CompareCopy};
use crate::formats::plcopen::parts::drawn_x;
use crate::ladder::element::{CoilKind, Element};
use crate::ladder::grid::Pos;
use crate::ladder::net::RungLogic;

impl Body {
    /// A block runs before what its outputs feed ([`super::order`]): the
    /// rungs writing a relay that holds a block's input or result
    /// ([`Body::helpers`]), or a device in [`Body::ordered`], run before
    /// the rungs reading it; then each comparison's `CMP` goes right
    /// before the copy of its flag.
    pub(super) fn helpers_first(&self, rungs: &mut Vec<(Pos, RungLogic, usize)>) {
        let mut touches: BTreeMap<&str, (Vec<usize>, Vec<usize>)> = self
            .helpers
            .iter()
            .map(|h| h.relay.as_str())
            .chain(self.ordered.iter().map(String::as_str))
            .map(|d| (d, (Vec::new(), Vec::new())))
            .collect();
        let carried = self.carried_first(rungs);
        if touches.is_empty() && carried.is_empty() {
            return;
        }
        for (i, (_, r, _)) in rungs.iter().enumerate() {
            for (e, _) in &r.outputs {
                if let Some(t) = e.written_device().and_then(|d| touches.get_mut(d)) {
                    t.0.push(i);
                }
            }
            for (e, _) in r.condition.leaves() {
                if let Some(t) = e.read_device().and_then(|d| touches.get_mut(d)) {
                    t.1.push(i);
                }
            }
        }
        // A reset wins over a count or a set in the same scan (CTU's R,
        // CTD's LD, R of a CTUD's QD relay): the rung resetting runs after
        // the rungs counting or setting.
        let mut wins: BTreeMap<&str, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
        for (i, (_, r, _)) in rungs.iter().enumerate() {
            for (e, _) in &r.outputs {
                let Some(d) = e.written_device().filter(|d| touches.contains_key(d)) else {
                    continue;
                };
                let entry = wins.entry(d).or_default();
                match e {
                    Element::Coil {
                        kind: CoilKind::Reset,
                        ..
                    } => entry.1.push(i),
                    _ => entry.0.push(i),
                }
            }
        }
        // A comparison reads its operands after this scan's writes, and
        // its flag is copied after it.
        let mut compared = Vec::new();
        for CompareCopy {
            at,
            relay,
            operands: [a, b],
        } in &self.compares
        {
            let Some(cmp) = rung_at(rungs, at) else {
                continue;
            };
            compared.push((vec![cmp], writing(rungs, &[relay])));
            compared.push((writing(rungs, &[a, b]), vec![cmp]));
        }
        let constraints: Vec<(Vec<usize>, Vec<usize>)> = touches
            .into_values()
            .chain(wins.into_values())
            .chain(compared)
            .chain(carried)
            .collect();
        let order = super::order::writers_first(rungs.len(), &constraints);
        let mut taken: Vec<Option<(Pos, RungLogic, usize)>> =
            std::mem::take(rungs).into_iter().map(Some).collect();
        rungs.extend(order.into_iter().filter_map(|i| taken.get_mut(i)?.take()));
        for CompareCopy { at, relay, .. } in &self.compares {
            let copy = writing(rungs, &[relay]).first().copied();
            if let (Some(c), Some(k)) = (rung_at(rungs, at), copy) {
                let rung = rungs.remove(c);
                let k = if c < k { k - 1 } else { k };
                rungs.insert(k, rung);
            }
        }
    }

    /// A comment belongs to the nearest rung that starts at or below it,
    /// distance being rows down (to the rung's top) plus columns across
    /// (to its leftmost element): a page of networks drawn side by side
    /// (OpenPLC's dancing-lights) puts each title above its own network,
    /// which may start lower than the next column's. Only the
    /// [`COMMENT_REACH`] rungs starting first below it are weighed (rungs
    /// are sorted by their top); below the last rung, the last rung
    /// takes it. Among rungs as near, the first one after it in the file
    /// takes it, weighed too when past those 16: CODESYS draws every
    /// element at 0,0 and writes each network's title before it.
    pub(super) fn attach_comments(&mut self, rungs: &mut [(Pos, RungLogic, usize)]) {
        if self.comments.is_empty() {
            return;
        }
        let lefts: Vec<usize> = rungs
            .iter()
            .map(|(_, r, _)| {
                let leaves = r.condition.leaves().into_iter().map(|(_, p)| p);
                let places = leaves.chain(r.outputs.iter().map(|(_, p)| *p));
                places.map(|p| drawn_x(p.col)).min().unwrap_or(0)
            })
            .collect();
        // The rungs by their line in the file.
        let mut by_line: Vec<(usize, usize)> =
            rungs.iter().enumerate().map(|(i, r)| (r.2, i)).collect();
        crate::sort::all(&mut by_line);
        for CommentBox {
            row: y,
            col: x,
            text,
            line,
        } in std::mem::take(&mut self.comments)
        {
            let first = rungs.partition_point(|(top, _, _)| top.row < y);
            let distance = |i: usize| (rungs[i].0.row - y) + lefts[i].abs_diff(x);
            // The first rung after the comment in the file.
            let next = by_line
                .get(by_line.partition_point(|&(l, _)| l <= line))
                .map(|&(_, i)| i)
                .filter(|&i| i >= first);
            let after = |i: usize| {
                if rungs[i].2 > line {
                    rungs[i].2
                } else {
                    usize::MAX
                }
            };
            let i = (first..rungs.len().min(first + COMMENT_REACH))
                .chain(next)
                .min_by_key(|&i| (distance(i), after(i), i))
                .unwrap_or(rungs.len().saturating_sub(1));
            if let Some((_, r, _)) = rungs.get_mut(i) {
                if !r.comment.is_empty() {
                    r.comment.push('\n');
                }
                r.comment.push_str(&text);
            }
        }
    }
}

impl Body {
    /// Soft PLC: for each variable carrying a box's output into another
    /// box, the rungs writing it (to run first) and those reading it.
    fn carried_first(&self, rungs: &[(Pos, RungLogic, usize)]) -> Vec<(Vec<usize>, Vec<usize>)> {
        let boxes = |r: &RungLogic| -> Vec<crate::ladder::BlockCall> {
            r.leaves()
                .into_iter()
                .map(|(e, _)| e)
                .chain(r.outputs.iter().map(|(e, _)| e))
                .filter_map(Element::block)
                .cloned()
                .collect()
        };
        let calls: Vec<Vec<crate::ladder::BlockCall>> =
            rungs.iter().map(|(_, r, _)| boxes(r)).collect();
        let named = |pins: &[(String, String)], name: &str| pins.iter().any(|(_, v)| v == name);
        self.temps
            .iter()
            .map(|t| {
                let (mut writers, mut readers) = (Vec::new(), Vec::new());
                for (i, calls) in calls.iter().enumerate() {
                    if calls.iter().any(|c| named(&c.outputs, &t.name)) {
                        writers.push(i);
                    }
                    if calls.iter().any(|c| named(&c.inputs, &t.name)) {
                        readers.push(i);
                    }
                }
                (writers, readers)
            })
            .collect()
    }
}

/// How many rungs below a comment box may take it (side by side
/// networks; bounded so a hostile file's comments cost linear time).
const COMMENT_REACH: usize = 16;

/// The rungs that write one of `devices`, in order.
fn writing(rungs: &[(Pos, RungLogic, usize)], devices: &[&String]) -> Vec<usize> {
    (0..rungs.len())
        .filter(|&i| {
            rungs[i].1.outputs.iter().any(|(e, _)| {
                e.written_device()
                    .is_some_and(|d| devices.iter().any(|w| w.as_str() == d))
            })
        })
        .collect()
}

/// The rung with an output placed at `at`.
fn rung_at(rungs: &[(Pos, RungLogic, usize)], at: &Pos) -> Option<usize> {
    rungs
        .iter()
        .position(|(_, x, _)| x.outputs.iter().any(|(_, p)| p == at))
}
