//! PLCopen declarations (issue #18): located variables map by rule, the
//! others through `--map`; names become device comments; a map entry the
//! file does not use is a warning; real files from other tools, when the
//! workplace's fixtures are present.

use engine::formats::plcopen::Document;
use engine::formats::plcopen::VarMap;
use engine::MachineId;

use crate::common::{hashigo, text, Temp};

const NAMED: &str = include_str!("fixtures/openplc-named.xml");

/// The workplace's real projects from other tools (read when present,
/// never committed).
const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");

#[test]
fn located_variables_map_by_rule_and_the_rest_need_a_map() {
    let errors = Document::read(NAMED)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .map(|i| i.ladder)
        .expect_err("memo has no device");
    assert_eq!(errors.len(), 1, "{errors:?}");
    let message = errors[0].error.to_string();
    assert!(
        message.contains("variable memo (declared at line 31)"),
        "{message}"
    );
    assert!(message.contains("--map: memo,DEVICE"), "{message}");
    let map = VarMap::parse("memo,M05\nTON9,T09\n").expect("a map");
    let imported = Document::read(NAMED)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    let devices: Vec<String> = imported
        .ladder
        .rungs
        .iter()
        .flat_map(|r| r.elements().map(|(_, e)| e.to_string()))
        .collect();
    for d in [
        "contact X00",
        "contact M02",
        "NC contact X01",
        "coil M02",
        "coil Y00",
        "coil M05",
    ] {
        assert!(devices.iter().any(|x| x == d), "{d} in {devices:?}");
    }
    let comments = &imported.ladder.device_comments;
    assert_eq!(comments.get("X00").map(String::as_str), Some("start"));
    assert_eq!(comments.get("M05").map(String::as_str), Some("memo"));
    assert_eq!(imported.unused_map_entries, vec![("TON9".to_string(), 2)]);
    // No machine: the names stay as written (a plain import).
    assert!(engine::formats::plcopen::Document::read(NAMED)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .is_ok());
}

#[test]
fn the_command_line_takes_a_map_and_warns_of_what_it_does_not_use() {
    let tmp = Temp::new("declare-cli");
    let xml = tmp.file("named.xml", NAMED);
    let map = tmp.file("map.csv", "name,device\nmemo,M05\nunused,M06\n");
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "io86a",
            "--program",
            &xml,
            "--map",
            &map,
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let il = text(&out.stdout);
    assert!(il.contains("OUT M05"), "{il}");
    let warning = text(&out.stderr);
    assert!(
        warning.starts_with(&format!("warning: {map}:3: \"unused\" is not a variable")),
        "{warning}"
    );
    // The program runs: start latches the lamp, stop drops it.
    let events = tmp.file("ev.csv", "100ms,X00,1\n200ms,X00,0\n500ms,X01,1\n");
    let run = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &xml,
            "--map",
            &map,
            "--input",
            &events,
            "--until",
            "600ms",
            "--every",
            "300ms",
            "--watch",
            "Y00,M05",
        ],
        "",
    );
    assert_eq!(
        text(&run.stdout),
        "time_ms,Y00,M05\n0,0,0\n300,1,1\n600,0,0\n",
        "{}",
        text(&run.stderr)
    );
    // Without the map: memo is named at its line; a bad map line too.
    let out = hashigo(&["compile", "--machine", "io86a", "--program", &xml], "");
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains(":85: variable memo"),
        "{}",
        text(&out.stderr)
    );
    let bad = tmp.file("bad.csv", "memo M05\n");
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "io86a",
            "--program",
            &xml,
            "--map",
            &bad,
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with(&format!("error: {bad}:1: expected NAME,DEVICE")));
    // A located output past the machine's own: refused with its sizes.
    let wide = NAMED.replace("%QX0.0", "%QX0.7");
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--format",
            "xml",
            "--map",
            &map,
        ],
        &wide,
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("%QX0.7 is unknown device \"Y07\""),
        "{}",
        text(&out.stderr)
    );
}

/// The real files from other tools, when the workplace has them (never
/// committed here): the seal-in lab imports on IO86A with a map.
#[test]
fn a_real_openplc_lab_imports_with_a_map() {
    let path = format!("{REAL}/lab1-seal-in.xml");
    let Ok(xml) = std::fs::read_to_string(&path) else {
        eprintln!("skipped: {path} is not here");
        return;
    };
    let map = VarMap::parse("I1,X00\nI2,X01\nQ1,Y00\nQ2,Y01\nQ3,Y02\n").expect("a map");
    let imported = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    let il = engine::ladder::compile::compile(
        &imported.ladder,
        MachineId::Io86a,
        engine::ladder::compile::Options::default(),
    )
    .expect("compiles");
    // As the XML draws it: I1 or Q1, and not I2, to Q1; Q1 to Q2; Q2 to Q3.
    let steps: Vec<&str> = il.lines().filter(|l| !l.starts_with(';')).collect();
    assert_eq!(
        steps,
        [
            "LD X00", "OR Y00", "ANI X01", "OUT Y00", "LD Y00", "OUT Y01", "LD Y01", "OUT Y02",
            "END"
        ]
    );
}

const TIMER: &str = include_str!("fixtures/openplc-timer.xml");

/// The 1-based line of `TIMER` holding `needle`.
fn line_of(needle: &str) -> usize {
    TIMER
        .lines()
        .position(|l| l.contains(needle))
        .expect("in the fixture")
        + 1
}

#[test]
fn the_program_a_task_runs_imports_with_its_timer_on_each_machine() {
    // IO86A: the in-line TON becomes T00's coil and contact (TON0 mapped).
    let map = VarMap::parse("TON0,T00\n").expect("a map");
    let io = Document::read(TIMER)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    let il = engine::ladder::compile::compile(&io.ladder, MachineId::Io86a, Default::default())
        .expect("compiles");
    let steps: Vec<&str> = il.lines().filter(|l| !l.starts_with(';')).collect();
    assert_eq!(
        steps,
        ["LD X00", "OUT T00", "K20", "LD T00", "OUT Y00", "END"],
        "{il}"
    );
    let said: Vec<(usize, String)> = io
        .warnings
        .iter()
        .map(|w| (w.line, w.error.to_string()))
        .collect();
    let expected = [
        (
            line_of("<pou name=\"helper\""),
            "functionBlock helper skipped",
        ),
        (line_of("<vendorElement"), "\"Network title\" skipped"),
        (
            line_of("<outVariable localId=\"6\""),
            "ET feeds only the variable \"elapsed\"",
        ),
    ];
    for (line, what) in expected {
        assert!(
            said.iter().any(|(l, w)| *l == line && w.contains(what)),
            "{what} at {line}: {said:?}"
        );
    }
    // Unmapped, TON0 is no IO86A timer: said at the block.
    let errors = Document::read(TIMER)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .map(|i| i.ladder)
        .expect_err("TON0 is no Tnn");
    assert_eq!(
        errors[0].line,
        line_of("<block localId=\"3\""),
        "{errors:?}"
    );
    // The AVR PLC keeps the box in line; its bits come from the map.
    let map = VarMap::parse("start,R4.0\nlamp,R5.0\n").expect("a map");
    let avr = Document::read(TIMER)
        .and_then(|document| document.import(Some(MachineId::AvrPlc), Some(&map), None))
        .expect("imports");
    let text = engine::ladder::compile::compile(&avr.ladder, MachineId::AvrPlc, Default::default())
        .expect("compiles");
    assert!(
        text.contains(".db TON,LOW(Timer0),LOW(2000/Scan)"),
        "{text}"
    );
    // --pou takes the function block alone; a name the file lacks is said.
    let helper = Document::read(TIMER)
        .and_then(|document| {
            document.import(
                Some(MachineId::Io86a),
                Some(&VarMap::parse("a,X01\nb,Y01\n").expect("map")),
                Some("HELPER"),
            )
        })
        .expect("imports");
    assert_eq!(helper.ladder.rungs.len(), 1);
    let none = Document::read(TIMER)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, Some("nope")))
        .expect_err("no such POU");
    assert!(
        none[0]
            .error
            .to_string()
            .contains("the file has helper, main"),
        "{:?}",
        none
    );
}

#[test]
fn a_time_from_a_constant_initialised_variable_and_a_proposed_map() {
    let xml = TIMER
        .replace("<expression>T#2s</expression>", "<expression>delay</expression>")
        .replace(
            r#"<variable name="elapsed">"#,
            r#"<variable name="delay"><type><TIME/></type><initialValue><simpleValue value="T#2s"/></initialValue></variable>
            <variable name="elapsed">"#,
        );
    let map = VarMap::parse("TON0,T00\n").expect("a map");
    let io = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    let il = engine::ladder::compile::compile(&io.ladder, MachineId::Io86a, Default::default())
        .expect("compiles");
    assert!(
        il.contains("OUT T00\nK20"),
        "T#2s from delay's initial value: {il}"
    );
    // `hashigo map` proposes a device for what has none; compile takes it.
    let tmp = Temp::new("declare-map");
    let path = tmp.file("named.xml", NAMED);
    let out = hashigo(&["map", "--machine", "io86a", "--program", &path], "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let proposed = text(&out.stdout);
    let entries: Vec<&str> = proposed.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(
        entries,
        ["memo,Y01"],
        "memo is written, Y00 is lamp's: {proposed}"
    );
    let map = tmp.file("proposed.csv", &proposed);
    let out = hashigo(
        &[
            "compile",
            "--machine",
            "io86a",
            "--program",
            &path,
            "--map",
            &map,
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("OUT Y01"));
    let timer = tmp.file("timer.xml", TIMER);
    let out = hashigo(&["map", "--machine", "io86a", "--program", &timer], "");
    assert!(
        text(&out.stdout).contains("\nTON0,T00\n"),
        "{}",
        text(&out.stdout)
    );
}

/// The 21 real projects, when present: each compiled on each machine with
/// the map `hashigo map` would propose; the counts docs/ladder.md reports.
#[test]
fn the_real_projects_that_compile_with_a_proposed_map() {
    use engine::formats::plcopen::{declare, dom};
    let Ok(entries) = std::fs::read_dir(REAL) else {
        eprintln!("skipped: {REAL} is not here");
        return;
    };
    let mut files: Vec<_> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "xml"))
        .collect();
    files.sort();
    let mut compiled = std::collections::BTreeMap::new();
    for machine in MachineId::ALL {
        let mut ok = Vec::new();
        for path in &files {
            let Ok(xml) = std::fs::read_to_string(path) else {
                continue;
            };
            let Ok(root) = dom::parse(&xml) else {
                continue;
            };
            let map = VarMap::from_pairs(declare::propose(&root, machine, None));
            let Ok(imported) = Document::read(&xml)
                .and_then(|document| document.import(Some(machine), Some(&map), None))
            else {
                continue;
            };
            let options = engine::ladder::compile::Options::default();
            if engine::ladder::compile::compile(&imported.ladder, machine, options).is_ok() {
                let name = path.file_stem().map(|s| s.to_string_lossy().to_string());
                ok.push(name.unwrap_or_default());
            }
        }
        compiled.insert(machine.name(), ok);
    }
    assert_eq!(
        compiled["io86a"],
        [
            "assembly-area",
            "ctu-ton-prueba",
            "dancing-lights",
            "dnp3-test",
            "lab1-seal-in",
            "lab4-ton-tof",
            "lab5-ctu-ctd",
            "mixer-lld",
            "openplc-ex-7segments",
            "openplc-ex-blink",
            "pr009g",
            "utn-circuit",
            "water-pump"
        ],
        "{compiled:?}"
    );
    assert_eq!(
        compiled["minasec-u"],
        ["lab1-seal-in", "pr009g", "water-pump"],
        "{compiled:?}"
    );
    assert_eq!(compiled["arduino-plc"], ["lab1-seal-in"], "{compiled:?}");
    assert_eq!(
        compiled["avr-plc"],
        [
            "dancing-lights",
            "lab1-seal-in",
            "lab4-ton-tof",
            "mixer-lld",
            "openplc-ex-blink",
            "pr009g",
            "water-pump"
        ],
        "{compiled:?}"
    );
}

#[test]
fn an_enable_pin_is_honoured_or_refused_and_initial_values_are_said() {
    let with_en = |from: &str| {
        TIMER.replace(
            r#"<variable formalParameter="IN">"#,
            &format!(
                r#"<variable formalParameter="EN"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></variable>
                <variable formalParameter="IN">"#
            ),
        )
    };
    let map = VarMap::parse("TON0,T00\n").expect("a map");
    // From the rail: always enabled, as Hashigo's blocks are.
    assert!(Document::read(&with_en("1"))
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .is_ok());
    // From a contact: refused at the block, never ignored.
    let errors = Document::read(&with_en("2"))
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect_err("EN wired");
    assert!(
        errors[0].error.to_string().contains("its EN is wired"),
        "{errors:?}"
    );
    // A variable declared TRUE: IO86A starts every device off.
    let xml = NAMED.replace(
        r#"<variable name="latch" address="%MX0.2"><type><BOOL/></type></variable>"#,
        r#"<variable name="latch" address="%MX0.2"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>"#,
    );
    let map = VarMap::parse("memo,M05\n").expect("a map");
    let imported = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None))
        .expect("imports");
    let said = crate::plcopen::said_warnings(&imported);
    assert_eq!(
        said,
        ["30: latch starts at TRUE in the file, but io86a starts M02 off at power-up"],
    );
}

#[test]
fn map_proposes_for_one_pou_with_the_globals_it_names() {
    // Two programs: first lights lamp; second sounds horn while the
    // global alarm is on.
    let pou = |name: &str, var: &str, contact: &str, coil: &str| {
        format!(
            r#"<pou name="{name}" pouType="program"><interface><localVars><variable name="{var}"><type><BOOL/></type></variable></localVars></interface><body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="10" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>{contact}</variable></contact>
<coil localId="3"><position x="30" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>{coil}</variable></coil>
</LD></body></pou>"#
        )
    };
    let xml = format!(
        r#"<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous>{}{}</pous></types>
<instances><configurations><configuration name="c"><globalVars><variable name="alarm"><type><BOOL/></type></variable></globalVars></configuration></configurations></instances></project>"#,
        pou("first", "lamp", "X00", "lamp"),
        pou("second", "horn", "alarm", "horn")
    );
    let tmp = Temp::new("declare-map-pou");
    let path = tmp.file("two.xml", &xml);
    let proposal = |extra: &[&str]| {
        let mut args = vec!["map", "--machine", "io86a", "--program", &path];
        args.extend_from_slice(extra);
        let out = hashigo(&args, "");
        (out.status.code(), text(&out.stdout), text(&out.stderr))
    };
    let entries = |stdout: &str| -> Vec<String> {
        stdout
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(str::to_string)
            .collect()
    };
    let (code, all, _) = proposal(&[]);
    assert_eq!(code, Some(0));
    // X00, named in first's body, is not proposed again.
    assert_eq!(entries(&all), ["lamp,Y00", "horn,Y01", "alarm,X01"]);
    let (code, second, err) = proposal(&["--pou", "SECOND"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(entries(&second), ["horn,Y00", "alarm,X00"]);
    let (code, _, err) = proposal(&["--pou", "third"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("no POU is named third: the file has first, second"),
        "{err}"
    );
}
