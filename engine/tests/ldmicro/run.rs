//! LDmicro files run on the soft PLC.

use engine::ladder::compile::{compile, Options};
use engine::ldmicro::{decode, parse, to_ladder};
use engine::machines::new_plc;
use engine::{MachineId, SimTime};

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/ldmicro");

#[test]
fn explore() {
    let Ok(dir) = std::fs::read_dir(REAL) else {
        return;
    };
    let mut names: Vec<String> = dir
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".ld"))
        .collect();
    names.sort();
    for name in names {
        let bytes = std::fs::read(format!("{REAL}/{name}")).unwrap();
        let file = parse(&decode(&bytes)).unwrap();
        match to_ladder(&file) {
            Err(e) => eprintln!("{name}: REFUSED {}: {}", e[0].line, e[0].error),
            Ok(ladder) => match compile(&ladder, MachineId::SoftPlc, Options::default()) {
                Err(e) => eprintln!(
                    "{name}: COMPILE {}",
                    e.iter()
                        .take(2)
                        .map(|x| x.to_string())
                        .collect::<Vec<_>>()
                        .join(" | ")
                ),
                Ok(text) => {
                    let mut plc = new_plc(MachineId::SoftPlc);
                    match plc.load_text(&text) {
                        Err(e) => eprintln!("{name}: LOAD {e}"),
                        Ok(()) => {
                            plc.run_until(SimTime::from_secs(2));
                            eprintln!("{name}: RUNS {} rungs", ladder.rungs.len());
                        }
                    }
                }
            },
        }
    }
}
