//! The soft PLC's program pane (the tools dock's Program tab): a choice
//! of language, then the IL text pane (which follows the ladder) or the
//! Structured Text editor (issue #55): line numbers that take
//! breakpoints, errors at their lines as the user types (checked a
//! moment after the last key), coloured text, the values each line uses
//! beside it, "Step statement" and the line the scan stands before.

use leptos::prelude::*;

use super::st_complete::{self, Completing};
use super::st_lex::{self, Kind};
use super::{SoftCtx, KEY};
use crate::chrome::text_program::TextProgramPane;
use crate::state::Ctx;
use crate::storage;

/// How long after the last key the ST text is checked.
const CHECK_AFTER_MS: u64 = 300;

/// The pane: the language choice and the pane of the language chosen.
#[component]
pub fn SoftProgram(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    let on = soft.st.on;
    view! {
        <div class="soft-program">
            <label class="st-language">
                {move || s().language} " "
                <select data-testid="soft-language" on:change=move |e| {
                    soft.st.set_on(event_target_value(&e) == "st");
                }>
                    <option value="il" selected=move || !on.get()>{move || s().il}</option>
                    <option value="st" selected=move || on.get()>{move || s().st}</option>
                </select>
            </label>
            {move || if on.get() {
                view! { <StEditor soft /> }.into_any()
            } else {
                view! { <IlPane soft /> }.into_any()
            }}
        </div>
    }
}

/// The IL text, which follows the ladder.
#[component]
fn IlPane(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    // In the page's language (issue #49).
    let errors = Memo::new(move |_| {
        let lang = ctx.lang.get();
        match engine::softplc::Program::load(&soft.text.get()) {
            Ok(_) => Vec::new(),
            Err(e) => e
                .iter()
                .map(|e| (e.line, crate::i18n::errors::load_error(lang, &e.error)))
                .collect::<Vec<_>>(),
        }
    });
    // The pane's Load starts the program loaded (the ladder's machine).
    let ladder = use_context::<crate::editor::LadderCtx>();
    view! {
        <TextProgramPane
            as_ladder=true
            prefix="soft-"
            text=soft.text
            errors=Signal::derive(move || errors.get())
            on_edit=Callback::new(|program: String| {
                storage::save_to(KEY, &storage::SavedText { program });
            })
            on_load=Callback::new(move |()| {
                if soft.load() {
                    if let Some(ladder) = ladder {
                        ladder.run_loaded();
                    }
                }
            })
            tall=true
        />
    }
}

/// The ST text checked: its function blocks (the ladder's boxes), or
/// its errors.
type Checked = Result<engine::softplc::st::StBlocks, Vec<engine::softplc::st::StLoadError>>;

/// The ST text's errors: (line, column, message).
fn st_errors(checked: &Checked) -> Vec<(usize, usize, String)> {
    match checked {
        Ok(_) => Vec::new(),
        Err(es) => es
            .iter()
            .map(|e| (e.line, e.column, e.message.clone()))
            .collect(),
    }
}

/// The coloured copy of the text under the transparent text area.
fn coloured(text: &str) -> impl IntoView {
    st_lex::pieces(text)
        .into_iter()
        .map(|line| {
            let spans = line
                .into_iter()
                .map(|(kind, s)| match kind {
                    Kind::Other => view! { <span>{s}</span> }.into_any(),
                    k => view! { <span class=k.class()>{s}</span> }.into_any(),
                })
                .collect_view();
            view! { {spans} "\n" }
        })
        .collect_view()
}

/// The ST text's errors as last checked: (line, column, message).
type Errors = Memo<Vec<(usize, usize, String)>>;

/// The Structured Text editor: its lines, text and values scroll as one.
#[component]
fn StEditor(soft: SoftCtx) -> impl IntoView {
    let st = soft.st;
    // Checked a moment after the last key: typing is never held up.
    let checked = RwSignal::new(st.text.get_untracked());
    // A text of blocks without a PROGRAM checks too: the ladder calls them.
    let report = Memo::new(move |_| engine::softplc::st::st_blocks(&checked.get()));
    let errors: Errors = Memo::new(move |_| report.with(st_errors));
    // Once it loads, its blocks are the ladder's boxes (issue #55).
    Effect::new(move || {
        report.with(|r| checked.with_untracked(|t| st.declare_blocks(t, r.as_ref().ok())));
    });
    let count = Memo::new(move |_| st.text.with(|t| t.split('\n').count()));
    let completing = Completing::new();
    let scroller = NodeRef::<leptos::html::Div>::new();
    let on_scroll = move |_| {
        if let Some(div) = scroller.get() {
            let lines = count.get_untracked().max(1) as f64;
            let per_line = f64::from(div.scroll_height()).max(1.0) / lines;
            let first = (f64::from(div.scroll_top()) / per_line).floor() as usize + 1;
            let shown = (f64::from(div.client_height()) / per_line).ceil() as usize + 1;
            crate::state::put(st.visible, (first, first + shown));
            soft.refresh();
        }
    };
    view! {
        <section class="program st-program">
            <div class="st-editor" data-testid="st-editor" node_ref=scroller on:scroll=on_scroll>
                <Gutter soft errors count />
                <Code soft checked count completing />
                <div class="st-values" aria-hidden="true">
                    <For each=move || 1..=count.get() key=|n| *n let:n>
                        <div class="st-value" data-testid=format!("st-value-{n}")
                            class:st-current-line=move || st.current.get() == Some(n)>
                            {move || st.values.with(|v| {
                                v.iter().find(|(l, _)| *l == n).map(|(_, s)| s.clone()).unwrap_or_default()
                            })}
                        </div>
                    </For>
                </div>
            </div>
            <st_complete::Completion c=completing />
            <Actions soft errors />
        </section>
    }
}

/// The line numbers: each takes a breakpoint, shows its error and the
/// line the scan stands before.
#[component]
fn Gutter(soft: SoftCtx, errors: Errors, count: Memo<usize>) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    let st = soft.st;
    let error_at = move |n: usize| {
        errors.with(|es| {
            es.iter()
                .find(|(l, _, _)| *l == n)
                .map(|(l, c, m)| format!("{l}:{c}: {m}"))
        })
    };
    view! {
        <div class="st-gutter">
            <For each=move || 1..=count.get() key=|n| *n let:n>
                <button type="button" class="st-line" data-testid=format!("st-line-{n}")
                    class:st-breakpoint=move || st.breakpoints.with(|b| b.contains(&n))
                    class:st-error=move || error_at(n).is_some()
                    class:st-current-line=move || st.current.get() == Some(n)
                    aria-pressed=move || st.breakpoints.with(|b| b.contains(&n)).to_string()
                    aria-label=move || s().breakpoint_at.replace("{line}", &n.to_string())
                    title=move || error_at(n).unwrap_or_default()
                    on:click=move |_| st.toggle_breakpoint(n, soft.sim)>
                    {n}
                </button>
            </For>
        </div>
    }
}

/// The text area over its coloured copy; each edit saved, checked a
/// moment after the last key, and offered completions.
#[component]
fn Code(
    soft: SoftCtx,
    checked: RwSignal<String>,
    count: Memo<usize>,
    completing: Completing,
) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    let st = soft.st;
    let timer = StoredValue::new(None::<TimeoutHandle>);
    let widest = Memo::new(move |_| {
        st.text
            .with(|t| t.split('\n').map(|l| l.chars().count()).max().unwrap_or(0))
    });
    let edited = move |value: String| {
        st.text.set(value);
        st.save();
        if let Some(h) = timer.get_value() {
            h.clear();
        }
        let handle = set_timeout_with_handle(
            move || checked.set(st.text.get_untracked()),
            std::time::Duration::from_millis(CHECK_AFTER_MS),
        );
        timer.set_value(handle.ok());
    };
    let on_input = move |e: web_sys::Event| {
        let value = event_target_value(&e);
        edited(value.clone());
        st_complete::typed(completing, &e, &value);
    };
    let on_key = move |e: web_sys::KeyboardEvent| {
        let text = st.text.get_untracked();
        st_complete::key(completing, &e, &text, edited);
    };
    let open = move || completing.items.with(|i| !i.is_empty());
    view! {
        <div class="st-code">
            <pre class="st-colour" aria-hidden="true">{move || st.text.with(|t| coloured(t))}</pre>
            <textarea class="st-text" data-testid="soft-st-text" spellcheck="false" wrap="off"
                autocapitalize="off" autocomplete="off"
                aria-label=move || s().st
                style:height=move || format!("calc({} * var(--st-line) + 1rem)", count.get())
                style:width=move || format!("max(100%, {}ch)", widest.get() + 2)
                prop:value=move || st.text.get()
                aria-autocomplete="list"
                aria-controls=move || open().then_some("st-completions")
                aria-activedescendant=move || open().then(|| format!("st-completion-{}", completing.chosen.get()))
                on:keydown=on_key
                on:blur=move |_| completing.items.set(Vec::new())
                on:input=on_input></textarea>
        </div>
    }
}

/// Load, Step statement, where the scan stands, the errors, the hint.
#[component]
fn Actions(soft: SoftCtx, errors: Errors) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let s = move || ctx.lang.get().st();
    let st = soft.st;
    let ladder = use_context::<crate::editor::LadderCtx>();
    let load = move |_| {
        if soft.load() {
            if let Some(ladder) = ladder {
                ladder.run_loaded();
            }
        }
    };
    let step = move |_| {
        if let Some(ladder) = ladder {
            st.step_statement(soft.sim, ladder);
        }
    };
    view! {
        <div class="program-actions">
            <button type="button" data-testid="soft-program-load"
                disabled=move || errors.with(|e| !e.is_empty()) on:click=load>
                {move || t().load}
            </button>
            <button type="button" data-testid="st-step" on:click=step>
                {move || s().step_statement}
            </button>
            <span class="st-status" data-testid="st-status" role="status">
                {move || st.current.get().map(|n| {
                    let said = if st.hit.get() { s().stopped_at } else { s().paused_at };
                    let said = said.replace("{line}", &n.to_string());
                    match st.current_call.get() {
                        Some(call) => format!("{said} · {}", s().in_call.replace("{instance}", &call)),
                        None => said,
                    }
                })}
            </span>
            {move || st.instances.with(|i| !i.is_empty()).then(|| view! { <InstanceChoice soft /> })}
        </div>
        <div class="errors" class:has-errors=move || errors.with(|e| !e.is_empty())
            data-testid="soft-program-error">
            {move || errors.with(|es| {
                if es.is_empty() {
                    t().errors_none.to_string()
                } else {
                    es.iter()
                        .map(|(l, c, m)| format!("{} {l}:{c}: {m}", t().line))
                        .collect::<Vec<_>>()
                        .join("\n")
                }
            })}
        </div>
        <StWhy soft />
        <p class="hint st-hint">{move || s().hint}</p>
    }
}

/// The block instance whose values its block's lines show (as CODESYS's
/// online view asks which instance to monitor): the program's instances
/// of the text's blocks, each block's first until one is chosen.
#[component]
fn InstanceChoice(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    let st = soft.st;
    let chosen = move || {
        let c = st.chosen.get();
        st.instances.with(|all| {
            let known = all.iter().any(|(n, _)| n.eq_ignore_ascii_case(&c));
            let first = || all.first().map(|(n, _)| n.clone()).unwrap_or_default();
            if known {
                c
            } else {
                first()
            }
        })
    };
    let choose = move |e: web_sys::Event| {
        st.chosen.set(event_target_value(&e));
        st.show_values(soft.sim);
    };
    view! {
        <label class="st-instance">
            {move || s().instance} " "
            <select data-testid="st-instance" prop:value=chosen on:change=choose>
                <For each=move || st.instances.get() key=|i| i.clone() let:i>
                    <option value=i.0.clone() selected={
                        let name = i.0.clone();
                        move || chosen().eq_ignore_ascii_case(&name)
                    }>{format!("{} ({})", i.0, i.1)}</option>
                </For>
            </select>
        </label>
    }
}

/// Why? on a variable of the ST program loaded (issue #55): the
/// statements that write it, each with its line, its operands' values
/// at the scan shown and whether it ran in it.
#[component]
fn StWhy(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    let name = RwSignal::new(String::new());
    let found = RwSignal::new(None::<(String, Vec<crate::editor::panes::why::StCause>)>);
    let ask = move |e: leptos::ev::SubmitEvent| {
        e.prevent_default();
        let n = name.get_untracked().trim().to_string();
        if !n.is_empty() {
            let causes = soft.st.why_variable(&n, soft.sim);
            found.set(Some((n, causes)));
        }
    };
    let item = move |c: &crate::editor::panes::why::StCause| {
        let line = c.line;
        let ran = c
            .ran
            .map(|r| move || if r { s().why_ran } else { s().why_not_ran });
        view! {
            <li data-testid="why-st" data-line=line.to_string()
                data-ran=c.ran.map(|r| if r { "1" } else { "0" })>
                {move || s().why_line.replace("{line}", &line.to_string())}
                " " <code>{c.statement.clone()}</code>
                {(!c.values.is_empty()).then(|| format!(" · {}", c.values.join(", ")))}
                {ran.map(|r| view! { " · " <span>{r}</span> })}
            </li>
        }
    };
    view! {
        <form class="st-why" on:submit=ask>
            <label>{move || s().why_name} " "
                <input data-testid="st-why-name" spellcheck="false" autocapitalize="off"
                    autocomplete="off" prop:value=move || name.get()
                    on:input=move |e| name.set(event_target_value(&e)) />
            </label>
            " " <button type="submit" data-testid="st-why">{move || s().why}</button>
        </form>
        {move || found.get().map(|(n, causes)| if causes.is_empty() {
            view! { <p data-testid="st-why-result">{s().why_none.replace("{name}", &n)}</p> }.into_any()
        } else {
            view! { <ul class="why-st" data-testid="st-why-result">{causes.iter().map(item).collect_view()}</ul> }.into_any()
        })}
    }
}
