//! The plant coupled to a page's machine (issue #52), natively: the
//! conveyor delivers under the book's ladder, the tank's overflow is an
//! alarm with its time, refusals land at their wiring row, and the plant
//! stands still while the machine does.

use engine::formats::project::PlantSetup;
use engine::machines::MinasecPlc;
use engine::plc::{Command, Plc};
use engine::record::Recorded;
use engine::SimTime;

use super::rig;
use crate::i18n::Lang;
use crate::sim::{Pace, Simulator, Speed};

const CONVEYOR: &str = include_str!("../../../engine/programs/minasec-u/conveyor.il");

fn setup(name: &str) -> PlantSetup {
    PlantSetup {
        name: name.to_string(),
        ..PlantSetup::default()
    }
}

fn minasec(program: &str) -> Recorded<MinasecPlc> {
    let mut m = Recorded::new(MinasecPlc::new());
    m.load_text(program).unwrap();
    let t1 = Command::Setting {
        name: "T1".into(),
        value: "1s".into(),
    };
    m.apply(t1).unwrap();
    m
}

fn quantity(shown: &super::Shown, name: &str) -> i64 {
    shown.quantities.iter().find(|(n, _)| *n == name).unwrap().1
}

#[test]
fn the_books_ladder_runs_the_belt_and_parts_are_delivered() {
    let mut m = minasec(CONVEYOR);
    let mut rig = rig::build(&setup("conveyor"), &mut m).unwrap();
    for _ in 0..600 {
        rig.advance(&mut m, SimTime::from_millis(100));
    }
    let shown = rig.show(&m);
    assert_eq!(m.now(), SimTime::from_secs(60));
    assert!(quantity(&shown, "delivered") >= 8, "{shown:?}");
    // The sensors reached the machine's inputs through the default wiring.
    let devices: Vec<_> = shown.signals.iter().map(|s| s.device.clone()).collect();
    assert_eq!(
        devices,
        [Some("X00".into()), Some("X01".into()), Some("Y00".into())]
    );
    assert!(shown.alarms.is_empty(), "{:?}", shown.alarms);
}

#[test]
fn a_ladder_that_keeps_fill_on_raises_the_overflow_alarm_with_its_time() {
    // fill is the tank's first actuator: Y00 by default.
    let mut m = minasec("000 LDI X07\n001 ST Y00\n");
    let mut rig = rig::build(&setup("tank"), &mut m).unwrap();
    rig.advance(&mut m, SimTime::from_secs(5));
    let shown = rig.show(&m);
    assert!(shown.alarms.is_empty(), "{:?}", shown.alarms);
    for _ in 0..5 {
        rig.advance(&mut m, SimTime::from_secs(10));
    }
    let shown = rig.show(&m);
    let (at, message) = shown.alarms.first().expect("an overflow alarm");
    assert!(
        message.contains("overflow") || message.contains("full"),
        "{message}"
    );
    // 50 % at the start, +8 %/s in, -2 %/s drawn: full at about 8.3 s.
    assert!((8_000..9_000).contains(at), "{at}");
    assert_eq!(shown.figure.first(), Some(&100_000));
}

#[test]
fn an_analog_signal_on_minasec_u_is_refused_at_its_row() {
    let mut m = minasec(CONVEYOR);
    let mut s = setup("tank");
    s.wiring = Some(vec![
        ["fill".into(), "Y00".into()],
        ["level".into(), "X04".into()],
    ]);
    let refused = rig::build(&s, &mut m).err().expect("refused");
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].0, 2);
    // Said in the page's language from its kind.
    let said = |lang| crate::i18n::plant_wiring::refusal(lang, &refused[0].1);
    assert!(said(Lang::En).contains("analog"), "{}", said(Lang::En));
    assert_eq!(
        said(Lang::Ja),
        "tank.level はアナログ信号ですが、X04 はアナログ入力ではありません (minasec-u にはアナログ入力がありません)"
    );
}

#[test]
fn the_default_rows_name_every_signal_and_leave_the_analog_one_open() {
    let m = minasec(CONVEYOR);
    let rows = super::wiring::default_rows("tank", &m);
    let rows: Vec<String> = rows.iter().map(|[s, d]| format!("{s},{d}")).collect();
    assert_eq!(
        rows,
        ["low,X00", "high,X01", "level,", "fill,Y00", "drain,Y01"]
    );
}

/// The book's ladder on MINASEC-U's simulator, the conveyor coupled.
fn conveyor_sim() -> Simulator<MinasecPlc> {
    let mut sim = Simulator::new(MinasecPlc::new());
    let (m, slot) = sim.machine_and_rig();
    m.load_text(CONVEYOR).unwrap();
    *slot = Some(rig::build(&setup("conveyor"), m).unwrap());
    sim
}

#[test]
fn max_speed_ends_a_scan_after_each_frame_however_late() {
    let mut sim = conveyor_sim();
    let scan = sim.machine().next_scan_end().unwrap() - sim.machine().now();
    assert!(
        scan > SimTime::from_millis(2),
        "a scan longer than a plant's slice: {scan:?}"
    );
    let max = Pace {
        speed: Speed::Max,
        paused: false,
    };
    for n in 1..=3 {
        // The frame left no time: its deadline has passed.
        sim.after_frame(max, -1.0, || 0.0);
        assert_eq!(sim.machine().scans(), n);
    }
}

#[test]
fn the_plant_stands_still_while_paused_or_stopped() {
    let mut sim = conveyor_sim();
    let pace = |paused| Pace {
        speed: Speed::Times(100),
        paused,
    };
    let shown = |sim: &mut Simulator<MinasecPlc>| {
        let (m, slot) = sim.machine_and_rig();
        slot.as_ref().unwrap().show(m)
    };
    for _ in 0..30 {
        sim.frame(pace(false), 16.0);
    }
    let running = shown(&mut sim);
    assert!(quantity(&running, "placed") >= 1, "{running:?}");
    for _ in 0..30 {
        sim.frame(pace(true), 16.0);
    }
    assert_eq!(shown(&mut sim), running);
    sim.machine_mut().apply(Command::Run(false)).unwrap();
    for _ in 0..30 {
        sim.frame(pace(false), 16.0);
    }
    let stopped = shown(&mut sim);
    assert_eq!(quantity(&stopped, "placed"), quantity(&running, "placed"));
    assert!(!stopped.running);
}

#[test]
fn the_tests_runner_grades_the_books_conveyor_with_its_plant() {
    use crate::editor::panes::runner::{run_cases, run_cases_with};
    use crate::editor::state::CaseResult;
    use engine::formats::Project;
    let project = Project::from_json(include_str!(
        "../../../engine/programs/minasec-u/conveyor.json"
    ))
    .unwrap();
    let settings: Vec<_> = project.settings.clone().into_iter().collect();
    let plant = project.plant.clone();
    assert!(plant.is_some());
    let results = run_cases_with(
        engine::MachineId::MinasecU,
        &settings,
        CONVEYOR,
        &project.tests,
        plant.as_ref(),
    );
    assert!(!results.is_empty());
    assert!(
        results.iter().all(|r| matches!(r, CaseResult::Pass)),
        "{results:?}"
    );
    // Without the plant the cases cannot name its quantities.
    let without = run_cases(
        engine::MachineId::MinasecU,
        &settings,
        CONVEYOR,
        &project.tests,
    );
    assert!(without.iter().any(|r| !matches!(r, CaseResult::Pass)));
}

#[test]
fn the_tanks_figure_says_its_level_as_the_quantity_does() {
    // 66.6 % is the quantity `level` 66: the figure said 67 (rounded).
    assert_eq!(super::draw::percent_said(66_600), "66 %");
    assert_eq!(super::draw::percent_said(100_000), "100 %");
    assert_eq!(super::draw::percent_said(999), "0 %");
}

#[test]
fn the_chart_and_watch_read_the_plant_as_it_stood_at_each_time() {
    // The tank's fill kept open: the level rises to full and runs over.
    let mut m = minasec("000 LDI X07\n001 ST Y00\n");
    let mut rig = rig::build(&setup("tank"), &mut m).unwrap();
    let mut seen = Vec::new();
    for _ in 0..12 {
        rig.advance(&mut m, SimTime::from_secs(1));
        seen.push((m.now(), quantity(&rig.show(&m), "level")));
    }
    let times: Vec<SimTime> = seen.iter().map(|(t, _)| *t).collect();
    let level = rig.series("tank.level", &times).expect("a quantity");
    let expected: Vec<_> = seen.iter().map(|(_, l)| Some(*l)).collect();
    assert_eq!(level, expected);
    // 50 % + (8 - 2) %/s for a second, less the first scan (rounded down).
    assert_eq!(level[0], Some(55));
    // A signal: the fill valve on from the first scan; `alarms` counts.
    let fill = rig.series("tank.fill", &times).unwrap();
    assert!(fill.iter().all(|v| *v == Some(1)), "{fill:?}");
    let alarms = rig.series("tank.alarms", &times).unwrap();
    assert_eq!(alarms[7], Some(0), "{alarms:?}");
    assert_eq!(alarms[9], Some(1), "overflow at about 8.3 s: {alarms:?}");
    // The high switch (at 80 %) reads 0 at 4 s (73 %), 1 at 6 s (85 %).
    let high = rig.series("tank.high", &[times[3], times[5]]).unwrap();
    assert_eq!(high, [Some(0), Some(1)]);
    // Before the plant was coupled it has no value; no such names.
    assert_eq!(
        rig.series("tank.level", &[SimTime::ZERO]),
        Some(vec![Some(50)])
    );
    assert_eq!(rig.series("tank.belt", &times), None);
    assert_eq!(rig.series("conveyor.level", &times), None);
    assert_eq!(rig.series("tank", &times), None);
}

#[test]
fn the_tank_couples_on_the_io86a_by_default_with_its_level_left_open() {
    // X04 is analog only in analog mode, which the page's IO86A does
    // not keep: the default leaves the level unwired, as on MINASEC-U.
    let mut m = Recorded::new(engine::machines::Io86aPlc::new());
    let rows = super::wiring::default_rows("tank", &m);
    let rows: Vec<String> = rows.iter().map(|[s, d]| format!("{s},{d}")).collect();
    assert_eq!(
        rows,
        ["low,X00", "high,X01", "level,", "fill,Y00", "drain,Y01"]
    );
    let rig = rig::build(&setup("tank"), &mut m).expect("coupled");
    let level = rig.show(&m).signals.into_iter().find(|s| s.name == "level");
    assert_eq!(level.and_then(|s| s.device), None);
}

#[test]
fn a_power_cycle_puts_the_plant_back_at_its_start() {
    let mut m = minasec(CONVEYOR);
    let mut rig = rig::build(&setup("conveyor"), &mut m).unwrap();
    rig.advance(&mut m, SimTime::from_secs(30));
    let before = rig.show(&m);
    assert!(quantity(&before, "delivered") >= 1, "{before:?}");
    let at = m.now();
    m.apply(Command::PowerCycle).unwrap();
    rig.power_cycle(&mut m);
    let after = rig.show(&m);
    for q in ["placed", "delivered", "on_belt"] {
        assert_eq!(quantity(&after, q), 0, "{q}: {after:?}");
    }
    // The chart shows the drop at the cycle; before it, the plant as it was.
    let delivered = rig.series("conveyor.delivered", &[at - SimTime::from_millis(1), at]);
    assert_eq!(
        delivered,
        Some(vec![Some(quantity(&before, "delivered")), Some(0)])
    );
    // It runs from its start again: the first part arrives as at power-on
    // (239 ms with seed 1), on the machine's clock from the cycle.
    m.apply(Command::Run(true)).unwrap();
    rig.advance(&mut m, SimTime::from_millis(238));
    assert_eq!(quantity(&rig.show(&m), "placed"), 0);
    rig.advance(&mut m, SimTime::from_millis(2));
    assert_eq!(quantity(&rig.show(&m), "placed"), 1);
}

#[test]
fn watch_is_offered_each_plant_name_it_takes() {
    let mut m = minasec(CONVEYOR);
    for name in super::PLANTS {
        let mut rig = rig::build(&setup(name), &mut m).unwrap();
        rig.advance(&mut m, SimTime::from_millis(10));
        let names = rig.show(&m).device_names();
        // Every signal and quantity, and the alarms, once each.
        let info = engine::plant::AnyPlant::new(name).unwrap();
        let info = engine::plant::Plant::info(&info);
        for s in info.signals.iter().map(|s| s.name) {
            assert!(
                names.contains(&format!("{name}.{s}")),
                "{name}.{s}: {names:?}"
            );
        }
        for q in info.quantities.iter().map(|q| q.name) {
            assert!(
                names.contains(&format!("{name}.{q}")),
                "{name}.{q}: {names:?}"
            );
        }
        assert!(names.contains(&format!("{name}.alarms")), "{names:?}");
        let mut once = names.clone();
        once.sort();
        once.dedup();
        assert_eq!(once.len(), names.len(), "{names:?}");
        // Each is a name the plant's series (Watch, the chart) takes.
        for n in &names {
            let values = rig.series(n, &[m.now()]);
            assert!(values.is_some_and(|v| v[0].is_some()), "{n}");
        }
        rig.detach(&mut m);
    }
}

#[test]
fn the_tests_runner_says_a_refused_plant_setup_in_the_pages_language() {
    use crate::editor::panes::runner::run_cases_with;
    use crate::editor::state::CaseResult;
    use engine::formats::Project;
    let project = Project::from_json(include_str!(
        "../../../engine/programs/minasec-u/conveyor.json"
    ))
    .unwrap();
    let settings: Vec<_> = project.settings.clone().into_iter().collect();
    let said = |plant: PlantSetup| {
        let results = run_cases_with(
            engine::MachineId::MinasecU,
            &settings,
            CONVEYOR,
            &project.tests[..1],
            Some(&plant),
        );
        match &results[0] {
            CaseResult::Error(both) => (both.en.clone(), both.ja.clone()),
            other => panic!("not refused: {other:?}"),
        }
    };
    // A wiring row: said at its row, in each language.
    let mut wired = setup("conveyor");
    wired.wiring = Some(vec![
        ["motor".into(), "Y00".into()],
        ["nosuch".into(), "X00".into()],
    ]);
    let (en, ja) = said(wired);
    assert!(en.starts_with("plant wiring entry 2: "), "{en}");
    assert!(ja.starts_with("プラントの配線 2 行目: "), "{ja}");
    assert!(ja.contains("信号 \"nosuch\" はありません"), "{ja}");
    // A fault: said after the fault as written.
    let mut faulty = setup("conveyor");
    faulty.faults = vec!["infeed dead".into()];
    let (en, ja) = said(faulty);
    assert!(en.starts_with("infeed dead: "), "{en}");
    assert!(ja.contains("センサー"), "{ja}");
    // A parameter.
    let mut tuned = setup("conveyor");
    tuned.params.insert("length".into(), "many".into());
    let (en, ja) = said(tuned);
    assert!(en.contains("length") && en.contains("many"), "{en}");
    assert!(ja.contains("整数"), "{ja}");
}

#[test]
fn a_part_is_drawn_at_its_place_on_the_belt_and_clipped_at_its_ends() {
    use super::draw::part_box;
    // A 2 m belt, 0.2 m parts: one half way in, one entering, one leaving.
    let figure = [2_000_000, 200_000, 1_100_000, 100_000, 2_100_000];
    let middle = part_box(&figure, 0).unwrap();
    // Its tail at 0.9 m of 2 m: 40 + 0.45 x 520 units; a tenth of the belt
    // long; its left edge 4.5 of its own lengths along.
    assert!((middle.x - 274.0).abs() < 1e-9, "{middle:?}");
    assert!((middle.width - 10.0).abs() < 1e-9 && (middle.at - 450.0).abs() < 1e-9);
    // Entering: its tail before the belt's start, drawn from the start and
    // placed half a length back (the belt's box clips it).
    let entering = part_box(&figure, 1).unwrap();
    assert!((entering.x - 40.0).abs() < 1e-9 && (entering.at + 50.0).abs() < 1e-9);
    // Leaving: past the end, clipped there.
    let leaving = part_box(&figure, 2).unwrap();
    assert!((leaving.at - 950.0).abs() < 1e-9);
    assert_eq!(part_box(&figure, 3), None, "no fourth part");
    assert_eq!(part_box(&[], 0), None);
    let flat = part_box(&[2_000_000, 0, 5], 0).unwrap();
    assert_eq!(
        (flat.width, flat.at),
        (0.0, 0.0),
        "a part without length is not drawn"
    );
}
