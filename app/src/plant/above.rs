//! The plant above the ladder on a phone (issue #52): on a narrow screen
//! the tools are a bottom sheet that covers the ladder, so the chosen
//! plant is drawn over the ladder instead, compact, as the ladder runs
//! it. Tablets and laptops keep it in the tools dock beside Watch and the
//! chart (docs/plants.md "In the page"). Only on a phone is it made at
//! all, so that the page holds one drawing of the plant elsewhere.

use leptos::prelude::*;

use super::Plants;
use crate::editor::LadderCtx;
use crate::state::Ctx;

/// The widest window drawn as a phone (style/workbench.css's phone rules).
const PHONE_MAX_PX: f64 = 700.0;

/// Whether the window is as narrow as a phone's.
fn narrow() -> bool {
    web_sys::window()
        .and_then(|w| w.inner_width().ok())
        .and_then(|w| w.as_f64())
        .is_some_and(|w| w <= PHONE_MAX_PX)
}

/// The chosen plant's figure above the ladder, on a phone only, once the
/// plants' part has arrived (the dock's tab fetches it).
#[component]
pub fn PlantAbove(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let phone = RwSignal::new(narrow());
    let resized = window_event_listener(leptos::ev::resize, move |_| {
        let now = narrow();
        if phone.get_untracked() != now {
            phone.set(now);
        }
    });
    on_cleanup(move || resized.remove());
    let chosen = Memo::new(move |_| ladder.cases.plant.with(Option::is_some));
    let label = move || ctx.lang.get().plant().tab;
    move || {
        let kit = plants.kit.get()?;
        (phone.get() && chosen.get()).then(|| {
            view! {
                <section class="plant-above" data-testid="plant-above" aria-label=label>
                    {(kit.above)()}
                </section>
            }
        })
    }
}
