//! A segment digit drawn: MINASEC-U's counter display and the soft PLC
//! board's LDmicro digits (7, 9, 14 or 16 segments).

use leptos::prelude::*;

/// How one segment is drawn in the digit's 20×36 cell.
#[derive(Clone, Copy)]
enum Shape {
    /// A bar: x, y, width, height.
    Bar(f32, f32, f32, f32),
    /// A diagonal or centre stroke: from (x1, y1) to (x2, y2).
    Stroke(f32, f32, f32, f32),
    /// The point.
    Dot,
}

/// Where segment `name` (a letter of `engine::runtime::ldmicro::segments::names`)
/// is on a digit of `segments` segments.
fn shape(segments: u8, name: char) -> Shape {
    use Shape::{Bar, Dot, Stroke};
    // Split bars: the middle on 14 and 16 segments, a and d on 16.
    let halves = segments >= 14;
    match (name, halves, segments == 16) {
        ('a', _, false) => Bar(3.0, 0.0, 14.0, 3.0),
        ('a', _, true) => Bar(3.0, 0.0, 6.5, 3.0),
        ('A', _, _) => Bar(10.5, 0.0, 6.5, 3.0),
        ('b', _, _) => Bar(17.0, 3.0, 3.0, 13.0),
        ('c', _, _) => Bar(17.0, 19.0, 3.0, 13.0),
        ('d', _, false) => Bar(3.0, 32.0, 14.0, 3.0),
        ('d', _, true) => Bar(3.0, 32.0, 6.5, 3.0),
        ('D', _, _) => Bar(10.5, 32.0, 6.5, 3.0),
        ('e', _, _) => Bar(0.0, 19.0, 3.0, 13.0),
        ('f', _, _) => Bar(0.0, 3.0, 3.0, 13.0),
        ('g', false, _) => Bar(3.0, 16.0, 14.0, 3.0),
        ('g', true, _) => Bar(3.0, 16.0, 6.5, 3.0),
        ('G', _, _) => Bar(10.5, 16.0, 6.5, 3.0),
        // Nine segments: two long diagonals, upper and lower.
        ('j', false, _) => Stroke(16.0, 4.5, 4.0, 15.0),
        ('m', false, _) => Stroke(16.0, 20.5, 4.0, 31.0),
        ('h', _, _) => Stroke(4.5, 4.5, 8.5, 14.5),
        ('i', _, _) => Stroke(10.0, 4.5, 10.0, 14.5),
        ('j', true, _) => Stroke(15.5, 4.5, 11.5, 14.5),
        ('m', true, _) => Stroke(8.5, 20.5, 4.5, 30.5),
        ('l', _, _) => Stroke(10.0, 20.5, 10.0, 30.5),
        ('k', _, _) => Stroke(11.5, 20.5, 15.5, 30.5),
        _ => Dot,
    }
}

/// A digit of `segments` segments (7 when not given) lighting the bits
/// of `lit`, in the order `engine::runtime::ldmicro::segments::names` gives (on
/// seven: bit 0 = a … bit 6 = g, bit 7 the point).
#[component]
pub fn Digit(lit: Signal<u32>, #[prop(default = 7)] segments: u8) -> impl IntoView {
    let names = engine::runtime::ldmicro::segments::names(segments);
    view! {
        <svg viewBox="-2 -2 26 40" class="digit" aria-hidden="true">
            {names
                .chars()
                .enumerate()
                .map(|(i, name)| {
                    let on = Signal::derive(move || lit.get() >> i & 1 != 0);
                    match shape(segments, name) {
                        Shape::Bar(x, y, w, h) => view! {
                            <rect x=x y=y width=w height=h rx="1" class="seg" class:lit=on data-seg=name.to_string()></rect>
                        }
                        .into_any(),
                        Shape::Stroke(x1, y1, x2, y2) => view! {
                            <line x1=x1 y1=y1 x2=x2 y2=y2 class="seg stroke" class:lit=on data-seg=name.to_string()></line>
                        }
                        .into_any(),
                        Shape::Dot => view! {
                            <circle cx="22.5" cy="33.5" r="1.5" class="seg point" class:lit=on data-seg=name.to_string()></circle>
                        }
                        .into_any(),
                    }
                })
                .collect_view()}
        </svg>
    }
}
