//! The docks as drawn: the tools dock's tabs and panels, the panel dock,
//! and the splitters that resize them (by pointer or by arrow keys).

use leptos::prelude::*;

use crate::docks::{Docks, Tool};
use crate::state::Ctx;

/// The tools dock: a tab per tool this machine has, one panel shown.
/// Every panel stays mounted (hidden when not shown), so a tool keeps its
/// state and what it shows is up to date when its tab is chosen.
#[component]
pub fn BottomDock(machine: engine::MachineId, panels: Vec<(Tool, AnyView)>) -> impl IntoView {
    let ctx = Ctx::get();
    let docks = ctx.docks;
    let t = move || ctx.lang.get().texts();
    let open = move || docks.sizes.with(|s| s.bottom_open);
    let tools: Vec<Tool> = panels.iter().map(|(tool, _)| *tool).collect();
    let tabs = tools
        .into_iter()
        .chain(std::iter::once(Tool::Panel))
        .filter(|tool| tool.on(machine))
        .map(|tool| {
            let shown = move || docks.tool.get() == tool;
            view! {
                <button type="button" role="tab" class="dock-tab"
                    class:phone-only=tool == Tool::Panel
                    data-testid=format!("dock-tab-{}", tool.hook())
                    id=format!("dock-tab-{}", tool.hook())
                    aria-controls=format!("dock-panel-{}", tool.hook())
                    aria-selected=move || (shown() && open()).to_string()
                    on:click=move |_| docks.toggle(tool)>
                    {move || tool_name(tool, ctx.lang.get())}
                </button>
            }
        })
        .collect_view();
    let panels = panels
        .into_iter()
        .map(|(tool, body)| {
            view! {
                <div class="dock-panel" role="tabpanel" data-dock-panel=tool.hook()
                    id=format!("dock-panel-{}", tool.hook())
                    aria-labelledby=format!("dock-tab-{}", tool.hook())
                    hidden=move || docks.tool.get() != tool>
                    {body}
                </div>
            }
        })
        .collect_view();
    follow_the_tab_shown(docks);
    let body = NodeRef::<leptos::html::Div>::new();
    let remember_scroll = keep_each_tabs_scroll(docks, body);
    view! {
        <section class="dock dock-bottom" data-testid="dock-bottom"
            data-open=move || open().to_string()
            data-sheet=move || docks.sheet.get().to_string()
            data-tool=move || docks.tool.get().hook()
            aria-label=move || t().tools_dock>
            <div class="dock-tabs-row">
                <div class="dock-tabs" role="tablist" aria-label=move || t().tools_dock>
                    {tabs}
                </div>
                <crate::start::guide::GuideLink section=Signal::derive(move || {
                    crate::start::guide::section_of(docks.tool.get(), machine)
                }) />
                <button type="button" class="dock-collapse" data-testid="dock-bottom-toggle"
                        aria-expanded=move || open().to_string()
                        title=move || if open() { t().dock_collapse } else { t().dock_expand }
                        aria-label=move || if open() { t().dock_collapse } else { t().dock_expand }
                        on:click=move |_| {
                            let now = !docks.sizes.with_untracked(|s| s.bottom_open);
                            docks.sheet.set(now);
                            docks.resize(|s| s.bottom_open = now);
                        }>
                        {move || if open() { "▾" } else { "▴" }}
                    </button>
            </div>
            <div class="dock-body" node_ref=body on:scroll=move |_| remember_scroll()>{panels}</div>
        </section>
    }
}

/// Each tab's panel keeps its own scroll, as a browser's tabs do: one
/// body holds every panel, so what one was scrolled to showed in the next
/// (the Plant tab opened scrolled past its drawing after a long Tests
/// pane). Returns what the body calls when it scrolls.
fn keep_each_tabs_scroll(docks: Docks, body: NodeRef<leptos::html::Div>) -> impl Fn() + Copy {
    let kept = StoredValue::new(Vec::<(Tool, i32)>::new());
    // Created after the panels' `hidden` (their render effects run
    // first), so the panel is shown when its scroll is put back; at once,
    // not a frame later, where it would undo a scroll made meanwhile (a
    // control scrolled into view as soon as its tab shows).
    Effect::new(move |_| {
        let tool = docks.tool.get();
        let top = kept.with_value(|k| k.iter().find(|(t, _)| *t == tool).map_or(0, |(_, y)| *y));
        if let Some(Some(body)) = body.try_get_untracked() {
            body.set_scroll_top(top);
        }
    });
    move || {
        if let Some(Some(body)) = body.try_get_untracked() {
            let tool = docks.tool.get_untracked();
            let top = body.scroll_top();
            kept.update_value(|k| {
                k.retain(|(t, _)| *t != tool);
                k.push((tool, top));
            });
        }
    }
}

/// Scrolls the tab strip (not the page) so that `tool`'s tab is whole.
fn show_tab(tool: Tool) {
    let doc = document();
    let Some(tab) = doc.get_element_by_id(&format!("dock-tab-{}", tool.hook())) else {
        return;
    };
    let Some(strip) = tab.parent_element() else {
        return;
    };
    let (t, s) = (
        tab.get_bounding_client_rect(),
        strip.get_bounding_client_rect(),
    );
    let by = if t.right() > s.right() {
        t.right() - s.right()
    } else if t.left() < s.left() {
        t.left() - s.left()
    } else {
        return;
    };
    strip.set_scroll_left(strip.scroll_left() + by.round() as i32);
}

/// The tab shown is brought into its strip's view (on a phone the strip
/// scrolls sideways and cut "Tests" under the "?"), and the phone's
/// sheet leaves the ladder and its strip above it.
fn follow_the_tab_shown(docks: Docks) {
    Effect::new(move |_| {
        let tool = docks.tool.get();
        let up = docks.sheet.get() && docks.sizes.with(|s| s.bottom_open);
        // Again when a pane's part arrives: the sheet has its height then.
        docks.arrived.track();
        request_animation_frame(move || {
            show_tab(tool);
            if up && tool != Tool::Panel {
                ladder_above_sheet();
            }
        });
    });
}

/// On a phone, with a tool up in the bottom sheet: the page scrolls (as
/// little as it must, never past the ladder's top) so that the ladder and
/// the strip of its inputs end above the sheet (docs/app.md, "Every
/// screen").
fn ladder_above_sheet() {
    let doc = document();
    let rect = |selector: &str| {
        doc.query_selector(selector)
            .ok()
            .flatten()
            .map(|e| e.get_bounding_client_rect())
    };
    let (Some(ladder), Some(sheet)) = (
        rect("[data-testid=ladder]"),
        rect(".dock-bottom[data-sheet=true] .dock-body"),
    ) else {
        return;
    };
    // Only where the sheet lies over the page (a phone): elsewhere the
    // dock is in the page's flow, under the ladder.
    let over = doc
        .query_selector(".dock-bottom")
        .ok()
        .flatten()
        .and_then(|d| window().get_computed_style(&d).ok().flatten())
        .and_then(|s| s.get_property_value("position").ok())
        .is_some_and(|p| p == "fixed");
    if !over || sheet.height() <= 0.0 || ladder.bottom() <= sheet.top() {
        return;
    }
    let strip = rect("[data-testid=io-strip]").map_or(0.0, |s| s.height());
    let by = (ladder.bottom() + strip - sheet.top()).min(ladder.top());
    if by > 0.0 {
        window().scroll_by_with_x_and_y(0.0, by);
    }
}

/// A tool's name on its tab.
pub fn tool_name(tool: Tool, lang: crate::i18n::Lang) -> &'static str {
    let t = lang.texts();
    match tool {
        Tool::Watch => t.watch,
        Tool::Chart => t.chart,
        Tool::Tests => t.tests,
        Tool::Why => t.why_tab,
        Tool::Listing => t.listing_problems,
        Tool::Comments => t.comments_tab,
        Tool::Variables => t.variables,
        Tool::Program => t.program_tab,
        Tool::Cpu => t.cpu_tab,
        Tool::Plant => lang.plant().tab,
        Tool::Panel => t.panel_tab,
    }
}

/// The panel dock: the machine's board, lamps and switches. On a phone it
/// is the sheet's Panel tab.
#[component]
pub fn RightDock(children: Children) -> impl IntoView {
    let ctx = Ctx::get();
    let docks = ctx.docks;
    let t = move || ctx.lang.get().texts();
    let open = move || docks.sizes.with(|s| s.right_open);
    view! {
        <aside class="dock dock-right machine-side" id="panel" tabindex="-1" data-testid="dock-right"
            data-open=move || open().to_string()
            data-sheet=move || (docks.sheet.get() && docks.tool.get() == Tool::Panel).to_string()
            aria-label=move || t().panel_dock>
            <button type="button" class="dock-collapse dock-right-toggle" data-testid="dock-right-toggle"
                aria-expanded=move || open().to_string()
                title=move || if open() { t().dock_collapse } else { t().dock_expand }
                aria-label=move || if open() { t().dock_collapse } else { t().dock_expand }
                on:click=move |_| docks.resize(|s| s.right_open = !s.right_open)>
                {move || if open() { "▸" } else { "◂" }}
            </button>
            <crate::start::guide::GuideLink section=Signal::derive(move || ctx.machine.get().name()) />
            <div class="dock-right-body">{children()}</div>
        </aside>
    }
}

/// Which way a splitter moves.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Split {
    /// Between the centre and the panel dock: moves sideways.
    Right,
    /// Between the ladder and the tools dock: moves up and down.
    Bottom,
}

/// A splitter: drag it, or focus it and use the arrow keys (16 px a
/// press, 64 with Shift). The size is remembered when the drag ends.
#[component]
pub fn Splitter(split: Split) -> impl IntoView {
    let ctx = Ctx::get();
    let docks: Docks = ctx.docks;
    let t = move || ctx.lang.get().texts();
    let dragging = StoredValue::new(None::<(f64, f64)>);
    let value = move || {
        docks.sizes.with(|s| match split {
            Split::Right => s.right_px,
            Split::Bottom => s.bottom_px,
        })
    };
    // A drag toward the dock makes it smaller: the dock is right of and
    // below its splitter.
    let set = move |px: f64| {
        docks.sizes.update(|s| match split {
            Split::Right => s.right_px = px.max(crate::docks::sizes::MIN_RIGHT_PX),
            Split::Bottom => s.bottom_px = px.max(crate::docks::sizes::MIN_BOTTOM_PX),
        })
    };
    let along = move |e: &web_sys::PointerEvent| match split {
        Split::Right => f64::from(e.client_x()),
        Split::Bottom => f64::from(e.client_y()),
    };
    view! {
        <div class="splitter" class:splitter-right=split == Split::Right class:splitter-bottom=split == Split::Bottom
            role="separator" tabindex="0"
            data-testid=match split { Split::Right => "splitter-right", Split::Bottom => "splitter-bottom" }
            aria-orientation=match split { Split::Right => "vertical", Split::Bottom => "horizontal" }
            aria-label=move || t().resize_dock
            aria-valuenow=move || format!("{:.0}", value())
            on:pointerdown=move |e: web_sys::PointerEvent| {
                if let Some(target) = e.target() {
                    use leptos::wasm_bindgen::JsCast;
                    if let Ok(el) = target.dyn_into::<web_sys::Element>() {
                        let _ = el.set_pointer_capture(e.pointer_id());
                    }
                }
                dragging.set_value(Some((along(&e), value())));
            }
            on:pointermove=move |e: web_sys::PointerEvent| {
                if let Some((start, size)) = dragging.get_value() {
                    set(size - (along(&e) - start));
                }
            }
            on:pointerup=move |_| {
                if dragging.get_value().is_some() {
                    dragging.set_value(None);
                    docks.save();
                }
            }
            on:keydown=move |e: web_sys::KeyboardEvent| {
                let step = if e.shift_key() { 64.0 } else { 16.0 };
                let delta = match (split, e.key().as_str()) {
                    (Split::Right, "ArrowLeft") | (Split::Bottom, "ArrowUp") => step,
                    (Split::Right, "ArrowRight") | (Split::Bottom, "ArrowDown") => -step,
                    _ => return,
                };
                e.prevent_default();
                set(value() + delta);
                docks.save();
            }
        ></div>
    }
}
