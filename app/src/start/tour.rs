//! The guided first rung (`data-testid="tour"`): a card beside the ladder
//! that asks for a start/stop self-hold step by step, checks each step as
//! it is done (`steps::done`) and moves on by itself; Next skips a step,
//! ✕ or Escape leaves the tour at any step. Not modal: the ladder, the
//! palette and the panel stay in use.

use leptos::prelude::*;
use leptos::wasm_bindgen::JsCast;

use super::steps::{self, Devices, Running, Step};
use crate::editor::LadderCtx;
use crate::state::Ctx;

/// The tour's card, while a tour runs.
#[component]
pub fn Tour() -> impl IntoView {
    let ctx = Ctx::get();
    let start = super::Start::get();
    let ladders = expect_context::<crate::editor::Ladders>();
    let ladder = move || ladders.of(ctx.machine.get());
    // Each change of the drawing or of the running machine checks the step.
    Effect::new(move |_| {
        let Some(step) = start.tour.get() else {
            return;
        };
        super::fetch::ensure_style();
        let l = ladder();
        l.drawing.revision.track();
        let now = running(l);
        if l.with_editor(|e| steps::done(step, l.machine, e.ladder(), now)) {
            let next = step.next();
            if next == Step::Hold {
                // The branch goes under the start contact: the cursor waits there.
                if let Some(at) = l.with_editor(|e| steps::under_start(l.machine, e.ladder())) {
                    l.move_to(at);
                }
            }
            start.tour.set(Some(next));
        }
    });
    let escape = window_event_listener(leptos::ev::keydown, move |e| {
        if e.key() == "Escape"
            && start.tour.get_untracked().is_some()
            && !super::typed_in_a_field(&e)
        {
            start.tour.set(None);
        }
    });
    on_cleanup(move || escape.remove());
    move || {
        start
            .tour
            .get()
            .map(|step| view! { <Card step ladder=ladder() /> })
    }
}

/// The card at `step`.
#[component]
fn Card(step: Step, ladder: LadderCtx) -> impl IntoView {
    let ctx = ladder.page;
    let start = super::Start::get();
    let s = move || ctx.lang.get().start();
    let devices = Devices::of(ladder.machine);
    let text = {
        let devices = devices.clone();
        move || {
            let (title, what) = s().steps[step.index()];
            (devices.fill(title), devices.fill(what))
        }
    };
    let next = move |_| {
        if step == Step::Done {
            start.tour.set(None);
            return;
        }
        let following = step.next();
        if following == Step::Contact {
            begin_drawing(ladder);
        }
        start.tour.set(Some(following));
    };
    let next_label = move || match step {
        Step::Intro => s().tour_next,
        Step::Done => s().tour_done_mark,
        _ => s().tour_skip,
    };
    let count = Step::ALL.len() - 2;
    let place = step.index().min(count);
    view! {
        <aside class="tour" data-testid="tour" role="dialog" aria-modal="false"
            aria-labelledby="tour-title" aria-live="polite">
            <div class="tour-step" data-testid="tour-step" data-step=step.hook()>
                <p class="tour-count muted">{move || s().tour_label} " · " {place} " / " {count}</p>
                <h2 id="tour-title">{
                    let text = text.clone();
                    move || text().0
                }</h2>
                <p>{move || text().1}</p>
                {step.draws().then(|| view! {
                    <p class="tour-how muted">
                        <span class="on-keys">{move || s().tour_keys}</span>
                        <span class="on-touch">{move || s().tour_taps}</span>
                    </p>
                })}
            </div>
            <div class="tour-buttons">
                <button type="button" data-testid="tour-next" class:primary=matches!(step, Step::Intro | Step::Done)
                    on:click=next>{next_label}</button>
                <button type="button" data-testid="tour-close" title=move || s().tour_close
                    aria-label=move || s().tour_close on:click=move |_| start.tour.set(None)>"✕"</button>
            </div>
        </aside>
    }
}

/// The drawing begins on an empty first rung with the cursor on its first
/// cell (the old ladder is one undo away) and the ladder focused for keys.
fn begin_drawing(ladder: LadderCtx) {
    let empty = ladder.with_editor(|e| {
        e.ladder()
            .rungs
            .iter()
            .all(|r| r.elements().next().is_none())
    });
    if !empty {
        ladder.apply(engine::ladder::edit::Edit::NewLadder);
    }
    ladder.move_to(engine::ladder::edit::Cursor::new(0, 0, 0));
    let grid = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("ladder"))
        .and_then(|el| el.dyn_into::<web_sys::HtmlElement>().ok());
    if let Some(grid) = grid {
        let _ = grid.focus();
    }
}

/// What the running machine shows of the tour's devices.
fn running(ladder: LadderCtx) -> Running {
    let d = Devices::of(ladder.machine);
    let live = ladder.live;
    let on = |name: &str| {
        live.io_values
            .with(|v| v.iter().any(|(n, on)| n.eq_ignore_ascii_case(name) && *on))
    };
    Running {
        running: live.monitor.get() && live.running.get(),
        start_on: on(&d.start),
        stop_on: on(&d.stop),
        out_on: on(&d.out),
    }
}

crate::parts::part_fn!(
    start_tour,
    /// The guided first rung is a part of its own (issue #53): fetched when it first
    /// shows, not by the first screen.
    pub(crate) fn part() -> Result<crate::parts::Draw, crate::parts::PartMissing> {
        Ok(|| view! { <Tour /> }.into_any())
    }
);
