//! Time travel in the page (issue #16): the machine records every scan
//! (`engine::record`); paused, the user steps back and forward a scan at
//! a time or drags the timeline, and the ladder, the panel and the watch
//! table show that scan exactly (the machine is replayed to it). Resume
//! from here makes that scan the live one; a break condition pauses the
//! run at the end of the first scan where it holds.

use engine::record::{Mark, TimeTravel};
use leptos::prelude::*;

use super::LadderCtx;

/// What the page shows of a machine's recording; `Copy`.
#[derive(Clone, Copy)]
pub struct TravelState {
    /// The first and last recorded scans.
    pub marks: RwSignal<(Mark, Mark)>,
    /// The first and last scans the timeline slider spans: the marks,
    /// except while the machine runs live and the slider is not in use,
    /// when it is left as it was (its thumb at the end): a range input
    /// whose bounds change costs a layout of the page, which with a large
    /// ladder took a third of each frame (docs/performance.md).
    pub slider: RwSignal<(Mark, Mark)>,
    /// The slider has the focus (a press gives it the focus).
    pub held: StoredValue<bool>,
    /// The scan shown, while travelling.
    pub shown: RwSignal<Option<Mark>>,
    /// Every scan where the break condition held.
    pub breaks: RwSignal<Vec<Mark>>,
    /// The scan a break stopped the run at, until it runs again.
    pub stopped_at: RwSignal<Option<Mark>>,
    /// The break condition as typed, and why it was refused.
    pub break_text: RwSignal<String>,
    pub break_error: RwSignal<Option<String>>,
    /// Bumped when the recording changed enough to redraw the chart.
    pub chart_tick: RwSignal<u64>,
    /// Wall time of the last chart redraw while running (ms).
    pub chart_drawn_ms: StoredValue<f64>,
}

impl TravelState {
    /// Nothing recorded yet.
    pub fn new() -> TravelState {
        TravelState {
            marks: RwSignal::new((0, 0)),
            slider: RwSignal::new((0, 0)),
            held: StoredValue::new(false),
            shown: RwSignal::new(None),
            breaks: RwSignal::new(Vec::new()),
            stopped_at: RwSignal::new(None),
            break_text: RwSignal::new(String::new()),
            break_error: RwSignal::new(None),
            chart_tick: RwSignal::new(0),
            chart_drawn_ms: StoredValue::new(f64::NEG_INFINITY),
        }
    }
}

impl Default for TravelState {
    fn default() -> Self {
        TravelState::new()
    }
}

/// The chart redraws at most this often while the machine runs.
const CHART_EVERY_MS: f64 = 250.0;

/// Copies the recording's marks, the shown scan and the breaks into the
/// signals that changed; `redraw` forces a chart redraw.
pub fn sync(ctx: LadderCtx, t: &mut dyn TimeTravel, now_ms: f64, redraw: bool) {
    let s = ctx.travel;
    let marks = t.marks();
    if s.marks.get_untracked() != marks {
        s.marks.set(marks);
    }
    let shown = t.shown();
    if s.shown.get_untracked() != shown {
        s.shown.set(shown);
    }
    let live_running =
        shown.is_none() && !ctx.page.paused.get_untracked() && ctx.live.running.get_untracked();
    if !live_running || s.held.get_value() {
        crate::state::put(s.slider, marks);
    }
    let breaks = t.breaks();
    if s.breaks.with_untracked(|b| *b != breaks) {
        s.breaks.set(breaks);
    }
    let due = now_ms - s.chart_drawn_ms.get_value() >= CHART_EVERY_MS;
    if redraw || due {
        s.chart_drawn_ms.set_value(now_ms);
        s.chart_tick.update(|n| *n += 1);
    }
}

/// Runs `f` on `ctx`'s machine's recording, then shows the result: the
/// signals, the panel and the ladder (a seek changes what they show).
pub fn travel<R>(ctx: LadderCtx, f: impl FnOnce(&mut dyn TimeTravel) -> R) -> Option<R> {
    travel_here(ctx, f)
}

/// [`travel`], outside a component too (the frame loop).
pub fn travel_here<R>(ctx: LadderCtx, f: impl FnOnce(&mut dyn TimeTravel) -> R) -> Option<R> {
    let result = ctx.recorded(|t| {
        let r = f(t);
        sync(ctx, t, crate::now_ms(), true);
        r
    });
    ctx.show_machine();
    result
}

/// Shows recorded scan `mark` (pausing first).
pub fn seek(ctx: LadderCtx, mark: Mark) {
    ctx.page.paused.set(true);
    travel(ctx, |t| {
        let (first, last) = t.marks();
        t.show(mark.clamp(first, last));
    });
}

/// One scan back from the shown one (or from the newest).
pub fn step_back(ctx: LadderCtx) {
    let (first, last) = ctx.travel.marks.get_untracked();
    let at = ctx.travel.shown.get_untracked().unwrap_or(last);
    seek(ctx, at.saturating_sub(1).max(first));
}

/// One scan forward; past the newest, live again.
pub fn step_forward(ctx: LadderCtx) {
    let (_, last) = ctx.travel.marks.get_untracked();
    match ctx.travel.shown.get_untracked() {
        Some(at) if at < last => seek(ctx, at + 1),
        _ => go_live(ctx),
    }
}

/// Back to the live machine.
pub fn go_live(ctx: LadderCtx) {
    travel(ctx, |t| t.go_live());
}

/// The time-travel bar: back, the timeline, forward, where it is, Live,
/// The travel bar's slider over the recorded scans (its bounds left as
/// they are while the machine runs live: `TravelState::slider`).
#[component]
fn Timeline(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let s = ctx.travel;
    // Paused: the slider spans the recording at once (a frame would too).
    Effect::new(move |_| {
        if ctx.page.paused.get() {
            crate::state::put(s.slider, s.marks.get_untracked());
        }
    });
    view! {
        <input type="range" data-testid="timeline" class="timeline" aria-label=move || t().scan_slider
                min=move || s.slider.get().0.to_string()
                max=move || s.slider.get().1.to_string()
                prop:value=move || s.shown.get().unwrap_or(s.slider.get().1).to_string()
                on:focus=move |_| {
                    s.held.set_value(true);
                    crate::state::put(s.slider, s.marks.get_untracked());
                }
                on:blur=move |_| s.held.set_value(false)
                on:input=move |e| {
                    if let Ok(m) = event_target_value(&e).parse::<Mark>() {
                        seek(ctx, m);
                    }
                } />
    }
}

/// Resume from here, and the break condition.
#[component]
pub fn TravelBar(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let s = ctx.travel;
    let at = move || s.shown.get().unwrap_or(s.marks.get().1);
    let label = move || {
        let (first, last) = s.marks.get();
        match s.shown.get() {
            Some(m) => format!("{} {m} / {last} ({} {first})", t().scan, t().kept_from),
            // The scan count is the app bar's clock's (one count, one place).
            None => t().live.to_string(),
        }
    };
    let set_break = move || {
        let text = s.break_text.get_untracked();
        let result = travel(ctx, |tr| tr.set_break(&text));
        let error = match result {
            Some(Err(e)) => Some(crate::i18n::errors::condition_error(
                ctx.page.lang.get_untracked(),
                &e,
            )),
            _ => None,
        };
        s.break_error.set(error);
    };
    view! {
        <div class="travel-bar" data-testid="travel-bar" data-travelling=move || s.shown.get().is_some().to_string()>
            <button type="button" data-testid="step-back" title=move || t().step_back
                on:click=move |_| step_back(ctx)>"◀"</button>
            <Timeline ctx />
            <button type="button" data-testid="step-forward" title=move || t().step_forward
                on:click=move |_| step_forward(ctx)>"▶"</button>
            <span class="travel-at" data-testid="travel-at" data-shown=move || s.shown.get().map(|m| m.to_string())
                data-mark=move || at().to_string()>
                {label}
            </span>
            <button type="button" data-testid="go-live" disabled=move || s.shown.get().is_none()
                on:click=move |_| go_live(ctx)>{move || t().live}</button>
            <button type="button" data-testid="resume-here" disabled=move || s.shown.get().is_none()
                on:click=move |_| {
                    travel(ctx, |tr| tr.resume_here());
                }>{move || t().resume_here}</button>
            <label class="break">
                {move || t().break_on} " "
                <input data-testid="break-input" spellcheck="false" placeholder=move || ctx.page.lang.get().texts().break_example
                    prop:value=move || s.break_text.get()
                    on:input=move |e| {
                        let text = event_target_value(&e);
                        let empty = text.trim().is_empty();
                        s.break_text.set(text);
                        // An empty field is no condition: disarmed at
                        // once, however it was emptied.
                        if empty {
                            set_break();
                        }
                    }
                    on:change=move |_| set_break()
                    on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Enter" { set_break() } />
            </label>
            <span class="break-status" data-testid="break-status" role="status">
                {move || s.break_error.get().or_else(|| {
                    s.stopped_at.get().map(|m| format!("{} {m}", t().break_hit))
                })}
            </span>
        </div>
    }
}
