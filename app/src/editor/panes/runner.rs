//! Running the Tests pane's cases from the page (issue #17): the case
//! runner itself is a part fetched when the cases first run (issue #53,
//! docs/performance.md "Parts"), so this asks for it and shows what came.

use engine::cases::{prepare_all, run_prepared, Outcome, TestCase};
use engine::formats::project::PlantSetup;
use engine::machines::try_new_plc;
use engine::plant::{fault, wiring, AnyPlant, Fault, Plant, PlantError, Planted, WireEntry};
use engine::plc::{Command, Plc};
use engine::MachineId;
use leptos::prelude::*;

use crate::editor::state::{CaseResult, LadderCtx};
use crate::i18n::errors::{self, Both};
use crate::i18n::{plant_errors, plant_wiring, Lang};
use crate::parts::PartMissing;
use crate::rig::Refusal;

/// Runs every case of `ctx`'s project and shows the results. A ladder
/// that does not compile passes nothing: an exercise says so in its
/// result (every case failed), the author's view in the message line.
pub fn run_all(ctx: LadderCtx) {
    let cases = ctx.cases.tests.get_untracked();
    let Some(listing) = ctx.drawing.listing.get_untracked() else {
        if ctx.cases.exercise.with_untracked(Option::is_some) {
            let failed = CaseResult::Error(Both::default());
            ctx.cases.results.set(vec![Some(failed); cases.len()]);
            return;
        }
        let t = ctx.page.lang.get_untracked().texts();
        ctx.panes
            .message
            .set(Some(t.tests_need_compile.to_string()));
        return;
    };
    let (machine, settings) = (ctx.machine, ctx.settings());
    let plant = ctx.cases.plant.get_untracked();
    let named = ctx.cases.report.with_untracked(|r| r.0.clone());
    // wasm-bindgen's own spawner: a teacher's `?answer` link runs the
    // cases while the page starts, before Leptos' executor is set up.
    wasm_bindgen_futures::spawn_local(async move {
        match run_cases_part(machine, settings, listing.text, cases, plant, named).await {
            Ok((results, right)) => {
                ctx.cases.report.update(|r| r.1 = right);
                ctx.cases
                    .results
                    .set(results.into_iter().map(Some).collect());
            }
            // Where Run was pressed; pressing it again retries the fetch.
            Err(PartMissing) => {
                let said = ctx.page.lang.get_untracked().parts().missing;
                ctx.panes.message.set(Some(said.to_string()));
            }
        }
    });
}

crate::parts::part_fn!(
    tests_runner,
    /// The case runner is a part of its own (issue #53): it is fetched when
    /// the cases are first run. Where the plant hides a fault, also
    /// whether `named` names it (then repaired for the cases).
    fn run_cases_part(
        machine: MachineId,
        settings: Vec<(String, String)>,
        program: String,
        cases: Vec<TestCase>,
        plant: Option<PlantSetup>,
        named: Option<String>,
    ) -> Result<(Vec<CaseResult>, Option<bool>), PartMissing> {
        let (plant, right) = match plant {
            Some(setup) => {
                let (setup, right) = repaired(setup, named.as_deref());
                (Some(setup), right)
            }
            None => (None, None),
        };
        let results = run_cases_with(machine, &settings, &program, &cases, plant.as_ref());
        Ok((results, right))
    }
);

/// `setup` with the hidden faults that `named` names taken away (the
/// student found and so repaired them), and whether it named one; `None`
/// when `setup` hides no fault (docs/plants.md "In the page": a
/// troubleshooting exercise). A fault the engine refuses stays, to be
/// said when the cases attach the plant.
pub fn repaired(mut setup: PlantSetup, named: Option<&str>) -> (PlantSetup, Option<bool>) {
    if !setup.faults.iter().any(|f| fault::is_hidden(f)) {
        return (setup, None);
    }
    let Some(info) = AnyPlant::new(&setup.name).map(|p| p.info()) else {
        return (setup, Some(false));
    };
    let Some(named) = named.and_then(|n| Fault::parse(n, info).ok()) else {
        return (setup, Some(false));
    };
    let before = setup.faults.len();
    setup.faults.retain(|text| {
        let found = Fault::parse(text, info).is_ok_and(|f| f.hidden && f.is_named(&named));
        !found
    });
    let right = setup.faults.len() < before;
    (setup, Some(right))
}

/// Runs `cases` on `machine`, each on a fresh machine with `settings`
/// applied and `program` loaded.
pub fn run_cases(
    machine: MachineId,
    settings: &[(String, String)],
    program: &str,
    cases: &[TestCase],
) -> Vec<CaseResult> {
    run_cases_with(machine, settings, program, cases, None)
}

/// [`run_cases`] with the project's plant, if it has one, attached to
/// each case's machine (issue #52): the cases grade what the plant did
/// (`conveyor.delivered >= 8 at 60s`).
pub fn run_cases_with(
    machine: MachineId,
    settings: &[(String, String)],
    program: &str,
    cases: &[TestCase],
    plant: Option<&PlantSetup>,
) -> Vec<CaseResult> {
    // The work of all the cases is counted before any runs (docs/limits.md).
    let prepared = match prepare_all(cases) {
        Ok(prepared) => prepared,
        Err(e) => {
            let said = Both::new(|lang| errors::case_error(lang, &e));
            return vec![CaseResult::Error(said); cases.len()];
        }
    };
    prepared
        .iter()
        .zip(cases)
        .map(|(case, source)| {
            let case = match case {
                Ok(case) => case,
                Err(e) => return CaseResult::Error(Both::new(|l| errors::case_error(l, e))),
            };
            // The shown machine, whose part is there (else: fetch it again).
            let Some(mut plc) = try_new_plc(machine) else {
                return CaseResult::Error(Both::new(|l| l.parts().missing.to_string()));
            };
            for (name, value) in settings {
                let setting = Command::Setting {
                    name: name.clone(),
                    value: value.clone(),
                };
                if let Err(e) = plc.apply(setting) {
                    let said = |l| format!("{name}={value}: {}", errors::plc_error(l, &e));
                    return CaseResult::Error(Both::new(said));
                }
            }
            if let Err(e) = plc.load_text(program) {
                return CaseResult::Error(Both::new(|l| errors::plc_error(l, &e)));
            }
            let mut plc = match plant {
                Some(setup) => match planted(plc, setup) {
                    Ok(plc) => plc,
                    Err(e) => return CaseResult::Error(Both::new(|l| e.said(l))),
                },
                None => plc,
            };
            match run_prepared(plc.as_mut(), case) {
                Ok(Outcome::Pass) => CaseResult::Pass,
                Ok(Outcome::Fail {
                    expectation, seen, ..
                }) => CaseResult::Fail(Both::new(|l| {
                    format!("{expectation}: {}", errors::observed(l, &seen))
                })),
                Err(e) => match unused_device(machine, program, source, &e) {
                    Some(device) => CaseResult::Unused(device),
                    None => CaseResult::Error(Both::new(|l| errors::case_error(l, &e))),
                },
            }
        })
        .collect()
}

/// Why a case's plant could not be attached, kept as a value so that it
/// is said in either language, as the Plant dock says it.
enum SetupRefused {
    /// The plant's name, its parameters or one of its faults (the fault
    /// as written).
    Plant(Option<String>, PlantError),
    /// A wiring row (1-based) the plant and the machine do not take.
    Row(usize, Refusal),
    /// A row refused in the engine's words only (not met: the rows are
    /// checked typed first).
    Words(usize, String),
}

impl SetupRefused {
    fn said(&self, lang: Lang) -> String {
        let row = |row: usize, r: &str| match lang {
            Lang::En => format!("plant wiring entry {row}: {r}"),
            Lang::Ja => format!("プラントの配線 {row} 行目: {r}"),
        };
        match self {
            SetupRefused::Plant(None, e) => plant_errors::plant_error(lang, e),
            SetupRefused::Plant(Some(fault), e) => {
                format!("{fault}: {}", plant_errors::plant_error(lang, e))
            }
            SetupRefused::Row(n, r) => row(*n, &plant_wiring::refusal(lang, r)),
            SetupRefused::Words(n, r) => row(*n, r),
        }
    }
}

/// `plc` with `setup`'s plant attached: its wiring, faults and
/// parameters, or the first thing wrong with them.
fn planted(plc: Box<dyn Plc>, setup: &PlantSetup) -> Result<Box<dyn Plc>, Box<SetupRefused>> {
    let mut plant = AnyPlant::new(&setup.name).ok_or_else(|| {
        SetupRefused::Plant(
            None,
            PlantError::NoPlant {
                name: setup.name.clone(),
                known: AnyPlant::names(),
            },
        )
    })?;
    plant
        .set_params(&setup.params)
        .map_err(|e| SetupRefused::Plant(None, e))?;
    let info = plant.info();
    let faults = setup
        .faults
        .iter()
        .map(|f| {
            Fault::parse(f, info).map_err(|e| Box::new(SetupRefused::Plant(Some(f.clone()), e)))
        })
        .collect::<Result<Vec<_>, _>>()?;
    // The rows (or the machine's default, as `Planted::new` makes it) are
    // checked here, typed, for the refusal to be said in the page's
    // language; `Planted::new` then checks the same rows again.
    let entries: Vec<WireEntry> = match &setup.wiring {
        Some(rows) => rows
            .iter()
            .enumerate()
            .map(|(i, [signal, device])| WireEntry {
                signal: signal.clone(),
                device: device.clone(),
                line: i + 1,
            })
            .collect(),
        None => {
            let mut entries = wiring::default_wiring(info, plc.as_ref()).0;
            entries.retain(|e| plc.device(&e.device).is_ok());
            entries
        }
    };
    if let Err(errors) = wiring::check(info, plc.as_ref(), &entries) {
        if let Some(e) = errors.into_iter().next() {
            return Err(Box::new(SetupRefused::Row(e.line, Refusal::Wire(e.error))));
        }
    }
    let planted = Planted::new(plc, plant, Some(&entries), faults).map_err(|errors| {
        let said: Vec<_> = errors.iter().map(|e| e.error.clone()).collect();
        SetupRefused::Words(errors.first().map_or(0, |e| e.line), said.join("; "))
    })?;
    Ok(Box::new(planted))
}

/// The device a case could not find, when that is because the program
/// does not use it yet: the soft PLC has only the devices its program
/// declares or uses, so an empty ladder has no `%IX0.0`. Other machines
/// have a fixed set of devices: a name they lack is the author's error.
fn unused_device(
    machine: MachineId,
    program: &str,
    case: &TestCase,
    e: &engine::cases::CaseError,
) -> Option<String> {
    use engine::cases::CaseError;
    // Only a machine whose program names its I/O (word boxes, variables:
    // the soft PLC) can be told of a device its program never uses.
    if !machine.target().capabilities().word_boxes {
        return None;
    }
    let device = match e {
        CaseError::Event(at) => engine::events::parse_events(&case.events)
            .ok()?
            .into_iter()
            .find(|ev| ev.line == at.line)?
            .device
            .clone(),
        CaseError::Device(i, _) => engine::cases::Expectation::parse(case.expect.get(*i)?)
            .ok()?
            .device()
            .to_string(),
        _ => return None,
    };
    let unknown = e.to_string().contains("unknown device");
    (unknown && !program.contains(device.as_str())).then_some(device)
}
