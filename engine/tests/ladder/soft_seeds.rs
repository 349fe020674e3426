//! The seed programs drawn as ladders behave the same on the soft PLC as
//! on their own machines (issue #30): each ladder with its devices given
//! soft PLC names (the inputs `%IX0.n`, the rest as written or, where the
//! machine's name is no IEC name, `R4_2` for `R4.2`), both machines run
//! with one scan period over the same inputs, the outputs compared.

use engine::events::InputValue;
use engine::formats::Project;
use engine::ladder::compile::{compile, Options};
use engine::ladder::{Element, Ladder};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

/// Each seed ladder that draws only what every machine has, its inputs.
const SEEDS: [(&str, &[&str]); 5] = [
    (
        include_str!("../../programs/arduino-plc/self-hold.json"),
        &["X000", "X001"],
    ),
    (
        include_str!("../../programs/avr-plc/self-hold.json"),
        &["R4.0", "R4.1", "R4.2"],
    ),
    (
        include_str!("../../programs/avr-plc/e-stop-timer.json"),
        &["R4.0", "R4.1"],
    ),
    (
        include_str!("../../programs/io86a/push-on-off.json"),
        &["X00"],
    ),
    (
        include_str!("../../programs/io86a/orb.json"),
        &["X00", "X01", "X02", "X03", "X04", "X05"],
    ),
];

/// The soft PLC's name for device `d` of a ladder whose inputs are
/// `inputs`.
fn soft_name(d: &str, inputs: &[&str]) -> String {
    match inputs.iter().position(|i| *i == d) {
        Some(n) => format!("%IX0.{n}"),
        None => d.replace('.', "_"),
    }
}

fn renamed(ladder: &Ladder, inputs: &[&str]) -> Ladder {
    let mut out = ladder.clone();
    for rung in &mut out.rungs {
        for cell in rung.cells.iter_mut().flatten().flatten() {
            match cell {
                Element::Contact { device, .. }
                | Element::Coil { device, .. }
                | Element::Pulse { device, .. } => *device = soft_name(device, inputs),
                _ => {}
            }
        }
    }
    out
}

/// Every device a coil or pulse drives.
fn outputs(ladder: &Ladder) -> Vec<String> {
    let mut out: Vec<String> = ladder
        .rungs
        .iter()
        .flat_map(|r| {
            r.elements()
                .filter_map(|(_, e)| e.written_device().map(str::to_string))
        })
        .collect();
    out.sort();
    out.dedup();
    out
}

/// A machine loaded with `text`, scanning every 10 ms where it can.
fn machine(id: MachineId, text: &str) -> Box<dyn Plc> {
    let mut plc = new_plc(id);
    let set = |plc: &mut Box<dyn Plc>, name: &str, value: &str| {
        plc.apply(Command::Setting {
            name: name.into(),
            value: value.into(),
        })
        .expect("setting");
    };
    match id {
        MachineId::Io86a => {
            set(&mut plc, "scan", "10ms");
            set(&mut plc, "filter", "0");
        }
        MachineId::AvrPlc | MachineId::SoftPlc => set(&mut plc, "scan", "10ms"),
        _ => {}
    }
    plc.load_text(text)
        .unwrap_or_else(|e| panic!("{id}: {e}\n{text}"));
    plc
}

#[test]
fn the_seed_ladders_run_alike_on_the_soft_plc() {
    let mut state = 0x2545_f491_u32;
    for (json, inputs) in SEEDS {
        let project = Project::from_json(json).expect("seed project");
        let own_text = compile(&project.ladder, project.machine, Options::default()).expect("own");
        let soft_ladder = renamed(&project.ladder, inputs);
        let soft_text =
            compile(&soft_ladder, MachineId::SoftPlc, Options::default()).expect("soft");
        let mut own = machine(project.machine, &own_text);
        let mut soft = machine(MachineId::SoftPlc, &soft_text);
        let watched = outputs(&project.ladder);
        // The AVR PLC's TOF is on for its set time after power-up (its
        // seed's warning); the soft PLC's is IEC's, off until its input
        // has been on: compared from the second second on.
        let tof = own_text.contains("TOF");
        for step in 0..60u64 {
            let t = SimTime::from_millis(100 * step);
            for (n, input) in inputs.iter().enumerate() {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                let on = i64::from(state.is_multiple_of(3));
                for (plc, name) in [
                    (&mut own, input.to_string()),
                    (&mut soft, format!("%IX0.{n}")),
                ] {
                    plc.run_until(t);
                    let d = plc.device(&name).expect("input");
                    plc.apply(Command::SetInput(d, InputValue::Int(on)))
                        .expect("on/off");
                }
            }
            let sample = t + SimTime::from_millis(95);
            own.run_until(sample);
            soft.run_until(sample);
            if tof && step < 11 {
                continue;
            }
            for d in &watched {
                let a = own.read(own.device(d).expect("own")).as_i64();
                let b = soft
                    .read(soft.device(&soft_name(d, inputs)).expect("soft"))
                    .as_i64();
                assert_eq!(a, b, "{} {d} at {sample}:\n{soft_text}", project.machine);
            }
        }
        if tof {
            // The difference, as documented.
            let (mut own, mut soft) = (
                machine(project.machine, &own_text),
                machine(MachineId::SoftPlc, &soft_text),
            );
            own.run_until(SimTime::from_millis(500));
            soft.run_until(SimTime::from_millis(500));
            let d = &watched[0];
            assert_eq!(own.read(own.device(d).expect("own")).as_i64(), 1);
            let soft_d = soft.device(&soft_name(d, inputs)).expect("soft");
            assert_eq!(soft.read(soft_d).as_i64(), 0);
        }
    }
}
