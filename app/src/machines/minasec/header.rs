//! MINASEC-U's items in the page's header: its simulated time and scans,
//! and the undo of an example that replaced its program text.

use engine::minasec::Mode;
use leptos::prelude::*;

use super::MinasecCtx;
use crate::state::{Ctx, MachineKind};

/// Puts back the program text an example replaced (while there is one).
#[component]
pub fn ExampleUndo() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <Show when=move || board.before_example.with(Option::is_some)>
            <button
                type="button"
                data-testid="example-undo"
                on:click=move |_| super::examples::undo(board)
            >
                {move || t().undo_open}
            </button>
        </Show>
    }
}

/// MINASEC-U's simulated time and scans.
#[component]
pub fn SimClock() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    // Running, paused (simulated time stopped, the machine in RUN) or
    // stopped (HALT or power off: no scan runs).
    let state = move || {
        let runs = board.panel.power.get() && board.panel.mode.get() == Mode::Run;
        match (runs, ctx.paused.get()) {
            (false, _) => "stopped",
            (true, true) => "paused",
            (true, false) => "running",
        }
    };
    view! {
        <span
            class="clock"
            data-testid="sim-time"
            data-state=state
            class:hidden=move || ctx.machine.get() != MachineKind::MinasecU
        >
            {move || {
                let ms = board.panel.sim_ms.get();
                let word = match state() {
                    "running" => t().state_running,
                    "paused" => t().state_paused,
                    _ => t().state_stopped,
                };
                format!(
                    "{word} · {} {}.{:03} {} · {} {}",
                    t().sim_time,
                    ms / 1000,
                    ms % 1000,
                    t().seconds,
                    board.panel.scans.get(),
                    t().scans,
                )
            }}
        </span>
    }
}
