//! PLCopen projects on the soft PLC as written (issue #30): no map, the
//! drawn bodies run as drawn. The workplace's real projects when present
//! (never committed): how many run, why the others do not, and some by
//! behaviour; and a project of our own with word data.

use engine::events::InputValue;
use engine::formats::plcopen::Document;
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

use crate::common::{hashigo, text, Temp};

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");
const WORDS: &str = include_str!("fixtures/soft-words.xml");

/// A real project, when the workplace has it.
fn real(name: &str) -> Option<String> {
    std::fs::read_to_string(format!("{REAL}/{name}")).ok()
}

/// A project loaded on a new soft PLC.
fn soft(xml: &str) -> Box<dyn Plc> {
    let program = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text).expect("loads");
    plc
}

fn set(plc: &mut dyn Plc, device: &str, v: i64) {
    let d = plc.device(device).expect(device);
    plc.apply(Command::SetInput(d, InputValue::Int(v)))
        .expect("input");
}

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

/// Runs to `ms` and reads `device`.
fn at(plc: &mut dyn Plc, ms: u64, device: &str) -> i64 {
    plc.run_until(SimTime::from_millis(ms));
    get(plc, device)
}

/// Each project that does not run, and what it is told.
const REFUSED: [(&str, &str); 6] = [
    (
        "beremiz-first-steps.xml",
        "CounterSFC is the project's own function block in SFC",
    ),
    (
        "beremiz-traffic-light.xml",
        "the project's own function block in SFC",
    ),
    (
        // Only its C pragmas, in its three ST bodies (see soft_st.rs).
        "bottle-refiller.xml",
        "a pragma `{…}` not supported by Hashigo's Structured Text",
    ),
    (
        "openplc-ex-blink-p1am.xml",
        "P1AM_INIT is not a standard block",
    ),
    (
        "openplc-ex-tcp-socket.xml",
        "TCP_CONNECT is not a standard block",
    ),
    ("sail-plant.xml", "EQ block's IN1 is not connected"),
];

#[test]
fn fifteen_of_the_real_projects_run_and_the_rest_say_why() {
    let Some(names) = crate::common::fixture_names(REAL, ".xml") else {
        return;
    };
    let mut ran = Vec::new();
    for name in &names {
        let xml = real(name).expect("readable");
        match Document::read(&xml).and_then(|document| document.soft_program(None)) {
            Ok(program) => {
                let mut plc = new_plc(MachineId::SoftPlc);
                plc.load_text(&program.text)
                    .unwrap_or_else(|e| panic!("{name}: {e}\n{}", program.text));
                plc.run_until(SimTime::from_secs(2));
                assert!(plc.scans() >= 200, "{name} runs");
                ran.push(name.clone());
            }
            Err(errors) => {
                let (_, why) = REFUSED
                    .iter()
                    .find(|(n, _)| n == name)
                    .unwrap_or_else(|| panic!("{name} refused: {errors:?}"));
                let said = errors[0].error.to_string();
                assert!(said.contains(why), "{name}: {said}");
                assert!(errors.iter().all(|e| e.line > 1), "{name}: at its line");
            }
        }
    }
    assert!(
        ran.len() >= 15,
        "{} of {} run: {ran:?}",
        ran.len(),
        names.len()
    );
}

#[test]
fn openplc_blink_blinks_500_ms_on_and_off() {
    let Some(xml) = real("openplc-ex-blink.xml") else {
        return;
    };
    for (scan_ms, half) in [(10, 510), (1, 501)] {
        let mut plc = soft(&xml);
        plc.apply(Command::Setting {
            name: "scan".into(),
            value: format!("{scan_ms}ms"),
        })
        .expect("scan");
        // Each half is PT plus the scan in which the other timer resets,
        // as OpenPLC's runtime runs it.
        let mut changes = Vec::new();
        let mut last = 0;
        for ms in (0..=3000).step_by(scan_ms as usize) {
            let now = at(plc.as_mut(), ms, "blink_led");
            if now != last {
                changes.push(ms);
                last = now;
            }
        }
        let halves: Vec<u64> = changes.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(halves.len() >= 4, "{changes:?}");
        assert!(
            halves.iter().all(|&h| h == half),
            "{scan_ms} ms: {halves:?}"
        );
    }
}

#[test]
fn a_real_seal_in_and_counters_behave() {
    if let Some(xml) = real("water-pump.xml") {
        let plc = soft(&xml);
        // Names keep their addresses: %IX0.1 is EmStop.
        assert_eq!(plc.device("EmStop").ok(), plc.device("%IX0.1").ok());
    }
    let Some(xml) = real("lab5-ctu-ctd.xml") else {
        return;
    };
    let mut plc = soft(&xml);
    for k in 0..3 {
        set(plc.as_mut(), "i1", 1);
        at(plc.as_mut(), 40 * k + 20, "count");
        set(plc.as_mut(), "i1", 0);
        at(plc.as_mut(), 40 * k + 40, "count");
    }
    assert_eq!(get(plc.as_ref(), "CTU0.CV"), 3, "three rising edges");
}

#[test]
fn word_data_gives_iec_numbers() {
    let mut plc = soft(WORDS);
    set(plc.as_mut(), "%IW0", 40);
    assert_eq!(at(plc.as_mut(), 10, "alarm"), 1, "40 * 3 > 100");
    assert_eq!(get(plc.as_ref(), "big"), 40_000, "INT_TO_DINT before MUL");
    assert_eq!(get(plc.as_ref(), "quot"), -3, "DIV truncates");
    assert_eq!(get(plc.as_ref(), "rest"), -1);
    assert_eq!(get(plc.as_ref(), "picked"), 10, "SEL with G off");
    assert_eq!(get(plc.as_ref(), "total"), 32766, "EN off: not added");
    assert_eq!(get(plc.as_ref(), "done"), 0, "ENO follows EN");
    set(plc.as_mut(), "run", 1);
    assert_eq!(at(plc.as_mut(), 20, "total"), 32767);
    assert_eq!(at(plc.as_mut(), 30, "total"), -32768, "INT wraps");
    assert_eq!(get(plc.as_ref(), "picked"), 20);
    set(plc.as_mut(), "%IW0", 5);
    assert_eq!(at(plc.as_mut(), 40, "five"), 1, "EQ of three inputs");
}

#[test]
fn the_command_line_runs_a_project_on_the_soft_plc_without_a_map() {
    let tmp = Temp::new("soft-plcopen");
    let xml = tmp.file("words.xml", WORDS);
    let events = tmp.file("ev.csv", "0,%IW0,40\n15ms,run,1\n");
    let out = hashigo(
        &[
            "run",
            "--machine",
            "soft-plc",
            "--program",
            &xml,
            "--input",
            &events,
            "--until",
            "30ms",
            "--every",
            "10ms",
            "--watch",
            "alarm,total,big",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "time_ms,alarm,total,big\n0,0,32766,0\n10,1,32766,40000\n20,1,32767,40000\n30,1,-32768,40000\n"
    );
    let map = tmp.file("map.csv", "run,X00\n");
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "soft-plc",
            "--program",
            &xml,
            "--map",
            &map,
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("the soft PLC needs no --map"));
    let bad = tmp.file(
        "bad.xml",
        &WORDS.replace(
            "<expression>level</expression>",
            "<expression>ghost</expression>",
        ),
    );
    let out = hashigo(&["compile", "--machine", "soft-plc", "--program", &bad], "");
    assert_eq!(out.status.code(), Some(2));
    let said = text(&out.stderr);
    assert!(said.starts_with(&format!("error: {bad}:")), "{said}");
    assert!(said.contains("`ghost` is not declared"), "{said}");
}

const OWN_BLOCK: &str = include_str!("fixtures/soft-own-block.xml");

#[test]
fn the_projects_own_function_blocks_run_as_blocks() {
    let program = Document::read(OWN_BLOCK)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    // The block is kept as a block: a section of its own, called twice.
    assert!(
        program.text.contains("FUNCTION_BLOCK Latch\nVAR_INPUT\n"),
        "{}",
        program.text
    );
    assert_eq!(
        program.text.matches("CAL one(").count(),
        1,
        "{}",
        program.text
    );
    assert_eq!(program.text.matches("CAL two(").count(), 1);
    let mut plc = soft(OWN_BLOCK);
    set(plc.as_mut(), "start1", 1);
    assert_eq!(at(plc.as_mut(), 20, "lamp1"), 1, "one latches");
    assert_eq!(get(plc.as_ref(), "lamp2"), 0, "two is its own instance");
    set(plc.as_mut(), "start1", 0);
    assert_eq!(at(plc.as_mut(), 40, "lamp1"), 1, "and holds");
    assert_eq!(get(plc.as_ref(), "count1"), 1, "one rising edge counted");
    assert_eq!(get(plc.as_ref(), "one.sets"), 1, "seen inside the instance");
    set(plc.as_mut(), "start2", 1);
    assert_eq!(at(plc.as_mut(), 60, "lamp2"), 1);
    set(plc.as_mut(), "stop", 1);
    assert_eq!(at(plc.as_mut(), 80, "lamp1"), 0, "stop drops both");
    assert_eq!(get(plc.as_ref(), "lamp2"), 0);
}
