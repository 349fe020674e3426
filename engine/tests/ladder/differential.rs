//! Differential tests: random ladders × random input timelines, compiled
//! for each machine and run on its emulator, against the reference
//! evaluator, compared after every scan. 500 cases per machine in the
//! normal run; `cargo test -p engine --test ladder -- --ignored` runs
//! 10 000. Shrunk failures are kept as regression tests at the end.

use engine::events::InputValue;
use engine::ladder::compile::{compile_logic, Options};
use engine::ladder::eval::Reference;
use engine::ladder::{Ladder, RungLogic};
use engine::machines::new_plc;
use engine::machines::{decompile, Source};
use engine::plc::{Command, Plc};

use crate::strategies::{case, pool, Pool};
use engine::{arduino, avr, io86a, minasec, MachineId, SimTime};
use proptest::test_runner::{Config, TestCaseError, TestRunner};

/// A machine under test, stepped one scan (pass) per input vector.
struct Timing {
    /// Time between input vectors (one scan).
    period: SimTime,
    /// When, within a period, inputs are applied and outputs read.
    offset: SimTime,
    /// Periods from applying inputs to reading the scan that used them.
    latency: u64,
}

/// Periods from applying inputs to reading the scan that used them:
/// MINASEC-U latches inputs at a scan boundary, the others at scan start.
fn latency(machine: MachineId) -> u64 {
    if machine == MachineId::MinasecU {
        2
    } else {
        1
    }
}

fn load(machine: MachineId, text: &str) -> Result<(Box<dyn Plc>, Timing), String> {
    let fail = |e: String| format!("compiled program does not load: {e}\n{text}");
    let mut plc = new_plc(machine);
    plc.load_text(text).map_err(|e| fail(e.to_string()))?;
    let (period, offset) = match machine {
        MachineId::MinasecU => {
            let clock = SimTime::from_micros(33);
            let period = SimTime::from_nanos(clock.as_nanos() * 256);
            let offset = SimTime::from_nanos(period.as_nanos() / 2 + clock.as_nanos() / 2);
            (period, offset)
        }
        MachineId::Io86a => {
            plc.apply(Command::Setting {
                name: "filter".into(),
                value: "0".into(),
            })
            .map_err(|e| e.to_string())?;
            (SimTime::from_millis(1), SimTime::from_micros(500))
        }
        MachineId::AvrPlc | MachineId::SoftPlc => {
            (SimTime::from_millis(10), SimTime::from_millis(5))
        }
        MachineId::ArduinoPlc => {
            let program = arduino::Program::parse(text, 512).map_err(|e| fail(format!("{e:?}")))?;
            let steps = program.words().len() as u64;
            let step = SimTime::from_micros(10);
            (
                SimTime::from_nanos(step.as_nanos() * steps),
                SimTime::from_micros(5),
            )
        }
    };
    let timing = Timing {
        period,
        offset,
        latency: latency(machine),
    };
    Ok((plc, timing))
}

/// Drives an input bit by name.
fn input(plc: &mut dyn Plc, device: &str, on: bool) {
    if let Ok(d) = plc.device(device) {
        let _ = plc.apply(Command::SetInput(d, InputValue::Int(i64::from(on))));
    }
}

/// A bit by name, as the last scan left it.
fn bit(plc: &dyn Plc, device: &str) -> Result<bool, String> {
    let d = plc.device(device).map_err(|e| e.to_string())?;
    Ok(plc.read(d) != 0)
}

/// Runs one case; `Ok(false)` when the ladder needs more than the machine
/// has (temporaries, steps), which the generator cannot foresee.
fn check(machine: MachineId, rungs: &[RungLogic], timeline: &[Vec<bool>]) -> Result<bool, String> {
    // Through the grid and back: the editor's model carries the logic.
    let ladder = Ladder::from_logic(rungs);
    let logic = ladder
        .logic(machine)
        .map_err(|e| format!("drawn ladder does not read back: {e:?}"))?;
    for (a, b) in rungs.iter().zip(&logic) {
        let (a, b) = (
            a.condition.without_positions(),
            b.condition.without_positions(),
        );
        if a.clone().normalised() != b {
            return Err(format!("layout changed the logic:\n{a:?}\n{b:?}"));
        }
    }
    let text = match compile_logic(&logic, machine, Options::default()) {
        Ok(t) => t,
        Err(e) if beyond_the_machine(&e) => return Ok(false),
        Err(e) => return Err(format!("compile failed: {e:?}")),
    };
    let p = pool(machine);
    // Devices the ladder leaves alone are the compiler's to use.
    let mentioned = |d: &str| {
        rungs.iter().any(|r| {
            r.outputs.iter().any(|(e, _)| e.written_device() == Some(d))
                || r.condition
                    .leaves()
                    .iter()
                    .any(|(e, _)| e.read_device() == Some(d))
        })
    };
    let watched: Vec<&str> = p.outputs.iter().copied().filter(|d| mentioned(d)).collect();
    let mut expected = Vec::new();
    reference_run(machine, logic, timeline, |reference, _| {
        expected.push(watched.iter().map(|d| reference.get(d)).collect::<Vec<_>>());
    })?;
    let got = machine_run(machine, &text, p.inputs, timeline, &watched)?;
    if let Some(read) = (0..expected.len()).find(|&j| got[j] != expected[j]) {
        let drawn: Vec<String> = rungs
            .iter()
            .map(|r| {
                let outs: Vec<String> = r.outputs.iter().map(|(e, _)| e.to_string()).collect();
                format!(
                    "{:?} -> {}",
                    r.condition.without_positions(),
                    outs.join(", ")
                )
            })
            .collect();
        return Err(format!(
            "scan {read}: {:?} = machine {:?}, reference {:?}\ninputs: {:?}\nladder:\n{}\nprogram:\n{text}",
            watched,
            got[read],
            expected[read],
            &timeline[..=read],
            drawn.join("\n")
        ));
    }
    Ok(true)
}

/// Runs the reference evaluator over `timeline` as `machine` sees it (a
/// scan per input vector, after the scans a latched machine runs before
/// the first), calling `each` after every vector's scan with its powers.
fn reference_run(
    machine: MachineId,
    logic: Vec<RungLogic>,
    timeline: &[Vec<bool>],
    mut each: impl FnMut(&Reference, Vec<Vec<engine::ladder::eval::ElementPower>>),
) -> Result<(), String> {
    let p = pool(machine);
    let mut reference = Reference::new(logic, 10).map_err(|e| format!("{e:?}"))?;
    if machine == MachineId::SoftPlc {
        reference = reference.with_iec_timers();
    }
    // A machine whose inputs wait for a scan boundary has run scans with
    // every input off before the first vector arrives.
    for _ in 1..latency(machine) {
        reference.scan();
    }
    for inputs in timeline {
        for (d, &on) in p.inputs.iter().zip(inputs) {
            reference.set(d, on);
        }
        let powers = reference.scan();
        each(&reference, powers);
    }
    Ok(())
}

/// Runs `text` on `machine` with one input vector a scan; returns the
/// watched devices after each of those scans.
fn machine_run(
    machine: MachineId,
    text: &str,
    inputs: &[&str],
    timeline: &[Vec<bool>],
    watched: &[&str],
) -> Result<Vec<Vec<bool>>, String> {
    let (mut sim, timing) = load(machine, text)?;
    let at = |j: u64| SimTime::from_nanos(j * timing.period.as_nanos() + timing.offset.as_nanos());
    let mut out = Vec::new();
    for j in 0..timeline.len() as u64 + timing.latency {
        sim.run_until(at(j));
        if j >= timing.latency {
            out.push(
                watched
                    .iter()
                    .map(|d| bit(sim.as_ref(), d))
                    .collect::<Result<Vec<_>, _>>()?,
            );
        }
        if let Some(vector) = timeline.get(j as usize) {
            for (d, &on) in inputs.iter().zip(vector) {
                input(sim.as_mut(), d, on);
            }
        }
    }
    Ok(out)
}

/// Limits of the machine the generator cannot foresee.
fn beyond_the_machine(e: &[engine::ladder::LadderError]) -> bool {
    e.iter().all(|e| {
        e.message.contains("temporary")
            || e.message.contains("steps")
            || e.message.contains("no relay")
    })
}

/// compile(decompile(x)) behaves like x, x being a compiled random ladder.
fn check_decompile(
    machine: MachineId,
    rungs: &[RungLogic],
    timeline: &[Vec<bool>],
) -> Result<bool, String> {
    let text = match compile_logic(rungs, machine, Options::default()) {
        Ok(t) => t,
        Err(e) if beyond_the_machine(&e) => return Ok(false),
        Err(e) => return Err(format!("compile failed: {e:?}")),
    };
    let ladder = match machine {
        MachineId::MinasecU => decompile(Source::Minasec(
            &minasec::Program::parse(&text).map_err(|e| format!("{e:?}"))?,
        )),
        MachineId::Io86a => decompile(Source::Io86a(
            &io86a::Program::parse(&text).map_err(|e| format!("{e:?}"))?,
        )),
        MachineId::AvrPlc => decompile(Source::Avr(
            &avr::Program::parse(&text, 10).map_err(|e| format!("{e:?}"))?,
            10,
        )),
        MachineId::ArduinoPlc => decompile(Source::Arduino(
            &arduino::Program::parse(&text, 512).map_err(|e| format!("{e:?}"))?,
        )),
        MachineId::SoftPlc => decompile(Source::Soft(
            &engine::softplc::Program::load(&text).map_err(|e| format!("{e:?}"))?,
        )),
    }
    .map_err(|e| format!("decompile failed: {e}\n{text}"))?;
    let again = match engine::ladder::compile::compile(&ladder, machine, Options::default()) {
        Ok(t) => t,
        Err(e) => return Err(format!("recompile failed: {e:?}\n{text}")),
    };
    let p = pool(machine);
    let watched: Vec<&str> = p
        .outputs
        .iter()
        .copied()
        .filter(|d| {
            rungs.iter().any(|r| {
                r.outputs
                    .iter()
                    .any(|(e, _)| e.written_device() == Some(*d))
            })
        })
        .collect();
    let a = machine_run(machine, &text, p.inputs, timeline, &watched)?;
    let b = machine_run(machine, &again, p.inputs, timeline, &watched)?;
    if a != b {
        return Err(format!(
            "{watched:?}\noriginal {a:?}\nround trip {b:?}\nprogram:\n{text}\nagain:\n{again}"
        ));
    }
    Ok(true)
}

fn differential(machine: MachineId, cases: u32) {
    property(machine, cases, check);
}

pub type Check = fn(MachineId, &[RungLogic], &[Vec<bool>]) -> Result<bool, String>;

/// Runs `check` over `cases` random ladders and timelines for `machine`;
/// most of them must fit the machine.
pub fn property(machine: MachineId, cases: u32, check: Check) {
    let p: &'static Pool = Box::leak(Box::new(pool(machine)));
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    let ran = std::cell::Cell::new(0u32);
    let result = runner.run(&case(p), |(rungs, timeline)| {
        match check(machine, &rungs, &timeline) {
            Ok(done) => {
                ran.set(ran.get() + u32::from(done));
                Ok(())
            }
            Err(e) => Err(TestCaseError::fail(e)),
        }
    });
    if let Err(e) = result {
        panic!("{machine}: {e}");
    }
    // Most cases must fit the machine, or the test proves little (the
    // Arduino sketch, with no relays, refuses about one case in five).
    let ran = ran.get();
    assert!(
        ran * 10 >= cases * 6,
        "{machine}: only {ran} of {cases} cases compiled"
    );
}

#[test]
fn minasec_u_matches_the_reference() {
    differential(MachineId::MinasecU, 500);
}

#[test]
fn io86a_matches_the_reference() {
    differential(MachineId::Io86a, 500);
}

#[test]
fn avr_plc_matches_the_reference() {
    differential(MachineId::AvrPlc, 500);
}

#[test]
fn arduino_plc_matches_the_reference() {
    differential(MachineId::ArduinoPlc, 500);
}

#[test]
fn soft_plc_matches_the_reference() {
    differential(MachineId::SoftPlc, 500);
}

#[test]
#[ignore = "10 000 cases per machine: run with --ignored"]
fn every_machine_matches_the_reference_10000() {
    for m in MachineId::ALL {
        differential(m, 10_000);
    }
}

#[test]
fn decompiled_programs_behave_like_the_originals() {
    for m in MachineId::ALL {
        property(m, 300, check_decompile);
    }
}

// ----- Shrunk failures found while building the compilers, kept fixed. -----

fn leaf(kind: engine::ladder::ContactKind, d: &str) -> engine::ladder::Net {
    engine::ladder::Net::Leaf(
        engine::ladder::Element::Contact {
            kind,
            device: d.into(),
        },
        engine::ladder::Pos::new(0, 0),
    )
}

fn coil(kind: engine::ladder::CoilKind, d: &str) -> (engine::ladder::Element, engine::ladder::Pos) {
    (
        engine::ladder::Element::Coil {
            kind,
            device: d.into(),
        },
        engine::ladder::Pos::new(0, 0),
    )
}

fn logic(
    condition: engine::ladder::Net,
    outputs: Vec<(engine::ladder::Element, engine::ladder::Pos)>,
) -> RungLogic {
    RungLogic {
        condition,
        outputs,
        comment: String::new(),
        sides: Vec::new(),
    }
}

#[test]
fn regression_io86a_outputs_keep_their_order_around_an_inverted_coil() {
    use engine::ladder::{CoilKind as K, ContactKind as C};
    // (!M01) then (M01): the last write wins, as drawn.
    let rungs = [logic(
        leaf(C::No, "X00"),
        vec![coil(K::Inverted, "M01"), coil(K::Normal, "M01")],
    )];
    assert_eq!(
        check(
            MachineId::Io86a,
            &rungs,
            &[vec![false; 4], vec![true, false, false, false]]
        ),
        Ok(true)
    );
}

#[test]
fn regression_avr_edge_memory_is_never_another_rungs_temporary() {
    use engine::ladder::{CoilKind as K, ContactKind as C, Net};
    let rising = || leaf(C::Rising, "R0.0");
    let rungs = [
        logic(
            Net::Series(vec![rising(), leaf(C::No, "R0.0")]),
            vec![coil(K::Normal, "R1.0")],
        ),
        logic(
            Net::Series(vec![rising(), leaf(C::No, "R0.2")]),
            vec![coil(K::Normal, "R1.0")],
        ),
    ];
    assert_eq!(
        check(MachineId::AvrPlc, &rungs, &[vec![true, false, true, false]]),
        Ok(true)
    );
}

#[test]
fn regression_parallel_branches_keep_their_order_through_the_grid() {
    use engine::ladder::{CoilKind as K, ContactKind as C, Net};
    let x = || leaf(C::No, "X00");
    let rungs = [logic(
        Net::Parallel(vec![
            x(),
            Net::Series(vec![x(), leaf(C::Nc, "X01")]),
            leaf(C::No, "X02"),
        ]),
        vec![coil(K::Normal, "Y00")],
    )];
    assert_eq!(
        check(
            MachineId::MinasecU,
            &rungs,
            &[vec![true, false, false, false]]
        ),
        Ok(true)
    );
}

#[test]
fn regression_arduino_refuses_a_result_it_cannot_keep() {
    use engine::ladder::{CoilKind as K, ContactKind as C};
    // Set Y002 changes what the rung reads before Set Y000 needs it.
    let rungs = [logic(
        leaf(C::No, "Y002"),
        vec![coil(K::Set, "Y002"), coil(K::Set, "Y000")],
    )];
    let e = compile_logic(&rungs, MachineId::ArduinoPlc, Options::default()).expect_err("no relay");
    assert!(e[0].message.contains("split the rung"), "{e:?}");
}

/// The live ladder's colours (issue #14): for random ladders and inputs,
/// each element's power in each scan, walked from the machine's own trace
/// through the compiler's source map, equals the reference evaluator's.
fn check_colours(
    machine: MachineId,
    rungs: &[RungLogic],
    timeline: &[Vec<bool>],
) -> Result<bool, String> {
    use engine::ladder::live::LiveLadder;
    let ladder = Ladder::from_logic(rungs);
    let logic = ladder.logic(machine).map_err(|e| format!("{e:?}"))?;
    let live = match LiveLadder::new(&ladder, machine, Options::default()) {
        Ok(l) => l,
        Err(e) if beyond_the_machine(&e) => return Ok(false),
        Err(e) => return Err(format!("compile failed: {e:?}")),
    };
    let p = pool(machine);
    let mut expected = Vec::new();
    reference_run(machine, logic, timeline, |_, powers| expected.push(powers))?;
    let text = &live.listing.text;
    let (mut sim, timing) = load(machine, text)?;
    sim.set_tracing(true);
    let at = |j: u64| SimTime::from_nanos(j * timing.period.as_nanos() + timing.offset.as_nanos());
    // Each element's power seen on / off since the history was last taken.
    let mut seen: std::collections::HashMap<(usize, engine::ladder::Pos), (bool, bool)> =
        std::collections::HashMap::new();
    for j in 0..timeline.len() as u64 + timing.latency {
        sim.run_until(at(j));
        if j >= timing.latency {
            let k = (j - timing.latency) as usize;
            let trace = sim.trace().ok_or("tracing on, but no scan traced")?;
            for (rung, report) in live.power(trace) {
                for e in report {
                    let s = seen.entry((rung, e.pos)).or_default();
                    if e.power_out {
                        s.0 = true;
                    } else {
                        s.1 = true;
                    }
                }
            }
            // Every third scan, as a frame would: no change is lost.
            if k % 3 == 2 {
                let pulses = live.pulses(&sim.take_trace_history());
                for ((rung, pos), (on, off)) in seen.drain() {
                    let marked = pulses
                        .iter()
                        .any(|(r, p)| *r == rung && p.iter().any(|x| x.pos == pos));
                    if on && off && !marked {
                        return Err(format!(
                            "scan {k}: rung {rung} {pos:?} changed but is not marked\nprogram:\n{text}"
                        ));
                    }
                }
            }
            let trace = sim.trace().ok_or("tracing on, but no scan traced")?;
            let got: Vec<Vec<(bool, bool)>> = live
                .power(trace)
                .into_iter()
                .map(|(_, r)| r.iter().map(|e| (e.power_in, e.power_out)).collect())
                .collect();
            let want: Vec<Vec<(bool, bool)>> = expected[k]
                .iter()
                .map(|r| r.iter().map(|e| (e.power_in, e.power_out)).collect())
                .collect();
            if got != want {
                return Err(format!(
                    "scan {k}: machine colours {got:?}\nreference {want:?}\ninputs {:?}\nprogram:\n{text}",
                    &timeline[..=k]
                ));
            }
        }
        if let Some(vector) = timeline.get(j as usize) {
            for (d, &on) in p.inputs.iter().zip(vector) {
                input(sim.as_mut(), d, on);
            }
        }
    }
    Ok(true)
}

#[test]
fn the_live_colours_are_the_machines_own_on_every_machine() {
    for machine in MachineId::ALL {
        property(machine, 200, check_colours);
    }
}

/// The guided first rung's devices (issue #47, `Capabilities::starter`):
/// the self-hold the tour asks for, drawn with them, runs on each machine
/// as the reference runs it, and the reference latches and releases.
#[test]
fn each_machines_first_rung_devices_run_a_self_hold() {
    use engine::ladder::edit::{Cursor, Edit, Editor};
    use engine::ladder::Element;
    for machine in MachineId::ALL {
        let [start, stop, out] = engine::ladder::target::capabilities(machine).starter;
        assert_eq!(&pool(machine).inputs[..2], &[start, stop], "{machine:?}");
        let mut editor = Editor::new(Ladder::default());
        let edits = [
            Edit::Place {
                at: Cursor::new(0, 0, 0),
                element: Element::no(start),
            },
            Edit::Place {
                at: Cursor::new(0, 0, 1),
                element: Element::nc(stop),
            },
            Edit::Place {
                at: Cursor::new(0, 0, 2),
                element: Element::coil(out),
            },
            Edit::PlaceBranch {
                at: Cursor::new(0, 1, 0),
                element: Element::no(out),
            },
        ];
        for edit in edits {
            editor.apply(edit).expect("the edit applies");
        }
        let logic = editor.ladder().logic(machine).expect("the self-hold reads");
        // Idle, start, let go, stop, let go.
        let timeline: Vec<Vec<bool>> = [
            (false, false),
            (true, false),
            (false, false),
            (false, true),
            (false, false),
        ]
        .iter()
        .map(|&(a, b)| vec![a, b, false, false])
        .collect();
        assert_eq!(check(machine, &logic, &timeline), Ok(true), "{machine:?}");
        let mut seen = Vec::new();
        reference_run(machine, logic, &timeline, |r, _| seen.push(r.get(out))).expect("it runs");
        assert_eq!(seen, [false, true, true, false, false], "{machine:?}");
    }
}
