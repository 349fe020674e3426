//! MINASEC-U's counter: a battery-backed two-digit BCD counter (74HC390),
//! compared with two rotary BCD switches (74HC688), whose clock is gated by
//! the match (seed, カウンター).

/// The counter and its set value.
///
/// The model is the gate, not an idealised counter: the counter's clock is
/// `count-up latch AND NOT match`, and the count advances on each rising
/// edge of that clock while clear is not active.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BcdCounter {
    count: u8,
    set_value: u8,
    up_latch: bool,
    clear_latch: bool,
    clear_button: bool,
    gate: bool,
}

impl BcdCounter {
    /// The count shown on the 7-segment digits, 0..=99.
    pub const fn count(&self) -> u8 {
        self.count
    }

    /// The rotary switches' value, 0..=99.
    pub const fn set_value(&self) -> u8 {
        self.set_value
    }

    /// The count-up latch (address `C0` written by ST).
    pub const fn up_latch(&self) -> bool {
        self.up_latch
    }

    /// The clear latch (address `C0R` written by ST).
    pub const fn clear_latch(&self) -> bool {
        self.clear_latch
    }

    /// Whether the CNTCLR button is held.
    pub const fn clear_button(&self) -> bool {
        self.clear_button
    }

    /// What reading `C0` gives: count == set value.
    pub const fn matched(&self) -> bool {
        self.count == self.set_value
    }

    /// Clear is active while the `C0R` latch or the CNTCLR button is on.
    pub const fn clearing(&self) -> bool {
        self.clear_latch || self.clear_button
    }

    /// Sets the rotary switches (caller keeps it in 0..=99).
    pub fn set_set_value(&mut self, value: u8) {
        self.set_value = value % 100;
        self.settle();
    }

    /// Writes the count-up latch.
    pub fn set_up_latch(&mut self, on: bool) {
        self.up_latch = on;
        self.settle();
    }

    /// Writes the clear latch.
    pub fn set_clear_latch(&mut self, on: bool) {
        self.clear_latch = on;
        self.settle();
    }

    /// Presses or releases CNTCLR.
    pub fn set_clear_button(&mut self, held: bool) {
        self.clear_button = held;
        self.settle();
    }

    /// Clears both latches (RESET or power-off); the count is kept.
    pub fn clear_latches(&mut self) {
        self.up_latch = false;
        self.clear_latch = false;
        self.settle();
    }

    /// Loads a count directly (the battery-backed value on restore).
    pub fn set_count(&mut self, count: u8) {
        self.count = count % 100;
        // A restored count is not an edge: the gate takes its level quietly.
        self.gate = self.up_latch && !self.matched();
    }

    /// Re-evaluates the gate after any input changed.
    fn settle(&mut self) {
        if self.clearing() {
            self.count = 0;
        }
        let gate = self.up_latch && !self.matched();
        if gate && !self.gate && !self.clearing() {
            self.count = (self.count + 1) % 100;
        }
        // After a count the match may have risen, closing the gate again.
        self.gate = self.up_latch && !self.matched();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pulse(c: &mut BcdCounter) {
        c.set_up_latch(true);
        c.set_up_latch(false);
    }

    #[test]
    fn counts_rising_edges_and_stops_at_match() {
        let mut c = BcdCounter::default();
        c.set_set_value(3);
        for _ in 0..5 {
            pulse(&mut c);
        }
        assert_eq!(c.count(), 3);
        assert!(c.matched());
    }

    #[test]
    fn holding_the_latch_counts_once() {
        let mut c = BcdCounter::default();
        c.set_set_value(10);
        c.set_up_latch(true);
        c.set_up_latch(true);
        assert_eq!(c.count(), 1);
    }

    #[test]
    fn turning_the_switches_under_a_held_latch_counts_one() {
        let mut c = BcdCounter::default();
        c.set_set_value(1);
        c.set_up_latch(true);
        assert_eq!(c.count(), 1);
        assert!(c.matched());
        c.set_set_value(5); // match falls while the latch is high: the clock rises
        assert_eq!(c.count(), 2);
    }

    #[test]
    fn clear_zeroes_and_ignores_clocks() {
        let mut c = BcdCounter::default();
        c.set_set_value(50);
        pulse(&mut c);
        pulse(&mut c);
        c.set_clear_latch(true);
        assert_eq!(c.count(), 0);
        pulse(&mut c);
        assert_eq!(c.count(), 0);
        c.set_up_latch(true);
        c.set_clear_latch(false); // gate already high: no edge on release
        assert_eq!(c.count(), 0);
        c.set_clear_button(true);
        c.set_up_latch(false);
        c.set_up_latch(true);
        assert_eq!(c.count(), 0);
    }

    #[test]
    fn wraps_from_99_to_00() {
        let mut c = BcdCounter::default();
        c.set_set_value(5);
        c.set_count(99);
        pulse(&mut c);
        assert_eq!(c.count(), 0);
    }
}
