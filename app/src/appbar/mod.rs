//! The app bar (issue #45, docs/app.md "The workbench"): the project's
//! name, the menus (File, Edit, View, Help; one button on a phone), the
//! machine, the one run control with Pause and the steps, the speed, the
//! machine's clock, and Share. Everything acts on the machine shown.

pub mod clock;
pub mod menu;
pub mod run;

use leptos::prelude::*;

use crate::editor::LadderCtx;
use crate::examples;
use crate::i18n::Lang;
use crate::machines::minasec;
use crate::state::{product_name, Ctx, MachineKind};
use crate::storage;
use crate::workspaces::Workspaces;
use menu::{label, Menu};

/// The app bar.
#[component]
pub fn AppBar() -> impl IntoView {
    let ctx = Ctx::get();
    let workspaces = expect_context::<Workspaces>();
    let t = move || ctx.lang.get().texts();
    let ladder = move || workspaces.ladders.of(ctx.machine.get());
    let menus_open = RwSignal::new(false);
    // On a phone the menus are behind one button: a press outside them or
    // on a button inside closes them, as a menu chosen from does.
    let menus = NodeRef::<leptos::html::Nav>::new();
    let toggle = NodeRef::<leptos::html::Button>::new();
    let outside = window_event_listener(leptos::ev::pointerdown, move |e| {
        if !menus_open.get_untracked() {
            return;
        }
        let target = e.target().and_then(|t| {
            use leptos::wasm_bindgen::JsCast;
            t.dyn_into::<web_sys::Node>().ok()
        });
        let within = |node: Option<web_sys::HtmlElement>| {
            node.zip(target.as_ref())
                .is_some_and(|(n, t)| n.contains(Some(t)))
        };
        let in_menus = within(menus.get_untracked());
        let on_toggle = within(toggle.get_untracked().map(Into::into));
        if !in_menus && !on_toggle {
            menus_open.set(false);
        }
    });
    on_cleanup(move || outside.remove());
    view! {
        <header class="top app-bar">
            <h1 class="brand">
                {move || t().brand}
                <span class="project-name" data-testid="app-project">{move || project_name(ladder())}</span>
            </h1>
            <button type="button" class="menus-toggle" data-testid="menus" node_ref=toggle aria-expanded=move || menus_open.get().to_string()
                aria-controls="menus" aria-label=move || t().menus title=move || t().menus
                on:click=move |_| menus_open.update(|o| *o = !*o)>"☰"</button>
            <nav class="menus" id="menus" node_ref=menus data-open=move || menus_open.get().to_string() aria-label=move || t().menus
                on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" { menus_open.set(false); }
                on:change=move |_| menus_open.set(false)
                on:click=move |e: web_sys::MouseEvent| {
                    // A choice in a menu's panel closes the phone's menus.
                    use leptos::wasm_bindgen::JsCast;
                    let chosen = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
                        .and_then(|el| el.closest(".menu-panel button").ok().flatten())
                        .is_some();
                    if chosen {
                        menus_open.set(false);
                    }
                }>
                <Menu id="file" label=label(|t| t.menu_file)>
                    {move || crate::parts::part_for("menu-file-part", ctx.lang.into(), ladder(), file_menu)}
                </Menu>
                <Menu id="edit" label=label(|t| t.menu_edit)>
                    {move || crate::parts::part_for("menu-edit-part", ctx.lang.into(), ladder(), edit_menu)}
                </Menu>
                <Menu id="view" label=label(|t| t.menu_view)>
                    {move || crate::parts::part_for("menu-view-part", ctx.lang.into(), ladder(), view_menu)}
                </Menu>
                <Menu id="help" label=label(|t| t.menu_help)>
                    {move || crate::parts::part_for("menu-help-part", ctx.lang.into(), ladder(), help_menu)}
                </Menu>
            </nav>
            <MachineSelect />
            {move || view! { <run::RunControls ctx=ladder() /> }}
            <run::SpeedSelect />
            {move || view! { <clock::SimClock ctx=ladder() /> }}
            <minasec::header::ExampleUndo />
            <span class="share-slot">{move || view! { <crate::editor::shared::ShareButton ctx=ladder() /> }}</span>
        </header>
    }
}

/// The project open on the machine shown, or the machine's own ladder.
fn project_name(ladder: LadderCtx) -> String {
    let t = ladder.page.lang.get().texts();
    let id = ladder.work.project.get();
    let projects = use_context::<crate::editor::projects::Projects>();
    id.and_then(|id| {
        projects?.index.with(|i| {
            i.projects
                .iter()
                .find(|p| p.id == id)
                .map(|p| p.name.clone())
        })
    })
    .or_else(|| {
        let ja = ladder.page.lang.get() == crate::i18n::Lang::Ja;
        ladder
            .work
            .title
            .get()
            .map(|(en, j)| if ja { j } else { en })
    })
    .unwrap_or_else(|| t.project_untitled.to_string())
}

/// File: projects, open and import, save and export, pictures, print, the
/// machine's examples, and copying the ladder to another machine.
#[component]
fn FileMenu(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let machine = ctx.machine;
    view! {
        <button type="button" data-testid="menu-new" on:click=move |_| ctx.new_ladder()>
            {move || t().new_ladder}
        </button>
        <button type="button" data-testid="projects-open" on:click=move |_| ctx.panes.toggle(ctx.panes.projects_open)>
            {move || t().projects}
        </button>
        <crate::editor::files::FileButtons ctx />
        <ExampleSelect machine />
        <crate::editor::CopyTo ctx />
    }
}

/// Edit: undo and redo, find, the clipboard, the rung and device comments.
#[component]
fn EditMenu(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    view! {
        <button type="button" data-testid="menu-undo" disabled=move || !ctx.drawing.can_undo.get()
            on:click=move |_| ctx.undo()>{move || format!("{} (Ctrl+Z)", t().undo)}</button>
        <button type="button" data-testid="menu-redo" disabled=move || !ctx.drawing.can_redo.get()
            on:click=move |_| ctx.redo()>{move || format!("{} (Ctrl+Y)", t().redo)}</button>
        <button type="button" data-testid="find-open" on:click=move |_| ctx.panes.toggle(ctx.panes.find_open)>
            {move || format!("{} (Ctrl+F)", t().find)}
        </button>
        <button type="button" data-testid="menu-copy" on:click=move |_| crate::editor::clipboard::copy(ctx)>
            {move || format!("{} (Ctrl+C)", t().copy)}
        </button>
        <button type="button" data-testid="menu-cut" on:click=move |_| crate::editor::clipboard::cut(ctx)>
            {move || format!("{} (Ctrl+X)", t().cut)}
        </button>
        <button type="button" data-testid="menu-paste" on:click=move |_| crate::editor::clipboard::paste(ctx)>
            {move || format!("{} (Ctrl+V)", t().paste)}
        </button>
    }
}

/// View: the ladder's zoom, the docks, and the language.
#[component]
fn ViewMenu(ctx: LadderCtx) -> impl IntoView {
    let ladder = ctx;
    let ctx = ladder.page;
    let docks = ctx.docks;
    let t = move || ctx.lang.get().texts();
    view! {
        <button type="button" data-testid="view-zoom-in"
            on:click=move |_| crate::editor::zoom::step(ladder, true)>{move || format!("{} ({})", t().zoom_in, ctx.lang.get().keys().ctrl_wheel)}</button>
        <button type="button" data-testid="view-zoom-out"
            on:click=move |_| crate::editor::zoom::step(ladder, false)>{move || t().zoom_out}</button>
        <button type="button" data-testid="view-zoom-100"
            on:click=move |_| ladder.panes.zoom.set(1.0)>"100 %"</button>
        <button type="button" data-testid="view-panel-dock" aria-pressed=move || docks.sizes.with(|s| s.right_open).to_string()
            on:click=move |_| docks.resize(|s| s.right_open = !s.right_open)>{move || t().panel_dock}</button>
        <button type="button" data-testid="view-tools-dock" aria-pressed=move || docks.sizes.with(|s| s.bottom_open).to_string()
            on:click=move |_| docks.resize(|s| s.bottom_open = !s.bottom_open)>{move || t().tools_dock}</button>
        <button type="button" data-testid="view-reset-docks"
            on:click=move |_| docks.resize(|s| *s = crate::docks::Sizes::default())>{move || t().reset_docks}</button>
        <ColouringToggle />
        <LangSelect />
    }
}

/// The old colouring of contacts, by device value (issue #46): a
/// toggle, remembered.
#[component]
fn ColouringToggle() -> impl IntoView {
    use crate::editor::conduct::{Colouring, COLOURING_KEY};
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let by_value = move || ctx.colouring.get() == Colouring::ByValue;
    let toggle = move |_| {
        let next = if by_value() {
            Colouring::ByConduction
        } else {
            Colouring::ByValue
        };
        ctx.colouring.set(next);
        storage::save_string(COLOURING_KEY, next.code());
    };
    view! {
        <button type="button" data-testid="view-colour-by-value" aria-pressed=move || by_value().to_string()
            title=move || t().colour_by_value_hint on:click=toggle>{move || t().colour_by_value}</button>
    }
}

/// Help: the guide, the start screen, the guided first rung, the keys.
#[component]
fn HelpMenu(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let s = move || ctx.page.lang.get().start();
    let start = crate::start::Start::get();
    view! {
        <button type="button" data-testid="help-guide" on:click=move |_| start.open_guide("")>
            {move || s().guide}
        </button>
        <button type="button" data-testid="help-start" on:click=move |_| start.open.set(true)>
            {move || s().start_again}
        </button>
        <button type="button" data-testid="help-tour" on:click=move |_| {
            start.tour.set(Some(crate::start::steps::Step::Intro));
        }>
            {move || s().tour_label}
        </button>
        <button type="button" data-testid="keys" on:click=move |_| ctx.panes.help.update(|h| *h = !*h)>
            {move || t().keys}
        </button>
    }
}

/// Which machine the page shows (remembered).
#[component]
fn MachineSelect() -> impl IntoView {
    let ctx = Ctx::get();
    view! {
        <label class="machine-select">
            <span class="label-text">{move || ctx.lang.get().texts().machine}</span>
            <select
                data-testid="machine"
                prop:value=move || ctx.machine.get().name()
                on:change=move |e| {
                    if let Ok(kind) = MachineKind::parse(&event_target_value(&e)) {
                        ctx.machine.set(kind);
                        storage::save_string(storage::MACHINE_KEY, kind.name());
                    }
                }
            >
                {MachineKind::ALL
                    .iter()
                    .map(|&kind| view! { <option value=kind.name()>{product_name(kind)}</option> })
                    .collect_view()}
            </select>
        </label>
    }
}

/// The interface language (remembered).
#[component]
fn LangSelect() -> impl IntoView {
    let ctx = Ctx::get();
    view! {
        <label>
            {move || ctx.lang.get().texts().language}
            <select
                data-testid="lang"
                prop:value=move || ctx.lang.get().code()
                on:change=move |e| {
                    if let Some(lang) = Lang::from_code(&event_target_value(&e)) {
                        ctx.lang.set(lang);
                        storage::save_lang(lang.code());
                        set_document_lang(lang);
                    }
                }
            >
                <option value="ja">"日本語"</option>
                <option value="en">"English"</option>
            </select>
        </label>
    }
}

/// The machine's examples: each opens as a ladder (one undo brings the
/// old ladder back); MINASEC-U's also replaces the text (undoable).
#[component]
fn ExampleSelect(machine: MachineKind) -> impl IntoView {
    let ctx = Ctx::get();
    let workspaces = expect_context::<Workspaces>();
    let t = move || ctx.lang.get().texts();
    let options = engine::examples::examples_of(machine)
        .map(|e| {
            view! {
                <option value=e.id>
                    {move || if ctx.lang.get() == Lang::Ja { e.title_ja } else { e.title_en }}
                </option>
            }
        })
        .collect_view();
    view! {
        <label>
            {move || t().example}
            <select
                data-testid="example"
                prop:value=""
                on:change=move |e| {
                    let id = event_target_value(&e);
                    examples::open(machine, &id, workspaces);
                    // Back to the prompt, so the same example can be opened again.
                    use leptos::wasm_bindgen::JsCast;
                    if let Some(select) = e
                        .target()
                        .and_then(|t| t.dyn_into::<web_sys::HtmlSelectElement>().ok())
                    {
                        select.set_value("");
                    }
                }
            >
                <option value="">{move || t().example_none}</option>
                {options}
            </select>
        </label>
    }
}

/// Sets `<html lang>` so screen readers and fonts follow the interface.
pub fn set_document_lang(lang: Lang) {
    if let Some(root) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.document_element())
    {
        let _ = root.set_attribute("lang", lang.code());
    }
}

crate::parts::part_fn!(
    menus,
    /// The File menu's controls, a part with the other menus' (issue
    /// #53): fetched when a menu first opens.
    fn file_menu() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <FileMenu ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    menus,
    /// The Edit menu's controls (part `menus`).
    fn edit_menu() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <EditMenu ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    menus,
    /// The View menu's controls (part `menus`).
    fn view_menu() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <ViewMenu ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    menus,
    /// The Help menu's controls (part `menus`).
    fn help_menu() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <HelpMenu ctx /> }.into_any())
    }
);
