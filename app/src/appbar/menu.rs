//! A menu of the app bar (File, Edit, View, Help; on a phone all of them
//! behind one button): a button that opens a panel of the controls the
//! toolbar once showed in a row. The panel's controls are drawn when it
//! first opens (they are a part, issue #53), then stay in the page while
//! closed (hidden), so a file input in it keeps its chosen file. Escape, a click
//! outside, a button chosen inside or a choice made in a field closes it.

use leptos::prelude::*;

use crate::state::Ctx;

/// A menu: `menu-<id>` opens `data-menu-panel="<id>"`.
#[component]
pub fn Menu(id: &'static str, label: Signal<&'static str>, children: ChildrenFn) -> impl IntoView {
    let open = RwSignal::new(false);
    // Set by the first opening (in the click itself, so that a menu
    // opened and closed at once is drawn too).
    let drawn = RwSignal::new(false);
    let node = NodeRef::<leptos::html::Div>::new();
    // A click anywhere outside the menu closes it.
    let outside = window_event_listener(leptos::ev::pointerdown, move |e| {
        if !open.get_untracked() {
            return;
        }
        let inside = e
            .target()
            .and_then(|t| {
                use leptos::wasm_bindgen::JsCast;
                t.dyn_into::<web_sys::Node>().ok()
            })
            .zip(node.get_untracked())
            .is_some_and(|(t, menu)| menu.contains(Some(&t)));
        if !inside {
            open.set(false);
        }
    });
    on_cleanup(move || outside.remove());
    view! {
        <div class="menu" node_ref=node
            on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" && open.get_untracked() {
                e.prevent_default();
                open.set(false);
            }>
            <button type="button" class="menu-button" data-testid=format!("menu-{id}")
                aria-haspopup="true" aria-expanded=move || open.get().to_string()
                aria-controls=format!("menu-panel-{id}")
                on:click=move |_| {
                    open.update(|o| *o = !*o);
                    if !drawn.get_untracked() {
                        drawn.set(true);
                    }
                }>
                {move || label.get()}
            </button>
            <div class="menu-panel" id=format!("menu-panel-{id}") data-menu-panel=id
                hidden=move || !open.get()
                // A choice made in a field (an example, a file, the machine
                // to copy to) closes the menu too; a check box does not.
                on:change=move |e: web_sys::Event| {
                    use leptos::wasm_bindgen::JsCast;
                    let checkbox = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok())
                        .is_some_and(|i| i.type_() == "checkbox");
                    if !checkbox {
                        open.set(false);
                    }
                }
                on:click=move |e: web_sys::MouseEvent| {
                    // A button chosen closes the menu; a field (a select,
                    // the file input, a check box) keeps it open to be used.
                    use leptos::wasm_bindgen::JsCast;
                    let chosen = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
                        .and_then(|el| el.closest("button").ok().flatten())
                        .is_some();
                    if chosen {
                        open.set(false);
                    }
                }>
                // Until first opened, a mark names the menu (the end-to-end
                // tests' `el()` opens such menus to look for a control).
                {move || if drawn.get() {
                    children().into_any()
                } else {
                    view! { <div hidden data-lazy-menu=id></div> }.into_any()
                }}
            </div>
        </div>
    }
}

/// The label of a menu in the page's language.
pub fn label(f: fn(&'static crate::i18n::Texts) -> &'static str) -> Signal<&'static str> {
    let ctx = Ctx::get();
    Signal::derive(move || f(ctx.lang.get().texts()))
}
