//! A recording holds the plant: every recorded scan brings the plant back
//! exactly as it was, and each scan's image holds its quantities.

use engine::machines::MinasecPlc;
use engine::plant::{AnyPlant, Planted};
use engine::plc::{Command, Plc};
use engine::record::Recorded;
use engine::SimTime;

const CONVEYOR: &str = include_str!("../../programs/minasec-u/conveyor.il");
const NAMES: [&str; 5] = [
    "conveyor.placed",
    "conveyor.delivered",
    "conveyor.on_belt",
    "conveyor.motor",
    "Y00",
];

fn planted() -> Planted<MinasecPlc> {
    let mut m = MinasecPlc::new();
    m.load_text(CONVEYOR).unwrap();
    let setting = Command::Setting {
        name: "T1".into(),
        value: "1s".into(),
    };
    m.apply(setting).unwrap();
    let plant = AnyPlant::new("conveyor").unwrap();
    Planted::new(m, plant, None, Vec::new()).unwrap()
}

fn values(p: &dyn Plc) -> Vec<i64> {
    NAMES
        .iter()
        .map(|n| p.read(p.device(n).unwrap()).as_i64())
        .collect()
}

#[test]
fn a_recording_replays_the_plant_exactly() {
    let mut recorded = Recorded::new(planted());
    recorded.run_until(SimTime::from_secs(40));
    let live_end = values(&recorded);
    assert!(live_end[1] >= 5, "{live_end:?}");
    let last = recorded.recording().last();
    let delivered = recorded.device("conveyor.delivered").unwrap();
    let (recording, machine) = recorded.recording_and_machine();
    let from_images = recording.values(machine, delivered, 0, last);
    assert_eq!(from_images.len() as u64, last + 1);
    for mark in [1, 300, 1234, 2500, last - 1] {
        let t = recorded.recording_mut().time_at(mark).expect("kept");
        // The same machine and plant run plainly to that scan's end.
        let mut plain = planted();
        plain.run_until(t);
        assert!(recorded.show(mark), "mark {mark}");
        assert_eq!(values(&recorded), values(&plain), "mark {mark} at {t}");
        let image = from_images[mark as usize].clone().expect("in the image");
        assert_eq!(image.as_i64(), values(&plain)[1], "mark {mark}");
    }
    // The images' deliveries only ever go up, as the plant's do.
    let counts: Vec<i64> = from_images
        .iter()
        .map(|v| v.clone().unwrap().as_i64())
        .collect();
    assert!(counts.windows(2).all(|w| w[0] <= w[1]));
    assert_eq!(*counts.last().unwrap(), live_end[1]);
}

#[test]
fn a_recorded_machine_names_its_terminals_for_the_default_wiring() {
    // The page wires a plant to its recorded machine (issue #52): the
    // recording must pass the machine's terminals on, or the default
    // wiring is empty.
    let recorded = Recorded::new(MinasecPlc::new());
    let info = &engine::plant::conveyor::INFO;
    let (wired, left) = engine::plant::wiring::default_wiring(info, &recorded);
    let pairs: Vec<_> = wired
        .iter()
        .map(|w| format!("{},{}", w.signal, w.device))
        .collect();
    assert_eq!(pairs, ["infeed,X00", "outfeed,X01", "motor,Y00"]);
    assert!(left.is_empty());
}
