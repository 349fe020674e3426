//! The block types Hashigo has a ladder form for, named once: the reader
//! checks a block against them, and an error lists them.

/// Blocks lowered to ladder (timers, counters, edges, boolean gates).
pub(super) const KNOWN_BLOCKS: &[&str] = &[
    "TON", "TOF", "TP", "CTU", "CTD", "CTUD", "R_TRIG", "F_TRIG", "NOT", "AND", "OR", "XOR", "SR",
    "RS",
];
pub(super) const COMPARISONS: &[&str] = &["GT", "GE", "EQ", "NE", "LE", "LT"];

/// Whether Hashigo has a ladder form for block type `ty` (upper case).
pub(super) fn is_known(ty: &str) -> bool {
    KNOWN_BLOCKS.contains(&ty) || COMPARISONS.contains(&ty)
}
