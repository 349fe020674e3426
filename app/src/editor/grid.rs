//! The ladder grid: one component per rung (keyed by the rung's id) and
//! one per cell (keyed by what it draws), so an edit redraws only the
//! cells it changed. Keys go to [`LadderCtx::key`]; clicks put the
//! cursor; palette items dropped on a cell act there.

use engine::ladder::edit::Cursor;
use leptos::prelude::*;

use super::model::{cell_class, cell_words, live_words, within, CellData, RungData};
use super::state::{LadderCtx, RungView};
use super::{palette, zoom};
use crate::i18n::Lang;

/// The focusable grid, `[data-testid=ladder]`.
#[component]
pub fn LadderGrid(ctx: LadderCtx, grid: NodeRef<leptos::html::Div>) -> impl IntoView {
    let cursor = ctx.drawing.cursor;
    let selected = Selector::new(move || cursor.get());
    // The block being selected, unchanged (and so silent) while there is none.
    let block = Memo::new(move |_| ctx.drawing.anchor.get().map(|a| (a, cursor.get())));
    // Keep the cursor's cell in view.
    Effect::new(move |_| {
        let c = cursor.get();
        let Some(grid) = grid.get() else { return };
        let selector = format!("[data-testid=\"cell-{}-{}-{}\"]", c.rung, c.row, c.col);
        if let Ok(Some(cell)) = grid.query_selector(&selector) {
            let options = web_sys::ScrollIntoViewOptions::new();
            options.set_block(web_sys::ScrollLogicalPosition::Nearest);
            options.set_inline(web_sys::ScrollLogicalPosition::Nearest);
            cell.scroll_into_view_with_scroll_into_view_options(&options);
        }
    });
    let on_key = move |e: web_sys::KeyboardEvent| {
        if ctx.panes.entry.with_untracked(Option::is_some) {
            return;
        }
        let (ctrl, key) = (e.ctrl_key() || e.meta_key(), e.key());
        // Copy, cut and paste go on to the clipboard events.
        if ctrl && matches!(key.to_ascii_lowercase().as_str(), "c" | "x" | "v") {
            if key.eq_ignore_ascii_case("v") {
                schedule_fallback_paste(ctx);
            }
            return;
        }
        if ctx.key(&key, e.shift_key(), ctrl, e.alt_key()) {
            e.prevent_default();
        }
    };
    let touches = zoom::Touches::new();
    let selected_end = selected.clone();
    view! {
        <div
            class="ladder"
            id="ladder"
            node_ref=grid
            data-testid="ladder"
            role="grid"
            tabindex="0"
            aria-label=move || ctx.page.lang.get().texts().ladder
            aria-multiselectable="true"
            on:keydown=on_key
            on:wheel=move |e: web_sys::WheelEvent| zoom::on_wheel(ctx, &e)
            on:pointerdown=move |e: web_sys::PointerEvent| touches.pointer(ctx, &e, false)
            on:pointermove=move |e: web_sys::PointerEvent| touches.pointer(ctx, &e, true)
            on:pointerup=move |e: web_sys::PointerEvent| touches.up(&e)
            on:pointercancel=move |e: web_sys::PointerEvent| touches.up(&e)
        >
            <div class="ladder-content" style=move || format!("zoom: {}", ctx.panes.zoom.get())>
            <For
                each=move || ctx.drawing.rungs.get()
                key=|r: &RungView| r.id
                children=move |r: RungView| {
                    let selected = selected.clone();
                    view! { <RungRows ctx r selected block grid /> }
                }
            />
            <EndLine ctx selected=selected_end />
            </div>
        </div>
    }
}

/// Ctrl+V where the browser sends no paste event (nothing editable has
/// focus): this page's own clipboard is pasted instead, once.
fn schedule_fallback_paste(ctx: LadderCtx) {
    ctx.clip.pasted.set_value(false);
    set_timeout(
        move || {
            if !ctx.clip.pasted.get_value() {
                ctx.paste_text(None);
            }
        },
        std::time::Duration::ZERO,
    );
}

/// A palette item (or nothing) dropped on cell `at`.
fn dropped(ctx: LadderCtx, at: Cursor, e: web_sys::DragEvent) {
    e.prevent_default();
    let data = e
        .data_transfer()
        .and_then(|dt| dt.get_data("text/plain").ok())
        .unwrap_or_default();
    if let Some(id) = data.strip_prefix("palette:") {
        ctx.move_to(at);
        palette::activate(ctx, id);
    }
}

/// One rung: its number and first step, its comment, and its rows.
#[component]
fn RungRows(
    ctx: LadderCtx,
    r: RungView,
    selected: Selector<Cursor>,
    block: Memo<Option<(Cursor, Cursor)>>,
    grid: NodeRef<leptos::html::Div>,
) -> impl IntoView {
    let number = r.number.clone();
    let data = r.data.clone();
    let rows = {
        let data = data.clone();
        move || (0..data.with(|d| d.rows)).collect::<Vec<_>>()
    };
    let columns = {
        let data = data.clone();
        move || {
            let cols = data.with(|d| d.cols);
            ctx.drawing
                .col_widths
                .with(|w| super::columns::grid_columns(w, cols))
        }
    };
    let t = move || ctx.page.lang.get().texts();
    let (n1, n2, n3) = (number.clone(), number.clone(), number.clone());
    let first = r.first_step.clone();
    let first2 = r.first_step.clone();
    let view = r.clone();
    let (d1, d2, d3) = (data.clone(), data.clone(), data.clone());
    view! {
        <div class="rung" role="rowgroup" data-testid=move || format!("rung-{}", n1.get())
            data-first-step=move || first2.get().map(|s| s.to_string())>
            <div class="rung-head">
                <span class="rung-num">{move || format!("{} {}", t().rung, n2.get() + 1)}</span>
                <span class="rung-step">{move || first.get().map(|s| format!("{} {s}", t().step))}</span>
            </div>
            <Show when=move || d1.with(|d| !d.comment.is_empty())>
                <div class="rung-comment">{let d = d2.clone(); move || d.with(|d| d.comment.clone())}</div>
            </Show>
            <div class="rung-grid" style=columns>
                <For
                    each=rows
                    key=|row| *row
                    children=move |row| {
                        let selected = selected.clone();
                        let view = view.clone();
                        let data = d3.clone();
                        let number = n3.clone();
                        let cells = move || data.with(|d: &RungData| {
                            d.cells.iter().filter(|c| c.row == row).cloned().collect::<Vec<_>>()
                        });
                        view! {
                            <div class="rung-row" role="row">
                                <For
                                    each=cells
                                    key=|c: &CellData| c.clone()
                                    children=move |c| {
                                        let selected = selected.clone();
                                        let cell_slot = view.slot(c.row * c.cols + c.col);
                                        view! { <Cell ctx c number=number.clone() cell_slot selected block grid /> }
                                    }
                                />
                            </div>
                        }
                    }
                />
            </div>
            {let d = data.clone(); move || d.with(|d| d.errors.iter().map(|e| view! {
                <div class="rung-error" data-testid="rung-error">{e.clone()}</div>
            }).collect_view())}
        </div>
    }
}

/// One cell. Drawn once per content; only its place in the ladder (the
/// rung may move), its selection and its live slot are reactive.
#[component]
fn Cell(
    ctx: LadderCtx,
    c: CellData,
    number: ArcRwSignal<usize>,
    cell_slot: super::state::CellSlot,
    selected: Selector<Cursor>,
    block: Memo<Option<(Cursor, Cursor)>>,
    grid: NodeRef<leptos::html::Div>,
) -> impl IntoView {
    let (row, col) = (c.row, c.col);
    let label = label_of(ctx, &c, number.clone(), cell_slot.clone(), selected.clone());
    let here = move || Cursor::new(number.get(), row, col);
    let testid = {
        let here = here.clone();
        move || format!("cell-{}-{row}-{col}", here().rung)
    };
    let in_block = {
        let here = here.clone();
        move || block.with(|b| b.is_some_and(|(a, z)| within(a, z, here())))
    };
    let device = (!c.device.is_empty()).then(|| c.device.clone());
    let forced_here = forced(ctx, c.device.clone());
    let hover = hover_of(&c, &cell_slot);
    let whole = whole_of(&c, &cell_slot);
    let (on, power, pulse) = (
        cell_slot.on_attr(),
        cell_slot.power_attr(),
        cell_slot.pulse_attr(),
    );
    let lit = lit_of(ctx, c.kind, &cell_slot);
    let whole_left = opens_left(&c);
    let [h1, h2, h3, h4, h5] = [(); 5].map(|_| here.clone());
    let (kind, driven) = (c.kind, device.clone());
    view! {
        <div
            class=cell_class(&c)
            class:sel=in_block
            class:whole-left=whole_left
            role="gridcell"
            data-testid=testid
            data-kind=c.kind.hook()
            data-device=device
            // The live state is said once per cell, as data attributes
            // the style sheet reads (no class for the same): each is an
            // effect of its own, and a frame may change every cell.
            data-on=on
            data-conducts=cell_slot.conducts_attr()
            class:lit=lit
            data-powered=power
            data-pulsed=pulse
            data-rises=cell_slot.rises()
            data-error=c.error.clone()
            title=hover
            aria-selected=move || if selected.selected(&h1()) { "true" } else { "false" }
            aria-label=label
            style=format!("grid-row: {}; grid-column: {}", row + 1, col + 1)
            on:mousedown=move |e: web_sys::MouseEvent| pressed(ctx, h2(), &e, grid)
            on:click=move |e: web_sys::MouseEvent| clicked(ctx, kind, driven.as_deref(), e.shift_key())
            class:stepped=move || ctx.live.stepped_cell.with(|s| *s == Some(h3()))
            class:forced=forced_here.clone()
            data-forced=move || forced_here().then_some("1")
            on:dblclick=move |_| {
                ctx.move_to(h4());
                ctx.dispatch(super::keys::Action::EditCell);
            }
            on:dragover=|e: web_sys::DragEvent| e.prevent_default()
            on:drop=move |e: web_sys::DragEvent| dropped(ctx, h5(), e)
        >
            <span class="dev">{c.device.clone()}</span>
            <span class="sym">{c.symbol.clone()}</span>
            <span class="cmt">{c.comment.clone()}</span>
            <span class="val" data-value=cell_slot.value_attr()>{cell_slot.value_attr()}</span>
            <span class="words" data-testid="box-values">{cell_slot.words_attr()}</span>
            {whole.map(|w| view! { <span class="whole" data-testid="box-whole" aria-hidden="true">{w}</span> })}
            // "Why": the cell asked about and the cells that decide it
            // (a child: the cell already carries tachys's most attributes).
            <span class="why" data-why=move || ctx.why.shown.with(|w| w.as_ref().and_then(|w| w.role_at(&here())))></span>
        </div>
    }
}

/// A cell's accessible name: its place, what it is, its live state, in
/// the page's language. While the machine runs, the live state is said
/// for the cell under the cursor only; every cell says it again once
/// paused or stopped. A name is read when the cursor comes to it, not 60
/// times a second, and rewriting each changed cell's name every frame
/// cost about 1 ms of the frame (issue #52, docs/performance.md).
fn label_of(
    ctx: LadderCtx,
    c: &CellData,
    number: ArcRwSignal<usize>,
    slot: super::state::CellSlot,
    selected: Selector<Cursor>,
) -> impl Fn() -> String + Send + Sync + 'static {
    let (row, col) = (c.row + 1, c.col + 1);
    let at_cursor = {
        let (number, (row, col)) = (number.clone(), (c.row, c.col));
        move || selected.selected(&Cursor::new(number.get(), row, col))
    };
    // Both languages' words once: the name is said again at each change of
    // the cell's live state.
    let (en, ja) = (cell_words(c, Lang::En), cell_words(c, Lang::Ja));
    // The language through a memo of this cell's own: the label is said
    // again at each live change, and an effect that re-runs leaves each
    // of its sources' subscriber lists (an ordered set: linear in its
    // length). The page's language has one subscriber per cell and more,
    // so a ladder whose every cell changed each frame spent most of the
    // frame there (200 rungs running with a plant: 100 ms frames).
    // A `Memo<bool>`, not a `Memo<Lang>`: each memo type is code of its
    // own in the first screen's wasm. Whether the machine runs, likewise.
    let in_ja = Memo::new(move |_| ctx.page.lang.get() == Lang::Ja);
    let still = Memo::new(move |_| !ctx.live.running.get() || ctx.page.paused.get());
    move || {
        let lang = if in_ja.get() { Lang::Ja } else { Lang::En };
        let words = if lang == Lang::Ja { &ja } else { &en };
        let mut state = String::new();
        if still.get() || at_cursor() {
            state = live_words(slot.on.get(), slot.powered.get(), lang);
            state.push_str(super::conduct::conduct_words(slot.conducts.get(), lang));
            if let Some(values) = slot.words.get() {
                state.push_str(", ");
                state.push_str(&values);
            }
        }
        let rung = number.get() + 1;
        match lang {
            Lang::En => format!("rung {rung}, row {row}, column {col}: {words}{state}"),
            Lang::Ja => format!("回路{rung} {row}行 {col}列: {words}{state}"),
        }
    }
}

/// Whether a cell is drawn lit, in the colouring chosen
/// ([`super::conduct::lit`]).
fn lit_of(
    ctx: LadderCtx,
    kind: super::model::CellKind,
    slot: &super::state::CellSlot,
) -> impl Fn() -> bool + Send + Sync + 'static {
    let (on, conducts) = (slot.on.clone(), slot.conducts.clone());
    // Through a memo of the cell's own, as the label's language.
    use super::conduct::Colouring;
    let by_value = Memo::new(move |_| ctx.page.colouring.get() == Colouring::ByValue);
    move || {
        let colouring = match by_value.get() {
            true => Colouring::ByValue,
            false => Colouring::ByConduction,
        };
        super::conduct::lit(kind, on.get(), conducts.get(), colouring)
    }
}

/// A box in its rung's right half shows its whole text leftwards.
fn opens_left(c: &CellData) -> bool {
    c.kind == super::model::CellKind::Box && c.col * 2 >= c.cols
}

/// Whether `device` is held from the ladder.
fn forced(ctx: LadderCtx, device: String) -> impl Fn() -> bool + Clone + Send + Sync + 'static {
    move || {
        !device.is_empty()
            && ctx
                .live
                .forced
                .with(|f| f.iter().any(|(d, _)| *d == device))
    }
}

/// A cell's tooltip: its error, else a box's whole text, else how often
/// its device rose since the last frame (a pulse too short to see).
fn hover_of(
    c: &CellData,
    slot: &super::state::CellSlot,
) -> impl Fn() -> Option<String> + Send + Sync + 'static {
    let (error, rises) = (c.error.clone(), slot.rises());
    let whole = whole_of(c, slot);
    move || {
        error
            .clone()
            .or_else(|| whole.as_ref().map(|w| w()))
            .or_else(|| rises().map(|n| format!("{n} ↑")))
    }
}

/// A box's whole text with its live values (`None` for anything else):
/// shown under the cell on hover, when the cursor is on it (focus, a tap
/// or a long press on touch), and as its tooltip.
fn whole_of(
    c: &CellData,
    slot: &super::state::CellSlot,
) -> Option<impl Fn() -> String + Clone + Send + Sync + 'static> {
    super::cell_kind::whole_text(c.kind, &c.words, None)?;
    let (kind, words, values) = (c.kind, c.words.clone(), slot.words.clone());
    Some(move || {
        values
            .with(|v| super::cell_kind::whole_text(kind, &words, v.as_deref()))
            .unwrap_or_default()
    })
}

/// A press on a cell: the cursor there (Shift: the selection grows to
/// it), and the focus on the grid.
fn pressed(ctx: LadderCtx, at: Cursor, e: &web_sys::MouseEvent, grid: NodeRef<leptos::html::Div>) {
    e.prevent_default();
    if e.shift_key() {
        ctx.extend_to(at);
    } else {
        ctx.move_to(at);
    }
    focus_in_place(grid);
}

/// A click on a cell: while the machine runs the drawn ladder, a contact
/// drives its input (Shift: for one scan).
fn clicked(ctx: LadderCtx, kind: super::model::CellKind, device: Option<&str>, pulse: bool) {
    if ctx.live.monitor.get_untracked() && kind.look().contact {
        if let Some(d) = device {
            super::live::drive_from_ladder(ctx, d, pulse);
        }
    }
}

/// The end line: the row after the last rung, where a new rung starts.
#[component]
fn EndLine(ctx: LadderCtx, selected: Selector<Cursor>) -> impl IntoView {
    let end_cells = move || (0..=ctx.drawing.out_col.get()).collect::<Vec<_>>();
    view! {
    <div class="rung end" role="rowgroup" data-testid="end-line">
        <div class="rung-head">
            <span class="rung-num">{move || ctx.page.lang.get().texts().end}</span>
        </div>
        <div
            class="rung-grid"
            role="row"
            style=move || ctx.drawing.col_widths.with(|w| super::columns::grid_columns(w, ctx.drawing.out_col.get() + 1))
        >
            <For
                each=end_cells
                key=|c| *c
                children=move |col| {
                    let selected = selected.clone();
                    let here = move || Cursor::new(ctx.drawing.rungs.with(Vec::len), 0, col);
                    view! {
                        <div
                            class="cell"
                            role="gridcell"
                            data-testid=move || format!("cell-{}-0-{col}", ctx.drawing.rungs.with(Vec::len))
                            data-kind=""
                            aria-selected=move || if selected.selected(&here()) { "true" } else { "false" }
                            aria-label=move || format!("{} {}", ctx.page.lang.get().texts().end_of_ladder, col + 1)
                            on:mousedown=move |_| ctx.move_to(here())
                            on:dragover=|e: web_sys::DragEvent| e.prevent_default()
                            on:drop=move |e: web_sys::DragEvent| dropped(ctx, here(), e)
                        ></div>
                    }
                }
            />
        </div>
    </div>
    }
}

/// Gives the grid the keyboard focus back.
pub fn focus(grid: NodeRef<leptos::html::Div>) {
    if let Some(g) = grid.get_untracked() {
        let _ = g.focus();
    }
}

/// Gives the grid the focus without scrolling the page: a press on a cell
/// must not move the cell away from under the pointer before its click.
fn focus_in_place(grid: NodeRef<leptos::html::Div>) {
    if let Some(g) = grid.get_untracked() {
        let options = web_sys::FocusOptions::new();
        options.set_prevent_scroll(true);
        let _ = g.focus_with_options(&options);
    }
}
