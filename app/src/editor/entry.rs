//! The device entry `[data-testid=device-input]`: opened by F5–F8 and the
//! palette at the cursor's cell, with completion from the machine's
//! devices and the project's comments. Enter or OK (touch: a chip, then
//! OK) commits (or shows the engine's refusal, changing nothing); Escape
//! or Cancel cancels.

use engine::ladder::edit::{complete, EntryKind};
use leptos::prelude::*;

use super::state::LadderCtx;
use super::texts;

/// The most completions listed.
const SHOWN: usize = 12;

/// The entry bar, shown while an entry is open.
#[component]
pub fn DeviceEntry(ctx: LadderCtx, on_close: Callback<()>) -> impl IntoView {
    let input = NodeRef::<leptos::html::Input>::new();
    let t = move || texts::texts(ctx.page.lang.get());
    let open = move || ctx.panes.entry.with(Option::is_some);
    // Focus the input each time the entry opens.
    Effect::new(move |_| {
        if open() {
            if let Some(i) = input.get() {
                let _ = i.focus();
                let len = i.value().len() as u32;
                let _ = i.set_selection_range(len, len);
            }
        }
    });
    let title = move || {
        ctx.panes.entry.with(|e| {
            e.as_ref().map(|e| {
                let t = t();
                let what = match e.kind {
                    EntryKind::Open => t.entry_open,
                    EntryKind::Closed => t.entry_closed,
                    EntryKind::Coil => t.entry_coil,
                    EntryKind::Instruction => t.entry_instruction,
                };
                let branch = if e.branch { t.entry_branch } else { "" };
                format!("{what} {branch} · {} {}", t.rung, e.at.rung + 1)
            })
        })
    };
    let options = move || {
        ctx.panes.entry.with(|e| {
            let Some(e) = e else { return Vec::new() };
            let last = e.text.split_whitespace().last().unwrap_or("");
            let comments = ctx.drawing.comments.get();
            complete(ctx.machine, last, &comments)
                .into_iter()
                .take(SHOWN)
                .collect::<Vec<_>>()
        })
    };
    let set_text = move |text: String| {
        ctx.panes.entry.update(|e| {
            if let Some(e) = e {
                e.text = text;
                e.error = None;
            }
        });
    };
    let close = move || {
        ctx.panes.entry.set(None);
        on_close.run(());
    };
    view! {
        <Show when=open>
            <div class="entry-bar" role="dialog" aria-label=title>
                <span class="entry-title">{title}</span>
                <input
                    node_ref=input
                    data-testid="device-input"
                    autocomplete="off"
                    spellcheck="false"
                    aria-invalid=move || ctx.panes.entry.with(|e| e.as_ref().is_some_and(|e| e.error.is_some())).to_string()
                    prop:value=move || ctx.panes.entry.with(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default())
                    on:input=move |e| set_text(event_target_value(&e))
                    on:keydown=move |e: web_sys::KeyboardEvent| match e.key().as_str() {
                        "Enter" => {
                            e.prevent_default();
                            if ctx.commit_entry() {
                                on_close.run(());
                            }
                        }
                        "Escape" => {
                            e.prevent_default();
                            close();
                        }
                        _ => {}
                    }
                />
                <button type="button" data-testid="device-ok" on:click=move |_| {
                    if ctx.commit_entry() {
                        on_close.run(());
                    }
                }>{move || t().ok}</button>
                <button type="button" on:click=move |_| close()>{move || t().cancel}</button>
                <div class="entry-error" role="alert" data-testid="device-error">
                    {move || ctx.panes.entry.with(|e| e.as_ref().and_then(|e| e.error.clone()))}
                </div>
                <ul class="entry-options" data-testid="device-options">
                    <For
                        each=options
                        key=|(name, comment)| (name.clone(), comment.clone())
                        children=move |(name, comment)| {
                            let fill = name.clone();
                            view! {
                                <li>
                                    <button
                                        type="button"
                                        tabindex="-1"
                                        on:mousedown=move |e: web_sys::MouseEvent| {
                                            e.prevent_default();
                                            let text = ctx.panes.entry.with_untracked(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default());
                                            let mut words: Vec<&str> = text.split_whitespace().collect();
                                            if !text.ends_with(' ') {
                                                words.pop();
                                            }
                                            words.push(&fill);
                                            set_text(words.join(" "));
                                        }
                                    >
                                        <b>{name}</b>
                                        {comment.map(|c| format!(" {c}"))}
                                    </button>
                                </li>
                            }
                        }
                    />
                </ul>
            </div>
        </Show>
    }
}
