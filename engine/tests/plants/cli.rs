use super::common::{hashigo, text, Temp};

const CONVEYOR: &str = include_str!("../../programs/minasec-u/conveyor.il");

fn run(args: &[&str]) -> (i32, String, String) {
    let out = hashigo(args, "");
    (
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr),
    )
}

/// The last CSV row's fields.
fn last_row(csv: &str) -> Vec<i64> {
    let row = csv.lines().last().unwrap_or_default();
    row.split(',').map(|f| f.parse().unwrap_or(-1)).collect()
}

#[test]
fn plants_lists_each_plant_with_its_default_wiring_per_machine() {
    let (code, out, _) = run(&["plants"]);
    assert_eq!(code, 0);
    assert!(out.contains("plant conveyor: "));
    assert!(out.contains("\n  in bit infeed: "));
    assert!(out.contains("\n  out bit motor: "));
    assert!(out.contains("\n  quantity delivered: parts that left the belt's end (parts)\n"));
    assert!(out.contains("\n  quantity alarms: "));
    assert!(out.contains("\n  parameter speed=250: "));
    assert!(out.contains("\n  in analog level: "));
    assert!(!out.contains("infeed,"), "no wiring without --machine");
    let (_, minasec, _) = run(&["plants", "--machine", "minasec-u"]);
    assert!(
        minasec.contains("\n  infeed,X00\n  outfeed,X01\n  motor,Y00\n"),
        "{minasec}"
    );
    assert!(minasec.contains("  # level not connected: minasec-u has no analog input"));
    let (_, io86a, _) = run(&["plants", "--machine", "io86a"]);
    assert!(io86a.contains("\n  level,X04\n"), "{io86a}");
    let (_, soft, _) = run(&["plants", "--machine", "soft-plc"]);
    assert!(soft.contains("\n  infeed,%IX0.0\n") && soft.contains("\n  level,%IW0\n"));
    let (_, arduino, _) = run(&["plants", "--machine", "arduino-plc"]);
    assert!(arduino.contains("\n  motor,Y000\n"), "{arduino}");
    let (_, avr, _) = run(&["plants", "--machine", "avr-plc"]);
    assert!(
        avr.contains("avr-plc wires by name: the program's bit INFEED"),
        "{avr}"
    );
    let (code, _, err) = run(&["plants", "--machine", "plc5"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: "), "{err}");
}

#[test]
fn run_drives_the_conveyor_from_power_on_and_watches_its_quantities() {
    let tmp = Temp::new("plant-run");
    let program = tmp.file("conveyor.il", CONVEYOR);
    let args = [
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--set",
        "T1=1s",
        "--plant",
        "conveyor",
        "--until",
        "60s",
        "--every",
        "20s",
        "--watch",
        "X00,conveyor.infeed,conveyor.motor,conveyor.placed,conveyor.delivered,conveyor.alarms",
    ];
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with(
        "time_ms,X00,conveyor.infeed,conveyor.motor,conveyor.placed,conveyor.delivered,conveyor.alarms\n0,0,0,0,0,0,0\n"
    ), "{out}");
    let last = last_row(&out);
    assert_eq!(last[0], 60_000);
    assert!(last[4] >= 10 && last[5] >= 8, "{out}");
    assert_eq!(last[6], 0);
    assert_eq!(err, "", "no alarm with the 1 s delay");
    // The same run again: the same rows.
    assert_eq!(run(&args).1, out);
    // A faster belt (a parameter) delivers more.
    let faster = [&args[..], &["--set", "conveyor.speed=500"]].concat();
    let (code, fast, err) = run(&faster);
    assert_eq!(code, 0, "{err}");
    assert!(last_row(&fast)[5] > last[5], "{fast}");
}

#[test]
fn run_prints_each_alarm_on_stderr_and_still_exits_0() {
    let tmp = Temp::new("plant-alarm");
    let program = tmp.file("at-once.il", "LD X00\nOR Y00\nST Y00\n");
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--until",
        "10s",
        "--watch",
        "conveyor.alarms",
    ]);
    assert_eq!(code, 0);
    assert!(out.ends_with("10000,1\n"), "{out}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 1, "{err}");
    let fields: Vec<&str> = lines[0].splitn(4, ": ").collect();
    assert_eq!(fields[0], "alarm");
    let ms: u64 = fields[1].parse().expect("TIME_ms is an integer");
    assert!((240..270).contains(&ms), "{err}");
    assert_eq!(fields[2], "conveyor");
    assert!(fields[3].contains("after a part arrived"), "{err}");
}

#[test]
fn an_input_event_on_a_device_the_plant_drives_is_an_error_naming_both() {
    let tmp = Temp::new("plant-event");
    let program = tmp.file("conveyor.il", CONVEYOR);
    let events = tmp.file("events.csv", "time,device,value\n1s,X02,1\n2s,X00,1\n");
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--input",
        &events,
        "--until",
        "3s",
        "--watch",
        "Y00",
    ]);
    assert_eq!(code, 2);
    assert_eq!(out, "");
    assert!(
        err.contains("events.csv:3: ") && err.contains("X00") && err.contains("conveyor.infeed"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
}

#[test]
fn a_wiring_file_moves_signals_and_its_problems_name_file_line_signal_and_device() {
    let tmp = Temp::new("plant-wiring");
    let program = tmp.file("p.il", "LD X05\nST Y03\n");
    let wiring = tmp.file("w.csv", "# moved\nsignal,device\ninfeed,X05\nmotor,Y03\n");
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--wiring",
        &wiring,
        "--until",
        "1s",
        "--watch",
        "X05,conveyor.motor,X00",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().last(), Some("1000,1,1,0"), "{out}");
    let bad = tmp.file("bad.csv", "infeed,X00\nlevel\nbelt,X01\nmotor,X02\n");
    let (code, _, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--wiring",
        &bad,
        "--until",
        "1s",
        "--watch",
        "Y00",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("bad.csv:2: expected SIGNAL,DEVICE"), "{err}");
    let bad = tmp.file("bad2.csv", "infeed,X00\nbelt,X01\nmotor,X02\n");
    let (code, _, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--wiring",
        &bad,
        "--until",
        "1s",
        "--watch",
        "Y00",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("bad2.csv:2: conveyor has no signal \"belt\""),
        "{err}"
    );
    assert!(
        err.contains(
            "bad2.csv:3: conveyor.motor is an actuator the PLC drives, and X02 is an input"
        ),
        "{err}"
    );
    let analog = tmp.file("analog.csv", "level,X04\n");
    let (code, _, err) = run(&[
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--plant",
        "tank",
        "--wiring",
        &analog,
        "--until",
        "1s",
        "--watch",
        "Y00",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("analog.csv:1: tank.level is an analog signal and X04 is not an analog input (minasec-u has no analog input)"), "{err}");
}

#[test]
fn plant_options_refuse_what_they_cannot_take() {
    let tmp = Temp::new("plant-options");
    let program = tmp.file("p.il", "LD X00\nST Y00\n");
    let base = [
        "run",
        "--machine",
        "minasec-u",
        "--program",
        &program,
        "--until",
        "1s",
        "--watch",
        "Y00",
    ];
    let cases: [(&[&str], &str); 7] = [
        (
            &["--plant", "conveyor", "--wiring", "-", "--input", "-"],
            "--wiring - and another option both read standard input",
        ),
        (
            &["--plant", "silo"],
            "--plant: no plant \"silo\" (plants: conveyor, tank, traffic, door, sorter, room-light)",
        ),
        (&["--fault", "motor dead"], "--fault needs --plant NAME"),
        (
            &["--plant", "conveyor", "--fault", "motor broken"],
            "--fault \"motor broken\": expected SIGNAL stuck 0|1",
        ),
        (
            &["--plant", "conveyor", "--fault", "infeed dead"],
            "dead is for actuators",
        ),
        (
            &["--plant", "conveyor", "--set", "conveyor.speed=fast"],
            "--set conveyor.speed=fast: speed takes a whole number (1..10000 mm/s)",
        ),
        (
            &["--plant", "tank", "--set", "tank.low_at=90"],
            "the low switch (90 %) is above the high switch (80 %)",
        ),
    ];
    for (extra, expected) in cases {
        let (code, out, err) = run(&[&base[..], extra].concat());
        assert_eq!(code, 2, "{extra:?}");
        assert_eq!(out, "");
        assert!(err.contains(expected), "{extra:?}: {err}");
    }
}

#[test]
fn the_tank_level_reaches_io86a_as_volts_once_its_input_is_analog() {
    let tmp = Temp::new("plant-io86a");
    let program = tmp.file("p.il", "LD X00\nOUT Y02\nEND\n");
    let base = [
        "run",
        "--machine",
        "io86a",
        "--program",
        &program,
        "--plant",
        "tank",
        "--until",
        "1s",
    ];
    let (code, _, err) = run(&[&base[..], &["--watch", "D06"]].concat());
    assert_eq!(code, 2);
    assert!(err.contains("tank.level on X04: X04 is a digital input: a voltage needs analog mode (--set X04=A:n1:n2)"), "{err}");
    // 0-5 V as 0..100 in D06: the tank's start level, 50 %, less its
    // 1 s of demand at 2 %/s.
    let (code, out, err) = run(&[
        &base[..],
        &[
            "--set",
            "X04=A:101:0",
            "--watch",
            "D06,tank.level,tank.low,X00,Y02",
        ],
    ]
    .concat());
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().last(), Some("1000,48,48,1,1,1"), "{out}");
}

#[test]
fn the_avr_plc_wires_by_name_and_the_arduino_sketch_by_its_pins() {
    let tmp = Temp::new("plant-avr");
    // The infeed starts and holds the motor at once: the alarm and the
    // running belt show the wiring works.
    let asm = ".equ INFEED_R=4\n.equ INFEED_B=Bit0\n.equ MOTOR_R=5\n.equ MOTOR_B=Bit0\n.csg\n.db Load_A,INFEED_R,INFEED_B,0\n.db Or_A,MOTOR_R,MOTOR_B,0\n.db Coil_A,MOTOR_R,MOTOR_B,0\n.db End_PLC,0,0,0\n";
    let program = tmp.file("at-once.asm", asm);
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "avr-plc",
        "--program",
        &program,
        "--plant",
        "conveyor",
        "--until",
        "3s",
        "--watch",
        "INFEED,MOTOR,conveyor.motor,conveyor.alarms",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().last(), Some("3000,0,1,1,1"), "{out}");
    assert!(err.starts_with("alarm: "), "{err}");
    let sketch = tmp.file(
        "at-once.txt",
        "0 LD X000\n1 OR Y000\n2 OUT Y000\n3 JUMP 0\n",
    );
    let (code, out, err) = run(&[
        "run",
        "--machine",
        "arduino-plc",
        "--program",
        &sketch,
        "--plant",
        "conveyor",
        "--until",
        "3s",
        "--watch",
        "X000,Y000,conveyor.alarms",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().last(), Some("3000,0,1,1"), "{out}");
}
