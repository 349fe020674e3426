//! Programming as on the board: erase with WRITE while running, then key
//! each step with the DIP switches, WRITE and CLOCK (プログラムの書き込み).

use engine::minasec::{Command, Machine, Mode, Program, SEED_TEST_PROGRAM};
use engine::SimTime;

use super::harness::{apply, clocks, mode, program};

/// Follows the book: erase all memory, then key `program` step by step.
fn key_in(m: &mut Machine, program: &Program) {
    // プログラムメモリの初期化: DIP all off, FAST, RUN, hold WRITE.
    apply(m, Command::SetDip(0));
    mode(m, Mode::Run);
    apply(m, Command::WriteButton(true));
    m.tick(SimTime::from_millis(20)); // more than one scan
    apply(m, Command::WriteButton(false));
    mode(m, Mode::Reset);
    mode(m, Mode::Halt);
    assert_eq!(m.memory(), &[0u8; 256], "memory erased");
    // プログラムの書き込み: DIP, WRITE, CLOCK for each step.
    for (address, step) in program.instructions().enumerate() {
        assert_eq!(usize::from(m.pc()), address, "the PC LEDs show the address");
        apply(m, Command::SetDip(step.encode()));
        apply(m, Command::WriteButton(true));
        apply(m, Command::WriteButton(false));
        assert_eq!(
            m.panel().instruction_leds,
            step.encode(),
            "the LEDs show the step"
        );
        clocks(m, 1);
    }
    mode(m, Mode::Reset);
}

#[test]
fn dip_write_clock_gives_the_same_memory_as_loading_the_text() {
    let seed = program(SEED_TEST_PROGRAM);
    let mut keyed = Machine::new();
    // Memory is undefined at first power-on: start from garbage.
    let mut garbage = [0u8; 256];
    for (i, b) in garbage.iter_mut().enumerate() {
        *b = (i as u8).wrapping_mul(97).wrapping_add(13);
    }
    keyed.load(&Program::from_bytes(garbage));
    key_in(&mut keyed, &seed);

    let mut loaded = Machine::new();
    loaded.load(&seed);
    assert_eq!(keyed.memory(), loaded.memory());
}

#[test]
fn a_keyed_program_runs_like_a_loaded_one() {
    let seed = program(SEED_TEST_PROGRAM);
    let mut keyed = Machine::new();
    key_in(&mut keyed, &seed);
    let mut loaded = Machine::new();
    loaded.load(&seed);
    for m in [&mut keyed, &mut loaded] {
        for command in [
            Command::SetDelay(engine::minasec::TimerId::T0, SimTime::from_millis(1100)),
            Command::SetCounterPreset(1, 0),
            Command::SetMode(Mode::Run),
            Command::SetInput(0, true),
        ] {
            apply(m, command);
        }
        m.tick(SimTime::from_secs(8));
    }
    assert_eq!(keyed.counter().count(), 4);
    assert_eq!(keyed.counter().count(), loaded.counter().count());
    assert_eq!(keyed.output_terminals(), loaded.output_terminals());
}

#[test]
fn while_write_is_held_the_cpu_executes_the_dip_value() {
    let mut m = Machine::new();
    apply(&mut m, Command::SetInput(0, true));
    clocks(&mut m, 256); // latch X00 = 1
    apply(&mut m, Command::SetDip(0b110_01000)); // ST Y00
    apply(&mut m, Command::WriteButton(true));
    assert_eq!(m.instruction().encode(), 0b110_01000);
    clocks(&mut m, 3); // writes steps 0..=3 with ST Y00
    apply(&mut m, Command::WriteButton(false));
    assert_eq!(&m.memory()[..4], &[0b110_01000; 4]);
    assert_eq!(m.memory()[4], 0);
}
