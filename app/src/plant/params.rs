//! The plant's parameters in the dock (part `plants`; docs/plants.md "In
//! the page"): each as the engine has it (`speed`, mm/s, its range), set
//! in the project (kept in projects and share links, as `--set
//! conveyor.speed=500` gives it) or at its default. A value out of range,
//! not a number, or that does not fit with the others (a part longer than
//! half the belt) is refused at its field and the project is left as it
//! was; a value taken couples the plant anew from its start.

use engine::formats::project::PlantSetup;
use engine::plant::error::PlantError;
use engine::plant::{any::ALL, parse_param, AnyPlant, Plant, PlantInfo};
use leptos::prelude::*;

use crate::editor::LadderCtx;
use crate::state::Ctx;

/// `setup` with parameter `key` set to `text` (empty: back to its
/// default), checked as the engine checks a `--set`: each value in its
/// range, all of them together; else why not.
pub(super) fn set_param(
    setup: &PlantSetup,
    key: &str,
    text: &str,
) -> Result<PlantSetup, PlantError> {
    let mut next = setup.clone();
    let text = text.trim();
    if text.is_empty() {
        next.params.remove(key);
    } else {
        next.params.insert(key.to_string(), text.to_string());
    }
    let Some(mut plant) = AnyPlant::new(&next.name) else {
        return Err(PlantError::NoPlant {
            name: next.name.clone(),
            known: AnyPlant::names(),
        });
    };
    let info = plant.info();
    for (k, v) in &next.params {
        let Some(i) = info.params.iter().position(|p| p.key == k) else {
            let known: Vec<_> = info.params.iter().map(|p| p.key).collect();
            return Err(PlantError::UnknownParam {
                plant: info.name,
                key: k.clone(),
                known: known.join(", "),
            });
        };
        plant.set_param(i, parse_param(&info.params[i], v)?);
    }
    plant.check().map_err(PlantError::Together)?;
    Ok(next)
}

/// The chosen plant's parameters, each a field.
#[component]
pub(super) fn Params(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let setup = ladder.cases.plant;
    let t = move || crate::i18n::plant_wiring::texts(ctx.lang.get());
    // The last refusal: the parameter's key and why.
    let refused = RwSignal::new(None::<(String, PlantError)>);
    // The fields follow the plant chosen (the dock's drawing stays).
    let name = Memo::new(move |_| setup.with(|s| s.as_ref().map(|s| s.name.clone())));
    let rows = move || {
        let name = name.get().unwrap_or_default();
        let info: Option<&'static PlantInfo> = ALL.iter().copied().find(|p| p.name == name);
        info.map(|i| i.params).unwrap_or_default()
        .iter()
        .map(|p| {
            let key = p.key;
            let value = move || {
                setup.with(|s| s.as_ref().and_then(|s| s.params.get(key).cloned()))
                    .unwrap_or_else(|| p.default.to_string())
            };
            let change = move |text: String| {
                let Some(now) = setup.get_untracked() else { return };
                match set_param(&now, key, &text) {
                    Ok(next) => {
                        refused.set(None);
                        if next != now {
                            setup.set(Some(next));
                            ladder.save();
                        }
                    }
                    Err(e) => refused.set(Some((key.to_string(), e))),
                }
            };
            let why = move || {
                refused.with(|r| {
                    r.as_ref()
                        .filter(|(k, _)| k == key)
                        .map(|(_, e)| crate::i18n::plant_wiring::param_error(ctx.lang.get(), e))
                })
            };
            let range = format!("{}..{} {}", p.min, p.max, p.unit);
            view! {
                <tr>
                    <th scope="row"><label for=format!("plant-param-{key}")>{key}</label>
                        <small>{" "}{range.trim_end().to_string()}</small></th>
                    <td>
                        <input type="text" id=format!("plant-param-{key}") data-testid=format!("plant-param-{key}")
                            inputmode=if p.unit == "ms" { "text" } else { "numeric" } spellcheck="false"
                            aria-invalid=move || why().is_some().to_string()
                            prop:value=value
                            on:change=move |e| change(event_target_value(&e)) />
                        <span class="wiring-refusal" role="alert" data-testid=format!("plant-param-refusal-{key}")
                            hidden=move || why().is_none()>{why}</span>
                    </td>
                </tr>
            }
        })
        .collect_view()
    };
    view! {
        <section class="plant-wiring plant-params" data-testid="plant-params" aria-label=move || t().params>
            <h3>{move || t().params}</h3>
            <p class="plant-params-note">{move || t().params_note}</p>
            <table><tbody>{rows}</tbody></table>
        </section>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conveyor() -> PlantSetup {
        PlantSetup {
            name: "conveyor".into(),
            ..PlantSetup::default()
        }
    }

    #[test]
    fn a_parameter_in_range_is_kept_as_written_and_empty_is_the_default() {
        let next = set_param(&conveyor(), "speed", " 500 ").unwrap();
        assert_eq!(next.params.get("speed").map(String::as_str), Some("500"));
        // A time for an ms parameter, as --set takes it.
        let next = set_param(&next, "interval", "2.5s").unwrap();
        assert_eq!(next.params.len(), 2);
        let back = set_param(&next, "speed", "").unwrap();
        assert_eq!(back.params.get("speed"), None);
    }

    #[test]
    fn out_of_range_not_a_number_or_not_fitting_is_refused_and_nothing_changes() {
        let setup = set_param(&conveyor(), "speed", "500").unwrap();
        let e = set_param(&setup, "speed", "20000").unwrap_err();
        assert!(
            matches!(e, PlantError::OutOfRange { value: 20000, .. }),
            "{e:?}"
        );
        assert_eq!(
            e.to_string(),
            "speed = 20000 is out of range (1..10000 mm/s)"
        );
        let e = set_param(&setup, "speed", "fast").unwrap_err();
        assert!(matches!(e, PlantError::NotANumber { .. }), "{e:?}");
        // A part longer than half the belt (2000 mm): the plant's check.
        let e = set_param(&setup, "part", "1500").unwrap_err();
        assert!(matches!(e, PlantError::Together(_)), "{e:?}");
        assert_eq!(setup.params.len(), 1);
    }
}
