//! AVR assembler expressions and the `Scan` symbol.

use engine::avr::{self, asm::assemble, asm::AsmError};
use engine::SimTime;

fn first_error(source: &str) -> AsmError {
    match assemble(source, 10) {
        Ok(_) => panic!("{source:.60} assembled"),
        Err(errors) => errors[0].error.clone(),
    }
}

#[test]
fn the_one_overflowing_quotient_is_an_error() {
    let e = first_error(".equ A=(-9223372036854775807-1)/-1\n");
    assert!(matches!(e, AsmError::Overflow(_)), "{e:?}");
    assert!(e.to_string().contains("overflows"), "{e}");
    assert!(matches!(
        first_error(".equ A=-(-9223372036854775807-1)\n"),
        AsmError::Overflow(_)
    ));
}

#[test]
fn deep_expressions_are_refused_not_recursed_into() {
    let parens = format!(".equ A={}1{}\n", "(".repeat(50_000), ")".repeat(50_000));
    let minus = format!(".equ A={}1\n", "-".repeat(200_000));
    let low = format!(
        ".equ A={}1{}\n",
        "LOW(".repeat(100_000),
        ")".repeat(100_000)
    );
    for source in [parens, minus, low] {
        let e = first_error(&source);
        assert!(matches!(e, AsmError::TooDeep(_)), "{e:?}");
        let message = e.to_string();
        assert!(
            message.len() < 200,
            "the message repeats the input: {message:.300}"
        );
    }
    // 64 levels are fine.
    let ok = format!(
        ".equ A={}1{}\n.db End_PLC,0,0,0\n",
        "(".repeat(64),
        ")".repeat(64)
    );
    assert!(assemble(&ok, 10).is_ok());
}

#[test]
fn the_scan_symbol_is_whole_milliseconds_or_refused() {
    assert_eq!(avr::scan_ms(SimTime::from_millis(10)), Ok(10));
    for bad in ["1500us", "500us", "0", "11s"] {
        let t = SimTime::parse(bad).expect("a time");
        let e = avr::scan_ms(t).expect_err(bad);
        assert!(
            e.to_string().contains("whole number of milliseconds"),
            "{bad}: {e}"
        );
    }
    let mut m = avr::Machine::new(avr::Program::default());
    assert!(m.apply_setting("scan", "1500us").is_err());
    assert_eq!(
        m.scan_period(),
        SimTime::from_millis(10),
        "unchanged on error"
    );
    assert!(m.apply_setting("scan", "2ms").is_ok());
    assert_eq!(m.scan_period(), SimTime::from_millis(2));
}
