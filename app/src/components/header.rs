//! The header: language, examples, speed and pause, and the clock readout.

use leptos::prelude::*;

use crate::examples;
use crate::i18n::Lang;
use crate::io86a::Io86aCtx;
use crate::sim::Speed;
use crate::state::{Ctx, MachineKind};
use crate::storage;

#[component]
pub fn Header() -> impl IntoView {
    let ctx = Ctx::get();
    let io = expect_context::<Io86aCtx>();
    let ard = expect_context::<crate::arduino::ArduinoCtx>();
    let avr = expect_context::<crate::avr::AvrCtx>();
    let t = move || ctx.lang.get().texts();
    let minasec = move || ctx.machine.get() == MachineKind::MinasecU;
    view! {
        <header class="top">
            <h1>
                {move || {
                    match ctx.machine.get() {
                        MachineKind::MinasecU => t().title,
                        MachineKind::Io86a => t().title_io86a,
                        MachineKind::ArduinoPlc => "Hashigo — Arduino PLC",
                        MachineKind::AvrPlc => "Hashigo — AVR PLC",
                    }
                }}
            </h1>
            <label>
                {move || t().machine}
                <select
                    data-testid="machine"
                    prop:value=move || ctx.machine.get().code()
                    on:change=move |e| {
                        if let Some(kind) = MachineKind::from_code(&event_target_value(&e)) {
                            ctx.machine.set(kind);
                            storage::save_string(storage::MACHINE_KEY, kind.code());
                        }
                    }
                >
                    <option value="minasec-u">"MINASEC-U"</option>
                    <option value="io86a">"PLC-IO86A"</option>
                    <option value="arduino-plc">"Arduino PLC"</option>
                    <option value="avr-plc">"AVR PLC"</option>
                </select>
            </label>
            <label>
                {move || t().language}
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
            <Show when=minasec>
            <label>
                {move || t().example}
                <select
                    data-testid="example"
                    prop:value=""
                    on:change=move |e| {
                        let id = event_target_value(&e);
                        examples::open(ctx, &id);
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
                    <option value="seed-test">{move || t().example_seed}</option>
                </select>
            </label>
            </Show>
            <Show when=move || ctx.before_example.with(Option::is_some)>
                <button
                    type="button"
                    data-testid="example-undo"
                    on:click=move |_| examples::undo(ctx)
                >
                    {move || t().undo_open}
                </button>
            </Show>
            <label>
                {move || t().speed}
                <select
                    data-testid="speed"
                    prop:value=move || ctx.speed.get().code()
                    on:change=move |e| {
                        if let Some(speed) = Speed::from_code(&event_target_value(&e)) {
                            ctx.speed.set(speed);
                            ctx.sim.update_value(|s| s.set_speed(speed));
                            io.sim.update_value(|s| s.set_speed(speed));
                            ard.sim.update_value(|s| s.set_speed(speed));
                            avr.sim.update_value(|s| s.set_speed(speed));
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
            <button
                type="button"
                data-testid="pause"
                aria-pressed=move || ctx.paused.get().to_string()
                on:click=move |_| {
                    let paused = !ctx.paused.get_untracked();
                    ctx.paused.set(paused);
                    ctx.sim.update_value(|s| s.set_paused(paused));
                    io.sim.update_value(|s| s.set_paused(paused));
                    ard.sim.update_value(|s| s.set_paused(paused));
                    avr.sim.update_value(|s| s.set_paused(paused));
                }
            >
                {move || if ctx.paused.get() { t().resume } else { t().pause }}
            </button>
            <span class="clock" data-testid="sim-time" class:hidden=move || !minasec()>
                {move || {
                    let ms = ctx.panel.sim_ms.get();
                    format!(
                        "{} {}.{:03} {} · {} {}",
                        t().sim_time,
                        ms / 1000,
                        ms % 1000,
                        t().seconds,
                        ctx.panel.scans.get(),
                        t().scans,
                    )
                }}
            </span>
        </header>
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
