//! The IO86A workspace's components: the 18-pin chip, its peripherals, the
//! serial terminal and the program panes.

use engine::events::InputValue;
use engine::io86a::peripherals::OutputSignal;
use engine::io86a::Program;
use leptos::prelude::*;

use super::Io86aCtx;
use crate::chrome::console::ConsolePane;
use crate::chrome::controls::Led;
use crate::chrome::text_program::TextProgramPane;
use crate::state::Ctx;

/// What sits at a pin of the DIP-18 package.
#[derive(Clone, Copy)]
enum Pin {
    X(u8),
    Y(u8),
    Other(&'static str),
}

/// Pins 1-9 down the left side, then 18-10 down the right (the manual's
/// pin table).
const LEFT: [(u8, Pin); 9] = [
    (1, Pin::Y(2)),
    (2, Pin::Y(3)),
    (3, Pin::Y(4)),
    (4, Pin::X(6)),
    (5, Pin::Other("GND")),
    (6, Pin::X(0)),
    (7, Pin::X(1)),
    (8, Pin::Other("SI")),
    (9, Pin::X(2)),
];
const RIGHT: [(u8, Pin); 9] = [
    (18, Pin::Y(1)),
    (17, Pin::Y(0)),
    (16, Pin::X(7)),
    (15, Pin::Y(5)),
    (14, Pin::Other("+5V")),
    (13, Pin::X(5)),
    (12, Pin::X(4)),
    (11, Pin::Other("SO")),
    (10, Pin::X(3)),
];

/// IR remote buttons: the manual's A and B codes, and two more NEC frames
/// with the same custom code.
const IR_BUTTONS: [(&str, u32); 4] = [
    ("A", 0x10EF_7807),
    ("B", 0x10EF_7887),
    ("C", 0x10EF_40BF),
    ("D", 0x10EF_C03F),
];

fn prefix(device: usize) -> &'static str {
    if device == 0 {
        "io86a-"
    } else {
        "io86a-b-"
    }
}

/// The IO86A's panel: its device (or two), their peripherals and the
/// serial terminal.
#[component]
pub fn Io86aPanel(io: Io86aCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <Show when=move || io.notice.with(Option::is_some)>
            <div class="notice" role="alert" data-testid="io86a-notice">
                {move || format!("{} {}", t().corrupt_saved, io.notice.get().unwrap_or_default())}
            </div>
        </Show>
        <div class="workspace io86a">
            <div class="devices">
                <Device device=0 />
                <Show when=move || io.two.get()>
                    <Device device=1 />
                </Show>
                <button
                    type="button"
                    class="toggle"
                    class:on=move || io.two.get()
                    data-testid="io86a-two"
                    aria-pressed=move || io.two.get().to_string()
                    on:click=move |_| io.two.update(|v| *v = !*v)
                >
                    {move || t().two_devices}
                </button>
            </div>
            <TerminalPane />
        </div>
    }
}

/// The IO86A's program texts, one per device (the tools dock's Program
/// tab).
#[component]
pub fn Io86aProgram(io: Io86aCtx) -> impl IntoView {
    view! {
        <div class="io86a-programs">
            <ProgramPane device=0 />
            <Show when=move || io.two.get()>
                <ProgramPane device=1 />
            </Show>
        </div>
    }
}

/// One device: the chip and its peripherals.
#[component]
fn Device(device: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let d = io.devices[device];
    let side = move |pins: [(u8, Pin); 9], right: bool| {
        pins.into_iter()
            .map(|(number, pin)| view! { <PinRow device=device number=number pin=pin right=right /> })
            .collect_view()
    };
    view! {
        <section class="device" aria-label=move || if device == 0 { t().device_a } else { t().device_b }>
            <h2>
                {move || if device == 0 { t().device_a } else { t().device_b }} " · "
                <span data-testid=format!("{}state", prefix(device))>
                    {move || if d.running.get() { t().running } else { t().stopped }}
                </span>
            </h2>
            <div class="dip18">
                <div class="pins left">{side(LEFT, false)}</div>
                <div class="package">
                    <span class="notch"></span>
                    <span class="part">"PLC-IO86A"</span>
                </div>
                <div class="pins right">{side(RIGHT, true)}</div>
            </div>
            <Peripherals device=device />
        </section>
    }
}

#[component]
fn PinRow(device: usize, number: u8, pin: Pin, right: bool) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let d = io.devices[device];
    let control = match pin {
        Pin::X(n) => {
            let on = d.inputs[usize::from(n)];
            view! {
                <button
                    type="button"
                    class="input-switch small"
                    class:on=move || on.get()
                    data-testid=format!("{}input-X{n:02}", prefix(device))
                    aria-pressed=move || on.get().to_string()
                    on:click=move |_| {
                        let v = !on.get_untracked();
                        io.drive(device, &format!("X{n:02}"), InputValue::Int(i64::from(v)));
                    }
                >
                    {format!("X{n:02}")}
                </button>
            }
            .into_any()
        }
        Pin::Y(n) => view! {
            <span class="pin-lamp">
                <Led
                    on=d.lamps[usize::from(n)]
                    testid=format!("{}lamp-Y{n:02}", prefix(device))
                    colour="amber"
                    label=format!("Y{n:02}")
                />
                {format!("Y{n:02}")}
            </span>
        }
        .into_any(),
        Pin::Other(name) => view! { <span class="pin-name">{name}</span> }.into_any(),
    };
    view! {
        <div class="pin" class:right=right>
            <span class="pin-number">{number}</span>
            {control}
        </div>
    }
}

/// Analog sliders, output gauges and the IR keypad, each when its pin mode
/// is set.
#[component]
fn Peripherals(device: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let d = io.devices[device];
    view! {
        <div class="peripherals">
            <AnalogInput device=device i=0 />
            <AnalogInput device=device i=1 />
            <OutputGauge device=device i=0 />
            <OutputGauge device=device i=1 />
            <Show when=move || d.ir.get()>
                <div class="ir" role="group" aria-label=move || t().ir_remote>
                    {move || t().ir_remote}
                    " "
                    <IrKeypad device=device />
                </div>
            </Show>
        </div>
    }
}

/// X04 (`i` = 0) or X05 in analog mode: a slider of volts and the D
/// register it gives.
#[component]
fn AnalogInput(device: usize, i: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let d = io.devices[device];
    let name = format!("X0{}", 4 + i);
    let testid = format!("{}analog-{name}", prefix(device));
    view! {
        <Show when=move || d.analog[i].get()>
            <label class="analog">
                {move || format!("{} {}", t().analog_in, 4 + i)}
                <input
                    type="range"
                    min="0"
                    max="5000"
                    step="10"
                    data-testid=testid.clone()
                    prop:value=move || d.analog_mv[i].get().to_string()
                    on:input=move |e| {
                        let mv = event_target_value(&e).parse::<i64>().unwrap_or(0);
                        io.drive(device, &format!("X0{}", 4 + i), InputValue::Millivolts(mv));
                    }
                />
                <span>
                    {move || {
                        let mv = d.analog_mv[i].get();
                        format!("{}.{:02} V → D0{} = {}", mv / 1000, mv % 1000 / 10, 6 + i, d.d[6 + i].get())
                    }}
                </span>
            </label>
        </Show>
    }
}

/// Y03 (`i` = 0) or Y04 as a servo dial or a PWM duty bar.
#[component]
fn OutputGauge(device: usize, i: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let signal = io.devices[device].outputs[i];
    view! {
        <div class="gauge" data-testid=format!("{}out-Y0{}", prefix(device), 3 + i)>
            {move || match signal.get() {
                OutputSignal::Level(_) => ().into_any(),
                OutputSignal::Servo(pulse) => {
                    let us = pulse.map_or(0, |p| p.as_nanos() / 1000);
                    // 500 µs = -90°, 1500 µs = 0°, 2500 µs = +90°.
                    let angle = (us as f64 - 1500.0) * 0.09;
                    view! {
                        <span>{format!("Y0{} {} {us} µs", 3 + i, t().servo)}</span>
                        <svg viewBox="-20 -20 40 24" class="servo" aria-hidden="true">
                            <path d="M -18 0 A 18 18 0 0 1 18 0" class="servo-arc"></path>
                            <line
                                x1="0"
                                y1="0"
                                x2="0"
                                y2="-16"
                                class="servo-arm"
                                class:off=pulse.is_none()
                                transform=format!("rotate({angle:.1})")
                            ></line>
                        </svg>
                    }
                    .into_any()
                }
                OutputSignal::Pwm { hz, duty } => view! {
                    <span>{format!("Y0{} {} {hz} Hz {duty} %", 3 + i, t().pwm)}</span>
                    <span class="duty">
                        <span class="duty-fill" style=format!("width: {duty}%")></span>
                    </span>
                }
                .into_any(),
            }}
        </div>
    }
}

/// The IR remote's buttons: a frame on X07 while a button is held.
#[component]
fn IrKeypad(device: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    IR_BUTTONS
        .iter()
        .map(|&(name, frame)| {
            let press = move |on: bool| {
                let frame = if on { i64::from(frame) } else { 0 };
                io.drive(device, "X07", InputValue::Int(frame));
            };
            view! {
                <button
                    type="button"
                    class="push"
                    data-testid=format!("{}ir-{name}", prefix(device))
                    on:pointerdown=move |_| press(true)
                    on:pointerup=move |_| press(false)
                    on:pointerleave=move |_| press(false)
                >
                    {name}
                </button>
            }
        })
        .collect_view()
}

/// Device A's serial terminal.
#[component]
fn TerminalPane() -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <ConsolePane
            title=Signal::derive(move || t().terminal.to_string())
            hint=Signal::derive(move || t().terminal_hint.to_string())
            testid="io86a-terminal"
            console=io.console
            on_line=Callback::new(move |line: String| io.type_line(&line))
            ctrl_c=(Signal::derive(move || t().ctrl_c.to_string()), Callback::new(move |()| io.type_line("^C")))
        />
    }
}

/// A device's program pane.
#[component]
fn ProgramPane(device: usize) -> impl IntoView {
    let io = expect_context::<Io86aCtx>();
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let text = io.texts[device];
    // Said in the page's language, and again when it changes (issue #49).
    let errors = Memo::new(move |_| match Program::parse(&text.get()) {
        Ok(_) => Vec::new(),
        Err(errors) => {
            let lang = ctx.lang.get();
            let said = |e: &engine::Located<_>| crate::i18n::errors::io86a_asm(lang, &e.error);
            errors.iter().map(|e| (e.line, said(e))).collect()
        }
    });
    view! {
        <TextProgramPane
            prefix=prefix(device)
            text=text
            errors=errors.into()
            on_edit=Callback::new(move |_| io.save())
            on_load=Callback::new(move |()| {
                io.load(device);
            })
            subtitle=Signal::derive(move || {
                (if device == 0 { t().device_a } else { t().device_b }).to_string()
            })
            as_ladder=device == 0
        />
    }
}
