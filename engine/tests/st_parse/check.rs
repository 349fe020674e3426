//! Name resolution and type checking: each refusal at its line and
//! column, and a correct program accepted.

use engine::iec::st::{check_source, parse_source};

use super::constructs::POUS;

fn refusals(text: &str) -> Vec<String> {
    let source = parse_source(text).unwrap_or_else(|e| panic!("{e}"));
    match check_source(&source) {
        Ok(()) => Vec::new(),
        Err(es) => es.iter().map(ToString::to_string).collect(),
    }
}

fn program(vars: &str, body: &str) -> String {
    format!("PROGRAM p\nVAR\n{vars}\nEND_VAR\n{body}\nEND_PROGRAM\n")
}

#[test]
fn a_correct_source_is_accepted() {
    assert_eq!(refusals(POUS), Vec::<String>::new());
    let ok = program(
        "a : INT; r : LREAL; b : BOOL; t0 : TON; w : WORD; arr : ARRAY [1..3] OF DINT; k : INT;",
        "a := a + 1 * 2; r := r * 2.5 + 1; b := a > 3 AND NOT b; w := w AND 16#FF;
         t0(IN := b, PT := T#1s, Q => b); b := t0.Q; arr[a] := DINT#5 + arr[1];
         FOR k := 1 TO 3 DO IF arr[k] = 0 THEN EXIT; END_IF; END_FOR;
         CASE a OF 1..2: a := -a; ELSE a := ABS(a); END_CASE;
         r := INT_TO_LREAL(a); b := GT(a, 2);",
    );
    assert_eq!(refusals(&ok), Vec::<String>::new());
}

#[test]
fn names_and_types_are_refused_at_their_place() {
    for (vars, body, want) in [
        ("a : INT;", "b := 1;", "line 5, column 1: `b` is not declared"),
        ("a : INT;", "a := a + c;", "line 5, column 10: `c` is not declared"),
        ("a : INT; a : BOOL;", "", "line 3, column 10: `a` is declared twice"),
        ("m : Motor;", "", "line 3, column 5: `Motor` is not a type"),
        ("a : INT; r : REAL;", "a := r;", "line 5, column 6: the value assigned must be INT, not REAL"),
        ("a : INT;", "a := 40000;", "line 5, column 6: the value assigned must be within INT's range -32768 … 32767, not 40000"),
        ("a : INT; d : DINT;", "a := a + d;", "line 5, column 10: the right operand must be INT, not DINT"),
        ("a : INT;", "IF a THEN END_IF;", "line 5, column 4: the IF condition must be BOOL, not INT"),
        ("b : BOOL;", "WHILE b DO END_WHILE; EXIT;", "line 5, column 23: EXIT is only allowed inside a loop"),
        ("a : INT; t : TON;", "a := t.QQ;", "line 5, column 8: TON has no member `QQ`"),
        ("t : TON;", "t(IN := TRUE, PRESET := T#1s);", "line 5, column 15: `t` has no input or output `PRESET`"),
        ("t : TON; a : INT;", "t(IN := a);", "line 5, column 9: an input's value must be BOOL, not INT"),
        ("a : INT;", "a(1);", "line 5, column 1: `a` is neither a function nor a function block instance"),
        ("a : INT;", "a := nothing(1);", "line 5, column 6: `nothing` is not declared"),
        ("arr : ARRAY [1..2, 1..2] OF INT;", "arr[1] := 0;", "line 5, column 5: `arr` has 2 dimension(s); 1 index(es) given"),
        ("a : INT;", "a[1] := 0;", "line 5, column 3: `a` is not an array"),
        ("r : REAL;", "r := r MOD 2.0;", "line 5, column 12: an operand of this operator must be of a type it applies to, not REAL"),
        ("s : STRING; a : INT;", "a := s;", "line 5, column 6: the value assigned must be INT, not STRING"),
    ] {
        let got = refusals(&program(vars, body));
        assert!(got.iter().any(|g| g.starts_with(want)), "{body}:\n  got  {got:?}\n  want {want}");
    }
}

#[test]
fn direct_addresses_have_their_size_type() {
    let text = program(
        "a : INT; b : BOOL;",
        "a := %IW0; b := %IX0.1;\na := %IX0.0;",
    );
    assert_eq!(
        refusals(&text),
        ["line 6, column 6: the value assigned must be INT, not BOOL"]
    );
}

#[test]
fn constants_and_outputs_are_not_written() {
    let text = "PROGRAM p VAR CONSTANT k : INT := 3; END_VAR\nk := 4;\nEND_PROGRAM";
    assert_eq!(
        refusals(text),
        ["line 2, column 1: `k` cannot be assigned (a constant, or a block's output, which only the block writes)"]
    );
    let outputs = program("t : TON; b : BOOL;", "t.IN := TRUE; b := t.Q;\nt.Q := b;");
    assert_eq!(
        refusals(&outputs),
        ["line 6, column 1: `t.Q` cannot be assigned (a constant, or a block's output, which only the block writes)"]
    );
}

#[test]
fn declaration_order_does_not_matter_and_aliases_resolve() {
    let text = "PROGRAM p VAR q : Pair; n : Count; END_VAR q.a := n; q.b := q.a > 0; END_PROGRAM
        TYPE Pair : STRUCT a : Count; b : BOOL; END_STRUCT; Count : DINT; END_TYPE";
    assert_eq!(refusals(text), Vec::<String>::new());
    let circle = "TYPE A : B; B : A; END_TYPE";
    assert!(refusals(circle).iter().all(|e| e.contains("is not a type")));
    assert!(!refusals(circle).is_empty());
}

#[test]
fn user_functions_and_blocks_are_checked() {
    let text = "FUNCTION f : INT VAR_INPUT x : INT; END_VAR f := x * 2; END_FUNCTION
FUNCTION_BLOCK fb VAR_INPUT go : BOOL; END_VAR VAR_OUTPUT n : INT; END_VAR n := f(x := 1); END_FUNCTION_BLOCK
PROGRAM p VAR i : fb; b : BOOL; r : REAL; END_VAR
i(go := TRUE, n => r);
r := f(3);
b := i.n;
END_PROGRAM";
    assert_eq!(
        refusals(text),
        [
            "line 4, column 20: an output's target must be INT, not REAL",
            "line 5, column 6: the value assigned must be REAL, not INT",
            "line 6, column 6: the value assigned must be BOOL, not INT",
        ]
    );
}
