//! What each name of an LDmicro file is — a bit, a number or a STRING's
//! text — as its elements use it; a name used as two of them is an error
//! at each line that uses it otherwise, in LDmicro's terms (`MOVE Yb 5`
//! where `Yb` is a coil), every one at once.

use std::collections::HashMap;

use super::element::{is_number, Element as Ld};
use super::elements::OPEN;
use super::error::LdError;
use super::file::LdFile;
use crate::error::Located;

/// What a name is in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Role {
    Bit,
    Number,
    /// A STRING's destination.
    Text,
}

impl Role {
    /// The role in LDmicro's words.
    pub(super) fn said(self) -> &'static str {
        match self {
            Role::Bit => "a bit",
            Role::Number => "a number",
            Role::Text => "a STRING's text",
        }
    }
}

/// One use of a name: the name, what it is there, the line and what
/// uses it (an element's keyword, or the `IO LIST`).
struct Use {
    name: String,
    role: Role,
    line: usize,
    by: String,
}

/// Every use of a name in the file, in file order (the IO LIST's `X…`
/// and `Y…` first, as bits), without numbers and the BOOLs the lowering
/// holds power in.
fn uses(file: &LdFile) -> Vec<Use> {
    let io = file
        .io
        .iter()
        .filter(|io| io.name.starts_with(['X', 'Y']))
        .map(|io| Use {
            name: io.name.clone(),
            role: Role::Bit,
            line: io.line,
            by: "the IO LIST".into(),
        });
    let used = file.elements().flat_map(|(e, line)| {
        names_used(e).into_iter().map(move |(name, role)| Use {
            name,
            role,
            line,
            by: e.keyword().to_string(),
        })
    });
    io.chain(used)
        .filter_map(|mut u| {
            u.name = u.name.trim().to_string();
            // The BOOLs the lowering holds power in are the compiler's to
            // declare (they read back so from a file written out).
            let held = u
                .name
                .strip_prefix("_ld")
                .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
            (!u.name.is_empty() && !is_number(&u.name) && !held).then_some(u)
        })
        .collect()
}

/// Each name the file's elements use and what it is, in the order the
/// board and the variables pane show them (the IO LIST's first). A name
/// used as two things is a bit if it is one anywhere, else a number
/// ([`conflicts`] refuses such a file).
pub(super) fn roles(file: &LdFile) -> Vec<(String, Role)> {
    let mut roles: Vec<(String, Role)> = Vec::new();
    let mut at: HashMap<String, usize> = HashMap::new();
    for u in uses(file) {
        match at.get(&u.name) {
            Some(&k) => roles[k].1 = roles[k].1.min(u.role),
            None => {
                at.insert(u.name.clone(), roles.len());
                roles.push((u.name, u.role));
            }
        }
    }
    roles
}

/// Each use of a name as something other than its first use made it,
/// an error at its line naming both (`renamed`: the LDmicro name of a
/// name given an IEC one).
pub(super) fn conflicts(file: &LdFile, renamed: &HashMap<String, String>) -> Vec<Located<LdError>> {
    let mut first: HashMap<String, Use> = HashMap::new();
    let mut said = std::collections::HashSet::new();
    let mut errors = Vec::new();
    for u in uses(file) {
        let Some(f) = first.get(&u.name) else {
            first.insert(u.name.clone(), u);
            continue;
        };
        // `ADD Xa Xa 1` says it once for its line.
        if f.role != u.role && said.insert((u.line, u.name.clone())) {
            let name = renamed.get(&u.name).unwrap_or(&u.name).clone();
            errors.push(Located::new(
                u.line,
                LdError::Role {
                    name,
                    here: format!("{} for {}", u.role.said(), u.by),
                    there: format!("{} for {} at line {}", f.role.said(), f.by, f.line),
                },
            ));
        }
    }
    errors
}

/// The names one element uses, each as a bit or a number.
fn names_used(e: &Ld) -> Vec<(String, Role)> {
    let numbers = |names: &[&str]| -> Vec<(String, Role)> {
        names
            .iter()
            .map(|n| (n.to_string(), Role::Number))
            .collect()
    };
    match e {
        Ld::Contacts { name, .. } | Ld::Coil { name, .. } => vec![(name.clone(), Role::Bit)],
        Ld::Open => vec![(OPEN.to_string(), Role::Bit)],
        Ld::MasterRelay => vec![(super::lower::MCR.to_string(), Role::Bit)],
        Ld::Timer { name, delay, .. } => numbers(&[name, delay]),
        Ld::Counter {
            name, max, init, ..
        } => numbers(&[name, max, init]),
        Ld::Res(name) | Ld::ReadAdc { name, .. } | Ld::Persist(name) => numbers(&[name]),
        Ld::TimeConvert { name, .. } => numbers(&[name]),
        Ld::Unary { dest, src, .. } => numbers(&[dest, src]),
        Ld::Math { dest, a, b, .. } => numbers(&[dest, a, b]),
        Ld::Compare { a, b, .. } => numbers(&[a, b]),
        Ld::ShiftRegister { name, stages } => (0..*stages)
            .map(|k| (format!("{name}{k}"), Role::Number))
            .collect(),
        Ld::Bit { var, bit, .. } => numbers(&[var, bit]),
        Ld::LookUpTable { dest, index, .. } => numbers(&[dest, index]),
        Ld::PiecewiseLinear { dest, index, .. } => numbers(&[dest, index, super::elements::PWL]),
        Ld::SetPwm { duty, .. } => numbers(&[duty]),
        Ld::UartSend { name, .. } | Ld::UartRecv { name, .. } => numbers(&[name]),
        Ld::FormattedString { var, .. } => numbers(&[var]),
        Ld::Text { dest, var, .. } => {
            let mut names = numbers(&[var]);
            names.push((dest.clone(), Role::Text));
            names
        }
        Ld::Segments { dest, src, .. } => numbers(&[dest, src]),
        _ => Vec::new(),
    }
}
