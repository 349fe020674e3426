//! Word data differential tests (issue #30): random ladders of contacts,
//! comparisons, function blocks and output boxes on INT and DINT
//! variables, compiled for the soft PLC and run on it, against the
//! reference evaluator's word data, compared after every scan (bits and
//! words). 300 cases in the normal run; `--ignored` runs 5 000.

use engine::events::InputValue;
use engine::ladder::compile::{compile, Options};
use engine::ladder::eval::Reference;
use engine::ladder::{
    BlockCall, CoilKind, ContactKind, Element, Ladder, Net, Pos, RungLogic, Variable,
};
use engine::machines::new_plc;
use engine::plc::Command;
use engine::{MachineId, SimTime};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

const INPUTS: [&str; 3] = ["%IX0.0", "%IX0.1", "%IX0.2"];
const BITS: [&str; 3] = ["%QX0.0", "%QX0.1", "m"];
const WORDS: [&str; 3] = ["w0", "w1", "w2"];

fn variables() -> Vec<Variable> {
    let mut w0 = Variable::new("w0", "INT");
    w0.initial = "3".into();
    let mut v = vec![w0, Variable::new("w1", "INT"), Variable::new("w2", "INT")];
    v.push(Variable::new("d0", "DINT"));
    v
}

fn call(kind: &str, inputs: &[(&str, String)], outputs: &[(&str, &str)]) -> BlockCall {
    BlockCall {
        kind: kind.into(),
        instance: String::new(),
        inputs: inputs
            .iter()
            .map(|(p, o)| (p.to_string(), o.clone()))
            .collect(),
        outputs: outputs
            .iter()
            .map(|(p, v)| (p.to_string(), v.to_string()))
            .collect(),
    }
}

fn operand() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(WORDS.to_vec()).prop_map(String::from),
        (-40i32..40).prop_map(|n| n.to_string()),
        Just("INT#32767".to_string()),
    ]
}

/// An in-line box of block `kind`, instance `instance`.
fn instance(
    kind: &str,
    instance: String,
    inputs: &[(&str, String)],
    outputs: &[(&str, &str)],
) -> Net {
    let mut c = call(kind, inputs, outputs);
    c.instance = instance;
    leaf(Element::Block(c))
}

fn leaf(e: Element) -> Net {
    Net::Leaf(e, Pos::new(0, 0))
}

fn contact() -> impl Strategy<Value = Net> {
    let devices: Vec<&str> = INPUTS.iter().chain(&BITS).copied().collect();
    (
        prop::sample::select(devices),
        prop::sample::select(vec![ContactKind::No, ContactKind::Nc, ContactKind::Rising]),
    )
        .prop_map(|(d, kind)| {
            leaf(Element::Contact {
                kind,
                device: d.into(),
            })
        })
}

/// An in-line box: a comparison, a timer, a counter or an edge.
fn inline_box(n: usize) -> impl Strategy<Value = Net> {
    prop_oneof![
        (
            prop::sample::select(vec!["GT", "GE", "EQ", "NE", "LE", "LT"]),
            operand(),
            operand()
        )
            .prop_map(|(k, a, b)| leaf(Element::Block(call(
                k,
                &[("IN1", a), ("IN2", b)],
                &[]
            )))),
        (1u32..6).prop_map(move |t| {
            instance(
                "TON",
                format!("t{n}"),
                &[("PT", format!("T#{}ms", t * 10))],
                &[],
            )
        }),
        (1i32..5, prop::sample::select(INPUTS.to_vec())).prop_map(move |(pv, r)| {
            let inputs = [("R", r.to_string()), ("PV", pv.to_string())];
            instance("CTU", format!("c{n}"), &inputs, &[("CV", "w2")])
        }),
        Just(instance("R_TRIG", format!("e{n}"), &[], &[])),
        prop::sample::select(INPUTS.to_vec()).prop_map(move |r| instance(
            "SR",
            format!("s{n}"),
            &[("R", r.to_string())],
            &[]
        )),
        (1i32..4, prop::sample::select(INPUTS.to_vec())).prop_map(move |(pv, cd)| {
            let inputs = [("CD", cd.to_string()), ("PV", pv.to_string())];
            instance("CTUD", format!("u{n}"), &inputs, &[("CV", "w1")])
        }),
    ]
}

/// An output: a coil, or a box writing a word.
fn output() -> impl Strategy<Value = Element> {
    let target = prop::sample::select(WORDS.to_vec());
    prop_oneof![
        (
            prop::sample::select(BITS.to_vec()),
            prop::sample::select(vec![CoilKind::Normal, CoilKind::Set, CoilKind::Reset])
        )
            .prop_map(|(d, kind)| Element::Coil {
                kind,
                device: d.into()
            }),
        (
            prop::sample::select(vec![
                "ADD", "SUB", "MUL", "DIV", "MOD", "MAX", "MIN", "AND", "XOR"
            ]),
            operand(),
            operand(),
            target.clone()
        )
            .prop_map(|(k, a, b, t)| Element::OutputBlock(call(
                k,
                &[("IN1", a), ("IN2", b)],
                &[("OUT", t)]
            ))),
        (operand(), target.clone()).prop_map(|(a, t)| Element::OutputBlock(call(
            "MOVE",
            &[("IN", a)],
            &[("OUT", t)]
        ))),
        (operand(), operand(), operand(), target.clone()).prop_map(|(mn, x, mx, t)| {
            Element::OutputBlock(call(
                "LIMIT",
                &[("MN", mn), ("IN", x), ("MX", mx)],
                &[("OUT", t)],
            ))
        }),
        (
            prop::sample::select(INPUTS.to_vec()),
            operand(),
            operand(),
            target.clone()
        )
            .prop_map(|(g, a, b, t)| {
                Element::OutputBlock(call(
                    "SEL",
                    &[("G", g.into()), ("IN0", a), ("IN1", b)],
                    &[("OUT", t)],
                ))
            }),
        (operand(), 0u8..17, target).prop_map(|(a, n, t)| {
            Element::OutputBlock(call(
                "SHL",
                &[("IN", a), ("N", n.to_string())],
                &[("OUT", t)],
            ))
        }),
        prop::sample::select(WORDS.to_vec()).prop_map(|w| {
            Element::OutputBlock(call("INT_TO_DINT", &[("IN", w.into())], &[("OUT", "d0")]))
        }),
    ]
}

fn rung(n: usize) -> impl Strategy<Value = RungLogic> {
    (
        contact(),
        prop::option::of(inline_box(n)),
        prop::option::of(contact()),
        prop::collection::vec(output(), 1..3),
    )
        .prop_map(|(first, boxed, last, outputs)| {
            let mut items = vec![first];
            items.extend(boxed);
            items.extend(last);
            RungLogic {
                condition: Net::Series(items).normalised(),
                outputs: outputs.into_iter().map(|e| (e, Pos::new(0, 0))).collect(),
                comment: String::new(),
                sides: Vec::new(),
            }
        })
}

type Case = (Vec<RungLogic>, Vec<Vec<bool>>);

fn case() -> impl Strategy<Value = Case> {
    (
        (0usize..5).prop_flat_map(|n| (0..n + 1).map(rung).collect::<Vec<_>>()),
        prop::collection::vec(prop::collection::vec(any::<bool>(), 3), 1..30),
    )
}

fn check((rungs, timeline): &Case) -> Result<(), TestCaseError> {
    let mut ladder = Ladder::from_logic(rungs);
    ladder.variables = variables();
    let text = compile(&ladder, MachineId::SoftPlc, Options::default())
        .map_err(|e| TestCaseError::fail(format!("compile: {e:?}")))?;
    let logic = ladder
        .logic(MachineId::SoftPlc)
        .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
    let mut reference = Reference::new(logic, 10)
        .map_err(|e| TestCaseError::fail(format!("{e:?}")))?
        .with_iec_timers()
        .with_variables(&ladder.variables);
    // The live ladder's colours come from the machine's own trace.
    let live =
        engine::ladder::live::LiveLadder::new(&ladder, MachineId::SoftPlc, Options::default())
            .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
    prop_assert_eq!(&live.listing.text, &text);
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&text)
        .map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
    plc.set_tracing(true);
    // The same ladder exported as PLCopen (what OpenPLC Editor opens)
    // and read back onto the soft PLC as written.
    let xml = engine::formats::plcopen::export(&ladder, "words")
        .map_err(|e| TestCaseError::fail(format!("export: {e:?}")))?;
    let again = engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.soft_program(None))
        .map_err(|e| TestCaseError::fail(format!("{e:?}\n{xml}")))?;
    // And the IL read back as a ladder, compiled again.
    let program =
        engine::softplc::Program::load(&text).map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
    let back = engine::machines::decompile(engine::machines::Source::Soft(&program))
        .map_err(|e| TestCaseError::fail(format!("decompile: {e}\n{text}")))?;
    let recompiled = compile(&back, MachineId::SoftPlc, Options::default())
        .map_err(|e| TestCaseError::fail(format!("recompile: {e:?}\n{text}")))?;
    let mut third = new_plc(MachineId::SoftPlc);
    third
        .load_text(&recompiled)
        .map_err(|e| TestCaseError::fail(format!("{e}\n{recompiled}")))?;
    let mut other = new_plc(MachineId::SoftPlc);
    other
        .load_text(&again.text)
        .map_err(|e| TestCaseError::fail(format!("{e}\n{}", again.text)))?;
    for (j, inputs) in timeline.iter().enumerate() {
        let t = SimTime::from_millis(10 * j as u64 + 5);
        plc.run_until(t);
        other.run_until(t);
        third.run_until(t);
        for (d, &on) in INPUTS.iter().zip(inputs) {
            reference.set(d, on);
            for m in [&mut plc, &mut other, &mut third] {
                // An input the program does not use is not the soft PLC's.
                let Ok(dev) = m.device(d) else { continue };
                m.apply(Command::SetInput(dev, InputValue::Int(i64::from(on))))
                    .map_err(|e| TestCaseError::fail(e.to_string()))?;
            }
        }
        plc.run_until(t + SimTime::from_millis(10));
        other.run_until(t + SimTime::from_millis(10));
        third.run_until(t + SimTime::from_millis(10));
        let want: Vec<Vec<(bool, bool)>> = reference
            .scan()
            .iter()
            .map(|r| r.iter().map(|e| (e.power_in, e.power_out)).collect())
            .collect();
        let trace = plc.trace().ok_or_else(|| TestCaseError::fail("no trace"))?;
        let got: Vec<Vec<(bool, bool)>> = live
            .power(trace)
            .into_iter()
            .map(|(_, r)| r.iter().map(|e| (e.power_in, e.power_out)).collect())
            .collect();
        prop_assert_eq!(got, want, "scan {}: colours\n{}", j, text);
        for d in BITS {
            let Ok(dev) = plc.device(d) else { continue };
            prop_assert_eq!(
                plc.read(dev).is_on(),
                reference.get(d),
                "scan {}: {}\n{}",
                j,
                d,
                text
            );
        }
        for w in WORDS.iter().chain(&["d0"]) {
            let got = plc.read(
                plc.device(w)
                    .map_err(|e| TestCaseError::fail(e.to_string()))?,
            );
            let want = reference.value(w).map(|d| d.to_value());
            prop_assert_eq!(Some(got.clone()), want, "scan {}: {}\n{}", j, w, text);
            let dev = third
                .device(w)
                .map_err(|e| TestCaseError::fail(e.to_string()))?;
            prop_assert_eq!(
                third.read(dev),
                got.clone(),
                "scan {}: {} decompiled\n{}\n{}",
                j,
                w,
                text,
                recompiled
            );
            if let Ok(dev) = other.device(w) {
                prop_assert_eq!(
                    other.read(dev),
                    got,
                    "scan {}: {} via PLCopen\n{}\n{}",
                    j,
                    w,
                    xml,
                    again.text
                );
            }
        }
        for d in BITS {
            if let (Ok(a), Ok(b)) = (plc.device(d), third.device(d)) {
                prop_assert_eq!(
                    plc.read(a),
                    third.read(b),
                    "scan {}: {} decompiled\n{}",
                    j,
                    d,
                    recompiled
                );
            }
        }
        for d in BITS {
            if let (Ok(a), Ok(b)) = (plc.device(d), other.device(d)) {
                prop_assert_eq!(
                    plc.read(a),
                    other.read(b),
                    "scan {}: {} via PLCopen\n{}",
                    j,
                    d,
                    again.text
                );
            }
        }
    }
    Ok(())
}

fn run(cases: u32) {
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    if let Err(e) = runner.run(&case(), |c| check(&c)) {
        panic!("{e}");
    }
}

#[test]
fn word_ladders_match_the_reference() {
    run(300);
}

#[test]
#[ignore = "5 000 cases: run with --ignored"]
fn word_ladders_match_the_reference_5000() {
    run(5_000);
}

/// A soft PLC project of our own: a rising edge adds one to `count`
/// (an output box), `count > 2` lights a lamp, a TON box times an input;
/// with two ladder tests on the word.
const COUNTER: &str = r#"{"format": "hashigo-project", "version": 2, "machine": "soft-plc", "ladder": {"rungs": [{"cells": [[{"type": "contact", "kind": "rising", "device": "%IX0.0"}, {"type": "output_block", "kind": "ADD", "inputs": [["IN1", "count"], ["IN2", "1"]], "outputs": [["OUT", "count"]]}]]}, {"cells": [[{"type": "block", "kind": "GT", "inputs": [["IN1", "count"], ["IN2", "2"]]}, {"type": "coil", "kind": "normal", "device": "%QX0.0"}]]}, {"cells": [[{"type": "contact", "kind": "no", "device": "%IX0.1"}, {"type": "block", "kind": "TON", "instance": "t0", "inputs": [["PT", "T#50ms"]], "outputs": [["ET", "waited"]]}, {"type": "coil", "kind": "normal", "device": "%QX0.1"}]]}], "variables": [{"name": "count", "type": "INT"}, {"name": "waited", "type": "TIME"}]}, "tests": [{"name": "three presses count to three", "events": "10ms,%IX0.0,1\n30ms,%IX0.0,0\n40ms,%IX0.0,1\n60ms,%IX0.0,0\n70ms,%IX0.0,1\n", "expect": ["count = 3 at 100ms", "%QX0.0 = 1 at 100ms", "count = 2 at 50ms"]}, {"name": "a wrong count fails", "events": "10ms,%IX0.0,1\n", "expect": ["count = 5 at 100ms"]}]}"#;

#[test]
fn ladder_tests_check_words_on_the_command_line() {
    use crate::common::{hashigo, text, Temp};
    let tmp = Temp::new("word-tests");
    let project = tmp.file("counter.json", COUNTER);
    let out = hashigo(&["test", "--program", &project], "");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "pass three presses count to three\n\
         fail a wrong count fails: count = 5 at 100ms: count was 1 at 100ms\n\
         1 passed, 1 failed\n"
    );
    // The same project runs, compiles, shares and explains.
    let run = hashigo(
        &[
            "run",
            "--program",
            &project,
            "--until",
            "100ms",
            "--watch",
            "count,waited",
        ],
        "",
    );
    assert_eq!(text(&run.stdout), "time_ms,count,waited\n0,0,0\n100,0,0\n");
    let share = hashigo(&["share", "--program", &project], "");
    assert!(
        text(&share.stdout).starts_with("3."),
        "{}",
        text(&share.stdout)
    );
    let why_of = |device: &str| {
        hashigo(
            &[
                "why",
                "--program",
                &project,
                "--at",
                "50ms",
                "--device",
                device,
            ],
            "",
        )
    };
    let why = why_of("%QX0.0");
    assert_eq!(why.status.code(), Some(0), "{}", text(&why.stderr));
    // A comparison that blocks the power says its operands' values; a
    // word written by an output box is explained by that box's rung.
    assert!(
        text(&why.stdout).contains("GT(IN1 := count, IN2 := 2); IN1 count = 0"),
        "{}",
        text(&why.stdout)
    );
    let why = why_of("count");
    assert!(
        text(&why.stdout).contains(
            "Rung 1, row 1, column 2: ADD(IN1 := count, IN2 := 1, OUT => count) gets no power."
        ),
        "{}",
        text(&why.stdout)
    );
}
