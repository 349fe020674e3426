//! The phone's strip: the inputs the ladder's contacts read and the
//! outputs its coils write, on the same screen as the ladder, so a tap on
//! X00 and its rung lighting are seen together. An input toggles as a
//! contact clicked on the running ladder does (held until released from
//! the watch tool's force list); an output is a lamp.

use engine::ladder::Ladder;
use leptos::prelude::*;

use super::LadderCtx;

/// A device on the strip.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct IoPoint {
    /// Its name as the ladder writes it.
    pub name: String,
    /// Read by a contact (an input to drive); else written by a coil (a lamp).
    pub input: bool,
}

/// The most devices the strip shows of each kind: a phone's width.
pub const MOST: usize = 8;

/// The ladder's inputs (contacts' devices not written by the ladder
/// itself) and outputs (coils' devices), each once, in order of first
/// use; at most [`MOST`] of each.
pub fn io_points(ladder: &Ladder) -> Vec<IoPoint> {
    let elements: Vec<&engine::ladder::Element> = ladder
        .rungs
        .iter()
        .flat_map(|r| r.elements().map(|(_, e)| e))
        .collect();
    let written: Vec<&str> = elements.iter().filter_map(|e| e.written_device()).collect();
    let mut inputs: Vec<IoPoint> = Vec::new();
    let mut outputs: Vec<IoPoint> = Vec::new();
    for e in &elements {
        if let Some(d) = e.read_device() {
            let fresh = !written.contains(&d) && !inputs.iter().any(|p| p.name == d);
            if fresh && inputs.len() < MOST {
                inputs.push(IoPoint {
                    name: d.to_string(),
                    input: true,
                });
            }
        }
        if let Some(d) = e.written_device() {
            if !outputs.iter().any(|p| p.name == d) && outputs.len() < MOST {
                outputs.push(IoPoint {
                    name: d.to_string(),
                    input: false,
                });
            }
        }
    }
    inputs.extend(outputs);
    inputs
}

/// The strip (shown on phones only, by the style sheet): `strip-in-<name>`
/// buttons and `strip-out-<name>` lamps, each with `data-on`.
#[component]
pub fn IoStrip(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let on = move |name: &str| {
        ctx.live
            .io_values
            .with(|v| v.iter().any(|(n, on)| n == name && *on))
    };
    view! {
        <div class="io-strip" data-testid="io-strip" role="group" aria-label=move || t().io_strip>
            <Show when=move || ctx.drawing.io.with(Vec::is_empty)>
                <span class="muted">{move || t().io_strip_empty}</span>
            </Show>
            <For each=move || ctx.drawing.io.get() key=|p| p.clone() children=move |p: IoPoint| {
                let name = p.name.clone();
                let testid = format!("strip-{}-{}", if p.input { "in" } else { "out" }, p.name);
                let lit = {
                    let name = name.clone();
                    move || if on(&name) { "1" } else { "0" }
                };
                if p.input {
                    let pressed = {
                        let name = name.clone();
                        move || on(&name).to_string()
                    };
                    let shown = name.clone();
                    view! {
                        <button type="button" class="strip-in" data-testid=testid data-on=lit aria-pressed=pressed
                            on:click=move |_| super::live::drive_from_ladder(ctx, &name, false)>
                            {shown}
                        </button>
                    }
                    .into_any()
                } else {
                    view! {
                        <span class="strip-out" data-testid=testid data-on=lit role="img"
                            aria-label={
                                let name = name.clone();
                                move || format!("{name} {}", if on(&name) { t().on } else { t().off })
                            }>
                            <span class="strip-lamp" aria-hidden="true"></span>
                            {name.clone()}
                        </span>
                    }
                    .into_any()
                }
            } />
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::ladder::{Element, Rung};

    #[test]
    fn the_strip_holds_the_ladders_inputs_then_its_outputs_each_once() {
        let rung = |cells: Vec<Vec<Option<Element>>>| Rung {
            comment: String::new(),
            cells,
            links: vec![],
        };
        let ladder = Ladder {
            rungs: vec![
                rung(vec![
                    vec![
                        Some(Element::no("X00")),
                        Some(Element::nc("X01")),
                        Some(Element::coil("Y00")),
                    ],
                    vec![Some(Element::no("Y00"))],
                ]),
                rung(vec![vec![
                    Some(Element::no("X00")),
                    Some(Element::coil("Y01")),
                ]]),
            ],
            ..Ladder::default()
        };
        let points: Vec<(String, bool)> = io_points(&ladder)
            .into_iter()
            .map(|p| (p.name, p.input))
            .collect();
        // Y00 is read by a contact but written by the ladder: a lamp only.
        let expected = [("X00", true), ("X01", true), ("Y00", false), ("Y01", false)];
        assert_eq!(points, expected.map(|(n, i)| (n.to_string(), i)).to_vec());
    }

    #[test]
    fn the_strip_stops_at_a_phones_width() {
        let contacts: Vec<Option<Element>> = (0..12)
            .map(|i| Some(Element::no(&format!("X{i:02}"))))
            .collect();
        let ladder = Ladder {
            rungs: vec![Rung {
                comment: String::new(),
                cells: vec![contacts],
                links: vec![],
            }],
            ..Ladder::default()
        };
        assert_eq!(io_points(&ladder).len(), MOST);
    }
}
