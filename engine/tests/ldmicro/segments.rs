//! LDmicro's `7SEGMENTS dest src common` on the soft PLC (issue #32):
//! the segments a character lights, inverted for a common-anode digit,
//! in the destination's width; the source written back as LDmicro's code
//! writes it; 9, 14 and 16 segments in the layout LDmicro's source gives
//! them; back out as `.ld`; and the waiting UART refused for having no
//! meaning scan by scan.

use engine::formats::ldmicro::{parse, to_ladder};
use engine::runtime::ldmicro::segments::{letters, lit};
use engine::SimTime;

use crate::run::{get, load, set};

/// A file whose presses of `Xa` count `n`, shown on a common-cathode
/// digit `seg` and a common-anode `anode` (one byte each); `d` is its own
/// source; `deg` shows `°`; `big` is past the table; `h` is a letter.
const COUNTER: &str = "LDmicro0.2\nCYCLE=10000\n\nVAR LIST\n    1 bytes seg\n    1 bytes anode\n    2 bytes n\nEND\n\n\
    IO LIST\n    Xa at 1\n    Yg at 2\nEND\n\nPROGRAM\n\
    RUNG 1\n  CONTACTS Xa 0\n  OSR\n  ADD n n 1\nEND\n\
    RUNG 2\n  PARALLEL\n    7SEGMENTS seg n C\n    7SEGMENTS anode n A\n  END\nEND\n\
    RUNG 3\n  MOVE d 3\n  7SEGMENTS d d C\nEND\n\
    RUNG 4\n  MOVE ch 176\n  7SEGMENTS deg ch C\nEND\n\
    RUNG 5\n  MOVE big 300\n  7SEGMENTS blank big C\nEND\n\
    RUNG 6\n  7SEGMENTS h 'H' C\nEND\n\
    RUNG 7\n  IF_BIT_SET seg 6\n  COIL Yg 0 0 0\nEND\n";

#[test]
fn a_count_shown_on_a_digit_lights_its_segments_and_the_anode_digit_the_inverse() {
    let mut plc = load(COUNTER);
    let mut scan = 0u64;
    let mut press = |plc: &mut dyn engine::plc::Plc| {
        for level in [1, 0] {
            set(plc, "Xa", level);
            scan += 1;
            plc.run_until(SimTime::from_millis(10 * scan + 5));
        }
    };
    press(plc.as_mut());
    // n = 1: b and c, on both digits as drawn.
    let face = |plc: &dyn engine::plc::Plc, name: &str, anode: bool| {
        letters(7, lit(7, get(plc, name), anode))
    };
    assert_eq!(get(plc.as_ref(), "n"), 1);
    assert_eq!(face(plc.as_ref(), "seg", false), "bc");
    assert_eq!(face(plc.as_ref(), "anode", true), "bc");
    // The anode digit's byte is the usual 0xF9, signed in one byte.
    assert_eq!(get(plc.as_ref(), "anode"), 0xF9 - 256);
    assert_eq!(get(plc.as_ref(), "Yg"), 0, "no g on a 1");
    for _ in 1..8 {
        press(plc.as_mut());
    }
    assert_eq!(face(plc.as_ref(), "seg", false), "abcdefg", "8");
    assert_eq!(get(plc.as_ref(), "Yg"), 1, "g lit, read back by IF_BIT_SET");
    for _ in 8..26 {
        press(plc.as_mut());
    }
    // 26 is past the hexadecimal digits: A (10) with its point.
    assert_eq!(face(plc.as_ref(), "seg", false), "abcefg.");
    // Its own source: the index written first, then the segments of 3.
    assert_eq!(face(plc.as_ref(), "d", false), "abcdg");
    // 176 is the degree sign, and the source becomes its place, 128.
    assert_eq!(face(plc.as_ref(), "deg", false), "abfg");
    assert_eq!(get(plc.as_ref(), "ch"), 128);
    // Past the table: a space, and the source becomes 32.
    assert_eq!(face(plc.as_ref(), "blank", false), "");
    assert_eq!(get(plc.as_ref(), "big"), 32);
    assert_eq!(face(plc.as_ref(), "h", false), "bcefg", "'H'");
}

#[test]
fn a_digit_goes_back_out_as_the_same_7segments_lines() {
    let ladder = to_ladder(&parse(COUNTER).expect("reads")).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, 10_000).expect("exports");
    for line in [
        "7SEGMENTS seg n C",
        "7SEGMENTS anode n A",
        "7SEGMENTS d d C",
        "7SEGMENTS h 72 C",
    ] {
        assert!(out.contains(line), "{line}\n{out}");
    }
    let again = to_ladder(&parse(&out).expect("reads")).expect("draws");
    assert_eq!(again.rungs, ladder.rungs);
}

/// A file showing `n` on a 9-, a 14- and a 16-segment digit, common
/// cathode, and on a 16-segment common-anode one in four bytes.
const WIDE: &str = "LDmicro0.2\nCYCLE=10000\n\nVAR LIST\n    2 bytes s9\n    2 bytes s14\n    4 bytes s16\n    4 bytes a16\nEND\n\n\
    PROGRAM\n\
    RUNG 1\n  PARALLEL\n    9SEGMENTS s9 n C\n    14SEGMENTS s14 n C\n    16SEGMENTS s16 n C\n    16SEGMENTS a16 n A\n  END\nEND\n";

#[test]
fn nine_fourteen_and_sixteen_segment_digits_light_in_ldmicros_layout() {
    let mut plc = load(WIDE);
    let mut shown = |n: i64| -> Vec<String> {
        set(plc.as_mut(), "n", n);
        let t = plc.now();
        plc.run_until(t.saturating_add(SimTime::from_millis(10)));
        [
            ("s9", 9, false),
            ("s14", 14, false),
            ("s16", 16, false),
            ("a16", 16, true),
        ]
        .iter()
        .map(|(name, segments, anode)| {
            letters(*segments, lit(*segments, get(plc.as_ref(), name), *anode))
        })
        .collect()
    };
    // 'X': the two long diagonals on nine segments, four strokes on 14 and 16.
    assert_eq!(shown(i64::from(b'X')), ["jm", "jmhk", "jmhk", "jmhk"]);
    // 'T': a, and the centre bars; a in two halves on sixteen.
    assert_eq!(shown(i64::from(b'T')), ["defg", "ail", "ailA", "ailA"]);
    // 7 with its point: the same as on seven segments on nine.
    assert_eq!(shown(23)[0], "abc.");
    // The anode digit's 16 segments are its value's low 17 bits inverted.
    shown(i64::from(b'T'));
    assert_eq!(
        get(plc.as_ref(), "a16") & 0x1_FFFF,
        !(1 | 1 << 11 | 1 << 13 | 1 << 16) & 0x1_FFFF
    );
    // Back out as the same lines.
    let ladder = to_ladder(&parse(WIDE).expect("reads")).expect("draws");
    let out = engine::formats::ldmicro::export(&ladder, 10_000).expect("exports");
    for line in [
        "9SEGMENTS s9 n C",
        "14SEGMENTS s14 n C",
        "16SEGMENTS s16 n C",
        "16SEGMENTS a16 n A",
    ] {
        assert!(out.contains(line), "{line}\n{out}");
    }
    let again = to_ladder(&parse(&out).expect("reads")).expect("draws");
    assert_eq!(again.rungs, ladder.rungs);
}

#[test]
fn a_common_that_is_neither_c_nor_a_is_no_ldmicro_line() {
    let text = "LDmicro0.2\nCYCLE=10000\n\nPROGRAM\nRUNG 1\n  7SEGMENTS d c X\nEND\n";
    let errors = parse(text).expect_err("refused");
    assert_eq!(errors[0].line, 6);
    assert!(
        errors[0].error.to_string().contains("C or A"),
        "{}",
        errors[0].error
    );
}

#[test]
fn the_board_draws_a_digit_for_each_variable_a_7segments_writes() {
    use engine::ladder::compile::{compile, Options};
    let ladder = to_ladder(&parse(COUNTER).expect("reads")).expect("draws");
    let il = compile(&ladder, engine::MachineId::SoftPlc, Options::default()).expect("compiles");
    let program = engine::softplc::Program::load(&il).expect("loads");
    let shown: Vec<(String, bool)> = program
        .segment_displays()
        .into_iter()
        .map(|d| (d.name, d.anode))
        .collect();
    assert!(program.segment_displays().iter().all(|d| d.segments == 7));
    let want = [
        ("seg", false),
        ("anode", true),
        ("d", false),
        ("deg", false),
        ("blank", false),
        ("h", false),
    ];
    let want: Vec<(String, bool)> = want.iter().map(|(n, a)| (n.to_string(), *a)).collect();
    assert_eq!(shown, want, "{il}");
}

#[test]
fn the_waiting_uart_is_refused_saying_why() {
    let text = "LDmicro0.2\nCYCLE=10000\n\nPROGRAM\nRUNG 1\n  UART_RECV w 2 1\nEND\n";
    let errors = to_ladder(&parse(text).expect("reads")).expect_err("refused");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].line, 6);
    let said = errors[0].error.to_string();
    assert!(
        said.starts_with(
            "UART_RECV waiting for its bytes: LDmicro's code loops on the port inside the scan"
        ),
        "{said}"
    );
    assert!(said.ends_with("the file is not opened"), "{said}");
}
