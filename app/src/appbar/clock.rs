//! The machine's clock in the app bar, for every machine: its state
//! (`data-state`: running, paused, stopped), simulated time (`data-ms`),
//! the scan count (the page's one) and the last scans' duration. Time
//! stands still while the machine is stopped or paused (`crate::sim`).
//! While it runs, the figures are said [`SAID_EVERY_MS`] apart.

use leptos::prelude::*;

use crate::editor::state::Clock;
use crate::editor::LadderCtx;

/// While the machine runs, the figures change at most this often (wall
/// ms): faster is a blur no one reads, and each change lays the app bar
/// out, which made the pointer's hover be tested again each frame
/// (issue #52, docs/performance.md). `data-ms` follows every frame.
const SAID_EVERY_MS: f64 = 250.0;

/// Whether the clock's figures are said again now: at once while the
/// machine stands (stopped or paused), else [`SAID_EVERY_MS`] after the
/// last time.
fn said_now(standing: bool, last_ms: f64, now_ms: f64) -> bool {
    standing || now_ms - last_ms >= SAID_EVERY_MS
}

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
    // The figures as said: a copy of the clock taken when due.
    let said = RwSignal::new(clock.get_untracked());
    let said_at = StoredValue::new(f64::NEG_INFINITY);
    Effect::new(move || {
        let now = clock.get();
        let standing = !now.running || ctx.page.paused.get();
        let wall = crate::now_ms();
        if said_now(standing, said_at.get_value(), wall) {
            said_at.set_value(wall);
            said.set(now);
        }
    });
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
                    let ms = said.with(Clock::ms);
                    format!(" · {}.{:03} {} ·", ms / 1000, ms % 1000, t().seconds)
                }}
            </span>
            <span class="clock-line">
                {move || {
                    let c = said.get();
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

#[cfg(test)]
mod tests {
    use super::{said_now, SAID_EVERY_MS};

    #[test]
    fn running_figures_are_said_a_quarter_second_apart_and_at_once_when_standing() {
        assert!(said_now(false, f64::NEG_INFINITY, 0.0), "the first time");
        assert!(!said_now(false, 1000.0, 1000.0 + SAID_EVERY_MS - 1.0));
        assert!(said_now(false, 1000.0, 1000.0 + SAID_EVERY_MS));
        assert!(said_now(true, 1000.0, 1001.0), "paused or stopped: at once");
    }
}
