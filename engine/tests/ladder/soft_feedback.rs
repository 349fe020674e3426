//! A drawn wire loop through an `inOutVariable` on the soft PLC (issue
//! #54): the loop is broken at the variable's readers, so the variable
//! is read after it is written wherever that can be. Beremiz's first
//! example's counter (`Cnt := SEL(Reset, ADD(1, Cnt), 17); Out := Cnt`)
//! drawn our own way in FBD and in LD (`fixtures/soft-feedback.xml`,
//! drawn so that top to bottom would run it wrong) counts with its ST
//! twin, scan for scan.

use engine::events::InputValue;
use engine::formats::plcopen::Document;
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

const OWN: &str = include_str!("fixtures/soft-feedback.xml");

fn soft(xml: &str) -> Box<dyn Plc> {
    let program = Document::read(xml)
        .and_then(|document| document.soft_program(None))
        .unwrap_or_else(|e| panic!("{e:?}"));
    let mut plc = new_plc(MachineId::SoftPlc);
    plc.load_text(&program.text)
        .unwrap_or_else(|e| panic!("{e}\n{}", program.text));
    plc
}

fn get(plc: &dyn Plc, device: &str) -> i64 {
    plc.read(plc.device(device).expect(device)).as_i64()
}

/// Makes one more scan.
fn scan(plc: &mut dyn Plc) {
    let goal = plc.scans() + 1;
    let mut t = plc.now();
    while plc.scans() < goal {
        t = t.saturating_add(SimTime::from_millis(1));
        plc.run_until(t);
    }
}

/// The three counters' outputs after a scan: FBD, LD, ST.
fn outs(plc: &dyn Plc) -> [i64; 3] {
    ["fbd", "ld", "st"].map(|c| get(plc, c))
}

#[test]
fn a_drawn_counter_through_an_in_out_variable_counts_with_its_st_twin() {
    let mut plc = soft(OWN);
    // Each scan: ADD reads Cnt as the last scan left it (the loop's one
    // read before the write), SEL gives ADD's sum while Reset is off,
    // the inOutVariable writes it to Cnt, and Out reads Cnt after that:
    // scan n gives n, as `Cnt := Cnt + 1; Out := Cnt` does. (Broken at
    // the drawing's first element, Out, Out read 0, 0, 1, 2: two behind.)
    for n in 1..=4 {
        scan(plc.as_mut());
        assert_eq!(outs(plc.as_ref()), [n; 3], "scan {n}");
    }
    // Reset on: SEL gives 17 to Cnt and Out in the same scan, each scan.
    let reset = plc.device("reset").expect("reset");
    plc.apply(Command::SetInput(reset, InputValue::Int(1)))
        .expect("input");
    for _ in 0..2 {
        scan(plc.as_mut());
        assert_eq!(outs(plc.as_ref()), [17; 3]);
    }
    // Off again: 18, then 19.
    plc.apply(Command::SetInput(reset, InputValue::Int(0)))
        .expect("input");
    for n in 18..=19 {
        scan(plc.as_mut());
        assert_eq!(outs(plc.as_ref()), [n; 3]);
    }
}
