use super::*;
use crate::plc::Plc;
use crate::softplc::st::st_blocks;
use crate::softplc::st_why::st_writes;
use crate::softplc::SoftPlc;
use crate::time::SimTime;

/// A library of one block whose output two branches write.
const LIBRARY: &str = "FUNCTION_BLOCK Pick
VAR_INPUT
  go : BOOL;
  x : INT;
END_VAR
VAR_OUTPUT
  ok : BOOL;
END_VAR
IF go AND x > 3 THEN
  ok := TRUE;
ELSE
  ok := FALSE;
END_IF;
END_FUNCTION_BLOCK
";

/// A ladder's IL calling two instances, the blocks' IL after it (as the
/// soft PLC compiles a ladder with ST boxes).
fn ladder_text(blocks: &StBlocks) -> String {
    let ladder = "VAR\n  p0 : Pick;\n  p1 : Pick;\nEND_VAR\n\
        CAL p0(go := TRUE, x := 5)\nCAL p1(go := TRUE, x := 1)\n";
    format!("{ladder}{}", blocks.il)
}

/// The ladder run one scan, traced.
fn ran_one_scan() -> (SoftPlc, StMap) {
    let blocks = st_blocks(LIBRARY).expect("a library loads");
    let text = ladder_text(&blocks);
    let mut plc = SoftPlc::new();
    plc.load_text(&text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    plc.set_tracing(true);
    plc.run_until(SimTime::from_millis(10));
    let map = StMap::for_ladder(plc.machine().program(), &text, &blocks);
    (plc, map)
}

#[test]
fn each_instance_has_its_body_and_each_step_its_st_line_and_call() {
    let (plc, map) = ran_one_scan();
    let names: Vec<(&str, &str)> = map
        .instances
        .iter()
        .map(|i| (i.name.as_str(), i.block.as_str()))
        .collect();
    assert_eq!(names, [("p0", "Pick"), ("p1", "Pick")]);
    let (p0, p1) = (&map.instances[0].steps, &map.instances[1].steps);
    assert_eq!(p0.end, p1.start, "one body after the other");
    assert_eq!(p1.end, plc.machine().program().len());
    // The ladder's own steps have no ST line and run in no call.
    assert_eq!(map.place(0), None);
    assert!(map.owners[..p0.start].iter().all(Option::is_none));
    // Both bodies are the block's lines 9 to 13, each in its own call.
    let lines_of = |steps: &std::ops::Range<usize>, owner| {
        let mut seen: Vec<usize> = steps
            .clone()
            .filter_map(|s| map.place(s))
            .map(|(line, o)| {
                assert_eq!(o, Some(owner), "step of call {owner}");
                line
            })
            .collect();
        seen.dedup();
        seen
    };
    // The THEN branch's jump to the end and the body's last label have
    // no line: not back to the IF's after a branch.
    let p0_lines = lines_of(p0, 0);
    assert_eq!(p0_lines, [9, 10, 12]);
    assert_eq!(p0_lines, lines_of(p1, 1));
    assert_eq!(map.instance("P1"), Some(1));
}

#[test]
fn why_names_the_write_that_ran_in_the_instances_call() {
    let (plc, map) = ran_one_scan();
    let writes = st_writes(LIBRARY, Some("Pick"), "ok");
    assert_eq!(
        writes.iter().map(|w| w.line).collect::<Vec<_>>(),
        [10, 12],
        "two writes in the text"
    );
    let ran = plc.trace().expect("traced").ran.clone();
    // p0 (x = 5) took the THEN branch, p1 (x = 1) the ELSE one.
    assert_eq!(map.ran_last(&writes, "p0", &ran), Some(0));
    assert_eq!(map.ran_last(&writes, "p1", &ran), Some(1));
    assert_eq!(map.ran_last(&writes, "nobody", &ran), None);
    // A scan in which no step ran: no write ran.
    assert_eq!(map.ran_last(&writes, "p0", &[]), None);
}

#[test]
fn a_ladder_not_ending_with_the_blocks_il_has_no_st_lines() {
    let blocks = st_blocks(LIBRARY).expect("a library loads");
    let text = ladder_text(&blocks);
    let program = Program::load(&text).expect("loads");
    // The same IL from a text one line down: its lines follow the text.
    let moved = st_blocks(&format!("\n{LIBRARY}")).expect("loads");
    assert_eq!(moved.il, blocks.il);
    let lines = moved.step_lines(&program, &text);
    assert_eq!(lines.iter().flatten().min(), Some(&10), "line 9 moved down");
    let stale = StBlocks {
        il: format!("{}\n", blocks.il),
        ..blocks
    };
    assert!(stale
        .step_lines(&program, &text)
        .iter()
        .all(Option::is_none));
}

#[test]
fn a_texts_blocks_span_their_lines() {
    let text = format!(
        "{LIBRARY}\nFUNCTION_BLOCK Other\nVAR\n  n : INT;\nEND_VAR\nn := 1;\nEND_FUNCTION_BLOCK\n"
    );
    let found = block_lines(&text);
    assert_eq!(
        found,
        [("Pick".to_string(), 1..=14), ("Other".to_string(), 16..=21)]
    );
    assert_eq!(block_lines("FUNCTION_BLOCK"), []);
}
