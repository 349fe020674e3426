//! The timing chart (issue #16), `[data-testid=timing-chart]`: chosen
//! devices against the recorded scans, bits as steps and words as bands
//! with their values written in them (issue #46, laid out in
//! [`super::bands`]). Each pixel column shows every value its scans took (so a
//! one-scan pulse is always at least a pixel wide, never merged away);
//! zoom and pan move over the recording, Follow keeps the newest scans
//! in view; a click puts the cursor on a scan (and, paused, travels
//! there); Export writes the visible scans as `hashigo run`'s CSV.

use engine::record::Mark;
use engine::SimTime;
use leptos::prelude::*;

use super::chart_window::{self as span, Window};
use crate::editor::{bands, LadderCtx};
pub use span::clock;

/// The chart's width in pixels (one column per pixel).
const WIDTH: usize = 600;
/// Each device's row height in pixels (a name button fits beside it;
/// a short dock shows more rows than at 30).
const ROW: usize = 24;

/// What is drawn: the scans in view, each device's values, their times.
#[derive(Clone, Debug, Default, PartialEq)]
struct ChartData {
    from: Mark,
    times: Vec<SimTime>,
    rows: Vec<(String, Vec<Option<i64>>)>,
}

impl ChartData {
    /// Where scan `at` is in the scans drawn, when it is among them.
    fn index_of(&self, at: Option<Mark>) -> Option<usize> {
        at.and_then(|m| m.checked_sub(self.from))
            .map(|i| i as usize)
    }
}

/// Whether a row is bits: every value 0 or 1.
fn is_bits(values: &[Option<i64>]) -> bool {
    values.iter().flatten().all(|&v| v == 0 || v == 1)
}

/// How often a row rose (0 to non-zero) in view.
fn rises(values: &[Option<i64>]) -> usize {
    values
        .windows(2)
        .filter(|w| w[0].unwrap_or(0) == 0 && w[1].unwrap_or(0) != 0)
        .count()
}

/// The devices a new chart shows: the ladder's outputs (and what its
/// output boxes write), then its contacts (and what its in-line boxes
/// read), each once, at most eight.
fn default_devices(ctx: LadderCtx) -> Vec<String> {
    use engine::ladder::element::Element;
    let ladder = ctx.ladder();
    let mut out: Vec<String> = Vec::new();
    let mut add = |d: &str| {
        if !d.is_empty() && !out.iter().any(|o| o.eq_ignore_ascii_case(d)) && out.len() < 8 {
            out.push(d.to_string());
        }
    };
    for pass in 0..2 {
        for rung in &ladder.rungs {
            for (_, e) in rung.elements() {
                match (pass, e) {
                    (0, Element::Coil { device, .. } | Element::TimerCoil { device, .. }) => {
                        add(device)
                    }
                    (0, Element::CounterCoil { device, .. }) => add(&format!("{device}.v")),
                    // A soft PLC box's results (a word draws as a value line).
                    (0, Element::OutputBlock(b)) => b.outputs.iter().for_each(|(_, v)| add(v)),
                    (1, Element::Contact { device, .. }) => add(device),
                    (1, Element::Block(b)) => b.watched().iter().for_each(|(_, d)| add(d)),
                    _ => {}
                }
            }
        }
    }
    out
}

/// The word "scan" in the page's language.
fn t_scan(ctx: LadderCtx) -> &'static str {
    ctx.page.lang.get_untracked().texts().scan
}

/// The chart's state; `Copy`.
#[derive(Clone, Copy)]
struct Chart {
    ctx: LadderCtx,
    /// `None` until the user picks: the ladder's own devices, as it is now.
    devices: RwSignal<Option<Vec<String>>>,
    window: RwSignal<Window>,
    /// The scan clicked (shown when not travelling).
    cursor: RwSignal<Option<Mark>>,
    /// The device name being typed, and why the last was refused.
    adding: RwSignal<String>,
    error: RwSignal<Option<String>>,
    data: RwSignal<ChartData>,
    /// The plot's width on the page (px), measured at each redraw: where
    /// a band is wide enough to write its value in.
    shown: RwSignal<f64>,
    plot: NodeRef<leptos::html::Div>,
    /// What was last read (scans, devices, the drawing's revision): a
    /// redraw that would read the same skips the reading.
    read: StoredValue<Option<span::Read>>,
}

impl Chart {
    fn new(ctx: LadderCtx) -> Chart {
        Chart {
            ctx,
            devices: RwSignal::new(None),
            window: RwSignal::new(Window::FOLLOW),
            cursor: RwSignal::new(None),
            adding: RwSignal::new(String::new()),
            error: RwSignal::new(None),
            data: RwSignal::new(ChartData::default()),
            shown: RwSignal::new(WIDTH as f64),
            plot: NodeRef::new(),
            read: StoredValue::new(None),
        }
    }

    /// The devices shown.
    fn chosen(self) -> Vec<String> {
        self.devices
            .get_untracked()
            .unwrap_or_else(|| default_devices(self.ctx))
    }

    /// Reads the scans in view from the recording (tracking what they
    /// depend on).
    fn redraw(self) {
        let w = self.window.get();
        let names = self
            .devices
            .get()
            .unwrap_or_else(|| default_devices(self.ctx));
        let revision = self.ctx.drawing.revision.get_untracked();
        // The chart reads the recording only while it is in sight: hidden,
        // not at every seek, nor at every frame of a running machine (1 ms
        // a frame, issue #52); shown again, this runs again.
        let docks = self.ctx.page.docks;
        let seen =
            docks.tool.get() == crate::docks::Tool::Chart && docks.sizes.with(|s| s.bottom_open);
        if !seen {
            return;
        }
        let fresh = self.ctx.recorded(|tr| {
            let (first, last) = tr.marks();
            let wide = w.span.unwrap_or_else(|| span::auto_span((first, last)));
            let at = tr.shown();
            let (from, end) = span::in_view(w, wide, (first, last), at);
            let key = (from, end, names.clone(), revision);
            if self.read.with_value(|r| r.as_ref() == Some(&key)) {
                return None;
            }
            self.read.set_value(Some(key));
            // A name the machine lacks may be its plant's (`tank.level`).
            let mut plant = Vec::new();
            let rows = (names.iter().enumerate())
                .map(|(i, n)| match tr.series(n, from, end) {
                    Ok(values) => (
                        n.clone(),
                        values.into_iter().map(|v| v.map(|v| v.as_i64())).collect(),
                    ),
                    Err(_) => {
                        plant.push(i);
                        (n.clone(), Vec::new())
                    }
                })
                .collect();
            let times = tr.times(from, end);
            Some((ChartData { from, times, rows }, plant))
        });
        if let Some((mut fresh, plant)) = fresh.flatten() {
            span::plant_rows(self.ctx, &mut fresh.rows, &fresh.times, &plant);
            if self.data.with_untracked(|d| *d != fresh) {
                self.data.set(fresh);
            }
        }
        // Measured in the next frame, when the browser lays the page out
        // anyway: measured here, in the middle of a seek's updates, it
        // forced a layout of its own (half of a seek's time in the page).
        // The chart may be gone by then (another machine shown): its
        // signals are read with `try_`, never to panic.
        let (plot, shown) = (self.plot, self.shown);
        request_animation_frame(move || {
            if let Some(plot) = plot.try_get_untracked().flatten() {
                let w = plot.get_bounding_client_rect().width().round();
                if w > 0.0 && shown.try_get_untracked().is_some_and(|s| s != w) {
                    shown.try_set(w);
                }
            }
        });
    }

    /// Adds the device typed, when the machine has it.
    fn add(self) {
        let name = self.adding.get_untracked().trim().to_string();
        if name.is_empty() {
            return;
        }
        let known = self
            .ctx
            .with_plc(|plc| plc.device(&name).map(|_| ()))
            .unwrap_or(Ok(()))
            .or_else(|e| {
                if span::plant_has(self.ctx, &name) {
                    Ok(())
                } else {
                    Err(e)
                }
            });
        match known {
            Ok(()) => {
                self.error.set(None);
                let mut list = self.chosen();
                if !list.contains(&name) {
                    list.push(name);
                }
                self.devices.set(Some(list));
                self.adding.set(String::new());
            }
            Err(e) => {
                let lang = self.ctx.page.lang.get_untracked();
                self.error
                    .set(Some(crate::i18n::errors::plc_error(lang, &e)));
            }
        }
    }

    fn remove(self, name: &str) {
        let mut list = self.chosen();
        list.retain(|x| x != name);
        self.devices.set(Some(list));
    }

    /// The scans in view now (the automatic span's, until a zoom).
    fn wide(self) -> u64 {
        self.window.get_untracked().span.unwrap_or_else(|| {
            self.data
                .with_untracked(|d| d.times.len() as u64)
                .max(span::MIN_SPAN)
        })
    }

    fn zoom(self, factor: f64) {
        let wide = self.wide();
        self.window.update(|w| {
            let span = (wide as f64 * factor).round() as u64;
            w.span = Some(span.clamp(span::MIN_SPAN, 1_000_000));
        });
    }

    fn pan(self, dir: i64) {
        let (first, last) = self.ctx.travel.marks.get_untracked();
        let wide = self.wide();
        self.window.update(|w| {
            w.span = Some(wide);
            let end = w.end.unwrap_or(last) as i64 + dir * (wide as i64 / 2);
            let end = (end.max(first as i64) as u64).min(last);
            w.end = Some(end);
        });
    }

    fn export(self) {
        let csv = self.data.with_untracked(csv_of);
        crate::editor::files::download("timing.csv", "text/csv", &csv);
    }

    /// A click at `x` pixels: the cursor there (and, paused, that scan).
    fn pick(self, x: i32) {
        let (n, from) = self.data.with_untracked(|d| (d.times.len(), d.from));
        if n == 0 {
            return;
        }
        let x = x.max(0) as usize;
        let mark = from + (x.min(WIDTH - 1) * n / WIDTH) as u64;
        self.cursor.set(Some(mark));
        if self.ctx.page.paused.get_untracked() {
            crate::editor::travel::seek(self.ctx, mark);
        }
    }

    /// A click on the plot, which is drawn `WIDTH` columns wide and shown
    /// as wide as its box.
    fn pick_at(self, e: &web_sys::MouseEvent) {
        use leptos::wasm_bindgen::JsCast;
        let shown = e
            .current_target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .map_or(WIDTH as f64, |el| el.get_bounding_client_rect().width());
        let x = f64::from(e.offset_x()) * WIDTH as f64 / shown.max(1.0);
        self.pick(x as i32);
    }

    /// The scan the values table shows: the one travelled to, or clicked.
    fn at(self) -> Option<Mark> {
        self.ctx.travel.shown.get().or(self.cursor.get())
    }

    /// Row `row`'s value at the scan shown or clicked.
    fn value_at(self, row: usize) -> Option<i64> {
        let at = self.at();
        self.data.with(|d| {
            let i = d.index_of(at)?;
            d.rows.get(row)?.1.get(i).copied().flatten()
        })
    }

    fn height(self) -> usize {
        self.data.with(|d| d.rows.len().max(1) * ROW)
    }
}

/// The scans in view as `hashigo run`'s CSV.
fn csv_of(d: &ChartData) -> String {
    let mut out = String::from("time_ms");
    for (name, _) in &d.rows {
        out.push(',');
        out.push_str(name);
    }
    out.push('\n');
    for (i, time) in d.times.iter().enumerate() {
        out.push_str(&time.to_string());
        for (_, values) in &d.rows {
            out.push(',');
            if let Some(Some(v)) = values.get(i) {
                out.push_str(&v.to_string());
            }
        }
        out.push('\n');
    }
    out
}

/// The chart.
#[component]
pub fn TimingChart(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let chart = Chart::new(ctx);
    // Redrawn when the recording moved on (at most every 250 ms while
    // running), the view moved, or the devices changed. An edit redraws at
    // once: the rows follow the ladder in the same frame, so the page
    // below does not jump up to 250 ms after the edit.
    Effect::new(move |_| {
        ctx.travel.chart_tick.track();
        ctx.drawing.revision.track();
        chart.redraw();
    });
    // A scan travelled to outside the view brings the view to it (a seek
    // within it only moves the cursor: nothing is read again).
    Effect::new(move |_| {
        let Some(at) = ctx.travel.shown.get() else {
            return;
        };
        let out = chart
            .data
            .with_untracked(|d| d.index_of(Some(at)).is_none_or(|i| i >= d.times.len()));
        if out {
            chart.redraw();
        }
    });
    // Another project on a clean slate: the chart's choices (devices,
    // the scan clicked, the window) were the last project's.
    Effect::new(move |first: Option<()>| {
        ctx.work.slate.track();
        if first.is_some() {
            chart.devices.set(None);
            chart.cursor.set(None);
            chart.error.set(None);
            chart.window.set(Window::FOLLOW);
        }
    });
    view! {
        <section class="chart-pane" data-testid="timing-chart">
            // Its dock tab names it: the heading is for screen readers, the
            // rows get the height.
            <h3 class="sr-only">{move || t().chart}</h3>
            <ChartTools chart />
            <p class="chart-error" role="alert">{move || chart.error.get()}</p>
            <div class="chart-body">
                <ChartNames chart />
                <ChartPlot chart />
            </div>
            <ChartValues chart />
        </section>
    }
}

/// Adding a device, zoom, pan, follow, export.
#[component]
fn ChartTools(chart: Chart) -> impl IntoView {
    let t = move || chart.ctx.page.lang.get().texts();
    view! {
        <div class="find-row">
            <input data-testid="chart-add" placeholder=move || t().chart_add spellcheck="false"
                prop:value=move || chart.adding.get()
                on:input=move |e| chart.adding.set(event_target_value(&e))
                on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Enter" { chart.add() } />
            <button type="button" on:click=move |_| chart.add()>"+"</button>
            <button type="button" data-testid="chart-zoom-in" title=move || t().zoom_in aria-label=move || t().zoom_in on:click=move |_| chart.zoom(0.5)>"⊕"</button>
            <button type="button" data-testid="chart-zoom-out" title=move || t().zoom_out aria-label=move || t().zoom_out on:click=move |_| chart.zoom(2.0)>"⊖"</button>
            <button type="button" data-testid="chart-pan-left" title=move || t().pan_left on:click=move |_| chart.pan(-1)>"◀"</button>
            <button type="button" data-testid="chart-pan-right" title=move || t().pan_right on:click=move |_| chart.pan(1)>"▶"</button>
            <button type="button" data-testid="chart-follow" on:click=move |_| chart.window.update(|w| w.end = None)>{move || t().chart_follow}</button>
            <button type="button" data-testid="chart-export" on:click=move |_| chart.export()>{move || t().chart_export}</button>
        </div>
    }
}

/// Each row's device, once: its name, its value at the scan shown or
/// clicked, and a button that takes it off. The rows follow the data; a
/// seek changes only each value's text.
#[component]
fn ChartNames(chart: Chart) -> impl IntoView {
    let t = move || chart.ctx.page.lang.get().texts();
    view! {
        <div class="chart-names">
            {move || {
                let pins = span::pin_names(&chart.ctx.ladder());
                chart.data.with(|d| {
                    d.rows.iter().enumerate().map(|(row, (name, _))| {
                        let gone = name.clone();
                        let v = move || chart.value_at(row).map(|v| v.to_string());
                        view! {
                            <div class="chart-name" style=format!("height: {ROW}px")>
                                <span>{span::row_name(&pins, name)}</span>
                                <span class="chart-value" data-testid=format!("chart-value-{name}")>{v}</span>
                                <button type="button" aria-label=format!("{} {name}", t().delete_test)
                                    on:click=move |_| chart.remove(&gone)>"×"</button>
                            </div>
                        }
                    }).collect_view()
                })
            }}
        </div>
    }
}

/// The rows drawn, the breaks and the cursor, with the values written
/// over them (HTML, so the text is not stretched with the plot) and the
/// time axis under them.
#[component]
fn ChartPlot(chart: Chart) -> impl IntoView {
    let height = move || chart.height();
    view! {
        <div class="chart-plot-col">
            <div class="chart-plot" node_ref=chart.plot style=move || format!("height: {}px", height())>
                <svg class="chart" height=height viewBox=move || format!("0 0 {WIDTH} {}", height())
                    preserveAspectRatio="none" aria-hidden="true"
                    on:click=move |e: web_sys::MouseEvent| chart.pick_at(&e)>
                    {move || chart.data.with(|d| d.rows.iter().enumerate().map(|(i, (name, values))| {
                        view! {
                            <g class="chart-row" data-testid=format!("chart-row-{name}")
                                data-rises=rises(values).to_string()
                                data-scans=values.len().to_string()
                                data-shape=if is_bits(values) { "bits" } else { "bands" }
                                transform=format!("translate(0 {})", i * ROW)>
                                {row_paths(values)}
                            </g>
                        }
                    }).collect_view())}
                    <ChartMarks chart />
                </svg>
                <ChartTexts chart />
            </div>
            <ChartAxis chart />
        </div>
    }
}

/// A row's paths: a bit row's steps, a word row's bands.
fn row_paths(values: &[Option<i64>]) -> impl IntoView {
    if is_bits(values) {
        let d = bands::bit_path(values, WIDTH, ROW);
        view! { <path class="chart-bits" d=d /> }.into_any()
    } else {
        let (lines, busy) = bands::word_path(&bands::bands(values, WIDTH), ROW);
        view! {
            <path class="chart-busy" d=busy />
            <path class="chart-word" d=lines />
        }
        .into_any()
    }
}

/// The breakpoints and the cursor.
#[component]
fn ChartMarks(chart: Chart) -> impl IntoView {
    let height = move || chart.height();
    move || {
        let (from, n) = chart.data.with(|d| (d.from, d.times.len() as u64));
        let x = move |m: Mark| (m.saturating_sub(from) * WIDTH as u64 / n.max(1)) as usize;
        let inside = move |m: &Mark| *m >= from && *m < from + n;
        let breaks = chart.ctx.travel.breaks.get().into_iter().filter(inside).map(|m| view! {
            <line class="chart-break" data-testid="chart-break" x1=x(m) x2=x(m) y1="0" y2=height() />
        }).collect_view();
        let shown = chart.at().filter(inside).map(|m| {
            view! {
                <line class="chart-cursor" x1=x(m) x2=x(m) y1="0" y2=height() />
            }
        });
        (breaks, shown)
    }
}

/// The words' values: written in each band wide enough on the page, and
/// at the cursor always. The bands' texts follow the data and the plot's
/// width only, so a seek redraws just the cursor's.
#[component]
fn ChartTexts(chart: Chart) -> impl IntoView {
    let pct = |col: usize| col as f64 * 100.0 / WIDTH as f64;
    let written = move || {
        let px_per_col = chart.shown.get() / WIDTH as f64;
        chart.data.with(|d| {
            d.rows.iter().enumerate().filter(|(_, (_, v))| !is_bits(v)).map(|(i, (name, values))| {
                let top = i * ROW;
                bands::bands(values, WIDTH).into_iter().filter_map(|b| {
                    let text = bands::band_text(&b, px_per_col)?;
                    let style = format!("left: {:.3}%; width: {:.3}%; top: {top}px; height: {ROW}px",
                        pct(b.from), pct(b.to - b.from));
                    Some(view! { <span class="chart-band-text" data-row=name.clone() style=style>{text}</span> })
                }).collect_view()
            }).collect_view()
        })
    };
    let here = move || {
        let at = chart.at();
        chart.data.with(|d| {
            let cursor = d.index_of(at).filter(|&i| i < d.times.len())?;
            let n = d.times.len().max(1);
            Some(d.rows.iter().enumerate().filter(|(_, (_, v))| !is_bits(v)).filter_map(|(i, (name, values))| {
                let v = values.get(cursor).copied().flatten()?;
                let style = format!("left: {:.3}%; top: {}px; height: {ROW}px", pct(cursor * WIDTH / n), i * ROW);
                Some(view! { <span class="chart-at" data-testid=format!("chart-at-{name}") style=style>{v.to_string()}</span> })
            }).collect_view())
        })
    };
    (written, here)
}

/// The time axis, labelled: the scans and simulated times at both ends.
#[component]
fn ChartAxis(chart: Chart) -> impl IntoView {
    let ctx = chart.ctx;
    view! {
        <div class="chart-axis" data-testid="chart-axis">
            {move || chart.data.with(|d| {
                let end = |i: usize| d.times.get(i).map(|t| {
                    format!("{} {} · {}", t_scan(ctx), d.from + i as u64, clock(*t))
                });
                (
                    view! { <span>{end(0)}</span> },
                    view! { <span class="chart-axis-label">{move || ctx.page.lang.get().texts().chart_time_axis}</span> },
                    view! { <span>{end(d.times.len().saturating_sub(1))}</span> },
                )
            })}
        </div>
    }
}

/// The scan shown or clicked, and its time (each device's value there
/// is beside its name).
#[component]
fn ChartValues(chart: Chart) -> impl IntoView {
    let t = move || chart.ctx.page.lang.get().texts();
    view! {
        <p class="chart-values" data-testid="chart-cursor">
            {move || {
                let at = chart.at();
                chart.data.with(|d| {
                    let i = d.index_of(at);
                    let time = i.and_then(|i| d.times.get(i)).map(|t| clock(*t));
                    at.map(|m| format!("{} {m} · {}", t().scan, time.unwrap_or_default()))
                })
            }}
        </p>
    }
}

#[cfg(test)]
#[path = "chart_tests.rs"]
mod tests;
