//! Share URLs: round trips, size goals, and never a panic on any input.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine as _;
use engine::formats::share::{decode, encode, ShareError};
use engine::formats::Project;
use engine::ladder::{CoilKind, Element, Ladder, Pos, Rung, TimerKind};
use engine::MachineId;
use proptest::prelude::*;

use crate::strategies::{pool, rung};

const SEED_JSON: &str = include_str!("../../programs/minasec-u/seed-test.json");

fn every_element() -> Rung {
    let mut r = Rung::default();
    let all = [
        Element::Wire,
        Element::no("X00"),
        Element::nc("X01"),
        Element::Not,
        Element::Edge { falling: true },
        Element::Timer {
            kind: TimerKind::Tp,
            name: "ちょっと".into(),
            preset_ms: 123_456,
        },
        Element::Coil {
            kind: CoilKind::Reset,
            device: "Y00".into(),
        },
        Element::Pulse {
            falling: true,
            device: "M1".into(),
        },
        Element::TimerCoil {
            device: "T00".into(),
            preset: 19,
        },
        Element::CounterCoil {
            device: "C07".into(),
            preset: 32767,
        },
        Element::Mov {
            src: "K10".into(),
            dst: "D00".into(),
        },
        Element::Cmp {
            a: "D00".into(),
            b: "K5".into(),
        },
        Element::Inc { dst: "D01".into() },
        Element::Dec { dst: "D02".into() },
    ];
    for (i, e) in all.into_iter().enumerate() {
        r.set(Pos::new(i % 3, i), Some(e));
    }
    r.links = vec![(0, 1).into(), (1, 5).into()];
    r.comment = "every element".into();
    r
}

#[test]
fn every_element_and_the_seed_round_trip() {
    let mut p = Project::from_json(SEED_JSON).expect("seed");
    assert_eq!(decode(&encode(&p).expect("encodes")), Ok(p.clone()));
    p.ladder.rungs.push(every_element());
    p.machine = MachineId::Io86a;
    assert_eq!(decode(&encode(&p).expect("encodes")), Ok(p));
}

#[test]
fn size_goals() {
    // The seed's test program: the five rungs as drawn, without the
    // comments (those are the user's text, stored as written).
    let mut seed = Project::from_json(SEED_JSON).expect("seed");
    // The ladder alone: the seed project also carries test cases.
    seed.tests.clear();
    seed.ladder.device_comments.clear();
    for r in &mut seed.ladder.rungs {
        r.comment.clear();
    }
    let text = encode(&seed).expect("encodes");
    assert!(text.len() <= 200, "seed: {} characters: {text}", text.len());
    let mut with_comments = Project::from_json(SEED_JSON).expect("seed");
    with_comments.tests.clear();
    let with_comments = encode(&with_comments).expect("encodes");
    assert!(
        with_comments.len() <= 400,
        "seed with comments: {}",
        with_comments.len()
    );

    // A 100-rung program of varied rungs: self-holds, interlocks, timers.
    let mut ladder = Ladder::default();
    for i in 0..100 {
        let x = |n: usize| format!("X{:02}", n % 8);
        let m = |n: usize| format!("M{:02}", n % 64);
        let mut r = Rung::default();
        r.set(Pos::new(0, 0), Some(Element::no(&x(i))));
        r.set(Pos::new(1, 0), Some(Element::no(&m(i))));
        r.set(Pos::new(0, 1), Some(Element::nc(&x(i + 3))));
        r.set(Pos::new(0, 2), Some(Element::no(&m(i + 7))));
        r.set(Pos::new(0, 3), Some(Element::coil(&m(i))));
        if i % 4 == 0 {
            r.set(
                Pos::new(1, 3),
                Some(Element::TimerCoil {
                    device: format!("T{:02}", i % 32),
                    preset: (i * 7 % 100) as u16,
                }),
            );
            r.links.push((0, 3).into());
        }
        r.links.push((0, 1).into());
        ladder.rungs.push(r);
    }
    let p = Project::new(MachineId::Io86a, ladder);
    p.ladder.logic(MachineId::Io86a).expect("a valid program");
    let text = encode(&p).expect("encodes");
    assert!(text.len() <= 2000, "100 rungs: {} characters", text.len());
    assert_eq!(decode(&text), Ok(p));
}

#[test]
fn damaged_links_say_what_is_wrong() {
    let mut seed = Project::from_json(SEED_JSON).expect("seed");
    seed.tests.clear();
    let good = encode(&seed).expect("encodes");
    assert!(matches!(decode("7.abc"), Err(ShareError::Version(v)) if v == "7"));
    assert_eq!(decode("1.***"), Err(ShareError::Base64));
    assert_eq!(decode("1.AAAA"), Err(ShareError::Inflate));
    // Cut short: the data ends inside a rung.
    let packed = URL_SAFE_NO_PAD.decode(&good[2..]).expect("b64");
    let raw = miniz_oxide::inflate::decompress_to_vec(&packed).expect("inflate");
    let cut = format!(
        "1.{}",
        URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            &raw[..raw.len() - 3],
            6
        ))
    );
    let e = decode(&cut).expect_err("cut");
    assert!(e.to_string().contains("damaged at byte"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_ladders_round_trip(rungs in prop::collection::vec(rung(Box::leak(Box::new(pool(MachineId::AvrPlc)))), 0..6)) {
        let mut p = Project::new(MachineId::AvrPlc, Ladder::from_logic(&rungs));
        p.settings.insert("scan".into(), "10ms".into());
        prop_assert_eq!(decode(&encode(&p).expect("encodes")), Ok(p));
    }

    #[test]
    fn arbitrary_text_never_panics(s in ".{0,200}") {
        let _ = decode(&s);
        let _ = decode(&format!("1.{s}"));
    }

    #[test]
    fn arbitrary_packed_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let _ = decode(&format!("1.{}", URL_SAFE_NO_PAD.encode(&bytes)));
        // Past base64 and inflate, straight into the binary reader.
        let packed = miniz_oxide::deflate::compress_to_vec(&bytes, 6);
        let _ = decode(&format!("1.{}", URL_SAFE_NO_PAD.encode(packed)));
    }
}

/// `hashigo share` then `hashigo unshare`: the project back, as JSON.
fn through_the_cli(project: &Project) -> Result<Project, String> {
    use crate::common::{hashigo, text, Temp};
    let tmp = Temp::new(&format!("share-{}", project.ladder.rungs.len()));
    let path = tmp.file("p.json", &project.to_json());
    let out = hashigo(&["share", "--program", &path], "");
    if out.status.code() != Some(0) {
        return Err(text(&out.stderr));
    }
    let fragment = text(&out.stdout).trim().to_string();
    let url = format!("https://example.invalid/hashigo/#{fragment}");
    let back = hashigo(&["unshare", &url], "");
    if back.status.code() != Some(0) {
        return Err(text(&back.stderr));
    }
    Project::from_json(&text(&back.stdout)).map_err(|e| e.to_string())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_projects_round_trip_through_share_and_unshare(
        rungs in prop::collection::vec(rung(Box::leak(Box::new(pool(MachineId::Io86a)))), 0..5),
    ) {
        let mut p = Project::new(MachineId::Io86a, Ladder::from_logic(&rungs));
        p.settings.insert("scan".into(), "2ms".into());
        p.ladder.device_comments.insert("X00".into(), "start <b>".into());
        prop_assert_eq!(through_the_cli(&p), Ok(p));
    }
}

#[test]
fn share_and_unshare_from_the_command_line() {
    use crate::common::{hashigo, text};
    let seed =
        Project::from_json(include_str!("../../programs/minasec-u/seed-test.json")).expect("seed");
    assert_eq!(through_the_cli(&seed), Ok(seed.clone()));
    // A text program is decompiled to its ladder first.
    let il = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/programs/minasec-u/seed-test.il"
    );
    let out = hashigo(&["share", "--machine", "minasec-u", "--program", il], "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let fragment = text(&out.stdout).trim().to_string();
    let back = hashigo(&["unshare", &fragment], "");
    let project = Project::from_json(&text(&back.stdout)).expect("a project");
    assert_eq!(project.machine, MachineId::MinasecU);
    assert_eq!(project.ladder.rungs.len(), seed.ladder.rungs.len());
    // Damaged, foreign and oversized links: exit 2, one line, no output.
    for bad in ["1.AAAA", "2.abc", "x", &"1.".repeat(40_000)] {
        let out = hashigo(&["unshare", bad], "");
        assert_eq!(out.status.code(), Some(2), "{bad:.20}");
        assert!(out.stdout.is_empty());
        let err = text(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("error: <link>: this share link"), "{err}");
    }
    let out = hashigo(&["unshare"], "");
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn a_rung_too_large_for_a_link_is_refused_when_encoding() {
    let mut p = Project::from_json(SEED_JSON).expect("seed");
    p.ladder.rungs[1].set(Pos::new(0, 70), Some(Element::coil("Y00")));
    assert_eq!(
        encode(&p),
        Err(ShareError::RungTooLarge {
            rung: 2,
            rows: 1,
            columns: 71
        })
    );
    let msg = encode(&p).expect_err("too wide").to_string();
    assert!(
        msg.starts_with("rung 2 spans 1 rows and 71 columns"),
        "{msg}"
    );
    // 64 × 64 still opens.
    let mut p = Project::from_json(SEED_JSON).expect("seed");
    p.ladder.rungs[1].set(Pos::new(63, 63), Some(Element::Wire));
    assert_eq!(decode(&encode(&p).expect("fits")), Ok(p));
}

#[test]
fn a_soft_plc_ladder_with_words_travels_in_a_version_3_link_and_a_version_2_file() {
    use engine::ladder::{BlockCall, Element, Rung, Variable};
    let add = BlockCall {
        kind: "ADD".into(),
        instance: String::new(),
        inputs: vec![("IN1".into(), "count".into()), ("IN2".into(), "1".into())],
        outputs: vec![("OUT".into(), "count".into())],
    };
    let ton = BlockCall {
        kind: "TON".into(),
        instance: "t0".into(),
        inputs: vec![("PT".into(), "T#1s".into())],
        outputs: Vec::new(),
    };
    let mut ladder = Ladder::default();
    ladder.rungs.push(Rung {
        comment: String::new(),
        cells: vec![vec![
            Some(Element::no("%IX0.0")),
            Some(Element::Block(ton)),
            Some(Element::OutputBlock(add)),
        ]],
        links: Vec::new(),
    });
    let mut count = Variable::new("count", "INT");
    count.initial = "5".into();
    count.retain = true;
    count.comment = "parts".into();
    ladder.variables.push(count);
    let project = Project::new(MachineId::SoftPlc, ladder);
    project
        .ladder
        .logic(MachineId::SoftPlc)
        .expect("a valid program");
    let link = encode(&project).expect("encodes");
    assert!(link.starts_with("3."), "{link}");
    assert_eq!(decode(&link), Ok(project.clone()));
    let json = project.to_json();
    assert!(json.contains("\"version\": 2"), "{json}");
    let mut back = Project::from_json(&json).expect("reads");
    back.version = 1;
    assert_eq!(back, project);
    // Without words a project is what older Hashigos read.
    let plain = Project::new(MachineId::SoftPlc, Ladder::default());
    assert!(plain.to_json().contains("\"version\": 1"));
    assert!(encode(&plain).expect("encodes").starts_with("1."));
}
