//! The BCD counter as the program drives it: count on the C0 latch's
//! rising edges, stop at the match, clear, wrap, survive RESET and power.

use engine::minasec::{Command, Machine, Mode};
use engine::SimTime;

use super::harness::{apply, input, lamp, mode, running};

/// X00 counts, C0 match lights Y00, X01 clears.
const COUNT: &str = "LD X00\nST C0\nLD C0\nST Y00\nLD X01\nST C0R\n";

/// Gives `n` pulses on X00, 20 ms on and 20 ms off each.
fn pulses(m: &mut Machine, n: usize) {
    for _ in 0..n {
        input(m, 0, true);
        m.tick(SimTime::from_millis(20));
        input(m, 0, false);
        m.tick(SimTime::from_millis(20));
    }
}

fn counter(preset: (u8, u8)) -> Machine {
    let mut m = running(COUNT);
    apply(&mut m, Command::SetCounterPreset(preset.0, preset.1));
    m
}

#[test]
fn counts_each_rising_edge_and_stops_at_the_match() {
    let mut m = counter((0, 5));
    pulses(&mut m, 3);
    assert_eq!(m.counter().count(), 3);
    assert!(!lamp(&m, 0));
    pulses(&mut m, 10);
    assert_eq!(m.counter().count(), 5, "the match closes the gate");
    assert!(lamp(&m, 0), "C0 reads the match");
    assert_eq!(m.panel().digits, Some((0, 5)));
}

#[test]
fn clear_latch_and_cntclr_button_zero_the_count() {
    let mut m = counter((2, 0));
    pulses(&mut m, 7);
    input(&mut m, 1, true);
    m.tick(SimTime::from_millis(20));
    assert_eq!(m.counter().count(), 0);
    pulses(&mut m, 3);
    assert_eq!(m.counter().count(), 0, "clocks are ignored while clearing");
    input(&mut m, 1, false);
    // ST C0 (step 1) runs before ST C0R (step 5) in each scan, so a pulse
    // latched with the release would still meet the clear: wait a scan.
    m.tick(SimTime::from_millis(20));
    pulses(&mut m, 4);
    assert_eq!(m.counter().count(), 4);
    apply(&mut m, Command::CountClearButton(true));
    assert_eq!(m.counter().count(), 0);
    pulses(&mut m, 2);
    assert_eq!(m.counter().count(), 0);
    apply(&mut m, Command::CountClearButton(false));
    pulses(&mut m, 2);
    assert_eq!(m.counter().count(), 2);
}

#[test]
fn wraps_from_99_to_00_when_the_match_lies_below() {
    let mut m = counter((9, 7));
    pulses(&mut m, 97);
    assert_eq!(m.counter().count(), 97);
    apply(&mut m, Command::SetCounterPreset(0, 3)); // X00 is low: no edge
    assert_eq!(m.counter().count(), 97);
    pulses(&mut m, 2);
    assert_eq!(m.counter().count(), 99);
    pulses(&mut m, 1);
    assert_eq!(m.counter().count(), 0, "99 wraps to 00");
    pulses(&mut m, 10);
    assert_eq!(m.counter().count(), 3);
}

#[test]
fn the_count_survives_reset_and_power_off() {
    let mut m = counter((5, 0));
    pulses(&mut m, 6);
    mode(&mut m, Mode::Reset);
    assert_eq!(m.counter().count(), 6, "RESET keeps the count");
    mode(&mut m, Mode::Run);
    apply(&mut m, Command::Power(false));
    assert_eq!(m.panel().digits, None, "the display is dark without power");
    m.tick(SimTime::from_secs(60));
    apply(&mut m, Command::Power(true));
    assert_eq!(m.counter().count(), 6, "battery-backed");
    pulses(&mut m, 1);
    assert_eq!(m.counter().count(), 7, "and it counts on from there");
}
