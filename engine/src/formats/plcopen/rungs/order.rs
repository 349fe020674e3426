//! The order imported rungs run in when a block was split into several
//! rungs (issue #18): the rungs writing what a block computes (a relay
//! holding its input or result, a counter, an in-line timer) run before
//! the rungs reading it, as the origin tool evaluates a block before what
//! its outputs feed; otherwise the drawing's order stands.

use std::collections::BinaryHeap;

/// Rungs `0..n` reordered so that, for each `(writers, readers)`, every
/// writer runs before every reader that is not itself a writer. A writer
/// moves up to just before the first reader that needs it (rather than
/// the readers moving down), and rungs no constraint names keep their
/// order. Constraints that contradict each other (a cycle) keep the
/// drawing's order among what is left. Linear in the sum of the
/// constraints' sizes, times log n.
pub(super) fn writers_first(n: usize, constraints: &[(Vec<usize>, Vec<usize>)]) -> Vec<usize> {
    // Built from the end: a rung may take the last free place once every
    // reader that must follow it has one. Each constraint is a node of
    // its own, free once all its readers are placed, so a device read
    // and written by many rungs costs their sum, not their product.
    let mut waits = vec![0usize; n + constraints.len()];
    let mut freed_by: Vec<Vec<usize>> = vec![Vec::new(); n + constraints.len()];
    for (k, (writers, readers)) in constraints.iter().enumerate() {
        let node = n + k;
        let mut sorted = writers.clone();
        crate::sort::all(&mut sorted);
        let readers: Vec<usize> = readers
            .iter()
            .copied()
            .filter(|r| *r < n && sorted.binary_search(r).is_err())
            .collect();
        if readers.is_empty() {
            continue;
        }
        for &r in &readers {
            freed_by[r].push(node);
        }
        waits[node] = readers.len();
        for &w in writers.iter().filter(|w| **w < n) {
            waits[w] += 1;
            freed_by[node].push(w);
        }
    }
    let mut placed = vec![false; n];
    let mut free: BinaryHeap<usize> = (0..n).filter(|&r| waits[r] == 0).collect();
    let mut from_end = Vec::with_capacity(n);
    let mut last_unplaced = n;
    while from_end.len() < n {
        let r = match free.pop() {
            Some(r) if !placed[r] => r,
            Some(_) => continue,
            None => {
                // A cycle: the last rung still waiting goes next.
                while last_unplaced > 0 && placed[last_unplaced - 1] {
                    last_unplaced -= 1;
                }
                match last_unplaced.checked_sub(1) {
                    Some(r) => r,
                    None => break,
                }
            }
        };
        placed[r] = true;
        from_end.push(r);
        let mut todo = vec![r];
        while let Some(x) = todo.pop() {
            for &next in &freed_by[x] {
                waits[next] = waits[next].saturating_sub(1);
                if waits[next] == 0 {
                    if next >= n {
                        todo.push(next);
                    } else if !placed[next] {
                        free.push(next);
                    }
                }
            }
        }
    }
    from_end.reverse();
    from_end
}

#[cfg(test)]
mod tests {
    use super::writers_first;

    #[test]
    fn no_constraint_keeps_the_drawing_order() {
        assert_eq!(writers_first(4, &[]), [0, 1, 2, 3]);
    }

    #[test]
    fn a_writer_moves_up_to_just_before_its_first_reader() {
        // Rung 3 writes what rungs 1 and 4 read.
        assert_eq!(writers_first(5, &[(vec![3], vec![1, 4])]), [0, 3, 1, 2, 4]);
        // A writer already first stays; a rung that reads and writes the
        // device is a writer only.
        assert_eq!(writers_first(3, &[(vec![0, 2], vec![1, 2])]), [0, 2, 1]);
    }

    #[test]
    fn chains_resolve_and_cycles_keep_their_order() {
        // 2 writes what 0 reads; 3 writes what 2 reads.
        let chain = [(vec![2], vec![0]), (vec![3], vec![2])];
        assert_eq!(writers_first(4, &chain), [3, 2, 0, 1]);
        // 0 and 1 each write what the other reads: both orders break one
        // constraint; the drawing's stands.
        let cycle = [(vec![0], vec![1]), (vec![1], vec![0])];
        let order = writers_first(2, &cycle);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, [0, 1], "every rung once: {order:?}");
    }

    #[test]
    fn thousands_of_readers_and_writers_of_one_device_stay_cheap() {
        let n = 20_000;
        let writers: Vec<usize> = (0..n).step_by(2).collect();
        let readers: Vec<usize> = (1..n).step_by(2).collect();
        let order = writers_first(n, &[(writers, readers)]);
        let first_reader = order.iter().position(|r| r % 2 == 1);
        assert_eq!(first_reader, Some(n / 2), "every writer first");
    }
}
