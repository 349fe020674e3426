//! The plant as the dock draws it (part `plants`): the conveyor's belt
//! with its parts, the tank with its level, the other plants as their
//! signals' lamps; each sensor and actuator lit when on and labelled with
//! the device it is wired to; the quantities; the alarms, said to screen
//! readers; the wiring table. Parts move because the rig publishes their
//! places each frame; the belt's and motor's own animation stops under
//! `prefers-reduced-motion` (style/plant.css).

use leptos::prelude::*;

use super::faults::Faults;
use super::manual::Manual;
use super::params::Params;
use super::wiring::WiringTable;
use super::{Plants, Shown, SignalShown};
use crate::editor::LadderCtx;
use crate::i18n::plant::PlantTexts;
use crate::state::Ctx;

/// The dock's drawing of the chosen plant ([`super::Kit::draw`]).
pub(super) fn draw() -> AnyView {
    view! { <PlantView /> }.into_any()
}

#[component]
fn PlantView() -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let ladder = expect_context::<LadderCtx>();
    let t = move || ctx.lang.get().plant();
    let shown = plants.shown;
    let frame = frame_of(shown);
    let standing =
        move || !plants.manual.get() && shown.with(|s| s.as_ref().is_some_and(|s| !s.running));
    // The quantities, a line each made once per plant, the values
    // following it.
    let quantities = move || {
        let t = t();
        frame.with(|f| {
            f.iter()
                .flat_map(|f| f.quantities.iter().map(|name| (f.plant, *name)))
                .map(|(plant, name)| {
                    view! {
                        <li data-testid=format!("plant-q-{name}")>
                            <span>{t.said(plant, name)}</span>" "
                            <output>{live(shown, name, quantity)}</output>
                        </li>
                    }
                })
                .collect_view()
        })
    };
    view! {
        <div class="plant-body">
            <div class="plant-figure">
                {figure(shown, frame, t)}
                <p class="plant-standing" hidden=move || !standing()>{move || t().standing}</p>
                <ul class="plant-quantities">{quantities}</ul>
                <Alarm />
            </div>
            <WiringTable ladder />
            <Params ladder />
            <Manual ladder />
            <Faults ladder />
        </div>
    }
}

/// What a drawing is made of apart from what moves: the plant, its
/// signals as wired (their values left out), its quantities' names and
/// the parts the belt's drawing has room for.
#[derive(Clone, PartialEq)]
struct Frame {
    plant: &'static str,
    signals: Vec<SignalShown>,
    quantities: Vec<&'static str>,
    part_slots: usize,
}

/// The shown plant's [`Frame`], as a memo: the drawing is made again only
/// when it changes.
fn frame_of(shown: RwSignal<Option<Shown>>) -> Memo<Option<Frame>> {
    Memo::new(move |last: Option<&Option<Frame>>| {
        let last = last.and_then(Option::as_ref);
        shown.with(|s| s.as_ref().map(|s| Frame::of(s, last)))
    })
}

impl Frame {
    /// `s`'s frame; the parts' room grows in steps, and never shrinks
    /// while the plant stays (a drawing made again each time a part came
    /// or went would cost what the frame saves).
    fn of(s: &Shown, last: Option<&Frame>) -> Frame {
        let still = |x: &SignalShown| SignalShown {
            value: 0,
            ..x.clone()
        };
        let parts = match s.plant {
            "conveyor" => s.figure.len().saturating_sub(2).next_power_of_two().max(8),
            _ => 0,
        };
        let had = last
            .filter(|f| f.plant == s.plant)
            .map_or(0, |f| f.part_slots);
        Frame {
            plant: s.plant,
            signals: s.signals.iter().map(still).collect(),
            quantities: s.quantities.iter().map(|(name, _)| *name).collect(),
            part_slots: parts.max(had),
        }
    }

    /// A sensor's or actuator's label: its name in words and its device.
    fn label(&self, name: &str, t: &PlantTexts) -> String {
        let wired = self.signals.iter().find(|x| x.name == name);
        let device = wired.and_then(|x| x.device.as_deref());
        let said = t.said(self.plant, name);
        format!("{said} {}", device.unwrap_or(t.unwired))
    }
}

/// The plant's own drawing: the conveyor's belt, the tank, or a lamp per
/// signal for the others. Made again only when the plant, its wiring or
/// the page's language changes; what moves (parts, level, lamps, counts)
/// follows `shown` attribute by attribute, so a running plant writes only
/// what changed in the frame (issue #52: the whole drawing was made again
/// each frame).
fn figure(
    shown: RwSignal<Option<Shown>>,
    frame: Memo<Option<Frame>>,
    t: impl Fn() -> &'static PlantTexts + Copy + Send + Sync + 'static,
) -> impl Fn() -> AnyView + Send + Sync + 'static {
    move || {
        let t = t();
        frame.with(|f| match f {
            Some(f) if f.plant == "conveyor" => conveyor(shown, f, t).into_any(),
            Some(f) if f.plant == "tank" => tank(shown, f, t).into_any(),
            Some(f) => lamps(shown, f, t).into_any(),
            None => ().into_any(),
        })
    }
}

/// A value of the shown plant (the type's default while none is shown),
/// for an attribute or a text that follows it: `of` the plant and `arg`
/// (a signal's name, a part's number). A function, not a closure, so that
/// the closure made here is of one type per argument and value type: the
/// page's code to keep an attribute or a class up to date is made once
/// per closure type, and a closure of each use's own was 10 KB more of the
/// plants' part.
fn live<A, T>(
    shown: RwSignal<Option<Shown>>,
    arg: A,
    of: fn(&Shown, A) -> T,
) -> impl Fn() -> T + Copy + Send + Sync + 'static
where
    A: Copy + Send + Sync + 'static,
    T: Default + 'static,
{
    move || shown.with(|s| s.as_ref().map(|s| of(s, arg)).unwrap_or_default())
}

/// The plant above the ladder on a phone ([`super::Kit::above`]): the
/// drawing and the latest alarm, compact, without the table. The alarm is
/// not a live region here: the dock's says it once.
pub(super) fn above() -> AnyView {
    let ctx = Ctx::get();
    let shown = Plants::get().shown;
    let t = move || ctx.lang.get().plant();
    let alarm = move || {
        shown.with(|s| {
            s.as_ref()
                .and_then(|s| s.alarms.last())
                .map(|(at, message)| {
                    format!(
                        "{} {}: {}",
                        t().alarm_at,
                        seconds(*at),
                        (t().alarm)(message)
                    )
                })
        })
    };
    view! {
        <div class="plant-above-figure">
            {figure(shown, frame_of(shown), t)}
            <p class="plant-alarm raised" hidden=move || alarm().is_none()>{alarm}</p>
        </div>
    }
    .into_any()
}

/// The latest alarm, with its simulated time; a live region, so a screen
/// reader says each new one.
#[component]
fn Alarm() -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let t = move || ctx.lang.get().plant();
    let text = move || {
        plants
            .shown
            .with(|s| match s.as_ref().and_then(|s| s.alarms.last()) {
                Some((at, message)) => {
                    format!(
                        "{} {}: {}",
                        t().alarm_at,
                        seconds(*at),
                        (t().alarm)(message)
                    )
                }
                None => t().no_alarm.to_string(),
            })
    };
    let raised = move || {
        plants
            .shown
            .with(|s| s.as_ref().is_some_and(|s| !s.alarms.is_empty()))
    };
    view! {
        <p class="plant-alarm" class:raised=raised role="status" aria-live="polite"
            data-testid="plant-alarm">{text}</p>
    }
}

/// `12345` ms as `12.345 s`.
fn seconds(ms: i64) -> String {
    format!("{}.{:03} s", ms / 1000, ms % 1000)
}

/// Whether the signal called `name` is on.
fn on(s: &Shown, name: &str) -> bool {
    signal_value(s, name) != 0
}

/// The quantity called `name` (0 if the plant has none).
fn quantity(s: &Shown, name: &str) -> i64 {
    s.quantities
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(0, |(_, v)| *v)
}

/// The conveyor's belt, left to right, `BELT_W` units long from `BELT_X`.
const BELT_X: f64 = 40.0;
const BELT_W: f64 = 520.0;

/// The belt's scale (units a µm) and a part's length (µm) from the
/// conveyor's figure: belt length, part length, then the parts' leading
/// edges.
fn belt_scale(figure: &[i64]) -> (f64, f64) {
    match figure {
        [l, p, ..] if *l > 0 => (BELT_W / *l as f64, *p as f64),
        _ => (BELT_W, 0.0),
    }
}

/// Part `i` on the belt as drawn: its left edge in the drawing's units
/// (`data-x`), its width and its place as a share of the belt, both in
/// percent (of the belt, of its own width); none: no such part.
pub(super) fn part_box(figure: &[i64], i: usize) -> Option<PartBox> {
    let (scale, part) = belt_scale(figure);
    let lead = *figure.get(2 + i)? as f64;
    let tail = lead - part;
    let (width, at) = match part > 0.0 {
        true => (part * scale / BELT_W * 100.0, tail / part * 100.0),
        false => (0.0, 0.0),
    };
    Some(PartBox {
        x: BELT_X + tail.max(0.0) * scale,
        width,
        at,
    })
}

/// A part as drawn ([`part_box`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct PartBox {
    /// Its left edge on the belt, in the drawing's units.
    pub x: f64,
    /// Its length, in percent of the belt's.
    pub width: f64,
    /// Its place: its left edge, in percent of its own length.
    pub at: f64,
}

/// The belt from the infeed (left) to its end (right), and the parts
/// riding it.
fn conveyor(shown: RwSignal<Option<Shown>>, f: &Frame, t: &'static PlantTexts) -> impl IntoView {
    // A box for each part the belt has room for; one without a part is
    // not displayed.
    let part = move |i: usize| {
        let b = live(shown, i, |s, i| part_box(&s.figure, i));
        let style = move || match b() {
            Some(b) => format!(
                "width: {:.3}%; transform: translateX({:.3}%)",
                b.width, b.at
            ),
            None => "display: none".to_string(),
        };
        view! { <span class="plant-part" data-x=move || b().map(|b| b.x) style=style></span> }
    };
    let motor = live(shown, "motor", on);
    // The belt and the motor turn while the plant moves: not while the
    // page is paused or the machine stopped, except in manual mode.
    let (ladder, manual) = (expect_context::<LadderCtx>(), Plants::get().manual);
    let running = live(shown, (), |s, ()| s.running);
    let turning = move || motor() && (manual.get() || (running() && !ladder.page.paused.get()));
    let eye_x = live(shown, (), |s, ()| {
        let (scale, part) = belt_scale(&s.figure);
        BELT_X + part * scale / 2.0
    });
    let delivered = live(shown, "delivered", quantity);
    let end = BELT_X + BELT_W - 4.0;
    let count = move || format!("{} {}", delivered(), t.delivered);
    let name = t.plant_name("conveyor");
    let said = move || format!("{name}: {}", count());
    view! {
        <div class="plant-belt-view">
            <svg class="plant-svg" viewBox="0 0 600 120" role="img" data-testid="plant-conveyor"
                aria-label=said>
                <rect class="plant-belt" class:running=turning x=BELT_X y="62" width=BELT_W height="10" rx="5" />
                <g class="plant-sensor" class:on=live(shown, "infeed", on) data-testid="plant-sig-infeed">
                    <line x1=eye_x y1="20" x2=eye_x y2="62" />
                    <circle cx=eye_x cy="16" r="6" />
                    <text x=BELT_X y="100">{f.label("infeed", t)}</text>
                </g>
                <g class="plant-sensor" class:on=live(shown, "outfeed", on) data-testid="plant-sig-outfeed">
                    <line x1=end y1="20" x2=end y2="62" />
                    <circle cx=end cy="16" r="6" />
                    <text x=BELT_X + BELT_W y="100" text-anchor="end">{f.label("outfeed", t)}</text>
                </g>
                <g class="plant-actuator" class:on=motor data-testid="plant-sig-motor">
                    <circle class="plant-spin" class:running=turning cx=BELT_X + BELT_W + 20.0 cy="67" r="12" />
                    <text x=BELT_X + BELT_W / 2.0 y="100" text-anchor="middle">{f.label("motor", t)}</text>
                </g>
                <text class="plant-count" x="300" y="24" text-anchor="middle" data-testid="plant-delivered">
                    {count}
                </text>
            </svg>
            // The parts are boxes over the drawing, moved by a transform: a
            // moved SVG shape lays the page out again each frame (and the
            // pointer's hover is then tested again), a transformed box does
            // not (issue #52). The belt's box clips them at its ends.
            <div class="plant-parts" aria-hidden="true">
                {(0..f.part_slots).map(part).collect_view()}
            </div>
        </div>
    }
}

/// The tank's level (thousandths of a percent) and its switches' heights
/// (percent) from its figure.
fn tank_levels(figure: &[i64]) -> (f64, f64, f64) {
    let fine = figure.first().copied().unwrap_or(0);
    match figure {
        [_, l, h, ..] => (fine as f64 / 1000.0, *l as f64, *h as f64),
        _ => (fine as f64 / 1000.0, 20.0, 80.0),
    }
}

/// Where a height in percent is drawn in the tank.
fn tank_y(percent: f64) -> f64 {
    140.0 - percent * 1.2
}

/// The tank: its level rising and falling, the valves above and below,
/// the switches at their heights.
fn tank(shown: RwSignal<Option<Shown>>, f: &Frame, t: &'static PlantTexts) -> impl IntoView {
    let levels = live(shown, (), |s, ()| tank_levels(&s.figure));
    let y_of = move |of: fn((f64, f64, f64)) -> f64| move || of(levels());
    let (level_y, height) = (y_of(|l| tank_y(l.0)), y_of(|l| l.0 * 1.2));
    let (high_y, low_y) = (y_of(|l| tank_y(l.2)), y_of(|l| tank_y(l.1)));
    let (high_text, low_text, level_text) = (
        y_of(|l| tank_y(l.2) + 4.0),
        y_of(|l| tank_y(l.1) + 4.0),
        y_of(|l| tank_y(l.0) + 4.0),
    );
    let percent = live(shown, (), |s, ()| {
        percent_said(s.figure.first().copied().unwrap_or(0))
    });
    let overflowing = live(shown, (), |s, ()| {
        quantity(s, "level") >= 100 && on(s, "fill")
    });
    let name = t.plant_name("tank");
    let said = move || format!("{name}: {} {}", t.level, percent());
    view! {
        <svg class="plant-svg plant-tank-svg" viewBox="0 0 360 160" role="img" data-testid="plant-tank"
            aria-label=said>
            <rect class="plant-vessel" x="120" y="20" width="120" height="120" />
            <rect class="plant-liquid" class:overflow=overflowing x="121" y=level_y
                width="118" height=height />
            <g class="plant-actuator" class:on=live(shown, "fill", on) data-testid="plant-sig-fill">
                <path d="M60 10 H150 V20" fill="none" />
                <text x="10" y="14">{f.label("fill", t)}</text>
            </g>
            <g class="plant-actuator" class:on=live(shown, "drain", on) data-testid="plant-sig-drain">
                <path d="M210 140 V150 H300" fill="none" />
                <text x="250" y="146">{f.label("drain", t)}</text>
            </g>
            <g class="plant-sensor" class:on=live(shown, "high", on) data-testid="plant-sig-high">
                <circle cx="248" cy=high_y r="5" />
                <text x="258" y=high_text>{f.label("high", t)}</text>
            </g>
            <g class="plant-sensor" class:on=live(shown, "low", on) data-testid="plant-sig-low">
                <circle cx="248" cy=low_y r="5" />
                <text x="258" y=low_text>{f.label("low", t)}</text>
            </g>
            <text class="plant-count" x="112" y=level_text text-anchor="end"
                data-testid="plant-level">{percent}</text>
        </svg>
    }
}

/// A level in thousandths of a percent, said in whole percent as the
/// quantity `level` is (truncated, so the two never disagree).
pub(super) fn percent_said(thousandths: i64) -> String {
    format!("{} %", thousandths / 1000)
}

/// Any other plant, simply: a lamp per signal, labelled with its device.
fn lamps(shown: RwSignal<Option<Shown>>, f: &Frame, t: &'static PlantTexts) -> impl IntoView {
    let plant = f.plant;
    let lamp = |x: &SignalShown| {
        let name = x.name;
        let device = x.device.clone().unwrap_or_else(|| "—".to_string());
        let value = live(shown, name, signal_value);
        let analog = x.analog;
        view! {
            <li class=if x.output { "plant-actuator" } else { "plant-sensor" } class:on=move || value() != 0
                data-testid=format!("plant-sig-{name}")>
                <span class="plant-lamp" aria-hidden="true"></span>
                <span>{t.said(plant, name)}</span>" "<small>{device}</small>" "
                {move || if analog { format!("{} %", value() / 1000) } else { String::new() }}
            </li>
        }
    };
    view! { <ul class="plant-lamps">{f.signals.iter().map(lamp).collect_view()}</ul> }
}

/// The value of the signal called `name` (0 if the plant has none).
fn signal_value(s: &Shown, name: &str) -> i64 {
    s.signals
        .iter()
        .find(|x| x.name == name)
        .map_or(0, |x| x.value)
}
