//! Parameters that do not fit together: a plant's own check of its
//! parameters (issue #52). Typed, as the alarms ([`super::alarm::AlarmKind`])
//! and the wiring's refusals ([`super::wiring::WireError`]) are, so that
//! the page says them in its language from the kind and the numbers;
//! `Display` is the English the command line says.

use std::fmt;

/// Why a plant's parameters, each within its range, do not fit together.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Misfit {
    /// The conveyor's part is longer than half its belt (mm).
    PartOverHalfBelt {
        /// `part`.
        part: i64,
        /// `length`.
        length: i64,
    },
    /// The tank's low switch is above its high switch (%).
    LowAboveHigh {
        /// `low_at`.
        low: i64,
        /// `high_at`.
        high: i64,
    },
    /// The sorter's part is longer than the pusher's face (mm).
    PartOverFace {
        /// `size`.
        part: i64,
        /// `face`.
        face: i64,
    },
    /// The sorter's belt is too short for two parts, or for the pusher
    /// (mm; the pusher spans `pusher_at..pusher_at + face`).
    BeltTooShort {
        /// `length`.
        length: i64,
        /// `size`.
        part: i64,
        /// Where the pusher's face begins.
        from: i64,
        /// Where it ends.
        to: i64,
    },
}

impl fmt::Display for Misfit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Misfit::PartOverHalfBelt { part, length } => write!(
                f,
                "part = {part} mm is more than half the belt (length = {length} mm)"
            ),
            Misfit::LowAboveHigh { low, high } => write!(
                f,
                "the low switch ({low} %) is above the high switch ({high} %)"
            ),
            Misfit::PartOverFace { part, face } => write!(
                f,
                "part = {part} mm is longer than the pusher's face (face = {face} mm)"
            ),
            Misfit::BeltTooShort {
                length,
                part,
                from,
                to,
            } => write!(
                f,
                "the belt (length = {length} mm) is too short for two parts of {part} mm, or for the pusher at {from}..{to} mm"
            ),
        }
    }
}

impl std::error::Error for Misfit {}
