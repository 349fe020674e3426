use super::*;
use crate::machines::MinasecPlc;
use crate::plc::{Command, Plc};

const REFERENCE: &str = include_str!("../../programs/minasec-u/conveyor.il");

fn minasec(program: &str) -> MinasecPlc {
    let mut m = MinasecPlc::new();
    m.load_text(program).unwrap();
    let set = |name: &str, value: &str| Command::Setting {
        name: name.into(),
        value: value.into(),
    };
    m.apply(set("T1", "1s")).unwrap();
    m
}

fn conveyor(program: &str) -> Planted<MinasecPlc> {
    let plant = AnyPlant::new("conveyor").unwrap();
    Planted::new(minasec(program), plant, None, Vec::new()).unwrap()
}

fn read(p: &Planted<MinasecPlc>, name: &str) -> i64 {
    p.read(p.device(name).unwrap()).as_i64()
}

#[test]
fn the_reference_ladder_delivers_parts_with_no_alarm() {
    let mut p = conveyor(REFERENCE);
    p.run_until(SimTime::from_secs(60));
    let delivered = read(&p, "conveyor.delivered");
    assert!(delivered >= 4, "delivered {delivered}");
    assert_eq!(read(&p, "conveyor.alarms"), 0, "{:?}", p.alarm_log());
    assert!(read(&p, "conveyor.placed") > delivered);
}

#[test]
fn a_belt_started_by_the_infeed_at_once_raises_the_alarm_with_its_time() {
    let mut p = conveyor("LD X00\nOR Y00\nST Y00\n");
    p.run_until(SimTime::from_secs(5));
    assert_eq!(read(&p, "conveyor.alarms"), 1);
    let alarm = &p.alarm_log()[0];
    assert!(
        alarm.message.contains("ms after a part arrived"),
        "{}",
        alarm.message
    );
    // The part arrived at 239 ms (seed 1); a scan or two later the belt ran.
    let at = alarm.at.as_nanos() / 1_000_000;
    assert!((240..270).contains(&at), "at {at} ms");
    assert_eq!(read(&p, "conveyor.motor"), 1);
    assert_eq!(read(&p, "Y00"), 1);
}

#[test]
fn an_event_on_an_input_the_plant_drives_is_refused_naming_both() {
    let p = conveyor(REFERENCE);
    let x00 = p.device("X00").unwrap();
    let e = p
        .check_input(x00, InputValue::Int(1))
        .unwrap_err()
        .to_string();
    assert!(e.contains("X00") && e.contains("conveyor.infeed"), "{e}");
    let x02 = p.device("X02").unwrap();
    assert!(p.check_input(x02, InputValue::Int(1)).is_ok());
    let placed = p.device("conveyor.placed").unwrap();
    assert!(p.check_input(placed, InputValue::Int(1)).is_err());
    let e = p.device("conveyor.belt").unwrap_err().to_string();
    assert!(e.contains("\"belt\""), "{e}");
}

#[test]
fn a_signal_the_machine_cannot_carry_is_refused_naming_both() {
    let tank = || AnyPlant::new("tank").unwrap();
    let wiring = [WireEntry {
        signal: "level".into(),
        device: "X02".into(),
        line: 3,
    }];
    let e = Planted::new(minasec(""), tank(), Some(&wiring), Vec::new()).unwrap_err();
    assert_eq!(e[0].line, 3);
    assert!(
        e[0].error.contains("tank.level") && e[0].error.contains("minasec-u has no analog input"),
        "{}",
        e[0].error
    );
    // By default the level is simply not connected there.
    let p = Planted::new(minasec(""), tank(), None, Vec::new()).unwrap();
    assert_eq!(p.wires().len(), 4);
    let twice = [
        WireEntry {
            signal: "low".into(),
            device: "X00".into(),
            line: 1,
        },
        WireEntry {
            signal: "high".into(),
            device: "X00".into(),
            line: 2,
        },
        WireEntry {
            signal: "fill".into(),
            device: "X01".into(),
            line: 4,
        },
    ];
    let e = Planted::new(minasec(""), tank(), Some(&twice), Vec::new()).unwrap_err();
    assert_eq!(e.iter().map(|e| e.line).collect::<Vec<_>>(), [2, 4]);
    assert!(
        e[1].error.contains("tank.fill is an actuator"),
        "{}",
        e[1].error
    );
}

#[test]
fn faults_act_from_their_time() {
    let plant = AnyPlant::new("conveyor").unwrap();
    let info = plant.info();
    let faults = vec![
        Fault::parse("outfeed stuck 1 from 2s", info).unwrap(),
        Fault::parse("motor dead from 3s", info).unwrap(),
    ];
    let mut p = Planted::new(
        minasec("LD X01\nST Y01\nLD M00\nST Y00\n"),
        plant,
        None,
        faults,
    )
    .unwrap();
    p.run_until(SimTime::from_millis(1990));
    assert_eq!(read(&p, "Y01"), 0);
    p.run_until(SimTime::from_millis(2020));
    assert_eq!((read(&p, "Y01"), read(&p, "conveyor.outfeed")), (1, 1));
    // A stuck actuator acts whatever the PLC writes; a dead one does not.
    let plant = AnyPlant::new("conveyor").unwrap();
    let faults = vec![Fault::parse("motor stuck 1", plant.info()).unwrap()];
    let mut p = Planted::new(minasec(""), plant, None, faults).unwrap();
    p.run_until(SimTime::from_secs(20));
    assert!(read(&p, "conveyor.delivered") >= 1);
    assert_eq!(read(&p, "conveyor.motor"), 1);
    let plant = AnyPlant::new("conveyor").unwrap();
    let faults = vec![Fault::parse("motor dead", plant.info()).unwrap()];
    let mut p = Planted::new(minasec("LDI X07\nST Y00\n"), plant, None, faults).unwrap();
    p.run_until(SimTime::from_secs(20));
    assert_eq!((read(&p, "conveyor.delivered"), read(&p, "Y00")), (0, 1));
}

#[test]
fn parameters_are_set_by_name_and_checked() {
    let mut p = conveyor(REFERENCE);
    let set = |name: &str, value: &str| Command::Setting {
        name: name.into(),
        value: value.into(),
    };
    p.apply(set("conveyor.speed", "500")).unwrap();
    p.apply(set("conveyor.interval", "2.5s")).unwrap();
    assert_eq!(p.plant().params()[1..4], [500, 200, 2500]);
    let e = p.apply(set("conveyor.speed", "0")).unwrap_err().to_string();
    assert!(e.contains("out of range"), "{e}");
    let e = p.apply(set("conveyor.sped", "1")).unwrap_err().to_string();
    assert!(
        e.contains("no parameter \"sped\"") && e.contains("speed"),
        "{e}"
    );
    let e = p
        .apply(set("conveyor.part", "1500"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("half the belt"), "{e}");
    assert_eq!(p.plant().params()[2], 200, "refused: unchanged");
    // The machine's own settings still reach it.
    assert!(p.apply(set("T0", "1.1s")).is_ok());
}

#[test]
fn a_power_cycle_resets_the_plant_and_the_image_holds_its_state() {
    let mut p = conveyor(REFERENCE);
    p.run_until(SimTime::from_secs(30));
    let placed = read(&p, "conveyor.placed");
    assert!(placed > 1);
    let mut image = Vec::new();
    p.image_into(&mut image);
    let dev = p.device("conveyor.placed").unwrap();
    assert_eq!(p.read_image(&image, dev).unwrap().as_i64(), placed);
    let y00 = p.device("Y00").unwrap();
    assert_eq!(p.read_image(&image, y00), Some(p.read(y00)));
    p.apply(Command::PowerCycle).unwrap();
    assert_eq!(read(&p, "conveyor.placed"), 0);
    p.run_until(SimTime::from_secs(31));
    assert_eq!(read(&p, "conveyor.placed"), 1, "the schedule starts over");
}
