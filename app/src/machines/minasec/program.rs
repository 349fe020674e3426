//! The program pane: the mnemonic text with line numbers and errors on
//! their lines as you type, the programming sheet beside it, and the
//! button that loads the program into the board.

use leptos::prelude::*;

use super::Parsed;
use crate::machines::minasec::MinasecCtx;
use crate::state::Ctx;

/// MINASEC-U's program pane.
#[component]
pub fn ProgramPane() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let t = move || ctx.lang.get().texts();
    let parsed = Memo::new(move |_| Parsed::of(&board.text.get()));
    let errors = Memo::new(move |_| {
        let lang = ctx.lang.get();
        match parsed.get() {
            Parsed::Good(_) => Vec::new(),
            Parsed::Bad(errors) => errors
                .iter()
                .map(|(line, e)| (*line, crate::i18n::errors::minasec_asm(lang, e)))
                .collect(),
        }
    });
    let up_to_date = move || {
        board
            .loaded
            .with(|l| l.as_deref() == Some(board.text.get().as_str()))
    };
    view! {
        <section class="program">
            <h2>{move || t().program}</h2>
            <TextWithLines board errors />
            <div class="program-actions">
                <button
                    type="button"
                    data-testid="program-load"
                    disabled=move || !errors.get().is_empty()
                    on:click=move |_| {
                        board.load_text();
                    }
                >
                    {move || t().load}
                </button>
                <crate::chrome::text_program::LoadAsLadder />
                <span class="status" data-testid="program-status">
                    {move || if up_to_date() { t().loaded } else { t().not_loaded }}
                </span>
            </div>
            <ErrorList errors />
            <Sheet parsed=parsed />
        </section>
    }
}

/// The text with its line numbers, the lines in error marked.
#[component]
fn TextWithLines(board: MinasecCtx, errors: Memo<Vec<(usize, String)>>) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let gutter_scroll = RwSignal::new(0);
    let line_count = Memo::new(move |_| board.text.with(|t| t.lines().count().max(1)));
    view! {
        <div class="editor">
            <pre class="gutter" aria-hidden="true" prop:scrollTop=move || gutter_scroll.get()>
                {move || {
                    let bad: Vec<usize> = errors.get().iter().map(|e| e.0).collect();
                    (1..=line_count.get())
                        .map(|n| {
                            let err = bad.contains(&n);
                            view! { <span class="ln" class:err=err>{format!("{n:>3}\n")}</span> }
                        })
                        .collect_view()
                }}
            </pre>
            <textarea
                data-testid="program-text"
                spellcheck="false"
                aria-label=move || t().program
                prop:value=move || board.text.get()
                on:input=move |e| {
                    board.text.set(event_target_value(&e));
                    board.save();
                }
                on:scroll=move |e| {
                    use leptos::wasm_bindgen::JsCast;
                    if let Some(el) = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::HtmlElement>().ok())
                    {
                        gutter_scroll.set(el.scroll_top());
                    }
                }
            ></textarea>
        </div>
    }
}

/// The errors by line, or "no errors".
#[component]
fn ErrorList(errors: Memo<Vec<(usize, String)>>) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <div
            class="errors"
            data-testid="program-error"
            role="status"
            aria-live="polite"
            class:has-errors=move || !errors.get().is_empty()
        >
            <Show when=move || !errors.get().is_empty() fallback=move || t().errors_none>
                <ul>
                    <For
                        each=move || errors.get()
                        key=|(line, message)| (*line, message.clone())
                        children=move |(line, message)| {
                            view! { <li>{move || format!("{} {line}: {message}", t().line)}</li> }
                        }
                    />
                </ul>
            </Show>
        </div>
    }
}

/// The programming sheet of the text as it stands (when it parses).
#[component]
fn Sheet(parsed: Memo<Parsed>) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let rows = Memo::new(move |_| match parsed.get() {
        Parsed::Good(program) => program
            .sheet()
            .rows
            .iter()
            .map(|r| {
                (
                    r.address,
                    r.instruction.opcode.mnemonic().to_string(),
                    r.instruction.address.to_string(),
                    r.instruction.binary(),
                )
            })
            .collect::<Vec<_>>(),
        Parsed::Bad(_) => Vec::new(),
    });
    view! {
        <table class="sheet" data-testid="program-sheet">
            <caption>{move || t().sheet}</caption>
            <thead>
                <tr>
                    <th>{move || t().sheet_address}</th>
                    <th>{move || t().sheet_opcode}</th>
                    <th>{move || t().sheet_operand}</th>
                    <th>{move || t().sheet_binary}</th>
                </tr>
            </thead>
            <tbody>
                <For
                    each=move || rows.get()
                    key=|row| row.clone()
                    children=|(address, opcode, operand, binary)| {
                        view! {
                            <tr>
                                <td>{format!("{address:03}")}</td>
                                <td>{opcode}</td>
                                <td>{operand}</td>
                                <td class="bin">{binary}</td>
                            </tr>
                        }
                    }
                />
            </tbody>
        </table>
    }
}
