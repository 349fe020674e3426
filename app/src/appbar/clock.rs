//! The machine's clock in the app bar, for every machine: its state
//! (`data-state`: running, paused, stopped), simulated time (`data-ms`),
//! the scan count (the page's one) and the last scans' duration. Time
//! stands still while the machine is stopped or paused (`crate::sim`).

use leptos::prelude::*;

use crate::editor::LadderCtx;

/// `sim-time`: what the machine's clock shows.
#[component]
pub fn SimClock(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let clock = ctx.live.clock;
    let state = move || match (clock.with(|c| c.running), ctx.page.paused.get()) {
        (false, _) => "stopped",
        (true, true) => "paused",
        (true, false) => "running",
    };
    view! {
        <span class="clock" data-testid="sim-time" role="status" data-state=state
            title=move || t().sim_time
            data-ms=move || clock.with(|c| c.ms()).to_string()>
            // Two short lines of a fixed width, so the app bar does not
            // move as the figures grow.
            <span class="clock-line">
                <span class="clock-state">{move || match state() {
                    "running" => t().state_running,
                    "paused" => t().state_paused,
                    _ => t().state_stopped,
                }}</span>
                {move || {
                    let ms = clock.with(|c| c.ms());
                    format!(" · {}.{:03} {} ·", ms / 1000, ms % 1000, t().seconds)
                }}
            </span>
            <span class="clock-line">
                {move || {
                    let c = clock.get();
                    let scan = c
                        .scan_us
                        .map(|us| format!(" · {} {}.{:02} ms", t().scan_time, us / 1000, us % 1000 / 10))
                        .unwrap_or_default();
                    format!("{} {}{scan}", c.scans, t().scans)
                }}
            </span>
        </span>
    }
}
