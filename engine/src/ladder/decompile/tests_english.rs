//! The command line's English of each step a program has no ladder form
//! at, exactly, from real texts (the reasons are kinds with arguments so
//! the page can say them in its language; `Display` unchanged).

use super::decompile_text;
use crate::MachineId;

/// The refusal of `text` on `machine`, as the command line says it.
fn said(machine: MachineId, text: &str) -> String {
    match decompile_text(machine, text, 10) {
        Ok(_) => panic!("drawn, should be refused:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_steps_with_no_ladder_form_are_said_as_before() {
    let soft = |text: &str| said(MachineId::SoftPlc, text);
    assert_eq!(
        soft("LD %IX0.0\nJMPC x\nx: LD %IX0.1\nST %QX0.0"),
        "step 1: labels and conditional operators have no ladder form"
    );
    assert_eq!(
        soft("VAR\n  i : INT;\nEND_VAR\nLD i\nADD 1\nST i"),
        "step 1: `ADD 1` has no ladder form yet"
    );
    assert_eq!(
        soft("VAR\n  t : TON;\nEND_VAR\nCAL t(IN := %IX0.0, PT := T#1s)"),
        "step 0: a call with no power out (Q =>) has no ladder form"
    );
    assert_eq!(
        soft("VAR\n  t : TON;\n  p : TIME;\n  q : BOOL;\nEND_VAR\nCAL t(IN := %IX0.0, PT := p, Q => q)"),
        "step 0: CAL t has no ladder form yet"
    );
    assert_eq!(
        soft("VAR\n  r : R_TRIG;\n  q : BOOL;\nEND_VAR\nCAL r(CLK := TRUE, Q => q)"),
        "step 0: an output with no LD before it"
    );
    assert_eq!(
        said(MachineId::MinasecU, "ST Y00"),
        "step 0: an output with no LD before it"
    );
}

#[test]
fn the_kinds_no_short_text_here_reaches_are_said_as_before() {
    use super::StepWhy as S;
    let said = [
        (
            S::Jump(3),
            "JUMP 3 has no ladder form: only a final JUMP 0 (or END)",
        ),
        (S::Word(0xBEEF), "word BEEF is no instruction"),
        (
            S::RegisterValue,
            "a set value from a data register has no ladder form here: use a K constant",
        ),
        (
            S::SecondDevice,
            "SETS / RSTS drive a second device: they have no ladder form here",
        ),
        (
            S::TooDeep,
            "blocks nest more than 100 deep here: a ladder cannot draw it (docs/limits.md)",
        ),
        (S::TwoBlocks, "ORB / ANB needs two blocks"),
        (S::NoLoad, "no LD before this step"),
    ];
    for (why, english) in said {
        assert_eq!(why.to_string(), english);
    }
}
