//! Devices in the editor: completion in the device entry, find, the
//! cross-reference list and batch replace (GX Works' device replace,
//! ranges included).

use std::collections::BTreeMap;

use crate::ladder::element::Element;
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::target::capabilities;
use crate::MachineId;

/// Every device name `machine` has, in its own spelling, in the order its
/// capability table lists them (`X00` … `X07`, `Y00` …). A machine with
/// word boxes (the soft PLC) has whatever I/O its program names: its
/// board's 8 inputs and 8 outputs are listed.
pub fn device_names(machine: MachineId) -> Vec<String> {
    if capabilities(machine).word_boxes {
        return ["%IX0.", "%QX0."]
            .iter()
            .flat_map(|area| (0..8).map(move |n| format!("{area}{n}")))
            .collect();
    }
    capabilities(machine)
        .devices
        .split(',')
        .map(str::trim)
        .flat_map(expand)
        .collect()
}

/// `X00-X07` → `X00` … `X07`; `R0.0-R31.7` → every bit; `T0` → itself;
/// `K` (a constant, not a device) → nothing.
fn expand(item: &str) -> Vec<String> {
    if item == "K" {
        return Vec::new();
    }
    let Some((a, b)) = item.split_once('-') else {
        return vec![item.to_string()];
    };
    if let (Some((ra, ba)), Some((rb, bb))) = (a.split_once('.'), b.split_once('.')) {
        // Register bits: R0.0-R31.7.
        let (Some(r0), Some(r1)) = (number(ra), number(rb)) else {
            return Vec::new();
        };
        let (Ok(b0), Ok(b1)) = (ba.parse::<u32>(), bb.parse::<u32>()) else {
            return Vec::new();
        };
        return (r0.1..=r1.1)
            .flat_map(|r| (b0..=b1).map(move |bit| format!("R{r}.{bit}")))
            .collect();
    }
    range(a, b).unwrap_or_default()
}

/// A name's letters and its number (`M07` → (`M`, 7, width 2)).
fn number(name: &str) -> Option<(String, u32, usize)> {
    let split = name.find(|c: char| c.is_ascii_digit())?;
    let (prefix, digits) = name.split_at(split);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((prefix.to_string(), digits.parse().ok()?, digits.len()))
}

/// `M00`, `M07` → `M00` … `M07` (same letters, same width).
fn range(a: &str, b: &str) -> Option<Vec<String>> {
    let (pa, na, wa) = number(a)?;
    let (pb, nb, _) = number(b)?;
    if !pa.eq_ignore_ascii_case(&pb) || nb < na || nb - na > 4096 {
        return None;
    }
    Some((na..=nb).map(|n| format!("{pa}{n:0wa$}")).collect())
}

/// The device entry's completion: every device of `machine` whose name
/// starts with `prefix` (any letter case) or whose comment contains it,
/// with its comment.
pub fn complete(
    machine: MachineId,
    prefix: &str,
    comments: &BTreeMap<String, String>,
) -> Vec<(String, Option<String>)> {
    let prefix = prefix.trim().to_ascii_uppercase();
    device_names(machine)
        .into_iter()
        .filter(|name| {
            name.to_ascii_uppercase().starts_with(&prefix)
                || (!prefix.is_empty()
                    && comments
                        .get(name)
                        .is_some_and(|c| c.to_ascii_uppercase().contains(&prefix)))
        })
        .map(|name| {
            let comment = comments.get(&name).cloned();
            (name, comment)
        })
        .collect()
}

/// The device entry's completion on a ladder with declared `variables`
/// (the soft PLC's): the variables whose name starts with `prefix` or
/// whose comment contains it come first, each with its comment (or its
/// type), then [`complete`]'s devices.
pub fn complete_declared(
    machine: MachineId,
    prefix: &str,
    comments: &BTreeMap<String, String>,
    variables: &[crate::ladder::Variable],
) -> Vec<(String, Option<String>)> {
    let upper = prefix.trim().to_ascii_uppercase();
    let mut out: Vec<(String, Option<String>)> = variables
        .iter()
        .filter(|v| {
            v.name.to_ascii_uppercase().starts_with(&upper)
                || (!upper.is_empty() && v.comment.to_ascii_uppercase().contains(&upper))
        })
        .map(|v| {
            let about = if v.comment.is_empty() {
                v.data_type.clone()
            } else {
                v.comment.clone()
            };
            (v.name.clone(), Some(about))
        })
        .collect();
    for (name, comment) in complete(machine, prefix, comments) {
        if !out.iter().any(|(n, _)| n.eq_ignore_ascii_case(&name)) {
            out.push((name, comment));
        }
    }
    out
}

/// How an element uses a device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UseRole {
    /// A contact reads it.
    Contact,
    /// A coil, timer or counter coil, or pulse output drives it.
    Coil,
    /// A data box reads or writes it.
    Box,
}

/// One place a device is used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Use {
    /// The rung (0-based).
    pub rung: usize,
    /// The cell.
    pub pos: Pos,
    /// How.
    pub role: UseRole,
}

/// The devices an element names, with how it uses each.
fn devices(e: &Element) -> Vec<(&str, UseRole)> {
    match e {
        Element::Contact { device, .. } => vec![(device, UseRole::Contact)],
        Element::Coil { device, .. }
        | Element::Pulse { device, .. }
        | Element::TimerCoil { device, .. }
        | Element::CounterCoil { device, .. } => vec![(device, UseRole::Coil)],
        Element::Mov { src, dst } => vec![(src, UseRole::Box), (dst, UseRole::Box)],
        Element::Cmp { a, b } => vec![(a, UseRole::Box), (b, UseRole::Box)],
        Element::Inc { dst } | Element::Dec { dst } => vec![(dst, UseRole::Box)],
        // An output box's outputs are written as a coil's device is (Why?
        // explains them by its rung's power).
        Element::Block(b) | Element::OutputBlock(b) => {
            let writes = if matches!(e, Element::OutputBlock(_)) {
                UseRole::Coil
            } else {
                UseRole::Box
            };
            b.inputs
                .iter()
                .map(|(_, o)| (o.as_str(), UseRole::Box))
                .chain(b.outputs.iter().map(|(_, o)| (o.as_str(), writes)))
                .filter(|(o, _)| crate::ladder::block::is_variable(o))
                .collect()
        }
        Element::Wire
        | Element::Not
        | Element::Edge { .. }
        | Element::Timer { .. }
        | Element::BoxInput { .. } => Vec::new(),
    }
}

/// The cross-reference list: every place `device` is used (any letter
/// case), rung by rung, top to bottom, left to right.
pub fn xref(ladder: &Ladder, device: &str) -> Vec<Use> {
    let mut out = Vec::new();
    for (rung, r) in ladder.rungs.iter().enumerate() {
        for (pos, e) in r.elements() {
            for (d, role) in devices(e) {
                if d.eq_ignore_ascii_case(device.trim()) {
                    out.push(Use { rung, pos, role });
                }
            }
        }
    }
    out
}

/// What find found: a cell, or a rung's comment (`pos` `None`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Found {
    /// The rung.
    pub rung: usize,
    /// The cell, if it is one.
    pub pos: Option<Pos>,
}

/// Ctrl+F: the rungs whose comment contains `text`, and the cells whose
/// device is `text` or whose device comment contains it (any letter case).
pub fn find(ladder: &Ladder, text: &str) -> Vec<Found> {
    let needle = text.trim().to_lowercase();
    if needle.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    for (rung, r) in ladder.rungs.iter().enumerate() {
        if r.comment.to_lowercase().contains(&needle) {
            out.push(Found { rung, pos: None });
        }
        for (pos, e) in r.elements() {
            let hit = devices(e).iter().any(|(d, _)| {
                d.to_lowercase() == needle
                    || ladder
                        .device_comments
                        .get(*d)
                        .is_some_and(|c| c.to_lowercase().contains(&needle))
            });
            if hit {
                out.push(Found {
                    rung,
                    pos: Some(pos),
                });
            }
        }
    }
    out
}

/// Why a batch replace's names do not make a plan.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReplaceError {
    /// A side names nothing.
    Empty,
    /// A range that is not two names of one kind, low to high (as written).
    Range(String),
    /// The two sides name different numbers of devices.
    Counts {
        /// What the replace takes, as written.
        from: String,
        /// How many devices that names.
        old: usize,
        /// What it puts instead, as written.
        to: String,
        /// How many devices that names.
        new: usize,
    },
}

impl std::fmt::Display for ReplaceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReplaceError::Empty => f.write_str("name a device or a range such as M00-M07"),
            ReplaceError::Range(spec) => write!(
                f,
                "{spec}: a range is two names of one kind, low to high, such as M00-M07"
            ),
            ReplaceError::Counts { from, old, to, new } => write!(
                f,
                "{from} names {old} devices but {to} names {new}: they must be as many"
            ),
        }
    }
}

impl std::error::Error for ReplaceError {}

/// A cell a replace changes: rung, cell, the element before and after.
pub type Replaced = (usize, Pos, Element, Element);

/// The preview of a batch replace: every cell whose devices change when
/// `from` becomes `to`. Both are one device (`X00` → `X03`) or ranges of
/// the same length (`M00-M07` → `M20-M27`); the error says why not.
pub fn replace_plan(ladder: &Ladder, from: &str, to: &str) -> Result<Vec<Replaced>, ReplaceError> {
    let names = |spec: &str| -> Result<Vec<String>, ReplaceError> {
        let spec = spec.trim();
        if spec.is_empty() {
            return Err(ReplaceError::Empty);
        }
        match spec.split_once('-') {
            Some((a, b)) => {
                range(a.trim(), b.trim()).ok_or_else(|| ReplaceError::Range(spec.to_string()))
            }
            None => Ok(vec![spec.to_string()]),
        }
    };
    let (old, new) = (names(from)?, names(to)?);
    if old.len() != new.len() {
        return Err(ReplaceError::Counts {
            from: from.trim().to_string(),
            old: old.len(),
            to: to.trim().to_string(),
            new: new.len(),
        });
    }
    let map: BTreeMap<String, &String> = old
        .iter()
        .map(|o| o.to_ascii_uppercase())
        .zip(new.iter())
        .collect();
    let swap = |d: &mut String| {
        if let Some(n) = map.get(&d.to_ascii_uppercase()) {
            *d = (*n).clone();
        }
    };
    let mut out = Vec::new();
    for (rung, r) in ladder.rungs.iter().enumerate() {
        for (pos, e) in r.elements() {
            let mut changed = e.clone();
            changed.names_mut(swap);
            if &changed != e {
                out.push((rung, pos, e.clone(), changed));
            }
        }
    }
    Ok(out)
}
