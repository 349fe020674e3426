//! Beside the ladder: the compiled listing in the machine's own format
//! (the selected rung's steps highlighted; a click on a step shows its
//! rung) and the problems list (a click puts the cursor there).

use engine::ladder::edit::{undeclared_in_box, Cursor, Edit, VariableEdit};
use engine::ladder::grid::Pos;
use engine::ladder::variables::Variable;
use leptos::prelude::*;

use crate::editor::state::LadderCtx;

/// `[data-testid=il-listing]`.
#[component]
pub fn ListingPane(ctx: LadderCtx, on_pick: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    // The steps of the cursor's rung.
    let chosen = Memo::new(move |_| {
        let rung = ctx.drawing.cursor.get().rung;
        ctx.drawing
            .listing
            .with(|l| l.as_ref().and_then(|l| l.steps_of(rung)))
    });
    let lines = Memo::new(move |_| {
        ctx.drawing.listing.with(|l| {
            l.as_ref().map_or_else(Vec::new, |l| {
                l.text
                    .lines()
                    .enumerate()
                    .map(|(i, line)| (i, line.to_string(), l.step_at_line(i)))
                    .collect::<Vec<_>>()
            })
        })
    });
    view! {
        <section class="listing-pane">
            <h3>{move || t().listing}</h3>
            <Show
                when=move || ctx.drawing.listing.with(Option::is_some)
                fallback=move || view! { <p class="muted" data-testid="il-listing-none">{move || t().listing_none}</p> }
            >
                <pre class="listing" data-testid="il-listing" tabindex="0" aria-label=move || t().listing>
                    <For
                        each=move || lines.get()
                        key=|(i, line, _)| (*i, line.clone())
                        children=move |(_, line, step)| {
                            let lit = move || step.is_some_and(|s| chosen.with(|c| c.as_ref().is_some_and(|r| r.contains(&s))));
                            view! {
                                <span
                                    class="line"
                                    class:step=step.is_some()
                                    class:lit=lit
                                    class:current=move || step.is_some() && ctx.live.stepped.with(|s| s.map(|x| x.0) == step)
                                    data-step=step.map(|s| s.to_string())
                                    on:click=move |_| {
                                        let rung = step.and_then(|s| ctx.drawing.listing.with_untracked(|l| l.as_ref().and_then(|l| l.rung_of_step(s))));
                                        if let Some(rung) = rung {
                                            ctx.move_to(Cursor::new(rung, 0, 0));
                                            on_pick.run(());
                                        }
                                    }
                                >
                                    {line}
                                    "\n"
                                </span>
                            }
                        }
                    />
                </pre>
            </Show>
        </section>
    }
}

/// `[data-testid=problems]`.
#[component]
pub fn ProblemsPane(ctx: LadderCtx, on_pick: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    view! {
        <section class="problems-pane">
            <h3>{move || t().problems}</h3>
            <div role="status" aria-live="polite">
            <ul class="problems" data-testid="problems">
                <Show when=move || ctx.drawing.problems.with(Vec::is_empty)>
                    <li class="muted">{move || t().problems_none}</li>
                </Show>
                <For
                    each=move || ctx.drawing.problems.get()
                    key=|p| p.clone()
                    children=move |p| {
                        let at = Cursor::new(p.rung, p.pos.map_or(0, |p| p.row), p.pos.map_or(0, |p| p.col));
                        let declare = p.pos.map(|pos| declare_buttons(ctx, p.rung, pos));
                        view! {
                            <li>
                                <button type="button" class="problem" on:click=move |_| {
                                    ctx.move_to(at);
                                    on_pick.run(());
                                }>{
                                    let (en, ja) = (p.text.clone(), p.ja.clone());
                                    move || if ctx.page.lang.get() == crate::i18n::Lang::Ja { ja.clone() } else { en.clone() }
                                }</button>
                                {declare}
                            </li>
                        }
                    }
                />
            </ul>
            </div>
        </section>
    }
}

/// "Declare NAME as TYPE" for each name the box at the problem's cell
/// uses undeclared (issue #49): one click declares it in the Variables
/// table with the type its use there needs.
fn declare_buttons(ctx: LadderCtx, rung: usize, pos: Pos) -> impl IntoView {
    let wanted = if ctx.machine.target().capabilities().word_boxes {
        undeclared_in_box(&ctx.ladder(), rung, pos)
    } else {
        Vec::new()
    };
    wanted
        .into_iter()
        .map(|(name, ty)| {
            let label = {
                let name = name.clone();
                move || {
                    let f = ctx.page.lang.get().files();
                    f.declare_as
                        .replace("{name}", &name)
                        .replace("{type}", ty.name())
                }
            };
            let declared = Variable::new(&name, ty.name());
            view! {
                <button type="button" class="declare-as" data-testid=format!("declare-as-{name}")
                    on:click=move |_| {
                        let edit = Edit::Variable(VariableEdit::Declare(declared.clone()));
                        if let Err(why) = ctx.try_edit(edit) {
                            ctx.panes.message.set(Some(why));
                        }
                    }>{label}</button>
            }
        })
        .collect_view()
}
