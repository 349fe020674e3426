//! Issue #43, round 3: il. The soft PLC's Instruction List loader, its
//! literals and types (and issue #44's literals and block outputs).

use engine::formats::plcopen::Document;
use engine::iec::{Data, DataType};
use engine::softplc::Program;

const MS: i64 = 1_000_000;

pub(super) fn load(text: &str) -> Program {
    Program::load(text).unwrap_or_else(|e| panic!("{text}\n{e:?}"))
}

/// Each error of a text refused: its line and message.
pub(super) fn refused(text: &str) -> Vec<(usize, String)> {
    match Program::load(text) {
        Ok(_) => panic!("loaded, should be refused:\n{text}"),
        Err(errors) => errors
            .into_iter()
            .map(|e| (e.line, e.error.to_string()))
            .collect(),
    }
}

/// The one error of a text refused, which must be at `line`.
fn refused_at(text: &str, line: usize) -> String {
    let got = refused(text);
    assert_eq!(got.len(), 1, "one error: {got:?}");
    assert_eq!(got[0].0, line, "{got:?}");
    got[0].1.clone()
}

fn int(t: DataType, v: i128) -> Option<Data> {
    Some(Data::integer(t, v))
}

// 43.1: shift counts of 2^32 or more.

#[test]
fn a_shift_by_two_to_the_32_or_more_gives_zero() {
    let mut p = load(
        "VAR\n  x : ULINT := 1;\n  n : ULINT := 4294967296;\n  m : LINT := 4294967297;\n\
         big : ULINT := 18446744073709551615;\n  \
         a : ULINT;\n  b : ULINT;\n  c : ULINT;\n  d : ULINT;\n  e : ULINT;\nEND_VAR\n\
         LD x\nSHL n\nST a\nLD x\nSHL m\nST b\nLD x\nSHR big\nST c\n\
         LD x\nROL m\nST d\nLD x\nROR big\nST e",
    );
    p.scan(0);
    assert_eq!(p.value("a"), int(DataType::Ulint, 0), "SHL by 2^32");
    assert_eq!(p.value("b"), int(DataType::Ulint, 0), "SHL by 2^32 + 1");
    assert_eq!(p.value("c"), int(DataType::Ulint, 0), "SHR by 2^64 - 1");
    // Rotations take the count modulo the width: 2^32 + 1 is 1 mod 64,
    // 2^64 - 1 is 63 mod 64 (ROR by 63 is ROL by 1).
    assert_eq!(p.value("d"), int(DataType::Ulint, 2), "ROL by 2^32 + 1");
    assert_eq!(p.value("e"), int(DataType::Ulint, 2), "ROR by 2^64 - 1");
}

#[test]
fn a_negative_count_shifts_to_zero_and_rotates_the_other_way() {
    let mut p = load(
        "VAR\n  x : WORD := 16#0001;\n  n : INT := -1;\n  a : WORD;\n  b : WORD;\n  \
         c : WORD;\n  far : LINT := -4294967296;\n  d : WORD;\nEND_VAR\n\
         LD x\nSHL n\nST a\nLD x\nROL n\nST b\nLD x\nROR n\nST c\nLD x\nSHR far\nST d",
    );
    p.scan(0);
    assert_eq!(p.value("d"), int(DataType::Word, 0), "SHR by -2^32");
    assert_eq!(p.value("a"), int(DataType::Word, 0));
    assert_eq!(
        p.value("b"),
        int(DataType::Word, 0x8000),
        "ROL by -1 is ROR by 1"
    );
    assert_eq!(
        p.value("c"),
        int(DataType::Word, 2),
        "ROR by -1 is ROL by 1"
    );
}

// 43.2: ULINT counters' PV of 2^63 or more.

#[test]
fn a_ulint_counter_takes_a_preset_of_two_to_the_63_and_more() {
    let mut p = load(
        "VAR\n  up : CTU_ULINT;\n  down : CTD_ULINT;\n  q : BOOL;\n  dq : BOOL;\n  \
         cv : ULINT;\n  pv : ULINT := 18446744073709551615;\nEND_VAR\n\
         CAL up(CU := TRUE, R := FALSE, PV := ULINT#9223372036854775808, Q => q)\n\
         CAL down(CD := FALSE, LD := TRUE, PV := pv, Q => dq, CV => cv)",
    );
    p.scan(0);
    assert_eq!(p.value("q"), Some(Data::Bool(false)), "CV 1 is below 2^63");
    assert_eq!(
        p.value("dq"),
        Some(Data::Bool(false)),
        "loaded, CV is not 0"
    );
    assert_eq!(p.value("cv"), int(DataType::Ulint, u64::MAX.into()));
}

// 43.3: one program a text.

#[test]
fn a_second_program_in_one_text_is_refused_at_its_line() {
    let text = "PROGRAM first\nVAR\n  a : BOOL;\nEND_VAR\nLD a\nRET\nEND_PROGRAM\n\
                PROGRAM second\nLD a\nST a\nEND_PROGRAM";
    let why = refused_at(text, 8);
    assert!(why.contains("one program"), "{why}");
}

// 43.4 and 44.1: typed literals refused where another type is needed;
// untyped ones take the type of their use.

#[test]
fn a_typed_literal_of_another_type_is_refused_even_when_it_fits() {
    let head = "VAR\n  d : DINT;\n  i : INT;\n  c : CTU;\n  b : BOOL;\nEND_VAR\n";
    for (code, line) in [
        ("LD d\nADD INT#5\nST d", 8),
        ("LD d\nGT INT#5\nST b", 8),
        ("LD i\nMAX DINT#5\nST i", 8),
        ("CAL c(CU := b, PV := DINT#5)", 7),
        ("LD DINT#5\nST i", 8),
    ] {
        let text = format!("{head}{code}");
        let why = refused_at(&text, line);
        assert!(why.contains("INT"), "{code}: {why}");
    }
    let why = refused_at(&format!("{head}LD d\nADD INT#5\nST d"), 8);
    assert_eq!(why, "`INT#5` is not a DINT value");
    let why = refused_at(&format!("{head}CAL c(CU := b, PV := DINT#5)"), 7);
    assert_eq!(why, "`DINT#5` is not an INT value");
}

#[test]
fn untyped_literals_take_the_type_their_use_needs() {
    let mut p = load(
        "VAR\n  w AT %MW0 : INT;\n  u : UINT;\n  big : ULINT;\n  b : BOOL;\n  \
         g : BOOL;\n  r : REAL;\n  c : CTU;\n  k : WORD;\n  n : INT := 7;\n  d : DINT;\n  v : UINT;\nEND_VAR\n\
         LD 40\nADD 2\nST %MW0\n\
         LD 0\nST u\n\
         LD 18446744073709551615\nST big\n\
         LD 5\nGT n\nST b\n\
         LD 3\nADD 4\nMUL n\nGT 40\nST g\n\
         LD 2\nADD r\nST r\n\
         LD 16#FFFF\nNOT\nST k\n\
         CAL c(CU := TRUE, PV := 1)\n\
         LD 70\nLIMIT 0, 50\nST n\n\
         LD TRUE\nSEL 1, 65535\nST v\n\
         LD 2\nMAX n\nDIV 10\nINT_TO_DINT\nST d",
    );
    p.scan(0);
    assert_eq!(p.value("w"), int(DataType::Int, 42));
    assert_eq!(p.value("u"), int(DataType::Uint, 0));
    assert_eq!(p.value("big"), int(DataType::Ulint, u64::MAX.into()));
    assert_eq!(p.value("b"), Some(Data::Bool(false)), "5 > 7");
    assert_eq!(p.value("g"), Some(Data::Bool(true)), "(3 + 4) * 7 > 40");
    assert_eq!(p.value("r"), Some(Data::Real(2.0)));
    assert_eq!(p.value("k"), int(DataType::Word, 0));
    assert_eq!(p.value("n"), int(DataType::Int, 50), "LIMIT's inputs");
    assert_eq!(p.value("v"), int(DataType::Uint, 65535), "SEL's inputs");
    assert_eq!(p.value("d"), int(DataType::Dint, 5), "MAX(2, 50) / 10");
}

#[test]
fn an_untyped_literal_with_no_typed_use_is_a_dint() {
    let mut p = load("VAR\n  d : DINT;\nEND_VAR\nLD 40000\nADD 2\nST d");
    p.scan(0);
    assert_eq!(p.value("d"), int(DataType::Dint, 40002));
    // With no typed use at all, DINT wraps as DINT does.
    let mut p = load("VAR\n  d : DINT;\nEND_VAR\nLD 2147483647\nADD 1\nST d");
    p.scan(0);
    assert_eq!(p.value("d"), int(DataType::Dint, -2147483648));
}

#[test]
fn an_untyped_literal_that_does_not_fit_its_use_is_refused_at_its_line() {
    let head = "VAR\n  i : INT;\n  u : UINT;\n  c : CTU;\nEND_VAR\n";
    for (code, line) in [
        ("LD 40000\nADD 2\nST i", 6),
        ("LD 2\nADD 40000\nST i", 7),
        ("LD -1\nST u", 6),
        ("LD i\nADD 70000\nST i", 7),
        ("CAL c(PV := 40000)", 6),
        // No type holds it, whatever its use.
        ("LD -18446744073709551615\nGT 0\nST i", 6),
    ] {
        let text = format!("{head}{code}");
        let why = refused_at(&text, line);
        assert!(why.contains("out of range for"), "{code}: {why}");
    }
}

#[test]
fn the_listing_of_untyped_literals_loads_back_the_same() {
    let p = load(
        "VAR\n  i : INT;\n  big : ULINT;\nEND_VAR\nLD 40\nADD 2\nST i\n\
         LD 18446744073709551615\nST big",
    );
    let again = load(&p.listing());
    assert_eq!(again.listing(), p.listing());
}

// 43.9: TIME and STRING literals, CAL parameters.

#[test]
fn a_time_literal_past_times_range_is_refused_at_its_line() {
    let text = "VAR\n  t : TIME;\nEND_VAR\nLD T#106752d\nST t";
    let why = refused_at(text, 4);
    assert!(
        why.contains("`T#106752d` is out of range for TIME"),
        "{why}"
    );
    // 2^63 ns, one past the greatest TIME: it was saturated.
    let text = "VAR\n  t : TIME;\nEND_VAR\nLD T#106751d23h47m16s854ms775us808ns\nST t";
    assert!(refused_at(text, 4).contains("out of range for TIME"));
    assert!(refused_at("VAR\n  t : TIME := T#200000d;\nEND_VAR\n", 2).contains("T#200000d"));
}

#[test]
fn time_literals_are_summed_exactly() {
    // 106751d 23h 47m 16s 854ms 775us 807ns is i64::MAX nanoseconds.
    let mut p = load(
        "VAR\n  t : TIME;\n  u : TIME;\nEND_VAR\n\
         LD T#106751d23h47m16s854ms775us807ns\nST t\nLD T#1d1ns\nST u",
    );
    p.scan(0);
    assert_eq!(p.value("t"), Some(Data::Time(i64::MAX)));
    assert_eq!(p.value("u"), Some(Data::Time(86_400_000_000_001)));
    let mut p = load("VAR\n  t : TIME;\nEND_VAR\nLD T#-106751d23h47m16s854ms775us808ns\nST t");
    p.scan(0);
    assert_eq!(p.value("t"), Some(Data::Time(i64::MIN)), "the least TIME");
}

#[test]
fn a_string_literal_above_u_00ff_is_refused_at_its_line() {
    let why = refused_at("VAR\n  s : STRING;\nEND_VAR\nLD 'π = 3'\nST s", 4);
    assert!(why.contains("one-byte") || why.contains("U+00FF"), "{why}");
    let why = refused_at("VAR\n  s : STRING := 'naïve €';\nEND_VAR\n", 2);
    assert!(why.contains("one-byte") || why.contains("U+00FF"), "{why}");
    // Latin-1 is a STRING's.
    let mut p = load("VAR\n  s : STRING;\nEND_VAR\nLD 'naïve'\nST s");
    p.scan(0);
    assert_eq!(p.value("s"), Some(Data::text("naïve")));
}

#[test]
fn a_cal_parameter_given_twice_or_empty_is_refused_at_its_line() {
    let head = "VAR\n  t : TON;\n  a : BOOL;\n  b : BOOL;\nEND_VAR\n";
    for code in [
        "CAL t(IN := a, IN := b)",
        "CAL t(IN := a, PT := T#1s, in := b)",
        "CAL t(IN := a, , PT := T#1s)",
        "CAL t(IN := a,)",
        "CAL t(,)",
    ] {
        let text = format!("{head}LD a\n{code}");
        let why = refused_at(&text, 7);
        assert!(
            why.contains("twice") || why.contains("empty"),
            "{code}: {why}"
        );
    }
    // No parameters at all is a call; an output may go to two variables.
    load(&format!("{head}CAL t()\nCAL t\nCAL t(Q => a, Q => b)"));
}

// 43.14: messages that mislead.

#[test]
fn s_and_r_on_a_non_bool_say_what_is_wrong() {
    let why = refused_at("VAR\n  i : INT;\n  b : BOOL;\nEND_VAR\nLD b\nS i", 6);
    assert!(why.contains("i is INT"), "{why}");
    assert!(!why.contains("is BOOL, i needs BOOL"), "{why}");
    let why = refused_at("VAR\n  i : INT;\n  b : BOOL;\nEND_VAR\nLD i\nR b", 6);
    assert!(why.contains("current result is INT"), "{why}");
}

#[test]
fn a_block_instance_given_as_a_bool_input_is_called_one() {
    let why = refused_at(
        "VAR\n  t : TON;\n  u : TON;\nEND_VAR\nCAL t(IN := u, PT := T#1s)",
        5,
    );
    assert!(why.contains("block instance"), "{why}");
    assert!(!why.contains("not declared"), "{why}");
}

#[test]
fn a_doubled_sign_is_not_a_number() {
    for lit in ["--5", "+-5", "-+5", "++5"] {
        let why = refused_at(&format!("VAR\n  d : DINT;\nEND_VAR\nLD {lit}\nST d"), 4);
        assert!(why.contains("not a number"), "{lit}: {why}");
    }
}

#[test]
fn an_unclosed_parenthesis_is_reported_at_its_own_line() {
    let why = refused_at(
        "VAR\n  a : BOOL;\n  b : BOOL;\nEND_VAR\nLD a\nAND( b\nST a\nLD b\nST b\nST a",
        6,
    );
    assert!(
        why.contains("never closed") || why.contains("pair"),
        "{why}"
    );
}

// 44.2: block outputs as operands.

#[test]
fn il_reads_a_blocks_outputs_as_operands() {
    let mut p = load(
        "VAR\n  t0 : TON;\n  c0 : CTU;\n  f0 : R_TRIG;\n  a : BOOL;\n  b : BOOL;\n  \
         g : BOOL;\n  n : INT;\n  x : BOOL := TRUE;\nEND_VAR\n\
         CAL t0(IN := x, PT := T#20ms)\n\
         CAL c0(CU := t0.Q, PV := 3)\n\
         CAL f0(CLK := x)\n\
         LD t0.Q\nST a\n\
         LD c0.CV\nST n\n\
         LD x\nANDN f0.Q\nST b\n\
         LD c0.CV\nGT 0\nST g",
    );
    p.scan(0);
    assert_eq!(p.value("a"), Some(Data::Bool(false)));
    assert_eq!(
        p.value("b"),
        Some(Data::Bool(false)),
        "f0.Q on at the first scan"
    );
    p.scan(10 * MS);
    assert_eq!(p.value("b"), Some(Data::Bool(true)));
    p.scan(20 * MS);
    assert_eq!(p.value("a"), Some(Data::Bool(true)));
    assert_eq!(p.value("n"), int(DataType::Int, 1));
    assert_eq!(p.value("g"), Some(Data::Bool(true)));
}

#[test]
fn a_blocks_output_is_read_not_written_and_must_exist() {
    let head = "VAR\n  t0 : TON;\n  a : BOOL;\nEND_VAR\n";
    let why = refused_at(&format!("{head}LD a\nST t0.Q"), 6);
    assert!(why.contains("t0.Q"), "{why}");
    let why = refused_at(&format!("{head}LD t0.QQ\nST a"), 5);
    assert!(why.contains("QQ"), "{why}");
    let why = refused_at(&format!("{head}LD a\nGT t0.ET\nST a"), 6);
    assert!(why.contains("TIME"), "{why}");
}

#[test]
fn il_reads_an_output_of_the_programs_own_block() {
    let text_with = |code: &str| {
        format!(
            "FUNCTION_BLOCK Twice\nVAR_INPUT\n  i : INT;\nEND_VAR\nVAR_OUTPUT\n  o : INT;\n\
             END_VAR\nVAR\n  hidden : INT;\nEND_VAR\nLD i\nMUL 2\nST o\nEND_FUNCTION_BLOCK\n\
             VAR\n  t : Twice;\n  n : INT;\nEND_VAR\nCAL t(i := 21)\n{code}"
        )
    };
    let mut p = load(&text_with("LD t.o\nST n"));
    p.scan(0);
    assert_eq!(p.value("n"), int(DataType::Int, 42));
    // Its inside is its own: only outputs are read.
    let why = refused_at(&text_with("LD t.hidden\nST n"), 20);
    assert!(why.contains("Twice has no output `hidden`"), "{why}");
}

// 43.11: nested instances of the program's own blocks.

#[test]
fn nested_instances_past_the_variables_limit_are_refused_once_before_any_is_made() {
    let mut text = String::from("FUNCTION_BLOCK Big\nVAR\n");
    for k in 0..500 {
        text.push_str(&format!("  v{k} : INT;\n"));
    }
    text.push_str("END_VAR\nLD v0\nADD 1\nST v0\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK Mid\nVAR\n");
    for k in 0..100 {
        text.push_str(&format!("  b{k} : Big;\n"));
    }
    text.push_str("END_VAR\nCAL b0\nEND_FUNCTION_BLOCK\nVAR\n");
    let first = text.lines().count() + 1;
    for k in 0..5 {
        text.push_str(&format!("  m{k} : Mid;\n"));
    }
    text.push_str("END_VAR\nCAL m0\nCAL m3\nCAL m4\n");
    let started = std::time::Instant::now();
    let got = refused(&text);
    assert_eq!(got.len(), 1, "said once, no cascade: {got:?}");
    // m0 … m2 hold 150 300 variables; m3 would take them past 200 000.
    assert_eq!(got[0].0, first + 3, "{got:?}");
    assert!(got[0].1.contains("200000 variables"), "{got:?}");
    assert!(started.elapsed().as_secs() < 5, "{:?}", started.elapsed());
}

#[test]
fn a_block_that_holds_itself_is_refused_at_that_declaration() {
    let got = refused(
        "FUNCTION_BLOCK A\nVAR\n  b : B;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK B\nVAR\n  x : BOOL;\n  a : A;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         VAR\n  top : A;\nEND_VAR\nCAL top",
    );
    assert_eq!(got.len(), 1, "{got:?}");
    assert_eq!(got[0].0, 9, "{got:?}");
    assert!(got[0].1.contains("does A hold itself?"), "{got:?}");
}

/// `%IX0.0 → [c0: CTU PV 3] → %QX0.0`, then a rung `[GT c0.CV 1] →
/// %QX0.1`: a box that reads the counter's CV, as typed in the editor.
fn counter_and_comparison() -> engine::ladder::Ladder {
    use engine::ladder::edit::{parse_entry, Cursor, Edit, Editor, EntryKind};
    use engine::ladder::{Element, Ladder};
    use engine::MachineId;
    let entry = |text: &str| {
        parse_entry(MachineId::SoftPlc, EntryKind::Instruction, text)
            .unwrap_or_else(|e| panic!("{text}: {e:?}"))
    };
    let mut e = Editor::new(Ladder::default());
    for index in 0..2 {
        e.apply(Edit::InsertRung { index }).expect("a rung");
    }
    let mut place = |rung, col, element| {
        let at = Cursor::new(rung, 0, col);
        e.apply(Edit::Place { at, element }).expect("places");
    };
    place(0, 0, Element::no("%IX0.0"));
    place(0, 1, entry("CTU c0 · 3"));
    place(0, 2, Element::coil("%QX0.0"));
    place(1, 0, entry("GT c0.CV 1"));
    place(1, 1, Element::coil("%QX0.1"));
    e.ladder().clone()
}

#[test]
fn a_ladder_box_reads_a_blocks_output() {
    use engine::events::InputValue;
    use engine::ladder::compile::{compile, Options};
    use engine::plc::Command;
    use engine::{MachineId, SimTime};
    let ladder = counter_and_comparison();
    let il = compile(&ladder, MachineId::SoftPlc, Options::default())
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert!(il.contains("c0.CV"), "{il}");
    let mut plc = engine::machines::new_plc(MachineId::SoftPlc);
    plc.load_text(&il).unwrap_or_else(|e| panic!("{e}\n{il}"));
    let input = plc.device("%IX0.0").expect("the input");
    let out = plc.device("%QX0.1").expect("the output");
    let mut t = 0;
    for press in [1, 0, 1, 0] {
        plc.apply(Command::SetInput(input, InputValue::Int(press)))
            .expect("input");
        t += 50;
        plc.run_until(SimTime::from_millis(t));
        // On once the count passes 1: after the second press.
        let want = i64::from(t >= 150);
        assert_eq!(plc.read(out).as_i64(), want, "at {t} ms\n{il}");
    }
}

// The CLI: a program written as IL tools write it runs; a literal that
// does not fit is said at its own line.

fn cli(args: &[&str]) -> (Option<i32>, String, String) {
    let out = crate::common::hashigo(args, "");
    (
        out.status.code(),
        crate::common::text(&out.stdout),
        crate::common::text(&out.stderr),
    )
}

#[test]
fn the_cli_runs_untyped_literals_and_block_outputs() {
    let dir = crate::common::Temp::new("round3-il-run");
    let program = dir.file(
        "count.il",
        "PROGRAM count\nVAR\n  c0 : CTU;\n  n AT %MW0 : INT;\nEND_VAR\n\
         CAL c0(CU := %IX0.0, PV := 2)\nLD c0.CV\nADD 40\nST %MW0\n\
         LD c0.Q\nST %QX0.0\nEND_PROGRAM\n",
    );
    let events = dir.file(
        "events.csv",
        "10ms,%IX0.0,1\n30ms,%IX0.0,0\n50ms,%IX0.0,1\n",
    );
    let (code, out, err) = cli(&[
        "run",
        "--machine",
        "soft-plc",
        "--program",
        &program,
        "--input",
        &events,
        "--until",
        "100ms",
        "--every",
        "100ms",
        "--watch",
        "%MW0,%QX0.0",
    ]);
    assert_eq!(code, Some(0), "{err}");
    // No scan has run at 0 ms (the first ends one period after power-on).
    assert_eq!(out, "time_ms,%MW0,%QX0.0\n0,0,0\n100,42,1\n");
}

#[test]
fn the_cli_says_a_literal_that_does_not_fit_at_its_line() {
    let dir = crate::common::Temp::new("round3-il-literal");
    let program = dir.file(
        "big.il",
        "VAR\n  i : INT;\nEND_VAR\nLD 40000\nADD 2\nST i\n",
    );
    let (code, _, err) = cli(&[
        "run",
        "--machine",
        "soft-plc",
        "--program",
        &program,
        "--until",
        "10ms",
        "--watch",
        "i",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(
        err.trim_end(),
        format!("error: {program}:4: `40000` is out of range for INT")
    );
}

#[test]
fn a_box_reading_a_blocks_output_loads_back_as_a_ladder() {
    use engine::ladder::compile::{compile, Options};
    use engine::MachineId;
    let il = compile(
        &counter_and_comparison(),
        MachineId::SoftPlc,
        Options::default(),
    )
    .unwrap_or_else(|e| panic!("{e:?}"));
    let back = engine::ladder::decompile::decompile_text(MachineId::SoftPlc, &il, 10)
        .unwrap_or_else(|e| panic!("{e:?}\n{il}"));
    let again = compile(&back, MachineId::SoftPlc, Options::default())
        .unwrap_or_else(|e| panic!("{e:?}\n{il}"));
    // The same code (the declarations may come in another order).
    let code = |t: &str| t.split_once("END_VAR").map(|(_, c)| c.to_string());
    assert_eq!(code(&again), code(&il), "{again}");
    let boxes: Vec<String> = back
        .rungs
        .iter()
        .flat_map(|r| r.elements().filter_map(|(_, e)| e.block().cloned()))
        .map(|b| format!("{} {:?}", b.kind(), b.inputs))
        .collect();
    assert!(
        boxes
            .iter()
            .any(|b| b.starts_with("GT") && b.contains("c0.CV")),
        "{boxes:?}"
    );
}

/// A PLCopen FBD body that reads a counter's CV by name (an
/// `inVariable` `c0.CV`) into a comparison.
const READS_CV: &str = include_str!("../fixtures/reads-cv.xml");

#[test]
fn a_plcopen_body_reads_a_blocks_output_by_name() {
    use engine::events::InputValue;
    use engine::plc::Command;
    use engine::{MachineId, SimTime};
    let program = engine::formats::plcopen::Document::read(READS_CV)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert!(program.text.contains("c0.CV"), "{}", program.text);
    let mut plc = engine::machines::new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text)
        .unwrap_or_else(|e| panic!("{e}\n{}", program.text));
    let run = plc.device("%IX0.0").expect("run");
    let lamp = plc.device("%QX0.0").expect("lamp");
    let mut t = 0;
    for press in [1, 0, 1, 0] {
        plc.apply(Command::SetInput(run, InputValue::Int(press)))
            .expect("input");
        t += 50;
        plc.run_until(SimTime::from_millis(t));
        assert_eq!(plc.read(lamp).as_i64(), i64::from(t >= 150), "at {t} ms");
    }
}

#[test]
fn a_box_reading_a_blocks_output_is_exported_and_opened_again() {
    use engine::formats::plcopen::export;
    use engine::MachineId;
    let ladder = counter_and_comparison();
    let xml = export(&ladder, "Main").unwrap_or_else(|e| panic!("{e:?}"));
    assert!(xml.contains("<expression>c0.CV</expression>"), "{xml}");
    let back = Document::read(&xml)
        .and_then(|document| document.import(Some(MachineId::SoftPlc), None, None))
        .map(|i| i.ladder)
        .unwrap_or_else(|e| panic!("{e:?}\n{xml}"));
    let logic = |l: &engine::ladder::Ladder| {
        engine::ladder::edit::align_outputs(l, 9)
            .logic(MachineId::SoftPlc)
            .expect("reads")
    };
    assert_eq!(logic(&back), logic(&ladder));
    // And the project as written runs it.
    engine::formats::plcopen::Document::read(&xml)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}\n{xml}"));
}
