//! The command line's English of each type and call problem, exactly,
//! from real texts: the loader's reasons are kinds with arguments (so
//! the page can say them in its language), their `Display` unchanged.

use super::Program;

/// The first error of a text refused: its line and its English.
fn said(text: &str) -> (usize, String) {
    match Program::load(text) {
        Ok(_) => panic!("loaded, should be refused:\n{text}"),
        Err(errors) => (errors[0].line, errors[0].error.to_string()),
    }
}

/// A text with declarations `vars` and IL `il`, refused with `english`.
fn refused(vars: &str, il: &str, english: &str) {
    let text = format!("VAR\n{vars}\nEND_VAR\n{il}\n");
    assert_eq!(said(&text).1, english, "{text}");
}

#[test]
fn the_functions_type_problems_are_said_as_before() {
    let v = "  b : BOOL;\n  i : INT;\n  d : DINT;\n  r : REAL;\n  s : STRING;";
    refused(v, "LD b\nNEG\nST b", "NEG needs a number");
    refused(
        v,
        "LD r\nSHL 1\nST r",
        "SHL, SHR, ROL and ROR shift an integer by an integer",
    );
    refused(
        v,
        "LD i\nINT_TO_STRING\nST s",
        "conversions to and from STRING do not run on the soft PLC yet",
    );
    refused(
        v,
        "LD d\nINT_TO_DINT\nST d",
        "the current result is DINT, not INT",
    );
    refused(
        v,
        "LD i\nSEL 1, 2\nST i",
        "SEL's first input (the current result) is a BOOL",
    );
    refused(v, "LD b\nSEL i, r\nST i", "SEL's two values have one type");
}

#[test]
fn the_stores_and_operands_type_problems_are_said_as_before() {
    let v = "  b : BOOL;\n  i : INT;\n  t : TON;\n  s : STRING;";
    refused(v, "LD b\nST i", "the current result is BOOL, i needs INT");
    refused(v, "LD b\nS i", "S sets or resets a BOOL: i is INT");
    refused(
        v,
        "LD b\nST 1",
        "a value is stored in a variable, not a literal",
    );
    refused(
        v,
        "LD t\nST b",
        "`t` is a block instance, not a value: read one of its outputs (`t.Q`)",
    );
    refused(
        v,
        "LD i.Q\nST b",
        "`i` is not a block instance: `i.Q` reads a block's output",
    );
    refused(
        v,
        "LD t.Q\nST t.Q",
        "`t.Q` is a block's output: it is read, not written",
    );
    refused(
        v,
        "LD '\u{100}'\nST s",
        &crate::iec::literal::string_value("\u{100}")
            .expect_err("no byte")
            .to_string(),
    );
}

#[test]
fn the_calls_type_and_call_problems_are_said_as_before() {
    let v = "  b : BOOL;\n  i : INT;\n  r : REAL;\n  t : TON;\n  f : LD_STRING;\n  g : LD_FMTSTR;";
    refused(v, "CAL t(IN := r)", "TON's IN is a BOOL");
    refused(v, "CAL t(Q => i)", "TON's Q is a BOOL");
    refused(v, "CAL f(FMT := 1)", "LD_STRING's FMT is a text: '…'");
    refused(
        v,
        "CAL f(FMT := 'a %s')",
        "FMT: `%s` prints no integer: the text takes %d %i %u %x %X %o %c or %%",
    );
    refused(
        v,
        "CAL g(FMT := 'a \\q')",
        "FMT: `\\q` is no escape of a formatted string (\\r \\n \\t \\a \\b \\e \\f \\v \\\\ \
         \\xAB, or \\1 … \\5 and \\-1 … \\-5 for the number); a backslash is `\\\\`",
    );
    refused(
        v,
        "CAL f(FMT := 'a %d')\nCAL f(FMT := 'b %d')",
        "f already has another text: one FMT for each instance",
    );
    refused(
        v,
        "LD t.IN\nST b",
        "`t.IN`: IN is an input of TON; the soft PLC gives a block's inputs in its CAL (CAL t(IN := …)) and reads only its outputs",
    );
}

#[test]
fn the_jumps_type_problems_are_said_as_before() {
    let v = "  x : BOOL;\n  n : INT;\n  d : DINT;";
    refused(
        v,
        "LD x\nJMPC wide\nLD n\nJMP put\nwide:\nLD d\nput:\nST n",
        "the current result reaches the label `put` as INT and as DINT: make them one type (*_TO_*) or start with LD",
    );
    refused(
        v,
        "LD n\nback:\nADD 1\nST n\nLD d\nGT 5\nJMPC out\nLD d\nJMP back\nout:\nLD n",
        "line 8, after the label `back`, uses the current result as INT; this jump brings DINT: make them one type or start there with LD",
    );
}

#[test]
fn the_own_blocks_limits_are_said_as_before() {
    let (line, english) = said(
        "FUNCTION_BLOCK A\nVAR\n  b : B;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK B\nVAR\n  x : BOOL;\n  a : A;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         VAR\n  top : A;\nEND_VAR\nCAL top",
    );
    assert_eq!(line, 9);
    assert_eq!(
        english,
        "a: function blocks hold instances more than 8 deep (does A hold itself?)"
    );
    // Nine blocks each holding the next: too deep, though none holds itself.
    let mut text = String::new();
    for k in 0..9 {
        text.push_str(&format!(
            "FUNCTION_BLOCK F{k}\nVAR\n  inner : F{};\nEND_VAR\nEND_FUNCTION_BLOCK\n",
            k + 1
        ));
    }
    text.push_str("FUNCTION_BLOCK F9\nVAR\n  x : BOOL;\nEND_VAR\nEND_FUNCTION_BLOCK\n");
    text.push_str("VAR\n  top : F0;\nEND_VAR\nCAL top\n");
    assert_eq!(
        said(&text).1,
        "top: function blocks hold instances more than 8 deep"
    );
    // 101 × 100 instances, declared flat: too many.
    let mut text =
        String::from("FUNCTION_BLOCK L\nVAR\n  x : BOOL;\nEND_VAR\nEND_FUNCTION_BLOCK\n");
    text.push_str("FUNCTION_BLOCK H\nVAR\n");
    for k in 0..100 {
        text.push_str(&format!("  l{k} : L;\n"));
    }
    text.push_str("END_VAR\nEND_FUNCTION_BLOCK\nVAR\n");
    for k in 0..100 {
        text.push_str(&format!("  h{k} : H;\n"));
    }
    text.push_str("END_VAR\nCAL h0\n");
    assert_eq!(
        said(&text).1,
        "h99: more than 10000 instances of the program's own blocks (docs/limits.md)"
    );
    // 65 blocks of 100 instances of 30 variables: too many variables.
    let mut text = String::from("FUNCTION_BLOCK L\nVAR\n");
    for k in 0..30 {
        text.push_str(&format!("  x{k} : BOOL;\n"));
    }
    text.push_str("END_VAR\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK H\nVAR\n");
    for k in 0..100 {
        text.push_str(&format!("  l{k} : L;\n"));
    }
    text.push_str("END_VAR\nEND_FUNCTION_BLOCK\nVAR\n");
    for k in 0..65 {
        text.push_str(&format!("  h{k} : H;\n"));
    }
    text.push_str("END_VAR\nCAL h0\n");
    assert_eq!(
        said(&text).1,
        "h64: the instances of the program's own blocks would hold more than 200000 variables (docs/limits.md)"
    );
}

#[test]
fn the_kinds_no_short_text_reaches_are_said_as_before() {
    use super::CallWhy;
    assert_eq!(
        CallWhy::BodySteps.to_string(),
        "the blocks' bodies need more than 2000000 steps for their instances (docs/limits.md)"
    );
    assert_eq!(
        CallWhy::NotVariable("x".into()).to_string(),
        "`x` is not a variable"
    );
    assert_eq!(
        CallWhy::NeedsInstance.to_string(),
        "CAL needs a block instance"
    );
}
