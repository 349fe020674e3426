//! The one machine interface: the same tests, through [`Plc`] only, on
//! all five machines (docs/architecture.md).

use engine::events::InputValue;
use engine::io86a::LoadLinked;
use engine::machines::new_plc;
use engine::plc::{Command, Own, Plc, PlcError, SettingError, Warning, MAX_TICK};
use engine::{MachineId, SimTime};

mod record;
mod soft;

/// A program in each machine's own text that copies one input to one
/// output, and the two devices' names.
fn copy_program(id: MachineId) -> (&'static str, &'static str, &'static str) {
    match id {
        MachineId::MinasecU => ("LD X00\nST Y00\n", "X00", "Y00"),
        MachineId::Io86a => ("LD X00\nOUT Y00\nEND\n", "X00", "Y00"),
        MachineId::ArduinoPlc => ("LD X000\nOUT Y000\nEND\n", "X000", "Y000"),
        MachineId::AvrPlc => (
            ".db Load_A,4,Bit0,0\n.db Coil_A,5,Bit0,0\n.db End_PLC,0,0,0\n",
            "R4.0",
            "R5.0",
        ),
        MachineId::SoftPlc => ("LD %IX0.0\nST %QX0.0\n", "%IX0.0", "%QX0.0"),
    }
}

/// Instructions in [`copy_program`] that one scan executes.
fn steps_per_scan(id: MachineId) -> usize {
    match id {
        MachineId::MinasecU => 256,
        MachineId::AvrPlc => 3, // End_PLC is a record too
        MachineId::SoftPlc => 2,
        _ => 3,
    }
}

fn loaded(id: MachineId) -> Box<dyn Plc> {
    let mut plc = new_plc(id);
    let (text, _, _) = copy_program(id);
    plc.load_text(text).unwrap_or_else(|e| panic!("{id}: {e}"));
    plc
}

fn set(plc: &mut dyn Plc, name: &str, on: bool) {
    let d = plc.device(name).expect("input");
    plc.apply(Command::SetInput(d, InputValue::Int(i64::from(on))))
        .expect("input takes 0/1");
}

fn read(plc: &dyn Plc, name: &str) -> i64 {
    plc.read(plc.device(name).expect("device")).as_i64()
}

/// Enough time and scans for an input to reach an output on every
/// machine: the IO86A's input filter holds a change for 20 ms after
/// power-on; MINASEC-U latches inputs at one scan boundary and shows
/// outputs at the next.
fn settle(plc: &mut dyn Plc) {
    plc.run_until(plc.now() + SimTime::from_millis(50));
    for _ in 0..3 {
        plc.step_scan();
    }
}

#[test]
fn every_machine_copies_an_input_to_an_output() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        assert_eq!(plc.id(), id);
        let (_, input, output) = copy_program(id);
        settle(plc.as_mut());
        assert_eq!(read(plc.as_ref(), output), 0, "{id}");
        set(plc.as_mut(), input, true);
        settle(plc.as_mut());
        assert_eq!(read(plc.as_ref(), output), 1, "{id}");
        set(plc.as_mut(), input, false);
        settle(plc.as_mut());
        assert_eq!(read(plc.as_ref(), output), 0, "{id}");
    }
}

#[test]
fn a_bad_program_is_refused_and_the_old_one_keeps_running() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        let listing = plc.listing();
        let (_, input, output) = copy_program(id);
        match plc.load_text("BOGUS X99\n") {
            Err(PlcError::Program(problems)) => {
                assert!(!problems.is_empty(), "{id}");
                assert_eq!(problems[0].line, 1, "{id}: {problems:?}");
            }
            other => panic!("{id}: {other:?}"),
        }
        assert_eq!(plc.listing(), listing, "{id}: the program did not change");
        set(plc.as_mut(), input, true);
        settle(plc.as_mut());
        assert_eq!(
            read(plc.as_ref(), output),
            1,
            "{id} still runs the old program"
        );
    }
}

#[test]
fn step_scan_runs_exactly_one_scan() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        settle(plc.as_mut());
        let (scans, t) = (plc.scans(), plc.now());
        plc.step_scan();
        assert_eq!(plc.scans(), scans + 1, "{id}");
        assert!(plc.now() > t, "{id}: time moves on");
    }
}

#[test]
fn step_instruction_walks_the_scan_in_listing_order() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        settle(plc.as_mut());
        let (_, input, output) = copy_program(id);
        set(plc.as_mut(), input, true);
        // Past the IO86A's input filter, then to a scan boundary.
        plc.run_until(plc.now() + SimTime::from_millis(50));
        plc.step_scan();
        let scans = plc.scans();
        let mut walked = Vec::new();
        while plc.scans() == scans {
            let step = plc
                .step_instruction()
                .unwrap_or_else(|| panic!("{id} runs"));
            walked.push(step);
            assert!(walked.len() <= 300, "{id}: the scan never ends");
        }
        let n = steps_per_scan(id);
        assert_eq!(walked, (0..n).collect::<Vec<_>>(), "{id}");
        if id != MachineId::MinasecU {
            // Scan machines show the result at the end of the stepped scan.
            assert_eq!(read(plc.as_ref(), output), 1, "{id}");
        }
    }
}

#[test]
fn only_minasec_has_a_clock_edge_to_step() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        let t = plc.now();
        let stepped = plc.step_clock();
        assert_eq!(stepped, id == MachineId::MinasecU, "{id}");
        if stepped {
            assert!(plc.now() > t);
        }
    }
}

#[test]
fn the_device_image_follows_the_devices() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        let (_, input, _) = copy_program(id);
        let mut before = vec![0xAA; 3]; // reused: its old contents go
        settle(plc.as_mut());
        plc.image_into(&mut before);
        assert!(!before.is_empty() && before != [0xAA; 3], "{id}");
        set(plc.as_mut(), input, true);
        settle(plc.as_mut());
        let mut after = Vec::new();
        plc.image_into(&mut after);
        assert_eq!(before.len(), after.len(), "{id}: one layout");
        assert_ne!(before, after, "{id}: the image changed with the devices");
    }
}

#[test]
fn warnings_come_from_the_engine() {
    let mut avr = new_plc(MachineId::AvrPlc);
    avr.load_text(
        ".dseg\nPLC_Timer_Top:\nT: .byte 2\n.cseg\n.db Load_A,4,Bit0,0\n.db TOF,LOW(T),LOW(100),HIGH(100)\n.db Coil_A,5,Bit0,0\n.db End_PLC,0,0,0\n",
    )
    .expect("loads");
    assert_eq!(avr.warnings(), [Warning::TofOnAtPowerUp]);
    let mut arduino = new_plc(MachineId::ArduinoPlc);
    arduino.load_text("LD X000\nOUT Y000\n").expect("loads");
    assert_eq!(arduino.warnings(), [Warning::RunsIntoErasedEeprom]);
    for id in MachineId::ALL {
        assert_eq!(loaded(id).warnings(), [], "{id}");
    }
}

#[test]
fn settings_are_listed_and_unknown_ones_refused() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        let settings = plc.settings();
        assert!(!settings.is_empty(), "{id}");
        let bogus = Command::Setting {
            name: "bogus".into(),
            value: "1".into(),
        };
        match plc.apply(bogus) {
            Err(PlcError::Setting(SettingError::Unknown { machine, takes, .. })) => {
                assert_eq!(machine, id);
                assert!(takes.contains(settings[0].name), "{id}: {takes}");
            }
            other => panic!("{id}: {other:?}"),
        }
    }
}

#[test]
fn power_cycle_clears_outputs_and_keeps_the_program() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        let (_, input, output) = copy_program(id);
        set(plc.as_mut(), input, true);
        settle(plc.as_mut());
        assert_eq!(read(plc.as_ref(), output), 1, "{id}");
        let listing = plc.listing();
        plc.apply(Command::PowerCycle).expect("power cycle");
        assert_eq!(plc.listing(), listing, "{id}");
        // The input is still driven: the output comes back.
        settle(plc.as_mut());
        assert_eq!(read(plc.as_ref(), output), 1, "{id}");
    }
}

#[test]
fn tick_is_capped() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        plc.tick(SimTime::from_secs(3600));
        assert_eq!(plc.now(), MAX_TICK, "{id}");
    }
}

#[test]
fn inputs_are_checked_against_the_machine() {
    for id in MachineId::ALL {
        let plc = loaded(id);
        let (_, input, output) = copy_program(id);
        let i = plc.device(input).expect("input");
        assert!(plc.check_input(i, InputValue::Int(2)).is_err(), "{id}");
        assert!(plc.check_input(i, InputValue::Int(1)).is_ok(), "{id}");
        if !matches!(id, MachineId::AvrPlc | MachineId::SoftPlc) {
            // AVR bits are inputs as soon as something drives them; the
            // soft PLC's events write any variable (as OpenPLC's monitor).
            let o = plc.device(output).expect("output");
            assert!(plc.check_input(o, InputValue::Int(1)).is_err(), "{id}");
        }
        assert!(
            matches!(plc.device("Q99"), Err(PlcError::Device(_))),
            "{id}"
        );
    }
}

#[test]
fn the_io86a_takes_a_linked_second_device() {
    let mut plc = new_plc(MachineId::Io86a);
    plc.load_text("LD X00\nSETS Y01\nLD X01\nRSTS Y01\nEND\n")
        .expect("A");
    plc.apply(Command::Own(Own::new(LoadLinked(
        "LD Y01\nOUT Y02\nEND\n".into(),
    ))))
    .expect("B");
    set(plc.as_mut(), "X00", true);
    settle(plc.as_mut());
    assert_eq!(read(plc.as_ref(), "B.Y01"), 1, "A's SETS reached B");
    assert_eq!(read(plc.as_ref(), "B.Y02"), 1, "B runs its own program");
    assert_eq!(read(plc.as_ref(), "Y01"), 0, "A's own Y01 is untouched");
    set(plc.as_mut(), "X00", false);
    set(plc.as_mut(), "X01", true);
    settle(plc.as_mut());
    assert_eq!(read(plc.as_ref(), "B.Y02"), 0);
    // B's inputs are its own.
    set(plc.as_mut(), "B.X03", true);
    settle(plc.as_mut());
    let mut front = engine::plc::Front::none();
    plc.front_into(&mut front);
    match front.get::<engine::io86a::Fronts>() {
        Some([a, b]) => {
            assert_eq!(b.inputs, 1 << 3);
            assert_eq!(a.inputs, 1 << 1);
        }
        None => panic!("{front:?}"),
    }
    assert!(matches!(
        plc.apply(Command::Own(Own::new(LoadLinked("BOGUS\n".into())))),
        Err(PlcError::Program(_))
    ));
    // Another machine's own command is refused by name.
    let panel = Command::Own(Own::new(engine::minasec::Command::SetDip(5)));
    assert_eq!(
        plc.apply(panel).map_err(|e| e.to_string()),
        Err("io86a has no MINASEC-U front panel (SetDip(5))".to_string())
    );
}

#[test]
fn running_and_fronts() {
    for id in MachineId::ALL {
        let mut plc = loaded(id);
        assert!(
            plc.running(),
            "{id} runs after power-up (as the CLI starts it)"
        );
        let mut front = engine::plc::Front::none();
        plc.front_into(&mut front);
        let expected = match id {
            MachineId::MinasecU => front.get::<engine::minasec::Panel>().is_some(),
            MachineId::Io86a => front.get::<engine::io86a::Fronts>().is_some(),
            _ => front.is_none(),
        };
        assert!(expected, "{id}: {front:?}");
        if id != MachineId::AvrPlc {
            plc.apply(Command::Run(false)).expect("stop");
            assert!(!plc.running(), "{id}");
        }
    }
}
