//! Manual mode (`plant-manual`, part `plants`; docs/plants.md "In the
//! page"): with the machine stopped, the user drives the plant's
//! actuators by hand, a toggle each, as a commissioning engineer jogs a
//! motor, and the plant moves on a clock of its own (real time). Run,
//! or leaving manual mode, gives the plant back to the machine as it
//! stands: its parts, level and places are kept.

use std::time::Duration;

use leptos::prelude::*;

use super::Plants;
use crate::editor::LadderCtx;
use crate::state::Ctx;

/// How often the plant moves by hand, in ms of real time.
const TICK_MS: u64 = 50;
/// The most a tick moves the plant (a tab in the background sleeps: it
/// does not catch up for minutes when it wakes).
const MOST_MS: f64 = 200.0;

/// The switch, the actuators' toggles and the clock that moves the plant.
#[component]
pub(super) fn Manual(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let t = move || ctx.lang.get().plant_faults();
    // Per signal of the plant: driven on by hand.
    let hand = RwSignal::new(Vec::<bool>::new());
    let running = move || plants.shown.with(|s| s.as_ref().is_some_and(|s| s.running));
    let ticker = StoredValue::new(None::<IntervalHandle>);
    let stop = move || {
        if let Some(handle) = ticker.try_update_value(Option::take).flatten() {
            handle.clear();
        }
    };
    let last = StoredValue::new(0.0_f64);
    let tick = move || {
        let now = js_sys::Date::now();
        let dt = (now - last.get_value()).clamp(0.0, MOST_MS);
        last.set_value(now);
        let mut gone = false;
        ladder.with_rig(|machine, rig| match rig {
            // Run gives the plant back to the machine.
            Some(_) if machine.running() => gone = true,
            Some(rig) => hand.with_untracked(|h| rig.jog(machine, h, dt as u32)),
            None => gone = true,
        });
        if gone {
            plants.manual.set(false);
        }
        plants.publish(ladder);
    };
    Effect::new(move || {
        stop();
        if plants.manual.get() {
            last.set_value(js_sys::Date::now());
            ticker.set_value(set_interval_with_handle(tick, Duration::from_millis(TICK_MS)).ok());
        } else {
            hand.set(Vec::new());
        }
    });
    on_cleanup(move || {
        stop();
        plants.manual.set(false);
    });
    view! {
        <section class="plant-manual" aria-label=move || t().manual>
            <label>
                <input type="checkbox" role="switch" data-testid="plant-manual"
                    prop:checked=move || plants.manual.get() disabled=running
                    on:change=move |e| plants.manual.set(event_target_checked(&e)) />
                {move || t().manual}
            </label>
            <Show when=move || plants.manual.get()>
                <p class="plant-manual-note">{move || t().manual_note}</p>
                <Toggles hand />
            </Show>
        </section>
    }
}

/// A toggle per actuator of the plant, pressed while driven on by hand.
#[component]
fn Toggles(hand: RwSignal<Vec<bool>>) -> impl IntoView {
    let plants = Plants::get();
    let toggles = move || {
        let signals = plants
            .shown
            .with(|s| s.as_ref().map(|s| s.signals.clone()).unwrap_or_default());
        signals
            .into_iter()
            .enumerate()
            .filter(|(_, s)| s.output)
            .map(|(i, s)| {
                let on = move || hand.with(|h| h.get(i).copied().unwrap_or(false));
                let flip = move |_| {
                    hand.update(|h| {
                        if h.len() <= i {
                            h.resize(i + 1, false);
                        }
                        h[i] = !h[i];
                    })
                };
                view! {
                    <button type="button" class="plant-hand" data-testid=format!("plant-hand-{}", s.name)
                        aria-pressed=move || on().to_string() on:click=flip>{s.name}</button>
                }
            })
            .collect_view()
    };
    view! { <div class="plant-hands">{toggles}</div> }
}
