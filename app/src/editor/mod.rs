//! The ladder editor, the main view of every machine's workspace
//! (issue #13, docs/editor.md). The editing model is the engine's
//! (`engine::ladder::edit`); here it is rendered and fed keys:
//!
//! - [`state`]: one machine's editor and the signals the view reads;
//! - [`model`], [`keys`]: what the cells show and what keys do (plain
//!   Rust, tested natively);
//! - [`grid`], [`entry`], [`palette`], [`side`], [`find`]: the views;
//! - [`store`], [`projects`]: the autosave and named projects;
//! - [`shared`], [`files`], [`picture`]: share links, files, SVG / PNG;
//! - [`cases`]: the Tests pane.

pub mod autosave;
pub mod cases;
pub mod cell_kind;
pub mod chart;
pub mod entry;
pub mod files;
pub mod find;
pub mod grid;
pub mod import;
pub mod keys;
pub mod live;
pub mod machine;
pub mod model;
pub mod palette;
pub mod picture;
pub mod projects;
pub mod shared;
pub mod side;
pub mod state;
pub mod store;

pub mod travel;
pub mod variables;
pub mod why;
pub mod zoom;

use engine::ladder::edit::Edit;
use engine::MachineId;
use leptos::prelude::*;

pub use state::{LadderCtx, Program};

/// Every machine's editor, indexed by the machine's place in
/// [`MachineId::ALL`]; `Copy`, provided as context so that a ladder can be
/// copied to another machine.
#[derive(Clone, Copy)]
pub struct Ladders {
    all: [LadderCtx; MachineId::ALL.len()],
}

impl Ladders {
    /// An editor for each machine, made by `make`.
    pub fn new(make: impl Fn(MachineId) -> LadderCtx) -> Ladders {
        Ladders {
            all: MachineId::ALL.map(make),
        }
    }

    /// The editor of `machine` (every machine has one).
    pub fn of(&self, machine: MachineId) -> LadderCtx {
        let index = MachineId::ALL.iter().position(|m| *m == machine);
        // ALL lists every machine: the position is always found.
        self.all[index.unwrap_or_default()]
    }
}

/// The editor: toolbar, device entry, palette, grid, listing, problems.
#[component]
pub fn LadderEditor(ctx: LadderCtx) -> impl IntoView {
    // The key map takes the focus when it opens (Escape closes it and
    // gives the focus back to the ladder).
    let keymap = NodeRef::<leptos::html::Div>::new();
    Effect::new(move |_| {
        if ctx.panes.help.get() {
            if let Some(d) = keymap.get() {
                let _ = d.focus();
            }
        }
    });
    let grid = NodeRef::<leptos::html::Div>::new();
    let refocus = Callback::new(move |()| grid::focus(grid));
    let t = move || ctx.page.lang.get().texts();
    clipboard_events(ctx);
    view! {
        <section class="ladder-editor" data-machine=ctx.machine.name()>
            <shared::SharedBanner ctx />
            <autosave::StorageBanner ctx />
            <Toolbar ctx refocus />
            <Show when=move || ctx.panes.tests_open.get()>
                <Drawer open=ctx.panes.tests_open refocus label=Signal::derive(move || t().tests.to_string())>
                    <cases::TestsPane ctx />
                </Drawer>
            </Show>
            <Show when=move || ctx.panes.projects_open.get()>
                <Drawer open=ctx.panes.projects_open refocus label=Signal::derive(move || t().projects.to_string())>
                    <projects::ProjectsPane ctx />
                </Drawer>
            </Show>
            <Show when=move || ctx.panes.find_open.get()>
                <Drawer open=ctx.panes.find_open refocus label=Signal::derive(move || t().find.to_string())>
                    <find::FindPane ctx on_pick=refocus />
                </Drawer>
            </Show>
            <div class="ladder-toolbar run-toolbar">
                <live::RunBar ctx />
                <zoom::ZoomBar ctx grid />
            </div>
            <travel::TravelBar ctx />
            <CommentBar ctx />
            <entry::DeviceEntry ctx on_close=refocus />
            <div class="edit-message" role="alert" data-testid="edit-message">
                {move || ctx.panes.message.get()}
            </div>
            <div class="ladder-main">
                <palette::Palette ctx on_done=refocus />
                <grid::LadderGrid ctx grid />
                <div class="ladder-side">
                    <side::ListingPane ctx on_pick=refocus />
                    <side::ProblemsPane ctx on_pick=refocus />
                    <why::WhyPanel ctx />
                    <live::WatchTable ctx />
                    <live::ForceList ctx />
                </div>
            </div>
            <chart::TimingChart ctx />
            <Show when=move || ctx.panes.help.get()>
                <div class="keymap" data-testid="keymap" role="dialog" aria-label=move || t().keys
                    node_ref=keymap tabindex="-1"
                    on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" {
                        e.prevent_default();
                        ctx.panes.help.set(false);
                        grid::focus(grid);
                    }>
                    <table>
                        {keys::KEY_MAP.iter().map(|(k, what)| view! {
                            <tr><th>{*k}</th><td>{*what}</td></tr>
                        }).collect_view()}
                    </table>
                    <button type="button" on:click=move |_| { ctx.panes.help.set(false); grid::focus(grid); }>
                        {move || t().close}
                    </button>
                </div>
            </Show>
        </section>
    }
}

/// A pane opened under the toolbar (Tests, Projects, Find), where the
/// user looks: it is scrolled into view and takes the focus when it opens;
/// Escape or Close shuts it and gives the focus back to the ladder.
#[component]
fn Drawer(
    open: RwSignal<bool>,
    refocus: Callback<()>,
    label: Signal<String>,
    children: Children,
) -> impl IntoView {
    let node = NodeRef::<leptos::html::Div>::new();
    Effect::new(move |_| {
        if let Some(n) = node.get() {
            let options = web_sys::ScrollIntoViewOptions::new();
            options.set_block(web_sys::ScrollLogicalPosition::Nearest);
            n.scroll_into_view_with_scroll_into_view_options(&options);
            let _ = n.focus();
        }
    });
    let close = move || {
        open.set(false);
        refocus.run(());
    };
    view! {
        <div class="drawer" role="dialog" aria-label=label tabindex="-1" node_ref=node
            on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" {
                e.prevent_default();
                close();
            }>
            <button type="button" class="pane-close" data-testid="pane-close" on:click=move |_| close()>
                "×"
            </button>
            {children()}
        </div>
    }
}

/// New, undo, redo, write to the machine, find, keys, copy elsewhere.
#[component]
fn Toolbar(ctx: LadderCtx, refocus: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let ladders = use_context::<Ladders>();
    let run_drawing = live::run_action(ctx);
    let others: Vec<MachineId> = MachineId::ALL
        .into_iter()
        .filter(|m| *m != ctx.machine)
        .collect();
    view! {
        <div class="ladder-toolbar" role="toolbar">
            <span class="tb-main">
            <button type="button" data-testid="new-ladder" on:click=move |_| {
                ctx.apply(Edit::NewLadder);
                refocus.run(());
            }>{move || t().new_ladder}</button>
            <button type="button" data-testid="undo" disabled=move || !ctx.drawing.can_undo.get()
                on:click=move |_| { ctx.undo(); refocus.run(()); }>{move || t().undo}</button>
            <button type="button" data-testid="redo" disabled=move || !ctx.drawing.can_redo.get()
                on:click=move |_| { ctx.redo(); refocus.run(()); }>{move || t().redo}</button>
            <button type="button" data-testid="ladder-write" disabled=move || ctx.drawing.listing.with(Option::is_none)
                on:click=move |_| {
                    // The same action as Run, said where the user looks.
                    if run_drawing() {
                        ctx.panes.message.set(Some(t().written.to_string()));
                    }
                }>{move || t().write_plc}</button>
            </span>
            <span class="tb-more">
            <shared::ShareButton ctx />
            <files::FileButtons ctx refocus />
            <button type="button" data-testid="tests-open" on:click=move |_| ctx.panes.toggle(ctx.panes.tests_open)>
                {move || t().tests}
            </button>
            <button type="button" data-testid="projects-open" on:click=move |_| ctx.panes.toggle(ctx.panes.projects_open)>
                {move || t().projects}
            </button>
            <button type="button" data-testid="find-open" on:click=move |_| ctx.panes.toggle(ctx.panes.find_open)>
                {move || t().find}
            </button>
            <button type="button" data-testid="keys" on:click=move |_| ctx.panes.help.update(|h| *h = !*h)>
                {move || t().keys}
            </button>
            <label>
                {move || t().copy_to}
                <select data-testid="copy-to" prop:value="" on:change=move |e| {
                    let target = MachineId::parse(&event_target_value(&e)).ok();
                    if let (Some(target), Some(ladders)) = (target, ladders) {
                        let other = ladders.of(target);
                        other.apply(Edit::Replace { ladder: ctx.ladder() });
                        ctx.page.machine.set(target);
                    }
                }>
                    <option value="">"—"</option>
                    {others.into_iter().map(|m| view! {
                        <option value=m.name()>{crate::state::product_name(m)}</option>
                    }).collect_view()}
                </select>
            </label>
            </span>
        </div>
    }
}

/// The cursor's rung comment and its device's comment, edited in place.
#[component]
fn CommentBar(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let rung_comment = move || {
        ctx.drawing.rungs.track();
        let rung = ctx.drawing.cursor.get().rung;
        ctx.with_editor(|e| e.ladder().rungs.get(rung).map(|r| r.comment.clone()))
    };
    let device = move || {
        ctx.drawing.rungs.track();
        let c = ctx.drawing.cursor.get();
        ctx.with_editor(|e| {
            let element = e.ladder().rungs.get(c.rung)?.get(c.pos())?;
            element
                .read_device()
                .or_else(|| element.written_device())
                .map(str::to_string)
        })
    };
    view! {
        <div class="comment-bar">
            <label>
                {move || t().rung_comment}
                <input
                    data-testid="rung-comment-input"
                    disabled=move || rung_comment().is_none()
                    prop:value=move || rung_comment().unwrap_or_default()
                    on:change=move |e| {
                        let index = ctx.drawing.cursor.get_untracked().rung;
                        ctx.apply(Edit::RungComment { index, text: event_target_value(&e) });
                    }
                />
            </label>
            <label>
                {move || format!("{} {}", t().device_comment, device().unwrap_or_default())}
                <input
                    data-testid="device-comment-input"
                    disabled=move || device().is_none()
                    prop:value=move || device().and_then(|d| ctx.drawing.comments.with(|c| c.get(&d).cloned())).unwrap_or_default()
                    on:change=move |e| {
                        if let Some(device) = device() {
                            ctx.apply(Edit::DeviceComment { device, text: event_target_value(&e) });
                        }
                    }
                />
            </label>
        </div>
    }
}

/// Copy, cut and paste through the system clipboard while the ladder has
/// the focus (the events reach the document, not the grid, when nothing
/// editable is focused), so rungs go between two tabs of the page.
fn clipboard_events(ctx: LadderCtx) {
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
