//! Completion in the Structured Text editor (issue #55): the POU's
//! declared variables and blocks whose names start as the word before
//! the caret does, offered as the user types a name (two letters) or on
//! Ctrl+Space; ↑/↓ choose, Enter or Tab take, Escape closes. The list is
//! a listbox the text area names as its active descendant, so a screen
//! reader follows the choice while the caret stays in the text.

use leptos::prelude::*;
use wasm_bindgen::JsCast;

use crate::state::Ctx;

/// The list offered, and its choice.
#[derive(Clone, Copy)]
pub struct Completing {
    /// (name, is a block); empty: closed.
    pub items: RwSignal<Vec<(String, bool)>>,
    pub chosen: RwSignal<usize>,
}

impl Completing {
    pub fn new() -> Completing {
        Completing {
            items: RwSignal::new(Vec::new()),
            chosen: RwSignal::new(0),
        }
    }

    fn close(&self) {
        if self.items.with_untracked(|i| !i.is_empty()) {
            self.items.set(Vec::new());
        }
    }
}

/// The byte index of UTF-16 offset `at` in `text` (a text area's caret).
fn byte_at(text: &str, at: usize) -> usize {
    let mut units = 0;
    for (i, c) in text.char_indices() {
        if units >= at {
            return i;
        }
        units += c.len_utf16();
    }
    text.len()
}

/// The name being typed before byte `caret`: (its start, the name).
pub fn word_before(text: &str, caret: usize) -> (usize, &str) {
    let head = &text[..caret];
    let start = head
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_alphanumeric() || *c == '_')
        .last()
        .map_or(caret, |(i, _)| i);
    (start, &head[start..])
}

/// The declared names that start as `prefix` does (any case), the name
/// typed in full left out.
pub fn candidates(text: &str, prefix: &str) -> Vec<(String, bool)> {
    let p = prefix.to_ascii_lowercase();
    super::st_lex::declared(text)
        .into_iter()
        .filter(|(n, _)| {
            let n = n.to_ascii_lowercase();
            n.starts_with(&p) && n != p
        })
        .collect()
}

fn area_of(e: &web_sys::Event) -> Option<web_sys::HtmlTextAreaElement> {
    e.target()?.dyn_into().ok()
}

/// After an edit: the list follows the name typed (opened from its second
/// letter, closed when no declared name fits).
pub fn typed(c: Completing, e: &web_sys::Event, text: &str) {
    let Some(area) = area_of(e) else {
        return;
    };
    let caret = byte_at(
        text,
        area.selection_start().ok().flatten().unwrap_or(0) as usize,
    );
    let (_, word) = word_before(text, caret);
    let open = c.items.with_untracked(|i| !i.is_empty());
    if word.chars().count() >= 2 || (open && !word.is_empty()) {
        c.items.set(candidates(text, word));
        c.chosen.set(0);
    } else {
        c.close();
    }
}

/// A key in the text area: Ctrl+Space opens the list; with it open, the
/// arrows choose, Enter/Tab take (`edited` gets the new text), Escape
/// closes. Other keys are the text area's own.
pub fn key(c: Completing, e: &web_sys::KeyboardEvent, text: &str, edited: impl Fn(String)) {
    let Some(area) = area_of(e) else {
        return;
    };
    let caret = byte_at(
        text,
        area.selection_start().ok().flatten().unwrap_or(0) as usize,
    );
    let (start, word) = word_before(text, caret);
    if e.ctrl_key() && (e.key() == " " || e.code() == "Space") {
        e.prevent_default();
        c.items.set(candidates(text, word));
        c.chosen.set(0);
        return;
    }
    let n = c.items.with_untracked(Vec::len);
    if n == 0 {
        return;
    }
    match e.key().as_str() {
        "ArrowDown" => c.chosen.update(|i| *i = (*i + 1) % n),
        "ArrowUp" => c.chosen.update(|i| *i = (*i + n - 1) % n),
        "Escape" => c.close(),
        "Enter" | "Tab" => {
            let Some((name, _)) = c
                .items
                .with_untracked(|i| i.get(c.chosen.get_untracked()).cloned())
            else {
                return;
            };
            let new = format!("{}{name}{}", &text[..start], &text[caret..]);
            let at = (text[..start].encode_utf16().count() + name.encode_utf16().count()) as u32;
            area.set_value(&new);
            let _ = area.set_selection_range(at, at);
            c.close();
            edited(new);
        }
        _ => return,
    }
    e.prevent_default();
}

/// The list, under the editor.
#[component]
pub fn Completion(c: Completing) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().st();
    view! {
        <Show when=move || c.items.with(|i| !i.is_empty())>
            <ul class="st-completions" role="listbox" id="st-completions" data-testid="st-completions"
                aria-label=move || s().completions>
                {move || c.items.get().into_iter().enumerate().map(|(i, (name, block))| {
                    let kind = if block { s().block } else { s().variable };
                    view! {
                        <li role="option" id=format!("st-completion-{i}")
                            aria-selected=move || (c.chosen.get() == i).to_string()
                            class:chosen=move || c.chosen.get() == i>
                            <span class="st-name">{name}</span> " " <small>{kind}</small>
                        </li>
                    }
                }).collect_view()}
            </ul>
        </Show>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_word_before_the_caret_and_what_completes_it() {
        let text = "PROGRAM p\nVAR\n  count, total : INT;\n  timer1 : TON;\nEND_VAR\nco";
        assert_eq!(word_before(text, text.len()), (text.len() - 2, "co"));
        assert_eq!(word_before("a := ", 5), (5, ""));
        assert_eq!(candidates(text, "co"), [("count".to_string(), false)]);
        let all: Vec<String> = candidates(text, "").into_iter().map(|(n, _)| n).collect();
        assert_eq!(all, ["count", "total", "timer1"]);
        assert_eq!(byte_at("日本x", 2), "日本".len());
    }
}
