//! Which in-line boxes would not stand on their rung's main line.
//!
//! The AVR PLC's NOT, edge and timer boxes act on the running result, so
//! its compiler takes them on a rung's main line only. A block another
//! tool draws may sit anywhere: NOT(a) OR a puts the NOT in a parallel
//! branch. The importer holds such a NOT's or edge's input in a spare
//! relay instead (its NC or edge contact then gives the box's output, as
//! on IO86A, which has no in-line boxes at all), and gives such a timer a
//! rung of its own into a spare relay whose contact gives its Q. A box is on the main line when
//! every path from the rail to what it feeds passes through it: its edge
//! is a bridge of the body's graph with the rail on its input's side.

use std::collections::HashSet;

/// One edge of the body's graph between (joined) points; `relayable`:
/// a NOT, edge or timer box the importer may move off the rung through a
/// relay.
pub(super) struct Link {
    pub from: usize,
    pub to: usize,
    pub relayable: bool,
}

/// The indices of the relayable links that are off their rung's main
/// line, once those found so far are relayed (a relayed box becomes a
/// contact from the rail to its output, which may take another box off
/// the main line: repeated until none is). `points` bounds the point
/// numbers. Each round is linear; it stops once more than `relays` are
/// found (there are no relays for more).
pub(super) fn off_main_line(
    links: &mut [Link],
    rail: usize,
    points: usize,
    relays: usize,
) -> HashSet<usize> {
    let mut off = HashSet::new();
    while off.len() <= relays {
        let on_main = main_line_links(links, rail, points);
        let newly: Vec<usize> = (0..links.len())
            .filter(|&i| links[i].relayable && !on_main[i])
            .collect();
        if newly.is_empty() {
            return off;
        }
        for i in newly {
            // Relayed: a contact of the relay, from the rail.
            links[i].from = rail;
            links[i].relayable = false;
            off.insert(i);
        }
    }
    off
}

/// Whether each link is a bridge whose far side (away from the rail)
/// holds its `to` point: Tarjan's bridges by an iterative depth-first
/// walk from the rail over the undirected multigraph. Links the rail
/// does not reach are not on a main line.
fn main_line_links(links: &[Link], rail: usize, points: usize) -> Vec<bool> {
    let mut around: Vec<Vec<(usize, usize)>> = vec![Vec::new(); points];
    for (i, l) in links.iter().enumerate() {
        if l.from < points && l.to < points {
            around[l.from].push((l.to, i));
            around[l.to].push((l.from, i));
        }
    }
    let mut on_main = vec![false; links.len()];
    if rail >= points {
        return on_main;
    }
    let unseen = usize::MAX;
    let (mut order, mut low) = (vec![unseen; points], vec![0; points]);
    let mut next = 0;
    // (point, link it was entered by, next neighbour to look at)
    let mut stack = vec![(rail, usize::MAX, 0usize)];
    order[rail] = next;
    low[rail] = next;
    next += 1;
    while let Some(&mut (p, by, ref mut k)) = stack.last_mut() {
        if let Some(&(q, link)) = around[p].get(*k) {
            *k += 1;
            if link == by {
                continue;
            }
            if order[q] == unseen {
                order[q] = next;
                low[q] = next;
                next += 1;
                stack.push((q, link, 0));
            } else {
                low[p] = low[p].min(order[q]);
            }
            continue;
        }
        stack.pop();
        if let Some(&(parent, _, _)) = stack.last() {
            low[parent] = low[parent].min(low[p]);
            // A bridge: nothing below p reaches above it but `by`. On
            // the main line when it runs from the rail's side to p's.
            if low[p] > order[parent] && links[by].to == p && links[by].from == parent {
                on_main[by] = true;
            }
        }
    }
    on_main
}

#[cfg(test)]
mod tests {
    use super::*;

    fn link(from: usize, to: usize) -> Link {
        Link {
            from,
            to,
            relayable: true,
        }
    }

    #[test]
    fn a_box_in_series_is_on_the_main_line_and_one_in_a_branch_is_not() {
        // 0 rail -a-> 1 -NOT-> 2 (coil): on it.
        let mut links = vec![link(0, 1), link(1, 2)];
        links[0].relayable = false;
        assert!(off_main_line(&mut links, 0, 3, 80).is_empty());
        // NOT(a) OR a: 0 -a-> 1 -NOT-> 2, and 1 joined... a second
        // contact 0 -> 2 in parallel: the NOT is off it.
        let mut links = vec![link(0, 1), link(1, 2), link(0, 2)];
        links[0].relayable = false;
        links[2].relayable = false;
        assert_eq!(off_main_line(&mut links, 0, 3, 80), HashSet::from([1]));
    }

    #[test]
    fn relaying_one_box_can_take_another_off_the_main_line() {
        // 0 -NOT1-> 1, then 1 -c-> 2 -NOT2-> 3 and 1 -d-> 3 in parallel:
        // NOT2 is off; relayed, it joins the rail to 3, so NOT1 is too.
        let mut links = vec![link(0, 1), link(1, 2), link(2, 3), link(1, 3)];
        links[1].relayable = false;
        links[3].relayable = false;
        assert_eq!(off_main_line(&mut links, 0, 4, 80), HashSet::from([0, 2]));
    }

    #[test]
    fn a_long_chain_is_walked_without_recursion() {
        let n = 200_000;
        let mut links: Vec<Link> = (0..n).map(|i| link(i, i + 1)).collect();
        assert!(off_main_line(&mut links, 0, n + 1, 80).is_empty());
    }
}
