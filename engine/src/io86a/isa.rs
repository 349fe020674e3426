//! PLC-IO86A's devices and instructions (machines.md §2): FX-style
//! mnemonics over X, Y, M, S, T, C, D and K.

use std::fmt;

pub use crate::operand::Io86aOperandError as OperandError;

/// A bit device: what contacts read and coils drive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Bit {
    /// Input `X00`-`X07`.
    X(u8),
    /// Output `Y00`-`Y05`.
    Y(u8),
    /// Relay `M00`-`M63` (M56-M63 special).
    M(u8),
    /// Plain relay `S00`-`S07`.
    S(u8),
    /// Timer contact `T00`-`T31`.
    T(u8),
    /// Counter contact `C00`-`C07`.
    C(u8),
}

/// A word operand: a constant or a current value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Word {
    /// `K0`-`K32767`.
    K(i16),
    /// Data register `D00`-`D07`.
    D(u8),
    /// A timer's current value (in its base units).
    T(u8),
    /// A counter's count.
    C(u8),
}

/// One instruction with its operands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Instruction {
    /// Start a block with a NO contact.
    Ld(Bit),
    /// Start a block with an NC contact.
    Ldi(Bit),
    /// Series NO contact.
    And(Bit),
    /// Series NC contact.
    Ani(Bit),
    /// Parallel NO contact.
    Or(Bit),
    /// Parallel NC contact.
    Ori(Bit),
    /// OR the current block with the one before it.
    Orb,
    /// AND the current block with the one before it.
    Anb,
    /// Drive a Y, M or S coil.
    Out(Bit),
    /// Drive timer `Tnn` with set value `preset` (`K` or `D`).
    OutTimer(u8, Word),
    /// Drive counter `Cnn` with set value `preset` (`K` or `D`).
    OutCounter(u8, Word),
    /// The bit is ON for one scan after the rung rises.
    Pls(Bit),
    /// The bit is ON for one scan after the rung falls.
    Plf(Bit),
    /// Latch a Y, M, S or C on.
    Set(Bit),
    /// Latch a Y, M, S or C off (a counter's count is cleared).
    Rst(Bit),
    /// Set Y/M of the linked device, every scan while ON.
    Sets(Bit),
    /// Reset Y/M of the linked device, every scan while ON.
    Rsts(Bit),
    /// Compare: M60 = S1>S2, M61 = S1=S2, M62 = S1<S2.
    Cmp(Word, Word),
    /// Copy a word into a D register.
    Mov(Word, u8),
    /// D += 1 (wrapping 32767 → -32768).
    Inc(u8),
    /// D -= 1.
    Dec(u8),
    /// End of the program.
    End,
}

impl Instruction {
    /// How many operand steps (`K10`, `D00`) follow the mnemonic when the
    /// operands are written on lines of their own.
    pub const fn operand_count(&self) -> usize {
        match self {
            Instruction::OutTimer(..) | Instruction::OutCounter(..) => 1,
            Instruction::Cmp(..) | Instruction::Mov(..) => 2,
            Instruction::Inc(_) | Instruction::Dec(_) => 1,
            _ => 0,
        }
    }
}

/// The largest set value or constant.
pub const K_MAX: i32 = 32767;

fn number(digits: &str, max: u8) -> Option<u8> {
    if digits.is_empty() || digits.len() > 2 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse::<u8>().ok().filter(|&n| n <= max)
}

/// Parses a bit device name (`X00`, `y5`, `M63`, `T31`, `C00`, `S07`).
pub fn parse_bit(text: &str) -> Result<Bit, OperandError> {
    let upper = text.to_ascii_uppercase();
    let bad = || OperandError::UnknownDevice(text.to_string());
    let mut chars = upper.chars();
    let kind = chars.next().ok_or_else(bad)?;
    let digits = chars.as_str();
    let bit = match kind {
        'X' => Bit::X(number(digits, 7).ok_or_else(bad)?),
        'Y' => Bit::Y(number(digits, 5).ok_or_else(bad)?),
        'M' => Bit::M(number(digits, 63).ok_or_else(bad)?),
        'S' => Bit::S(number(digits, 7).ok_or_else(bad)?),
        'T' => Bit::T(number(digits, 31).ok_or_else(bad)?),
        'C' => Bit::C(number(digits, 7).ok_or_else(bad)?),
        _ => return Err(bad()),
    };
    Ok(bit)
}

/// Parses a word operand (`K10`, `D00`, `T00`, `C03`).
pub fn parse_word(text: &str) -> Result<Word, OperandError> {
    let upper = text.to_ascii_uppercase();
    if let Some(k) = upper.strip_prefix('K') {
        let value: i32 = k
            .parse()
            .map_err(|_| OperandError::BadConstant(text.to_string()))?;
        if !(0..=K_MAX).contains(&value) {
            return Err(OperandError::BadConstant(text.to_string()));
        }
        return Ok(Word::K(value as i16));
    }
    if let Some(d) = upper.strip_prefix('D') {
        return number(d, 7)
            .map(Word::D)
            .ok_or_else(|| OperandError::UnknownDevice(text.to_string()));
    }
    match parse_bit(text)? {
        Bit::T(n) => Ok(Word::T(n)),
        Bit::C(n) => Ok(Word::C(n)),
        _ => Err(OperandError::NotAWord(text.to_string())),
    }
}

impl fmt::Display for Bit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (kind, n) = match *self {
            Bit::X(n) => ('X', n),
            Bit::Y(n) => ('Y', n),
            Bit::M(n) => ('M', n),
            Bit::S(n) => ('S', n),
            Bit::T(n) => ('T', n),
            Bit::C(n) => ('C', n),
        };
        write!(f, "{kind}{n:02}")
    }
}

impl fmt::Display for Word {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Word::K(k) => write!(f, "K{k}"),
            Word::D(n) => write!(f, "D{n:02}"),
            Word::T(n) => write!(f, "T{n:02}"),
            Word::C(n) => write!(f, "C{n:02}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn device_ranges() {
        assert_eq!(parse_bit("X07"), Ok(Bit::X(7)));
        assert_eq!(parse_bit("y5"), Ok(Bit::Y(5)));
        assert_eq!(parse_bit("M63"), Ok(Bit::M(63)));
        assert_eq!(parse_bit("T31"), Ok(Bit::T(31)));
        for bad in [
            "X08", "Y06", "M64", "S08", "T32", "C08", "Z00", "", "X", "X123",
        ] {
            assert!(parse_bit(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_word("K32767"), Ok(Word::K(32767)));
        assert_eq!(parse_word("D0"), Ok(Word::D(0)));
        assert_eq!(parse_word("T05"), Ok(Word::T(5)));
        assert!(matches!(
            parse_word("K32768"),
            Err(OperandError::BadConstant(_))
        ));
        assert!(matches!(
            parse_word("K-1"),
            Err(OperandError::BadConstant(_))
        ));
        assert!(matches!(parse_word("X00"), Err(OperandError::NotAWord(_))));
        assert!(matches!(
            parse_word("D08"),
            Err(OperandError::UnknownDevice(_))
        ));
    }
}
