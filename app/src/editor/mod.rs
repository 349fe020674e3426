//! The ladder editor, the main view of every machine's workspace
//! (issue #13, docs/editor.md). The editing model is the engine's
//! (`engine::ladder::edit`); here it is rendered and fed keys:
//!
//! - [`state`]: one machine's editor and the signals the view reads;
//! - [`model`], [`keys`]: what the cells show and what keys do (plain
//!   Rust, tested natively);
//! - [`grid`], [`entry`], [`palette`], [`side`], [`find`]: the views;
//! - [`panes`]: the tools' panes (Tests, chart, Why?, listing, variables,
//!   Find, Projects);
//! - [`files`]: share links, files, SVG / PNG, the autosave.

pub mod bands;
pub mod box_fields;
pub mod cell_kind;
pub mod clipboard;
pub mod columns;
pub mod conduct;
pub mod entry;
pub mod files;
pub mod grid;
pub mod keys;
pub mod live;
pub mod machine;
pub mod model;
pub mod on_screen;
pub mod palette;
pub mod panes;
pub mod state;
pub mod strip;

pub mod travel;
pub mod zoom;

use engine::ladder::edit::Edit;
use engine::MachineId;
use leptos::prelude::*;

pub use files::{autosave, import, picture, shared, store};
pub use panes::{cases, chart, find, projects, side, variables, why};
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
        self.all[machine.index()]
    }
}

/// The editor in the workbench's centre: its compact toolbar, the
/// device entry, the palette and the grid (and on a phone the strip of
/// the ladder's inputs and outputs). The tools around it are the docks'
/// ([`tools`]).
#[component]
pub fn LadderEditor(ctx: LadderCtx, grid: NodeRef<leptos::html::Div>) -> impl IntoView {
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
    let refocus = Callback::new(move |()| grid::focus(grid));
    let t = move || ctx.page.lang.get().texts();
    clipboard::listen(ctx);
    view! {
        <section class="ladder-editor" data-machine=ctx.machine.name()>
            <shared::SharedBanner ctx />
            <autosave::StorageBanner ctx />
            <Toolbar ctx grid refocus />
            <Show when=move || ctx.panes.projects_open.get()>
                <Drawer open=ctx.panes.projects_open refocus label=Signal::derive(move || t().projects.to_string())>
                    {crate::parts::part_for("projects-part", ctx.page.lang.into(), ctx, panes::parts::projects)}
                </Drawer>
            </Show>
            <Show when=move || ctx.panes.find_open.get()>
                <Drawer open=ctx.panes.find_open refocus label=Signal::derive(move || t().find.to_string())>
                    {crate::parts::part_for("find-part", ctx.page.lang.into(), (ctx, refocus), panes::parts::find)}
                </Drawer>
            </Show>
            <Show when=move || ctx.panes.import.with(Option::is_some)>
                {crate::parts::part_for("import-part", ctx.page.lang.into(), (ctx, ctx.panes.import, refocus), import::dialog)}
            </Show>
            <travel::TravelBar ctx />
            <entry::DeviceEntry ctx on_close=refocus />
            <div class="edit-message" role="alert" data-testid="edit-message">
                {move || ctx.panes.message.get()}
            </div>
            <div class="ladder-main">
                <palette::Palette ctx on_done=refocus />
                <grid::LadderGrid ctx grid />
            </div>
            <strip::IoStrip ctx />
            <Show when=move || ctx.panes.help.get()>
                <div class="keymap" data-testid="keymap" role="dialog" aria-label=move || t().keys
                    node_ref=keymap tabindex="-1"
                    on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" {
                        e.prevent_default();
                        ctx.panes.help.set(false);
                        grid::focus(grid);
                    }>
                    <table>
                        {move || ctx.page.lang.get().keys().key_map.iter().map(|(k, what)| view! {
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

/// The editor's tools as the bottom dock shows them, each with its tool:
/// watch and forces, chart, tests, Why?, listing and problems, and (the
/// soft PLC) the variables. The machine adds its program text and views.
pub fn tools(
    ctx: LadderCtx,
    grid: NodeRef<leptos::html::Div>,
) -> Vec<(crate::docks::Tool, AnyView)> {
    use crate::docks::Tool;
    let refocus = Callback::new(move |()| grid::focus(grid));
    let mut tools = vec![
        (
            Tool::Watch,
            view! { <div class="dock-pair"><live::WatchTable ctx /><live::ForceList ctx /></div> }
                .into_any(),
        ),
        (
            Tool::Chart,
            pane_part(Tool::Chart, "chart-part", ctx, panes::parts::chart),
        ),
        (
            Tool::Tests,
            pane_part(Tool::Tests, "tests-part", ctx, panes::parts::tests),
        ),
        (
            Tool::Why,
            pane_part(Tool::Why, "why-part", (ctx, refocus), panes::parts::why),
        ),
        (
            Tool::Listing,
            pane_part(
                Tool::Listing,
                "listing-part",
                (ctx, refocus),
                panes::parts::listing,
            ),
        ),
    ];
    why::answer_requests(ctx);
    tools.push((Tool::Comments, view! { <CommentBar ctx /> }.into_any()));
    if Tool::Variables.on(ctx.machine) {
        tools.push((
            Tool::Variables,
            pane_part(
                Tool::Variables,
                "variables-part",
                ctx,
                panes::parts::variables,
            ),
        ));
    }
    tools
}

/// A tool's pane held in a part (`load`, its part function): drawn, and
/// fetched, when its tab is first shown; `testid` names its place while
/// it is fetched.
fn pane_part<A, F, Fut>(tool: crate::docks::Tool, testid: &'static str, arg: A, load: F) -> AnyView
where
    A: Copy + Send + Sync + 'static,
    F: Fn() -> Fut + Copy + Send + Sync + 'static,
    Fut: std::future::Future<Output = Result<crate::parts::DrawFor<A>, crate::parts::PartMissing>>
        + 'static,
{
    let ctx = crate::state::Ctx::get();
    let (lang, docks) = (ctx.lang, ctx.docks);
    // Its arrival is told to the docks (a phone's sheet grows then: the
    // ladder is kept above it).
    let load = move || async move {
        let part = load().await;
        docks.arrived.notify();
        part
    };
    crate::docks::when_first_shown(docks, tool, move || {
        crate::parts::part_for(testid, lang.into(), arg, load).into_any()
    })
}

/// A pane opened under the toolbar (Projects, Find), where the
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

/// The compact toolbar over the ladder: New, Undo, Redo, Write to PLC,
/// Tests, the zoom, and what the run means for the drawing. Each button
/// is an icon with a tooltip naming its key; the rest is in the menus.
#[component]
fn Toolbar(
    ctx: LadderCtx,
    grid: NodeRef<leptos::html::Div>,
    refocus: Callback<()>,
) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let run_drawing = live::run_action(ctx);
    view! {
        <div class="ladder-toolbar" role="toolbar" aria-label=move || t().toolbar>
            <button type="button" class="icon-button" data-testid="new-ladder" title=move || t().new_ladder
                aria-label=move || t().new_ladder
                on:click=move |_| {
                    ctx.new_ladder();
                    refocus.run(());
                }>
                // A blank sheet, not "+": the zoom bar's "+" sat beside it on
                // a phone, where the labels are hidden.
                <svg class="icon" viewBox="0 0 16 16" aria-hidden="true">
                    <path d="M3.5 1.5h6l3 3v10h-9z M9.5 1.5v3h3" fill="none" stroke="currentColor" stroke-width="1.4" stroke-linejoin="round" />
                </svg>
                <span class="wide-only" aria-hidden="true">{move || t().new_ladder}</span></button>
            <button type="button" class="icon-button" data-testid="undo" disabled=move || !ctx.drawing.can_undo.get()
                title=move || format!("{} (Ctrl+Z)", t().undo) aria-label=move || t().undo
                on:click=move |_| { ctx.undo(); refocus.run(()); }>"↶"</button>
            <button type="button" class="icon-button" data-testid="redo" disabled=move || !ctx.drawing.can_redo.get()
                title=move || format!("{} (Ctrl+Y)", t().redo) aria-label=move || t().redo
                on:click=move |_| { ctx.redo(); refocus.run(()); }>"↷"</button>
            <button type="button" class="icon-button" data-testid="ladder-write" disabled=move || ctx.drawing.listing.with(Option::is_none)
                title=move || t().write_plc aria-label=move || t().write_plc
                on:click=move |_| {
                    // The same action as Run, said where the user looks.
                    if run_drawing() {
                        ctx.panes.message.set(Some(t().written.to_string()));
                    }
                }><span aria-hidden="true">"⇩"</span><span class="wide-only" aria-hidden="true">{move || t().write_plc}</span></button>
            <button type="button" class="icon-button" data-testid="tests-open" title=move || t().tests
                aria-label=move || t().tests
                on:click=move |_| ctx.page.docks.toggle(crate::docks::Tool::Tests)>
                <span aria-hidden="true">"✓"</span><span class="wide-only" aria-hidden="true">{move || t().tests}</span>
            </button>
            <live::RunStatus ctx />
            <zoom::ZoomBar ctx grid />
        </div>
    }
}

/// Copies the whole ladder to another machine's editor and shows it there.
#[component]
pub fn CopyTo(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let ladders = use_context::<Ladders>();
    let others: Vec<MachineId> = MachineId::ALL
        .into_iter()
        .filter(|m| *m != ctx.machine)
        .collect();
    view! {
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
