//! The plant's faults in the dock (part `plants`; docs/plants.md "In the
//! page"): the author's Faults section (`plant-faults`: a signal stuck
//! off or on, an actuator dead, from a time, hidden or not), kept as the
//! project's faults; and, in an exercise whose plant hides a fault, the
//! student's report (`fault-report`): the faulty signal and its kind,
//! which Check my answer grades.

use engine::formats::project::PlantSetup;
use engine::plant::{any::ALL, fault, Fault, Kind, PlantError, PlantInfo};
use leptos::prelude::*;

use crate::editor::LadderCtx;
use crate::i18n::plant_faults::PlantFaults;
use crate::state::Ctx;

/// The kinds of fault as the engine writes them (`dead` fits actuators
/// only: the engine refuses it on a sensor, at Add).
const KINDS: [&str; 3] = ["stuck 0", "stuck 1", "dead"];

/// A kind's words in the page's language.
fn kind_label(t: &PlantFaults, kind: &str) -> &'static str {
    match kind {
        "stuck 0" => t.stuck_0,
        "stuck 1" => t.stuck_1,
        _ => t.dead,
    }
}

/// The plant `name`'s bit signals, those a fault can act on.
fn bit_signals(name: &str) -> Vec<&'static str> {
    ALL.iter()
        .find(|p| p.name == name)
        .map(|p: &&PlantInfo| {
            p.signals
                .iter()
                .filter(|s| s.kind != Kind::Analog)
                .map(|s| s.name)
                .collect()
        })
        .unwrap_or_default()
}

/// A fault's text as the engine reads it (`infeed stuck 0 from 5s
/// hidden`), from the form's fields; `from` in seconds, empty: from 0.
pub(super) fn fault_text(signal: &str, kind: &str, from: &str, hidden: bool) -> String {
    let mut text = format!("{signal} {kind}");
    let from = from.trim();
    if !from.is_empty() && from != "0" {
        let unit = if from.chars().all(|c| c.is_ascii_digit() || c == '.') {
            "s"
        } else {
            ""
        };
        text.push_str(&format!(" from {from}{unit}"));
    }
    if hidden {
        text.push_str(" hidden");
    }
    text
}

/// Adds `text` to the setup's faults after the engine's check, or says
/// why not, by kind (the setup is left as it was).
pub(super) fn add_fault(setup: &mut PlantSetup, text: String) -> Result<(), PlantError> {
    let info = ALL
        .iter()
        .find(|p| p.name == setup.name)
        .ok_or_else(|| PlantError::NoPlant {
            name: setup.name.clone(),
            known: engine::plant::AnyPlant::names(),
        })?;
    Fault::parse(&text, info)?;
    setup.faults.push(text);
    Ok(())
}

/// The Faults section: the author's list and form, or, for a student in
/// an exercise, the faults not hidden and the report of a hidden one.
#[component]
pub(super) fn Faults(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().plant_faults();
    let setup = ladder.cases.plant;
    let student =
        move || ladder.cases.exercise.with(Option::is_some) && !ladder.cases.authoring.get();
    let hides = move || {
        setup.with(|s| {
            s.as_ref()
                .is_some_and(|s| s.faults.iter().any(|f| fault::is_hidden(f)))
        })
    };
    let rows = move || {
        let as_student = student();
        let faults = setup.with(|s| s.as_ref().map(|s| s.faults.clone()).unwrap_or_default());
        let shown: Vec<_> = faults
            .into_iter()
            .enumerate()
            .filter(|(_, f)| !(as_student && fault::is_hidden(f)))
            .collect();
        // A student whose plant hides a fault is not told "no fault".
        if shown.is_empty() && !(as_student && hides()) {
            return view! { <li class="plant-fault-none">{move || t().no_faults}</li> }.into_any();
        }
        shown
            .into_iter()
            .map(|(i, text)| {
                let remove = move |_| {
                    setup.update(|s| {
                        if let Some(s) = s.as_mut().filter(|s| i < s.faults.len()) {
                            s.faults.remove(i);
                        }
                    });
                    ladder.save();
                };
                view! {
                    <li data-testid=format!("plant-fault-{i}")>
                        <code>{text}</code>
                        <Show when=move || !as_student>
                            <button type="button" class="quiet" data-testid=format!("plant-fault-remove-{i}")
                                on:click=remove>{move || t().remove}</button>
                        </Show>
                    </li>
                }
            })
            .collect_view()
            .into_any()
    };
    view! {
        <section class="plant-faults" data-testid="plant-faults" aria-label=move || t().faults>
            <h3>{move || t().faults}</h3>
            <ul>{rows}</ul>
            <Show when=move || !student()>
                <AddFault ladder />
            </Show>
            <Show when=move || student() && hides()>
                <FaultReport ladder />
            </Show>
        </section>
    }
}

/// The author's form: a signal, a kind, from when, hidden; Add.
#[component]
fn AddFault(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().plant_faults();
    let setup = ladder.cases.plant;
    let name = move || setup.with(|s| s.as_ref().map(|s| s.name.clone()).unwrap_or_default());
    let signal = RwSignal::new(String::new());
    let kind = RwSignal::new(KINDS[0].to_string());
    let from = RwSignal::new(String::new());
    let hidden = RwSignal::new(false);
    // The fault refused, as written, and why.
    let refusal = RwSignal::new(None::<(String, PlantError)>);
    let signals = move || {
        let all = bit_signals(&name());
        if !all.iter().any(|s| signal.with_untracked(|v| v == s)) {
            signal.set(all.first().map(|s| s.to_string()).unwrap_or_default());
        }
        all.into_iter()
            .map(|s| view! { <option value=s selected=move || signal.get() == s>{s}</option> })
            .collect_view()
    };
    let add = move |_| {
        let text = fault_text(
            &signal.get_untracked(),
            &kind.get_untracked(),
            &from.get_untracked(),
            hidden.get_untracked(),
        );
        let mut said = None;
        setup.update(|s| {
            if let Some(s) = s {
                said = add_fault(s, text.clone()).err().map(|e| (text, e));
            }
        });
        if said.is_none() {
            ladder.save();
        }
        refusal.set(said);
    };
    view! {
        <div class="plant-fault-add">
            <label>{move || t().signal}
                <select data-testid="plant-fault-signal" on:change=move |e| signal.set(event_target_value(&e))>{signals}</select>
            </label>
            <label>{move || t().kind}
                <select data-testid="plant-fault-kind" on:change=move |e| kind.set(event_target_value(&e))>
                    {KINDS.map(|k| view! { <option value=k>{move || kind_label(t(), k)}</option> }).collect_view()}
                </select>
            </label>
            <label>{move || t().from}
                <input type="text" inputmode="decimal" size="5" data-testid="plant-fault-from"
                    prop:value=move || from.get() on:change=move |e| from.set(event_target_value(&e)) />
            </label>
            <label>
                <input type="checkbox" data-testid="plant-fault-hidden" prop:checked=move || hidden.get()
                    on:change=move |e| hidden.set(event_target_checked(&e)) />
                {move || t().hidden}
            </label>
            <button type="button" data-testid="plant-fault-add" on:click=add>{move || t().add}</button>
            <p class="wiring-refusal" role="alert" data-testid="plant-fault-refusal" hidden=move || refusal.with(Option::is_none)>
                {move || t().refused}{" "}{move || refusal.with(|r| r.as_ref().map(|(text, e)| {
                    format!("{text}: {}", crate::i18n::plant_errors::plant_error(ctx.lang.get(), e))
                }).unwrap_or_default())}
            </p>
        </div>
    }
}

/// The student's report of the hidden fault: the signal and the kind,
/// kept as a fault's text (`infeed stuck 0`) for Check my answer.
#[component]
fn FaultReport(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().plant_faults();
    let report = ladder.cases.report;
    let name = ladder
        .cases
        .plant
        .with_untracked(|s| s.as_ref().map(|s| s.name.clone()).unwrap_or_default());
    let signals = bit_signals(&name);
    let chosen = move |part: usize| {
        report.with(|r| {
            let text = r.0.clone().unwrap_or_default();
            let (signal, kind) = text.split_once(' ').unwrap_or(("", ""));
            [signal, kind][part].to_string()
        })
    };
    // A new choice is a new answer: the last check's verdict on the
    // fault no longer holds.
    let set = move |part: usize, value: String| {
        let mut both = [chosen(0), chosen(1)];
        both[part] = value;
        report.set((Some(both.join(" ")), None));
    };
    let signal_options = signals
        .into_iter()
        .map(|s| {
            view! { <option value=s selected=move || chosen(0) == s>{s}</option> }
        })
        .collect_view();
    view! {
        <fieldset class="fault-report" data-testid="fault-report">
            <legend>{move || t().report}</legend>
            <p>{move || t().report_note}</p>
            <label>{move || t().signal}
                <select data-testid="fault-report-signal" on:change=move |e| set(0, event_target_value(&e))>
                    <option value="" selected=move || chosen(0).is_empty()>{move || t().choose}</option>
                    {signal_options}
                </select>
            </label>
            <label>{move || t().kind}
                <select data-testid="fault-report-kind" on:change=move |e| set(1, event_target_value(&e))>
                    <option value="" selected=move || chosen(1).is_empty()>{move || t().choose}</option>
                    {KINDS.map(|k| view! { <option value=k selected=move || chosen(1) == k>{move || kind_label(t(), k)}</option> }).collect_view()}
                </select>
            </label>
        </fieldset>
    }
}
