//! Two PLC-IO86As with their serial ports crossed (SI ↔ SO): each one's
//! SETS/RSTS set or reset the other's Y and M (the manual's two-device
//! example).

use super::machine::Machine;
use crate::time::SimTime;

/// The IO86A's own command ([`crate::plc::Command::Own`]): loads a second
/// device, linked to the first by SETS / RSTS (the manual's two-device
/// example); its devices are named `B.X00`. Text in the IO86A listing
/// format; an empty text unlinks it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadLinked(pub String);

impl std::fmt::Display for LoadLinked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("linked second device")
    }
}

/// Two linked devices, stepped scan by scan in time order. A device's
/// SETS/RSTS writes reach the other at the end of the scan that made them
/// (the serial transfer time is not modelled).
#[derive(Clone, Debug)]
pub struct LinkedPair {
    /// Device A.
    pub a: Machine,
    /// Device B.
    pub b: Machine,
}

impl LinkedPair {
    /// Links `a` and `b`.
    pub fn new(a: Machine, b: Machine) -> LinkedPair {
        LinkedPair { a, b }
    }

    /// Runs both devices to `t`, delivering writes after every scan.
    pub fn run_until(&mut self, t: SimTime) {
        loop {
            let next_a = self.a.next_scan_at();
            let next_b = self.b.next_scan_at();
            let next = match (next_a, next_b) {
                (Some(x), Some(y)) => x.min(y),
                (Some(x), None) | (None, Some(x)) => x,
                (None, None) => break,
            };
            if next > t {
                break;
            }
            if next_a == Some(next) {
                self.a.run_until(next);
                for w in self.a.take_link_writes() {
                    self.b.write_bit(w.bit, w.on);
                }
            }
            if next_b == Some(next) {
                self.b.run_until(next);
                for w in self.b.take_link_writes() {
                    self.a.write_bit(w.bit, w.on);
                }
            }
        }
        self.a.run_until(t);
        self.b.run_until(t);
    }
}
