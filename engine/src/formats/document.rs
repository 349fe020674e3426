//! One way in for every file that holds a ladder: open it (its text read
//! into that format's document, once), list its programs, propose a map
//! for a machine, import it for a machine. The command line and the files
//! worker both go through here, keeping the document between the steps.

use std::fmt;

use super::ldmicro::{self, LdError, LdFile};
use super::plcopen::{self, ImportError, VarMap};
use super::project::{Project, ProjectError};
use crate::error::Located;
use crate::ladder::grid::LadderError;
use crate::machines::IEC_MACHINE;
use crate::MachineId;

/// The files Hashigo opens as a ladder.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Hashigo's own project (`.json`).
    Project,
    /// PLCopen TC6 XML (`.xml`).
    PlcOpen,
    /// An LDmicro `.ld` file.
    LdMicro,
}

/// `--set`-style settings a file holds: name, value, the line of each.
pub type Settings = Vec<(String, String, usize)>;

/// A file read once, in its format's own shape.
#[derive(Clone, Debug)]
pub enum Document {
    /// A project and its settings' lines.
    Project(Project, Settings),
    /// A PLCopen project.
    PlcOpen(plcopen::Document),
    /// An LDmicro file and the line of its `CYCLE=`.
    LdMicro(LdFile, usize),
}

/// Why a file does not open or import, in its format's words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FileError {
    /// Not a project this build reads.
    Project(ProjectError),
    /// A PLCopen file's problem.
    PlcOpen(ImportError),
    /// An LDmicro file's problem.
    LdMicro(LdError),
    /// The file runs on this machine only (LDmicro's on the soft PLC).
    OnlyOn(MachineId),
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FileError::Project(e) => e.fmt(f),
            FileError::PlcOpen(e) => e.fmt(f),
            FileError::LdMicro(e) => e.fmt(f),
            FileError::OnlyOn(m) => write!(f, "the file runs on {} only", m.name()),
        }
    }
}

impl std::error::Error for FileError {}

/// Problems, each at its line of the file.
pub type Errors = Vec<Located<FileError>>;

fn wrap<E>(errors: Vec<Located<E>>, kind: impl Fn(E) -> FileError) -> Errors {
    errors
        .into_iter()
        .map(|e| Located::new(e.line, kind(e.error)))
        .collect()
}

/// A file imported for a machine: the project it stands for and what is
/// worth saying about it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Opened {
    /// The project, for the machine asked for.
    pub project: Project,
    /// Its settings with their lines (a project's own; LDmicro's `CYCLE=`
    /// as the scan).
    pub settings: Settings,
    /// What was dropped or skipped, at its line of the file.
    pub warnings: Vec<Located<String>>,
    /// Map entries the file does not use: (name, line of the map).
    pub unused_map_entries: Vec<(String, usize)>,
}

impl Document {
    /// Reads `text` as a file of `kind`; every problem at its line.
    pub fn open(kind: Kind, text: &str) -> Result<Document, Errors> {
        match kind {
            Kind::Project => {
                let project = Project::from_json(text)
                    .map_err(|e| vec![Located::new(e.line, FileError::Project(e.error))])?;
                let settings = project
                    .settings
                    .iter()
                    .map(|(n, v)| (n.clone(), v.clone(), Project::setting_line(text, n)))
                    .collect();
                // Its Structured Text's blocks are its ladder's boxes (issue
                // #55); a text that does not load leaves those boxes
                // unknown, each said at its cell when the ladder compiles.
                if let Some(program) = &project.program {
                    if let Ok(b) = crate::softplc::st::st_blocks(&program.text) {
                        crate::ladder::user_blocks::set(b.blocks, b.il);
                    }
                }
                Ok(Document::Project(project, settings))
            }
            Kind::PlcOpen => plcopen::Document::read(text)
                .map(Document::PlcOpen)
                .map_err(|e| wrap(e, FileError::PlcOpen)),
            Kind::LdMicro => {
                let file = ldmicro::parse(text).map_err(|e| wrap(e, FileError::LdMicro))?;
                let line = text
                    .lines()
                    .position(|l| l.trim_start().starts_with("CYCLE="))
                    .map_or(1, |i| i + 1);
                Ok(Document::LdMicro(file, line))
            }
        }
    }

    /// The machine the file is for when it says (a project names its
    /// own; an LDmicro file runs on the soft PLC; a PLCopen file names
    /// none).
    pub fn machine(&self) -> Option<MachineId> {
        match self {
            Document::Project(p, _) => Some(p.machine),
            Document::PlcOpen(_) => None,
            Document::LdMicro(..) => Some(IEC_MACHINE),
        }
    }

    /// The only machine the file runs on, if it has one (LDmicro's).
    pub fn only_machine(&self) -> Option<MachineId> {
        matches!(self, Document::LdMicro(..)).then_some(IEC_MACHINE)
    }

    /// The programs one may import alone (a PLCopen file's drawn POUs);
    /// none for a file that is one ladder.
    pub fn programs(&self) -> Vec<String> {
        match self {
            Document::PlcOpen(d) => d.programs(),
            _ => Vec::new(),
        }
    }

    /// A device of `machine` for each name the file gives none (a PLCopen
    /// file's variables and block instances, `given` first, for `pou` or
    /// the whole file); nothing for files whose names are devices already.
    pub fn propose(
        &self,
        machine: MachineId,
        given: Option<&VarMap>,
        pou: Option<&str>,
    ) -> Result<Vec<(String, String)>, FileError> {
        match self {
            Document::PlcOpen(d) => d.propose(machine, given, pou).map_err(FileError::PlcOpen),
            _ => Ok(Vec::new()),
        }
    }

    /// The file as a project for `machine`: a project's ladder as saved,
    /// a PLCopen file's through `map` (POU `pou` alone, or what the tasks
    /// run), an LDmicro file's (its `CYCLE=` as the scan setting) on the
    /// soft PLC only. Every problem at its line of the file.
    pub fn import(
        &self,
        machine: MachineId,
        map: Option<&VarMap>,
        pou: Option<&str>,
    ) -> Result<Opened, Errors> {
        let opened = |project, settings| Opened {
            project,
            settings,
            warnings: Vec::new(),
            unused_map_entries: Vec::new(),
        };
        match self {
            Document::Project(project, settings) => {
                let mut project = project.clone();
                project.machine = machine;
                Ok(opened(project, settings.clone()))
            }
            Document::PlcOpen(d) => {
                let imported = d
                    .import(Some(machine), map, pou)
                    .map_err(|e| wrap(e, FileError::PlcOpen))?;
                Ok(Opened {
                    warnings: imported
                        .warnings
                        .into_iter()
                        .map(|w| Located::new(w.line, w.error.to_string()))
                        .collect(),
                    unused_map_entries: imported.unused_map_entries,
                    ..opened(Project::new(machine, imported.ladder), Vec::new())
                })
            }
            Document::LdMicro(file, line) => {
                if machine != IEC_MACHINE {
                    let only = FileError::OnlyOn(IEC_MACHINE);
                    return Err(vec![Located::new(1, only)]);
                }
                let ladder = ldmicro::to_ladder(file).map_err(|e| wrap(e, FileError::LdMicro))?;
                let mut project = Project::new(machine, ladder);
                let scan = scan_of(file.cycle_us);
                project.settings.insert("scan".into(), scan.clone());
                Ok(opened(project, vec![("scan".into(), scan, *line)]))
            }
        }
    }

    /// What compiling the file's ladder refused, at the file's own lines
    /// where the file is the program's own drawing (LDmicro's: never at a
    /// rung or cell it does not have); `None` for the others, whose
    /// errors stay at their rung and cell.
    pub fn locate(&self, errors: Vec<LadderError>) -> Option<Vec<Located<LdError>>> {
        match self {
            Document::LdMicro(file, _) => Some(ldmicro::locate(file, errors)),
            _ => None,
        }
    }
}

/// An LDmicro `CYCLE=` (µs) as a scan setting: in ms when whole.
fn scan_of(us: u64) -> String {
    if us.is_multiple_of(1000) {
        format!("{}ms", us / 1000)
    } else {
        format!("{us}us")
    }
}
