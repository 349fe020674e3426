//! `?bench`: the engine's speed in this browser, on the same program and
//! the same measure as `hashigo bench` (steps executed per second of wall
//! time, inputs held at 0).

use std::time::Duration;

use engine::machines::new_plc;
use engine::MachineId;
use leptos::prelude::*;

/// The 256-step benchmark program (the seed test program repeated).
pub const BENCH_PROGRAM: &str = include_str!("../../engine/programs/minasec-u/bench-256.il");

/// Steps the page runs: 1e6 scans.
pub const BENCH_STEPS: u64 = 256_000_000;

/// Runs `steps` steps and returns the seconds they took (as `hashigo
/// bench` does: through the machine interface).
pub fn measure(steps: u64) -> Option<f64> {
    let mut machine = new_plc(MachineId::MinasecU);
    machine.load_text(BENCH_PROGRAM).ok()?;
    let (end, executed) = machine.time_for_steps(steps)?;
    let start = crate::now_ms();
    machine.run_until(end);
    let seconds = (crate::now_ms() - start) / 1000.0;
    (executed == steps).then_some(seconds)
}

#[component]
pub fn BenchPage() -> impl IntoView {
    let result = RwSignal::new(String::from("running…"));
    // Let the page paint before the measurement takes the thread.
    set_timeout(
        move || {
            // A warm-up run first, so the browser's optimising tier has
            // compiled the kernel: the figure is steady state, as natively.
            let _ = measure(BENCH_STEPS / 8);
            result.set(match measure(BENCH_STEPS) {
                Some(seconds) => format!(
                    "steps={BENCH_STEPS} seconds={seconds:.6} steps_per_second={:.0}",
                    BENCH_STEPS as f64 / seconds
                ),
                None => "error: the benchmark did not run".to_string(),
            });
        },
        Duration::from_millis(50),
    );
    view! {
        <main class="bench">
            <h1>"Hashigo engine benchmark (wasm)"</h1>
            <p>"MINASEC-U, 256-step program, inputs at 0, fast path."</p>
            <pre data-testid="bench-result">{move || result.get()}</pre>
        </main>
    }
}
