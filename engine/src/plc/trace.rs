//! Per-step tracing: while it is on, a machine records for each step of
//! each scan the bit the step read and its running result after it, and
//! keeps the last completed scan's record. The ladder view walks a rung's
//! network with these values to colour it by the power the machine itself
//! computed (issue #14); nothing is recorded while tracing is off.

/// What one scan's steps did, by step number.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ScanTrace {
    /// The bit each step read (a contact's device, before any inversion).
    pub read: Vec<bool>,
    /// The running result after each step.
    pub result: Vec<bool>,
    /// Whether each step ran in the scan.
    pub ran: Vec<bool>,
}

impl ScanTrace {
    fn clear(&mut self) {
        self.read.fill(false);
        self.result.fill(false);
        self.ran.fill(false);
    }

    fn set(&mut self, step: usize, read: bool, result: bool) {
        if self.ran.len() <= step {
            let n = step + 1;
            self.read.resize(n, false);
            self.result.resize(n, false);
            self.ran.resize(n, false);
        }
        self.read[step] = read;
        self.result[step] = result;
        self.ran[step] = true;
    }
}

/// What each step did over the scans since it was last asked: which
/// values its read bit and its result took ([`SEEN_READ_ON`], …), and how
/// often its read bit rose. A one-scan pulse between two frames shows
/// here although neither frame's scan has it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TraceHistory {
    /// Flags per step.
    pub seen: Vec<u8>,
    /// Rises of the read bit per step (from one scan to the next).
    pub rises: Vec<u32>,
}

/// The read bit was on in some scan.
pub const SEEN_READ_ON: u8 = 1;
/// The read bit was off in some scan.
pub const SEEN_READ_OFF: u8 = 2;
/// The result was on in some scan.
pub const SEEN_RESULT_ON: u8 = 4;
/// The result was off in some scan.
pub const SEEN_RESULT_OFF: u8 = 8;

/// The recorder a machine carries.
#[derive(Clone, Debug, Default)]
pub struct Tracer {
    on: bool,
    current: ScanTrace,
    last: Option<ScanTrace>,
    history: TraceHistory,
}

impl Tracer {
    /// Starts or stops recording (stopping forgets what was recorded).
    pub fn set(&mut self, on: bool) {
        self.on = on;
        if !on {
            self.current = ScanTrace::default();
            self.last = None;
            self.history = TraceHistory::default();
        }
    }

    /// Whether it records.
    pub fn on(&self) -> bool {
        self.on
    }

    /// Step `step` read `read` and left `result`. Inlined by force: every
    /// machine's interpreter calls it per step, and the page is built for
    /// size (docs/performance.md).
    #[inline(always)]
    pub fn step(&mut self, step: usize, read: bool, result: bool) {
        if self.on {
            self.current.set(step, read, result);
        }
    }

    /// Adds the scan just completed to the history (whole scans only, so
    /// a look between two scans' steps never splits one).
    fn remember(&mut self) {
        let h = &mut self.history;
        let scan = &self.current;
        if h.seen.len() < scan.ran.len() {
            h.seen.resize(scan.ran.len(), 0);
            h.rises.resize(scan.ran.len(), 0);
        }
        for step in (0..scan.ran.len()).filter(|&s| scan.ran[s]) {
            let (read, result) = (scan.read[step], scan.result[step]);
            h.seen[step] |= if read { SEEN_READ_ON } else { SEEN_READ_OFF }
                | if result {
                    SEEN_RESULT_ON
                } else {
                    SEEN_RESULT_OFF
                };
            let was = self
                .last
                .as_ref()
                .and_then(|l| l.read.get(step).copied())
                .unwrap_or(false);
            if read && !was {
                h.rises[step] += 1;
            }
        }
    }

    /// What the steps did since the last call (then forgotten).
    pub fn take_history(&mut self) -> TraceHistory {
        std::mem::take(&mut self.history)
    }

    /// The scan ended: its record becomes the last one.
    pub fn end_scan(&mut self) {
        if !self.on {
            return;
        }
        self.remember();
        // The older buffer is reused for the next scan.
        let mut next = self.last.take().unwrap_or_default();
        next.clear();
        self.last = Some(std::mem::replace(&mut self.current, next));
    }

    /// The last completed scan's record, while tracing.
    pub fn last(&self) -> Option<&ScanTrace> {
        self.last.as_ref()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_last_completed_scan_is_kept_and_only_while_on() {
        let mut t = Tracer::default();
        t.step(0, true, true);
        t.end_scan();
        assert_eq!(t.last(), None, "off: nothing recorded");
        t.set(true);
        t.step(0, true, true);
        t.step(2, false, true);
        assert_eq!(t.last(), None, "no scan completed yet");
        t.end_scan();
        let first = t.last().cloned().expect("a scan");
        assert_eq!(first.ran, vec![true, false, true]);
        assert_eq!(first.result, vec![true, false, true]);
        t.step(1, true, false);
        assert_eq!(t.last(), Some(&first), "the scan under way is not shown");
        t.end_scan();
        let second = t.last().expect("a scan");
        let ran = |s: usize| second.ran.get(s).copied().unwrap_or(false);
        assert_eq!((ran(0), ran(1), ran(2)), (false, true, false));
        assert!(second.read[1] && !second.result[1]);
        let history = t.take_history();
        // Step 0 read on in the first scan; step 1 read on in the second
        // (a rise from the first scan's off).
        assert_eq!(history.seen[0], SEEN_READ_ON | SEEN_RESULT_ON);
        assert_eq!(history.seen[1], SEEN_READ_ON | SEEN_RESULT_OFF);
        assert_eq!(history.rises[..2], [1, 1]);
        assert_eq!(t.take_history(), TraceHistory::default(), "taken");
        t.set(false);
        assert_eq!(t.last(), None);
    }
}
