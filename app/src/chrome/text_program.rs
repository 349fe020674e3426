//! The program pane of the machines whose programs are plain text
//! (IO86A, the Arduino sketch, the AVR PLC): the text, its errors by line
//! as you type, a warning about a quirk the program will meet, and Load.

use leptos::prelude::*;

use crate::state::Ctx;

/// The pane. Its test hooks are `{prefix}program-text`, `{prefix}program-
/// load`, `{prefix}program-error` and `{prefix}warning`.
#[component]
pub fn TextProgramPane(
    prefix: &'static str,
    text: RwSignal<String>,
    /// The text's errors as its machine's parser reports them: (line, message).
    errors: Signal<Vec<(usize, String)>>,
    /// Called with the text after each edit (to save it).
    on_edit: Callback<String>,
    /// Called when Load is pressed (only possible without errors).
    on_load: Callback<()>,
    /// Shown after "Program" in the heading (a device's name).
    #[prop(optional)]
    subtitle: Option<Signal<String>>,
    /// A warning about the program, when there is one.
    #[prop(optional)]
    warning: Option<Signal<Option<String>>>,
    /// A taller text area (for assembler sources).
    #[prop(optional)]
    tall: bool,
    /// This pane is the ladder's second view: it offers "Load as ladder".
    #[prop(optional)]
    as_ladder: bool,
) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let has_errors = move || errors.with(|e| !e.is_empty());
    let warning = warning.unwrap_or_else(|| Signal::derive(|| None));
    view! {
        <section class="program">
            <h2>
                {move || t().program}
                {subtitle.map(|s| view! { " · " {move || s.get()} })}
            </h2>
            <textarea
                class="plain"
                class:tall=tall
                data-testid=format!("{prefix}program-text")
                spellcheck="false"
                aria-label=move || t().program
                prop:value=move || text.get()
                on:input=move |e| {
                    let value = event_target_value(&e);
                    text.set(value.clone());
                    on_edit.run(value);
                }
            ></textarea>
            <div class="program-actions">
                <button
                    type="button"
                    data-testid=format!("{prefix}program-load")
                    disabled=has_errors
                    on:click=move |_| on_load.run(())
                >
                    {move || t().load}
                </button>
                {as_ladder.then(LoadAsLadder)}
            </div>
            <div class="errors" class:has-errors=has_errors data-testid=format!("{prefix}program-error")>
                {move || {
                    let line = t().line;
                    errors.with(|errors| {
                        if errors.is_empty() {
                            t().errors_none.to_string()
                        } else {
                            errors
                                .iter()
                                .map(|(n, message)| format!("{line} {n}: {message}"))
                                .collect::<Vec<_>>()
                                .join("\n")
                        }
                    })
                }}
            </div>
            <Show when=move || warning.with(Option::is_some)>
                <div class="warning" data-testid=format!("{prefix}warning")>
                    {move || warning.get().unwrap_or_default()}
                </div>
            </Show>
        </section>
    }
}

/// "Load as ladder" `[data-testid=load-as-ladder]`: the pane's program
/// becomes the workspace's ladder (one undo away), or the engine's
/// located error is shown and nothing changes.
#[component]
pub fn LoadAsLadder() -> impl IntoView {
    let ladder = use_context::<crate::editor::LadderCtx>();
    let ctx = Ctx::get();
    ladder.map(|ladder| {
        view! {
            <button
                type="button"
                data-testid="load-as-ladder"
                on:click=move |_| {
                    let result = ladder.load_text_as_ladder();
                    ladder.panes.message.set(result.err());
                }
            >
                {move || ctx.lang.get().texts().load_as_ladder}
            </button>
        }
    })
}
