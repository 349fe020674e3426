//! Why a device name does not parse on MINASEC-U or the PLC-IO86A. Each
//! machine's assembler refuses an operand with these, and so does the
//! ladder's device check (`ladder::target::ElementError`): they sit below
//! both, so the ladder names no machine folder while each machine folder
//! implements the ladder's target (docs/architecture.md). The machines
//! re-export them as `minasec::isa::OperandError` and
//! `io86a::isa::OperandError`.

use std::fmt;

/// Why a MINASEC-U operand could not be parsed.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum MinasecOperandError {
    /// Not a MINASEC-U device name.
    UnknownDevice(String),
    /// A `%binary` or `$hex` address that is malformed or above 31.
    BadRawAddress(String),
}

impl fmt::Display for MinasecOperandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MinasecOperandError::UnknownDevice(d) => write!(
                f,
                "unknown device {}: MINASEC-U has X00-X07, Y00-Y07, M00-M07, M10-M13, T0, T1, C0, C0R", crate::error::shown(d)
            ),
            MinasecOperandError::BadRawAddress(d) => write!(
                f,
                "bad raw address {}: write %00000..%11111 or $00..$1F", crate::error::shown(d)
            ),
        }
    }
}

/// Why a PLC-IO86A operand could not be parsed.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Io86aOperandError {
    /// Not a device of the IO86A.
    UnknownDevice(String),
    /// A `K` constant outside 0..=32767 or malformed.
    BadConstant(String),
    /// A bit device where a word (K, D, T, C) is needed.
    NotAWord(String),
}

impl fmt::Display for Io86aOperandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Io86aOperandError::UnknownDevice(d) => write!(
                f,
                "unknown device {}: PLC-IO86A has X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07", crate::error::shown(d)
            ),
            Io86aOperandError::BadConstant(k) => write!(f, "bad constant {}: K0..K32767", crate::error::shown(k)),
            Io86aOperandError::NotAWord(d) => {
                write!(f, "{} is a bit: this operand is a word (K, D, T or C)", crate::error::shown(d))
            }
        }
    }
}
