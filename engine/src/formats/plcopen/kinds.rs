//! The block types Hashigo has a ladder form for, named once: a block's
//! `typeName` is parsed into a [`BlockKind`] when it is read, and
//! everything after matches on the kind.

use std::fmt;

use crate::iec::Comparison;

/// A block type Hashigo lowers to ladder.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum BlockKind {
    /// On-delay timer.
    Ton,
    /// Off-delay timer.
    Tof,
    /// Pulse timer.
    Tp,
    /// Up-counter.
    Ctu,
    /// Down-counter.
    Ctd,
    /// Up-down counter.
    Ctud,
    /// Rising edge.
    RTrig,
    /// Falling edge.
    FTrig,
    /// NOT.
    Not,
    /// AND of two or more inputs.
    And,
    /// OR of two or more inputs.
    Or,
    /// XOR of two inputs.
    Xor,
    /// Set-dominant flip-flop.
    Sr,
    /// Reset-dominant flip-flop.
    Rs,
    /// A comparison of words.
    Compare(Comparison),
}

/// Every block type by its IEC name.
const NAMES: [(&str, BlockKind); 20] = [
    ("TON", BlockKind::Ton),
    ("TOF", BlockKind::Tof),
    ("TP", BlockKind::Tp),
    ("CTU", BlockKind::Ctu),
    ("CTD", BlockKind::Ctd),
    ("CTUD", BlockKind::Ctud),
    ("R_TRIG", BlockKind::RTrig),
    ("F_TRIG", BlockKind::FTrig),
    ("NOT", BlockKind::Not),
    ("AND", BlockKind::And),
    ("OR", BlockKind::Or),
    ("XOR", BlockKind::Xor),
    ("SR", BlockKind::Sr),
    ("RS", BlockKind::Rs),
    ("GT", BlockKind::Compare(Comparison::Gt)),
    ("GE", BlockKind::Compare(Comparison::Ge)),
    ("EQ", BlockKind::Compare(Comparison::Eq)),
    ("NE", BlockKind::Compare(Comparison::Ne)),
    ("LE", BlockKind::Compare(Comparison::Le)),
    ("LT", BlockKind::Compare(Comparison::Lt)),
];

impl BlockKind {
    /// The kind a `typeName` names (any case), if Hashigo has one.
    pub(super) fn parse(type_name: &str) -> Option<BlockKind> {
        NAMES
            .iter()
            .find(|(name, _)| name.eq_ignore_ascii_case(type_name.trim()))
            .map(|(_, kind)| *kind)
    }

    /// Its IEC name (`TON`, `R_TRIG`, `GT`).
    pub(super) fn name(self) -> &'static str {
        NAMES
            .iter()
            .find(|(_, kind)| *kind == self)
            .map_or("?", |(name, _)| name)
    }
}

impl fmt::Display for BlockKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The names of the blocks that are (`comparisons`) or are not
/// comparisons, for messages: `TON, TOF, …`.
pub(super) fn names(comparisons: bool) -> String {
    let list: Vec<&str> = NAMES
        .iter()
        .filter(|(_, k)| matches!(k, BlockKind::Compare(_)) == comparisons)
        .map(|(name, _)| *name)
        .collect();
    list.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_reads_back_from_its_name() {
        for (name, kind) in NAMES {
            assert_eq!(BlockKind::parse(name), Some(kind));
            assert_eq!(BlockKind::parse(&name.to_ascii_lowercase()), Some(kind));
            assert_eq!(kind.name(), name);
        }
        assert_eq!(BlockKind::parse("PID"), None);
        assert_eq!(names(true), "GT, GE, EQ, NE, LE, LT");
    }
}
