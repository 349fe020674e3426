//! LDmicro's elements as the soft PLC's blocks, scan by scan, against
//! what LDmicro's own code does (docs/ldmicro.md, "Elements").

use engine::events::InputValue;
use engine::machines::SoftPlc;
use engine::plc::{Command, Plc};
use engine::SimTime;

/// A soft PLC running `body` with `x` (%IX0.0) in, `y` (%QX0.0) out and
/// `n` a DINT, scanning every 10 ms.
fn plc(block: &str, body: &str) -> SoftPlc {
    let text = format!(
        "VAR\n  x AT %IX0.0 : BOOL;\n  y AT %QX0.0 : BOOL;\n  n : DINT;\n  b : {block};\nEND_VAR\n{body}\n"
    );
    let mut plc = SoftPlc::new();
    plc.load_text(&text)
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    plc
}

/// `y` and `n` after each scan, with `x` as `inputs` gives it scan by scan.
fn trace(plc: &mut SoftPlc, inputs: &[bool]) -> Vec<(bool, i64)> {
    let x = plc.device("x").expect("x");
    let (y, n) = (plc.device("y").expect("y"), plc.device("n").expect("n"));
    let mut out = Vec::new();
    for (k, &on) in inputs.iter().enumerate() {
        plc.apply(Command::SetInput(x, InputValue::Int(i64::from(on))))
            .expect("x");
        plc.run_until(SimTime::from_millis(10 * k as u64 + 15));
        out.push((plc.read(y).as_i64() == 1, plc.read(n).as_i64()));
    }
    out
}

const TIMER: &str = "CAL b(IN := x, P := 3, T := n, T => n, Q => y)";

#[test]
fn ton_turns_on_once_its_count_reaches_the_period_and_resets_with_its_input() {
    let mut p = plc("LD_TON", TIMER);
    let got = trace(&mut p, &[true, true, true, true, true, false, true]);
    assert_eq!(
        got,
        vec![
            (false, 1),
            (false, 2),
            (false, 3),
            (true, 3),
            (true, 3),
            (false, 0),
            (false, 1)
        ]
    );
}

#[test]
fn tof_starts_off_and_holds_on_for_its_period_after_the_input_falls() {
    let mut p = plc("LD_TOF", TIMER);
    let got = trace(&mut p, &[false, true, false, false, false, false]);
    assert_eq!(
        got,
        vec![
            (false, 3),
            (true, 0),
            (true, 1),
            (true, 2),
            (true, 3),
            (false, 3)
        ]
    );
}

#[test]
fn rto_keeps_its_count_while_off() {
    let mut p = plc("LD_RTO", TIMER);
    let got = trace(&mut p, &[true, true, false, true, true]);
    assert_eq!(
        got,
        vec![(false, 1), (false, 2), (false, 2), (false, 3), (true, 3)]
    );
}

#[test]
fn tcy_pulses_its_output_every_period_while_on() {
    let mut p = plc("LD_TCY", "CAL b(IN := x, P := 1, T := n, T => n, Q => y)");
    let got: Vec<bool> = trace(&mut p, &[true; 8])
        .into_iter()
        .map(|(q, _)| q)
        .collect();
    assert_eq!(
        got,
        vec![false, true, true, false, false, true, true, false]
    );
}

const COUNTER: &str = "CAL b(IN := x, MAX := 2, INIT := 0, C := n, C => n, Q => y)";

#[test]
fn ctu_counts_rises_up_to_its_limit_and_is_on_there() {
    let mut p = plc("LD_CTU", COUNTER);
    let got = trace(&mut p, &[true, true, false, true, false, true, false]);
    assert_eq!(
        got,
        vec![
            (false, 1),
            (false, 1),
            (false, 1),
            (true, 2),
            (true, 2),
            (true, 2),
            (true, 2)
        ]
    );
}

#[test]
fn ctc_wraps_to_its_start_past_its_limit_with_a_one_scan_pulse() {
    let mut p = plc("LD_CTC", COUNTER);
    let rises = [true, false, true, false, true, false, true];
    let got = trace(&mut p, &rises);
    assert_eq!(
        got,
        vec![
            (false, 1),
            (false, 1),
            (false, 2),
            (false, 2),
            (true, 0),
            (false, 0),
            (false, 1)
        ]
    );
}

#[test]
fn a_falling_input_counts_where_the_file_says_so() {
    let mut p = plc(
        "LD_CTU",
        "CAL b(IN := x, MAX := 5, INIT := 0, C := n, C => n, EDGE := 1, Q => y)",
    );
    let got: Vec<i64> = trace(&mut p, &[true, false, true, false])
        .into_iter()
        .map(|(_, n)| n)
        .collect();
    assert_eq!(got, vec![0, 1, 1, 2]);
}

#[test]
fn osc_passes_every_other_scan() {
    let mut p = plc("LD_OSC", "CAL b(IN := x, Q => y)");
    let got: Vec<bool> = trace(&mut p, &[true, true, true, true, false])
        .into_iter()
        .map(|(q, _)| q)
        .collect();
    assert_eq!(got, vec![true, false, true, false, false]);
}
