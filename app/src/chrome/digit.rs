//! One 7-segment digit drawn: MINASEC-U's counter display and the soft
//! PLC board's LDmicro digits.

use leptos::prelude::*;

/// A digit lighting the segments in `lit`: bit 0 = a … bit 6 = g, bit 7
/// the point (the order of every datasheet and of LDmicro's table).
#[component]
pub fn Digit(lit: Signal<u8>) -> impl IntoView {
    // (x, y, width, height) of segments a..g in a 20×36 cell.
    const SEGMENTS: [(u8, u8, u8, u8); 7] = [
        (3, 0, 14, 3),
        (17, 3, 3, 13),
        (17, 19, 3, 13),
        (3, 32, 14, 3),
        (0, 19, 3, 13),
        (0, 3, 3, 13),
        (3, 16, 14, 3),
    ];
    let point = Signal::derive(move || lit.get() & 0x80 != 0);
    view! {
        <svg viewBox="-2 -2 26 40" class="digit" aria-hidden="true">
            {SEGMENTS
                .iter()
                .enumerate()
                .map(|(i, &(x, y, w, h))| {
                    let on = Signal::derive(move || lit.get() >> i & 1 != 0);
                    view! {
                        <rect x=x y=y width=w height=h rx="1" class="seg" class:lit=on></rect>
                    }
                })
                .collect_view()}
            <circle cx="22.5" cy="33.5" r="1.5" class="seg point" class:lit=point></circle>
        </svg>
    }
}
