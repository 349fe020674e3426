//! The wiring table (part `plants`): each signal of the plant and the
//! device it is on, editable; refusals said at their row; the machine's
//! default one click away. An edit is applied as the project's wiring
//! (kept in projects and share links), which couples the plant anew.

use engine::formats::project::PlantSetup;
use engine::plant::wiring::{self, WireEntry};
use engine::plant::{any::ALL, Direction, PlantInfo};
use engine::plc::Plc;
use leptos::prelude::*;

use super::Plants;
use crate::editor::LadderCtx;
use crate::state::Ctx;

/// The machine's default wiring of `plant` as the page couples it: a
/// signal whose terminal the machine, as it stands, would refuse is left
/// unwired (the IO86A's X04 carries the tank's level only in analog
/// mode, a setting the page's workspace does not keep), as on a machine
/// with no terminal for it, so the default always couples.
pub(super) fn default_entries(plant: &PlantInfo, machine: &dyn Plc) -> Vec<WireEntry> {
    let mut entries = wiring::default_wiring(plant, machine).0;
    entries.retain(|e| wiring::check(plant, machine, std::slice::from_ref(e)).is_ok());
    entries
}

/// The machine's default wiring of plant `name`: `SIGNAL`, `DEVICE` rows,
/// a signal with no terminal left with an empty device.
pub(super) fn default_rows(name: &str, machine: &dyn Plc) -> Vec<[String; 2]> {
    let Some(info) = ALL.iter().find(|p| p.name == name) else {
        return Vec::new();
    };
    let entries = default_entries(info, machine);
    info.signals
        .iter()
        .map(|s| {
            let device = entries
                .iter()
                .find(|e| e.signal == s.name)
                .map(|e| e.device.clone())
                .unwrap_or_default();
            [s.name.to_string(), device]
        })
        .collect()
}

/// The rows shown: the project's wiring, or the default for the machine.
fn rows_of(ladder: LadderCtx, setup: &PlantSetup) -> Vec<[String; 2]> {
    match &setup.wiring {
        Some(rows) => rows.clone(),
        None => ladder
            .with_plc(|plc| default_rows(&setup.name, plc))
            .unwrap_or_default(),
    }
}

/// The wiring table of the chosen plant.
#[component]
pub(super) fn WiringTable(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let setup = ladder.cases.plant;
    let t = move || ctx.lang.get().plant();
    // The rows as edited, reset from the project whenever it changes.
    let rows = RwSignal::new(Vec::<[String; 2]>::new());
    Effect::new(move || {
        if let Some(s) = setup.get() {
            rows.set(rows_of(ladder, &s));
        }
    });
    let apply = move |wiring: Option<Vec<[String; 2]>>| {
        setup.update(|s| {
            if let Some(s) = s {
                s.wiring = wiring;
            }
        });
        ladder.save();
    };
    let body = move || {
        let n = rows.with(Vec::len);
        (0..n)
            .map(|i| view! { <WiringRow setup rows i /> })
            .collect_view()
    };
    view! {
        <section class="plant-wiring" data-testid="wiring" aria-label=move || t().wiring>
            <h3>{move || t().wiring}</h3>
            <table>
                <thead><tr><th scope="col">{move || t().signal}</th><th scope="col">{move || t().device}</th></tr></thead>
                <tbody>{body}</tbody>
            </table>
            <p class="wiring-refusal" role="alert" data-testid="wiring-refusal"
                hidden=move || plants.refusals.with(|r| r.iter().all(|(at, _)| *at != 0))>
                {move || t().refused}{" "}
                {move || refusal_at(plants, 0, ctx.lang.get())}
            </p>
            <div class="wiring-actions">
                <button type="button" data-testid="wiring-apply"
                    on:click=move |_| apply(Some(rows.get_untracked()))>{move || t().apply}</button>
                <button type="button" data-testid="wiring-default"
                    on:click=move |_| apply(None)>{move || t().default_wiring}</button>
            </div>
        </section>
    }
}

/// The refusals said at wiring row `row` (1-based; 0: not a row's) in
/// `lang`, joined.
fn refusal_at(plants: Plants, row: usize, lang: crate::i18n::Lang) -> String {
    plants.refusals.with(|r| {
        r.iter()
            .filter(|(at, _)| *at == row)
            .map(|(_, m)| crate::i18n::plant_wiring::refusal(lang, m))
            .collect::<Vec<_>>()
            .join("; ")
    })
}

/// Whether `name` is an actuator of plant `plant`.
fn is_output(plant: Option<&str>, name: &str) -> bool {
    ALL.iter()
        .find(|p| Some(p.name) == plant)
        .and_then(|p| p.signals.iter().find(|s| s.name == name))
        .is_some_and(|s| s.direction == Direction::Out)
}

/// Row `i` of the wiring table: the signal, its device, its refusal.
#[component]
fn WiringRow(
    setup: RwSignal<Option<PlantSetup>>,
    rows: RwSignal<Vec<[String; 2]>>,
    i: usize,
) -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let t = move || ctx.lang.get().plant();
    let cell = move |c: usize| rows.with(|r| r.get(i).map(|r| r[c].clone()).unwrap_or_default());
    let signal = cell(0);
    let plant = setup.with_untracked(|s| s.as_ref().map(|s| s.name.clone()));
    let out = is_output(plant.as_deref(), &signal);
    let kind = move || {
        if out {
            t().direction_out
        } else {
            t().direction_in
        }
    };
    let refusal = move || refusal_at(plants, i + 1, ctx.lang.get());
    let refused = move || !refusal().is_empty();
    // The engine's name is what wiring files and tests write; the words
    // follow it where the language has its own.
    let said = {
        let (signal, plant) = (signal.clone(), plant.clone().unwrap_or_default());
        move || {
            let said = t().said(&plant, &signal);
            (said != signal).then(|| format!(" {said}"))
        }
    };
    let label = {
        let signal = signal.clone();
        move || format!("{signal}: {}", t().device)
    };
    view! {
        <tr data-testid=format!("wiring-row-{signal}") class:refused=refused>
            <th scope="row">{signal.clone()}{said}<small>{" "}{kind}</small></th>
            <td>
                <input type="text" data-testid=format!("wiring-device-{signal}")
                    aria-label=label
                    aria-invalid=move || refused().to_string()
                    prop:value=move || cell(1)
                    on:change=move |e| {
                        let v = event_target_value(&e);
                        rows.update(|r| if let Some(r) = r.get_mut(i) { r[1] = v; });
                    } />
                <span class="wiring-refusal" role="alert"
                    data-testid=format!("wiring-refusal-{signal}")
                    hidden=move || !refused()>{refusal}</span>
            </td>
        </tr>
    }
}
