//! Ctrl+F: find a device or comment text, batch-replace devices with a
//! preview (`X00`→`X03`, `M00-M07`→`M20-M27`), and the cross-reference
//! list of a device with its rungs and steps. Every result is one click
//! from its cell.

use engine::ladder::edit::{find, replace_plan, xref, Cursor, Edit, UseRole};
use leptos::prelude::*;

use crate::editor::state::LadderCtx;

/// Tracks every change of the ladder (the listing and problems both
/// change with it; the rung list covers rung moves).
fn track_ladder(ctx: LadderCtx) {
    ctx.drawing.rungs.track();
    ctx.drawing.problems.track();
    ctx.drawing.listing.track();
}

/// The find pane.
#[component]
pub fn FindPane(ctx: LadderCtx, on_pick: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let query = RwSignal::new(String::new());
    let pick = Callback::new(move |c: Cursor| {
        ctx.move_to(c);
        on_pick.run(());
    });
    let close = move || {
        ctx.panes.find_open.set(false);
        on_pick.run(());
    };
    view! {
        <section class="find-pane" aria-label=move || t().find>
            <div class="find-row">
                <label>
                    {move || t().find}
                    <input
                        data-testid="find"
                        spellcheck="false"
                        prop:value=move || query.get()
                        on:input=move |e| query.set(event_target_value(&e))
                        on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" { close() }
                    />
                </label>
                <button type="button" on:click=move |_| close()>{move || t().close}</button>
            </div>
            <FoundList ctx query pick />
            <h4>{move || t().xref}</h4>
            <XrefTable ctx query pick />
            <h4>{move || t().replace}</h4>
            <ReplaceBox ctx />
        </section>
    }
}

/// Where the text searched for is found: each a button to its cell.
#[component]
fn FoundList(ctx: LadderCtx, query: RwSignal<String>, pick: Callback<Cursor>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let found = move || {
        track_ladder(ctx);
        let q = query.get();
        ctx.with_editor(|e| find(e.ladder(), &q))
    };
    view! {
        <ul class="found" data-testid="found">
            {move || found().into_iter().map(|f| {
                let at = Cursor::new(f.rung, f.pos.map_or(0, |p| p.row), f.pos.map_or(0, |p| p.col));
                let what = match f.pos {
                    Some(p) => ctx.page.lang.get().words().cell(f.rung + 1, p.row + 1, p.col + 1),
                    None => format!("{} {} ({})", t().rung, f.rung + 1, t().rung_comment),
                };
                view! { <li><button type="button" on:click=move |_| pick.run(at)>{what}</button></li> }
            }).collect_view()}
        </ul>
    }
}

/// The cross reference of the device searched for: each use with its
/// rung and first step.
#[component]
fn XrefTable(ctx: LadderCtx, query: RwSignal<String>, pick: Callback<Cursor>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let uses = move || {
        track_ladder(ctx);
        let q = query.get();
        let steps = ctx.drawing.listing.get();
        ctx.with_editor(|e| {
            xref(e.ladder(), &q)
                .into_iter()
                .map(|u| {
                    let step = steps
                        .as_ref()
                        .and_then(|l| l.steps_of(u.rung))
                        .map(|s| s.start);
                    (u, step)
                })
                .collect::<Vec<_>>()
        })
    };
    view! {
        <table class="xref" data-testid="xref">
            <tbody>
                {move || uses().into_iter().map(|(u, step)| {
                    let words = ctx.page.lang.get().words();
                    let role = match u.role {
                        UseRole::Contact => words.use_roles[0],
                        UseRole::Coil => words.use_roles[1],
                        UseRole::Box => words.use_roles[2],
                    };
                    let at = Cursor::new(u.rung, u.pos.row, u.pos.col);
                    view! {
                        <tr>
                            <td>{role}</td>
                            <td>{format!("{} {}", t().rung, u.rung + 1)}</td>
                            <td>{step.map(|s| format!("{} {s}", t().step))}</td>
                            <td><button type="button" on:click=move |_| pick.run(at)>
                                {words.row_col(u.pos.row + 1, u.pos.col + 1)}
                            </button></td>
                        </tr>
                    }
                }).collect_view()}
            </tbody>
        </table>
    }
}

/// Batch replace of devices, with its preview.
#[component]
fn ReplaceBox(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let from = RwSignal::new(String::new());
    let to = RwSignal::new(String::new());
    let plan = move || {
        track_ladder(ctx);
        let (f, w) = (from.get(), to.get());
        if f.trim().is_empty() || w.trim().is_empty() {
            return Ok(Vec::new());
        }
        ctx.with_editor(|e| replace_plan(e.ladder(), &f, &w))
    };
    let apply = move || {
        let edit = Edit::ReplaceDevices {
            from: from.get_untracked(),
            to: to.get_untracked(),
        };
        if ctx.apply(edit) {
            from.set(String::new());
            to.set(String::new());
        }
    };
    view! {
        <div class="find-row">
            <input data-testid="replace-from" placeholder="X00 / M00-M07" spellcheck="false"
                prop:value=move || from.get() on:input=move |e| from.set(event_target_value(&e)) />
            <span>{move || t().replace_with}</span>
            <input data-testid="replace-to" placeholder="X03 / M20-M27" spellcheck="false"
                prop:value=move || to.get() on:input=move |e| to.set(event_target_value(&e)) />
            <button type="button" data-testid="replace-apply"
                disabled=move || !plan().is_ok_and(|p| !p.is_empty()) on:click=move |_| apply()>
                {move || t().replace_apply}
            </button>
        </div>
        <ul class="replace-preview" data-testid="replace-preview">
            {move || match plan() {
                Ok(list) => list.into_iter().map(|(rung, pos, was, will)| {
                    let at = ctx.page.lang.get().words().cell(rung + 1, pos.row + 1, pos.col + 1);
                    view! { <li>{format!("{at}: {was} → {will}")}</li> }
                }).collect_view().into_any(),
                Err(why) => {
                    let said = crate::i18n::errors::replace_error(ctx.page.lang.get(), &why);
                    view! { <li class="error">{said}</li> }.into_any()
                }
            }}
        </ul>
    }
}
