//! PLCopen projects: block pins by formal name (item 7), loops of wires
//! through typed functions (item 8), messages that said the wrong thing
//! (item 14).

use super::*;

/// Item 7: a misspelled input of a standard block was dropped (a TON's
/// PT left at 0, a CTU never reset); now refused at the block's line,
/// as the IL loader refuses an unknown CAL input.
#[test]
fn a_standard_blocks_input_it_does_not_have_is_refused_at_its_line() {
    let vars = [
        var("start", "BOOL", "%IX0.0"),
        var("clear", "BOOL", "%IX0.1"),
        var("lamp", "BOOL", "%QX0.0"),
        var("t0", "TON", ""),
    ]
    .concat();
    let body = [
        input(1, "start"),
        input(2, "T#500ms"),
        block(
            3,
            "TON",
            "t0",
            &[("IN", 1, ""), ("PTT", 2, "")],
            &["Q", "ET"],
        ),
        output(4, 3, "Q", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "typeName=\"TON\"");
    assert_eq!(
        soft_errors(&xml),
        [format!(
            "{at}: TON block t0 has no input `PTT` (its inputs: IN, PT)"
        )]
    );

    let vars = [
        var("pulse", "BOOL", "%IX0.0"),
        var("clear", "BOOL", "%IX0.1"),
        var("done", "BOOL", "%QX0.0"),
        var("c0", "CTU", ""),
    ]
    .concat();
    let body = [
        input(1, "pulse"),
        input(2, "clear"),
        input(5, "3"),
        block(
            3,
            "CTU",
            "c0",
            &[("CU", 1, ""), ("RESET", 2, ""), ("PV", 5, "")],
            &["Q", "CV"],
        ),
        output(4, 3, "Q", "done"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "typeName=\"CTU\"");
    assert_eq!(
        soft_errors(&xml),
        [format!(
            "{at}: CTU block c0 has no input `RESET` (its inputs: CU, R, PV)"
        )]
    );
}

/// Item 7: the same on the project's own blocks.
#[test]
fn an_own_blocks_input_it_does_not_have_is_refused_at_its_line() {
    let vars = [
        var("go", "BOOL", "%IX0.0"),
        var("stop", "BOOL", "%IX0.1"),
        var("lamp", "BOOL", "%QX0.0"),
        var("one", "Latch", ""),
    ]
    .concat();
    let body = [
        input(1, "go"),
        input(2, "stop"),
        block(
            3,
            "Latch",
            "one",
            &[("set", 1, ""), ("rest", 2, "")],
            &["q"],
        ),
        output(4, 3, "q", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, LATCH);
    let at = line_of(&xml, "typeName=\"Latch\"");
    assert_eq!(
        soft_errors(&xml),
        [format!(
            "{at}: Latch block one has no input `rest` (its inputs: set, reset)"
        )]
    );
    // Spelled right, it runs (the pins match in any case, as IEC's names do).
    let fixed = xml.replace("\"rest\"", "\"RESET\"");
    let soft = Document::read(&fixed).and_then(|document| document.soft_program(None));
    assert!(soft.is_ok(), "{:?}", soft.err());
}

/// Item 14: a wire from an output pin the block lacks was "a loop of
/// wires through a TON block"; it says the pin now, at the line of the
/// element the wire feeds.
#[test]
fn a_wire_from_an_output_pin_a_block_lacks_says_so() {
    let vars = [
        var("start", "BOOL", "%IX0.0"),
        var("lamp", "BOOL", "%QX0.0"),
        var("t0", "TON", ""),
        var("one", "Latch", ""),
        var("lamp2", "BOOL", "%QX0.1"),
    ]
    .concat();
    let body = [
        input(1, "start"),
        input(2, "T#500ms"),
        block(
            3,
            "TON",
            "t0",
            &[("IN", 1, ""), ("PT", 2, "")],
            &["Q", "ET"],
        ),
        output(4, 3, "QQ", "lamp"),
        block(
            5,
            "Latch",
            "one",
            &[("set", 1, ""), ("reset", 1, "")],
            &["q"],
        ),
        output(6, 5, "out", "lamp2"),
    ]
    .concat();
    let xml = project(&vars, &body, LATCH);
    let four = line_of(&xml, "<outVariable localId=\"4\"");
    let six = line_of(&xml, "<outVariable localId=\"6\"");
    assert_eq!(
        soft_errors(&xml),
        [
            format!("{four}: output variable lamp is wired from TON block t0's `QQ`, an output the block does not have (its outputs: Q, ET)"),
            format!("{six}: output variable lamp2 is wired from Latch block one's `out`, an output the block does not have (its outputs: q)"),
        ]
    );
}

/// Item 14: a connection to an element that is not drawn is said once,
/// at its line; what the refused element feeds is not called "a loop of
/// wires" as well.
#[test]
fn a_dangling_connection_is_said_once_with_no_false_loop() {
    let vars = [var("level", "INT", "%IW0"), var("out", "INT", "%QW0")].concat();
    let body = [
        input(1, "level"),
        block(2, "ADD", "", &[("IN1", 1, ""), ("IN2", 99, "")], &["OUT"]),
        block(3, "MUL", "", &[("IN1", 2, "OUT"), ("IN2", 1, "")], &["OUT"]),
        output(4, 3, "OUT", "out"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "typeName=\"ADD\"");
    assert_eq!(
        soft_errors(&xml),
        [format!("{at}: a connection to 99, which is not drawn")]
    );
}

/// Item 14: an instance of the project's own block (drawn, so it runs)
/// that no variable declares was told "Latch is the project's own
/// function block in LD: the soft PLC runs the project's function blocks
/// drawn in LD or FBD", which contradicts itself.
#[test]
fn an_undeclared_instance_of_an_own_block_says_to_declare_it() {
    let vars = [var("go", "BOOL", "%IX0.0"), var("lamp", "BOOL", "%QX0.0")].concat();
    let body = [
        input(1, "go"),
        block(
            3,
            "Latch",
            "one",
            &[("set", 1, ""), ("reset", 1, "")],
            &["q"],
        ),
        output(4, 3, "q", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, LATCH);
    let at = line_of(&xml, "typeName=\"Latch\"");
    assert_eq!(
        soft_errors(&xml),
        [format!("{at}: one is not declared: declare it as a Latch instance (`one : Latch;`) among the POU's variables")]
    );
}

/// Item 8: a loop of wires through functions whose types the drawing
/// gives was refused ("a loop of wires through a DINT_TO_INT block");
/// it runs as docs/soft-plc.md says: the loop's first element reads what
/// the loop left in the last scan.
#[test]
fn a_loop_of_wires_through_typed_functions_runs_a_scan_behind() {
    // An ADD feeding its own input: a counter of scans.
    let vars = [var("count", "INT", "%QW0"), var("step", "INT", "")].concat();
    let body = [
        input(1, "INT#1"),
        block(2, "ADD", "", &[("IN1", 2, "OUT"), ("IN2", 1, "")], &["OUT"]),
        output(3, 2, "OUT", "count"),
        output(4, 2, "OUT", "step"),
    ]
    .concat();
    let mut plc = soft_plc(&project(&vars, &body, ""));
    plc.run_until(SimTime::from_millis(100));
    let scans = plc.scans() as i64;
    assert_eq!(read(plc.as_ref(), "count"), scans);

    // A conversion pair feeding each other, with an ADD in the loop:
    // INT_TO_DINT(DINT_TO_INT(x) + 2) — each scan adds 2 to what the loop
    // left.
    let vars = [var("wide", "DINT", "%QD0"), var("narrow", "INT", "%QW0")].concat();
    let body = [
        block(1, "INT_TO_DINT", "", &[("IN", 3, "OUT")], &["OUT"]),
        block(2, "DINT_TO_INT", "", &[("IN", 1, "OUT")], &["OUT"]),
        input(5, "INT#2"),
        block(3, "ADD", "", &[("IN1", 2, "OUT"), ("IN2", 5, "")], &["OUT"]),
        output(6, 1, "OUT", "wide"),
        output(7, 3, "OUT", "narrow"),
    ]
    .concat();
    let mut plc = soft_plc(&project(&vars, &body, ""));
    plc.run_until(SimTime::from_millis(100));
    let scans = plc.scans() as i64;
    assert_eq!(read(plc.as_ref(), "narrow"), 2 * scans);
    // The conversion runs first (topmost) and reads the ADD's last scan.
    assert_eq!(read(plc.as_ref(), "wide"), 2 * (scans - 1));
}

/// Item 8: a loop whose type nothing gives (an ADD of its own output and
/// an untyped literal) is still refused, saying why.
#[test]
fn a_loop_whose_type_nothing_gives_is_refused_saying_so() {
    let vars = var("count", "INT", "%QW0");
    let body = [
        input(1, "1"),
        block(2, "ADD", "", &[("IN1", 2, "OUT"), ("IN2", 1, "")], &["OUT"]),
        output(3, 2, "OUT", "count"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "typeName=\"ADD\"");
    assert_eq!(
        soft_errors(&xml),
        [format!(
            "{at}: ADD block: a loop of wires through it whose type nothing gives: type a literal in the loop (INT#1) or break it with a variable"
        )]
    );
}

/// Item 7 on the bit machines: a CTU's misspelled `RESET` was dropped
/// (the counter never reset); refused at the block's line, as a TON's
/// `PTT` (which was "its PT input is not connected").
#[test]
fn a_bit_machines_block_input_it_does_not_have_is_refused_at_its_line() {
    let vars = [
        var("pulse", "BOOL", "%IX0.0"),
        var("clear", "BOOL", "%IX0.1"),
        var("done", "BOOL", "%QX0.0"),
        var("c0", "CTU", ""),
        var("t0", "TON", ""),
        var("lamp", "BOOL", "%QX0.1"),
    ]
    .concat();
    let body = [
        input(1, "pulse"),
        input(2, "clear"),
        input(5, "3"),
        block(
            3,
            "CTU",
            "c0",
            &[("CU", 1, ""), ("RESET", 2, ""), ("PV", 5, "")],
            &["Q", "CV"],
        ),
        output(4, 3, "Q", "done"),
        input(6, "T#500ms"),
        block(
            7,
            "TON",
            "t0",
            &[("IN", 1, ""), ("PTT", 6, "")],
            &["Q", "ET"],
        ),
        output(8, 7, "Q", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let map = engine::formats::plcopen::VarMap::parse("c0,C00\nt0,T00\n").expect("a map");
    let errors = refused(
        engine::formats::plcopen::Document::read(&xml)
            .and_then(|document| document.import(Some(MachineId::Io86a), Some(&map), None)),
        "misspelled inputs",
    );
    let said: Vec<String> = errors
        .iter()
        .map(|e| format!("{}: {}", e.line, e.error))
        .collect();
    let (ctu, ton) = (
        line_of(&xml, "typeName=\"CTU\""),
        line_of(&xml, "typeName=\"TON\""),
    );
    assert_eq!(
        said,
        [
            format!("{ctu}: CTU block c0: it has no input `RESET` (its inputs: CU, R, PV)"),
            format!("{ton}: TON block t0: it has no input `PTT` (its inputs: IN, PT)"),
        ]
    );
}

/// Item 14 on the bit machines: a wire from an output the block does not
/// have was "no path joins the left rail to coil Y01"; it says the pin,
/// as the soft PLC's readers do.
#[test]
fn every_reader_says_a_wire_from_an_output_a_block_lacks() {
    let vars = [
        var("start", "BOOL", "%IX0.0"),
        var("lamp", "BOOL", "%QX0.1"),
        var("t0", "TON", ""),
    ]
    .concat();
    let body = [
        input(1, "start"),
        input(2, "T#500ms"),
        block(
            3,
            "TON",
            "t0",
            &[("IN", 1, ""), ("PT", 2, "")],
            &["Q", "ET"],
        ),
        output(4, 3, "QQ", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "<outVariable localId=\"4\"");
    let map = engine::formats::plcopen::VarMap::parse("t0,T00\n").expect("a map");
    let said = |machine| -> Vec<String> {
        let errors = refused(
            engine::formats::plcopen::Document::read(&xml)
                .and_then(|document| document.import(Some(machine), Some(&map), None)),
            "a wire from QQ",
        );
        errors
            .iter()
            .map(|e| format!("{}: {}", e.line, e.error))
            .collect()
    };
    assert_eq!(
        said(MachineId::Io86a),
        [format!("{at}: output variable lamp is wired from TON block t0's `QQ`, an output the block does not have (its outputs: Q, ET)")],
    );
    // The page's reader on the soft PLC said it already, at the block.
    let block = line_of(&xml, "typeName=\"TON\"");
    assert_eq!(
        said(MachineId::SoftPlc),
        [format!("{block}: TON block t0: TON has no output QQ")]
    );
}

/// Items 7 and 8 through `hashigo run`: a misspelled input exits 2 with
/// the block's line; a loop of wires through an ADD runs, adding one a
/// scan.
#[test]
fn hashigo_run_refuses_a_misspelled_input_and_runs_a_typed_loop() {
    let tmp = crate::common::Temp::new("round3-files-run");
    let vars = [
        var("start", "BOOL", "%IX0.0"),
        var("lamp", "BOOL", "%QX0.0"),
        var("t0", "TON", ""),
    ]
    .concat();
    let body = [
        input(1, "start"),
        input(2, "T#500ms"),
        block(
            3,
            "TON",
            "t0",
            &[("IN", 1, ""), ("PTT", 2, "")],
            &["Q", "ET"],
        ),
        output(4, 3, "Q", "lamp"),
    ]
    .concat();
    let xml = project(&vars, &body, "");
    let at = line_of(&xml, "typeName=\"TON\"");
    let path = tmp.file("misspelled.xml", &xml);
    let args = [
        "run",
        "--machine",
        "soft-plc",
        "--program",
        &path,
        "--until",
        "50ms",
        "--every",
        "10ms",
        "--watch",
    ];
    let out = crate::common::hashigo(&[&args[..], &["lamp"]].concat(), "");
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        crate::common::text(&out.stderr),
        format!("error: {path}:{at}: TON block t0 has no input `PTT` (its inputs: IN, PT)\n")
    );

    let vars = var("count", "INT", "%QW0");
    let body = [
        input(1, "INT#1"),
        block(2, "ADD", "", &[("IN1", 2, "OUT"), ("IN2", 1, "")], &["OUT"]),
        output(3, 2, "OUT", "count"),
    ]
    .concat();
    let path = tmp.file("loop.xml", &project(&vars, &body, ""));
    let args = [
        "run",
        "--machine",
        "soft-plc",
        "--program",
        &path,
        "--until",
        "50ms",
        "--every",
        "10ms",
        "--watch",
        "count",
    ];
    let out = crate::common::hashigo(&args, "");
    let stdout = crate::common::text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        crate::common::text(&out.stderr)
    );
    let counts: Vec<i64> = stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).and_then(|v| v.parse().ok()).expect(l))
        .collect();
    assert_eq!(counts.len(), 6, "{stdout}");
    assert!(counts.windows(2).all(|w| w[1] == w[0] + 1), "{stdout}");
}
