//! Running a machine one scan at a time: what recording and replay share,
//! so both see exactly the same scans.

use crate::plc::Plc;
use crate::time::SimTime;

/// Runs `machine` to `t`, stopping at the end of every scan to call
/// `at_scan`, which returns whether to go on. Returns true when it reached
/// `t`, false when `at_scan` stopped it (the time is then that scan's end).
/// Running to `t` in these pieces is the same as one `run_until(t)`: each
/// piece runs what is due by its own end.
pub fn run_scans<M: Plc + ?Sized>(
    machine: &mut M,
    t: SimTime,
    mut at_scan: impl FnMut(&M) -> bool,
) -> bool {
    if !run_whole_scans(machine, t, &mut at_scan) {
        return false;
    }
    // The rest, up to `t`: part of a scan (or, for a machine that cannot
    // say when its scan ends, everything).
    let before = machine.scans();
    machine.run_until(t);
    machine.scans() == before || at_scan(machine)
}

/// Runs `machine` scan by scan to the end of the last scan that ends at or
/// before `t`, calling `at_scan` at each end, which returns whether to go
/// on; false when it stopped the run. It stops short, too, for a machine
/// that cannot say when its scan ends (nothing moved) rather than spin:
/// what remains is for a plain `run_until`.
pub fn run_whole_scans<M: Plc + ?Sized>(
    machine: &mut M,
    t: SimTime,
    mut at_scan: impl FnMut(&M) -> bool,
) -> bool {
    loop {
        let before = machine.scans();
        let started = machine.now();
        match machine.next_scan_end() {
            Some(end) if end <= t => machine.run_until(end),
            _ => return true,
        }
        if machine.scans() != before {
            if !at_scan(machine) {
                return false;
            }
        } else if machine.now() <= started && machine.next_scan_end() <= Some(started) {
            return true;
        }
    }
}
