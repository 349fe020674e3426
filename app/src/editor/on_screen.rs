//! Which rungs a running frame brings up to date: those the ladder shows
//! (with an eighth of a view above and below) every frame, the others in
//! turn, one frame in [`TURNS`]; the AVR panel's lamps likewise. With 200
//! rungs whose every cell changes each frame (a plant coupled, issue #52),
//! repainting them all cost 30 ms of script a frame, most of it for rungs
//! nobody saw. A paused, stopped or travelled-to machine changes nothing
//! a frame, so every rung is brought up to date then (it costs only
//! comparisons), as after a step or a seek.
//!
//! What is on screen is measured once a frame, before the frame changes
//! the page (the view's effects run after it), by a binary search over
//! the items' boxes: about 16 reads of a laid-out page, and no observer
//! to ship on the first screen.

use std::ops::Range;

use leptos::wasm_bindgen::JsCast;

/// A rung off screen is brought up to date once in this many running
/// frames (each frame a different sixteenth of them: with 200 rungs,
/// an eighth in turn cost more script than the rungs on screen).
pub const TURNS: u64 = 16;

/// Which rungs a frame brings up to date.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Due {
    /// Every rung.
    All,
    /// The rungs in `shown`, and each other rung whose number is
    /// `turn` modulo [`TURNS`].
    InTurn {
        /// The rungs on screen (by number, 0-based).
        shown: Range<usize>,
        /// The running frame's count.
        turn: u64,
    },
}

impl Due {
    /// What a frame of `turn` brings up to date: everything when it has
    /// no turn (the machine paused, stopped or travelled to: the frame
    /// changes nothing, as after a step or a seek), else what `shown`
    /// finds on screen every frame and the rest in turn (everything when
    /// nothing can be measured).
    pub fn of(turn: Option<u64>, shown: impl FnOnce() -> Option<Range<usize>>) -> Due {
        match turn.and_then(|turn| Some((turn, shown()?))) {
            Some((turn, shown)) => Due::InTurn { shown, turn },
            None => Due::All,
        }
    }

    /// Whether rung (or row) `number` is brought up to date this frame.
    pub fn covers(&self, number: usize) -> bool {
        match self {
            Due::All => true,
            Due::InTurn { shown, turn } => {
                shown.contains(&number) || number as u64 % TURNS == turn % TURNS
            }
        }
    }
}

/// The rungs, of `count` in order down the ladder, whose box (top,
/// bottom) as `bounds` gives it meets `lo..hi`. A rung without a box
/// (not laid out) counts as meeting it, so it is never left behind.
pub fn meeting(
    count: usize,
    lo: f64,
    hi: f64,
    bounds: impl Fn(usize) -> Option<(f64, f64)>,
) -> Range<usize> {
    // The first rung whose bottom is below `lo`, then the first from
    // there whose top is at or below `hi`: boxes go down in order.
    let first = partition(0, count, |i| {
        bounds(i).is_some_and(|(_, bottom)| bottom <= lo)
    });
    let end = partition(first, count, |i| bounds(i).is_none_or(|(top, _)| top < hi));
    first..end
}

/// The first index in `from..to` where `before` is false (it is true
/// for a prefix and false after).
fn partition(from: usize, to: usize, before: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (from, to);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The rungs of ladder `grid` on screen now ([`shown_in`]).
pub fn rungs_on_screen(grid: &web_sys::Element) -> Option<Range<usize>> {
    shown_in(grid, &grid.query_selector_all(".rung").ok()?)
}

/// Which of `items` (in order down the page) `view` shows now (its box
/// within the window), with an eighth of a view above and below (an item
/// scrolled into view is brought up to date in the next frame anyway; a
/// wider margin cost the browser the style, layout and paint of items
/// nobody saw); `None` when there is no view to measure (hidden, not laid
/// out).
pub fn shown_in(view: &web_sys::Element, items: &web_sys::NodeList) -> Option<Range<usize>> {
    let rect = view.get_bounding_client_rect();
    let window_height = web_sys::window()?.inner_height().ok()?.as_f64()?;
    let (top, bottom) = (rect.top().max(0.0), rect.bottom().min(window_height));
    if bottom <= top {
        return None;
    }
    let margin = (bottom - top) / 8.0;
    let bounds = |i: usize| {
        let item: web_sys::Element = items.get(i as u32)?.unchecked_into();
        let r = item.get_bounding_client_rect();
        Some((r.top(), r.bottom()))
    };
    Some(meeting(
        items.length() as usize,
        top - margin,
        bottom + margin,
        bounds,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rungs 100 high, one under the other from 0.
    fn rows(i: usize) -> Option<(f64, f64)> {
        Some((i as f64 * 100.0, i as f64 * 100.0 + 100.0))
    }

    #[test]
    fn the_rungs_meeting_the_view_are_found() {
        assert_eq!(meeting(200, 250.0, 520.0, rows), 2..6);
        assert_eq!(meeting(200, -50.0, 50.0, rows), 0..1);
        assert_eq!(meeting(200, 19_950.0, 30_000.0, rows), 199..200);
        assert_eq!(meeting(200, 30_000.0, 40_000.0, rows), 200..200);
        assert_eq!(meeting(0, 0.0, 100.0, rows), 0..0);
        // A rung without a box is never left out.
        let unlaid = |i: usize| if i == 3 { None } else { rows(i) };
        assert_eq!(meeting(200, 0.0, 250.0, unlaid), 0..4);
    }

    #[test]
    fn a_rung_off_screen_comes_up_once_in_turns() {
        let due = |turn| Due::InTurn {
            shown: 10..20,
            turn,
        };
        assert!(
            (0..TURNS).all(|t| due(t).covers(12)),
            "on screen: every frame"
        );
        let far = 150;
        let frames = (0..TURNS * 3).filter(|&t| due(t).covers(far)).count();
        assert_eq!(frames, 3, "off screen: once in {TURNS} frames");
        // Each frame brings a different share of the rungs off screen.
        let share = |t| (20..200).filter(|&n| due(t).covers(n)).count();
        assert!(
            (0..TURNS).all(|t| (11..=12).contains(&share(t))),
            "{:?}",
            (0..TURNS).map(share).collect::<Vec<_>>()
        );
        assert!((0..300).all(|n| Due::All.covers(n)));
    }

    #[test]
    fn a_frame_without_a_turn_brings_everything_up_to_date() {
        // Paused, stopped or travelled to: whatever is on screen, all of
        // it (the AVR panel's lamps too: one rule for both).
        assert_eq!(Due::of(None, || Some(0..10)), Due::All);
        assert!(Due::of(None, || Some(0..10)).covers(150));
        // Running: what is on screen and the rest in turn...
        assert_eq!(
            Due::of(Some(7), || Some(0..10)),
            Due::InTurn {
                shown: 0..10,
                turn: 7
            }
        );
        // ...unless nothing could be measured (hidden, not laid out).
        assert_eq!(Due::of(Some(7), || None), Due::All);
    }
}
