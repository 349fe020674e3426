//! Map files (`--map MAP.csv`, the page's mapping table): `name,device`
//! a line, read as a CSV reader reads it, each device checked on the
//! machine at the map's own line.

use std::collections::HashMap;
use std::fmt;

use crate::error::Located;
use crate::ladder::target::{check_device, ElementError};
use crate::MachineId;

/// Why a map file's line does not read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MapError {
    /// Not two fields, an empty one, or a quote never closed (the line,
    /// shown).
    Malformed(String),
    /// A name mapped a second time (shown), and the line of the first.
    Twice {
        /// The name.
        name: String,
        /// The first line mapping it.
        first: usize,
    },
}

impl fmt::Display for MapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MapError::Malformed(line) => write!(f, "expected NAME,DEVICE, found {line}"),
            MapError::Twice { name, first } => {
                write!(f, "{name} is mapped twice (first at line {first})")
            }
        }
    }
}

impl std::error::Error for MapError {}

/// A map file: `name,device` a line (`#` comments, blank lines and a
/// `name,device` header skipped).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VarMap {
    /// (name, device, line), in file order.
    pub entries: Vec<(String, String, usize)>,
}

impl VarMap {
    /// A map of `pairs` (name, device), numbered as lines 1, 2, … (what
    /// a file of them would be: the page's mapping table, a proposal).
    pub fn from_pairs(pairs: impl IntoIterator<Item = (String, String)>) -> VarMap {
        let entries = pairs
            .into_iter()
            .enumerate()
            .map(|(i, (name, device))| (name, device, i + 1))
            .collect();
        VarMap { entries }
    }

    /// Reads a map file as a CSV reader would: a byte-order mark skipped,
    /// fields optionally in double quotes (`"I1","X00"`, `""` for a quote
    /// inside), `#` comments outside quotes, blank lines and a
    /// `name,device` header skipped; every malformed line is an error at
    /// its line.
    pub fn parse(text: &str) -> Result<VarMap, Vec<Located<MapError>>> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut entries = Vec::new();
        let mut errors = Vec::new();
        let mut seen: HashMap<String, usize> = HashMap::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let malformed = || MapError::Malformed(crate::shown(raw.trim()));
            let Some(fields) = csv_fields(raw) else {
                errors.push(Located::new(line, malformed()));
                continue;
            };
            let (name, device) = match fields.as_slice() {
                [] => continue,
                [name, device] => (name.as_str(), device.as_str()),
                _ => {
                    errors.push(Located::new(line, malformed()));
                    continue;
                }
            };
            if line == 1
                && name.eq_ignore_ascii_case("name")
                && device.eq_ignore_ascii_case("device")
            {
                continue;
            }
            if name.is_empty() || device.is_empty() {
                errors.push(Located::new(line, malformed()));
                continue;
            }
            if let Some(first) = seen.insert(name.to_ascii_lowercase(), line) {
                errors.push(Located::new(
                    line,
                    MapError::Twice {
                        name: crate::shown(name),
                        first,
                    },
                ));
                continue;
            }
            entries.push((name.to_string(), device.to_string(), line));
        }
        if errors.is_empty() {
            Ok(VarMap { entries })
        } else {
            Err(errors)
        }
    }

    /// Checks every device the map names (each part of a `T01+M20`) on
    /// `machine`, each error at the entry's line, before any import uses
    /// them.
    pub fn check(&self, machine: MachineId) -> Result<(), Vec<Located<ElementError>>> {
        let errors: Vec<_> = self
            .entries
            .iter()
            .flat_map(|(_, device, line)| {
                device
                    .split('+')
                    .filter_map(move |part| check_device(machine, part).err())
                    .map(move |e| Located::new(*line, e))
            })
            .collect();
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }
}

/// One CSV line's fields, trimmed, with `#` starting a comment outside
/// quotes; `None` when a quote is not closed or text follows one.
fn csv_fields(line: &str) -> Option<Vec<String>> {
    let mut fields = Vec::new();
    let mut chars = line.chars().peekable();
    loop {
        while chars.next_if(|c| *c == ' ' || *c == '\t').is_some() {}
        let mut field = String::new();
        if chars.next_if_eq(&'"').is_some() {
            loop {
                match chars.next()? {
                    '"' if chars.next_if_eq(&'"').is_some() => field.push('"'),
                    '"' => break,
                    c => field.push(c),
                }
            }
            while chars.next_if(|c| *c == ' ' || *c == '\t').is_some() {}
            if !matches!(chars.peek(), None | Some(',' | '#')) {
                return None;
            }
        } else {
            while let Some(c) = chars.next_if(|c| *c != ',' && *c != '#') {
                field.push(c);
            }
            field.truncate(field.trim_end().len());
        }
        let blank_line = fields.is_empty() && field.is_empty() && chars.peek() != Some(&',');
        if !blank_line {
            fields.push(field);
        }
        match chars.next() {
            Some(',') => continue,
            _ => return Some(fields),
        }
    }
}
