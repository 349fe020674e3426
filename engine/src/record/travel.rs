//! Time travel as the page drives it: one object-safe interface over
//! every machine's [`Recorded`], so the page's controls, timing chart and
//! "why" reach any workspace's recording without knowing its machine.

use super::{Break, Condition, ConditionError, Mark, Recorded};
use crate::plc::{Plc, PlcError, Value};
use crate::time::SimTime;

/// A recorded machine, seen through its recording.
pub trait TimeTravel {
    /// The machine as shown (the travelled-to scan's, or live).
    fn plc(&self) -> &dyn Plc;
    /// The first and last recorded scans.
    fn marks(&self) -> (Mark, Mark);
    /// The past scan shown, or `None` when live.
    fn shown(&self) -> Option<Mark>;
    /// Shows recorded scan `mark`; false if not kept.
    fn show(&mut self, mark: Mark) -> bool;
    /// Back to the live machine.
    fn go_live(&mut self);
    /// Resumes from the shown scan, dropping the later recording.
    fn resume_here(&mut self) -> bool;
    /// Sets the break condition from its text (empty: none).
    fn set_break(&mut self, text: &str) -> Result<(), ConditionError>;
    /// Where the break condition held since the last call.
    fn take_break(&mut self) -> Option<Break>;
    /// Every scan where it held.
    fn breaks(&self) -> Vec<Mark>;
    /// The end time of each scan in `from..=to` (kept ones).
    fn times(&mut self, from: Mark, to: Mark) -> Vec<SimTime>;
    /// `device`'s value at each scan in `from..=to` (kept ones).
    fn series(
        &mut self,
        device: &str,
        from: Mark,
        to: Mark,
    ) -> Result<Vec<Option<Value>>, PlcError>;
    /// The scan at or before `at` where `device` last changed.
    fn last_change(&mut self, device: &str, at: Mark) -> Option<Mark>;
}

impl<M: Plc + Clone> TimeTravel for Recorded<M> {
    fn plc(&self) -> &dyn Plc {
        self
    }

    fn marks(&self) -> (Mark, Mark) {
        (self.recording().first(), self.recording().last())
    }

    fn shown(&self) -> Option<Mark> {
        Recorded::shown(self)
    }

    fn show(&mut self, mark: Mark) -> bool {
        Recorded::show(self, mark)
    }

    fn go_live(&mut self) {
        Recorded::go_live(self);
    }

    fn resume_here(&mut self) -> bool {
        Recorded::resume_here(self)
    }

    fn set_break(&mut self, text: &str) -> Result<(), ConditionError> {
        if text.trim().is_empty() {
            Recorded::set_break(self, None);
            return Ok(());
        }
        let condition = Condition::parse(text, &*self)?;
        Recorded::set_break(self, Some(condition));
        Ok(())
    }

    fn take_break(&mut self) -> Option<Break> {
        Recorded::take_break(self)
    }

    fn breaks(&self) -> Vec<Mark> {
        Recorded::breaks(self).to_vec()
    }

    fn times(&mut self, from: Mark, to: Mark) -> Vec<SimTime> {
        self.recording_mut().times(from, to)
    }

    fn series(
        &mut self,
        device: &str,
        from: Mark,
        to: Mark,
    ) -> Result<Vec<Option<Value>>, PlcError> {
        let d = self.device(device)?;
        let (rec, machine) = self.recording_and_machine();
        Ok(rec.values(machine, d, from, to))
    }

    fn last_change(&mut self, device: &str, at: Mark) -> Option<Mark> {
        let d = self.device(device).ok()?;
        let (rec, machine) = self.recording_and_machine();
        rec.last_change(machine, d, at)
    }
}
