//! The one way in (issue #48): a file opened once as a `formats::Document`,
//! then asked for its programs, a map and its ladder for a machine.

use engine::formats::plcopen::dom::parsed_count;
use engine::formats::{Document, FileError, Kind, Project};
use engine::ladder::Ladder;
use engine::MachineId;

use crate::common::{hashigo, text, Temp};

const NAMED: &str = include_str!("fixtures/openplc-named.xml");
const TIMER: &str = include_str!("fixtures/openplc-timer.xml");

#[test]
fn a_plcopen_file_is_read_once_and_asked_everything() {
    let before = parsed_count();
    let document = Document::open(Kind::PlcOpen, NAMED).expect("opens");
    assert_eq!(document.machine(), None, "a PLCopen file names no machine");
    assert_eq!(document.programs(), ["main"]);
    let rows = document
        .propose(MachineId::Io86a, None, None)
        .expect("proposes");
    let memo = rows.iter().find(|(n, _)| n == "memo");
    assert!(memo.is_some_and(|(_, d)| !d.is_empty()), "{rows:?}");
    let map = engine::formats::plcopen::VarMap::from_pairs(rows);
    let opened = document
        .import(MachineId::Io86a, Some(&map), None)
        .expect("imports with the proposed devices");
    assert_eq!(opened.project.machine, MachineId::Io86a);
    assert_eq!(opened.project.ladder.rungs.len(), 2);
    // Unmapped, memo has no device: refused at its line, in the file's words.
    let errors = document
        .import(MachineId::Io86a, None, None)
        .expect_err("memo has no device");
    assert!(errors
        .iter()
        .all(|e| matches!(e.error, FileError::PlcOpen(_))));
    assert_eq!(parsed_count() - before, 1, "the XML is parsed once");
}

#[test]
fn a_pou_no_file_has_is_refused_with_those_it_has() {
    let document = Document::open(Kind::PlcOpen, TIMER).expect("opens");
    let e = document
        .propose(MachineId::Io86a, None, Some("nope"))
        .expect_err("no such POU");
    assert!(e.to_string().contains("nope"), "{e}");
}

#[test]
fn a_project_opens_for_its_own_machine_or_the_one_asked() {
    let mut project = Project::new(MachineId::AvrPlc, Ladder::default());
    project.settings.insert("scan".into(), "20ms".into());
    let text = project.to_json();
    let document = Document::open(Kind::Project, &text).expect("opens");
    assert_eq!(document.machine(), Some(MachineId::AvrPlc));
    assert!(document.programs().is_empty());
    let opened = document
        .import(MachineId::Io86a, None, None)
        .expect("imports");
    assert_eq!(opened.project.machine, MachineId::Io86a);
    let line = text
        .lines()
        .position(|l| l.contains("\"scan\""))
        .expect("there")
        + 1;
    assert_eq!(opened.settings, [("scan".into(), "20ms".into(), line)]);
    let bad = Document::open(Kind::Project, "{\n\"format\": 1\n}").expect_err("not a project");
    assert!(matches!(bad[0].error, FileError::Project(_)), "{bad:?}");
}

#[test]
fn an_ldmicro_file_runs_on_the_soft_plc_only_with_its_cycle_as_the_scan() {
    let text = "LDmicro0.2\nCYCLE=2500 us at Timer1, YPlcCycleDuty:0\n\nIO LIST\n    Xa at 1\n    Yq at 3\nEND\n\nPROGRAM\nRUNG 1\n  CONTACTS Xa 0\n  COIL Yq 0 0 0 0\nEND\n";
    let document = Document::open(Kind::LdMicro, text).expect("opens");
    assert_eq!(document.machine(), Some(MachineId::SoftPlc));
    let opened = document
        .import(MachineId::SoftPlc, None, None)
        .expect("imports");
    assert_eq!(opened.settings, [("scan".into(), "2500us".into(), 2)]);
    assert_eq!(opened.project.ladder.rungs.len(), 1);
    let refused = document
        .import(MachineId::Io86a, None, None)
        .expect_err("LDmicro files run on the soft PLC");
    assert_eq!(refused[0].error, FileError::OnlyOn(MachineId::SoftPlc));
    let broken =
        Document::open(Kind::LdMicro, "LDmicro0.1\nCYCLE=10000\n").expect_err("no PROGRAM");
    assert!(
        matches!(broken[0].error, FileError::LdMicro(_)),
        "{broken:?}"
    );
}

#[test]
fn hashigo_map_reads_the_file_as_compile_does() {
    // `hashigo map` opens the file through the same document as compile:
    // an XML file that is no PLCopen project is refused at its line, as
    // compile refuses it, instead of a map with nothing in it.
    let tmp = Temp::new("documents-map");
    let path = tmp.file(
        "other.xml",
        "<?xml version=\"1.0\"?>\n<recipe>\n</recipe>\n",
    );
    for command in ["map", "compile"] {
        let out = hashigo(&[command, "--machine", "io86a", "--program", &path], "");
        assert_eq!(out.status.code(), Some(2), "{command}");
        let said = text(&out.stderr);
        assert!(
            said.contains("other.xml:2: not a PLCopen project: the root element is <recipe>"),
            "{command}: {said}"
        );
        assert!(text(&out.stdout).is_empty(), "{command}");
    }
}
