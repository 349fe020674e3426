//! RESET and power: what they clear, and what the battery keeps.

use engine::minasec::{Command, Mode, TimerId};
use engine::SimTime;

use super::harness::{addr, apply, input, lamp, mode, program, running};

const LATCHES: &str = "LD X00\nST Y00\nST M00\nST M13\nST T1\nST C0\n";

#[test]
fn reset_clears_pc_acc_latches_and_images_only() {
    let mut m = running(LATCHES);
    apply(
        &mut m,
        Command::SetDelay(TimerId::T0, SimTime::from_millis(500)),
    );
    apply(&mut m, Command::SetCounterPreset(4, 2));
    apply(&mut m, Command::SetDip(0xA5));
    input(&mut m, 0, true);
    m.run_until(SimTime::from_millis(30));
    m.run_until(SimTime::from_nanos(30_000_000 + 33_000 * 7)); // mid-scan
    assert!(lamp(&m, 0) && m.read(addr("M13")) && m.timer(TimerId::T1).coil());
    assert_eq!(m.counter().count(), 1);
    let memory = *m.memory();

    mode(&mut m, Mode::Reset);
    assert_eq!((m.pc(), m.acc()), (0, false));
    assert_eq!(m.output_terminals(), 0);
    assert_eq!(m.input_image(), 0);
    for latch in ["Y00", "M00", "M13"] {
        assert!(!m.read(addr(latch)), "{latch} cleared");
    }
    assert!(!m.timer(TimerId::T1).coil(), "timer coils cleared");
    assert!(!m.counter().up_latch(), "counter inputs cleared");
    // Not cleared: memory, count, and the panel's switch positions.
    assert_eq!(m.memory(), &memory);
    assert_eq!(m.counter().count(), 1);
    assert_eq!(m.counter().set_value(), 42);
    assert_eq!(m.timer(TimerId::T0).delay(), SimTime::from_millis(500));
    assert_eq!(m.dip(), 0xA5);
    assert_eq!(m.input_terminals(), 1);

    // Held in reset, nothing runs.
    m.tick(SimTime::from_secs(1));
    assert_eq!(m.output_terminals(), 0);
    mode(&mut m, Mode::Run);
    m.tick(SimTime::from_millis(30));
    assert!(lamp(&m, 0), "runs again after RESET");
}

#[test]
fn power_off_keeps_program_and_count_and_power_on_resets() {
    let mut m = running(LATCHES);
    apply(&mut m, Command::SetCounterPreset(0, 9));
    input(&mut m, 0, true);
    m.run_until(SimTime::from_millis(30));
    let memory = *m.memory();
    apply(&mut m, Command::Power(false));
    let panel = m.panel();
    assert!(!panel.power && panel.lamps == 0 && panel.pc_leds == 0 && !panel.acc_led);
    m.tick(SimTime::from_secs(3600));
    let clocks_off = m.clocks();
    m.tick(SimTime::from_secs(1));
    assert_eq!(m.clocks(), clocks_off, "no clocks without power");
    apply(&mut m, Command::Power(true));
    assert_eq!(m.memory(), &memory, "program memory is battery-backed");
    assert_eq!(m.counter().count(), 1);
    assert_eq!(m.output_terminals(), 0, "power-on starts from reset");
    m.tick(SimTime::from_millis(30));
    assert!(lamp(&m, 0), "and the program runs again");
    assert_eq!(m.memory(), program(LATCHES).bytes());
}

#[test]
fn erased_memory_is_harmless() {
    let mut m = running("");
    input(&mut m, 0, true);
    m.tick(SimTime::from_secs(1));
    assert_eq!(m.output_terminals(), 0);
    assert!(m.acc(), "every step is LD X00");
    assert_eq!(m.memory(), &[0u8; 256]);
}
