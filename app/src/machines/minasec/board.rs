//! MINASEC-U's front panel, drawn as the board: LEDs, switches, knobs and
//! the 7-segment counter. Every control sends a `Command`; every light
//! reads its own signal.

use engine::minasec::panel::seven_segments;
use engine::minasec::{ClockSpeed, Command, Mode, TimerId};
use engine::SimTime;
use leptos::ev;
use leptos::prelude::*;

use crate::chrome::controls::{Knob, Led, Momentary, Toggle};
use crate::chrome::digit::Digit;
use crate::machines::minasec::MinasecCtx;
use crate::state::Ctx;

/// A press held at least this long acts as a push button, not a toggle.
const MOMENTARY_MS: f64 = 300.0;

/// The whole board.
#[component]
pub fn Board() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <section class="board" aria-label="MINASEC-U">
            <div class="silk">"MINASEC-U"</div>
            <div class="row">
                <PowerAndMode />
                <div class="group">
                    <h3>{move || t().pc}</h3>
                    <LedRow signals=board.panel.pc prefix="pc-led" label="PC" colour="red" />
                </div>
                <div class="group">
                    <h3>{move || t().instruction}</h3>
                    <LedRow
                        signals=board.panel.instruction
                        prefix="inst-led"
                        label="INST"
                        colour="green"
                    />
                </div>
                <div class="group">
                    <h3>"A"</h3>
                    <Led
                        on=board.panel.acc
                        testid="acc-led".to_string()
                        colour="amber"
                        label="ACC".to_string()
                    />
                </div>
            </div>
            <div class="row">
                <DipSwitches />
            </div>
            <div class="row">
                <Inputs />
                <Outputs />
            </div>
            <div class="row">
                <Timers />
                <CounterPanel />
            </div>
        </section>
    }
}

/// LEDs for the eight bits of a byte, bit 7 on the left.
#[component]
fn LedRow(
    signals: [RwSignal<bool>; 8],
    prefix: &'static str,
    label: &'static str,
    colour: &'static str,
) -> impl IntoView {
    (0..8)
        .rev()
        .map(|bit| {
            view! {
                <span class="cell">
                    <Led
                        on=signals[bit]
                        testid=format!("{prefix}-{bit}")
                        colour=colour
                        label=format!("{label} {bit}")
                    />
                    <small>{bit}</small>
                </span>
            }
        })
        .collect_view()
}

#[component]
fn PowerAndMode() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    let mode_button = move |mode: Mode, testid: &'static str| {
        let label = Signal::derive(move || {
            match mode {
                Mode::Run => t().run,
                Mode::Halt => t().halt,
                Mode::Reset => t().reset,
            }
            .to_string()
        });
        view! {
            <Toggle
                on=Signal::derive(move || board.panel.mode.get() == mode)
                testid=testid.to_string()
                label=label
                set=Callback::new(move |_| {
                    board.send(Command::SetMode(mode));
                })
                class="mode"
            />
        }
    };
    view! {
        <div class="group controls">
            <Toggle
                on=board.panel.power.into()
                testid="power".to_string()
                label=Signal::derive(move || t().power.to_string())
                set=Callback::new(move |on| {
                    board.send(Command::Power(on));
                })
                class="power"
            />
            <div class="mode-switch" role="group" aria-label="RUN-HALT-RESET">
                {mode_button(Mode::Run, "mode-run")}
                {mode_button(Mode::Halt, "mode-halt")}
                {mode_button(Mode::Reset, "mode-reset")}
            </div>
            <Toggle
                on=board.panel.slow.into()
                testid="clock-slow".to_string()
                label=Signal::derive(move || {
                    let t = t();
                    format!("{} / {}", t.slow, t.fast)
                })
                set=Callback::new(move |slow| {
                    board.send(Command::SetClock(if slow { ClockSpeed::Slow } else { ClockSpeed::Fast }));
                })
            />
            <Momentary
                held=board.panel.clock_held.into()
                testid="clock-button".to_string()
                label=Signal::derive(move || t().clock.to_string())
                set=Callback::new(move |pressed| {
                    board.send(Command::ClockButton(pressed));
                })
            />
        </div>
    }
}

#[component]
fn DipSwitches() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    const NAMES: [&str; 8] = ["A0", "A1", "A2", "A3", "A4", "OP0", "OP1", "OP2"];
    let switches = (0..8)
        .rev()
        .map(|bit| {
            let on = board.panel.dip[bit];
            view! {
                <Toggle
                    on=on.into()
                    testid=format!("dip-{bit}")
                    label=Signal::derive(move || NAMES[bit].to_string())
                    set=Callback::new(move |v: bool| {
                        let mut dip = 0u8;
                        for (b, s) in board.panel.dip.iter().enumerate() {
                            if s.get_untracked() {
                                dip |= 1 << b;
                            }
                        }
                        dip = (dip & !(1 << bit)) | (u8::from(v) << bit);
                        board.send(Command::SetDip(dip));
                    })
                    class="dip"
                />
            }
        })
        .collect_view();
    view! {
        <div class="group">
            <h3>{move || t().dip}</h3>
            <div class="dips">{switches}</div>
            <Momentary
                held=board.panel.write_held.into()
                testid="write".to_string()
                label=Signal::derive(move || t().write.to_string())
                set=Callback::new(move |pressed| {
                    board.send(Command::WriteButton(pressed));
                })
            />
        </div>
    }
}

/// X00..X07: a click toggles; a press held longer acts as a push button.
#[component]
fn Inputs() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    let switches = (0..8u8)
        .map(|n| {
            let on = board.panel.inputs[usize::from(n)];
            let pressed_at = StoredValue::new(None::<(f64, bool)>);
            let set = move |v: bool| {
                board.send(Command::SetInput(n, v));
            };
            view! {
                <button
                    type="button"
                    class="input-switch"
                    class:on=move || on.get()
                    data-testid=format!("input-X{n:02}")
                    aria-pressed=move || on.get().to_string()
                    on:pointerdown=move |_| {
                        let before = on.get_untracked();
                        pressed_at.set_value(Some((js_sys::Date::now(), before)));
                        set(true);
                    }
                    on:pointerup=move |_| {
                        if let Some((at, before)) = pressed_at.get_value() {
                            pressed_at.set_value(None);
                            let held = js_sys::Date::now() - at >= MOMENTARY_MS;
                            set(if held { before } else { !before });
                        }
                    }
                    on:pointerleave=move |_| {
                        if let Some((_, before)) = pressed_at.get_value() {
                            pressed_at.set_value(None);
                            set(before);
                        }
                    }
                    on:click=move |e: ev::MouseEvent| {
                        // detail 0: activated from the keyboard, not a pointer.
                        if e.detail() == 0 {
                            set(!on.get_untracked());
                        }
                    }
                >
                    {format!("X{n:02}")}
                </button>
            }
        })
        .collect_view();
    view! {
        <div class="group">
            <h3>{move || t().inputs}</h3>
            <div class="switches">{switches}</div>
        </div>
    }
}

#[component]
fn Outputs() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    let lamps = (0..8usize)
        .map(|n| {
            view! {
                <span class="cell">
                    <Led
                        on=board.panel.lamps[n]
                        testid=format!("lamp-Y{n:02}")
                        colour="amber"
                        label=format!("Y{n:02}")
                    />
                    <small>{format!("Y{n:02}")}</small>
                </span>
            }
        })
        .collect_view();
    view! {
        <div class="group">
            <h3>{move || t().outputs}</h3>
            <div class="lamps">{lamps}</div>
        </div>
    }
}

#[component]
fn Timers() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    // RV1 in 10 ms steps (0.10..1.10 s), RV2 in 100 ms steps (1.0..11.0 s).
    let knob = move |id: TimerId, unit_ms: u64, testid: &'static str, name: &'static str| {
        let (lo, hi) = id.range();
        let to_steps = move |d: SimTime| (d.as_nanos() / 1_000_000 / unit_ms) as i64;
        let signal = board.panel.delays_ms[id.index()];
        view! {
            <div class="cell knob-cell">
                <Knob
                    value=Signal::derive(move || (signal.get() / unit_ms) as i64)
                    min=to_steps(lo)
                    max=to_steps(hi)
                    testid=testid.to_string()
                    label=Signal::derive(move || format!("{name} ({} {})", t().timer, if id == TimerId::T0 { "T0" } else { "T1" }))
                    now=if unit_ms == 10 { seconds_from_centis } else { seconds_from_decis }
                    text=Callback::new(move |steps: i64| {
                        format!("{:.2} {}", steps as f64 * unit_ms as f64 / 1000.0, t().seconds)
                    })
                    set=Callback::new(move |steps: i64| {
                        let delay = SimTime::from_millis(steps as u64 * unit_ms);
                        if board.send(Command::SetDelay(id, delay)) {
                            board.save();
                        }
                    })
                />
                <small>{name}</small>
            </div>
        }
    };
    view! {
        <div class="group">
            <h3>{move || t().timer}</h3>
            <div class="knobs">
                {knob(TimerId::T0, 10, "rv1", "RV1")}
                {knob(TimerId::T1, 100, "rv2", "RV2")}
            </div>
        </div>
    }
}

fn seconds_from_centis(v: i64) -> String {
    format!("{:.2}", v as f64 / 100.0)
}

fn seconds_from_decis(v: i64) -> String {
    format!("{:.1}", v as f64 / 10.0)
}

#[component]
fn CounterPanel() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    let digits = board.panel.digits;
    let rotary = move |index: usize, testid: &'static str| {
        let signal = board.panel.preset[index];
        view! {
            <Knob
                value=Signal::derive(move || i64::from(signal.get()))
                min=0
                max=9
                testid=testid.to_string()
                label=Signal::derive(move || {
                    format!("{} ({})", t().counter_set, if index == 0 { t().tens } else { t().ones })
                })
                now=|v| v.to_string()
                text=Callback::new(|v: i64| v.to_string())
                set=Callback::new(move |v: i64| {
                    let mut preset = [board.panel.preset[0].get_untracked(), board.panel.preset[1].get_untracked()];
                    preset[index] = v as u8;
                    if board.send(Command::SetCounterPreset(preset[0], preset[1])) {
                        board.save();
                    }
                })
            />
        }
    };
    view! {
        <div class="group">
            <h3>{move || t().counter}</h3>
            <div class="counter">
                <div
                    class="seg7"
                    data-testid="seg7"
                    role="img"
                    aria-label=move || {
                        digits.get().map(|(a, b)| format!("{a}{b}")).unwrap_or_default()
                    }
                >
                    <span class="sr-only">
                        {move || digits.get().map(|(a, b)| format!("{a}{b}")).unwrap_or_default()}
                    </span>
                    <Digit lit=Signal::derive(move || digits.get().map_or(0, |d| u32::from(seven_segments(d.0)))) />
                    <Digit lit=Signal::derive(move || digits.get().map_or(0, |d| u32::from(seven_segments(d.1)))) />
                </div>
                <div class="rotaries">
                    {rotary(0, "counter-set-tens")}
                    {rotary(1, "counter-set-ones")}
                </div>
                <Momentary
                    held=board.panel.count_clear_held.into()
                    testid="cntclr".to_string()
                    label=Signal::derive(move || t().count_clear.to_string())
                    set=Callback::new(move |pressed| {
                        board.send(Command::CountClearButton(pressed));
                    })
                />
            </div>
        </div>
    }
}
