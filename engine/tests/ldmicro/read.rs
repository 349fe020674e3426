//! Reading `.ld` files: the workplace's 32 real files (never committed)
//! read whole, each element line counted against SOURCES.md's census of
//! them; every form of each element; bad files refused at their line.

use std::collections::BTreeMap;

use engine::formats::ldmicro::element::CounterKind;
use engine::formats::ldmicro::{decode, parse, Element, LdFile, Node, Version};
use engine::runtime::ldmicro::TimerKind;

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/ldmicro");

/// Each keyword line of the file counted: RUNG, SERIES, PARALLEL and the
/// elements.
fn census(file: &LdFile) -> BTreeMap<String, usize> {
    let mut counts = BTreeMap::new();
    *counts.entry("RUNG".to_string()).or_default() += file.rungs.len();
    let mut todo: Vec<&Node> = file.rungs.iter().flat_map(|r| r.series.iter()).collect();
    while let Some(n) = todo.pop() {
        let key = match n {
            Node::Leaf(e, _) => e.keyword().to_string(),
            Node::Series(v, _) => {
                todo.extend(v);
                "SERIES".into()
            }
            Node::Parallel(v, _) => {
                todo.extend(v);
                "PARALLEL".into()
            }
        };
        *counts.entry(key).or_default() += 1;
    }
    counts
}

/// SOURCES.md's rows: file, header, keyword counts.
fn sources() -> Vec<(String, String, BTreeMap<String, usize>)> {
    let text = std::fs::read_to_string(format!("{REAL}/SOURCES.md")).expect("SOURCES.md");
    text.lines()
        .filter(|l| l.starts_with("| ") && l.contains(".ld |"))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
            let counts = cells[6]
                .split(", ")
                .filter_map(|kv| {
                    let (k, v) = kv.rsplit_once(' ')?;
                    Some((k.to_string(), v.parse().ok()?))
                })
                .collect();
            (cells[0].to_string(), cells[5].to_string(), counts)
        })
        .collect()
}

#[test]
fn all_32_real_files_read_whole_as_their_census_says() {
    if std::fs::metadata(REAL).is_err() {
        eprintln!("no {REAL}: skipped");
        return;
    }
    let rows = sources();
    assert_eq!(rows.len(), 32);
    for (name, header, expected) in rows {
        let bytes = std::fs::read(format!("{REAL}/{name}")).expect("readable");
        let file = parse(&decode(&bytes)).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let version = if header == "LDmicro0.1" {
            Version::V01
        } else {
            Version::V02
        };
        assert_eq!(file.version, version, "{name}");
        assert_eq!(census(&file), expected, "{name}");
    }
}

#[test]
fn settings_and_lists_read_in_both_forms() {
    let v01 = "LDmicro0.1\r\nMICRO=Microchip PIC16F877 40-PDIP\r\nCYCLE=10000\r\nCRYSTAL=4000000\r\nBAUD=2400\r\n\r\nIO LIST\r\n    Xbutton at 21\r\nEND\r\n\r\nPROGRAM\r\nRUNG\r\n    CONTACTS Xbutton 1\r\n    COIL Yled 0 0 0\r\nEND\r\n";
    let f = parse(v01).expect("reads");
    assert_eq!(
        (f.version, f.cycle_us, f.crystal_hz, f.baud),
        (Version::V01, 10_000, 4_000_000, 2400)
    );
    assert_eq!(f.micro, "Microchip PIC16F877 40-PDIP");
    assert_eq!(
        (f.io[0].name.as_str(), f.io[0].rest.as_str()),
        ("Xbutton", "at 21")
    );
    let v02 = "LDmicro0.2\nMICRO=Atmel AVR ATmega328 32-Pin packages\nCYCLE=1000 us at Timer0, YPlcCycleDuty:0\nCRYSTAL=16000000 Hz\nBAUD=9600 Hz, RATE=0 Hz, SPEED=0 Hz\nCOMPILED=D:\\x.hex\nCOMPILER=AVRGCC\n\nVAR LIST\n    1 bytes Cs100 \n    4 bytes big \tnote\nEND\n\nIO LIST\nEND\n\nPROGRAM\nRUNG 1\n  OSR\nEND\n";
    let f = parse(v02).expect("reads");
    assert_eq!(
        (f.version, f.cycle_us, f.crystal_hz, f.baud),
        (Version::V02, 1000, 16_000_000, 9600)
    );
    assert_eq!(
        (f.compiled.as_str(), f.compiler.as_str()),
        ("D:\\x.hex", "AVRGCC")
    );
    assert_eq!(
        (f.size_of("Cs100"), f.size_of("big"), f.size_of("other")),
        (1, 4, 2)
    );
    assert_eq!(f.vars[1].note, "note");
    // A note in Windows' Latin-1 (not UTF-8) reads; the elements are ASCII.
    let latin = b"LDmicro0.2\nVAR LIST\n    1 bytes Cb \tInutilis\xe9\nEND\nPROGRAM\n";
    let f = parse(&decode(latin)).expect("reads");
    assert_eq!(f.vars[0].note, "Inutilis\u{e9}");
    // A bare header reads as 0.2, as LDmicro 4.x reads it.
    let bare = parse("LDmicro\nPROGRAM\nRUNG\nSHORT\nEND\n").expect("reads");
    assert_eq!(bare.version, Version::V02);
}

fn one(version: &str, line: &str) -> Element {
    let text = format!("{version}\nPROGRAM\nRUNG\n    {line}\nEND\n");
    let f = parse(&text).unwrap_or_else(|e| panic!("{line}: {e:?}"));
    match &f.rungs[0].series[0] {
        Node::Leaf(e, 4) => e.clone(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn each_element_reads_in_its_2x_and_4x_forms() {
    // A timer without an adjust is one cycle shorter in a 0.1 file (TON,
    // TOF, RTO only, as LDmicro's loader has it).
    for (version, adjust) in [("LDmicro0.1", -1), ("LDmicro0.2", 0)] {
        let e = one(version, "TON Tdelay 500000");
        assert_eq!(
            e,
            Element::Timer {
                kind: TimerKind::Ton,
                name: "Tdelay".into(),
                delay: "500000".into(),
                adjust
            }
        );
        let e = one(version, "TCY Tc 100000");
        assert!(
            matches!(
                e,
                Element::Timer {
                    kind: TimerKind::Tcy,
                    adjust: 0,
                    ..
                }
            ),
            "{e:?}"
        );
    }
    assert!(matches!(
        one("LDmicro0.1", "TOF Toff 100000 2"),
        Element::Timer { adjust: 2, .. }
    ));
    assert_eq!(
        one("LDmicro0.1", "CTU Cup 10"),
        Element::Counter {
            kind: CounterKind::Ctu,
            name: "Cup".into(),
            max: "10".into(),
            init: "0".into(),
            input: '/'
        }
    );
    // 4.x: a start and which change counts; a variable in a numeric slot.
    assert_eq!(
        one("LDmicro0.2", "CTU C0 T0 0 \\"),
        Element::Counter {
            kind: CounterKind::Ctu,
            name: "C0".into(),
            max: "T0".into(),
            init: "0".into(),
            input: '\\'
        }
    );
    assert!(matches!(
        one("LDmicro0.2", "CONTACTS Xa 1 1"),
        Element::Contacts {
            negated: true,
            set1: true,
            ..
        }
    ));
    assert!(matches!(
        one("LDmicro0.1", "CONTACTS Xa 0"),
        Element::Contacts {
            negated: false,
            set1: false,
            ..
        }
    ));
    assert!(matches!(
        one("LDmicro0.2", "COIL Yq 0 0 0 1"),
        Element::Coil { toggle: true, .. }
    ));
    assert!(matches!(
        one("LDmicro0.1", "COIL Yq 0 1 0"),
        Element::Coil {
            set_only: true,
            toggle: false,
            ..
        }
    ));
    assert_eq!(
        one("LDmicro0.1", "FORMATTED_STRING Css 3 92 50 46"),
        Element::FormattedString {
            var: "Css".into(),
            text: "\\2.".into()
        }
    );
    assert_eq!(
        one(
            "LDmicro0.2",
            "FORMATTED_STRING (none) Hello\\x20world\\r\\n"
        ),
        Element::FormattedString {
            var: String::new(),
            text: "Hello world\r\n".into()
        }
    );
    assert_eq!(
        one("LDmicro0.1", "LOOK_UP_TABLE duty Ci 5 0 10 70 80 70 10"),
        Element::LookUpTable {
            dest: "duty".into(),
            index: "Ci".into(),
            values: vec![10, 70, 80, 70, 10],
            as_string: false,
            name: "duty5".into()
        }
    );
    assert!(
        matches!(one("LDmicro0.2", "PIECEWISE_LINEAR y x 2 0 0 100 1000 tab"), Element::PiecewiseLinear { ref points, .. } if points == &[(0, 0), (100, 1000)])
    );
    assert!(
        matches!(one("LDmicro0.1", "SET_PWM duty 2000"), Element::SetPwm { ref name, .. } if name.is_empty())
    );
    assert!(
        matches!(one("LDmicro0.2", "SET_PWM duty 2000.0 led 8"), Element::SetPwm { ref name, ref frequency, .. } if name == "Pled" && frequency == "2000")
    );
    assert!(matches!(
        one("LDmicro0.2", "UART_RECV inch 2 1"),
        Element::UartRecv {
            bytes: 2,
            wait: true,
            whole: false,
            ..
        }
    ));
    assert!(matches!(
        one("LDmicro0.2", "UART_SEND_BUSY"),
        Element::UartSendReady
    ));
    assert_eq!(
        one("LDmicro0.1", "COMMENT a\\r\\nb \\\\ c"),
        Element::Comment("a\r\nb \\ c".into())
    );
    assert!(matches!(
        one("LDmicro0.2", "7SEGMENTS #PORTB Cs C"),
        Element::Segments {
            segments: 7,
            common: 'C',
            ..
        }
    ));
    assert!(
        matches!(one("LDmicro0.2", "I2C_RD a b c d e f g h"), Element::Hardware { ref keyword, .. } if keyword == "I2C_RD")
    );
}

#[test]
fn a_bad_file_is_refused_at_its_line_naming_what_is_wrong() {
    let bad = |text: &str, line: usize, says: &str| {
        let errors = parse(text).expect_err(text);
        assert_eq!(errors[0].line, line, "{text}: {errors:?}");
        let said = errors[0].error.to_string();
        assert!(said.contains(says), "{text}: {said}");
    };
    bad("hello\n", 1, "not an LDmicro file");
    bad("LDmicro0.1\nCYCLE=10000\n", 1, "no PROGRAM line");
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  FROB x\nEND\n",
        4,
        "unknown element \"FROB\"",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  TON T1\nEND\n",
        4,
        "TON takes name delay [adjust]",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  CONTACTS Xa maybe\nEND\n",
        4,
        "\"maybe\" is not a number",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  CTU C0 5 0 x\nEND\n",
        4,
        "CTU takes name max",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  LOOK_UP_TABLE d i 3 0 1 2\nEND\n",
        4,
        "says 3 entries but has 2",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  PARALLEL\n    CONTACTS Xa 0\n",
        4,
        "ends inside this PARALLEL",
    );
    bad(
        "LDmicro0.1\nPROGRAM\nRUNG\n  PARALLEL\n  PARALLEL\n  END\n  END\nEND\n",
        5,
        "PARALLEL directly inside PARALLEL",
    );
    bad(
        "LDmicro0.1\nPROGRAM\n  CONTACTS Xa 0\n",
        3,
        "a rung starts with RUNG",
    );
    bad(
        "LDmicro0.2\nVAR LIST\n  two bytes x\nEND\nPROGRAM\n",
        3,
        "VAR LIST",
    );
    let deep = format!(
        "LDmicro0.1\nPROGRAM\nRUNG\n{}SHORT\n{}END\n",
        "SERIES\n".repeat(200),
        "END\n".repeat(200)
    );
    bad(&deep, 104, "nested more than 100 deep");
    // Every error of the file at once, nothing read partly.
    let two =
        parse("LDmicro0.1\nPROGRAM\nRUNG\n  FROB\nEND\nRUNG\n  TON x\nEND\n").expect_err("two");
    assert_eq!(two.iter().map(|e| e.line).collect::<Vec<_>>(), vec![4, 7]);
}
