//! `hashigo` with `--machine io86a`.

use super::common::{hashigo, text, Temp};

const BLINK: &str =
    "1 LDI T01\n2 OUT T00\n3 K2\n4 LD T00\n5 OUT T01\n6 K2\n7 LDI T00\n8 OUT Y00\n9 END\n";

#[test]
fn run_blinks_the_led_every_0_2_s() {
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--until",
            "1s",
            "--every",
            "100ms",
            "--watch",
            "Y00,T00.v",
        ],
        BLINK,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = text(&out.stdout);
    let y00: Vec<&str> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).unwrap_or(""))
        .collect();
    // The first scan is at 1 ms: T00 starts there and expires at 201 ms;
    // T01 then expires at 401 ms, and T00 restarts on the next scan (402),
    // so the phases are [1, 201) on, [201, 401) off, [401, 602) on, ...
    assert_eq!(
        y00,
        ["0", "1", "1", "0", "0", "1", "1", "0", "0", "1", "1"],
        "{csv}"
    );
}

#[test]
fn run_takes_scan_and_input_events() {
    let tmp = Temp::new("io86a");
    let program = tmp.file("p.il", "LD X00\nOUT Y00\nEND\n");
    let events = tmp.file("e.csv", "35ms,X00,1\n");

    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            &program,
            "--set",
            "scan=10ms",
            "--input",
            &events,
            "--until",
            "70ms",
            "--every",
            "10ms",
            "--watch",
            "X00,Y00",
        ],
        "",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Scans every 10 ms: X00 rises at 35 ms; the default input filter (!2)
    // passes it after 20 ms, so the 60 ms scan is the first to see it.
    assert_eq!(
        text(&out.stdout),
        "time_ms,X00,Y00\n0,0,0\n10,0,0\n20,0,0\n30,0,0\n40,0,0\n50,0,0\n60,1,1\n70,1,1\n"
    );
}

#[test]
fn asm_prints_the_l_listing() {
    let out = hashigo(
        &["asm", "--machine", "io86a", "--program", "-"],
        "LD X00\nMOV K10 D00\nEND\n",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "1 LD X00\n2 MOV K10 D00\n3 END\n");
}

#[test]
fn bad_programs_are_located() {
    let program = "LD X00\nOUT T00\nLD X01\nOUT X02\nLD X09\n";
    let out = hashigo(&["asm", "--machine", "io86a", "--program", "-"], program);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>:2: OUT T/C needs its set value on the next step, e.g. K10\n\
         error: <stdin>:4: OUT X02: X02 is an input and cannot be driven\n\
         error: <stdin>:5: unknown device \"X09\": PLC-IO86A has X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07\n"
    );
    let long = "LD X00\n".repeat(512);
    let out = hashigo(&["asm", "--machine", "io86a", "--program", "-"], &long);
    assert_eq!(
        text(&out.stderr),
        "error: <stdin>:512: too many steps: 512, PLC-IO86A holds 511\n"
    );
}

#[test]
fn bench_counts_instructions() {
    let out = hashigo(
        &[
            "bench",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--steps",
            "900",
        ],
        BLINK,
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Whole scans: 101 scans of 9 instructions (END included) cover 900.
    assert!(
        text(&out.stdout).starts_with("steps=903 "),
        "{}",
        text(&out.stdout)
    );
}

#[test]
fn run_the_manuals_servo_example_with_pin_settings() {
    let tmp = Temp::new("io86a-servo");
    let events = tmp.file("e.csv", "35ms,X00,1\n");
    std::fs::write(&events, "0,X04,0V\n60ms,X04,2.5V\n110ms,X04,5V\n").expect("write");
    let out = hashigo(
        &[
            "run",
            "--machine",
            "io86a",
            "--program",
            "-",
            "--set",
            "X04=A:401:100",
            "--set",
            "Y03=R",
            "--input",
            &events,
            "--until",
            "150ms",
            "--every",
            "50ms",
            "--watch",
            "D06,Y03.v",
        ],
        "1 LD M57\n2 MOV\n3 D06\n4 D04\n5 OUT Y03\n6 END\n",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "time_ms,D06,Y03.v\n0,0,0\n50,100,500\n100,300,1500\n150,500,2500\n"
    );
}

#[test]
fn console_runs_the_terminal_with_the_clock_advancing_between_lines() {
    let tmp = Temp::new("io86a-console");
    let program = tmp.file("p.il", "LD X00\nOUT Y00\nEND\n");
    std::fs::write(&program, "LD M57\nOUT Y00\nEND\n").expect("write");
    let out = hashigo(
        &[
            "console",
            "--machine",
            "io86a",
            "--program",
            &program,
            "--step",
            "5ms",
        ],
        "^C\r\nY?\r\nR\r\nY?\r\n",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stdout),
        "R>^C\r\n>Y?\r\nY:00000000\r\n>R\r\nR>Y?\r\nY:00000001\r\nR>",
        "stopped before the first scan; R, then Y? shows the output"
    );
    let out = hashigo(&["console", "--machine", "minasec-u"], "");
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("no serial terminal"));
}
