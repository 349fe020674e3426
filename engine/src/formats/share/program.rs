//! What version 6 links add (issue #55): the project's program text
//! (the soft PLC's Structured Text) after a version 5 link's body, whose
//! plant is then preceded by a flag (a project may carry ST and no
//! plant). A project without a program text keeps its version 1-5 link,
//! which older Hashigos open.

use super::{put_str, Reader, ShareError};
use crate::formats::project::{ProgramText, Project};

/// The plant flag and plant, then the language (0: ST) and the text.
pub(super) fn put(w: &mut Vec<u8>, project: &Project) {
    w.push(u8::from(project.plant.is_some()));
    if project.plant.is_some() {
        super::plant::put(w, project);
    }
    w.push(0);
    put_str(w, project.program.as_ref().map_or("", |p| &p.text));
}

impl Reader<'_> {
    /// What [`put`] wrote.
    pub(super) fn program(&mut self, project: &mut Project) -> Result<(), ShareError> {
        project.plant = match self.byte()? {
            0 => None,
            1 => Some(self.plant()?),
            _ => return Err(self.bad("the plant flag is neither 0 nor 1")),
        };
        if self.byte()? != 0 {
            return Err(self.bad("a program text in a language this Hashigo lacks"));
        }
        project.program = Some(ProgramText::st(&self.string()?));
        Ok(())
    }
}
