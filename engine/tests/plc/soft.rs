//! The soft PLC through [`Plc`]: its devices (names, addresses, block
//! outputs), events of any type, RUN / STOP, stepping, images, settings
//! and its listing.

use engine::events::{InputValue, Real};
use engine::machines::new_plc;
use engine::plc::{Command, Plc, Value};
use engine::{MachineId, SimTime};

const PROGRAM: &str = "PROGRAM demo
(* a comment
   over two lines *)
VAR
  Start AT %IX0.0 : BOOL;
  level AT %IW0 : INT;
  lamp AT %QX0.0 : BOOL;
  speed : REAL := 1.5;
  count : UINT;
  delay : TON;
END_VAR
LD start
ST lamp
CAL delay(IN := lamp, PT := T#50ms)
LD count
ADD 1
ST count
LD level
GT 100
ST %QX0.1
END_PROGRAM
";

fn soft() -> Box<dyn Plc> {
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(PROGRAM).expect("loads");
    plc
}

fn value(plc: &dyn Plc, name: &str) -> Value {
    plc.read(plc.device(name).unwrap_or_else(|e| panic!("{name}: {e}")))
}

fn set(plc: &mut dyn Plc, name: &str, v: InputValue) {
    let d = plc.device(name).expect("device");
    plc.apply(Command::SetInput(d, v)).expect("takes it");
}

#[test]
fn devices_are_names_addresses_and_block_outputs() {
    let mut plc = soft();
    for same in ["start", "START", "%IX0.0", "%I0.0"] {
        assert_eq!(plc.device(same).ok(), plc.device("Start").ok(), "{same}");
    }
    set(plc.as_mut(), "%IX0.0", InputValue::Int(1));
    plc.run_until(SimTime::from_millis(100));
    assert_eq!(value(plc.as_ref(), "lamp"), 1);
    assert_eq!(
        value(plc.as_ref(), "delay"),
        1,
        "an instance alone is its Q"
    );
    assert_eq!(value(plc.as_ref(), "delay.Q"), 1);
    // IN came on in the scan at 10 ms; ET stops at PT.
    assert_eq!(value(plc.as_ref(), "delay.ET"), 50);
    assert_eq!(value(plc.as_ref(), "delay.v"), 50);
    assert_eq!(value(plc.as_ref(), "count"), Value::Uint(10));
    assert_eq!(value(plc.as_ref(), "speed").to_string(), "1.5");
    let e = plc.device("ghost").expect_err("unknown").to_string();
    assert!(e.contains("unknown device \"ghost\""), "{e}");
    let e = plc.device("delay.CV").expect_err("no CV").to_string();
    assert_eq!(e, "delay has no output CV");
}

#[test]
fn events_set_values_of_any_type_and_say_what_a_type_takes() {
    let mut plc = soft();
    set(plc.as_mut(), "%IW0", InputValue::Int(250));
    let real = Real::new(2.25).expect("finite");
    set(plc.as_mut(), "speed", InputValue::Real(real));
    // A variable that is no input is written at once; an input's
    // terminal is read at the next scan's start.
    assert_eq!(value(plc.as_ref(), "speed").to_string(), "2.25");
    assert_eq!(value(plc.as_ref(), "level"), 0);
    plc.step_scan();
    assert_eq!(value(plc.as_ref(), "level"), 250);
    assert_eq!(value(plc.as_ref(), "%QX0.1"), 1);
    let level = plc.device("level").expect("level");
    let refused = |v| plc.check_input(level, v).expect_err("refused").to_string();
    assert_eq!(
        refused(InputValue::Int(40_000)),
        "level is INT: 40000 is not one (an integer in its range)"
    );
    assert!(refused(InputValue::Real(real)).contains("is INT"));
    assert!(refused(InputValue::Millivolts(2500)).contains("2.5V"));
    let start = plc.device("start").expect("start");
    assert!(plc.check_input(start, InputValue::Int(2)).is_err());
    let q = plc.device("delay.Q").expect("Q");
    let e = plc.check_input(q, InputValue::Int(1)).expect_err("output");
    assert!(e.to_string().contains("block's output"), "{e}");
    // Releasing an input's terminal gives its zero.
    plc.apply(Command::ReleaseInput(plc.device("%IW0").expect("IW0")))
        .expect("release");
    plc.step_scan();
    assert_eq!(value(plc.as_ref(), "level"), 0);
}

#[test]
fn stop_holds_every_value_and_run_goes_on() {
    let mut plc = soft();
    plc.run_until(SimTime::from_millis(30));
    assert_eq!(plc.scans(), 3);
    plc.apply(Command::Run(false)).expect("stop");
    assert!(!plc.running());
    assert_eq!(plc.next_scan_end(), None);
    plc.run_until(SimTime::from_millis(200));
    assert_eq!((plc.scans(), plc.now()), (3, SimTime::from_millis(200)));
    assert_eq!(value(plc.as_ref(), "count"), 3);
    assert_eq!(plc.step_instruction(), None, "no step while stopped");
    plc.apply(Command::Run(true)).expect("run");
    plc.run_until(SimTime::from_millis(220));
    assert_eq!(value(plc.as_ref(), "count"), 5);
}

#[test]
fn a_scan_steps_one_instruction_at_a_time_and_is_traced() {
    let mut plc = soft();
    plc.set_tracing(true);
    let steps: Vec<Option<usize>> = (0..9).map(|_| plc.step_instruction()).collect();
    assert_eq!(steps, (0..9).map(Some).collect::<Vec<_>>());
    assert_eq!(plc.scans(), 1, "the ninth instruction ended the scan");
    let trace = plc.trace().expect("traced");
    assert_eq!(trace.ran.len(), 9);
    assert!(trace.ran.iter().all(|&r| r));
    // `LD count` read 0 (off); `ADD 1` left 1 (on).
    assert!(!trace.read[3] && trace.result[4]);
    // Mid-scan, a read shows what the last whole scan left: `count` is
    // stored by the sixth instruction, and shows at the scan's end.
    assert_eq!(value(plc.as_ref(), "count"), 1);
    for _ in 0..6 {
        plc.step_instruction();
    }
    assert_eq!(
        value(plc.as_ref(), "count"),
        1,
        "2 is stored, not yet shown"
    );
    for _ in 6..9 {
        plc.step_instruction();
    }
    assert_eq!(value(plc.as_ref(), "count"), 2);
}

#[test]
fn an_image_reads_back_as_the_machine_does() {
    let mut plc = soft();
    set(plc.as_mut(), "start", InputValue::Int(1));
    set(plc.as_mut(), "%IW0", InputValue::Int(-7));
    plc.run_until(SimTime::from_millis(80));
    let mut image = Vec::new();
    plc.image_into(&mut image);
    for name in [
        "start", "level", "lamp", "speed", "count", "delay", "delay.ET", "%QX0.1",
    ] {
        let d = plc.device(name).expect(name);
        assert_eq!(plc.read_image(&image, d), Some(plc.read(d)), "{name}");
    }
}

#[test]
fn the_scan_period_is_a_setting() {
    let mut plc = soft();
    let scan = |v: &str| Command::Setting {
        name: "scan".into(),
        value: v.into(),
    };
    plc.apply(scan("1ms")).expect("1 ms");
    plc.run_until(SimTime::from_millis(100));
    assert_eq!(value(plc.as_ref(), "count"), 100);
    for bad in ["0", "11s", "fast"] {
        assert!(plc.apply(scan(bad)).is_err(), "{bad}");
    }
    let e = plc
        .apply(Command::Setting {
            name: "T0".into(),
            value: "1s".into(),
        })
        .expect_err("unknown");
    assert_eq!(e.to_string(), "unknown setting \"T0\": soft-plc takes scan");
}

#[test]
fn the_listing_loads_back_to_itself() {
    for text in [
        PROGRAM,
        include_str!("../../programs/soft-plc/bench-256.il"),
        "VAR_RETAIN\n  x : LREAL;\nEND_VAR\n",
    ] {
        let mut plc = new_plc(MachineId::SoftPlc);
        if plc.load_text(text).is_err() {
            continue; // the third is refused: LREAL is no type here
        }
        let listing = plc.listing();
        let mut again = new_plc(MachineId::SoftPlc);
        again.load_text(&listing).expect("the listing loads");
        assert_eq!(again.listing(), listing);
    }
    let mut plc = soft();
    let bad = "PROGRAM p\n(* one\n two *)\nLD ghost\n";
    let e = plc.load_text(bad).expect_err("undeclared").to_string();
    assert!(
        e.starts_with("line 4: "),
        "the line number survives the comment: {e}"
    );
}
