//! The header: the machine, the language, examples, speed and pause, and
//! the clock readout. Speed and pause are page-wide (`Ctx`); the frame
//! loop hands them to whichever workspace is shown.

use leptos::prelude::*;

use crate::examples;
use crate::i18n::Lang;
use crate::machines::minasec;
use crate::sim::Speed;
use crate::state::{product_name, Ctx, MachineKind};
use crate::storage;
use crate::workspaces::Workspaces;

#[component]
pub fn Header() -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <header class="top">
            <h1>
                {move || match ctx.machine.get() {
                    MachineKind::MinasecU => t().title,
                    MachineKind::Io86a => t().title_io86a,
                    MachineKind::ArduinoPlc => t().title_arduino,
                    MachineKind::AvrPlc => t().title_avr,
                    MachineKind::SoftPlc => "Soft PLC (IEC 61131-3)",
                }}
            </h1>
            <MachineSelect />
            <LangSelect />
            {move || {
                let machine = ctx.machine.get();
                view! { <ExampleSelect machine /> }
            }}
            <minasec::header::ExampleUndo />
            <SpeedSelect />
            <PauseButton />
            <minasec::header::SimClock />
        </header>
    }
}

/// Which machine the page shows (remembered).
#[component]
fn MachineSelect() -> impl IntoView {
    let ctx = Ctx::get();
    view! {
        <label>
            {move || ctx.lang.get().texts().machine}
            <select
                data-testid="machine"
                prop:value=move || ctx.machine.get().name()
                on:change=move |e| {
                    if let Ok(kind) = MachineKind::parse(&event_target_value(&e)) {
                        ctx.machine.set(kind);
                        storage::save_string(storage::MACHINE_KEY, kind.name());
                    }
                }
            >
                {MachineKind::ALL
                    .iter()
                    .map(|&kind| view! { <option value=kind.name()>{product_name(kind)}</option> })
                    .collect_view()}
            </select>
        </label>
    }
}

/// The interface language (remembered).
#[component]
fn LangSelect() -> impl IntoView {
    let ctx = Ctx::get();
    view! {
        <label>
            {move || ctx.lang.get().texts().language}
            <select
                data-testid="lang"
                prop:value=move || ctx.lang.get().code()
                on:change=move |e| {
                    if let Some(lang) = Lang::from_code(&event_target_value(&e)) {
                        ctx.lang.set(lang);
                        storage::save_lang(lang.code());
                        set_document_lang(lang);
                    }
                }
            >
                <option value="ja">"日本語"</option>
                <option value="en">"English"</option>
            </select>
        </label>
    }
}

/// The machine's examples: each opens as a ladder (one undo brings the
/// old ladder back); MINASEC-U's also replaces the text (undoable).
#[component]
fn ExampleSelect(machine: MachineKind) -> impl IntoView {
    let ctx = Ctx::get();
    let workspaces = expect_context::<Workspaces>();
    let t = move || ctx.lang.get().texts();
    let options = engine::examples::examples_of(machine)
        .map(|e| {
            view! {
                <option value=e.id>
                    {move || if ctx.lang.get() == Lang::Ja { e.title_ja } else { e.title_en }}
                </option>
            }
        })
        .collect_view();
    view! {
        <label>
            {move || t().example}
            <select
                data-testid="example"
                prop:value=""
                on:change=move |e| {
                    let id = event_target_value(&e);
                    examples::open(machine, &id, workspaces);
                    // Back to the prompt, so the same example can be opened again.
                    use leptos::wasm_bindgen::JsCast;
                    if let Some(select) = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::HtmlSelectElement>().ok())
                    {
                        select.set_value("");
                    }
                }
            >
                <option value="">{move || t().example_none}</option>
                {options}
            </select>
        </label>
    }
}

/// How fast simulated time runs, for every machine.
#[component]
fn SpeedSelect() -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <label>
            {move || t().speed}
            <select
                data-testid="speed"
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
        </label>
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
            data-testid="pause"
            aria-pressed=move || ctx.paused.get().to_string()
            on:click=move |_| ctx.paused.update(|p| *p = !*p)
        >
            {move || if ctx.paused.get() { t().resume } else { t().pause }}
        </button>
    }
}

/// Sets `<html lang>` so screen readers and fonts follow the interface.
pub fn set_document_lang(lang: Lang) {
    if let Some(root) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.document_element())
    {
        let _ = root.set_attribute("lang", lang.code());
    }
}
