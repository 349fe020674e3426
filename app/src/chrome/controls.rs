//! Generic panel parts: LEDs, switches, push buttons and knobs. Each takes
//! signals and callbacks; none knows the machine.

use leptos::ev;
use leptos::prelude::*;

/// An LED: `data-on` is `1` or `0`.
#[component]
pub fn Led(
    /// Whether it is lit.
    on: RwSignal<bool>,
    /// The test hook.
    testid: String,
    /// Its colour class (`red`, `green`, `amber`).
    #[prop(default = "red")]
    colour: &'static str,
    /// What a screen reader says.
    label: String,
) -> impl IntoView {
    // The page's language, where there is a page (not in component tests).
    let lang = use_context::<crate::state::Ctx>().map(|c| c.lang);
    let state = move |lit: bool| match (lang.map(|l| l.get()), lit) {
        (Some(crate::i18n::Lang::Ja), true) => "点灯",
        (Some(crate::i18n::Lang::Ja), false) => "消灯",
        (_, true) => "ON",
        (_, false) => "OFF",
    };
    view! {
        <span
            class=format!("led {colour}")
            class:on=move || on.get()
            data-testid=testid
            data-on=move || if on.get() { "1" } else { "0" }
            role="img"
            aria-label=move || format!("{label}: {}", state(on.get()))
        ></span>
    }
}

/// A latching switch: a button with `aria-pressed`.
#[component]
pub fn Toggle(
    on: Signal<bool>,
    testid: String,
    /// What the switch is called.
    label: Signal<String>,
    /// Called with the new position.
    set: Callback<bool>,
    #[prop(default = "toggle")] class: &'static str,
) -> impl IntoView {
    view! {
        <button
            type="button"
            class=class
            class:on=move || on.get()
            data-testid=testid
            aria-pressed=move || on.get().to_string()
            on:click=move |_| set.run(!on.get_untracked())
        >
            {move || label.get()}
        </button>
    }
}

/// A push button held while the mouse, finger or key is down.
#[component]
pub fn Momentary(
    held: Signal<bool>,
    testid: String,
    label: Signal<String>,
    /// Called with `true` on press and `false` on release.
    set: Callback<bool>,
) -> impl IntoView {
    let press = move || {
        if !held.get_untracked() {
            set.run(true);
        }
    };
    let release = move || {
        if held.get_untracked() {
            set.run(false);
        }
    };
    view! {
        <button
            type="button"
            class="push"
            class:on=move || held.get()
            data-testid=testid
            aria-pressed=move || held.get().to_string()
            on:pointerdown=move |e: ev::PointerEvent| {
                e.prevent_default();
                press();
            }
            on:pointerup=move |_| release()
            on:pointerleave=move |_| release()
            on:pointercancel=move |_| release()
            on:keydown=move |e: ev::KeyboardEvent| {
                if (e.key() == " " || e.key() == "Enter") && !e.repeat() {
                    e.prevent_default();
                    press();
                }
            }
            on:keyup=move |e: ev::KeyboardEvent| {
                if e.key() == " " || e.key() == "Enter" {
                    release();
                }
            }
            on:blur=move |_| release()
        >
            {move || label.get()}
        </button>
    }
}

/// The value a key gives a knob at `v` (arrows a step, Page keys ten,
/// Home/End the ends); `None` for other keys.
fn knob_key(key: &str, v: i64, min: i64, max: i64) -> Option<i64> {
    match key {
        "ArrowUp" | "ArrowRight" => Some(v + 1),
        "ArrowDown" | "ArrowLeft" => Some(v - 1),
        "PageUp" => Some(v + 10),
        "PageDown" => Some(v - 10),
        "Home" => Some(min),
        "End" => Some(max),
        _ => None,
    }
}

/// Keeps the pointer's moves coming to the element pressed while it is
/// dragged outside it.
fn capture(e: &ev::PointerEvent) {
    use leptos::wasm_bindgen::JsCast;
    if let Some(el) = e
        .target()
        .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
    {
        let _ = el.set_pointer_capture(e.pointer_id());
    }
}

/// A knob as an ARIA slider: drag up/down, turn the wheel, or use the arrow
/// keys (Page keys for ten steps, Home/End for the ends).
#[component]
pub fn Knob(
    /// The value in steps (an integer from `min` to `max`).
    value: Signal<i64>,
    min: i64,
    max: i64,
    testid: String,
    label: Signal<String>,
    /// `aria-valuenow` for a value (e.g. seconds).
    now: fn(i64) -> String,
    /// The text shown and spoken (e.g. "1.10 s").
    text: Callback<i64, String>,
    /// Called with a new value within `min..=max`.
    set: Callback<i64>,
) -> impl IntoView {
    let clamp = move |v: i64| v.clamp(min, max);
    let change = move |v: i64| {
        let v = clamp(v);
        if v != value.get_untracked() {
            set.run(v);
        }
    };
    // Dragging: pixels moved since the press, 2 px per step.
    let drag_from = StoredValue::new(None::<(f64, i64)>);
    let angle = move || {
        let span = (max - min).max(1) as f64;
        -135.0 + 270.0 * (value.get() - min) as f64 / span
    };
    view! {
        <div
            class="knob"
            role="slider"
            tabindex="0"
            data-testid=testid
            aria-label=move || label.get()
            aria-valuemin=now(min)
            aria-valuemax=now(max)
            aria-valuenow=move || now(value.get())
            aria-valuetext=move || text.run(value.get())
            on:keydown=move |e: ev::KeyboardEvent| {
                if let Some(next) = knob_key(&e.key(), value.get_untracked(), min, max) {
                    e.prevent_default();
                    change(next);
                }
            }
            on:wheel=move |e: ev::WheelEvent| {
                e.prevent_default();
                change(value.get_untracked() + if e.delta_y() < 0.0 { 1 } else { -1 });
            }
            on:pointerdown=move |e: ev::PointerEvent| {
                drag_from.set_value(Some((e.client_y() as f64, value.get_untracked())));
                capture(&e);
            }
            on:pointermove=move |e: ev::PointerEvent| {
                if let Some((y0, v0)) = drag_from.get_value() {
                    let steps = ((y0 - e.client_y() as f64) / 2.0).round() as i64;
                    change(v0 + steps);
                }
            }
            on:pointerup=move |_| drag_from.set_value(None)
            on:pointercancel=move |_| drag_from.set_value(None)
        >
            <svg viewBox="-20 -20 40 40" class="dial" aria-hidden="true">
                <circle r="17" class="dial-body"></circle>
                <line
                    x1="0"
                    y1="0"
                    x2="0"
                    y2="-14"
                    class="dial-mark"
                    transform=move || format!("rotate({:.1})", angle())
                ></line>
            </svg>
            <span class="knob-text">{move || text.run(value.get())}</span>
        </div>
    }
}
