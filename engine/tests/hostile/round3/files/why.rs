//! `hashigo why` on what boxes write (item 5).

use super::*;

/// `hashigo why` on the soft PLC's counting example with three parts
/// counted and the level measured: (exit code, standard output).
fn why_parts(device: &str) -> (Option<i32>, String, String) {
    let tmp = crate::common::Temp::new(&format!("round3-why-{}", device.replace(['%', '.'], "_")));
    let events = tmp.file(
        "events.csv",
        "100ms,sensor,1\n150ms,sensor,0\n200ms,sensor,1\n250ms,sensor,0\n300ms,sensor,1\n350ms,sensor,0\n0,measure,1\n0,level_in,500\n",
    );
    let program = concat!(env!("CARGO_MANIFEST_DIR"), "/programs/soft-plc/parts.il");
    let out = crate::common::hashigo(
        &[
            "why",
            "--machine",
            "soft-plc",
            "--program",
            program,
            "--input",
            &events,
            "--at",
            "1s",
            "--device",
            device,
        ],
        "",
    );
    (
        out.status.code(),
        crate::common::text(&out.stdout),
        crate::common::text(&out.stderr),
    )
}

/// Item 5: a variable a box writes through `=>` (`CV => parts`) was "No
/// output of the ladder writes parts"; it names the rung and the box,
/// with what the box reads.
#[test]
fn why_names_the_box_that_writes_a_variable_through_an_output() {
    let (code, out, err) = why_parts("parts");
    assert_eq!(code, Some(0), "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("parts = 3 at 1000 ms"), "{out}");
    assert_eq!(
        lines[1],
        "Rung 1, row 1, column 2: box CTU c0 writes parts through its CV output; its power (CU) is off in this scan.",
        "{out}"
    );
    assert_eq!(lines[2], "It reads R clear = 0; PV INT#12.", "{out}");
    assert_eq!(
        lines[3], "Its power would come on if any one of these changed:",
        "{out}"
    );
    assert!(
        lines[4].starts_with("  rung 1, row 1, column 1: contact sensor; sensor = 0, since 350 ms"),
        "{out}"
    );
    assert!(!out.contains("No output of the ladder writes"), "{out}");
}

/// Item 5: the instance's own outputs (`c0.CV`, `c0.Q`) are the box's.
#[test]
fn why_names_the_box_of_an_instances_output() {
    for (device, value, pin) in [("c0.CV", 3, "CV"), ("c0.Q", 0, "Q")] {
        let (code, out, err) = why_parts(device);
        assert_eq!(code, Some(0), "{err}");
        let lines: Vec<&str> = out.lines().collect();
        assert!(
            lines[0].starts_with(&format!("{device} = {value} at 1000 ms")),
            "{out}"
        );
        assert!(
            lines[1].starts_with(&format!(
                "Rung 1, row 1, column 2: box CTU c0 writes {device} through its {pin} output"
            )),
            "{out}"
        );
    }
}

/// Item 5: the `%` address of a declared variable is the variable:
/// `%QW0` (`level`, written by a DIV box) was "No output of the ladder
/// writes %QW0" while `level` was explained.
#[test]
fn why_on_a_declared_variables_address_explains_the_variable() {
    let (code, by_name, err) = why_parts("level");
    assert_eq!(code, Some(0), "{err}");
    let (code, by_address, err) = why_parts("%QW0");
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(by_address, by_name);
    assert!(by_name.starts_with("level = 50 at 1000 ms"), "{by_name}");
    assert!(
        by_name.contains("Rung 2, row 1, column 2: DIV"),
        "{by_name}"
    );
}

/// Item 5: a variable the ladder drew away (the CTU's `Q => _q0`, which
/// its ladder carries on as the box's power to the coil) is found at the
/// IL line that writes it.
#[test]
fn why_names_the_il_line_that_writes_a_variable_the_ladder_does_not_show() {
    let (code, out, err) = why_parts("_q0");
    assert_eq!(code, Some(0), "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].starts_with("_q0 = 0 at 1000 ms"), "{out}");
    assert!(
        lines[1].starts_with("Line 18 of ") && lines[1].ends_with(
            "parts.il writes _q0: CAL c0(CU := _p0, R := clear, PV := INT#12, CV => parts, Q => _q0)"
        ),
        "{out}"
    );
}

/// Item 5 on a PLCopen project: a CTU's CV wired to `count` (at `%QW0`)
/// was "No output of the ladder writes"; by name, by address and as
/// `c0.CV` it names the box.
#[test]
fn why_on_a_plcopen_projects_counter_output_names_its_box() {
    let tmp = crate::common::Temp::new("round3-why-plcopen");
    let vars = [
        var("pulse", "BOOL", "%IX0.0"),
        var("clear", "BOOL", "%IX0.1"),
        var("count", "INT", "%QW0"),
        var("c0", "CTU", ""),
    ]
    .concat();
    let body = [
        input(1, "pulse"),
        input(2, "clear"),
        input(5, "3"),
        block(
            3,
            "CTU",
            "c0",
            &[("CU", 1, ""), ("R", 2, ""), ("PV", 5, "")],
            &["Q", "CV"],
        ),
        output(4, 3, "CV", "count"),
    ]
    .concat();
    let path = tmp.file("counter.xml", &project(&vars, &body, ""));
    let events = tmp.file("events.csv", "100ms,pulse,1\n150ms,pulse,0\n");
    for device in ["count", "%QW0", "c0.CV"] {
        let out = crate::common::hashigo(
            &[
                "why",
                "--machine",
                "soft-plc",
                "--program",
                &path,
                "--input",
                &events,
                "--at",
                "200ms",
                "--device",
                device,
            ],
            "",
        );
        let stdout = crate::common::text(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            crate::common::text(&out.stderr)
        );
        let lines: Vec<&str> = stdout.lines().collect();
        // The CTU writes nothing else, so it is an output box: `count` is
        // its output as a coil's device is; `c0.CV` is its instance's.
        let (name, box_line) = if device == "c0.CV" {
            ("c0.CV", "box CTU c0 writes c0.CV through its CV output; its power (CU) is off in this scan.")
        } else {
            (
                "count",
                "c0: CTU(R := clear, PV := 3, CV => count) gets no power.",
            )
        };
        assert!(
            lines[0].starts_with(&format!("{name} = 1 at 200 ms")),
            "{stdout}"
        );
        assert_eq!(
            lines[1],
            format!("Rung 1, row 1, column 2: {box_line}"),
            "{stdout}"
        );
        let cause = "  rung 1, row 1, column 1: contact pulse; pulse = 0";
        assert!(
            lines.last().is_some_and(|l| l.starts_with(cause)),
            "{stdout}"
        );
    }
}
