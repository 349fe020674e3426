//! The Arduino PLC sketch: the seed's examples, its quirks, the monitor.

#[path = "../common/mod.rs"]
mod common;

mod cli;

use engine::arduino::{monitor, Chip, Machine, PopOrder, Program};
use engine::SimTime;

fn machine(text: &str) -> Machine {
    let program = Program::parse(text, 512).unwrap_or_else(|e| panic!("{e:?}"));
    let mut m = Machine::new(&program, Chip::Atmega328);
    m.set_enabled(true);
    m
}

fn us(n: u64) -> SimTime {
    SimTime::from_micros(n)
}

fn y(m: &Machine, n: u8) -> bool {
    m.outputs() >> n & 1 != 0
}

/// Sets an input and runs 1 ms (100 steps).
fn input(m: &mut Machine, n: u8, on: bool) {
    m.set_input(n, on);
    let t = m.now() + SimTime::from_millis(1);
    m.run_until(t);
}

#[test]
fn the_seeds_self_hold_with_jump_0() {
    let mut m = machine("0 LD X000\n1 OR Y000\n2 ANDN X001\n3 OUT Y000\n4 JUMP 0\n");
    input(&mut m, 0, false);
    assert!(!y(&m, 0));
    input(&mut m, 0, true);
    assert!(y(&m, 0));
    input(&mut m, 0, false);
    assert!(y(&m, 0), "holds itself");
    input(&mut m, 1, true);
    assert!(!y(&m, 0), "X001 breaks the hold");
    input(&mut m, 1, false);
    assert!(!y(&m, 0));
}

#[test]
fn the_seeds_block_form_with_orb() {
    // LD X000 / LD Y000 / ANDN X002 / ORB / ANDN X001 / OUT Y000, then END.
    let mut m = machine("LD X000\nLD Y000\nANDN X002\nORB\nANDN X001\nOUT Y000\nEND\n");
    let mut hold = false;
    for bits in [
        0b000u8, 0b001, 0b000, 0b100, 0b001, 0b010, 0b000, 0b001, 0b000,
    ] {
        for n in 0..3 {
            m.set_input(n, bits >> n & 1 != 0);
        }
        let t = m.now() + SimTime::from_millis(1);
        m.run_until(t);
        let x = |n: u8| bits >> n & 1 != 0;
        hold = (x(0) || (hold && !x(2))) && !x(1);
        assert_eq!(y(&m, 0), hold, "inputs {bits:03b}");
    }
}

#[test]
fn inputs_are_read_as_each_step_runs_and_outputs_change_at_once() {
    let mut m = machine("LD X000\nOUT Y000\nLD X000\nOUT Y001\nEND\n");
    // Steps run at 10, 20, 30, 40, 50 µs: X000 rises between the two LDs.
    m.run_until(us(25));
    m.set_input(0, true);
    m.run_until(us(40));
    assert!(!y(&m, 0), "the first LD saw X000 off");
    assert!(y(&m, 1), "the second LD, a step later, saw it on");
}

#[test]
fn a_program_without_end_runs_into_erased_steps_and_spins_at_255() {
    let mut m = machine("LD X000\nOUT Y000\n");
    m.set_input(0, true);
    m.run_until(us(25));
    assert!(y(&m, 0), "the two steps ran once");
    m.run_until(SimTime::from_millis(10));
    assert_eq!(m.pc(), 255, "JUMP 255 at step 255, for ever");
    m.set_input(0, false);
    m.run_until(SimTime::from_millis(20));
    assert!(y(&m, 0), "nothing runs the program again");
}

#[test]
fn the_sketch_pop_order_is_an_opt_in_quirk() {
    let text = "LD X000\nOUT Y000\nEND\n";
    let mut intended = machine(text);
    let mut sketch = machine(text);
    sketch.set_pop_order(PopOrder::Sketch);
    for m in [&mut intended, &mut sketch] {
        input(m, 0, true);
    }
    assert!(y(&intended, 0), "OUT takes the top: X000");
    assert!(
        !y(&sketch, 0),
        "the sketch's pop returns the bit under the top"
    );
}

#[test]
fn the_stack_is_sixteen_bits_deep() {
    let ors = |n: usize| "ORB\n".repeat(n);
    let lds = |n: usize| "LD X001\n".repeat(n);
    let deep = |pushes: usize| {
        format!(
            "LD X000\n{}{}OUT Y000\nEND\n",
            lds(pushes - 1),
            ors(pushes - 1)
        )
    };
    let mut sixteen = machine(&deep(16));
    input(&mut sixteen, 0, true);
    assert!(y(&sixteen, 0), "16 values fit: the first is still there");
    let mut seventeen = machine(&deep(17));
    input(&mut seventeen, 0, true);
    assert!(!y(&seventeen, 0), "the 17th push shifts the first out");
}

#[test]
fn monitor_commands() {
    let program = Program::parse(
        "0 LD X000\n1 OR Y000\n2 ANDN X001\n3 OUT Y000\n4 JUMP 0\n",
        512,
    )
    .unwrap();
    let mut m = Machine::new(&program, Chip::Atmega328);
    assert!(!m.enabled(), "disabled after power-up");
    let help = monitor::type_line(&mut m, "?");
    assert_eq!(
        help,
        "\r\n? help\r\ns assemble\r\nl disassemble\r\np show PLC code with hexadecimal format\r\ne enable PLC handling\r\nd disable PLC handling\r\n"
    );
    assert_eq!(
        monitor::type_line(&mut m, "l"),
        "\r\nLD X000\r\nOR Y000\r\nANDN X001\r\nOUT Y000\r\nJUMP 000\r\n"
    );
    let dump = monitor::type_line(&mut m, "p");
    let lines: Vec<&str> = dump.split("\r\n").collect();
    assert_eq!(
        lines.len(),
        18,
        "a blank line, 16 lines of 16 words, and the end"
    );
    assert_eq!(
        lines[1],
        "2000 6008 5001 1008 F000 FFFF FFFF FFFF FFFF FFFF FFFF FFFF FFFF FFFF FFFF FFFF "
    );
    assert_eq!(monitor::type_line(&mut m, "s5 end"), "\r\n");
    assert_eq!(m.eeprom()[5], 0x0000);
    assert_eq!(monitor::type_line(&mut m, "s6 or y003"), "\r\n");
    assert_eq!(m.eeprom()[6], 0x600B);
    assert_eq!(
        monitor::type_line(&mut m, "s7 OUT X000"),
        "\r\nERR OUT X000: outputs are Y000-Y005\r\n"
    );
    assert_eq!(monitor::type_line(&mut m, "e"), "\r\n");
    assert!(m.enabled());
    monitor::type_line(&mut m, "d");
    assert!(!m.enabled());
}

#[test]
fn chips_hold_256_or_512_steps() {
    let program = Program::parse("300 END\n", 512).unwrap();
    let mut m = Machine::new(&program, Chip::Atmega328);
    assert_eq!(m.eeprom().len(), 512);
    assert!(m
        .apply_setting("chip", "168")
        .unwrap_err()
        .to_string()
        .contains("step 300"));
    let mut small = Machine::new(&Program::parse("END\n", 512).unwrap(), Chip::Atmega328);
    assert_eq!(small.apply_setting("chip", "168"), Ok(()));
    assert_eq!(small.eeprom().len(), 256);
}
