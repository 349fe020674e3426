//! The page's file formats, run in a Web Worker that the page fetches the
//! first time a PLCopen file is opened or exported (issue #29): they are
//! a sixth of the page's code and most visits never use them, so the
//! first screen does not wait for them (docs/performance.md, "First
//! visit"). The service worker keeps this worker for offline use like
//! every other file of the release.
//!
//! The page and the worker exchange [`Envelope`]s as JSON text; what each
//! request does is plain Rust ([`handle`]), tested natively.

use engine::formats::plcopen::ImportError;
use engine::formats::plcopen::{self, Document, VarMap};
use engine::formats::{self, FileError, Kind};
use engine::ladder::edit::{align_outputs, COLUMNS};
use engine::ladder::target::ElementError;
use engine::ladder::Ladder;
use engine::machines::IEC_MACHINE;
use engine::MachineId;
use serde::{Deserialize, Serialize};

/// What the worker posts once it listens: messages sent before then would
/// be lost (its module is still loading), so the page holds them till it.
pub const READY: &str = "ready";

/// A request or its reply with the number that pairs them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Envelope<T> {
    /// Chosen by the page; the reply carries it back.
    pub id: u32,
    pub body: T,
}

/// What the page asks of the worker.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Request {
    /// Import a PLCopen file's ladder for `machine`. With `rows: None`
    /// (the file just opened) the worker proposes a device for each
    /// variable; otherwise `rows` are the user's (name, device) pairs
    /// and `pou` the POU chosen (`None`: what the tasks run).
    Import {
        file: String,
        text: String,
        machine: MachineId,
        rows: Option<Vec<(String, String)>>,
        pou: Option<String>,
    },
    /// Export `ladder` as PLCopen XML with one program named `name`.
    Export { ladder: Ladder, name: String },
    /// Open an LDmicro `.ld` file as a soft PLC ladder (docs/ldmicro.md).
    OpenLd { file: String, text: String },
    /// Write a soft PLC ladder of LDmicro's elements as an `.ld` file
    /// whose scan is `cycle_us`.
    ExportLd { ladder: Ladder, cycle_us: u64 },
}

/// The worker's answer to a [`Request`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Reply {
    Import(ImportReply),
    /// The XML, or each reason the ladder cannot be exported.
    Export(Result<String, Vec<String>>),
    /// The LDmicro file's ladder, or each reason it does not open
    /// (`file:line: …`).
    OpenLd(Result<LdOpened, Vec<String>>),
    /// The `.ld` text, or each reason (at its rung and cell) it cannot
    /// be written.
    ExportLd(Result<String, Vec<String>>),
}

/// An LDmicro file as the soft PLC's ladder.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LdOpened {
    /// The ladder, its outputs aligned.
    pub ladder: Ladder,
    /// The file's `CYCLE=`, in µs: the scan its timers count.
    pub cycle_us: u64,
}

/// What an import attempt found.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ImportReply {
    /// The POUs with an LD or FBD body.
    pub pous: Vec<String>,
    /// Each variable with the device it is to take (proposed, or the
    /// user's as sent).
    pub rows: Vec<(String, String)>,
    /// What was dropped or skipped, each with `file:line`.
    pub warnings: Vec<String>,
    /// The same warnings typed, one for each (issue #49): the page says
    /// them in its own language.
    #[serde(default)]
    pub warnings_said: Vec<Said>,
    /// Why the file does not import, each at its line or at its row.
    pub errors: Vec<String>,
    /// The same errors typed, one for each (issue #49): the page says
    /// those it can in its own language.
    pub said: Vec<Said>,
    /// The imported ladder, its outputs aligned, when there are no errors.
    pub ladder: Option<Ladder>,
    /// When the file does not import on the machine asked for but does on
    /// another (the soft PLC runs most OpenPLC projects): that machine, so
    /// the page can offer the switch (issue #49).
    pub runs_on: Option<MachineId>,
    /// The project's ST POUs as one `.st` text for the soft PLC's ST pane
    /// (issue #55), beside the ladder: on the soft PLC, for the whole
    /// project (no POU picked), when it has any.
    #[serde(default)]
    pub st: Option<String>,
}

/// One import error as the page can say it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Said {
    /// Where: `file:line`, or the table's `name → device`.
    pub at: String,
    /// The machine's typed refusal, when that is what it is.
    pub cause: Option<ElementError>,
    /// Any other reason in Japanese, made here from its kind (issue #49).
    #[serde(default)]
    pub ja: Option<String>,
}

/// Does what `request` asks.
pub fn handle(request: Request) -> Reply {
    match request {
        Request::Import {
            file,
            text,
            machine,
            rows,
            pou,
        } => Reply::Import(import(&file, &text, machine, rows, pou.as_deref())),
        Request::Export { ladder, name } => Reply::Export(
            plcopen::export(&ladder, &name)
                .map_err(|errors| errors.iter().map(ToString::to_string).collect()),
        ),
        Request::OpenLd { file, text } => Reply::OpenLd(open_ld(&file, &text)),
        Request::ExportLd { ladder, cycle_us } => Reply::ExportLd(
            engine::formats::ldmicro::export(&ladder, cycle_us)
                .map_err(|errors| errors.iter().map(ToString::to_string).collect()),
        ),
    }
}

/// An LDmicro file read and drawn for the soft PLC; every problem at its
/// line.
fn open_ld(file: &str, text: &str) -> Result<LdOpened, Vec<String>> {
    let at = |errors: Vec<engine::Located<FileError>>| {
        errors
            .iter()
            .map(|e| format!("{file}:{}: {}", e.line, e.error))
            .collect::<Vec<_>>()
    };
    let document = formats::Document::open(Kind::LdMicro, text).map_err(at)?;
    let opened = document.import(IEC_MACHINE, None, None).map_err(at)?;
    let formats::Document::LdMicro(parsed, _) = &document else {
        return Err(vec![format!("{file}: not an LDmicro file")]);
    };
    Ok(LdOpened {
        ladder: align_outputs(&opened.project.ladder, COLUMNS - 1),
        cycle_us: parsed.cycle_us,
    })
}

/// One import attempt (see [`Request::Import`]): the file is read once,
/// and that one document is asked for its programs, the devices proposed,
/// the ladder and, when refused here, whether the soft PLC runs it.
fn import(
    file: &str,
    text: &str,
    machine: MachineId,
    rows: Option<Vec<(String, String)>>,
    pou: Option<&str>,
) -> ImportReply {
    let mut reply = ImportReply::default();
    let document = Document::read(text);
    if let Ok(document) = &document {
        reply.pous = document.programs();
    }
    // The soft PLC takes the project's own names: nothing to map.
    let soft = machine == IEC_MACHINE;
    reply.rows = match (rows, &document) {
        _ if soft => Vec::new(),
        (Some(rows), _) => rows,
        (None, Ok(document)) => document.propose(machine, None, None).unwrap_or_default(),
        (None, Err(_)) => Vec::new(),
    };
    let map = VarMap::from_pairs(
        reply
            .rows
            .iter()
            .filter(|(_, d)| !d.trim().is_empty())
            .map(|(n, d)| (n.clone(), d.trim().to_string())),
    );
    if let Err(errors) = map.check(machine) {
        // Said at the table's row (the map's lines number its filled rows).
        for e in &errors {
            if let Some((name, device, _)) = map.entries.iter().find(|(_, _, l)| *l == e.line) {
                let at = format!("{name} → {device}");
                reply.errors.push(format!("{at}: {}", e.error));
                let cause = Some(e.error.clone());
                reply.said.push(Said {
                    at,
                    cause,
                    ja: None,
                });
            }
        }
        return reply;
    }
    let imported = document
        .as_ref()
        .map_err(Clone::clone)
        .and_then(|d| d.import(Some(machine), Some(&map), pou));
    // A project whose programs are all in ST: an empty ladder, the ST
    // in the pane (issue #55).
    let whole_on_soft = soft && pou.is_none();
    let imported = match (imported, &document) {
        (Err(errors), Ok(d)) if whole_on_soft => st::drawn_apart(d, errors),
        (other, _) => other,
    };
    if whole_on_soft && imported.is_ok() {
        reply.st = document.as_ref().ok().and_then(st::text);
    }
    match imported {
        Ok(imported) => {
            for w in &imported.warnings {
                let at = format!("{file}:{}", w.line);
                let english = w.error.to_string();
                reply
                    .warnings
                    .push(format!("{at}: {}", page_warning(&english)));
                let ja = Some(said_warning_ja::warning_ja(&w.error));
                reply.warnings_said.push(Said {
                    at,
                    cause: None,
                    ja,
                });
            }
            reply.ladder = Some(align_outputs(&imported.ladder, COLUMNS - 1));
        }
        Err(errors) => {
            for e in &errors {
                let at = format!("{file}:{}", e.line);
                reply.errors.push(format!("{at}: {}", e.error.in_page()));
                let cause = match &e.error {
                    ImportError::Element(why) => Some(why.clone()),
                    _ => None,
                };
                let ja = said_ja::import_ja(&e.error);
                reply.said.push(Said { at, cause, ja });
            }
            reply.runs_on = document.ok().and_then(|d| elsewhere(&d, machine, pou));
        }
    }
    reply
}

/// The machine that imports a file refused on `machine`: the soft PLC,
/// which takes the project's own names and boxes, when it draws the file
/// whole (no map: it needs none).
fn elsewhere(document: &Document, machine: MachineId, pou: Option<&str>) -> Option<MachineId> {
    let soft = IEC_MACHINE;
    let takes = match document.import(Some(soft), None, pou) {
        Ok(_) => true,
        Err(errors) => pou.is_none() && st::drawn_apart(document, errors).is_ok(),
    };
    (machine != soft && takes).then_some(soft)
}

/// A warning in the page's words: the command line's advice (`--pou NAME
/// imports it alone`) is the Program picker's job here.
fn page_warning(warning: &str) -> &str {
    warning.split(" (--pou ").next().unwrap_or(warning)
}

/// Reads a request envelope and returns the reply's, as JSON. A message
/// that is not a request gets no reply (`None`): only the page sends any.
pub fn answer(message: &str) -> Option<String> {
    let Envelope { id, body } = serde_json::from_str::<Envelope<Request>>(message).ok()?;
    serde_json::to_string(&Envelope {
        id,
        body: handle(body),
    })
    .ok()
}

mod said_gate_ja;
pub mod said_iec_ja;
mod said_ja;
pub mod said_program_ja;
mod said_soft_ja;
pub mod said_st_ja;
pub use said_soft_ja::box_error_ja;
mod said_warning_ja;
mod st;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_st;
