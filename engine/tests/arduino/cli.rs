//! `hashigo` with `--machine arduino-plc`.

use super::common::{hashigo, text, Temp};

const SELF_HOLD: &str = "0 LD X000\n1 OR Y000\n2 ANDN X001\n3 OUT Y000\n4 JUMP 0\n";

#[test]
fn run_the_self_hold_with_events() {
    let tmp = Temp::new("arduino");
    let events = tmp.file("e.csv", "10ms,X000,1\n20ms,X000,0\n35ms,X001,1\n");

    let out = hashigo(
        &[
            "run",
            "--machine",
            "arduino-plc",
            "--program",
            "-",
            "--input",
            &events,
            "--until",
            "50ms",
            "--every",
            "10ms",
            "--watch",
            "X000,X001,Y000",
        ],
        SELF_HOLD,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "time_ms,X000,X001,Y000\n0,0,0,0\n10,1,0,0\n20,0,0,1\n30,0,0,1\n40,0,1,0\n50,0,1,0\n"
    );
}

#[test]
fn quirk_sketch_changes_the_result() {
    let run = |quirk: &str| {
        let out = hashigo(
            &[
                "run",
                "--machine",
                "arduino-plc",
                "--program",
                "-",
                "--set",
                quirk,
                "--until",
                "1ms",
                "--watch",
                "Y000",
            ],
            "LD Y000\nORN Y000\nOUT Y000\nEND\n",
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
        text(&out.stdout)
    };
    assert_eq!(run("quirk=none"), "time_ms,Y000\n0,0\n1,1\n");
    assert_eq!(run("quirk=sketch"), "time_ms,Y000\n0,0\n1,0\n");
}

#[test]
fn asm_prints_the_p_dump() {
    let out = hashigo(
        &["asm", "--machine", "arduino-plc", "--program", "-"],
        SELF_HOLD,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let dump = text(&out.stdout);
    assert_eq!(dump.lines().count(), 16);
    assert!(dump.starts_with("2000 6008 5001 1008 F000 FFFF "), "{dump}");
}

#[test]
fn console_is_the_serial_monitor() {
    let out = hashigo(
        &["console", "--machine", "arduino-plc"],
        "s0 LD X000\rs1 OUT Y000\rl\r",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "\r\n\r\n\r\nLD X000\r\nOUT Y000\r\n");
}

#[test]
fn bad_programs_are_located() {
    let out = hashigo(
        &["asm", "--machine", "arduino-plc", "--program", "-"],
        "LD X000\nOUT X001\n600 END\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>:2: OUT X001: outputs are Y000-Y005\nerror: <stdin>:3: step 600 is beyond the EEPROM: this chip holds 512 steps\n"
    );
}
