//! Messages: what they say about times, versions and what they echo.

use engine::ladder::Project;
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
    assert!(e.error.contains("versions start at 1"), "{e}");
    assert!(!e.error.contains("newer"), "{e}");
    let v9 = SEED.replace("\"version\": 1", "\"version\": 9");
    assert!(Project::from_json(&v9)
        .expect_err("v9")
        .error
        .contains("newer"));
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
