//! Reading the files a command names: `-` is standard input.

use std::io::Read;

/// A file's name as errors print it, and its text.
pub struct SourceFile {
    pub name: String,
    pub text: String,
}

impl SourceFile {
    /// Reads `path`, or standard input for `-`.
    pub fn read(path: &str) -> Result<SourceFile, String> {
        let (name, text) = if path == "-" {
            let mut text = String::new();
            std::io::stdin()
                .read_to_string(&mut text)
                .map_err(|e| format!("<stdin>: cannot read: {e}"))?;
            ("<stdin>".to_string(), text)
        } else {
            let bytes = std::fs::read(path).map_err(|e| format!("{path}: cannot read: {e}"))?;
            let text = String::from_utf8(bytes).map_err(|e| {
                format!(
                    "{path}: not UTF-8 text (first bad byte at offset {})",
                    e.utf8_error().valid_up_to()
                )
            })?;
            (path.to_string(), text)
        };
        Ok(SourceFile { name, text })
    }

    /// `error: FILE:LINE: message` bodies for located errors.
    pub fn located<E: std::fmt::Display>(&self, errors: &[engine::Located<E>]) -> Vec<String> {
        errors
            .iter()
            .map(|e| format!("{}:{}: {}", self.name, e.line, e.error))
            .collect()
    }
}

/// The program formats of cli.md.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Il,
    Asm,
    Json,
    Xml,
}

impl Format {
    /// From `--format`, or else the file's ending; anything else is the
    /// machine's own mnemonic text.
    pub fn choose(flag: Option<&str>, path: &str) -> Result<Format, String> {
        if let Some(f) = flag {
            return match f {
                "il" => Ok(Format::Il),
                "asm" => Ok(Format::Asm),
                "json" => Ok(Format::Json),
                "xml" => Ok(Format::Xml),
                other => Err(format!(
                    "unknown --format {}: il, asm, json or xml",
                    engine::shown(&other)
                )),
            };
        }
        let lower = path.to_ascii_lowercase();
        Ok(if lower.ends_with(".asm") {
            Format::Asm
        } else if lower.ends_with(".json") {
            Format::Json
        } else if lower.ends_with(".xml") {
            Format::Xml
        } else {
            Format::Il
        })
    }
}
