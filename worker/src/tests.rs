use super::*;
use engine::formats::plcopen::Document;
use engine::ladder::edit::{align_outputs, COLUMNS};

const NAMED: &str = include_str!("../../engine/tests/ladder/fixtures/openplc-named.xml");

fn import_request(text: &str, rows: Option<Vec<(String, String)>>) -> ImportReply {
    match handle(Request::Import {
        file: "named.xml".into(),
        text: text.into(),
        machine: MachineId::Io86a,
        rows,
        pou: None,
    }) {
        Reply::Import(reply) => reply,
        other => panic!("an import gets an import reply: {other:?}"),
    }
}

#[test]
fn a_file_just_opened_gets_devices_proposed_for_its_names() {
    let reply = import_request(NAMED, None);
    assert_eq!(reply.pous, ["main"]);
    let memo = reply.rows.iter().find(|(n, _)| n == "memo");
    assert!(memo.is_some_and(|(_, d)| !d.is_empty()), "{:?}", reply.rows);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let ladder = reply.ladder.expect("imported with the proposed devices");
    assert_eq!(ladder.rungs.len(), 2);
}

#[test]
fn a_bad_device_is_refused_at_its_row_and_nothing_is_imported() {
    let first = import_request(NAMED, None);
    let rows: Vec<_> = first
        .rows
        .into_iter()
        .map(|(n, d)| {
            if n == "memo" {
                (n, "Q99".to_string())
            } else {
                (n, d)
            }
        })
        .collect();
    let reply = import_request(NAMED, Some(rows));
    assert!(reply.ladder.is_none());
    assert!(
        reply.errors.iter().any(|e| e.starts_with("memo → Q99:")),
        "{:?}",
        reply.errors
    );
}

#[test]
fn a_broken_file_is_refused_with_its_name_and_line() {
    let reply = import_request("<project>\n<types>\n</project>", None);
    assert!(reply.ladder.is_none());
    assert!(
        reply.errors.iter().any(|e| e.starts_with("named.xml:")),
        "{:?}",
        reply.errors
    );
}

#[test]
fn an_exported_ladder_imports_back_as_drawn() {
    let ladder = import_request(NAMED, None).ladder.expect("imports");
    let Reply::Export(Ok(xml)) = handle(Request::Export {
        ladder: ladder.clone(),
        name: "Main".into(),
    }) else {
        panic!("the imported ladder exports");
    };
    let again = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::Io86a), None, None))
        .map(|i| i.ladder)
        .expect("its own export imports");
    // The drawing comes back; the variables' names stay with the file.
    assert_eq!(align_outputs(&again, COLUMNS - 1).rungs, ladder.rungs);
}

#[test]
fn envelopes_carry_their_number_and_garbage_gets_no_reply() {
    let request = Envelope {
        id: 7,
        body: Request::Import {
            file: "named.xml".into(),
            text: NAMED.into(),
            machine: MachineId::Io86a,
            rows: None,
            pou: None,
        },
    };
    let text = serde_json::to_string(&request).expect("a request serialises");
    let reply: Envelope<Reply> =
        serde_json::from_str(&answer(&text).expect("a reply")).expect("a reply envelope");
    assert_eq!(reply.id, 7);
    assert!(matches!(reply.body, Reply::Import(r) if r.ladder.is_some()));
    assert_eq!(answer("not json"), None);
    assert_eq!(answer(r#"{"id": 1, "body": "Nothing"}"#), None);
}

#[test]
fn a_plcopen_project_on_the_soft_plc_needs_no_map_and_is_drawn_or_refused_whole() {
    let soft = |text: &str| match handle(Request::Import {
        file: "p.xml".into(),
        text: text.into(),
        machine: MachineId::SoftPlc,
        rows: None,
        pou: None,
    }) {
        Reply::Import(reply) => reply,
        other => panic!("{other:?}"),
    };
    // Contacts and coils on the project's own names: drawn, nothing mapped.
    let reply = soft(NAMED);
    assert!(reply.rows.is_empty(), "no map on the soft PLC");
    let ladder = reply.ladder.expect("drawn");
    assert!(!ladder.rungs.is_empty());
    // Boxes on words: drawn as the soft PLC's boxes, the same ladder.
    let example = engine::examples::EXAMPLES
        .iter()
        .find(|e| e.machine == MachineId::SoftPlc && e.id == "parts")
        .expect("the example");
    let parts = engine::ladder::decompile::decompile_text(MachineId::SoftPlc, example.text, 10)
        .expect("opens");
    let Reply::Export(Ok(xml)) = handle(Request::Export {
        ladder: parts.clone(),
        name: "Main".into(),
    }) else {
        panic!("exports");
    };
    let reply = soft(&xml);
    assert!(reply.errors.is_empty(), "{:?}", reply.errors);
    let drawn = reply.ladder.expect("drawn");
    let logic = |l: &engine::ladder::Ladder| l.logic(MachineId::SoftPlc).expect("reads");
    assert_eq!(logic(&drawn), logic(&align_outputs(&parts, COLUMNS - 1)));
    assert_eq!(drawn.variables, parts.variables);
    // A block the soft PLC lacks: refused whole at its line, with what
    // to do, and no advice to map to a data register.
    let reply = soft(&xml.replace("typeName=\"CTU\"", "typeName=\"PID_X\""));
    assert!(reply.ladder.is_none());
    assert!(reply.errors[0].starts_with("p.xml:"), "{:?}", reply.errors);
    assert!(reply.errors[0].contains("PID_X"), "{:?}", reply.errors);
    assert!(reply.errors.iter().all(|e| !e.contains("data register")));
    // The page has no command line: no error advises one (issue #49).
    assert!(
        reply
            .errors
            .iter()
            .all(|e| !e.contains("hashigo") && !e.contains("--")),
        "{:?}",
        reply.errors
    );
    assert_eq!(reply.runs_on, None, "already on the soft PLC");
}

#[test]
fn an_ldmicro_file_opens_as_a_soft_plc_ladder_or_says_why_at_its_line() {
    let open = |text: &str| match handle(Request::OpenLd {
        file: "a.ld".into(),
        text: text.into(),
    }) {
        Reply::OpenLd(r) => r,
        other => panic!("{other:?}"),
    };
    let opened = open("LDmicro0.1\nCYCLE=5000\nPROGRAM\nRUNG\n  CONTACTS Xa 0\n  TON Tw 50000\n  COIL Yq 0 0 0\nEND\n")
        .expect("opens");
    assert_eq!(opened.cycle_us, 5000);
    let il =
        engine::ladder::compile::compile(&opened.ladder, MachineId::SoftPlc, Default::default())
            .expect("compiles");
    // 50 ms at 5 ms in a 0.1 file: 9 cycles.
    assert!(il.contains("Tw_ld(IN := _p0, P := DINT#9"), "{il}");
    let errors =
        open("LDmicro0.1\nPROGRAM\nRUNG\n  I2C_RD a b c d e f g h\nEND\n").expect_err("hardware");
    assert_eq!(errors.len(), 1);
    assert!(
        errors[0].starts_with("a.ld:4: I2C_RD drives hardware"),
        "{errors:?}"
    );
}

#[test]
fn an_element_with_too_many_attributes_is_refused_at_its_line() {
    // Issue #43 item 10: the page's reader is the engine's, attributes
    // read in linear time and at most 256 an element.
    let attrs: String = (0..100_000).map(|i| format!(" a{i}=\"\"")).collect();
    let text = NAMED.replacen("<types>", &format!("<types>\n<x{attrs}/>"), 1);
    let line = text
        .lines()
        .position(|l| l.starts_with("<x a0"))
        .expect("there")
        + 1;
    let reply = import_request(&text, None);
    assert!(reply.ladder.is_none());
    assert_eq!(
        reply.errors,
        [format!(
            "named.xml:{line}: <x> has more than 256 attributes (docs/limits.md)"
        )]
    );
}

const TIMER: &str = include_str!("../../engine/tests/ladder/fixtures/openplc-timer.xml");

fn import_on(machine: MachineId, text: &str) -> ImportReply {
    match handle(Request::Import {
        file: "t.xml".into(),
        text: text.into(),
        machine,
        rows: None,
        pou: None,
    }) {
        Reply::Import(reply) => reply,
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_file_refused_here_that_the_soft_plc_runs_names_the_soft_plc() {
    // Issue #49: an OpenPLC timer project on MINASEC-U (no in-line TON)
    // is refused at its line, and the reply says where it does run.
    let reply = import_on(MachineId::MinasecU, TIMER);
    assert!(reply.ladder.is_none(), "{reply:?}");
    assert!(!reply.errors.is_empty());
    assert_eq!(
        reply.runs_on,
        Some(MachineId::SoftPlc),
        "{:?}",
        reply.errors
    );
    assert!(reply.errors.iter().all(|e| !e.contains("hashigo run")));
    // Each error typed beside its words, the machine's refusal with its
    // kind and arguments (the page says it in Japanese from them).
    assert_eq!(reply.said.len(), reply.errors.len());
    let lacks = reply.said.iter().find_map(|s| match &s.cause {
        Some(engine::ladder::target::ElementError::Lacks { machine, what, .. }) => {
            Some((*machine, what.clone(), s.at.clone()))
        }
        _ => None,
    });
    let (machine, what, at) = lacks.expect("a typed refusal");
    assert_eq!(machine, MachineId::MinasecU);
    assert!(what.contains("TON"), "{what}");
    assert!(at.starts_with("t.xml:"), "{at}");
    // ... and there it imports whole.
    let soft = import_on(MachineId::SoftPlc, TIMER);
    assert!(soft.ladder.is_some(), "{:?}", soft.errors);
    // A file no machine takes offers none.
    let broken = TIMER.replace("typeName=\"TON\"", "typeName=\"PID_X\"");
    assert_eq!(import_on(MachineId::MinasecU, &broken).runs_on, None);
}

#[test]
fn a_page_warning_loses_the_command_lines_advice() {
    assert_eq!(
        page_warning("program Other skipped: no task runs it (--pou Other imports it alone)"),
        "program Other skipped: no task runs it"
    );
    assert_eq!(page_warning("plain"), "plain");
}

#[test]
fn import_errors_in_the_page_advise_the_program_picker_not_the_command_line() {
    use engine::formats::plcopen::ImportError;
    for e in [
        ImportError::NoDrawnInPrograms("Main".into(), "Sub".into()),
        ImportError::ProjectBlock("Sub".into(), "ST".into()),
    ] {
        assert!(e.to_string().contains("--pou"), "the CLI keeps its advice");
        let page = e.in_page();
        assert!(!page.contains("--"), "{page}");
        assert!(page.contains("Program"), "{page}");
    }
}

#[test]
fn an_import_reads_the_file_once_whatever_it_is_asked() {
    // Issue #48: the worker keeps the document it read and asks it for the
    // programs, the proposed devices, the import and the machine that runs
    // it instead, so each request parses the XML once.
    let cases = [
        (MachineId::Io86a, NAMED),       // proposed, then imported
        (MachineId::MinasecU, TIMER),    // refused, then tried on the soft PLC
        (MachineId::SoftPlc, TIMER),     // drawn as written
        (MachineId::Io86a, "<project>"), // not even XML
    ];
    for (machine, text) in cases {
        let before = engine::formats::plcopen::dom::parsed_count();
        let reply = import_on(machine, text);
        let parsed = engine::formats::plcopen::dom::parsed_count() - before;
        assert_eq!(parsed, 1, "{machine:?}: {:?}", reply.errors);
    }
}

#[test]
fn a_broken_file_is_said_in_japanese_too_at_its_line() {
    let reply = import_request("<project>\n<a>\n</project>\n", None);
    let said = reply.said.first().expect("an error");
    assert!(said.at.starts_with("named.xml:"), "{said:?}");
    assert!(said.cause.is_none());
    assert_eq!(
        said.ja.as_deref(),
        Some("XML の形が正しくありません"),
        "{reply:?}"
    );
}

#[test]
fn a_soft_plc_refusal_is_said_in_japanese_too_at_its_line() {
    // Issue #49: a block the soft PLC does not have (a vendor's) gets its
    // Japanese with the reply, not only the engine's English.
    let text = TIMER.replace("typeName=\"TON\"", "typeName=\"VENDOR_FB\"");
    let reply = import_on(MachineId::SoftPlc, &text);
    assert!(reply.ladder.is_none(), "{reply:?}");
    let said = reply.said.first().expect("an error");
    assert!(said.at.starts_with("t.xml:"), "{said:?}");
    let ja = said.ja.as_deref().unwrap_or_default();
    assert!(ja.contains("VENDOR_FB"), "{reply:?}");
    assert!(
        ja.contains("ソフトPLCの関数でもブロックでもありません"),
        "{reply:?}"
    );
}

#[test]
fn import_warnings_are_said_in_japanese_too_at_their_lines() {
    // Issue #49: each warning has its Japanese, at the same place.
    let reply = import_on(MachineId::SoftPlc, TIMER);
    assert!(!reply.warnings.is_empty(), "{reply:?}");
    assert_eq!(reply.warnings_said.len(), reply.warnings.len(), "{reply:?}");
    for (english, said) in reply.warnings.iter().zip(&reply.warnings_said) {
        assert!(english.starts_with(&format!("{}: ", said.at)), "{said:?}");
        let ja = said.ja.as_deref().unwrap_or_default();
        assert!(ja.chars().any(|c| c > '\u{3000}'), "{english}: {ja:?}");
    }
}

#[test]
fn a_soft_plc_declaration_refused_is_said_in_japanese_too_at_its_line() {
    // Issue #49: the declaration's reason is a kind (an address refused
    // here), said in Japanese, not the engine's English words.
    let text = TIMER.replace(r#"address="%QX0.0""#, r#"address="%QX0.9""#);
    let reply = import_on(MachineId::SoftPlc, &text);
    assert!(reply.ladder.is_none(), "{reply:?}");
    let said = reply.said.first().expect("an error");
    assert_eq!(said.at, "t.xml:52", "{said:?}");
    assert_eq!(
        said.ja.as_deref(),
        Some("変数 lamp: `%QX0.9`: ビット番号は 0-7 です"),
        "{reply:?}"
    );
}
