//! The soft PLC board's rows: its scan period, a switch and push button
//! per input, a lamp per output, a slider per analog input and a gauge
//! per analog output.

use leptos::prelude::*;

use super::{hook, DigitRow, SoftCtx, Terminal, SLIDER_MAX};
use crate::chrome::controls::{Led, Momentary};
use crate::chrome::digit::Digit;
use crate::state::{put, Ctx};

/// The cyclic task's period, in ms (fractions for an LDmicro file's
/// 4.5 ms cycle); a value the machine refuses is said beside it.
#[component]
pub(super) fn ScanSetting(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let refused = RwSignal::new(String::new());
    let shown = move || {
        soft.scan_us.track();
        shown_now(soft)
    };
    view! {
        <label class="soft-scan">
            {move || t().soft_scan}
            <input
                type="number"
                min="0.001"
                max="10000"
                step="any"
                class="soft-number"
                data-testid="soft-scan"
                prop:value=shown
                on:change=move |e| {
                    let ms = event_target_value(&e);
                    match soft.set_scan(&format!("{}ms", ms.trim())) {
                        Ok(()) => refused.set(String::new()),
                        Err(why) => {
                            refused.set(why);
                            // The field shows what the machine runs at
                            // (the signal did not change: set it here).
                            let field = event_target::<web_sys::HtmlInputElement>(&e);
                            field.set_value(&shown_now(soft));
                        }
                    }
                }
            />
            " ms"
            <span class="soft-refused" role="alert">{move || refused.get()}</span>
        </label>
    }
}

/// The scan period as the field shows it, in ms.
fn shown_now(soft: SoftCtx) -> String {
    format!("{}", soft.scan_us.get_untracked() as f64 / 1000.0)
}

/// A terminal's label: its address, and its variable's name.
fn label(term: &Terminal) -> String {
    if term.name.is_empty() {
        term.address.clone()
    } else {
        format!("{} {}", term.address, term.name)
    }
}

#[component]
pub(super) fn SwitchRow(soft: SoftCtx, term: Terminal) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let hook = hook(&term.address);
    let driven = term.driven;
    let on = Signal::derive(move || driven.get() != 0);
    let held = term.held;
    let (flip, press) = (term.clone(), term.clone());
    view! {
        <li class="soft-terminal">
            <button type="button" class="input-switch small" class:on=on
                data-testid=format!("soft-input-{hook}")
                aria-pressed=move || on.get().to_string()
                aria-label=label(&term)
                title=move || t().drive
                on:click=move |_| {
                    // A bit takes 0 and 1: never refused.
                    let _ = soft.drive(&flip, i64::from(!on.get_untracked()));
                }>
            </button>
            <Momentary held=Signal::derive(move || held.get())
                testid=format!("soft-push-{hook}")
                label=Signal::derive(move || t().soft_push.to_string())
                set=Callback::new(move |down| soft.push(&press, down)) />
            <span class="soft-label">{label(&term)}</span>
        </li>
    }
}

#[component]
pub(super) fn LampRow(term: Terminal) -> impl IntoView {
    let value = term.value;
    let lit = RwSignal::new(false);
    Effect::new(move |_| put(lit, value.get() != 0));
    view! {
        <li class="soft-terminal">
            <Led on=lit testid=format!("soft-lamp-{}", hook(&term.address)) colour="amber"
                label=label(&term) />
            <span class="soft-label">{label(&term)}</span>
        </li>
    }
}

#[component]
pub(super) fn SliderRow(soft: SoftCtx, term: Terminal) -> impl IntoView {
    let hook = hook(&term.address);
    let driven = term.driven;
    let refused = RwSignal::new(None::<String>);
    let set = move |t: &Terminal, text: &str| match text.trim().parse::<i64>() {
        Ok(v) => refused.set(soft.drive(t, v).err()),
        Err(_) => refused.set(Some(format!("{text:?}: a whole number"))),
    };
    let (slid, typed) = (term.clone(), term.clone());
    view! {
        <li class="soft-terminal analog">
            <label>
                <span class="soft-label">{label(&term)}</span>
                <input type="range" min="0" max=SLIDER_MAX.to_string()
                    data-testid=format!("soft-analog-{hook}")
                    prop:value=move || driven.get().to_string()
                    on:input=move |e| set(&slid, &event_target_value(&e)) />
            </label>
            <input type="number" class="soft-number" data-testid=format!("soft-analog-value-{hook}")
                aria-label=label(&term)
                prop:value=move || driven.get().to_string()
                on:change=move |e| set(&typed, &event_target_value(&e)) />
            <span class="soft-refused" role="alert" data-testid=format!("soft-analog-error-{hook}")>
                {move || refused.get()}
            </span>
        </li>
    }
}

#[component]
pub(super) fn GaugeRow(term: Terminal) -> impl IntoView {
    let value = term.value;
    view! {
        <li class="soft-terminal analog">
            <span class="soft-label">{label(&term)}</span>
            <meter min="0" max=SLIDER_MAX.to_string() prop:value=move || value.get() as f64
                data-testid=format!("soft-gauge-{}", hook(&term.address))
                data-value=move || value.get().to_string()></meter>
            <output class="soft-number">{move || value.get().to_string()}</output>
        </li>
    }
}

/// The program's segment digits, when it has any.
#[component]
pub(super) fn Digits(soft: SoftCtx) -> impl IntoView {
    // Rebuilt only when a program is loaded: no keyed list needed.
    move || {
        let digits = soft.digits.get();
        (!digits.is_empty()).then(|| {
            view! {
                <ul class="soft-digits seg7" data-testid="soft-digits">
                    {digits.into_iter().map(|digit| view! { <DigitView digit /> }).collect_view()}
                </ul>
            }
        })
    }
}

/// A digit wired to a variable: the segments it lights, named for tests
/// and screen readers (`abcdefg.`; engine's `segments::names`).
#[component]
fn DigitView(digit: DigitRow) -> impl IntoView {
    use engine::runtime::ldmicro::segments::{letters, lit};
    let (value, anode, segments) = (digit.value, digit.anode, digit.segments);
    let bits = Signal::derive(move || lit(segments, value.get(), anode));
    let face = move || letters(segments, bits.get());
    let common = if anode { "A" } else { "C" };
    let name = digit.name.clone();
    view! {
        <li class="soft-digit" data-testid=format!("soft-digit-{}", digit.name)
            data-lit=face data-common=common>
            <Digit lit=bits segments />
            <span class="soft-label" title=move || format!("{name}: {}", face())>
                {digit.name.clone()}
            </span>
        </li>
    }
}
