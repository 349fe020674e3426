//! Reading the files a command names: `-` is standard input.

use std::io::Read;

use engine::limits::MAX_INPUT_BYTES;

/// A file's name as errors print it, and its text.
pub struct SourceFile {
    pub name: String,
    pub text: String,
}

impl SourceFile {
    /// Reads `path`, or standard input for `-`: UTF-8 text of at most
    /// [`MAX_INPUT_BYTES`] (a longer file is refused before it is read
    /// whole).
    pub fn read(path: &str) -> Result<SourceFile, String> {
        let name = if path == "-" {
            "<stdin>".to_string()
        } else {
            path.to_string()
        };
        let mut bytes = Vec::new();
        let limit = MAX_INPUT_BYTES as u64 + 1;
        let read = if path == "-" {
            std::io::stdin().lock().take(limit).read_to_end(&mut bytes)
        } else {
            std::fs::File::open(path).and_then(|f| f.take(limit).read_to_end(&mut bytes))
        };
        read.map_err(|e| format!("{name}: cannot read: {e}"))?;
        if bytes.len() > MAX_INPUT_BYTES {
            return Err(format!(
                "{name}: the file is larger than the {MAX_INPUT_BYTES} bytes an input may have (docs/limits.md)"
            ));
        }
        if name.to_ascii_lowercase().ends_with(".ld") {
            // LDmicro's users wrote their notes in Windows' code page.
            let text = engine::formats::ldmicro::decode(&bytes).into_owned();
            return Ok(SourceFile { name, text });
        }
        let text = String::from_utf8(bytes).map_err(|e| {
            let at = e.utf8_error().valid_up_to();
            let bytes = e.as_bytes();
            let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
            let column = at
                - bytes[..at]
                    .iter()
                    .rposition(|&b| b == b'\n')
                    .map_or(0, |p| p + 1)
                + 1;
            format!(
                "{name}:{line}: not UTF-8 text: byte {:#04x} at column {column} (byte offset {at})",
                bytes[at]
            )
        })?;
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
    /// An LDmicro file (`.ld`): runs on the soft PLC.
    Ld,
    /// Structured Text (`.st`): runs on the soft PLC.
    St,
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
                "ld" => Ok(Format::Ld),
                "st" => Ok(Format::St),
                other => Err(format!(
                    "unknown --format {}: il, asm, json, xml, ld or st",
                    engine::shown(other)
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
        } else if lower.ends_with(".ld") {
            Format::Ld
        } else if lower.ends_with(".st") {
            Format::St
        } else {
            Format::Il
        })
    }
}
