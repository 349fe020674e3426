//! Messages: what they say about times, versions and what they echo.

use engine::formats::{Project, ProjectError};
use engine::{shown, SimTime};

const SEED: &str = include_str!("../../programs/minasec-u/seed-test.json");

#[test]
fn times_say_what_is_wrong_with_them() {
    let says = |t: &str, what: &str| {
        let e = SimTime::parse(t).expect_err(t).to_string();
        assert!(e.contains(what), "{t}: {e}");
    };
    says("-1", "cannot be negative");
    says("1e30", "not an exponent");
    says("10000000000s", "past the simulated clock's limit");
    says("3h", "the unit must be ns, us, ms or s");
    assert!(SimTime::from_secs(9_000_000)
        .checked_add(SimTime::from_secs(2_000_000))
        .is_none());
}

#[test]
fn a_byte_order_mark_is_skipped() {
    let with_bom = format!("\u{feff}{SEED}");
    assert_eq!(Project::from_json(&with_bom), Project::from_json(SEED));
    assert!(Project::from_json(&with_bom).is_ok());
}

#[test]
fn version_zero_is_not_from_a_newer_hashigo() {
    let v0 = SEED.replace("\"version\": 1", "\"version\": 0");
    let e = Project::from_json(&v0).expect_err("version 0");
    assert_eq!(e.line, 3);
    assert_eq!(e.error, ProjectError::VersionZero);
    assert!(e.error.to_string().contains("versions start at 1"), "{e}");
    let v9 = SEED.replace("\"version\": 1", "\"version\": 9");
    assert_eq!(
        Project::from_json(&v9).expect_err("v9").error,
        ProjectError::Newer(9)
    );
}

#[test]
fn echoed_text_is_quoted_escaped_and_short() {
    assert_eq!(shown("a\u{0}\u{1b}[31m\n"), r#""a\u{0}\u{1b}[31m\n""#);
    let huge = "X".repeat(1 << 20);
    assert!(shown(&huge).len() < 50);
    let e = engine::io86a::isa::parse_bit(&huge)
        .expect_err("unknown")
        .to_string();
    assert!(e.len() < 200, "{:.300}", e);
}

#[test]
fn program_and_event_line_limits_are_checked_first() {
    let program = "; comment\n".repeat(100_001);
    let errors = engine::io86a::Program::parse(&program).expect_err("too long");
    assert_eq!(errors.len(), 1);
    assert_eq!(errors[0].line, 100_001);
    assert!(errors[0]
        .error
        .to_string()
        .contains("100001 lines, more than the 100000"));
    assert!(engine::io86a::Program::parse(&"; comment\n".repeat(100_000)).is_ok());
    for parsed in [
        engine::minasec::Program::parse(&program)
            .map(|_| ())
            .map_err(|e| e[0].error.to_string()),
        engine::arduino::Program::parse(&program, 512)
            .map(|_| ())
            .map_err(|e| e[0].error.to_string()),
        engine::avr::Program::parse(&program, 10)
            .map(|_| ())
            .map_err(|e| e[0].error.to_string()),
    ] {
        assert!(parsed
            .expect_err("too long")
            .contains("more than the 100000"));
    }
    let events = "0,X00,1\n".repeat(1_000_001);
    let errors = engine::events::parse_events(&events).expect_err("too many");
    assert_eq!(errors.len(), 1);
    assert!(errors[0]
        .error
        .to_string()
        .contains("more than the 1000000"));
}
