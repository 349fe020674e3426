//! "Why is this coil off (or on)?" in the page: the W key or the Why?
//! button explains the cell under the cursor in the scan shown, with the
//! engine's answer (`engine::ladder::why`, from the machine's own trace).
//! The deciding cells are marked on the ladder (`data-why`), each listed
//! with its device's state, the scan it last changed (a click travels
//! there) and the rungs that drive it (a click goes there).

use engine::ladder::grid::Pos;
use engine::ladder::why::{causes, drivers};
use engine::record::Mark;
use leptos::prelude::*;

use crate::editor::model::element_words;
use crate::editor::LadderCtx;
use crate::i18n::Lang;
use engine::ladder::edit::Cursor;

/// One explanation as the page shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct WhyView {
    /// The rung (0-based) and cell asked about.
    pub rung: usize,
    pub target: Pos,
    /// What the cell is (`coil Y00`), and in Japanese.
    pub what: String,
    pub what_ja: String,
    /// Whether power reaches it.
    pub powered: bool,
    /// Whether only all causes together would change it.
    pub together: bool,
    /// The scan explained (`None`: live).
    pub scan: Option<Mark>,
    /// The recorded scan it explains (the shown one, else the newest).
    pub at_mark: Mark,
    /// The deciding cells.
    pub causes: Vec<CauseView>,
}

/// One deciding cell.
#[derive(Clone, Debug, PartialEq)]
pub struct CauseView {
    pub pos: Pos,
    /// The element (`NC contact X01`).
    pub what: String,
    pub what_ja: String,
    /// Its device and the device's value, if it reads one.
    pub device: Option<(String, engine::plc::Value)>,
    /// The scan the device last changed, if recorded.
    pub changed: Option<Mark>,
    /// Where its device is written: (rung, cell) of each driving output.
    pub drivers: Vec<(usize, Pos)>,
    /// A soft PLC box's operands with their values (`level = 50`), which
    /// decide it.
    pub values: Vec<String>,
    /// A box of an ST block: the block's statements that wrote the output
    /// its power leaves by (issue #55).
    pub st: Vec<StCause>,
}

/// A statement of the project's Structured Text that wrote a value Why?
/// names (issue #55): its line, its text and its operands' values.
#[derive(Clone, Debug, PartialEq)]
pub struct StCause {
    /// Its 1-based line of the ST pane's text.
    pub line: usize,
    /// The line as written.
    pub statement: String,
    /// Each name it reads with its value (`y = 11`).
    pub values: Vec<String>,
    /// Whether it ran in the scan explained (`None`: not known).
    pub ran: Option<bool>,
}

impl WhyView {
    /// `"target"`, `"cause"` or nothing, for the cell at `at`.
    pub fn role_at(&self, at: &Cursor) -> Option<&'static str> {
        if at.rung != self.rung {
            return None;
        }
        let pos = Pos::new(at.row, at.col);
        if pos == self.target {
            Some("target")
        } else if self.causes.iter().any(|c| c.pos == pos) {
            Some("cause")
        } else {
            None
        }
    }
}

/// What the editor shows of "why"; `Copy`.
#[derive(Clone, Copy)]
pub struct WhyState {
    /// The last explanation shown.
    pub shown: RwSignal<Option<WhyView>>,
    /// The machine has moved on from the scan it explains (running).
    pub stale: RwSignal<bool>,
    /// Bumped by the W key: explain the cell under the cursor.
    pub request: RwSignal<u64>,
    /// The last request the pane took the focus for (the pane is a part,
    /// drawn after the request that first showed it).
    pub focused: StoredValue<u64>,
}

impl WhyState {
    /// Nothing explained yet.
    pub fn new() -> WhyState {
        WhyState {
            shown: RwSignal::new(None),
            stale: RwSignal::new(false),
            request: RwSignal::new(0),
            focused: StoredValue::new(0),
        }
    }
}

impl Default for WhyState {
    fn default() -> Self {
        WhyState::new()
    }
}

/// Explains the cell under the cursor in the scan shown; `None` when the
/// ladder is not running as drawn or the cell decides nothing.
pub fn explain(ctx: LadderCtx) -> Option<WhyView> {
    explain_at(ctx, ctx.drawing.cursor.get_untracked())
}

/// Keeps the explanation shown with the scan it explains: paused, it is
/// explained again whenever the scan shown changes (the same cell);
/// running, it is marked stale (`why_stale`) once the machine has moved
/// on, until asked again.
pub fn follow(ctx: LadderCtx) {
    let Some((at_mark, cell)) = ctx.why.shown.with_untracked(|w| {
        w.as_ref()
            .map(|w| (w.at_mark, Cursor::new(w.rung, w.target.row, w.target.col)))
    }) else {
        return;
    };
    let Some(now) = ctx.recorded(|t| t.shown().unwrap_or(t.marks().1)) else {
        return;
    };
    if now == at_mark {
        return;
    }
    if ctx.page.paused.get_untracked() {
        ctx.why.shown.set(explain_at(ctx, cell));
        ctx.why.stale.set(false);
    } else if !ctx.why.stale.get_untracked() {
        ctx.why.stale.set(true);
    }
}

/// Explains the cell `at` in the scan shown.
fn explain_at(ctx: LadderCtx, at: Cursor) -> Option<WhyView> {
    let target = Pos::new(at.row, at.col);
    let ladder = ctx.ladder();
    let scan = ctx.travel.shown.get_untracked();
    let mut found = None;
    ctx.with_plc(|plc| {
        let why = plc
            .trace()
            .and_then(|trace| ctx.with_live(|l| l?.explain(trace, at.rung, target)));
        let Some(why) = why else {
            return;
        };
        let listed = causes(&ladder, at.rung, &why)
            .into_iter()
            .map(|c| {
                let device = c.device.as_ref().and_then(|d| {
                    let handle = plc.device(d).ok()?;
                    Some((d.clone(), plc.read(handle)))
                });
                let drivers = c
                    .device
                    .as_deref()
                    .map_or_else(Vec::new, |d| outputs(&ladder, d));
                let values = c.element.block().map_or_else(Vec::new, |b| {
                    b.watched()
                        .iter()
                        .filter_map(|(label, d)| {
                            let handle = plc.device(d).ok()?;
                            Some(format!("{label} = {}", plc.read(handle)))
                        })
                        .collect()
                });
                CauseView {
                    pos: c.pos,
                    what: element_words(&c.element, Lang::En),
                    what_ja: element_words(&c.element, Lang::Ja),
                    device,
                    changed: None,
                    drivers,
                    values,
                    st: Vec::new(),
                }
            })
            .collect();
        let element = ladder.rungs[at.rung].get(target);
        let what = element.map_or_else(String::new, |e| element_words(e, Lang::En));
        let what_ja = element.map_or_else(String::new, |e| element_words(e, Lang::Ja));
        found = Some(WhyView {
            rung: at.rung,
            target,
            what,
            what_ja,
            powered: why.powered,
            together: why.together,
            scan,
            at_mark: 0,
            causes: listed,
        });
    });
    let mut view = found?;
    // A box of an ST block follows into its statements (issue #55), asked
    // once the machine is no longer borrowed: the soft PLC reads it too.
    let row = &ladder.rungs[at.rung];
    for cause in &mut view.causes {
        if let Some(b) = row.get(cause.pos).and_then(|e| e.block()) {
            cause.st = ctx.why_st(b.kind(), b.instance.clone());
        }
    }
    // When each device last changed, from the recording.
    ctx.recorded(|t| {
        let at = t.shown().unwrap_or(t.marks().1);
        view.at_mark = at;
        for cause in &mut view.causes {
            if let Some((device, _)) = &cause.device {
                cause.changed = t.last_change(device, at);
            }
        }
    });
    Some(view)
}

/// The outputs that write `device`: (rung, cell), top to bottom.
fn outputs(ladder: &engine::ladder::Ladder, device: &str) -> Vec<(usize, Pos)> {
    drivers(ladder, device)
        .into_iter()
        .filter_map(|rung| {
            let pos = ladder.rungs.get(rung)?.elements().find_map(|(p, e)| {
                let writes = match e {
                    engine::ladder::element::Element::Coil { device: d, .. }
                    | engine::ladder::element::Element::Pulse { device: d, .. }
                    | engine::ladder::element::Element::TimerCoil { device: d, .. }
                    | engine::ladder::element::Element::CounterCoil { device: d, .. } => {
                        d.eq_ignore_ascii_case(device)
                    }
                    _ => false,
                };
                writes.then_some(p)
            })?;
            Some((rung, pos))
        })
        .collect()
}

/// Explains the cell under the cursor, as the Why? button does.
fn ask(ctx: LadderCtx) {
    ctx.why.shown.set(explain(ctx));
    ctx.why.stale.set(false);
}

/// The W key asks through the editor's action, seen here, outside the
/// pane (a part drawn when first shown): the answer is shown in its tab
/// (it only outlined the cell when another tab was up).
pub fn answer_requests(ctx: LadderCtx) {
    Effect::new(move |first: Option<()>| {
        ctx.why.request.track();
        if first.is_some() {
            ask(ctx);
            ctx.page.docks.show(crate::docks::Tool::Why);
        }
    });
}

/// The Why? button and the explanation: `[data-testid=why-panel]`.
/// `on_back` gives the ladder the focus back (Escape).
#[component]
pub fn WhyPanel(ctx: LadderCtx, on_back: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let pane = NodeRef::<leptos::html::Section>::new();
    let ask = move || ask(ctx);
    // A W key's answer ([`answer_requests`]) takes the focus once drawn,
    // so it is read out (also when this pane was drawn for it); Escape
    // goes back to the ladder.
    Effect::new(move |_| {
        let request = ctx.why.request.get();
        if request != ctx.why.focused.get_value() {
            ctx.why.focused.set_value(request);
            // The pane may be closed by the next frame.
            request_animation_frame(move || {
                if let Some(Some(p)) = pane.try_get_untracked() {
                    let _ = p.focus();
                }
            });
        }
    });
    let back = move |e: leptos::ev::KeyboardEvent| {
        if e.key() == "Escape" {
            e.prevent_default();
            on_back.run(());
        }
    };
    view! {
        <section class="why-pane" data-testid="why-panel" tabindex="-1" node_ref=pane on:keydown=back
            data-stale=move || if ctx.why.stale.get() { "1" } else { "0" }>
            <h3>
                <button type="button" data-testid="why" on:click=move |_| ask()>{move || t().why}</button>
            </h3>
            {move || match ctx.why.shown.get() {
                None => view! { <p class="why-none">{t().why_none}</p> }.into_any(),
                Some(w) => {
                    let what = if ctx.page.lang.get() == Lang::Ja { &w.what_ja } else { &w.what };
                    let head = format!(
                        "{} {} ({} {}{})",
                        what,
                        if w.powered { t().why_on } else { t().why_off },
                        t().rung,
                        w.rung + 1,
                        w.scan.map(|s| format!(", {} {s}", t().scan)).unwrap_or_default(),
                    );
                    let lead = if w.together { t().why_all } else { t().why_any };
                    view! {
                        <p data-testid="why-head" data-powered=if w.powered { "1" } else { "0" }>{head}</p>
                        <p>{lead}</p>
                        <ul>
                            {w.causes.into_iter().map(|c| cause_view(ctx, c)).collect_view()}
                        </ul>
                    }.into_any()
                }
            }}
        </section>
    }
}

/// A statement of the ST that wrote a value: its line (a click shows it
/// in the Program tab), its text and its operands' values.
fn st_view(ctx: LadderCtx, s: &StCause) -> impl IntoView {
    let st = move || ctx.page.lang.get().st();
    let line = s.line;
    let ran = s
        .ran
        .map(|r| move || if r { st().why_ran } else { st().why_not_ran });
    view! {
        <li data-testid="why-st" data-line=line.to_string()
            data-ran=s.ran.map(|r| if r { "1" } else { "0" })>
            <button type="button" class="why-st-line"
                on:click=move |_| ctx.page.docks.show(crate::docks::Tool::Program)>
                {move || st().why_line.replace("{line}", &line.to_string())}
            </button>
            " " <code>{s.statement.clone()}</code>
            {(!s.values.is_empty()).then(|| format!(" · {}", s.values.join(", ")))}
            {ran.map(|r| view! { " · " <span>{r}</span> })}
        </li>
    }
}

fn cause_view(ctx: LadderCtx, c: CauseView) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let device = c.device.clone().map(|(d, _)| d).unwrap_or_default();
    let state = c.device.as_ref().map(|(d, v)| format!(" · {d} = {v}"));
    let changed = c.changed;
    let pos = c.pos;
    view! {
        <li data-testid="why-cause" data-device=device>
            <button type="button" class="why-cell"
                on:click=move |_| ctx.move_to(Cursor::new(ctx.why.shown.get_untracked().map_or(0, |w| w.rung), pos.row, pos.col))>
                {move || if ctx.page.lang.get() == Lang::Ja { c.what_ja.clone() } else { c.what.clone() }}
            </button>
            {state}
            {(!c.values.is_empty()).then(|| view! {
                " · " <span data-testid="why-values">{c.values.join(", ")}</span>
            })}
            {(!c.st.is_empty()).then(|| view! { <ul class="why-st">{c.st.iter().map(|s| st_view(ctx, s)).collect_view()}</ul> })}
            // What changed and who drives it are a device's: a box has none.
            {c.device.is_some().then(|| view! {
            " · "
            {match changed {
                Some(m) => view! {
                    <button type="button" data-testid="why-changed" data-scan=m.to_string()
                        on:click=move |_| crate::editor::travel::seek(ctx, m)>
                        {format!("{} {m}", t().why_changed)}
                    </button>
                }.into_any(),
                None => view! { <span>{t().why_unchanged}</span> }.into_any(),
            }}
            " · "
            {if c.drivers.is_empty() {
                view! { <span data-testid="why-input">{t().why_input}</span> }.into_any()
            } else {
                c.drivers.into_iter().map(|(rung, at)| view! {
                    <button type="button" data-testid="why-driver" data-rung=(rung + 1).to_string()
                        on:click=move |_| ctx.move_to(Cursor::new(rung, at.row, at.col))>
                        {format!("{} {}", t().why_driven_by, rung + 1)}
                    </button>
                }).collect_view().into_any()
            }}
            })}
        </li>
    }
}
