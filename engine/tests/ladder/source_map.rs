//! The compiler's source map (issue #14's groundwork): for random ladders
//! on every machine, each contact and in-line box of the drawing has the
//! line of the listing that reads its device or computes its output,
//! within its rung's steps.

use crate::differential::property;
use engine::ladder::compile::{compile_listing, Options};
use engine::ladder::{ContactKind, Element, Ladder};
use engine::MachineId;

/// How `device` appears in a line of `machine`'s listing.
fn spelled(machine: MachineId, device: &str) -> String {
    match machine {
        MachineId::AvrPlc => {
            let (r, b) = device
                .trim_start_matches('R')
                .split_once('.')
                .unwrap_or(("", ""));
            format!(",{r},Bit{b},")
        }
        _ => device.to_string(),
    }
}

fn check(machine: MachineId, ladder: &Ladder) -> Result<bool, String> {
    let Ok(listing) = compile_listing(ladder, machine, Options::default()) else {
        return Ok(false);
    };
    let lines: Vec<&str> = listing.text.lines().collect();
    for (i, rung) in ladder.rungs.iter().enumerate() {
        let steps = listing
            .steps_of(i)
            .ok_or(format!("rung {i} has no steps"))?;
        for (pos, e) in rung.elements() {
            if e.is_output() || *e == Element::Wire {
                continue;
            }
            let source = listing
                .sources
                .iter()
                .find(|s| s.rung == i && s.pos == pos)
                .ok_or(format!("rung {i} {pos:?} {e}: no source\n{}", listing.text))?;
            let step = listing
                .step_at_line(source.line)
                .ok_or(format!("rung {i} {pos:?}: line {} is no step", source.line))?;
            if !steps.contains(&step) {
                return Err(format!("rung {i} {pos:?}: step {step} outside {steps:?}"));
            }
            if let Element::Contact {
                kind: ContactKind::No | ContactKind::Nc,
                device,
            } = e
            {
                let line = lines[source.line];
                if !line.contains(&spelled(machine, device)) {
                    return Err(format!(
                        "rung {i} {pos:?} {e}: line {line:?} does not read it\n{}",
                        listing.text
                    ));
                }
            }
        }
    }
    Ok(true)
}

/// [`check`] on the ladder the generated logic draws.
fn check_drawn(
    machine: MachineId,
    rungs: &[engine::ladder::RungLogic],
    _: &[Vec<bool>],
) -> Result<bool, String> {
    check(machine, &Ladder::from_logic(rungs))
}

#[test]
fn every_leaf_has_its_line_on_every_machine() {
    for machine in MachineId::ALL {
        property(machine, 300, check_drawn);
    }
}

/// Step instruction walks a whole scan in listing order on every machine,
/// and each step it names is a step of the listing (so the page can point
/// at its element).
#[test]
fn step_instruction_walks_the_scan_in_listing_order() {
    use engine::ladder::{Element, Rung};
    use engine::machines::new_plc;
    use engine::plc::Command;
    let devices = |m: MachineId| match m {
        MachineId::MinasecU => ("X00", "X01", "Y00"),
        MachineId::Io86a => ("X00", "X01", "Y00"),
        MachineId::AvrPlc => ("R4.0", "R4.1", "R5.0"),
        MachineId::ArduinoPlc => ("X000", "X001", "Y000"),
        MachineId::SoftPlc => ("%IX0.0", "%IX0.1", "%QX0.0"),
    };
    for machine in MachineId::ALL {
        let (a, b, y) = devices(machine);
        let rung = Rung {
            cells: vec![
                vec![
                    Some(Element::no(a)),
                    Some(Element::nc(b)),
                    Some(Element::coil(y)),
                ],
                vec![Some(Element::no(y))],
            ],
            links: vec![engine::ladder::Link { row: 0, col: 1 }],
            ..Rung::default()
        };
        let ladder = Ladder {
            rungs: vec![rung.clone(), rung],
            ..Ladder::default()
        };
        let listing = compile_listing(&ladder, machine, Options::default()).expect("compiles");
        let mut plc = new_plc(machine);
        plc.load_text(&listing.text).expect("loads");
        let _ = plc.apply(Command::Run(true));
        // Finish the scan under way; the next step starts a scan.
        plc.step_scan();
        let mut steps = Vec::new();
        let scans = plc.scans();
        while plc.scans() == scans && steps.len() < 1000 {
            match plc.step_instruction() {
                Some(s) => steps.push(s),
                None => break,
            }
        }
        let program_steps = listing.step_lines.len();
        let in_listing: Vec<usize> = steps
            .iter()
            .copied()
            .filter(|&s| s < program_steps)
            .collect();
        assert_eq!(
            in_listing,
            (0..in_listing.len()).collect::<Vec<_>>(),
            "{machine}: {steps:?}"
        );
        assert!(
            in_listing.len() + 1 >= program_steps,
            "{machine}: {steps:?} of {program_steps}"
        );
        // The first step reads the first contact: the page outlines it.
        assert_eq!(
            listing.step_of_leaf(0, engine::ladder::Pos::new(0, 0)),
            Some(0)
        );
    }
}
