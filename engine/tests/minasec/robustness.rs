//! No input text makes any parser or console panic: arbitrary strings, and
//! strings made of the formats' own pieces, into every machine's reader.

use engine::{arduino, avr, events, io86a, minasec};
use proptest::prelude::*;

/// Text built from the formats' own words, so that it gets past the first
/// checks more often than random characters do.
fn plausible() -> impl Strategy<Value = String> {
    let word = prop_oneof![
        Just("LD"),
        Just("OUT"),
        Just("ST"),
        Just("ANDI"),
        Just("ORB"),
        Just("ANB"),
        Just("MOV"),
        Just("K"),
        Just("K32768"),
        Just("D0"),
        Just("X00"),
        Just("Y09"),
        Just("T0"),
        Just("C0R"),
        Just("$1F"),
        Just("%1"),
        Just("255"),
        Just("999999999999"),
        Just(".db"),
        Just(".equ A="),
        Just(".dseg"),
        Just("LOW("),
        Just(")"),
        Just(","),
        Just(";"),
        Just(":"),
        Just("="),
        Just("?"),
        Just("-"),
        Just("1.5s"),
        Just("JUMP"),
        Just("s0"),
        Just("\u{3042}"),
        Just("\t"),
    ];
    prop::collection::vec(
        prop::collection::vec(word, 0..6).prop_map(|w| w.join(" ")),
        0..12,
    )
    .prop_map(|lines| lines.join("\n"))
}

fn any_text() -> impl Strategy<Value = String> {
    prop_oneof![any::<String>(), plausible()]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn parsers_never_panic(text in any_text()) {
        let _ = minasec::Program::parse(&text);
        let _ = io86a::Program::parse(&text);
        let _ = arduino::Program::parse(&text, 512);
        let _ = avr::Program::parse(&text, 10);
        let _ = events::parse_events(&text);
        let _ = engine::SimTime::parse(&text);
    }

    #[test]
    fn consoles_never_panic(lines in prop::collection::vec(any_text(), 1..8)) {
        let mut io = io86a::Machine::new(io86a::Program::default());
        let mut terminal = io86a::Terminal::new(&io);
        let mut ard = arduino::Machine::new(&arduino::Program::default(), arduino::Chip::Atmega168);
        for line in &lines {
            let _ = terminal.type_line(&mut io, line);
            let _ = arduino::monitor::type_line(&mut ard, line);
            let t = io.now() + engine::SimTime::from_millis(5);
            io.run_until(t);
            ard.run_until(t);
        }
    }
}
