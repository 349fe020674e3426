//! PLCopen projects drawn on the soft PLC (issue #31): the page's ladder
//! reader gives boxes, box input networks and the project's variables,
//! and the drawn ladder, compiled, runs as the project runs as written
//! (the soft PLC's own PLCopen reader, [`to_il`], is the oracle).

use engine::events::InputValue;
use engine::formats::plcopen::export;
use engine::formats::plcopen::Document;
use engine::iec::Address;
use engine::ladder::compile::{compile, Options};
use engine::ladder::edit::align_outputs;
use engine::ladder::{Element, Ladder};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");
const WORDS: &str = include_str!("fixtures/soft-words.xml");
const SOFT: Option<MachineId> = Some(MachineId::SoftPlc);
/// Scans a feedback loop broken at another block may put the drawn
/// ladder behind or ahead of the project as written.
const LOOP_SCANS: usize = 2;

/// The real projects the soft PLC runs as written that the page does not
/// draw, and why (at their line).
const NOT_DRAWN: [(&str, &str); 3] = [
    ("dnp3-test.xml", "wired straight to the left rail"),
    // Its ST runs (EXECUTE holds it); a ladder has no box for it.
    (
        "codesys-execute.xml",
        "EXECUTE is not a function or block the soft PLC has",
    ),
    (
        "saw-trap.xml",
        "RANDOM is declared as ULINT here and as INT",
    ),
];

fn loaded(text: &str) -> Box<dyn Plc> {
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    plc
}

/// The located inputs or outputs the project's variables declare; in a
/// project that locates none, the bits the ladder's contacts read only
/// (inputs, `%IX`) or its coils write (outputs, `%QX`).
fn located(ladder: &Ladder, prefix: &str) -> Vec<String> {
    let at: Vec<String> = ladder
        .variables
        .iter()
        .filter_map(|v| Address::parse(&v.address).ok())
        .map(|a| a.to_string())
        .filter(|a| a.starts_with(prefix))
        .collect();
    if !at.is_empty() || ladder.variables.iter().any(|v| !v.address.is_empty()) {
        return at;
    }
    let elements = || {
        ladder
            .rungs
            .iter()
            .flat_map(|r| r.elements().map(|(_, e)| e))
    };
    let written: Vec<&str> = elements().filter_map(Element::written_device).collect();
    let mut bits: Vec<String> = match prefix {
        "%IX" => elements()
            .filter_map(Element::read_device)
            .filter(|d| !written.contains(d) && !d.starts_with('_'))
            .map(str::to_string)
            .collect(),
        "%QX" => written
            .iter()
            .filter(|d| !d.starts_with('_'))
            .map(|d| d.to_string())
            .collect(),
        _ => Vec::new(),
    };
    bits.sort();
    bits.dedup();
    bits
}

/// Runs the project as written and as drawn side by side for 20 s of
/// inputs changing at pseudo-random times, comparing every located
/// output every scan (10 ms); returns how many output values changed.
/// Where a project feeds a block's output back to its input (a counter
/// reset by a timer it starts), the drawn ladder runs top to bottom and
/// the reader in data-flow order, each breaking the loop at another
/// block: the two may then differ for [`LOOP_SCANS`] scans, never more.
fn same_behaviour(name: &str, xml: &str, ladder: &Ladder) -> usize {
    let written = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{name}: {e:?}"));
    let drawn = compile(ladder, MachineId::SoftPlc, Options::default())
        .unwrap_or_else(|e| panic!("{name}: {e:?}"));
    if std::env::var("SHOW").is_ok() {
        eprintln!("{name}\n{drawn}");
    }
    let (mut a, mut b) = (loaded(&written.text), loaded(&drawn));
    let bits = located(ladder, "%IX");
    let words = located(ladder, "%IW");
    let outputs: Vec<String> = [located(ladder, "%QX"), located(ladder, "%QW")].concat();
    assert!(!outputs.is_empty(), "{name} has outputs");
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let mut changes = 0;
    let mut last: Vec<i64> = vec![0; outputs.len()];
    let mut apart: Vec<usize> = vec![0; outputs.len()];
    for step in 1..=2000u64 {
        if step % 7 == 0 && !(bits.is_empty() && words.is_empty()) {
            let r = next();
            let all = bits.len() + words.len();
            let k = (r % all as u64) as usize;
            let (device, value) = match bits.get(k) {
                Some(d) => (d, (r >> 8) as i64 & 1),
                None => (&words[k - bits.len()], (r >> 8) as i64 % 1024),
            };
            for plc in [&mut a, &mut b] {
                let d = plc.device(device).expect(device);
                plc.apply(Command::SetInput(d, InputValue::Int(value)))
                    .expect("input");
            }
        }
        let t = SimTime::from_millis(step * 10);
        a.run_until(t);
        b.run_until(t);
        for (k, out) in outputs.iter().enumerate() {
            let read = |p: &dyn Plc| p.read(p.device(out).expect(out)).as_i64();
            let (x, y) = (read(a.as_ref()), read(b.as_ref()));
            apart[k] = if x == y { 0 } else { apart[k] + 1 };
            assert!(
                apart[k] <= LOOP_SCANS,
                "{name}: {out} at {} ms: {x} as written, {y} as drawn",
                step * 10
            );
            changes += usize::from(x != last[k]);
            last[k] = x;
        }
    }
    changes
}

#[test]
fn the_real_projects_the_soft_plc_runs_are_drawn_and_run_the_same() {
    let Some(names) = crate::common::fixture_names(REAL, ".xml") else {
        return;
    };
    let mut drawn = Vec::new();
    for name in &names {
        let xml = std::fs::read_to_string(format!("{REAL}/{name}")).expect("readable");
        let runs = Document::read(&xml)
            .and_then(|document| document.soft_program(None))
            .is_ok();
        match Document::read(&xml)
            .and_then(|document| document.import(SOFT, None, None))
            .map(|i| i.ladder)
        {
            Ok(ladder) => {
                assert!(runs, "{name} drawn but not run as written");
                let changes = same_behaviour(name, &xml, &ladder);
                eprintln!("{name}: {changes} output changes");
                drawn.push(name.clone());
            }
            Err(errors) => {
                let said = errors[0].error.to_string();
                assert!(errors[0].line > 1, "{name}: at its line");
                if runs {
                    let (_, why) = NOT_DRAWN
                        .iter()
                        .find(|(n, _)| n == name)
                        .unwrap_or_else(|| panic!("{name} not drawn: {said}"));
                    assert!(said.contains(why), "{name}: {said}");
                }
            }
        }
    }
    assert!(drawn.len() >= 12, "{} drawn: {drawn:?}", drawn.len());
}

#[test]
fn our_word_project_is_drawn_with_its_boxes_and_runs_the_same() {
    let ladder = Document::read(WORDS)
        .and_then(|document| document.import(SOFT, None, None))
        .map(|i| i.ladder)
        .unwrap_or_else(|e| panic!("{e:?}"));
    let kinds: Vec<String> = ladder
        .rungs
        .iter()
        .flat_map(|r| {
            r.elements()
                .filter_map(|(_, e)| e.block().map(|b| b.kind()))
        })
        .collect();
    eprintln!("{kinds:?}");
    assert!(kinds.iter().any(|k| k == "MUL"), "{kinds:?}");
    assert!(same_behaviour("soft-words.xml", WORDS, &ladder) > 0);
}

/// `%IX0.0 → [c0: CTU PV 3] → %QX0.0`, its R fed below by `%IX0.1` OR
/// `%IX0.2`, and a word result: what the editor draws.
fn counter_with_reset() -> Ladder {
    use engine::ladder::edit::{parse_entry, Cursor, Edit, Editor, EntryKind};
    let entry =
        |text: &str| parse_entry(MachineId::SoftPlc, EntryKind::Instruction, text).expect(text);
    let mut e = Editor::new(Ladder::default());
    let mut place = |row, col, element| {
        let at = Cursor::new(0, row, col);
        e.apply(Edit::Place { at, element }).expect("places");
    };
    place(0, 0, Element::no("%IX0.0"));
    place(0, 1, entry("CTU c0 · 3"));
    place(0, 2, Element::coil("%QX0.0"));
    place(1, 0, Element::no("%IX0.1"));
    place(1, 1, entry("PIN R"));
    e.apply(Edit::PlaceBranch {
        at: Cursor::new(0, 2, 0),
        element: Element::no("%IX0.2"),
    })
    .expect("the OR below");
    e.ladder().clone()
}

#[test]
fn a_soft_plc_ladder_exported_and_opened_again_is_the_same_ladder() {
    let examples = engine::examples::EXAMPLES
        .iter()
        .filter(|e| e.machine == MachineId::SoftPlc);
    let mut ladders: Vec<(String, Ladder)> = examples
        .map(|e| {
            let l = engine::ladder::decompile::decompile_text(MachineId::SoftPlc, e.text, 10)
                .unwrap_or_else(|err| panic!("{}: {err:?}", e.id));
            (e.id.to_string(), l)
        })
        .collect();
    ladders.push(("reset network".into(), counter_with_reset()));
    for (name, ladder) in ladders {
        let xml = export(&ladder, "Main").unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let back = Document::read(&xml)
            .and_then(|document| document.import(SOFT, None, None))
            .map(|i| i.ladder)
            .unwrap_or_else(|e| panic!("{name}: {e:?}\n{xml}"));
        // Drawn with the outputs in the editor's last column, as the
        // page opens it.
        let logic = |l: &Ladder| {
            align_outputs(l, 9)
                .logic(MachineId::SoftPlc)
                .expect("reads")
        };
        assert_eq!(logic(&back), logic(&ladder), "{name}");
        // The export declares the instances and the BOOLs a ladder used
        // undeclared (a name a contact or coil uses undeclared is a BOOL).
        let plain_bool = |v: &engine::ladder::variables::Variable| {
            v.data_type == "BOOL" && v.address.is_empty() && v.comment.is_empty()
        };
        let declared: Vec<_> = back
            .variables
            .iter()
            .filter(|v| ladder.variables.contains(v) || (v.data_type != "CTU" && !plain_bool(v)))
            .cloned()
            .collect();
        assert_eq!(declared, ladder.variables, "{name}");
    }
}

#[test]
fn a_box_input_network_read_back_from_the_il_is_drawn_under_its_box() {
    let ladder = counter_with_reset();
    let il = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
    let back = engine::ladder::decompile::decompile_text(MachineId::SoftPlc, &il, 10)
        .unwrap_or_else(|e| panic!("{e:?}\n{il}"));
    assert_eq!(
        back.rungs.len(),
        1,
        "one rung, its reset network under the box"
    );
    let pin = back.rungs[0]
        .elements()
        .find(|(_, e)| matches!(e, Element::BoxInput { .. }));
    assert_eq!(
        pin.map(|(p, _)| (p.row, p.col)),
        Some((1, 1)),
        "{:?}",
        back.rungs[0]
    );
    let logic = |l: &Ladder| {
        align_outputs(l, 9)
            .logic(MachineId::SoftPlc)
            .expect("reads")
    };
    let (back, ours) = (logic(&back), logic(&ladder));
    // The same network on the same input (PV reads back typed: INT#3).
    assert_eq!(back[0].sides, ours[0].sides);
    assert_eq!(back[0].outputs, ours[0].outputs);
}

#[test]
fn function_boxes_whose_en_is_open_stand_on_the_rail_and_always_run() {
    // MUL(level, 3) written to `big`: no contact before it.
    let ladder = Document::read(WORDS)
        .and_then(|document| document.import(SOFT, None, None))
        .map(|i| i.ladder)
        .expect("drawn");
    let on_rail = ladder.rungs.iter().find(|r| {
        r.elements()
            .any(|(p, e)| p.col > 0 && e.block().is_some_and(|b| b.kind() == "SEL"))
    });
    let rung = on_rail.expect("the SEL rung");
    assert!(
        rung.elements()
            .filter(|(p, _)| p.col == 0)
            .all(|(_, e)| matches!(e, Element::Wire)),
        "{rung:?}"
    );
    let logic = ladder.logic(MachineId::SoftPlc).expect("reads");
    assert!(logic
        .iter()
        .any(|l| matches!(l.condition, engine::ladder::Net::Leaf(Element::Wire, _))));
}

#[test]
fn an_exported_edge_comes_back_as_an_edge_and_a_named_trigger_as_its_box() {
    use engine::ladder::edit::{parse_entry, Cursor, Edit, Editor, EntryKind};
    // `a → [myTrig: R_TRIG] → r` (a project's own trigger, a box) and
    // `a → falling edge → q` (the editor's in-line edge).
    let mut e = Editor::new(Ladder::default());
    let mut place = |rung, col, element| {
        let at = Cursor::new(rung, 0, col);
        e.apply(Edit::Place { at, element }).expect("places");
    };
    let trigger = parse_entry(
        MachineId::SoftPlc,
        EntryKind::Instruction,
        "myTrig: R_TRIG()",
    )
    .expect("a box");
    place(0, 0, Element::no("a"));
    place(0, 1, trigger);
    place(0, 2, Element::coil("r"));
    place(1, 0, Element::no("a"));
    place(1, 1, Element::Edge { falling: true });
    place(1, 2, Element::coil("q"));
    let ladder = e.ladder().clone();
    let elements = |l: &Ladder| -> Vec<Element> {
        l.rungs
            .iter()
            .flat_map(|r| r.elements().map(|(_, e)| e.clone()).collect::<Vec<_>>())
            .collect()
    };
    let xml = export(&ladder, "Main").expect("exports");
    assert!(xml.contains("F_TRIG"), "exported as an F_TRIG");
    let back = Document::read(&xml)
        .and_then(|document| document.import(SOFT, None, None))
        .map(|i| i.ladder)
        .expect("imports");
    let back_elements = elements(&back);
    assert!(
        back_elements.contains(&Element::Edge { falling: true }),
        "{back_elements:?}"
    );
    assert!(
        back_elements
            .iter()
            .any(|e| e.block().is_some_and(|b| b.instance == "myTrig")),
        "a project's own trigger keeps its box: {back_elements:?}"
    );
    assert!(back.variables.iter().all(|v| !v.name.starts_with("F_TRIG")));
}
