//! The standard blocks' parameters by name (IEC 61131-3's timers,
//! counters, edges and bistables, and LDmicro's elements run as blocks:
//! [`ldmicro`]): what every layer asks of a block's signature, from the
//! ladder's drawing to the soft PLC's loader. Their runtime is
//! `crate::runtime`.

pub mod ldmicro;

use super::data::DataType;

/// A counter's kind and count type: `CTU` and `CTU_INT` count INT,
/// `CTU_DINT` DINT … (CTD, CTUD alike); `None` for any other block.
pub fn counter(block: &str) -> Option<(&'static str, DataType)> {
    let (base, ty) = block.split_once('_').unwrap_or((block, "INT"));
    let base = ["CTU", "CTD", "CTUD"].into_iter().find(|b| *b == base)?;
    let ty = DataType::from_name(ty).filter(|t| {
        matches!(
            t,
            DataType::Int | DataType::Dint | DataType::Lint | DataType::Udint | DataType::Ulint
        )
    })?;
    Some((base, ty))
}

/// A block's inputs (name, type), in order.
pub fn inputs(block: &str) -> Vec<(&'static str, DataType)> {
    use DataType::{Bool, Time};
    if block.starts_with("LD_") {
        return ldmicro::inputs(block);
    }
    match counter(block) {
        Some(("CTU", n)) => vec![("CU", Bool), ("R", Bool), ("PV", n)],
        Some(("CTD", n)) => vec![("CD", Bool), ("LD", Bool), ("PV", n)],
        Some((_, n)) => vec![
            ("CU", Bool),
            ("CD", Bool),
            ("R", Bool),
            ("LD", Bool),
            ("PV", n),
        ],
        None => match block {
            "TON" | "TOF" | "TP" => vec![("IN", Bool), ("PT", Time)],
            "R_TRIG" | "F_TRIG" => vec![("CLK", Bool)],
            "SR" => vec![("S1", Bool), ("R", Bool)],
            "RS" => vec![("S", Bool), ("R1", Bool)],
            _ => Vec::new(),
        },
    }
}

/// A block's outputs (name, type), in order.
pub fn outputs(block: &str) -> Vec<(&'static str, DataType)> {
    use DataType::{Bool, Time};
    if block.starts_with("LD_") {
        return ldmicro::outputs(block);
    }
    match counter(block) {
        Some(("CTUD", n)) => vec![("QU", Bool), ("QD", Bool), ("CV", n)],
        Some((_, n)) => vec![("Q", Bool), ("CV", n)],
        None => match block {
            "TON" | "TOF" | "TP" => vec![("Q", Bool), ("ET", Time)],
            "R_TRIG" | "F_TRIG" => vec![("Q", Bool)],
            "SR" | "RS" => vec![("Q1", Bool)],
            _ => Vec::new(),
        },
    }
}

/// The standard function blocks a variable can be an instance of (and
/// LDmicro's: [`is_block_type`]).
pub const BLOCK_TYPES: [&str; 25] = [
    "TON",
    "TOF",
    "TP",
    "CTU",
    "CTD",
    "CTUD",
    "R_TRIG",
    "F_TRIG",
    "SR",
    "RS",
    "CTU_INT",
    "CTU_DINT",
    "CTU_LINT",
    "CTU_UDINT",
    "CTU_ULINT",
    "CTD_INT",
    "CTD_DINT",
    "CTD_LINT",
    "CTD_UDINT",
    "CTD_ULINT",
    "CTUD_INT",
    "CTUD_DINT",
    "CTUD_LINT",
    "CTUD_UDINT",
    "CTUD_ULINT",
];

/// Whether `name` (upper case) is a block a variable can be an instance
/// of: a standard one, or one of LDmicro's ([`ldmicro::NAMES`]).
pub fn is_block_type(name: &str) -> bool {
    BLOCK_TYPES.contains(&name) || ldmicro::NAMES.contains(&name)
}
