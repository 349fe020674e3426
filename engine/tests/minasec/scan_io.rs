//! Scan-boundary I/O: inputs latched and outputs driven only at the PC
//! wrap; output latches read back at once; 256 steps every scan.

use engine::minasec::{Command, Mode};

use super::harness::{addr, apply, clocks, halted, input, lamp, mode};

const ECHO: &str = "LD X00\nST Y00\nLD Y00\nST M00\n";

#[test]
fn an_input_change_mid_scan_is_seen_only_next_scan() {
    let mut m = halted(ECHO);
    input(&mut m, 0, true);
    clocks(&mut m, 2); // steps 0-1 of scan 0: the image is still 0
    assert!(!m.read(addr("Y00")), "the image was cleared at power-on");
    clocks(&mut m, 254);
    assert_eq!(m.pc(), 0);
    assert_eq!(m.input_image(), 1, "latched at the wrap");

    // A change mid-scan is not seen until the next wrap.
    clocks(&mut m, 100);
    input(&mut m, 0, false);
    clocks(&mut m, 156);
    assert!(m.read(addr("Y00")), "scan 1 still saw X00 = 1");
    clocks(&mut m, 2);
    assert!(!m.read(addr("Y00")), "scan 2 sees X00 = 0");
}

#[test]
fn outputs_change_only_at_the_boundary_but_read_back_at_once() {
    let mut m = halted(ECHO);
    input(&mut m, 0, true);
    clocks(&mut m, 256); // scan 0 latches X00 = 1 at its end
    clocks(&mut m, 2); // LD X00, ST Y00
    assert!(m.read(addr("Y00")), "the Y00 latch is set");
    assert!(!lamp(&m, 0), "the Y00 terminal waits for the boundary");
    clocks(&mut m, 2); // LD Y00, ST M00
    assert!(m.read(addr("M00")), "Y00 read back in the same scan");
    clocks(&mut m, 251);
    assert!(!lamp(&m, 0), "still before the wrap at step 255");
    clocks(&mut m, 1);
    assert!(lamp(&m, 0), "the terminal follows at the wrap");
}

#[test]
fn every_scan_runs_all_256_steps_and_erased_steps_act_as_ld_x00() {
    let mut m = halted("LDI X00\n");
    input(&mut m, 0, true);
    clocks(&mut m, 256);
    assert_eq!(m.scans(), 1);
    assert_eq!(m.clocks(), 256);
    clocks(&mut m, 1);
    assert!(!m.acc(), "LDI X00 with X00 on");
    clocks(&mut m, 1);
    assert!(m.acc(), "erased step 1 is LD X00");
    clocks(&mut m, 254);
    assert_eq!((m.pc(), m.scans()), (0, 2), "the PC wraps after step 255");
    assert!(m.acc());
}

#[test]
fn a_store_at_step_255_lands_before_the_wrap() {
    // Steps 1..=254 are erased (LD X00), so A holds X00 at step 255.
    let mut m = halted("LDI X00\n255 ST Y07\n");
    input(&mut m, 0, true);
    clocks(&mut m, 512);
    assert!(lamp(&m, 7));
}

#[test]
fn halt_stops_the_clock_and_run_resumes_it() {
    let mut m = halted(ECHO);
    input(&mut m, 0, true);
    m.tick(engine::SimTime::from_secs(1));
    assert_eq!(m.clocks(), 0, "HALT: no clocks without the button");
    mode(&mut m, Mode::Run);
    m.tick(engine::SimTime::from_millis(20));
    assert!(lamp(&m, 0));
    mode(&mut m, Mode::Halt);
    let clocks_at_halt = m.clocks();
    m.tick(engine::SimTime::from_secs(1));
    assert_eq!(m.clocks(), clocks_at_halt);
    // CLOCK does nothing at RUN (the oscillator drives the line).
    mode(&mut m, Mode::Run);
    let before = m.clocks();
    apply(&mut m, Command::ClockButton(true));
    apply(&mut m, Command::ClockButton(false));
    assert_eq!(m.clocks(), before);
}
