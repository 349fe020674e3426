//! PLCopen TC6 XML: both namespaces, OpenPLC's dialect, round trips,
//! and imported programs running on the machines.

use engine::formats::plcopen::export;
use engine::formats::plcopen::Document;
use engine::formats::Project;
use engine::iec::literal::parse_time_literal;
use engine::ladder::compile::{compile, Options};
use engine::ladder::Ladder;
use engine::{avr, MachineId, SimTime};
use proptest::prelude::*;

use crate::common::{hashigo, text};
use crate::strategies::{pool, rung};

const BLINK: &str = include_str!("fixtures/openplc-blink.xml");
const BEREMIZ: &str = include_str!("fixtures/beremiz-v1.xml");
const SEED_JSON: &str = include_str!("../../programs/minasec-u/seed-test.json");

#[test]
fn openplc_blink_runs_on_the_avr_plc() {
    let ladder = Document::read(BLINK)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    assert_eq!(ladder.rungs.len(), 3);
    assert_eq!(ladder.rungs[0].comment, "lamp := NOT lamp_off");
    let text = compile(&ladder, MachineId::AvrPlc, Options::default()).expect("compiles");
    let program = avr::Program::parse(&text, 10).expect("assembles");
    let mut m = avr::Machine::new(program);
    let lamp = avr::BitRef {
        register: 1,
        bit: 0,
    };
    let mut seen = Vec::new();
    for t in [500, 1500, 2500, 3500, 4500] {
        m.run_until(SimTime::from_millis(t));
        seen.push(m.bit(lamp));
    }
    // One second on, one second off.
    assert_eq!(seen, [true, false, true, false, true], "{text}");
}

#[test]
fn a_v1_file_runs_on_io86a_from_the_command_line() {
    let events = "time,device,value\n100ms,X00,1\n200ms,X00,0\n3s,X01,1\n3.1s,X01,0\n4s,X02,1\n4.1s,X02,0\n4.2s,X02,1\n4.3s,X02,0\n4.4s,X02,1\n4.5s,X02,0\n";
    let dir = std::env::temp_dir().join(format!("hashigo-plcopen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let ev = dir.join("events.csv");
    std::fs::write(&ev, events).expect("events");
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--format",
            "xml",
            "--input",
            ev.to_str().expect("path"),
            "--until",
            "5s",
            "--every",
            "500ms",
            "--watch",
            "Y00,Y01,C00.v",
        ],
        BEREMIZ,
    );
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let rows: Vec<String> = text(&out.stdout).lines().map(String::from).collect();
    let row = |t: &str| {
        rows.iter()
            .find(|r| r.starts_with(&format!("{t},")))
            .cloned()
            .unwrap_or_default()
    };
    assert_eq!(row("1500"), "1500,1,0,0", "self-hold on, T00 still timing");
    assert_eq!(row("2500"), "2500,1,1,0", "T00 (K19 = 1.9 s) done");
    assert_eq!(row("3500"), "3500,0,0,0", "stop drops Y00 and the timer");
    assert_eq!(
        row("5000"),
        "5000,0,1,3",
        "three rising edges of X02 count C00 to 3"
    );
}

fn same_logic(a: &Ladder, b: &Ladder, machine: MachineId) -> Result<(), String> {
    let (a, b) = (
        a.logic(machine).map_err(|e| format!("{e:?}"))?,
        b.logic(machine).map_err(|e| format!("{e:?}"))?,
    );
    if a.len() != b.len() {
        return Err(format!("{} rungs became {}", a.len(), b.len()));
    }
    for (x, y) in a.iter().zip(&b) {
        let ox: Vec<_> = x.outputs.iter().map(|(e, _)| e).collect();
        let oy: Vec<_> = y.outputs.iter().map(|(e, _)| e).collect();
        if x.condition.without_positions() != y.condition.without_positions()
            || ox != oy
            || x.comment != y.comment
        {
            return Err(format!("{x:?}\nbecame\n{y:?}"));
        }
    }
    Ok(())
}

#[test]
fn the_seed_ladder_and_both_fixtures_round_trip() {
    let seed = Project::from_json(SEED_JSON).expect("seed").ladder;
    let back = Document::read(&export(&seed, "seed").expect("exports"))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports back");
    same_logic(&seed, &back, MachineId::MinasecU).expect("seed round trip");
    for (fixture, machine) in [(BLINK, MachineId::AvrPlc), (BEREMIZ, MachineId::Io86a)] {
        let ladder = Document::read(fixture)
            .and_then(|document| document.import(None, None, None))
            .map(|i| i.ladder)
            .expect("fixture");
        let again = Document::read(&export(&ladder, "x").expect("exports"))
            .and_then(|document| document.import(None, None, None))
            .map(|i| i.ladder)
            .expect("imports back");
        same_logic(&ladder, &again, machine).expect("fixture round trip");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_ladders_round_trip(rungs in prop::collection::vec(rung(Box::leak(Box::new(pool(MachineId::AvrPlc)))), 1..5)) {
        let mut ladder = Ladder::from_logic(&rungs);
        ladder.rungs[0].comment = "first <rung> & \"quotes\"\nline two".into();
        let xml = export(&ladder, "random").map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
        let back = Document::read(&xml).and_then(|document| document.import(None, None, None)).map(|i| i.ladder).map_err(|e| TestCaseError::fail(format!("{e:?}\n{xml}")))?;
        same_logic(&ladder, &back, MachineId::AvrPlc).map_err(|e| TestCaseError::fail(format!("{e}\n{xml}")))?;
    }
}

/// An import's warnings, each as `LINE: text`.
pub(crate) fn said_warnings(imported: &engine::formats::plcopen::Imported) -> Vec<String> {
    imported
        .warnings
        .iter()
        .map(|w| format!("{}: {}", w.line, w.error))
        .collect()
}

#[test]
fn bad_files_are_errors_at_their_lines() {
    let err = |xml: &str| {
        Document::read(xml)
            .and_then(|document| document.import(None, None, None))
            .map(|i| i.ladder)
            .expect_err("must fail")
    };
    let e = err("<project xmlns=\"urn:other\"/>");
    assert!(e[0].error.to_string().contains("not PLCopen TC6"), "{e:?}");
    let e = err("<project>\n<types>\n</project>");
    assert_eq!(e[0].line, 3, "{e:?}");
    assert!(e[0].error.to_string().contains("not well-formed"), "{e:?}");
    let e = err("<project><types/></project>");
    assert!(
        e[0].error
            .to_string()
            .contains("no POU with an LD or FBD body"),
        "{e:?}"
    );
    // An unknown block, at its line.
    let bad = BLINK.replacen(
        "typeName=\"TON\" instanceName=\"TON0\"",
        "typeName=\"MOD\" instanceName=\"TON0\"",
        1,
    );
    let line = bad
        .lines()
        .position(|l| l.contains("typeName=\"MOD\""))
        .expect("line")
        + 1;
    let e = err(&bad);
    assert_eq!(
        (
            e[0].line,
            e[0].error
                .to_string()
                .contains("block MOD is not supported")
        ),
        (line, true),
        "{e:?}"
    );
    // A contact that leads nowhere (the origin tool runs it to no
    // effect) is dropped, and said at its line.
    let dangling = BLINK.replacen(
        "</LD>",
        "<contact localId=\"99\" negated=\"false\"><position x=\"1\" y=\"900\"/><connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn><variable>R3.3</variable></contact>\n</LD>",
        1,
    );
    let line = dangling
        .lines()
        .position(|l| l.contains("localId=\"99\""))
        .expect("line")
        + 1;
    let imported = engine::formats::plcopen::Document::read(&dangling)
        .and_then(|document| document.import(None, None, None))
        .expect("imports");
    let said = said_warnings(&imported);
    assert_eq!(
        said,
        [format!("{line}: contact R3.3 leads to no coil: dropped")]
    );
    assert_eq!(
        imported.ladder,
        Document::read(BLINK)
            .and_then(|document| document.import(None, None, None))
            .map(|i| i.ladder)
            .expect("the file without it"),
        "nothing else changes"
    );
    // A PLCopen variable that is not the machine's device: at its line.
    let foreign = BLINK.replacen(
        "<variable>R1.1</variable>",
        "<variable>lamp_off</variable>",
        1,
    );
    // Reported at the element's start tag.
    let lines: Vec<&str> = foreign.lines().collect();
    let var_line = lines
        .iter()
        .position(|l| l.contains("lamp_off</variable>"))
        .expect("line");
    let line = lines[..var_line]
        .iter()
        .rposition(|l| l.contains("<contact"))
        .expect("contact")
        + 1;
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "avr-plc",
            "--program",
            "-",
            "--format",
            "xml",
        ],
        &foreign,
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        format!("error: <stdin>:{line}: unknown device \"lamp_off\": avr-plc ladders name bits R0.0-R31.7\n")
    );
}

#[test]
fn time_literals() {
    for (t, ms) in [
        ("T#500ms", 500),
        ("T#1s", 1000),
        ("TIME#1.5s", 1500),
        ("t#1m30s", 90_000),
        ("T#20S", 20_000),
        ("T#1h_2m", 3_720_000),
    ] {
        assert_eq!(parse_time_literal(t), Some(ms), "{t}");
    }
    for bad in ["500ms", "T#", "T#5", "T#5x", "D#1s", "T#1s5"] {
        assert_eq!(parse_time_literal(bad), None, "{bad}");
    }
}

#[test]
fn what_is_not_ladder_is_named_with_its_language() {
    let pou = |name: &str, kind: &str, body: &str| {
        format!(r#"<pou name="{name}" pouType="{kind}"><body>{body}</body></pou>"#)
    };
    let ld = "<LD><leftPowerRail localId=\"1\"><position x=\"0\" y=\"0\"/><connectionPointOut/></leftPowerRail></LD>";
    let project = |pous: &str, task: &str| {
        format!(
            r#"<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>{pous}</pous></types>
<instances><configurations><configuration name="c"><resource name="r"><task name="t"><pouInstance name="i" typeName="{task}"/></task></resource></configuration></configurations></instances></project>"#
        )
    };
    // The task runs an ST program; the LD is in a function block.
    let xml = project(
        &(pou("plc_prg", "program", "<ST/>") + &pou("CounterLD", "functionBlock", ld)),
        "plc_prg",
    );
    let e = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("ST program");
    assert!(
        e[0].error
            .to_string()
            .contains("(plc_prg in ST) have no LD or FBD body: Hashigo imports ladder (LD) and function block diagram (FBD) bodies; these POUs have one: CounterLD in LD"),
        "{e:?}"
    );
    // No LD anywhere: each POU's language said.
    let xml = project(&pou("seq", "program", "<SFC/>"), "seq");
    let e = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("SFC only");
    assert!(e[0].error.to_string().contains("(seq in SFC)"), "{e:?}");
    // A block calling the project's own ST function block, at its line.
    let call = ld.replace(
        "</LD>",
        "\n<block localId=\"2\" typeName=\"detect\" instanceName=\"d0\"><position x=\"1\" y=\"1\"/></block></LD>",
    );
    let xml = project(
        &(pou("main", "program", &call) + &pou("detect", "functionBlock", "<ST/>")),
        "main",
    );
    let e = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("a project block");
    assert_eq!(e[0].line, 2, "{e:?}");
    assert!(
        e[0].error
            .to_string()
            .contains("block detect calls the project's own ST function block"),
        "{e:?}"
    );
}

#[test]
fn a_comment_goes_to_the_network_drawn_under_it_side_by_side_too() {
    // Two networks side by side, each under its title; the right one
    // starts higher, and a third title sits under the left one.
    let network = |id: u32, x: u32, y: u32, input: &str, output: &str| {
        format!(
            r#"
    <leftPowerRail localId="{id}"><position x="{x}" y="{y}"/><connectionPointOut/></leftPowerRail>
    <contact localId="{}"><position x="{}" y="{y}"/><connectionPointIn><connection refLocalId="{id}"/></connectionPointIn><variable>{input}</variable></contact>
    <coil localId="{}"><position x="{}" y="{y}"/><connectionPointIn><connection refLocalId="{}"/></connectionPointIn><variable>{output}</variable></coil>"#,
            id + 1,
            x + 20,
            id + 2,
            x + 100,
            id + 1
        )
    };
    let comment = |x: u32, y: u32, text: &str| {
        format!(
            r#"
    <comment localId="{}"><position x="{x}" y="{y}"/><content><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">{text}</xhtml:p></content></comment>"#,
            x + y
        )
    };
    let xml = format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="main" pouType="program"><body><LD>{}{}{}{}{}{}
</LD></body></pou></pous></types></project>"#,
        comment(20, 20, "left"),
        comment(500, 10, "right"),
        comment(20, 200, "below"),
        network(100, 20, 100, "X00", "Y00"),
        network(200, 500, 60, "X01", "Y01"),
        network(300, 20, 260, "X02", "Y02"),
    );
    let ladder = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    // Each rung named by its coil's device.
    let said: Vec<(String, &str)> = ladder
        .rungs
        .iter()
        .map(|r| {
            let coil = r.elements().find_map(|(_, e)| match e {
                engine::ladder::Element::Coil { device, .. } => Some(device.clone()),
                _ => None,
            });
            (coil.unwrap_or_default(), r.comment.as_str())
        })
        .collect();
    assert_eq!(
        said,
        [
            ("Y01".to_string(), "right"),
            ("Y00".to_string(), "left"),
            ("Y02".to_string(), "below")
        ],
        "{xml}"
    );
}
