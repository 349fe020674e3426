//! The plants of issue #51 (traffic, door, sorter, room-light) on the
//! command line: listed by `hashigo plants`, and their faults acting
//! through the framework on the reference ladders.

use super::common::{hashigo, text};

const PROGRAMS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/programs");

fn run(args: &[&str]) -> (i32, String, String) {
    let out = hashigo(args, "");
    (
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr),
    )
}

/// Runs the MINASEC-U reference ladder of `plant` with `faults` until
/// `until`; the last row's values of `watch` and the standard error.
fn reference(plant: &str, faults: &[&str], until: &str, watch: &str) -> (Vec<i64>, String) {
    let program = format!("{PROGRAMS}/minasec-u/{plant}.il");
    let mut args = vec!["run", "--machine", "minasec-u", "--program", &program];
    args.extend(["--set", "T0=1s", "--set", "T1=6s", "--plant", plant]);
    for f in faults {
        args.extend(["--fault", f]);
    }
    args.extend(["--until", until, "--watch", watch]);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let last = out.lines().last().unwrap_or_default();
    let values = last
        .split(',')
        .skip(1)
        .map(|f| f.parse().unwrap())
        .collect();
    (values, err)
}

#[test]
fn plants_lists_the_four_with_their_names_and_default_wiring() {
    let (code, out, _) = run(&["plants"]);
    assert_eq!(code, 0);
    for line in [
        "plant traffic: ",
        "\n  in bit button: ",
        "\n  out bit dont_walk: ",
        "\n  quantity waited_max: ",
        "plant door: ",
        "\n  quantity position: ",
        "\n  parameter grace=200: ",
        "plant sorter: ",
        "\n  in bit pusher_out: ",
        "\n  quantity wrong: ",
        "plant room-light: ",
        "\n  in analog light: ",
        "\n  quantity lamp_on_ms: ",
    ] {
        assert!(out.contains(line), "{line:?} in {out}");
    }
    let (_, io86a, _) = run(&["plants", "--machine", "io86a"]);
    assert!(
        io86a.contains("\n  dark,X00\n  light,X04\n  lamp,Y00\n"),
        "{io86a}"
    );
    assert!(io86a.contains("\n  button,X00\n  car_red,Y00\n"), "{io86a}");
    let (_, minasec, _) = run(&["plants", "--machine", "minasec-u"]);
    assert!(minasec.contains("  # light not connected: minasec-u has no analog input"));
}

#[test]
fn a_dead_walk_light_lets_nobody_cross_and_the_wait_grows() {
    let watch = "traffic.crossed,traffic.waited_max,traffic.alarms";
    let (ok, _) = reference("traffic", &[], "120s", watch);
    assert!(ok[0] >= 4 && ok[1] < 2000, "{ok:?}");
    let (dead, _) = reference("traffic", &["walk dead"], "120s", watch);
    assert_eq!(dead[0], 0, "{dead:?}");
    assert!(
        dead[1] > 100_000,
        "the first pedestrian still waits: {dead:?}"
    );
}

#[test]
fn a_door_whose_top_switch_is_stuck_drives_against_the_top_with_an_alarm() {
    let (ok, err) = reference("door", &[], "60s", "door.position,door.alarms");
    assert_eq!((ok.as_slice(), err.as_str()), (&[100, 0][..], ""));
    let (stuck, err) = reference("door", &["top stuck 0"], "60s", "door.position,door.alarms");
    assert_eq!(stuck, [100, 1]);
    assert!(
        err.contains(
            ": door: the motor drives up against the top limit switch for more than 200 ms"
        ),
        "{err}"
    );
}

#[test]
fn a_height_sensor_stuck_off_sends_every_tall_part_to_the_wrong_bin() {
    let watch = "sorter.right,sorter.wrong,sorter.alarms";
    let (ok, _) = reference("sorter", &[], "120s", watch);
    assert_eq!((ok[1], ok[2]), (0, 0), "{ok:?}");
    let (stuck, _) = reference("sorter", &["tall stuck 0 from 30s"], "120s", watch);
    assert!(stuck[1] >= 5, "tall parts at the end: {stuck:?}");
    assert!(stuck[0] < ok[0], "{stuck:?} against {ok:?}");
}

#[test]
fn a_dark_sensor_stuck_on_wastes_the_whole_day_and_analog_faults_are_refused() {
    let watch = "room-light.lamp_on_ms,room-light.unlit_ms";
    let (ok, _) = reference("room-light", &[], "60s", watch);
    assert!(ok[0] <= 50 && ok[1] <= 50, "{ok:?}");
    let (stuck, _) = reference("room-light", &["dark stuck 1"], "60s", watch);
    assert!(stuck[0] >= 27_000, "lamp on all day: {stuck:?}");
    let program = format!("{PROGRAMS}/soft-plc/room-light.il");
    let (code, _, err) = run(&[
        "run",
        "--machine",
        "soft-plc",
        "--program",
        &program,
        "--plant",
        "room-light",
        "--fault",
        "light stuck 1",
        "--until",
        "1s",
        "--watch",
        "room-light.lamp",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.starts_with("error: ") && err.contains("light"), "{err}");
}

#[test]
fn each_exercise_fails_a_plausible_wrong_ladder_by_what_the_machine_did() {
    use engine::formats::Project;
    use engine::ladder::decompile::decompile_text;
    use engine::MachineId;
    let tmp = super::common::Temp::new("plant-wrong");
    for (plant, wrong, failed) in [
        // Green always, walk latched by the button: the conflict.
        (
            "traffic",
            "LDI C0R\nST Y02\nLD X00\nOR Y03\nST Y03\n",
            "fail everyone crosses safely for five minutes: traffic.alarms = 0",
        ),
        // Opens on the remote and never stops at the top.
        (
            "door",
            "LD X03\nOR Y00\nST Y00\n",
            "fail no alarm in five minutes: door.alarms = 0",
        ),
        // Pushes every part, tall or short.
        (
            "sorter",
            "LDI C0R\nST Y00\nLD X00\nOR Y01\nANDI X02\nST Y01\n",
            "fail the pusher never hits a part: sorter.wrong = 0",
        ),
        // The lamp always on.
        (
            "room-light",
            "LDI C0R\nST Y00\n",
            "fail no light wasted, no dark room, for two days: room-light.lamp_on_ms <= 100",
        ),
    ] {
        let path = format!("{PROGRAMS}/minasec-u/{plant}.json");
        let mut project = Project::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
        project.ladder = decompile_text(MachineId::MinasecU, wrong, 10).unwrap();
        let file = tmp.file(&format!("{plant}.json"), &project.to_json());
        let (code, out, _) = run(&["test", "--program", &file]);
        assert_eq!(code, 1, "{plant}: {out}");
        assert!(out.contains(failed), "{plant}: {out}");
    }
}

#[test]
fn a_door_blocked_while_closing_opens_again_and_one_that_closes_on_raises_the_alarm() {
    // The eye blocked at 75 s, while the reference door closes (71-81 s).
    let blocked = [
        "--plant",
        "door",
        "--set",
        "door.eye_every=75s",
        "--set",
        "door.eye_spread=0",
        "--set",
        "door.seed=1",
        "--until",
        "90s",
        "--watch",
        "door.position,door.alarms",
    ];
    let door = format!("{PROGRAMS}/minasec-u/door.il");
    let args = [
        &["run", "--machine", "minasec-u", "--program", &door][..],
        &blocked,
    ]
    .concat();
    let (code, out, err) = run(&args);
    assert_eq!((code, err.as_str()), (0, ""));
    assert!(out.ends_with("\n90000,100,0\n"), "opened again: {out}");
    let tmp = super::common::Temp::new("door-eye");
    let blind = tmp.file("blind.il", "LD X03\nAND X01\nOR Y00\nANDI X00\nST Y00\nLD X03\nAND X00\nOR Y01\nANDI X01\nANDI Y00\nST Y01\n");
    let args = [
        &["run", "--machine", "minasec-u", "--program", &blind][..],
        &blocked,
    ]
    .concat();
    let (_, out, err) = run(&args);
    assert!(out.ends_with("\n90000,0,1\n"), "closed on: {out}");
    assert!(
        err.contains("75200: door: the door closes while the photo-eye is blocked"),
        "{err}"
    );
}
