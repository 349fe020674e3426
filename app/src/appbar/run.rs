//! The one run control of the page (issue #45): Run / Stop, Pause, the
//! step buttons and the speed, for the machine shown. Run writes the
//! drawing to the machine and starts it; Stop stops the machine as its
//! own switch would (MINASEC-U HALT, IO86A STOP, the Arduino sketch
//! disabled, the soft PLC STOP) and powers the AVR PLC off, which has no
//! RUN switch. A board's own RUN/HALT keys act on the same machine; the
//! clock (`clock.rs`) shows the machine's state, whatever started it.

use engine::plc::Command;
use leptos::prelude::*;

use crate::editor::LadderCtx;
use crate::sim::Speed;
use crate::state::Ctx;

/// Stop on a machine with no RUN switch: its power switch, off (a power
/// cycle, which puts its plant back at its start, issue #52).
fn power_off(ctx: LadderCtx) {
    ctx.operate(|plc| {
        let _ = plc.apply(Command::PowerCycle);
    });
    ctx.with_rig(|machine, rig| {
        if let Some(rig) = rig {
            rig.power_cycle(machine);
        }
    });
    ctx.live.powered_off.set(true);
}

/// Run, Stop, the step buttons and Pause for `ctx`'s machine.
#[component]
pub fn RunControls(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let kind = ctx.machine;
    let operate = move |f: &dyn Fn(&mut dyn engine::plc::Plc)| ctx.operate(f);
    // The machine runs the drawing: Run wrote it, and the machine (as
    // its last frame showed) is in RUN. A machine that runs a program of
    // its own (the IO86A's and the AVR's from power-up, a text loaded by
    // hand) shows Run, which writes the drawing: the clock beside it says
    // the machine's state either way.
    let runs =
        move || ctx.live.monitor.get() && ctx.live.running.get() && !ctx.live.powered_off.get();
    let run = move |_| {
        if runs() {
            if !kind.target().stoppable() {
                // No RUN switch: Stop is the power switch.
                power_off(ctx);
            } else {
                operate(&|plc| {
                    let _ = plc.apply(Command::Run(false));
                });
            }
            ctx.live.monitor.set(false);
            ctx.live.running.set(false);
            return;
        }
        ctx.live.powered_off.set(false);
        crate::editor::live::run_drawing(ctx);
    };
    let step = move |which: u8| {
        if which == 0 && ctx.travel.shown.get_untracked().is_some() {
            // Travelling: the next recorded scan, not a new branch.
            crate::editor::travel::step_forward(ctx);
            return;
        }
        ctx.page.paused.set(true);
        let stepped = std::cell::Cell::new(None);
        operate(&|plc| match which {
            0 => plc.step_scan(),
            1 => stepped.set(plc.step_instruction()),
            _ => {
                plc.step_clock();
            }
        });
        if which == 1 {
            crate::editor::live::show_stepped(ctx, stepped.get());
        }
    };
    view! {
        <span class="run-controls" role="group" aria-label=move || t().run_controls>
            <button type="button" class="run-button" data-testid="run" aria-pressed=move || runs().to_string()
                data-running=move || runs().to_string()
                on:click=run>
                {move || if runs() { t().stop } else { t().run_drawing }}
            </button>
            <PauseButton />
            <button type="button" class="icon-button" data-testid="step-scan" title=move || t().step_scan
                aria-label=move || t().step_scan on:click=move |_| step(0)>
                <span aria-hidden="true">"⇥"</span><span class="wide-only">{move || t().step_scan_short}</span>
            </button>
            <button type="button" class="icon-button" data-testid="step-instr" title=move || t().step_instr
                aria-label=move || t().step_instr on:click=move |_| step(1)>
                <span aria-hidden="true">"↧"</span><span class="wide-only">{move || t().step_instr_short}</span>
            </button>
            {kind.target().steps_clocks().then(|| view! {
                <button type="button" class="icon-button" data-testid="step-clock" title=move || t().step_clock
                    aria-label=move || t().step_clock on:click=move |_| step(2)>
                    <span aria-hidden="true">"◷"</span><span class="wide-only">{move || t().step_clock_short}</span>
                </button>
            })}
        </span>
    }
}

/// Freezes or resumes simulated time, for every machine.
#[component]
fn PauseButton() -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <button
            type="button"
            class="icon-button"
            data-testid="pause"
            aria-pressed=move || ctx.paused.get().to_string()
            title=move || if ctx.paused.get() { t().resume } else { t().pause }
            aria-label=move || if ctx.paused.get() { t().resume } else { t().pause }
            on:click=move |_| ctx.paused.update(|p| *p = !*p)
        >
            <span aria-hidden="true">{move || if ctx.paused.get() { "▶" } else { "‖" }}</span>
            <span class="wide-only">{move || if ctx.paused.get() { t().resume } else { t().pause }}</span>
        </button>
    }
}

/// How fast simulated time runs, for every machine.
#[component]
pub fn SpeedSelect() -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <select
            data-testid="speed"
            aria-label=move || t().speed
            title=move || t().speed
            prop:value=move || ctx.speed.get().code()
            on:change=move |e| {
                if let Some(speed) = Speed::from_code(&event_target_value(&e)) {
                    ctx.speed.set(speed);
                }
            }
        >
            {Speed::ALL
                .iter()
                .map(|&speed| {
                    let code = speed.code();
                    view! {
                        <option value=code.clone()>
                            {move || match speed {
                                Speed::Times(n) => format!("×{n}"),
                                Speed::Max => t().speed_max.to_string(),
                            }}
                        </option>
                    }
                })
                .collect_view()}
        </select>
    }
}
