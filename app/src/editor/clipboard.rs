//! The clipboard: copy, cut and paste through the system clipboard while
//! the ladder has the focus (the events reach the document, not the grid,
//! when nothing editable is focused), so rungs go between two tabs of the
//! page; and the Edit menu's Copy, Cut and Paste.

use leptos::prelude::*;

use super::LadderCtx;

/// Edit ▸ Copy: the selection (or the cursor's cell) to this page's
/// clipboard and, where the browser allows, the system's.
pub fn copy(ctx: LadderCtx) {
    if let Some(text) = ctx.copy_text() {
        to_system(&text);
    }
}

/// Edit ▸ Cut: copied, then cleared.
pub fn cut(ctx: LadderCtx) {
    if let Some(text) = ctx.cut_text() {
        to_system(&text);
    }
}

/// Edit ▸ Paste: this page's clipboard at the cursor.
pub fn paste(ctx: LadderCtx) {
    ctx.paste_text(None);
}

/// Writes `text` to the system clipboard; a refusal (permissions) leaves
/// this page's clipboard, which holds it too.
fn to_system(text: &str) {
    if let Some(window) = web_sys::window() {
        let _ = window.navigator().clipboard().write_text(text);
    }
}

/// Listens to the system's copy, cut and paste while the editor is shown.
pub fn listen(ctx: LadderCtx) {
    fn on_ladder() -> bool {
        web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.active_element())
            .and_then(|e| e.get_attribute("data-testid"))
            .as_deref()
            == Some("ladder")
    }
    let copy = window_event_listener(leptos::ev::copy, move |e| {
        if !on_ladder() {
            return;
        }
        if let (Some(text), Some(dt)) = (ctx.copy_text(), e.clipboard_data()) {
            let _ = dt.set_data("text/plain", &text);
            e.prevent_default();
        }
    });
    let cut = window_event_listener(leptos::ev::cut, move |e| {
        if !on_ladder() {
            return;
        }
        if let (Some(text), Some(dt)) = (ctx.cut_text(), e.clipboard_data()) {
            let _ = dt.set_data("text/plain", &text);
            e.prevent_default();
        }
    });
    let paste = window_event_listener(leptos::ev::paste, move |e| {
        if !on_ladder() {
            return;
        }
        ctx.clip.pasted.set_value(true);
        e.prevent_default();
        let text = e
            .clipboard_data()
            .and_then(|dt| dt.get_data("text/plain").ok())
            .filter(|t| !t.is_empty());
        ctx.paste_text(text);
    });
    on_cleanup(move || {
        copy.remove();
        cut.remove();
        paste.remove();
    });
}
