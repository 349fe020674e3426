//! The device entry `[data-testid=device-input]`: opened by F5–F8 and the
//! palette at the cursor's cell, with completion from the machine's
//! devices and the project's comments. Enter or OK (touch: a chip, then
//! OK) commits (or shows the engine's refusal, changing nothing); Escape
//! or Cancel cancels.

use engine::ladder::edit::{complete_declared, EntryKind};
use leptos::prelude::*;

use super::state::LadderCtx;

/// The most completions listed.
const SHOWN: usize = 12;

/// The entry's text with its last word replaced by `chosen` (or
/// `chosen` added after a space).
pub fn completed(text: &str, chosen: &str) -> String {
    let mut words: Vec<&str> = text.split_whitespace().collect();
    if !text.ends_with(' ') {
        words.pop();
    }
    words.push(chosen);
    words.join(" ")
}

/// The entry bar, shown while an entry is open.
#[component]
pub fn DeviceEntry(ctx: LadderCtx, on_close: Callback<()>) -> impl IntoView {
    let input = NodeRef::<leptos::html::Input>::new();
    let t = move || ctx.page.lang.get().texts();
    let open = move || ctx.panes.entry.with(Option::is_some);
    focus_on_open(ctx, input);
    let title = move || {
        ctx.panes
            .entry
            .with(|e| e.as_ref().map(|e| title_of(e, t())))
    };
    let set_text = Callback::new(move |text: String| {
        ctx.panes.entry.update(|e| {
            if let Some(e) = e {
                e.text = text;
                e.error = None;
            }
        });
    });
    let close = move || {
        ctx.panes.entry.set(None);
        on_close.run(());
    };
    let commit = move || {
        if ctx.commit_entry() {
            on_close.run(());
        }
    };
    let text = move || {
        ctx.panes
            .entry
            .with(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default())
    };
    let invalid = move || {
        ctx.panes
            .entry
            .with(|e| e.as_ref().is_some_and(|e| e.error.is_some()))
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
                    aria-invalid=move || invalid().to_string()
                    placeholder=move || placeholder(ctx)
                    prop:value=text
                    on:input=move |e| set_text.run(event_target_value(&e))
                    on:keydown=move |e: web_sys::KeyboardEvent| match e.key().as_str() {
                        "Enter" => {
                            e.prevent_default();
                            commit();
                        }
                        "Escape" => {
                            e.prevent_default();
                            close();
                        }
                        _ => {}
                    }
                />
                <button type="button" data-testid="device-ok" on:click=move |_| commit()>{move || t().ok}</button>
                <button type="button" on:click=move |_| close()>{move || t().cancel}</button>
                <div class="entry-error" role="alert" data-testid="device-error">
                    {move || ctx.panes.entry.with(|e| e.as_ref().and_then(|e| e.error.clone()))}
                </div>
                <super::box_fields::BoxFields ctx set_text
                    commit=Callback::new(move |()| commit()) close=Callback::new(move |()| close()) />
                <EntryOptions ctx set_text />
            </div>
        </Show>
    }
}

/// Focuses the input, its caret at the end, each time the entry opens.
fn focus_on_open(ctx: LadderCtx, input: NodeRef<leptos::html::Input>) {
    Effect::new(move |_| {
        if ctx.panes.entry.with(Option::is_some) {
            if let Some(i) = input.get() {
                let _ = i.focus();
                let len = i.value().len() as u32;
                let _ = i.set_selection_range(len, len);
            }
        }
    });
}

/// How a box is typed, where boxes are (issue #49): the soft PLC's
/// instruction entry (F8).
fn placeholder(ctx: LadderCtx) -> Option<&'static str> {
    let instruction = ctx
        .panes
        .entry
        .with(|e| e.as_ref().is_some_and(|e| e.kind == EntryKind::Instruction));
    (instruction && ctx.machine.target().capabilities().word_boxes)
        .then(|| ctx.page.lang.get().files().box_usage)
}

/// The entry's title: what it places, as a branch or not, on which rung.
fn title_of(e: &super::state::EntryState, t: &crate::i18n::Texts) -> String {
    let what = match e.kind {
        EntryKind::Open => t.entry_open,
        EntryKind::Closed => t.entry_closed,
        EntryKind::Coil => t.entry_coil,
        EntryKind::Instruction => t.entry_instruction,
    };
    let branch = if e.branch { t.entry_branch } else { "" };
    format!("{what} {branch} · {} {}", t.rung, e.at.rung + 1)
}

/// The completions of the word being typed: the machine's devices and
/// the project's commented ones, each a chip that fills it in.
#[component]
fn EntryOptions(ctx: LadderCtx, set_text: Callback<String>) -> impl IntoView {
    let options = move || {
        ctx.panes.entry.with(|e| {
            let Some(e) = e else { return Vec::new() };
            let last = e.text.split_whitespace().last().unwrap_or("");
            let comments = ctx.drawing.comments.get();
            let variables = ctx.drawing.variables.get();
            complete_declared(ctx.machine, last, &comments, &variables)
                .into_iter()
                .take(SHOWN)
                .collect::<Vec<_>>()
        })
    };
    let fill = move |chosen: &str| {
        let text = ctx
            .panes
            .entry
            .with_untracked(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default());
        set_text.run(completed(&text, chosen));
    };
    view! {
        <ul class="entry-options" data-testid="device-options">
            <For
                each=options
                key=|(name, comment)| (name.clone(), comment.clone())
                children=move |(name, comment)| {
                    let chosen = name.clone();
                    view! {
                        <li>
                            <button type="button" tabindex="-1" on:mousedown=move |e: web_sys::MouseEvent| {
                                e.prevent_default();
                                fill(&chosen);
                            }>
                                <b>{name}</b>
                                {comment.map(|c| format!(" {c}"))}
                            </button>
                        </li>
                    }
                }
            />
        </ul>
    }
}

#[cfg(test)]
mod tests {
    use super::completed;

    #[test]
    fn a_chip_replaces_the_word_being_typed_or_follows_a_space() {
        assert_eq!(completed("X0", "X00"), "X00");
        assert_eq!(completed("MOV K5", "K50"), "MOV K50");
        assert_eq!(completed("MOV K50 ", "D00"), "MOV K50 D00");
        assert_eq!(completed("", "Y00"), "Y00");
    }
}
