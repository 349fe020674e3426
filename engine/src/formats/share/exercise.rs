//! What version 4 links add (issue #49): an exercise's task, whether its
//! tests are hidden, and each case's hint, after a version 3 link's
//! variables. A project without them keeps its version 1, 2 or 3 link,
//! which older Hashigos open.

use super::{put_str, Reader, ShareError};
use crate::formats::project::Project;
use crate::formats::project::{Exercise, Task, TestsShown, MAX_TASK_BYTES};

/// Whether the project needs a version 4 link.
pub(super) fn needed(project: &Project) -> bool {
    project.exercise.as_ref().is_some_and(|e| !e.is_plain())
        || project.tests.iter().any(|c| !c.hint.is_empty())
}

/// The task in both languages, the hidden flag, then one hint a case.
pub(super) fn put(w: &mut Vec<u8>, project: &Project) {
    let exercise = project.exercise.clone().unwrap_or_default();
    put_str(w, &exercise.task.en);
    put_str(w, &exercise.task.ja);
    w.push(u8::from(exercise.hidden()));
    for case in &project.tests {
        put_str(w, &case.hint);
    }
}

impl Reader<'_> {
    /// What [`put`] wrote, into `project` (whose cases are read).
    pub(super) fn exercise(&mut self, project: &mut Project) -> Result<(), ShareError> {
        let en = self.task()?;
        let ja = self.task()?;
        let tests = match self.byte()? {
            0 => TestsShown::Shown,
            1 => TestsShown::Hidden,
            _ => return Err(self.bad("the hidden flag is neither 0 nor 1")),
        };
        let exercise = Exercise {
            task: Task { en, ja },
            tests,
        };
        // A hint-only project that is not an exercise keeps none.
        if project.exercise.is_some() {
            project.exercise = Some(exercise);
        } else if !exercise.is_plain() {
            return Err(self.bad("a task for a project that is not an exercise"));
        }
        for case in &mut project.tests {
            case.hint = self.string()?;
        }
        Ok(())
    }

    /// A task, refused past [`MAX_TASK_BYTES`].
    fn task(&mut self) -> Result<String, ShareError> {
        let text = self.string()?;
        if text.len() > MAX_TASK_BYTES {
            return Err(self.bad("a task longer than a project may have"));
        }
        Ok(text)
    }
}
