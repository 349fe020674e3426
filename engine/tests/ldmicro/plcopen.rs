//! LDmicro files out as PLCopen projects (issue #32): every real file
//! that runs goes out as a project OpenPLC Editor opens, and the soft PLC
//! runs that project — as written, and opened again as a ladder — as it
//! runs the file.

use engine::formats::ldmicro::{parse, to_ladder};
use engine::ladder::compile::{compile, Options};
use engine::machines::new_plc;
use engine::plc::Plc;
use engine::{MachineId, SimTime};

use crate::run::{real, set, REAL};

#[test]
fn every_real_file_that_runs_goes_out_as_plcopen_and_runs_the_same() {
    let Some(names) = crate::common::fixture_names(REAL, ".ld") else {
        return;
    };
    let mut same = 0;
    for name in &names {
        let file = parse(&real(name).expect("readable")).expect("reads");
        let Ok(ladder) = to_ladder(&file) else {
            continue;
        };
        let il = compile(&ladder, MachineId::SoftPlc, Options::default()).expect("compiles");
        let xml = engine::formats::plcopen::export(&ladder, "ld")
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let again = engine::formats::plcopen::Document::read(&xml)
            .and_then(|document| document.soft_program(None))
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        // Opened in the page, the project is a ladder again.
        let opened = engine::formats::plcopen::Document::read(&xml)
            .and_then(|document| document.import(Some(MachineId::SoftPlc), None, None))
            .map(|i| i.ladder)
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let redrawn = compile(&opened, MachineId::SoftPlc, Options::default())
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let mut plcs = [0, 1, 2].map(|_| new_plc(MachineId::SoftPlc));
        for (plc, text) in plcs.iter_mut().zip([&il, &again.text, &redrawn]) {
            plc.load_text(text)
                .unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        }
        // Every input on for a while, then off: each variable the same
        // on both after each scan.
        let inputs: Vec<&str> = ladder
            .variables
            .iter()
            .filter(|v| v.address.starts_with("%IX"))
            .map(|v| v.name.as_str())
            .collect();
        for scan in 1..=60u64 {
            for plc in &mut plcs {
                for input in &inputs {
                    set(plc.as_mut(), input, i64::from(scan / 20 == 1));
                }
                plc.run_until(SimTime::from_millis(10 * scan + 5));
            }
            for v in ladder.variables.iter().filter(|v| v.elementary().is_some()) {
                let read = |plc: &dyn Plc| plc.device(&v.name).map(|d| plc.read(d)).ok();
                for other in &plcs[1..] {
                    assert_eq!(
                        read(plcs[0].as_ref()),
                        read(other.as_ref()),
                        "{name}: {} at scan {scan}",
                        v.name
                    );
                }
            }
        }
        same += 1;
    }
    assert!(same >= 27 || names.is_empty(), "{same}");
}
