//! The second round of hostile input (issue #24): share links, ladder
//! tests, `why`, PLCopen element order, map files. Each test failed on the
//! main branch before the fix it names.

use engine::formats::share;
use engine::formats::Project;

use crate::common::{hashigo, text, Temp};

const IO86A: &str = "LD X00\nOUT Y00\nEND\n";
const TIMER: &str = include_str!("../../programs/io86a/timer.json");

/// Runs `hashigo` and returns (exit code, stdout, stderr).
fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = hashigo(args, "");
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// The IO86A timer example with `cases` (name, events, expectations).
fn with_cases(cases: &[(&str, &str, Vec<String>)]) -> String {
    let mut project = Project::from_json(TIMER).expect("the example reads");
    project.tests = cases
        .iter()
        .map(|(name, events, expect)| engine::cases::TestCase {
            name: name.to_string(),
            events: events.to_string(),
            expect: expect.clone(),
            hint: String::new(),
        })
        .collect();
    project.to_json()
}

// 1. Device names with many `B.` prefixes.

#[test]
fn a_name_of_many_b_prefixes_is_one_unknown_device_not_a_stack_overflow() {
    let tmp = Temp::new("round2-b");
    let p = tmp.file("p.il", IO86A);
    let name = format!("{}X00", "B.".repeat(85_000));
    let events = tmp.file("e.csv", &format!("0s,{name},1\n"));
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "io86a",
        "--program",
        &p,
        "--input",
        &events,
        "--until",
        "1s",
        "--watch",
        "Y00",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: ") && err.contains("unknown device"),
        "{err}"
    );
    assert!(err.len() < 400, "one short line: {} bytes", err.len());

    let project = with_cases(&[("deep", "", vec![format!("{name} = 0 at 1s")])]);
    let json = tmp.file("deep.json", &project);
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn only_one_b_prefix_names_device_b() {
    let tmp = Temp::new("round2-bb");
    let p = tmp.file("p.il", IO86A);
    for twice in ["B.B.Y00", "b.B.Y00", "B.b.Y00"] {
        let (code, _, err) = run(&[
            "run",
            "--machine",
            "io86a",
            "--program",
            &p,
            "--until",
            "1s",
            "--watch",
            twice,
        ]);
        assert_eq!(code, Some(2), "{twice}: {err}");
        assert!(err.contains(&format!("\"{twice}\"")), "named whole: {err}");
    }
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "io86a",
        "--program",
        &p,
        "--until",
        "0s",
        "--watch",
        "B.Y00,b.y00",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, "time_ms,B.Y00,b.y00\n0,0,0\n");
}

// 2. Share links and the counts they hold.

/// A version-1 share text of `rungs` empty rungs for IO86A.
fn empty_rungs_link(rungs: u64) -> String {
    use base64::Engine as _;
    let mut data = vec![1u8, 0, 0];
    let mut n = rungs;
    loop {
        let b = (n & 0x7F) as u8;
        n >>= 7;
        if n == 0 {
            data.push(b);
            break;
        }
        data.push(b | 0x80);
    }
    for _ in 0..rungs {
        data.extend([0, 0, 0]); // no comment, no rows, no links
    }
    let packed = miniz_oxide::deflate::compress_to_vec(&data, 10);
    format!(
        "1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
    )
}

#[test]
fn a_share_link_of_more_rungs_than_a_ladder_may_have_is_refused() {
    let at_limit = empty_rungs_link(10_000);
    let project = share::decode(&at_limit).expect("10 000 rungs open");
    assert_eq!(project.ladder.rungs.len(), 10_000);
    let err = share::decode(&empty_rungs_link(10_001)).expect_err("10 001 do not");
    assert_eq!(
        err.to_string(),
        "this share link holds 10001 rungs, more than the 10000 a project may have (docs/limits.md)"
    );

    let huge = empty_rungs_link(300_000);
    assert!(huge.len() < 2_000, "a small link: {}", huge.len());
    let (code, out, err) = run(&["unshare", &huge]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty(), "nothing built, nothing printed");
    assert!(err.contains("holds 300000 rungs"), "{err}");
}

#[test]
fn a_share_link_cannot_name_a_setting_twice() {
    let mut project = Project::new(engine::MachineId::Io86a, Default::default());
    project.settings.insert("filter".into(), "0".into());
    let link = share::encode(&project).expect("encodes");
    assert!(share::decode(&link).is_ok());
    // The same binary with the one setting's entry repeated.
    use base64::Engine as _;
    let body = link.strip_prefix("1.").expect("version 1");
    let packed = base64::engine::general_purpose::URL_SAFE_NO_PAD
        .decode(body)
        .expect("base64");
    let data = miniz_oxide::inflate::decompress_to_vec(&packed).expect("inflates");
    // machine, count 1, "filter" (len 6), "0" (len 1)
    let entry = [6, b'f', b'i', b'l', b't', b'e', b'r', 1, b'0'];
    assert_eq!(&data[1..11], &[&[1u8][..], &entry].concat()[..]);
    let mut twice = vec![data[0], 2];
    twice.extend(entry);
    twice.extend(entry);
    twice.extend(&data[11..]);
    let forged = format!(
        "1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD
            .encode(miniz_oxide::deflate::compress_to_vec(&twice, 10))
    );
    let err = share::decode(&forged).expect_err("a name given twice");
    assert!(err.to_string().contains("a name given twice"), "{err}");
}

// 3. The work of ladder tests.

#[test]
fn the_same_long_window_a_thousand_times_is_looked_at_once() {
    let tmp = Temp::new("round2-work");
    let same = vec!["Y00 stays 0 from 0s to 9000s".to_string(); 1_000];
    let json = tmp.file("same.json", &with_cases(&[("same", "", same)]));
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, "pass same\n1 passed, 0 failed\n");
}

#[test]
fn tests_past_the_work_limit_are_refused_before_any_runs() {
    let tmp = Temp::new("round2-limit");
    let distinct: Vec<String> = (0..1_000)
        .map(|i| format!("Y00 stays 0 from {i}ms to 9000s"))
        .collect();
    let json = tmp.file("many.json", &with_cases(&[("many", "", distinct)]));
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty(), "nothing ran: {out}");
    assert_eq!(
        err,
        format!("error: {json}: the tests would take more than 100000000 samples (instants and expectations looked at; docs/limits.md): shorten their windows\n")
    );
    // The limit counts every case together.
    let long = || vec!["X01 stays 0 from 0s to 2000s".to_string()];
    let cases: Vec<_> = (0..30).map(|i| (["a", "b"][i % 2], "", long())).collect();
    let json = tmp.file("cases.json", &with_cases(&cases));
    let (code, _, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(2), "{err}");
    // Within it, several long cases run.
    let json = tmp.file("few.json", &with_cases(&cases[..4]));
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.ends_with("4 passed, 0 failed\n"), "{out}");
}

// 4. PLCopen element order.

/// An order of a body's elements, or (`Err(n)`) the drawing's own order
/// of however many it has.
type Order = Result<Vec<usize>, usize>;

/// The orders a body's `n` elements are written in: as the drawing reads,
/// with the last block (the AND, before the coil) first, and reversed.
fn orders(n: usize) -> [Vec<usize>; 3] {
    let written: Vec<usize> = (0..n).collect();
    let mut and_first = vec![n - 2];
    and_first.extend((0..n).filter(|&i| i != n - 2));
    [
        written.clone(),
        and_first,
        written.into_iter().rev().collect(),
    ]
}

/// `Y01 = AND(X01, XOR(X00·X01, X02), X02)` as LD or FBD with its inputs
/// and coil named by `dev` (0-2 inputs, 3 the coil), elements in `order`.
fn and_of_a_xor(fbd: bool, dev: fn(usize) -> String, order: Order) -> String {
    let conn = |id: usize, pin: &str| {
        let pin = if pin.is_empty() {
            String::new()
        } else {
            format!(r#" formalParameter="{pin}""#)
        };
        format!(r#"<connectionPointIn><connection refLocalId="{id}"{pin}/></connectionPointIn>"#)
    };
    let var = |pin: &str, id: usize, out: &str| {
        format!(
            r#"<variable formalParameter="{pin}">{}</variable>"#,
            conn(id, out)
        )
    };
    let block = |id: usize, ty: &str, ins: String| {
        format!(
            r#"<block localId="{id}" typeName="{ty}"><position x="{}" y="10"/><inputVariables>{ins}</inputVariables><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#,
            id * 10
        )
    };
    // Ids: 1 rail, 10-12 X00-X02, 13 X01 after X00 (FBD: AND of them),
    // 20 XOR, 21 AND, 30 Y01.
    let out = |id: usize| if fbd && id >= 13 { "OUT" } else { "" };
    let mut elements = Vec::new();
    if fbd {
        for n in 0..3 {
            elements.push(format!(
                r#"<inVariable localId="{}"><position x="10" y="{}"/><connectionPointOut/><expression>{}</expression></inVariable>"#,
                10 + n,
                10 * n,
                dev(n)
            ));
        }
        elements.push(block(13, "AND", var("IN1", 10, "") + &var("IN2", 11, "")));
    } else {
        elements.push(
            r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>"#
                .to_string(),
        );
        for n in 0..3 {
            elements.push(format!(
                r#"<contact localId="{}"><position x="20" y="{}"/>{}<variable>{}</variable></contact>"#,
                10 + n,
                10 * n,
                conn(1, ""),
                dev(n)
            ));
        }
        elements.push(format!(
            r#"<contact localId="13"><position x="30" y="0"/>{}<variable>{}</variable></contact>"#,
            conn(10, ""),
            dev(1)
        ));
    }
    elements.push(block(
        20,
        "XOR",
        var("IN1", 13, out(13)) + &var("IN2", 12, ""),
    ));
    elements.push(block(
        21,
        "AND",
        var("IN1", 11, "") + &var("IN2", 20, "OUT") + &var("IN3", 12, ""),
    ));
    elements.push(if fbd {
        format!(
            r#"<outVariable localId="30"><position x="300" y="0"/>{}<expression>{}</expression></outVariable>"#,
            conn(21, "OUT"),
            dev(3)
        )
    } else {
        format!(
            r#"<coil localId="30"><position x="300" y="0"/>{}<variable>{}</variable></coil>"#,
            conn(21, "OUT"),
            dev(3)
        )
    });
    let order = order.unwrap_or_else(|n| orders(n)[0].clone());
    let written: Vec<&str> = order
        .iter()
        .filter_map(|&i| elements.get(i).map(String::as_str))
        .collect();
    assert_eq!(written.len(), elements.len(), "an order of every element");
    let language = if fbd { "FBD" } else { "LD" };
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="main" pouType="program"><body><{language}>
{}
</{language}></body></pou></pous></types></project>"#,
        written.join("\n")
    )
}

/// Y01's value for each of the 8 inputs in turn, run by `hashigo run`.
fn truth_table(machine: &str, xml: &str, dev: fn(usize) -> String) -> Vec<bool> {
    let tmp = Temp::new(&format!("round2-order-{machine}"));
    let p = tmp.file("net.xml", xml);
    let mut events = String::new();
    for k in 0..8 {
        for n in 0..3 {
            events += &format!("{}ms,{},{}\n", 100 * k, dev(n), (k >> n) & 1);
        }
    }
    let e = tmp.file("e.csv", &events);
    let mut args = vec![
        "run",
        "--machine",
        machine,
        "--program",
        &p,
        "--input",
        &e,
        "--until",
        "800ms",
        "--every",
        "50ms",
    ];
    let coil = dev(3);
    args.extend(["--watch", &coil]);
    if machine == "io86a" {
        args.extend(["--set", "filter=0"]);
    }
    let (code, out, err) = run(&args);
    assert_eq!(code, Some(0), "{err}\n{xml}");
    out.lines()
        .skip(1)
        .filter_map(|l| l.split_once(','))
        .filter(|(t, _)| t.ends_with("50"))
        .map(|(_, v)| v == "1")
        .collect()
}

#[test]
fn an_and_block_written_before_what_it_reads_keeps_every_input() {
    // Y01 = X01 and X02 and not X00.
    let want: Vec<bool> = (0..8).map(|k| k & 0b110 == 0b110 && k & 1 == 0).collect();
    let io86a: fn(usize) -> String = |n| ["X00", "X01", "X02", "Y01"][n].to_string();
    let avr: fn(usize) -> String = |n| ["R4.0", "R4.1", "R4.2", "R5.1"][n].to_string();
    for (machine, dev) in [("io86a", io86a), ("avr-plc", avr)] {
        for fbd in [false, true] {
            let n = if fbd { 7 } else { 8 };
            for order in orders(n) {
                let xml = and_of_a_xor(fbd, dev, Ok(order.clone()));
                assert_eq!(
                    truth_table(machine, &xml, dev),
                    want,
                    "{machine}, fbd {fbd}, order {order:?}\n{xml}"
                );
            }
        }
    }
}

// 5, 9, 10. What `hashigo test` writes.

#[test]
fn the_junit_report_is_well_formed_whatever_a_case_is_called() {
    let tmp = Temp::new("round2-junit");
    let name = "a\u{fffe}b\u{ffff}c\u{1}d\ne\tf<&\"g";
    let failing = vec!["Y00 stays 1 from 0s to 1s".to_string()];
    let json = tmp.file("p.json", &with_cases(&[(name, "", failing)]));
    let report = tmp.file("report.xml", "");
    let (code, _, err) = run(&["test", "--program", &json, "--junit", &report]);
    assert_eq!(code, Some(1), "{err}");
    let xml = std::fs::read_to_string(&report).expect("the report");
    let mut reader = quick_xml::Reader::from_str(&xml);
    let mut names = Vec::new();
    loop {
        match reader.read_event() {
            Ok(quick_xml::events::Event::Eof) => break,
            Ok(quick_xml::events::Event::Start(e) | quick_xml::events::Event::Empty(e))
                if e.name().as_ref() == b"testcase" =>
            {
                let attr = e
                    .try_get_attribute("name")
                    .expect("attributes parse")
                    .expect("a name");
                names.push(attr.unescape_value().expect("unescapes").into_owned());
            }
            Ok(_) => {}
            Err(e) => panic!("not well-formed: {e}\n{xml}"),
        }
    }
    assert!(!xml.contains('\u{fffe}') && !xml.contains('\u{ffff}') && !xml.contains('\u{1}'));
    assert_eq!(names, ["a\u{fffd}b\u{fffd}c\u{fffd}d\ne\tf<&\"g"]);
}

#[test]
fn a_case_name_cannot_forge_a_line_or_reach_the_terminal() {
    let tmp = Temp::new("round2-names");
    let name = "ok\nfail forged: \u{1b}[31mred";
    let holds = vec!["Y00 = 0 at 0s".to_string()];
    let json = tmp.file("p.json", &with_cases(&[(name, "", holds)]));
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        out,
        "pass ok\\nfail forged: \\u{1b}[31mred\n1 passed, 0 failed\n"
    );
}

#[test]
fn an_edge_that_went_the_other_way_is_reported_as_seen() {
    let tmp = Temp::new("round2-edge");
    let expect = vec!["Y00 rises within 1s..2s".to_string()];
    // X00 on from the start; off at 1.5 s: the lamp falls, never rises.
    let json = tmp.file(
        "p.json",
        &with_cases(&[("fell", "0s,X00,1\n1.5s,X00,0\n", expect)]),
    );
    let (code, out, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(1), "{err}");
    let line = out.lines().next().unwrap_or_default();
    assert!(
        line.contains("Y00 did not rise (it went from 1 to 0, falling at 15"),
        "{line}"
    );
    let expect = vec!["Y00 rises within 0.5s..1s".to_string()];
    let json = tmp.file("q.json", &with_cases(&[("still", "", expect)]));
    let (_, out, _) = run(&["test", "--program", &json]);
    assert!(out.contains("Y00 did not rise (it stayed 0)"), "{out}");
}

#[test]
fn a_whole_number_too_large_is_called_out_of_range() {
    let tmp = Temp::new("round2-range");
    let huge = vec!["C00.v = 99999999999999999999 at 1s".to_string()];
    let json = tmp.file("p.json", &with_cases(&[("big", "", huge)]));
    let (code, _, err) = run(&["test", "--program", &json]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("\"99999999999999999999\" is out of range"),
        "{err}"
    );
}

// 11. Duplicate keys.

#[test]
fn a_setting_or_device_comment_given_twice_is_refused_at_the_second() {
    let tmp = Temp::new("round2-dup");
    let settings = TIMER.replacen(
        "\"machine\": \"io86a\",",
        "\"machine\": \"io86a\",\n  \"settings\": {\n    \"filter\": \"0\",\n    \"filter\": \"20\"\n  },",
        1,
    );
    assert_ne!(settings, TIMER);
    let p = tmp.file("s.json", &settings);
    let (code, _, err) = run(&["compile", "--program", &p]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.starts_with(&format!("error: {p}:7: ")) && err.contains("\"filter\" is given twice"),
        "{err}"
    );
    let comments = TIMER.replacen(
        "\"rungs\": [",
        "\"device_comments\": {\"X00\": \"start\",\n\"x00\": \"a\",\n\"X00\": \"stop\"},\n    \"rungs\": [",
        1,
    );
    assert_ne!(comments, TIMER);
    let p = tmp.file("c.json", &comments);
    let (code, _, err) = run(&["compile", "--program", &p]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("\"X00\" is given twice"), "{err}");
}

// 6, 7, 8, 12. `hashigo why`.

#[test]
fn why_takes_any_spelling_of_a_device_the_ladder_names() {
    let tmp = Temp::new("round2-why-names");
    let orb = include_str!("../../programs/io86a/orb.json").replace("\"Y05\"", "\"y5\"");
    let p = tmp.file("orb.json", &orb);
    let e = tmp.file("e.csv", "0s,X00,1\n0s,X01,1\n");
    for asked in ["Y05", "Y5", "y05", " Y05 "] {
        let (code, out, err) = run(&[
            "why",
            "--program",
            &p,
            "--input",
            &e,
            "--set",
            "filter=0",
            "--at",
            "1s",
            "--device",
            asked,
        ]);
        assert_eq!(code, Some(0), "{asked}: {err}");
        assert!(out.starts_with("Y05 = 1 at 1000 ms"), "{asked}: {out}");
        assert!(out.contains("coil Y05 gets power"), "{asked}: {out}");
    }
    let (code, out, err) = run(&[
        "why",
        "--program",
        &p,
        "--input",
        &e,
        "--at",
        "1s",
        "--device",
        "X06 ",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with("X06 = 0"), "{out}");
}

#[test]
fn why_on_an_avr_source_takes_its_equ_names() {
    let tmp = Temp::new("round2-why-avr");
    let e = tmp.file("e.csv", "0s,INPUT1,1\n0s,INPUT2,1\n");
    let (code, out, err) = run(&[
        "why",
        "--machine",
        "avr-plc",
        "--program",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/programs/avr-plc/self-hold.asm"
        ),
        "--input",
        &e,
        "--at",
        "1s",
        "--device",
        "COIL1",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with("R5.0 = 1 at 1000 ms"), "{out}");
    assert!(out.contains("coil R5.0 gets power"), "{out}");
}

#[test]
fn why_on_the_arduino_sketch_reports_the_end_of_the_scan_it_explains() {
    let tmp = Temp::new("round2-why-arduino");
    // Two rungs write Y000: on, then off, every pass.
    let p = tmp.file(
        "two.txt",
        "0 LD X000\n1 OUT Y000\n2 LD X001\n3 OUT Y000\n4 JUMP 0\n",
    );
    let e = tmp.file("e.csv", "0s,X000,1\n");
    for at in ["1s", "1.0001s", "1.0002s", "1.0003s", "1.00045s", "0.5s"] {
        let (code, out, err) = run(&[
            "why",
            "--machine",
            "arduino-plc",
            "--program",
            &p,
            "--input",
            &e,
            "--at",
            at,
            "--device",
            "Y000",
        ]);
        assert_eq!(code, Some(0), "{err}");
        let mut lines = out.lines();
        let head = lines.next().unwrap_or_default();
        let coil = lines.next().unwrap_or_default();
        assert!(
            head.starts_with("Y000 = 0 at ") && head.ends_with("unchanged since power-on"),
            "{at}: {out}"
        );
        assert!(coil.ends_with("coil Y000 gets no power."), "{at}: {out}");
    }
}

#[test]
fn why_on_a_plcopen_file_says_each_warning_once() {
    let tmp = Temp::new("round2-why-warn");
    // A vendor element is skipped with a warning.
    let xml = and_of_a_xor(false, |n| ["X00", "X01", "X02", "Y01"][n].to_string(), Err(8))
        .replace(
            "</LD>",
            r#"<vendorElement localId="99"><position x="0" y="0"/><alternativeText>a vendor's</alternativeText></vendorElement></LD>"#,
        );
    let p = tmp.file("net.xml", &xml);
    let (code, out, err) = run(&[
        "why",
        "--machine",
        "io86a",
        "--program",
        &p,
        "--at",
        "1s",
        "--device",
        "Y01",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with("Y01 = 0"), "{out}");
    let lines: Vec<&str> = err.lines().collect();
    let once: std::collections::HashSet<&str> = lines.iter().copied().collect();
    assert_eq!(lines.len(), once.len(), "{err}");
    assert_eq!(err.matches("a vendor's own element").count(), 1, "{err}");
}

// 13, 14. Map files.

const SEAL_IN: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="main" pouType="program">
<interface><localVars>
<variable name="start"><type><BOOL/></type></variable>
<variable name="lamp"><type><BOOL/></type></variable>
</localVars></interface>
<body><LD>
<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>
<contact localId="2"><position x="10" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>start</variable></contact>
<coil localId="3"><position x="50" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>lamp</variable></coil>
</LD></body></pou></pous></types></project>"#;

/// `hashigo compile` of `program` for IO86A with `--map map`.
fn compile_mapped(program: &str, map: &str) -> (Option<i32>, String, String) {
    run(&[
        "compile",
        "--machine",
        "io86a",
        "--program",
        program,
        "--map",
        map,
    ])
}

#[test]
fn a_map_file_is_read_as_a_csv_reader_reads_it() {
    let tmp = Temp::new("round2-map");
    let p = tmp.file("seal.xml", SEAL_IN);
    let plain = tmp.file("plain.csv", "start,X03\nlamp,Y02\n");
    let (code, want, err) = compile_mapped(&p, &plain);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        want.contains("LD X03") && want.contains("OUT Y02"),
        "{want}"
    );
    let spreadsheet = tmp.file(
        "sheet.csv",
        "\u{feff}\"name\",\"device\"\r\n\"start\",\"X03\"\r\n\"lamp\", \"Y02\" # the lamp\r\n",
    );
    let (code, out, err) = compile_mapped(&p, &spreadsheet);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out, want);
    // `map --map` keeps what the file maps: nothing left to propose.
    let (code, out, err) = run(&[
        "map",
        "--machine",
        "io86a",
        "--program",
        &p,
        "--map",
        &spreadsheet,
    ]);
    assert_eq!(code, Some(0), "{err}");
    let entries: Vec<&str> = out.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(entries, ["start,X03", "lamp,Y02"], "{out}");
    let unclosed = tmp.file("bad.csv", "\"start,X03\nlamp,Y02\n");
    let (code, _, err) = compile_mapped(&p, &unclosed);
    assert_eq!(code, Some(2));
    assert!(
        err.starts_with(&format!("error: {unclosed}:1: expected NAME,DEVICE")),
        "{err}"
    );
}

#[test]
fn a_bad_device_in_a_map_file_is_reported_at_the_maps_line() {
    let tmp = Temp::new("round2-map-bad");
    let p = tmp.file("seal.xml", SEAL_IN);
    let map = tmp.file("m.csv", "# devices\nstart,X03\nlamp,Y99\n");
    let (code, out, err) = compile_mapped(&p, &map);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert!(
        err.starts_with(&format!("error: {map}:3: ")) && err.contains("\"Y99\""),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
}

// Also: the CSV cap at exactly its limit.

#[test]
fn exactly_the_csv_cap_is_allowed() {
    use engine::headless::Schedule;
    use engine::SimTime;
    let rows = |until: u64, every: u64| {
        Schedule {
            until: SimTime::from_millis(until),
            every: SimTime::from_millis(every),
        }
        .rows()
    };
    assert_eq!(rows(10_000, 3_000), 5); // 0, 3, 6, 9 and 10 s
    assert_eq!(rows(9_000, 3_000), 4);
    assert_eq!(rows(0, 0), 1);
    assert_eq!(rows(49_999_999, 1), engine::limits::MAX_CSV_VALUES);
    let tmp = Temp::new("round2-cap");
    let p = tmp.file("p.il", IO86A);
    // One value past the cap is refused; the cap itself is checked the
    // same way (rows × devices), so 25 000 000 rows of 2 are not.
    let (code, _, err) = run(&[
        "run",
        "--machine",
        "io86a",
        "--program",
        &p,
        "--until",
        "25000s",
        "--every",
        "1ms",
        "--watch",
        "Y00,Y01",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("more than 50000000 values"), "{err}");
}
