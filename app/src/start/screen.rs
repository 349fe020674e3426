//! The start screen (`data-testid="start"`): not modal, over the centre
//! of the workbench, on a fresh profile's first visit to the bare page and
//! from Help. Its words and pictures are `web/start/<lang>.html`, fetched
//! when it first shows; every control in it carries `data-start` naming
//! what it does, read here by one click handler:
//!
//! - `machine:<name>`: the machine (its card shows pressed, its examples
//!   show in the gallery);
//! - `draw`: the guided first rung; `open`: the File menu's file input;
//! - `example` / `exercise`: show that part (the gallery, the exercises);
//! - `example:<machine>:<id>`: opens that example;
//! - a link to `#<share text>`: opens an exercise (the address's
//!   fragment, as any share link); the form `exercise-link` opens a
//!   pasted link.
//!
//! Anything chosen but the machine and the parts closes the screen for good.

use leptos::prelude::*;
use leptos::wasm_bindgen::JsCast;

use super::fetch::{FetchState, Fetched};
use super::steps::Step;
use crate::state::{Ctx, MachineKind};
use crate::storage;

/// The start screen.
#[component]
pub fn StartScreen() -> impl IntoView {
    let ctx = Ctx::get();
    let start = super::Start::get();
    let s = move || ctx.lang.get().start();
    let fetched = RwSignal::new(Fetched::Loading);
    let body = NodeRef::<leptos::html::Div>::new();
    let url = move || format!("start/{}.html", ctx.lang.get().code());
    Effect::new(move |_| {
        if start.open.get() {
            super::fetch::ensure_style();
            super::place_below_bar();
            start.files.load(&url(), fetched);
        }
    });
    // The fragment is in the page: mark the machine shown.
    Effect::new(move |_| {
        let machine = ctx.machine.get();
        fetched.track();
        // After the text is drawn into the page; by then the screen may
        // be gone (an example chosen changes the machine and closes it).
        request_animation_frame(move || {
            if let Some(Some(root)) = body.try_get_untracked() {
                show_machine(&root, machine);
            }
        });
    });
    let html = move || match fetched.get() {
        Fetched::Text(text) => text,
        _ => String::new(),
    };
    let resized = window_event_listener(leptos::ev::resize, |_| super::place_below_bar());
    on_cleanup(move || resized.remove());
    view! {
        <Show when=move || start.open.get()>
            <section class="start" data-testid="start" aria-label=move || s().start_label>
                <button type="button" class="start-close" data-testid="start-close"
                    title=move || s().start_close aria-label=move || s().start_close
                    on:click=move |_| start.close()>"✕"</button>
                <FetchState fetched retry=move || start.files.load(&untrack(url), fetched) />
                <div class="start-body" node_ref=body inner_html=html
                    on:click=move |e| on_click(ctx, &e)
                    on:submit=move |e| on_submit(ctx, &e)></div>
            </section>
        </Show>
    }
}

/// The `data-start` of the control under a click, if any.
fn chosen(e: &web_sys::Event) -> Option<(web_sys::Element, String)> {
    let target = e.target()?.dyn_into::<web_sys::Element>().ok()?;
    let control = target.closest("[data-start]").ok()??;
    let what = control.get_attribute("data-start")?;
    Some((control, what))
}

fn on_click(ctx: Ctx, e: &web_sys::MouseEvent) {
    let start = super::Start::get();
    let Some((control, what)) = chosen(e) else {
        return;
    };
    let part = |name: &str| {
        if let Some(root) = control.closest(".start-body").ok().flatten() {
            show_part(&root, name);
        }
    };
    match what.split(':').collect::<Vec<_>>().as_slice() {
        ["machine", name] => {
            if let Ok(kind) = MachineKind::parse(name) {
                ctx.machine.set(kind);
                storage::save_string(storage::MACHINE_KEY, kind.name());
            }
        }
        ["draw"] => {
            start.close();
            start.tour.set(Some(Step::Intro));
        }
        ["example"] => part("example"),
        ["exercise"] => part("exercise"),
        ["example", machine, id] => {
            if let Ok(kind) = MachineKind::parse(machine) {
                ctx.machine.set(kind);
                storage::save_string(storage::MACHINE_KEY, kind.name());
                // Opened by the page, which holds every workspace.
                start.example.set(Some((kind, (*id).to_string())));
                start.close();
            }
        }
        ["open"] => {
            start.close();
            // The File menu's controls are drawn when it first opens (a
            // part, issue #53): opened, it shows where Open lives, and its
            // file input is asked once drawn (within the click's
            // activation, which lets a script open a file chooser).
            click_testid("menu-file");
            click_when_drawn("open-file", 60);
        }
        // A link to an exercise: the address's fragment opens it.
        ["exercise-open"] => start.close(),
        _ => {}
    }
}

/// The pasted exercise link: its fragment opens as a share link does.
fn on_submit(ctx: Ctx, e: &web_sys::SubmitEvent) {
    e.prevent_default();
    let Some(form) = e
        .target()
        .and_then(|t| t.dyn_into::<web_sys::HtmlFormElement>().ok())
    else {
        return;
    };
    let field = form
        .query_selector("input")
        .ok()
        .flatten()
        .and_then(|i| i.dyn_into::<web_sys::HtmlInputElement>().ok());
    let Some(field) = field else {
        return;
    };
    let link = field.value();
    let fragment = link.rsplit_once('#').map_or(link.trim(), |(_, f)| f.trim());
    if fragment.is_empty() {
        return;
    }
    let ladders = expect_context::<crate::editor::Ladders>();
    crate::editor::shared::open_fragment(ctx, ladders, fragment);
    super::Start::get().close();
}

/// Shows part `name` of the screen (`data-start-part`), hiding the
/// others, and brings it into view (it is below the choices).
fn show_part(root: &web_sys::Element, name: &str) {
    for_each(root, "[data-start-part]", |el| {
        let shown = el.get_attribute("data-start-part").as_deref() == Some(name);
        let _ = el.toggle_attribute_with_force("hidden", !shown);
        if shown {
            el.scroll_into_view();
        }
    });
}

/// Marks `machine`'s card pressed and shows its examples only.
fn show_machine(root: &web_sys::Element, machine: MachineKind) {
    let mine = format!("machine:{}", machine.name());
    for_each(root, "[data-start^='machine:']", |el| {
        let pressed = el.get_attribute("data-start").as_deref() == Some(mine.as_str());
        let _ = el.set_attribute("aria-pressed", if pressed { "true" } else { "false" });
    });
    for_each(root, "[data-gallery]", |el| {
        let hide = el.get_attribute("data-gallery").as_deref() != Some(machine.name());
        let _ = el.toggle_attribute_with_force("hidden", hide);
    });
}

fn for_each(root: &web_sys::Element, selector: &str, mut f: impl FnMut(&web_sys::Element)) {
    let Ok(list) = root.query_selector_all(selector) else {
        return;
    };
    for i in 0..list.length() {
        if let Some(el) = list
            .item(i)
            .and_then(|n| n.dyn_into::<web_sys::Element>().ok())
        {
            f(&el);
        }
    }
}

/// Clicks the page's control `testid` (the File menu's file input).
fn click_testid(testid: &str) {
    let found = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| {
            d.query_selector(&format!("[data-testid='{testid}']"))
                .ok()
                .flatten()
        })
        .and_then(|el| el.dyn_into::<web_sys::HtmlElement>().ok());
    if let Some(el) = found {
        el.click();
    }
}

/// Clicks the element with `testid` once it is in the page, looking
/// again every 50 ms at most `tries` times.
fn click_when_drawn(testid: &'static str, tries: u32) {
    let there = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| {
            d.query_selector(&format!("[data-testid='{testid}']"))
                .ok()
                .flatten()
        })
        .is_some();
    if there {
        click_testid(testid);
    } else if tries > 0 {
        set_timeout(
            move || click_when_drawn(testid, tries - 1),
            std::time::Duration::from_millis(50),
        );
    }
}

crate::parts::part_fn!(
    start_screen,
    /// The start screen is a part of its own (issue #53): fetched when it first
    /// shows, not by the first screen.
    pub(crate) fn part() -> Result<crate::parts::Draw, crate::parts::PartMissing> {
        Ok(|| view! { <StartScreen /> }.into_any())
    }
);
