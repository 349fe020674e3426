//! Recording and time travel (issue #16) on all five machines: any
//! recorded scan comes back exactly, and a machine resumed from one runs
//! on exactly as the original did.

use engine::events::InputValue;
use engine::machines::{ArduinoPlc, AvrPlc, Io86aPlc, MinasecPlc};
use engine::plc::{Command, Plc};
use engine::record::{run_scans, Mark, Recording, DEFAULT_BUDGET, KEYFRAME_EVERY};
use engine::SimTime;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// What the user does between frames.
#[derive(Clone, Debug)]
enum Action {
    /// A frame of this many simulated milliseconds.
    Frame(u64),
    /// Input `n` (of the machine's list) on or off.
    Set(usize, bool),
    StepScan,
    StepInstruction,
}

fn action() -> impl Strategy<Value = Action> {
    prop_oneof![
        6 => (1u64..60).prop_map(Action::Frame),
        3 => (0usize..3, any::<bool>()).prop_map(|(n, on)| Action::Set(n, on)),
        1 => Just(Action::StepScan),
        1 => Just(Action::StepInstruction),
    ]
}

/// A machine with a seed example loaded, and the inputs it reads.
fn loaded<M: Plc>(mut m: M, text: &str, inputs: &[&str]) -> (M, Vec<engine::plc::Device>) {
    m.load_text(text).expect("the example loads");
    let inputs = inputs.iter().map(|n| m.device(n).expect("input")).collect();
    (m, inputs)
}

/// What a run under a recording gives: the recording, after each action
/// the last mark and the time, and the truth: every scan's image and end
/// time as a twin machine, driven the same way with no recording, showed
/// them.
struct Recorded<M> {
    rec: Recording<M>,
    after: Vec<(Mark, SimTime)>,
    truth: Vec<(Vec<u8>, SimTime)>,
}

fn record<M: Plc + Clone>(
    m: &mut M,
    inputs: &[engine::plc::Device],
    actions: &[Action],
    budget: usize,
) -> Recorded<M> {
    let mut twin = m.clone();
    let mut truth = vec![shot(&twin)];
    let mut rec = Recording::new(m, budget);
    let mut after = Vec::new();
    for a in actions {
        act(&mut rec, m, inputs, a);
        let seen = twin.scans();
        match *a {
            Action::Frame(ms) => {
                let t = twin.now().saturating_add(SimTime::from_millis(ms));
                run_scans(&mut twin, t, |x| {
                    truth.push(shot(x));
                    true
                });
            }
            Action::Set(n, on) => {
                let d = inputs[n % inputs.len()];
                let value = InputValue::Int(i64::from(on));
                twin.apply(Command::SetInput(d, value)).expect("input");
            }
            Action::StepScan => twin.step_scan(),
            Action::StepInstruction => {
                twin.step_instruction();
            }
        }
        if !matches!(a, Action::Frame(_)) && twin.scans() != seen {
            truth.push(shot(&twin));
        }
        after.push((rec.last(), m.now()));
    }
    Recorded { rec, after, truth }
}

/// A machine's image and time.
fn shot<M: Plc>(m: &M) -> (Vec<u8>, SimTime) {
    let mut image = Vec::new();
    m.image_into(&mut image);
    (image, m.now())
}

fn act<M: Plc + Clone>(
    rec: &mut Recording<M>,
    m: &mut M,
    inputs: &[engine::plc::Device],
    a: &Action,
) {
    match *a {
        Action::Frame(ms) => {
            rec.tick(m, SimTime::from_millis(ms), None);
        }
        Action::Set(n, on) => {
            let d = inputs[n % inputs.len()];
            rec.apply(m, Command::SetInput(d, InputValue::Int(i64::from(on))))
                .expect("a bit input");
        }
        Action::StepScan => rec.step_scan(m),
        Action::StepInstruction => {
            rec.step_instruction(m);
        }
    }
}

fn images<M: Plc + Clone>(rec: &mut Recording<M>, from: Mark) -> Vec<(Vec<u8>, SimTime)> {
    (from..=rec.last())
        .map(|k| {
            let mut image = Vec::new();
            assert!(rec.image_at(k, &mut image), "mark {k} kept");
            (image, rec.time_at(k).expect("kept"))
        })
        .collect()
}

/// Every mark replays to the image and time recorded; resuming at the
/// mark an action left and doing again what followed that scan records
/// the same scans.
fn check<M: Plc + Clone>(
    m: M,
    inputs: &[engine::plc::Device],
    actions: &[Action],
    resume_at: usize,
) -> Result<(), TestCaseError> {
    let mut live = m.clone();
    let Recorded {
        mut rec,
        after,
        truth,
    } = record(&mut live, inputs, actions, DEFAULT_BUDGET);
    prop_assert_eq!(rec.last() + 1, truth.len() as u64, "one mark per scan");
    let mut image = Vec::new();
    for k in rec.first()..=rec.last() {
        let again = rec.machine_at(k).expect("every kept mark replays");
        let (true_image, true_time) = &truth[k as usize];
        again.image_into(&mut image);
        prop_assert_eq!(&image, true_image, "the machine at mark {}", k);
        prop_assert_eq!(again.now(), *true_time, "its time at mark {}", k);
        prop_assert_eq!(rec.time_at(k), Some(*true_time), "time at mark {}", k);
        prop_assert!(rec.image_at(k, &mut image), "kept");
        prop_assert_eq!(&image, true_image, "the image at mark {}", k);
    }
    let (mark, _) = after[resume_at % after.len()];
    let mut branch = rec.clone();
    let mut resumed = branch.resume_from(mark).expect("the mark is kept");
    prop_assert_eq!(branch.last(), mark, "later scans dropped");
    // What came after that scan: the rest of the action that completed it
    // (a frame runs on to its end), then every later action.
    let next = match after.iter().position(|&(m, _)| m == mark) {
        Some(p) if mark > 0 => {
            if let Action::Frame(_) = actions[p] {
                branch.run(&mut resumed, after[p].1, None);
            }
            p + 1
        }
        _ => 0,
    };
    for a in &actions[next..] {
        act(&mut branch, &mut resumed, inputs, a);
    }
    prop_assert_eq!(branch.last(), rec.last(), "as many scans");
    prop_assert_eq!(images(&mut branch, mark), images(&mut rec, mark));
    Ok(())
}

fn property<M: Plc + Clone>(m: M, inputs: Vec<engine::plc::Device>, cases: u32) {
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    let strategy = (prop::collection::vec(action(), 1..40), any::<usize>());
    runner
        .run(&strategy, |(actions, resume_at)| {
            check(m.clone(), &inputs, &actions, resume_at)
        })
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn every_recorded_scan_replays_and_resumes_exactly_on_minasec_u() {
    let (m, inputs) = loaded(
        MinasecPlc::new(),
        engine::minasec::SEED_TEST_PROGRAM,
        &["X00", "X01", "X02"],
    );
    property(m, inputs, 24);
}

#[test]
fn every_recorded_scan_replays_and_resumes_exactly_on_io86a() {
    let text = include_str!("../../programs/io86a/timer.il");
    let (m, inputs) = loaded(Io86aPlc::new(), text, &["X00", "X01"]);
    property(m, inputs, 32);
}

#[test]
fn every_recorded_scan_replays_and_resumes_exactly_on_avr_plc() {
    let text = include_str!("../../programs/avr-plc/e-stop-timer.asm");
    let (m, inputs) = loaded(AvrPlc::new(), text, &["Run", "Direct"]);
    property(m, inputs, 32);
}

#[test]
fn every_recorded_scan_replays_and_resumes_exactly_on_arduino_plc() {
    let text = include_str!("../../programs/arduino-plc/self-hold.txt");
    let (m, inputs) = loaded(ArduinoPlc::new(), text, &["X000", "X001"]);
    property(m, inputs, 24);
}

#[test]
fn the_oldest_scans_go_first_once_over_budget_and_the_rest_still_replay() {
    let text = include_str!("../../programs/io86a/timer.il");
    let (mut m, inputs) = loaded(Io86aPlc::new(), text, &["X00"]);
    let budget = 64 << 10;
    let mut rec = Recording::new(&m, budget);
    for n in 0..400u64 {
        let on = InputValue::Int(i64::from(n % 3 == 0));
        rec.apply(&mut m, Command::SetInput(inputs[0], on))
            .expect("input");
        rec.tick(&mut m, SimTime::from_millis(25), None);
    }
    assert!(rec.first() > 0, "old scans dropped");
    assert_eq!(
        rec.first() % KEYFRAME_EVERY,
        0,
        "a whole keyframe at a time"
    );
    assert!(rec.bytes() <= budget, "{} bytes over {budget}", rec.bytes());
    assert!(rec.machine_at(rec.first() - 1).is_none(), "dropped is gone");
    let mut image = Vec::new();
    for k in [rec.first(), rec.first() + 1, rec.last() - 1, rec.last()] {
        let again = rec.machine_at(k).expect("kept");
        again.image_into(&mut image);
        let mut recorded = Vec::new();
        assert!(rec.image_at(k, &mut recorded));
        assert_eq!(image, recorded, "mark {k}");
    }
    // 10 000 scans at 1 ms, each reading X00 and a timer.
    assert_eq!(rec.last(), 10_000);
}

/// The seed program under a recording: press start, break when the count
/// lamp Y01 rises (the count reached 10), look five scans back.
#[test]
fn the_seed_breaks_when_its_count_lamp_rises_and_shows_the_scans_before() {
    use engine::record::{Condition, Recorded};
    let (m, inputs) = loaded(
        MinasecPlc::new(),
        engine::minasec::SEED_TEST_PROGRAM,
        &["X00"],
    );
    let mut r = Recorded::new(m);
    // The book's panel: RV1 1.1 s, RV2 1 s, the counter set to 10.
    for (name, value) in [("T0", "1.1s"), ("T1", "1s"), ("C0", "10")] {
        let setting = Command::Setting {
            name: name.into(),
            value: value.into(),
        };
        r.apply(setting).expect("a panel setting");
    }
    let count = r.device("C0.v").expect("count");
    let y01 = r.device("Y01").expect("lamp");
    let stop = Condition::parse("Y01 rises", &r).expect("condition");
    r.set_break(Some(stop));
    let press = |r: &mut Recorded<MinasecPlc>, on: i64| {
        r.apply(Command::SetInput(inputs[0], InputValue::Int(on)))
            .expect("start button");
    };
    press(&mut r, 1);
    r.tick(SimTime::from_millis(200));
    press(&mut r, 0);
    let mut hit = None;
    for _ in 0..600 {
        r.tick(SimTime::from_millis(100));
        hit = r.take_break();
        if hit.is_some() {
            break;
        }
    }
    let hit = hit.expect("the count lamp rose within a minute");
    assert_eq!(r.recording().last(), hit.mark, "stopped at that scan's end");
    assert_eq!((r.read(y01).as_i64(), r.read(count).as_i64()), (1, 10));
    assert_eq!(r.breaks(), &[hit.mark]);
    // Five scans back the lamp was off and the count one lower.
    assert!(r.show(hit.mark - 5));
    assert_eq!(r.shown(), Some(hit.mark - 5));
    assert_eq!((r.read(y01).as_i64(), r.read(count).as_i64()), (0, 9));
    let then = r.now();
    assert!(then < r.recording_mut().time_at(hit.mark).expect("kept"));
    // Back to live, then resume from a past scan: the later scans go.
    r.go_live();
    assert_eq!(r.read(count), 10);
    assert!(r.show(hit.mark - 5));
    assert!(r.resume_here());
    assert_eq!(r.recording().last(), hit.mark - 5);
    assert_eq!(r.shown(), None);
    assert!(r.breaks().is_empty(), "the break's scan was dropped");
    // Run on: the same rise comes again, at the same scan.
    for _ in 0..100 {
        r.tick(SimTime::from_millis(100));
        if let Some(again) = r.take_break() {
            assert_eq!(again.mark, hit.mark, "deterministic");
            return;
        }
    }
    panic!("the rise came again");
}

/// Anything that changes the machine while a past scan is shown resumes
/// from it; a refused command changes nothing, not even the travel.
#[test]
fn operating_a_past_scan_resumes_from_it_and_a_refusal_changes_nothing() {
    use engine::record::Recorded;
    let text = include_str!("../../programs/io86a/timer.il");
    let (m, inputs) = loaded(Io86aPlc::new(), text, &["X00"]);
    let mut r = Recorded::new(m);
    r.tick(SimTime::from_millis(50));
    let last = r.recording().last();
    assert!(last >= 40, "{last} scans");
    assert!(r.show(10));
    let y00 = r.device("Y00").expect("output");
    assert!(r.apply(Command::SetInput(y00, InputValue::Int(1))).is_err());
    assert_eq!(r.shown(), Some(10), "still travelling");
    assert_eq!(r.recording().last(), last, "nothing dropped");
    r.apply(Command::SetInput(inputs[0], InputValue::Int(1)))
        .expect("X00 is an input");
    assert_eq!(r.shown(), None, "live again, from scan 10");
    assert_eq!(r.recording().last(), 10);
}

/// A case the property once found: resuming at the frame before an input
/// changes, on the AVR PLC (10 ms scans).
#[test]
fn resuming_just_before_an_input_change_replays_it() {
    let text = include_str!("../../programs/avr-plc/e-stop-timer.asm");
    let (m, inputs) = loaded(AvrPlc::new(), text, &["Run", "Direct"]);
    let actions = [
        Action::Frame(53),
        Action::Frame(27),
        Action::Frame(55),
        Action::Frame(31),
        Action::Frame(47),
        Action::Set(0, true),
        Action::Frame(4),
        Action::Frame(3),
    ];
    for resume_at in 0..7 {
        check(m.clone(), &inputs, &actions, resume_at)
            .unwrap_or_else(|e| panic!("{resume_at}: {e}"));
    }
}

/// `nth_scan_end` says when the n-th scan from now ends: running scan by
/// scan meets each prediction exactly (so recording, which runs in one go
/// to just before a keyframe, takes its copy at a scan's end).
fn predictions_hold<M: Plc + Clone>(mut m: M) {
    // Mid-scan, as after a Step instruction.
    m.step_instruction();
    let predicted: Vec<Option<SimTime>> = (1..=300).map(|n| m.nth_scan_end(n)).collect();
    let mut ends = Vec::new();
    let far = predicted[299]
        .expect("a prediction")
        .saturating_add(SimTime::from_secs(1));
    run_scans(&mut m, far, |x| {
        ends.push(x.now());
        ends.len() < 300
    });
    let predicted: Vec<SimTime> = predicted
        .into_iter()
        .map(|p| p.expect("predicted"))
        .collect();
    assert_eq!(predicted, ends, "{:?}", m.id());
}

#[test]
fn each_machine_says_when_its_nth_scan_ends() {
    let (m, _) = loaded(MinasecPlc::new(), engine::minasec::SEED_TEST_PROGRAM, &[]);
    predictions_hold(m);
    let (m, _) = loaded(
        Io86aPlc::new(),
        include_str!("../../programs/io86a/timer.il"),
        &[],
    );
    predictions_hold(m);
    let (m, _) = loaded(
        AvrPlc::new(),
        include_str!("../../programs/avr-plc/e-stop-timer.asm"),
        &[],
    );
    predictions_hold(m);
    let text = include_str!("../../programs/arduino-plc/self-hold.txt");
    let (m, _) = loaded(ArduinoPlc::new(), text, &[]);
    predictions_hold(m);
}

/// The page's view of a recording: each scan's time and a device's value,
/// made by replay on demand, agree with what the machine showed live.
#[test]
fn series_and_last_change_read_what_the_machine_showed() {
    use engine::record::{Recorded, TimeTravel};
    let text = include_str!("../../programs/io86a/timer.il");
    let (m, inputs) = loaded(Io86aPlc::new(), text, &["X00"]);
    let mut r = Recorded::new(m);
    let y00 = r.device("Y00").expect("output");
    let mut live = vec![r.read(y00).as_i64()];
    // 600 scans at 1 ms, X00 pressed at 100 ms (past the keyframes at
    // 256 and 512, so images come from three replays).
    for ms in 1..=600u64 {
        if ms == 100 {
            r.apply(Command::SetInput(inputs[0], InputValue::Int(1)))
                .expect("input");
        }
        r.tick(SimTime::from_millis(1));
        live.push(r.read(y00).as_i64());
    }
    let travel: &mut dyn TimeTravel = &mut r;
    let (first, last) = travel.marks();
    assert_eq!((first, last), (0, 600));
    let series = travel.series("Y00", first, last).expect("a device");
    let series: Vec<i64> = series
        .into_iter()
        .map(|v| v.expect("in the image").as_i64())
        .collect();
    assert_eq!(series, live);
    let times = travel.times(first, last);
    assert_eq!(times.len(), 601);
    assert_eq!(times[600], SimTime::from_millis(600));
    let rose = live.iter().position(|&v| v == 1).expect("Y00 came on") as u64;
    assert_eq!(travel.last_change("Y00", last), Some(rose));
    assert_eq!(
        travel.last_change("Y00", rose - 1),
        None,
        "off since power-on"
    );
    assert!(travel.series("Q9", first, last).is_err());
    assert!(travel.set_break("Y00 wobbles").is_err());
    assert!(travel.set_break("Y01 rises").is_ok());
}

#[test]
fn every_recorded_scan_replays_and_resumes_exactly_on_the_soft_plc() {
    // Words, a timer, a counter and an edge: all of its state.
    let text =
        "VAR\n  count : INT;\n  t : TON;\n  c : CTU;\n  e : R_TRIG;\n  up : BOOL;\nEND_VAR\n\
                CAL e(CLK := %IX0.0, Q => up)\n\
                LD up\nJMPCN skip\nLD count\nADD 7\nST count\n\
                skip: LD %IX0.1\nST %QX0.0\n\
                CAL t(IN := %IX0.1, PT := T#30ms)\n\
                CAL c(CU := %IX0.0, R := %IX0.1, PV := 3)\n";
    let (m, inputs) = loaded(
        engine::machines::SoftPlc::new(),
        text,
        &["%IX0.0", "%IX0.1"],
    );
    property(m, inputs, 32);
}
