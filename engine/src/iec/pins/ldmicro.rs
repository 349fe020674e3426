//! The LDmicro blocks' names and parameters (`crate::runtime::ldmicro` runs
//! them): which inputs each takes and which outputs it gives, in order,
//! with their types, and the one input given as a text.

use crate::iec::data::DataType;

/// The LDmicro blocks by name.
pub const NAMES: [&str; 48] = [
    "LD_TON",
    "LD_TOF",
    "LD_RTO",
    "LD_RTL",
    "LD_TCY",
    "LD_THI",
    "LD_TLO",
    "LD_CTU",
    "LD_CTD",
    "LD_CTC",
    "LD_CTR",
    "LD_OSL",
    "LD_OSC",
    "LD_TOGGLE",
    "LD_BIN2BCD",
    "LD_BCD2BIN",
    "LD_SWAP",
    "LD_OPPOSITE",
    "LD_SR0",
    "LD_SETBIT",
    "LD_CLRBIT",
    "LD_IFBIT",
    "LD_IFNBIT",
    "LD_ADD",
    "LD_SUB",
    "LD_MUL",
    "LD_DIV",
    "LD_MOD",
    "LD_AND",
    "LD_OR",
    "LD_XOR",
    "LD_SHL",
    "LD_SHR",
    "LD_ROL",
    "LD_ROR",
    "LD_MOVE",
    "LD_NOT",
    "LD_NEG",
    "LD_UART_SEND",
    "LD_UART_RECV",
    "LD_UART_AVAIL",
    "LD_UART_READY",
    "LD_FMTSTR",
    "LD_STRING",
    "LD_SEG7",
    "LD_SEG9",
    "LD_SEG14",
    "LD_SEG16",
];

/// The input of a block given as a text (LDmicro's formatted string:
/// `FMT := 'Hello \-5$R$N'`; its STRING's C format: `FMT := 'n=%d'`),
/// fixed for the instance; `None` for a block without one.
pub fn text_input(block: &str) -> Option<&'static str> {
    matches!(block, "LD_FMTSTR" | "LD_STRING").then_some("FMT")
}

/// A block's inputs (name, type), in order.
pub fn inputs(block: &str) -> Vec<(&'static str, DataType)> {
    use DataType::{Bool, Dint, Int};
    match family(block) {
        // D: the destination as it is, given back while unpowered.
        Some(Family::Text) => vec![("IN", Bool), ("V", Dint), ("D", DataType::String)],
        Some(Family::Timer) => vec![("IN", Bool), ("P", Dint), ("T", Dint)],
        Some(Family::Counter) => vec![
            ("IN", Bool),
            ("MAX", Dint),
            ("INIT", Dint),
            ("C", Dint),
            ("EDGE", Int),
        ],
        Some(Family::Shot) => vec![("IN", Bool)],
        Some(Family::Toggle) => vec![("IN", Bool), ("V", Bool)],
        Some(Family::Op) => vec![
            ("IN", Bool),
            ("A", Dint),
            ("B", Dint),
            ("D", Dint),
            ("W", Int),
        ],
        Some(Family::Serial) if block == "LD_FMTSTR" => vec![("IN", Bool), ("V", Dint)],
        // N: how many of V's bytes, the lowest first (1 when 0).
        Some(Family::Serial) => vec![("IN", Bool), ("V", Dint), ("N", Int)],
        None => Vec::new(),
    }
}

/// A block's outputs (name, type), in order: the power it passes on
/// first.
pub fn outputs(block: &str) -> Vec<(&'static str, DataType)> {
    use DataType::{Bool, Dint};
    match family(block) {
        Some(Family::Text) => vec![("Q", Bool), ("D", DataType::String)],
        Some(Family::Timer) => vec![("Q", Bool), ("T", Dint)],
        Some(Family::Counter) => vec![("Q", Bool), ("C", Dint)],
        Some(Family::Shot) => vec![("Q", Bool)],
        Some(Family::Toggle) => vec![("Q", Bool), ("V", Bool)],
        // A segment digit's source comes back as LDmicro rewrites it.
        Some(Family::Op) if block.starts_with("LD_SEG") => {
            vec![("Q", Bool), ("D", Dint), ("A", Dint)]
        }
        Some(Family::Op) => vec![("Q", Bool), ("D", Dint)],
        Some(Family::Serial) if block == "LD_UART_RECV" => vec![("Q", Bool), ("V", Dint)],
        Some(Family::Serial) => vec![("Q", Bool)],
        None => Vec::new(),
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Family {
    Timer,
    Counter,
    Shot,
    Toggle,
    /// LDmicro's word operations the IEC functions lack: `D := f(A, B)`
    /// in a `W`-bit word (16 when 0), or (IFBIT) a test passing power.
    Op,
    /// The serial port's: a byte `V` sent or received, a formatted
    /// string sent (LD_UART_AVAIL and LD_UART_READY take only IN).
    Serial,
    /// LDmicro's STRING: `D := sprintf(FMT, V)` while powered (the text
    /// is the instance's, `crate::runtime::instance::Instance` prints it).
    Text,
}

fn family(block: &str) -> Option<Family> {
    match block {
        "LD_TON" | "LD_TOF" | "LD_RTO" | "LD_RTL" | "LD_TCY" | "LD_THI" | "LD_TLO" => {
            Some(Family::Timer)
        }
        "LD_CTU" | "LD_CTD" | "LD_CTC" | "LD_CTR" => Some(Family::Counter),
        "LD_OSL" | "LD_OSC" | "LD_UART_AVAIL" | "LD_UART_READY" => Some(Family::Shot),
        "LD_UART_SEND" | "LD_UART_RECV" | "LD_FMTSTR" => Some(Family::Serial),
        "LD_TOGGLE" => Some(Family::Toggle),
        "LD_STRING" => Some(Family::Text),
        "LD_BIN2BCD" | "LD_BCD2BIN" | "LD_SWAP" | "LD_OPPOSITE" | "LD_SR0" | "LD_SETBIT"
        | "LD_CLRBIT" | "LD_IFBIT" | "LD_IFNBIT" | "LD_ADD" | "LD_SUB" | "LD_MUL" | "LD_DIV"
        | "LD_MOD" | "LD_AND" | "LD_OR" | "LD_XOR" | "LD_SHL" | "LD_SHR" | "LD_ROL" | "LD_ROR"
        | "LD_MOVE" | "LD_NOT" | "LD_NEG" | "LD_SEG7" | "LD_SEG9" | "LD_SEG14" | "LD_SEG16" => {
            Some(Family::Op)
        }
        _ => None,
    }
}
