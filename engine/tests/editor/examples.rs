//! The example menu's programs open as ladders on their machine, and the
//! ladder compiles back to a program that runs like the example.

use engine::events::InputValue;
use engine::examples::EXAMPLES;
use engine::ladder::compile::{compile, Options};
use engine::ladder::decompile::decompile_text;
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::MachineId;
use engine::SimTime;

#[test]
fn every_example_opens_as_a_ladder_that_runs_like_its_text() {
    for ex in EXAMPLES {
        let what = format!("{} {}", ex.machine, ex.id);
        let ladder = decompile_text(ex.machine, ex.text, 10)
            .unwrap_or_else(|e| panic!("{what}: does not open as a ladder: {e}"));
        assert!(!ladder.rungs.is_empty(), "{what}: no rungs");
        let text = compile(&ladder, ex.machine, Options::default())
            .unwrap_or_else(|e| panic!("{what}: the ladder does not compile: {e:?}"));
        // Both programs, driven the same way, give the same device image.
        let mut original = new_plc(ex.machine);
        let mut redrawn = new_plc(ex.machine);
        original.load_text(ex.text).expect("the example loads");
        redrawn.load_text(&text).expect("the compiled ladder loads");
        for plc in [&mut original, &mut redrawn] {
            let _ = plc.apply(Command::Run(true));
        }
        // Every device a contact reads, pressed and released in turn.
        let mut inputs: Vec<String> = ladder
            .rungs
            .iter()
            .flat_map(|r| r.elements())
            .filter_map(|(_, e)| e.read_device().map(str::to_string))
            .collect();
        inputs.sort();
        inputs.dedup();
        let named: Vec<String> = ladder.variables.iter().map(|v| v.name.clone()).collect();
        let inputs: Vec<(String, bool)> = inputs
            .iter()
            .map(|d| (d.clone(), true))
            .chain(inputs.iter().map(|d| (d.clone(), false)))
            .collect();
        for (i, (input, on)) in inputs.iter().enumerate() {
            for plc in [&mut original, &mut redrawn] {
                if let Ok(device) = plc.device(input) {
                    let value = InputValue::Int(i64::from(*on));
                    let _ = plc.apply(Command::SetInput(device, value));
                }
                plc.run_until(SimTime::from_millis(2500 * (i as u64 + 1)));
            }
            let (mut a, mut b) = (Vec::new(), Vec::new());
            if ex.machine == MachineId::SoftPlc {
                // The compiler declares its variables in its own order:
                // the images' layouts differ, so compare by name.
                for name in &named {
                    let read = |plc: &dyn Plc| plc.device(name).ok().map(|d| plc.read(d));
                    a.push(read(original.as_ref()));
                    b.push(read(redrawn.as_ref()));
                }
                assert_eq!(a, b, "{what}: after {input} = {on}: {named:?}");
                continue;
            }
            let (mut a, mut b) = (Vec::new(), Vec::new());
            original.image_into(&mut a);
            redrawn.image_into(&mut b);
            assert_eq!(a, b, "{what}: after {input} = {on}");
        }
    }
}

#[test]
fn outputs_move_to_the_output_column_and_the_logic_stays() {
    use engine::ladder::edit::{align_outputs, COLUMNS};
    let seed = {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/programs/minasec-u/seed-test.json"
        ))
        .expect("seed");
        engine::formats::Project::from_json(&text)
            .expect("reads")
            .ladder
    };
    let ladders = EXAMPLES
        .iter()
        .map(|ex| {
            (
                ex.machine,
                decompile_text(ex.machine, ex.text, 10).expect("opens"),
            )
        })
        .chain([(engine::MachineId::MinasecU, seed)]);
    for (machine, ladder) in ladders {
        let aligned = align_outputs(&ladder, COLUMNS - 1);
        for (i, rung) in aligned.rungs.iter().enumerate() {
            for (pos, e) in rung.elements() {
                if e.is_output() {
                    assert_eq!(pos.col, COLUMNS - 1, "{machine} rung {i}: {e}");
                }
            }
        }
        let before = compile(&ladder, machine, Options::default()).expect("compiles");
        let after = compile(&aligned, machine, Options::default());
        assert_eq!(after.as_ref(), Ok(&before), "{machine}: {aligned:#?}");
        // Already aligned: nothing moves.
        assert_eq!(align_outputs(&aligned, COLUMNS - 1), aligned);
    }
}

#[test]
fn the_soft_plcs_parts_example_counts_scales_and_compares() {
    let ex = EXAMPLES
        .iter()
        .find(|e| e.machine == MachineId::SoftPlc && e.id == "parts")
        .expect("the example");
    let ladder = decompile_text(ex.machine, ex.text, 10).expect("opens");
    assert_eq!(ladder.rungs.len(), 3, "count, scale, compare: no rung lost");
    let text = compile(&ladder, ex.machine, Options::default()).expect("compiles");
    let mut plc = new_plc(ex.machine);
    plc.load_text(&text).expect("loads");
    let set = |plc: &mut Box<dyn Plc>, name: &str, v: i64| {
        let d = plc.device(name).expect(name);
        plc.apply(Command::SetInput(d, InputValue::Int(v)))
            .expect(name);
    };
    let read = |plc: &dyn Plc, name: &str| plc.read(plc.device(name).expect(name)).as_i64();
    set(&mut plc, "measure", 1);
    set(&mut plc, "level_in", 900);
    let mut t = 0;
    for n in 0..12 {
        set(&mut plc, "sensor", 1);
        t += 50;
        plc.run_until(SimTime::from_millis(t));
        set(&mut plc, "sensor", 0);
        t += 50;
        plc.run_until(SimTime::from_millis(t));
        assert_eq!(
            read(plc.as_ref(), "batch"),
            i64::from(n == 11),
            "after part {}",
            n + 1
        );
    }
    assert_eq!(read(plc.as_ref(), "parts"), 12);
    assert_eq!(
        (read(plc.as_ref(), "level"), read(plc.as_ref(), "high")),
        (90, 1),
        "900 ‰ is 90 %, above 80"
    );
    set(&mut plc, "level_in", 700);
    plc.run_until(SimTime::from_millis(t + 50));
    assert_eq!(
        (read(plc.as_ref(), "level"), read(plc.as_ref(), "high")),
        (70, 0)
    );
}

#[test]
fn a_soft_plc_rung_whose_box_drives_nothing_is_refused_not_dropped() {
    let parts = EXAMPLES
        .iter()
        .find(|e| e.machine == MachineId::SoftPlc && e.id == "parts")
        .expect("the example")
        .text;
    // The scale rung as the compiler writes it ends with `LD _p1` (its
    // power again: an output box); without it the DIV box drives nothing.
    let cut = parts.replacen("_skip0: LD _p1\nLD _p1\n", "_skip0: LD _p1\n", 1);
    assert_ne!(cut, parts);
    let err = decompile_text(MachineId::SoftPlc, &cut, 10)
        .expect_err("the DIV rung would be lost")
        .to_string();
    assert!(err.contains("a box and no output"), "{err}");
    // A box with nothing after it at the end of the text, too.
    let end = "VAR\n a : INT;\n b : INT;\nEND_VAR\nLD a\nGT INT#3\n";
    let err = decompile_text(MachineId::SoftPlc, end, 10).expect_err("GT alone");
    assert!(err.to_string().contains("no output"), "{err}");
}
