//! The plant dock (issue #52, docs/plants.md "In the page"): a simulated
//! machine for the ladder to control, coupled to the running machine.
//!
//! Only this thin shell is in the first screen: the dock's tab, the
//! plant select, the [`Rig`] interface the frame loop calls and what it
//! publishes ([`Shown`]). The plants' engine, the coupling and the
//! drawing are a part (`plants`) fetched when a plant is first chosen:
//! [`plant_kit`] hands back function pointers ([`Kit`]) and the rig it
//! builds is a boxed trait object made inside the part, so that nothing
//! the first screen reaches names a plant's code.

mod draw;
mod faults;
mod history;
mod manual;
mod params;
mod rig;
mod series;
mod wiring;

mod above;
pub use above::PlantAbove;

use engine::formats::project::PlantSetup;
use leptos::prelude::*;

pub use crate::rig::{Build, Refusal, Refusals, Rig, RigSlot, Shown, SignalShown};

use crate::editor::LadderCtx;
use crate::parts::{Draw, PartMissing};
use crate::state::Ctx;

/// The plants the select offers, in the engine's order.
pub const PLANTS: [&str; 6] = [
    "conveyor",
    "tank",
    "traffic",
    "door",
    "sorter",
    "room-light",
];

/// What the `plants` part hands back: plain function pointers into it.
#[derive(Clone, Copy)]
pub struct Kit {
    /// Couples a plant to the machine, or refuses (each refusal at its
    /// wiring row, 1-based; 0: not a row's).
    pub build: Build,
    /// The dock's drawing (the figure, signals, alarms, wiring).
    pub draw: Draw,
    /// The figure alone, above the ladder on a phone.
    pub above: Draw,
}

/// The plant dock's state, page-wide (one workspace shows at a time).
#[derive(Clone, Copy)]
pub struct Plants {
    /// The part's functions, once fetched.
    pub kit: RwSignal<Option<Kit>>,
    /// What the shown workspace's rig last published.
    pub shown: RwSignal<Option<Shown>>,
    /// Refusals of the chosen setup (wiring row, message).
    pub refusals: RwSignal<Refusals>,
    /// Manual mode: the user drives the actuators, the machine stopped.
    pub manual: RwSignal<bool>,
}

impl Plants {
    /// No plant yet.
    pub fn new() -> Plants {
        Plants {
            kit: RwSignal::new(None),
            shown: RwSignal::new(None),
            refusals: RwSignal::new(Vec::new()),
            manual: RwSignal::new(false),
        }
    }

    /// The dock's state from the context.
    pub fn get() -> Plants {
        expect_context::<Plants>()
    }

    /// After a frame of `ladder`'s machine: publishes what its rig shows
    /// (only when it changed, so a still plant redraws nothing).
    pub fn publish(&self, ladder: LadderCtx) {
        // Travelling: the shown scan's time (the plant as it was then).
        let past = ladder
            .recorded(|t| t.shown().map(|_| t.plc().now()))
            .flatten();
        let mut out = None;
        ladder.with_rig(|machine, rig| {
            if let Some(rig) = rig {
                out = Some(match past {
                    Some(at) => rig.show_at(at),
                    None => rig.show(machine),
                });
            }
        });
        // No rig (none chosen, refused, or the machine still on its
        // way): nothing drawn, never another workspace's plant.
        if self.shown.with_untracked(|s| s.as_ref() != out.as_ref()) {
            self.shown.set(out);
        }
    }

    /// Couples `setup`'s plant to `ladder`'s machine (none: uncouples),
    /// fetching the part first; the rig in place is kept when it was
    /// built from the same setup.
    fn couple(&self, ladder: LadderCtx, setup: Option<PlantSetup>) {
        let Some(setup) = setup else {
            ladder.with_rig(|machine, rig| {
                if let Some(mut old) = rig.take() {
                    old.detach(machine);
                }
            });
            self.shown.set(None);
            self.refusals.set(Vec::new());
            return;
        };
        // The part's place in the dock fetches it; coupled when it comes.
        let Some(kit) = self.kit.get_untracked() else {
            return;
        };
        // A machine still on its way (its part): coupled when it comes,
        // to the setup its project has then.
        if !ladder.attached() {
            let plants = *self;
            ladder.when_attached(move || plants.couple(ladder, ladder.cases.plant.get_untracked()));
            return;
        }
        let mut refused = Vec::new();
        ladder.with_rig(|machine, rig| {
            if rig.as_ref().is_some_and(|r| r.setup() == &setup) {
                return;
            }
            if let Some(mut old) = rig.take() {
                old.detach(machine);
            }
            match (kit.build)(&setup, machine) {
                Ok(new) => *rig = Some(new),
                Err(e) => refused = e,
            }
        });
        self.refusals.set(refused);
        self.publish(ladder);
    }
}

impl Default for Plants {
    fn default() -> Self {
        Plants::new()
    }
}

crate::parts::part_fn!(
    plants,
    /// The plants' engine, coupling and drawing: a part of its own
    /// (issue #52), fetched when a plant is first chosen.
    fn plant_kit() -> Result<Kit, PartMissing> {
        Ok(Kit {
            build: rig::build,
            draw: draw::draw,
            above: draw::above,
        })
    }
);

/// The plant dock: the select, then the plant as the part draws it.
#[component]
pub fn PlantDock(ladder: LadderCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let plants = Plants::get();
    let setup = ladder.cases.plant;
    // Couples the plant whenever the setup changes or the part arrives
    // (and when this workspace is shown again).
    Effect::new(move || {
        let chosen = setup.get();
        plants.kit.track();
        plants.couple(ladder, chosen);
    });
    let t = move || ctx.lang.get().plant();
    let chosen = move || setup.with(|s| s.as_ref().map(|s| s.name.clone()).unwrap_or_default());
    let choose = move |name: String| {
        let next = PLANTS.contains(&name.as_str()).then(|| PlantSetup {
            name,
            ..PlantSetup::default()
        });
        setup.set(next);
        ladder.save();
    };
    let options = move || {
        PLANTS
            .iter()
            .map(|&name| {
                view! {
                    <option value=name selected=move || chosen() == name>
                        {move || t().plant_name(name)}
                    </option>
                }
            })
            .collect_view()
    };
    // The part's place, made again only when a plant comes or goes (a
    // new wiring redraws from the same part).
    let chosen_any = Memo::new(move |_| setup.with(Option::is_some));
    let body = move || {
        if !chosen_any.get() {
            return view! { <p class="plant-idle">{move || t().idle}</p> }.into_any();
        }
        // The part's loader says "Loading…" and offers a retry if the
        // fetch fails; the kit it brings also couples the plant.
        let load = move || async move {
            let kit = plant_kit().await?;
            let _ = plants.kit.try_set(Some(kit));
            Ok(kit.draw)
        };
        crate::parts::part("plant-part", ctx.lang.into(), load).into_any()
    };
    view! {
        <section class="plant-dock" data-testid="plant">
            <label class="plant-choose">
                <span>{move || t().choose}</span>
                <select data-testid="plant-select"
                    on:change=move |e| choose(event_target_value(&e))>
                    <option value="" selected=move || chosen().is_empty()>{move || t().none}</option>
                    {options}
                </select>
            </label>
            {body}
        </section>
    }
}

#[cfg(test)]
mod faults_tests;
#[cfg(test)]
mod tests;
