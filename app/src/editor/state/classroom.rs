//! A clean slate per project (issue #49): what one project's work left on
//! screen (the Tests pane's results, inputs held from the ladder, Why?,
//! the chart's choices) does not stay when another is opened, imported
//! or begun; and who sees an exercise how (the student's view, the
//! author's).

use super::*;
use engine::plc::Command;

/// How one case came out in the page.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseResult {
    /// Every expectation held.
    Pass,
    /// The first expectation that did not, and what was seen.
    Fail(crate::i18n::errors::Both),
    /// The case could not run (a bad line, a device the machine lacks).
    Error(crate::i18n::errors::Both),
    /// The case names a device the ladder does not use yet (the soft
    /// PLC has only the devices its program uses): the answer is not
    /// there yet, which is a failure, not the author's error.
    Unused(String),
}

impl LadderCtx {
    /// Forgets what the last project's work left on screen: the tests'
    /// results, the inputs held from the ladder (released on the
    /// machine), the Why? explanation; views with state of their own
    /// follow `work.slate`.
    pub fn clean_slate(&self) {
        self.cases.results.set(Vec::new());
        // The fault a student named was for the last project's plant.
        self.cases.report.set((None, None));
        let held = self.live.forced.get_untracked();
        if !held.is_empty() {
            self.operate(|plc| {
                for (device, _) in &held {
                    if let Ok(d) = plc.device(device) {
                        // Released whatever it was: the machine may not
                        // have it held any more, which is what is wanted.
                        let _ = plc.apply(Command::ReleaseInput(d));
                    }
                }
            });
            self.live.forced.set(Vec::new());
        }
        self.why.shown.set(None);
        self.work.title.set(None);
        self.work.slate.update(|n| *n += 1);
    }

    /// The app bar's title for what was just opened here (a file's name,
    /// an example's title in each language), after its clean slate.
    pub fn titled(&self, en: &str, ja: &str) {
        self.work.title.set(Some((en.to_string(), ja.to_string())));
    }

    /// A new, empty ladder (File > New, the toolbar's +) on a clean
    /// slate. The tests stay (New is one undo away, and the tests are not
    /// in the ladder's undo): only what they said of the old ladder goes.
    pub fn new_ladder(&self) {
        self.apply(Edit::NewLadder);
        self.clean_slate();
    }

    /// Whether the student's view of an exercise is shown: an exercise,
    /// not being authored.
    pub fn student(&self) -> bool {
        self.cases.exercise.with(Option::is_some) && !self.cases.authoring.get()
    }
}
