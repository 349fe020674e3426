//! Files that hold a ladder, each read in phases (text → document →
//! model) and written back: Hashigo's own project files ([`project`],
//! versioned JSON) and share links ([`share`]), PLCopen XML ([`plcopen`],
//! IEC 61131-10 TC6: drawn LD/FBD bodies and IL, for the bit machines'
//! lowering and for the soft PLC as written) and LDmicro's `.ld` files
//! ([`ldmicro`]). [`Document`] is the one way in: a file opened once,
//! then asked for its programs, a map and its ladder for a machine.
//! `ladder/` imports nothing from here.

pub mod document;
pub mod ldmicro;
pub mod plcopen;
pub mod project;
pub mod share;

pub use document::{Document, FileError, Kind, Opened};
pub use project::{Project, ProjectError};
