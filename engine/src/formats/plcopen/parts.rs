//! Small readers of an element's XML shared by the phases: its place,
//! its negation and edge marks, coils and timer coils it stands for.

use super::dom::Node;
use super::error::{ImportError, LowerError};
use crate::io86a::isa::{parse_bit, K_MAX};
use crate::io86a::machine::Timer;
use crate::io86a::Bit;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::Pos;

/// Whether a variable box's expression is a variable's name (not a
/// literal: `T#1s`, `10`, `TRUE`).
pub(super) fn is_variable_name(expr: &str) -> bool {
    let e = expr.trim();
    let first = e.chars().next();
    first.is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && !e.contains('#')
        && !matches!(e.to_ascii_uppercase().as_str(), "TRUE" | "FALSE")
        && e.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
}

pub(super) fn coil(kind: CoilKind, device: String) -> Element {
    Element::Coil { kind, device }
}

/// `OUT Tnn K…` from a TON named like an IO86A timer.
pub(super) fn timer_coil(name: &str, preset_ms: u32) -> Result<Element, ImportError> {
    let Ok(Bit::T(n)) = parse_bit(name) else {
        return Err(ImportError::TimerName(name.to_string()));
    };
    // The machine's own rule (T00-T23 count 100 ms, T24-T31 10 ms).
    let base = (Timer::base(n).as_nanos() / 1_000_000) as u32;
    if !preset_ms.is_multiple_of(base) {
        return Err(ImportError::TimerUnits {
            name: name.to_string(),
            ms: preset_ms,
            base,
        });
    }
    let preset = u16::try_from(preset_ms / base)
        .ok()
        .filter(|&k| i32::from(k) <= K_MAX)
        .ok_or_else(|| ImportError::TimerTooLong(name.to_string(), preset_ms))?;
    Ok(Element::TimerCoil {
        device: name.to_string(),
        preset,
    })
}

/// A connector's or continuation's name as they are matched: any case.
pub(super) fn connector_name(n: &Node) -> String {
    n.attr("name")
        .unwrap_or_default()
        .trim()
        .to_ascii_lowercase()
}

/// An XML Schema boolean attribute (`true`, `false`, `1`, `0`); absent
/// is false.
pub(super) fn negated(n: &Node) -> Result<bool, ImportError> {
    match n.attr("negated").map(str::trim) {
        None | Some("false" | "0") => Ok(false),
        Some("true" | "1") => Ok(true),
        Some(other) => Err(ImportError::NotBoolean(other.to_string())),
    }
}

/// The `edge` attribute: `None` for none, else `rising` or `falling`.
pub(super) fn edge(n: &Node) -> Result<Option<&'static str>, ImportError> {
    match n.attr("edge").map(str::trim) {
        None | Some("none") => Ok(None),
        Some("rising") => Ok(Some("rising")),
        Some("falling") => Ok(Some("falling")),
        Some(other) => Err(ImportError::BadEdge(other.to_string())),
    }
}

/// The coil `storage` attribute: `None` for none, else `set` or `reset`.
pub(super) fn storage(n: &Node) -> Result<Option<&'static str>, ImportError> {
    match n.attr("storage").map(str::trim) {
        None | Some("none") => Ok(None),
        Some("set") => Ok(Some("set")),
        Some("reset") => Ok(Some("reset")),
        Some(other) => Err(ImportError::BadStorage(other.to_string())),
    }
}

/// Where element number `seq` of the file, drawn at (`y`, `x`), sorts:
/// by row, then column, then file order. Saturating: on wasm32 a column
/// past what `usize` holds sorts last rather than wrap around.
pub(super) fn place(y: usize, x: usize, seq: usize) -> Pos {
    Pos::new(y, x.saturating_mul(PLACES_PER_X).saturating_add(seq))
}

/// Places in one drawn column ([`place`]).
pub(super) const PLACES_PER_X: usize = 65_536;

/// How far a split box's contact is placed from its coil
/// ([`Body::split_box`]): a place of its own, past every drawn one.
pub(super) const SPLIT_PLACES: usize = usize::MAX / 2;

/// The drawn column a place sorts in ([`place`], [`SPLIT_PLACES`]).
pub(super) fn drawn_x(col: usize) -> usize {
    col.checked_sub(SPLIT_PLACES).unwrap_or(col) / PLACES_PER_X
}

/// An element's `<position x y>` (0, 0 when absent or odd), as (y, x).
pub(super) fn position(n: &Node) -> (usize, usize) {
    let p = n.child("position");
    let num = |k: &str| {
        p.and_then(|p| p.attr(k))
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|v| v.is_finite() && *v >= 0.0 && *v < 1e7)
            .map_or(0, |v| v as usize)
    };
    (num("y"), num("x"))
}

/// The contact that conducts in the scan `c` starts conducting.
pub(super) fn rising(c: &Element) -> Result<Element, LowerError> {
    rekind(c, "IN is already an edge contact", |kind| match kind {
        ContactKind::No => Some(ContactKind::Rising),
        // NC conducts from when the device falls.
        ContactKind::Nc => Some(ContactKind::Falling),
        _ => None,
    })
}

/// The contact that conducts when `c` does not.
pub(super) fn invert(c: &Element) -> Result<Element, LowerError> {
    rekind(c, "an edge contact cannot be inverted", |kind| match kind {
        ContactKind::No => Some(ContactKind::Nc),
        ContactKind::Nc => Some(ContactKind::No),
        _ => None,
    })
}

/// Contact `c` on the same device with the kind `to` gives (`None`: the
/// reason `edge` says).
pub(super) fn rekind(
    c: &Element,
    edge: &'static str,
    to: impl Fn(ContactKind) -> Option<ContactKind>,
) -> Result<Element, LowerError> {
    match c {
        Element::Contact { kind, device } => Ok(Element::Contact {
            kind: to(*kind).ok_or(LowerError::Contact(edge))?,
            device: device.clone(),
        }),
        _ => Err(LowerError::Contact("not a contact")),
    }
}

/// The contact that gives box `e` (NOT, R_TRIG, F_TRIG) fed by a contact
/// of `kind`, when there is one: NOT turns NO and NC into each other; an
/// edge box on a NO contact is that edge's contact. An edge of an NC
/// contact or of an edge (and NOT of an edge) keeps its relay: R_TRIG of
/// NOT a fires in the first scan when a is off, a's falling contact
/// does not.
pub(super) fn turned(e: &Element, kind: ContactKind) -> Option<ContactKind> {
    match (e, kind) {
        (Element::Not, ContactKind::No) => Some(ContactKind::Nc),
        (Element::Not, ContactKind::Nc) => Some(ContactKind::No),
        (Element::Edge { falling: false }, ContactKind::No) => Some(ContactKind::Rising),
        (Element::Edge { falling: true }, ContactKind::No) => Some(ContactKind::Falling),
        _ => None,
    }
}
