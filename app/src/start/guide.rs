//! The guide in the page (`data-testid="guide"`, Help → Guide): a panel
//! beside the workbench showing `web/guide/<lang>.html`, fetched when
//! first opened and kept by the service worker for offline use; each
//! pane's "?" opens it at that pane's section.

use leptos::prelude::*;
use leptos::wasm_bindgen::JsCast;

use super::fetch::{FetchState, Fetched};
use crate::docks::Tool;
use crate::state::Ctx;

/// The guide's panel, while open.
#[component]
pub fn Guide() -> impl IntoView {
    let ctx = Ctx::get();
    let start = super::Start::get();
    let s = move || ctx.lang.get().start();
    let fetched = RwSignal::new(Fetched::Loading);
    let body = NodeRef::<leptos::html::Div>::new();
    let url = move || format!("guide/{}.html", ctx.lang.get().code());
    Effect::new(move |_| {
        if start.guide.with(Option::is_some) {
            super::fetch::ensure_style();
            super::place_below_bar();
            start.files.load(&url(), fetched);
        }
    });
    // Once the text is in, the section asked for comes into view.
    Effect::new(move |_| {
        let section = start.guide.get();
        let loaded = fetched.with(|f| matches!(f, Fetched::Text(_)));
        if let (Some(section), true) = (section, loaded) {
            // After the text is drawn into the page.
            // The guide may be closed by then.
            request_animation_frame(move || {
                if let Some(Some(root)) = body.try_get_untracked() {
                    scroll_to(&root, &section);
                }
            });
        }
    });
    let html = move || match fetched.get() {
        Fetched::Text(text) => text,
        _ => String::new(),
    };
    // Escape closes it wherever the focus is, but in a text field.
    let escape = window_event_listener(leptos::ev::keydown, move |e| {
        if e.key() == "Escape"
            && !super::typed_in_a_field(&e)
            && start.guide.with_untracked(Option::is_some)
        {
            start.guide.set(None);
        }
    });
    on_cleanup(move || escape.remove());
    view! {
        <Show when=move || start.guide.with(Option::is_some)>
            <aside class="guide" data-testid="guide" aria-label=move || s().guide>
                <header class="guide-head">
                    <h2>{move || s().guide}</h2>
                    <button type="button" data-testid="guide-close" title=move || s().guide_close
                        aria-label=move || s().guide_close on:click=move |_| start.guide.set(None)>"✕"</button>
                </header>
                <FetchState fetched retry=move || start.files.load(&url(), fetched) />
                <div class="guide-body" node_ref=body inner_html=html
                    on:click=move |e: web_sys::MouseEvent| follow_link(&e, body)></div>
            </aside>
        </Show>
    }
}

/// A link within the guide (`#section`) scrolls the panel, leaving the
/// page's address alone (it holds share links).
fn follow_link(e: &web_sys::MouseEvent, body: NodeRef<leptos::html::Div>) {
    let link = e
        .target()
        .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
        .and_then(|el| el.closest("a[href^='#']").ok().flatten());
    let (Some(link), Some(root)) = (link, body.get_untracked()) else {
        return;
    };
    if let Some(href) = link.get_attribute("href") {
        e.prevent_default();
        scroll_to(&root, href.trim_start_matches('#'));
    }
}

fn scroll_to(root: &web_sys::Element, section: &str) {
    if section.is_empty() {
        root.set_scroll_top(0);
        return;
    }
    let found = root
        .query_selector(&format!("[id='{}']", section.replace('\'', "")))
        .ok()
        .flatten();
    if let Some(el) = found {
        el.scroll_into_view();
    }
}

/// The guide's section on `tool` (its pane's "?"); the machine's panel
/// goes to the machine's own section.
pub fn section_of(tool: Tool, machine: engine::MachineId) -> &'static str {
    match tool {
        Tool::Watch => "watch",
        Tool::Chart => "chart",
        Tool::Tests => "tests",
        Tool::Why => "why",
        Tool::Listing => "listing",
        Tool::Comments => "drawing",
        Tool::Variables => "variables",
        Tool::Program => "program",
        Tool::Cpu => "cpu",
        Tool::Plant => "plant",
        Tool::Panel => machine.name(),
    }
}

/// A "?" that opens the guide at `section` (beside a pane's title).
#[component]
pub fn GuideLink(#[prop(into)] section: Signal<&'static str>) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().start();
    view! {
        <button type="button" class="guide-link" data-testid="guide-link" data-section=move || section.get()
            title=move || s().guide_section aria-label=move || s().guide_section
            on:click=move |_| super::Start::get().open_guide(section.get())>"?"</button>
    }
}

crate::parts::part_fn!(
    start_guide,
    /// The guide's panel is a part of its own (issue #53): fetched when it first
    /// shows, not by the first screen.
    pub(crate) fn part() -> Result<crate::parts::Draw, crate::parts::PartMissing> {
        Ok(|| view! { <Guide /> }.into_any())
    }
);
