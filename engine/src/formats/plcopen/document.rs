//! A PLCopen file read once: the XML parsed and checked as a project, then
//! asked what it holds (its programs, a map for a machine) and imported
//! (for a bit machine through a map, or for the soft PLC as written) as
//! often as the caller needs, without reading the text again.

use super::declare::{self, VarMap};
use super::dom::Node;
use super::error::Errors;
use super::import::{self, drawn_body, Imported};
use super::soft::{self, SoftProgram};
use crate::MachineId;

/// A PLCopen TC6 project (v2.01, v2.00 or v1.0) as read: its text (IL
/// bodies are copied from it as written) and its element tree.
#[derive(Clone, Debug)]
pub struct Document {
    text: String,
    root: Node,
}

impl Document {
    /// Reads `text` as a PLCopen project; errors at their line (not XML,
    /// not a project, a namespace this reader does not know).
    pub fn read(text: &str) -> Result<Document, Errors> {
        Ok(Document {
            root: import::project(text)?,
            text: text.to_string(),
        })
    }

    /// The project's root element, for callers that walk it themselves.
    pub fn root(&self) -> &Node {
        &self.root
    }

    /// The names of the POUs with a drawn (LD or FBD) body, in file order:
    /// the programs a page can offer to import one at a time.
    pub fn programs(&self) -> Vec<String> {
        let mut pous = Vec::new();
        self.root.descendants("pou", &mut pous);
        pous.iter()
            .filter(|p| drawn_body(p).is_some())
            .filter_map(|p| p.attr("name").map(str::to_string))
            .collect()
    }

    /// A device of `machine` proposed for each variable and block instance
    /// with none yet (`given` kept first), for what POU `pou` uses or,
    /// with `None`, for the whole project ([`declare::propose_in`]).
    pub fn propose(
        &self,
        machine: MachineId,
        given: Option<&VarMap>,
        pou: Option<&str>,
    ) -> Result<Vec<(String, String)>, super::ImportError> {
        let scope = match pou {
            Some(wanted) => import::pou_named(&self.root, wanted)?,
            None => &self.root,
        };
        Ok(declare::propose_in(&self.root, scope, machine, given))
    }

    /// The project as a ladder for `machine` (`None`: unchecked), its
    /// variables through `map`: POU `pou` alone or, with `None`, the
    /// programs the configuration's tasks run. Every problem at its line.
    pub fn import(
        &self,
        machine: Option<MachineId>,
        map: Option<&VarMap>,
        pou: Option<&str>,
    ) -> Result<Imported, Errors> {
        import::ladder_of(&self.root, machine, map, pou)
    }

    /// The project's Structured Text as one `.st` text: its types, the
    /// configuration's globals and its ST POUs ([`super::st_source`]),
    /// what [`super::export_st`] writes back as a project.
    pub fn st_text(&self) -> String {
        super::st_source(&self.root)
    }

    /// The project as the soft PLC's program text, run as drawn with no
    /// map: `pou` alone or the programs the tasks run.
    pub fn soft_program(&self, pou: Option<&str>) -> Result<SoftProgram, Errors> {
        soft::il_of(&self.root, &self.text, pou)
    }
}
