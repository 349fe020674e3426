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
    let figure = move || shown.with(|s| figure_of(s.as_ref(), t()));
    let standing =
        move || !plants.manual.get() && shown.with(|s| s.as_ref().is_some_and(|s| !s.running));
    let quantities = move || {
        shown.with(|s| {
            s.iter()
                .flat_map(|s| s.quantities.iter().map(|q| (s.plant, q)))
                .map(|(plant, (name, value))| {
                    view! {
                        <li data-testid=format!("plant-q-{name}")>
                            <span>{t().said(plant, name)}</span>" "<output>{*value}</output>
                        </li>
                    }
                })
                .collect_view()
        })
    };
    view! {
        <div class="plant-body">
            <div class="plant-figure">
                {figure}
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

/// The plant's own drawing: the conveyor's belt, the tank, or a lamp per
/// signal for the others.
fn figure_of(s: Option<&Shown>, t: &'static PlantTexts) -> AnyView {
    match s {
        Some(s) if s.plant == "conveyor" => conveyor(s, t).into_any(),
        Some(s) if s.plant == "tank" => tank(s, t).into_any(),
        Some(s) => lamps(s, t).into_any(),
        None => ().into_any(),
    }
}

/// The plant above the ladder on a phone ([`super::Kit::above`]): the
/// drawing and the latest alarm, compact, without the table. The alarm is
/// not a live region here: the dock's says it once.
pub(super) fn above() -> AnyView {
    let ctx = Ctx::get();
    let shown = Plants::get().shown;
    let t = move || ctx.lang.get().plant();
    let figure = move || shown.with(|s| figure_of(s.as_ref(), t()));
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
            {figure}
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

/// The signal called `name`, if the plant has it.
fn signal<'a>(s: &'a Shown, name: &str) -> Option<&'a SignalShown> {
    s.signals.iter().find(|x| x.name == name)
}

/// A sensor's or actuator's label: its name in words and its device.
fn label(s: &Shown, name: &str, t: &PlantTexts) -> String {
    let device = signal(s, name).and_then(|x| x.device.clone());
    let said = t.said(s.plant, name);
    format!("{said} {}", device.as_deref().unwrap_or(t.unwired))
}

fn on(s: &Shown, name: &str) -> bool {
    signal(s, name).is_some_and(|x| x.value != 0)
}

fn quantity(s: &Shown, name: &str) -> i64 {
    s.quantities
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(0, |(_, v)| *v)
}

/// The belt from the infeed (left) to its end (right), 520 units long.
fn conveyor(s: &Shown, t: &'static PlantTexts) -> impl IntoView {
    const X0: f64 = 40.0;
    const W: f64 = 520.0;
    let (length, part) = match s.figure.as_slice() {
        [l, p, ..] if *l > 0 => (*l as f64, *p as f64),
        _ => (1.0, 0.0),
    };
    let scale = W / length;
    let parts = s.figure.iter().skip(2).map(|&lead| {
        let tail = (lead as f64 - part).max(0.0);
        let head = (lead as f64).min(length);
        let x = X0 + tail * scale;
        let w = ((head - tail) * scale).max(0.0);
        view! { <rect class="plant-part" x=x y="38" width=w height="24" rx="2" /> }
    });
    let motor = on(s, "motor");
    let eye_w = part * scale;
    let delivered = quantity(s, "delivered");
    view! {
        <svg class="plant-svg" viewBox="0 0 600 120" role="img" data-testid="plant-conveyor"
            aria-label=format!("{}: {delivered} {}", t.plant_name("conveyor"), t.delivered)>
            <rect class="plant-belt" class:running=motor x=X0 y="62" width=W height="10" rx="5" />
            {parts.collect_view()}
            <g class="plant-sensor" class:on=on(s, "infeed") data-testid="plant-sig-infeed">
                <line x1=X0 + eye_w / 2.0 y1="20" x2=X0 + eye_w / 2.0 y2="62" />
                <circle cx=X0 + eye_w / 2.0 cy="16" r="6" />
                <text x=X0 y="100">{label(s, "infeed", t)}</text>
            </g>
            <g class="plant-sensor" class:on=on(s, "outfeed") data-testid="plant-sig-outfeed">
                <line x1=X0 + W - 4.0 y1="20" x2=X0 + W - 4.0 y2="62" />
                <circle cx=X0 + W - 4.0 cy="16" r="6" />
                <text x=X0 + W y="100" text-anchor="end">{label(s, "outfeed", t)}</text>
            </g>
            <g class="plant-actuator" class:on=motor data-testid="plant-sig-motor">
                <circle class="plant-spin" class:running=motor cx=X0 + W + 20.0 cy="67" r="12" />
                <text x=X0 + W / 2.0 y="100" text-anchor="middle">{label(s, "motor", t)}</text>
            </g>
            <text class="plant-count" x="300" y="24" text-anchor="middle" data-testid="plant-delivered">
                {format!("{delivered} {}", t.delivered)}
            </text>
        </svg>
    }
}

/// The tank: its level rising and falling, the valves above and below,
/// the switches at their heights.
fn tank(s: &Shown, t: &'static PlantTexts) -> impl IntoView {
    let fine = s.figure.first().copied().unwrap_or(0);
    let percent = percent_said(fine);
    let level = fine as f64 / 1000.0;
    let (low, high) = match s.figure.as_slice() {
        [_, l, h, ..] => (*l as f64, *h as f64),
        _ => (20.0, 80.0),
    };
    let y_of = |percent: f64| 140.0 - percent * 1.2;
    let full = quantity(s, "level") >= 100;
    let overflowing = full && on(s, "fill");
    view! {
        <svg class="plant-svg plant-tank-svg" viewBox="0 0 360 160" role="img" data-testid="plant-tank"
            aria-label=format!("{}: {} {percent}", t.plant_name("tank"), t.level)>
            <rect class="plant-vessel" x="120" y="20" width="120" height="120" />
            <rect class="plant-liquid" class:overflow=overflowing x="121" y=y_of(level)
                width="118" height=level * 1.2 />
            <g class="plant-actuator" class:on=on(s, "fill") data-testid="plant-sig-fill">
                <path d="M60 10 H150 V20" fill="none" />
                <text x="10" y="14">{label(s, "fill", t)}</text>
            </g>
            <g class="plant-actuator" class:on=on(s, "drain") data-testid="plant-sig-drain">
                <path d="M210 140 V150 H300" fill="none" />
                <text x="250" y="146">{label(s, "drain", t)}</text>
            </g>
            <g class="plant-sensor" class:on=on(s, "high") data-testid="plant-sig-high">
                <circle cx="248" cy=y_of(high) r="5" />
                <text x="258" y=y_of(high) + 4.0>{label(s, "high", t)}</text>
            </g>
            <g class="plant-sensor" class:on=on(s, "low") data-testid="plant-sig-low">
                <circle cx="248" cy=y_of(low) r="5" />
                <text x="258" y=y_of(low) + 4.0>{label(s, "low", t)}</text>
            </g>
            <text class="plant-count" x="112" y=y_of(level) + 4.0 text-anchor="end"
                data-testid="plant-level">{percent.clone()}</text>
        </svg>
    }
}

/// A level in thousandths of a percent, said in whole percent as the
/// quantity `level` is (truncated, so the two never disagree).
pub(super) fn percent_said(thousandths: i64) -> String {
    format!("{} %", thousandths / 1000)
}

/// Any other plant, simply: a lamp per signal, labelled with its device.
fn lamps(s: &Shown, t: &'static PlantTexts) -> impl IntoView {
    let lamp = |x: &SignalShown| {
        let device = x.device.clone().unwrap_or_else(|| "—".to_string());
        let value = if x.analog {
            format!("{} %", x.value / 1000)
        } else {
            String::new()
        };
        view! {
            <li class=if x.output { "plant-actuator" } else { "plant-sensor" } class:on=x.value != 0
                data-testid=format!("plant-sig-{}", x.name)>
                <span class="plant-lamp" aria-hidden="true"></span>
                <span>{t.said(s.plant, x.name)}</span>" "<small>{device}</small>" "{value}
            </li>
        }
    };
    view! { <ul class="plant-lamps">{s.signals.iter().map(lamp).collect_view()}</ul> }
}
