//! Ladders from JSON projects: links, long rungs, many rungs, wiring
//! messages, and the per-machine checks that once let wrong programs by.

use engine::formats::{Project, ProjectError};
use engine::ladder::compile::{compile, Options};
use engine::ladder::LadderErrorKind;
use engine::MachineId;

use crate::gen::{coil, contact, project, rung, series_rung};

fn compile_json(json: &str, options: Options) -> Result<String, Vec<String>> {
    let p = Project::from_json(json).map_err(|e| vec![e.to_string()])?;
    compile(&p.ladder, p.machine, options)
        .map_err(|errors| errors.iter().map(ToString::to_string).collect())
}

#[test]
fn a_link_at_the_largest_row_is_an_error_not_a_panic() {
    let r = rung(
        &[vec![contact("X00"), coil("Y00")]],
        "[18446744073709551615, 0]",
    );
    let errors =
        compile_json(&project("minasec-u", &[r]), Options::default()).expect_err("bad link");
    assert_eq!(
        errors,
        ["rung 1, row 18446744073709551616, column 1: a vertical link reaches past the rung's last row or column"]
    );
}

#[test]
fn a_rung_of_twenty_thousand_contacts_compiles() {
    let json = project("avr-plc", &[series_rung(20_000, "R0.0", "R1.0")]);
    let text = compile_json(&json, Options::default()).expect("compiles");
    assert_eq!(text.matches("And_A,0,Bit0,0").count(), 19_999);
    assert!(
        text.contains(".db Coil_A,1,Bit0,0\n.db End_PLC"),
        "{}",
        &text[text.len() - 200..]
    );
}

#[test]
fn a_machine_with_fewer_steps_says_so_for_a_long_rung() {
    let json = project("io86a", &[series_rung(10_000, "X00", "Y00")]);
    let errors = compile_json(&json, Options::default()).expect_err("too long");
    assert_eq!(
        errors,
        ["rung 1: the program needs 10002 steps: io86a has 511"]
    );
}

#[test]
fn a_grid_larger_than_the_rung_limit_is_refused_before_analysis() {
    // 2 000 rows, the last one 1 000 columns wide: 2 million cells.
    let mut rows = vec![vec![contact("X00"), coil("Y00")]];
    rows.extend((1..1999).map(|_| vec![]));
    rows.push(vec!["null".to_string(); 1000]);
    let json = project("io86a", &[rung(&rows, "")]);
    let p = Project::from_json(&json).expect("reads");
    let errors = p.ladder.logic(MachineId::Io86a).expect_err("too large");
    assert_eq!(errors.len(), 1);
    assert_eq!(errors[0].kind, LadderErrorKind::Limit);
    assert!(
        errors[0].message.contains("more than the 1048576 cells"),
        "{errors:?}"
    );
}

#[test]
fn too_many_rungs_are_refused_when_read() {
    let rungs = vec![series_rung(1, "X00", "Y00"); 10_001];
    let e = Project::from_json(&project("io86a", &rungs)).expect_err("too many");
    assert_eq!(e.error, ProjectError::TooManyRungs(10_001));
    assert!(
        e.error
            .to_string()
            .contains("10001 rungs, more than the 10000"),
        "{e}"
    );
}

#[test]
fn a_shorted_contact_is_named_as_such() {
    // Row 1's wire and the link at column 1 join both sides of X00 to the
    // rail: the contact is shorted (the coil then sits on the rail too,
    // but that is the consequence, not the cause).
    let r = rung(
        &[
            vec![contact("X00"), coil("Y00")],
            vec![r#"{"type":"wire"}"#.into()],
        ],
        "[0, 1]",
    );
    let errors = compile_json(&project("io86a", &[r]), Options::default()).expect_err("short");
    assert_eq!(
        errors,
        ["rung 1, row 1, column 1: short circuit: a wire joins both sides of this element"]
    );
}

#[test]
fn a_plain_coil_on_an_io86a_counter_is_refused_at_its_cell() {
    let r = rung(&[vec![contact("X00"), coil("C07")]], "");
    let errors = compile_json(&project("io86a", &[r]), Options::default()).expect_err("plain coil");
    assert_eq!(errors.len(), 1);
    assert!(
        errors[0].starts_with("rung 1, row 1, column 2: a plain coil cannot drive counter C07"),
        "{errors:?}"
    );
    // Set and reset coils on a counter stay allowed (`SET C07`, `RST C07`).
    let set = r#"{"type":"coil","kind":"reset","device":"C07"}"#.to_string();
    let r = rung(&[vec![contact("X00"), set]], "");
    assert!(compile_json(&project("io86a", &[r]), Options::default()).is_ok());
}

fn avr_timer(preset_ms: u32) -> String {
    let timer = format!(r#"{{"type":"timer","kind":"ton","name":"t","preset_ms":{preset_ms}}}"#);
    project(
        "avr-plc",
        &[rung(&[vec![contact("R0.0"), timer, coil("R1.0")]], "")],
    )
}

#[test]
fn avr_timer_presets_that_do_not_fit_are_located_errors() {
    let ten = Options { avr_scan_ms: 10 };
    for (ms, why) in [
        (
            655_360,
            "65536 scans of 10 ms: the AVR PLC's timers count at most 65535",
        ),
        (700_000, "70000 scans of 10 ms"),
        (5, "not a whole number of 10 ms scans"),
        (15, "not a whole number of 10 ms scans"),
    ] {
        let errors = compile_json(&avr_timer(ms), ten).expect_err("out of range");
        assert_eq!(errors.len(), 1, "{ms}: {errors:?}");
        assert!(
            errors[0].starts_with("rung 1, row 1, column 2: TON") && errors[0].contains(why),
            "{ms}: {errors:?}"
        );
    }
    let text = compile_json(&avr_timer(655_350), ten).expect("65535 scans fit");
    assert!(
        text.contains("LOW(655350/Scan),HIGH(655350/Scan)"),
        "{text}"
    );
    // At a 1 ms scan 5 ms is five scans.
    assert!(compile_json(&avr_timer(5), Options { avr_scan_ms: 1 }).is_ok());
}
