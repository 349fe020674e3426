//! A program text a project keeps beside its ladder (issue #55): the
//! soft PLC's Structured Text, whose function blocks the ladder's boxes
//! call and whose `PROGRAM`, if any, runs when ST is chosen
//! (docs/soft-plc.md, "Structured Text in the page"). Kept as typed,
//! errors and all: it is checked where it is used, not when read.

use serde::{Deserialize, Serialize};

/// The language of a project's program text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    /// IEC 61131-3 Structured Text.
    St,
}

/// A project's program text.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProgramText {
    /// Its language (`"st"`).
    pub language: Language,
    /// The text as typed.
    pub text: String,
}

impl ProgramText {
    /// A Structured Text program.
    pub fn st(text: &str) -> ProgramText {
        ProgramText {
            language: Language::St,
            text: text.to_string(),
        }
    }
}
