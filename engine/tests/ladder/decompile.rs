//! Programs back to ladders: the seeds' own listings.

use engine::ladder::compile::{compile, Options};
use engine::ladder::{analyse, Element, Ladder, Net};
use engine::machines::{decompile, Source};
use engine::{arduino, io86a, minasec, MachineId};

/// Each rung as `condition -> outputs`, contacts written `X00` / `!X00`,
/// series `a & b`, parallel `(a | b)`.
fn show(ladder: &Ladder) -> Vec<String> {
    fn net(n: &Net) -> String {
        match n {
            Net::Leaf(Element::Contact { kind, device }, _) => match kind {
                engine::ladder::ContactKind::Nc => format!("!{device}"),
                _ => device.clone(),
            },
            Net::Leaf(e, _) => e.to_string(),
            Net::Series(v) => v.iter().map(net).collect::<Vec<_>>().join(" & "),
            Net::Parallel(v) => format!("({})", v.iter().map(net).collect::<Vec<_>>().join(" | ")),
        }
    }
    ladder
        .rungs
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let l = analyse(r, i).expect("draws").expect("not empty");
            let outs: Vec<String> = l.outputs.iter().map(|(e, _)| e.to_string()).collect();
            format!("{} -> {}", net(&l.condition), outs.join(", "))
        })
        .collect()
}

#[test]
fn the_seed_listing_comes_back_as_its_five_rungs() {
    let p = minasec::Program::parse(minasec::SEED_TEST_PROGRAM).expect("seed");
    let ladder = decompile(Source::Minasec(&p)).expect("decompiles");
    assert_eq!(
        show(&ladder),
        [
            "(X00 | Y00) & !X01 -> coil Y00",
            // `ANDI T1` goes on from the stored result: Y00 holds it.
            "Y00 & !T1 -> coil T0",
            "T0 -> coil T1, coil C0",
            "C0 -> coil Y01",
            "X02 -> coil C0R",
        ]
    );
    // And compiles back to the same steps but one (the reload of Y00).
    let text = compile(&ladder, MachineId::MinasecU, Options::default()).expect("compiles");
    let again = minasec::Program::parse(&text).expect("parses");
    assert_eq!(again.len(), p.len() + 1);
}

#[test]
fn a_temporary_relay_folds_back_into_its_rung() {
    let text = "LD X00\nAND X01\nST M10\nLD X02\nAND X03\nOR M10\nST Y00\n";
    let p = minasec::Program::parse(text).expect("parses");
    let ladder = decompile(Source::Minasec(&p)).expect("decompiles");
    assert_eq!(show(&ladder), ["(X02 & X03 | X00 & X01) -> coil Y00"]);
    // Written again later, M10 is a relay of the program: it stays.
    let p = minasec::Program::parse(&format!("{text}LD M00\nST M10\n")).expect("parses");
    let ladder = decompile(Source::Minasec(&p)).expect("decompiles");
    assert_eq!(
        show(&ladder),
        [
            "X00 & X01 -> coil M10",
            "(X02 & X03 | M10) -> coil Y00",
            "M00 -> coil M10"
        ]
    );
}

#[test]
fn the_arduino_seed_examples() {
    let hold = arduino::Program::parse(
        "0 LD X000\n1 OR Y000\n2 ANDN X001\n3 OUT Y000\n4 JUMP 0\n",
        256,
    )
    .expect("seed");
    assert_eq!(
        show(&decompile(Source::Arduino(&hold)).expect("decompiles")),
        ["(X000 | Y000) & !X001 -> coil Y000"]
    );
    let block = arduino::Program::parse(
        "LD X000\nLD Y000\nANDN X002\nORB\nANDN X001\nOUT Y000\nEND\n",
        256,
    )
    .expect("seed");
    assert_eq!(
        show(&decompile(Source::Arduino(&block)).expect("decompiles")),
        ["(X000 | Y000 & !X002) & !X001 -> coil Y000"]
    );
    let jump = arduino::Program::parse("LD X000\nOUT Y000\nJUMP 1\n", 256).expect("parses");
    let e = decompile(Source::Arduino(&jump)).expect_err("no ladder form");
    assert_eq!(
        e.to_string(),
        "step 2: JUMP 1 has no ladder form: only a final JUMP 0 (or END)"
    );
}

#[test]
fn io86a_blocks_and_boxes() {
    let text =
        "LD X00\nOR X01\nLD X02\nOR X03\nANB\nOUT Y00\nOUT T00\nK19\nLD T00\nMOV\nK10\nD00\nEND\n";
    let p = io86a::Program::parse(text).expect("parses");
    let ladder = decompile(Source::Io86a(&p)).expect("decompiles");
    assert_eq!(
        show(&ladder),
        [
            "(X00 | X01) & (X02 | X03) -> coil Y00, timer T00 K19",
            "T00 -> MOV K10 D00"
        ]
    );
    let links = io86a::Program::parse("LD X00\nSETS Y00\n").expect("parses");
    let e = decompile(Source::Io86a(&links)).expect_err("no ladder form");
    assert!(e.to_string().starts_with("step 1: SETS / RSTS"), "{e}");
}
