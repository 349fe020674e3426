//! The project's own Structured Text function blocks as ladder boxes
//! (issue #55): declared from an ST text (`softplc::st::st_blocks`),
//! typed in the device entry by their pins, compiled with their IL after
//! the ladder's and run on the soft PLC; a box whose block the text no
//! longer declares is an error at its cell, the ladder kept.

use engine::events::InputValue;
use engine::ladder::compile::{compile, Options};
use engine::ladder::edit::{parse_entry, Cursor, Edit, Editor, EntryKind};
use engine::ladder::{user_blocks, Element, Ladder, Variable};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

/// Blocks only, no PROGRAM: a library for the ladder.
const LIBRARY: &str = "\
FUNCTION_BLOCK Scale
VAR_INPUT
  go : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ok : BOOL;
  y : INT;
END_VAR
y := x * 2 + 1;
ok := go AND y > 10;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Count
VAR_INPUT
  step : INT;
END_VAR
VAR_OUTPUT
  n : INT;
END_VAR
n := n + step;
END_FUNCTION_BLOCK
";

fn declare(text: &str) {
    let b = engine::softplc::st::st_blocks(text).expect("loads");
    user_blocks::set(b.blocks, b.il);
}

fn entry(text: &str) -> Element {
    parse_entry(MachineId::SoftPlc, EntryKind::Instruction, text).expect(text)
}

/// `%IX0.0 → [s0: SCALE x] → %QX0.0` and `[c0: COUNT 2]` on a rung of
/// its own.
fn ladder() -> Ladder {
    let mut e = Editor::new(Ladder::default());
    let mut place = |rung, row, col, element| {
        e.apply(Edit::Place {
            at: Cursor::new(rung, row, col),
            element,
        })
        .expect("places");
    };
    place(0, 0, 0, Element::no("%IX0.0"));
    place(0, 0, 1, entry("SCALE s0 x"));
    place(0, 0, 2, Element::coil("%QX0.0"));
    place(1, 0, 0, entry("COUNT c0 2"));
    place(1, 0, 1, Element::coil("%QX0.1"));
    let mut ladder = e.ladder().clone();
    let mut x = Variable::new("x", "INT");
    x.initial = "3".into();
    ladder.variables.push(x);
    ladder
}

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

#[test]
fn a_library_of_st_blocks_gives_their_pins() {
    let b = engine::softplc::st::st_blocks(LIBRARY).expect("a library loads");
    assert!(!b.program);
    let names: Vec<_> = b.blocks.iter().map(|b| b.name.as_str()).collect();
    assert_eq!(names, ["SCALE", "COUNT"]);
    assert_eq!(b.blocks[0].inputs.len(), 2);
    assert_eq!(b.blocks[0].outputs[1].0, "y");
    assert!(b.il.starts_with("FUNCTION_BLOCK"), "{}", b.il);
    assert!(!b.il.contains("PROGRAM"), "{}", b.il);
    // Its errors are at their lines, as a program's.
    let bad = LIBRARY.replace("y := x * 2 + 1;", "y := nope;");
    let errors = engine::softplc::st::st_blocks(&bad).expect_err("refused");
    assert_eq!(errors[0].line, 10, "{errors:?}");
}

#[test]
fn a_ladder_box_calls_an_st_block_and_its_power_follows_its_bool_pins() {
    declare(LIBRARY);
    let ladder = ladder();
    let scale = ladder.rungs[0]
        .get(engine::ladder::Pos::new(0, 1))
        .expect("the box");
    let call = scale.block().expect("a box");
    assert_eq!(call.to_string(), "s0: SCALE(x := x)", "power into go");
    assert_eq!(
        call.watched()[..2],
        [
            ("ok".to_string(), "s0.ok".to_string()),
            ("y".into(), "s0.y".into())
        ]
    );
    let text = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
    assert!(text.contains("FUNCTION_BLOCK SCALE") || text.contains("FUNCTION_BLOCK Scale"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    plc.run_until(SimTime::from_millis(35));
    assert_eq!(get(plc.as_ref(), "s0.y"), 7, "x * 2 + 1 with x = 3");
    assert_eq!(get(plc.as_ref(), "%QX0.0"), 0, "no power in: ok is FALSE");
    // No BOOL input: it runs while powered (every scan here), adding 2.
    let scans = plc.scans() as i64;
    assert_eq!(get(plc.as_ref(), "c0.n"), 2 * scans);
    assert_eq!(get(plc.as_ref(), "%QX0.1"), 1, "no BOOL output: power on");
    let d = plc.device("x").expect("x");
    plc.apply(Command::SetInput(d, InputValue::Int(6)))
        .expect("x");
    let d = plc.device("%IX0.0").expect("input");
    plc.apply(Command::SetInput(d, InputValue::Int(1)))
        .expect("on");
    plc.run_until(SimTime::from_millis(70));
    assert_eq!(get(plc.as_ref(), "s0.y"), 13);
    assert_eq!(get(plc.as_ref(), "%QX0.0"), 1, "go and y > 10");
}

#[test]
fn a_box_whose_block_is_gone_is_an_error_at_its_cell_the_ladder_kept() {
    declare(LIBRARY);
    let ladder = ladder();
    // The text no longer declares SCALE.
    let only_count = LIBRARY
        .split("END_FUNCTION_BLOCK\n")
        .nth(1)
        .expect("the second block")
        .to_string()
        + "END_FUNCTION_BLOCK\n";
    declare(&only_count);
    let errors = compile(&ladder, MachineId::SoftPlc, Options::default()).expect_err("refused");
    assert_eq!(errors.len(), 1, "{errors:?}");
    let e = &errors[0];
    assert_eq!(
        (e.rung, e.pos),
        (1, Some(engine::ladder::Pos::new(0, 1))),
        "{e}"
    );
    assert!(e.to_string().contains("SCALE"), "{e}");
    // Declared again: it compiles.
    declare(LIBRARY);
    assert!(compile(&ladder, MachineId::SoftPlc, Options::default()).is_ok());
}
