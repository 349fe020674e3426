//! `hashigo` with `--machine avr-plc`.

use super::common::{hashigo, text};

#[test]
fn run_shows_the_tof_power_up_pulse_and_scan_changes_the_scan_symbol() {
    let run = |scan: &str| {
        let out = hashigo(
            &[
                "run",
                "--machine",
                "avr-plc",
                "--program",
                "-",
                "--format",
                "asm",
                "--set",
                scan,
                "--until",
                "1.5s",
                "--every",
                "500ms",
                "--watch",
                "E_Stop,E_Stop_Timer.v",
            ],
            super::E_STOP,
        );
        assert!(out.status.success(), "{}", text(&out.stderr));
        text(&out.stdout)
    };
    // 1000/Scan scans of the scan period is one second either way.
    assert_eq!(
        run("scan=10ms"),
        "time_ms,E_Stop,E_Stop_Timer.v\n0,0,0\n500,1,50\n1000,1,100\n1500,0,100\n"
    );
    assert_eq!(
        run("scan=20ms"),
        "time_ms,E_Stop,E_Stop_Timer.v\n0,0,0\n500,1,25\n1000,1,50\n1500,0,50\n"
    );
}

#[test]
fn asm_prints_the_records_with_numeric_bytes() {
    let out = hashigo(
        &["asm", "--machine", "avr-plc", "--program", "-"],
        super::E_STOP,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        ".db 1,4,1,0\n.db 3,4,2,0\n.db 12,0,100,0\n.db 7,6,128,0\n.db 255,0,0,0\n"
    );
}

#[test]
fn bad_sources_and_names_are_located() {
    let out = hashigo(
        &["asm", "--machine", "avr-plc", "--program", "-"],
        ".db Load_A,Nope,1,0\n.db End_PLC,0,0,0\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>:1: unknown symbol \"Nope\"\n"
    );
    let out = hashigo(
        &[
            "run",
            "--machine",
            "avr-plc",
            "--program",
            "-",
            "--until",
            "1s",
            "--watch",
            "Ghost",
        ],
        super::E_STOP,
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("error: --watch: unknown bit \"Ghost\""));
}
