//! Numbers in an LDmicro file, read as LDmicro 4.x reads them: its
//! `IsNumber` decides whether an operand is a number or a name, its
//! `hobatoi` gives the value (docs/ldmicro.md, "Reading a file").

use super::escape::unescape;

/// Whether an operand is a number rather than a variable's name, as
/// LDmicro's `IsNumber` decides it: a digit first, or one sign then a
/// digit (`-5`, `+0x10`; `--5` is a name), or a text of more than two
/// characters between single quotes (`'A'`, `'\n'`).
pub fn is_number(operand: &str) -> bool {
    let s = operand.trim_start();
    let unsigned = s.strip_prefix(['-', '+']).map(str::trim_start);
    match unsigned {
        Some(rest) => rest.starts_with(|c: char| c.is_ascii_digit()),
        None => {
            s.starts_with(|c: char| c.is_ascii_digit())
                || (s.len() > 2 && s.starts_with('\'') && s.ends_with('\''))
        }
    }
}

/// An LDmicro number's value, as `hobatoi` reads it into LDmicro's
/// 32-bit `long`: one sign, then `0x` hexadecimal (wrapping in 32 bits
/// as C's `strtoul` into a `long`: `0xFFFFFFFF` is −1), `0b` binary,
/// `0o` or a leading `0` octal, or decimal, each read up to the first
/// character that is no digit of its base and the rest ignored (`12abc`
/// is 12, `09` is 0, `1.5` is 1), past the 32-bit range held at its
/// end (`strtol`); or one character, or one escape, in single quotes
/// (`'A'`, `'\n'`; a byte above 127 is negative, LDmicro's `char` being
/// signed). `None` where LDmicro refuses it: quotes around more than
/// one character.
pub fn number(text: &str) -> Option<i64> {
    let s = text.trim_start();
    if s.starts_with('\'') {
        let quoted = s.strip_prefix('\'')?.strip_suffix('\'')?;
        let unescaped = unescape(quoted);
        let mut chars = unescaped.chars();
        return match (chars.next(), chars.next()) {
            (Some(c), None) => u8::try_from(u32::from(c)).ok().map(|b| i64::from(b as i8)),
            _ => None,
        };
    }
    let (negative, rest) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    let lower = rest.to_ascii_lowercase();
    let (radix, digits) = if let Some(d) = lower.strip_prefix("0x") {
        (16, d)
    } else if let Some(d) = lower.strip_prefix("0b") {
        (2, d)
    } else if let Some(d) = lower.strip_prefix("0o") {
        (8, d)
    } else if lower.starts_with('0') {
        (8, lower.as_str())
    } else {
        (10, lower.as_str())
    };
    // The digits of the base, up to the first that is none; their value
    // held at u64's end (far past 32 bits, where it is held again).
    let magnitude = digits
        .chars()
        .map_while(|c| c.to_digit(radix))
        .fold(0u64, |n, d| {
            n.saturating_mul(u64::from(radix))
                .saturating_add(u64::from(d))
        });
    Some(if radix == 16 {
        // `strtoul`: held at 0xFFFFFFFF, negated in 32 bits, then read
        // as a signed `long`.
        let m = u32::try_from(magnitude).unwrap_or(u32::MAX);
        let m = if negative { m.wrapping_neg() } else { m };
        i64::from(m as i32)
    } else {
        let signed = if negative {
            -(magnitude.min(1 << 31) as i64)
        } else {
            magnitude.min(i32::MAX as u64) as i64
        };
        signed.clamp(i64::from(i32::MIN), i64::from(i32::MAX))
    })
}

#[cfg(test)]
mod tests {
    use super::{is_number, number};

    #[test]
    fn is_number_is_ldmicros() {
        for n in ["5", "-5", "+5", "0x1F", "'A'", "12abc", "- 5"] {
            assert!(is_number(n), "{n}");
        }
        for n in ["--5", "+-5", "x5", "'A", "''", "-", "Tdelay"] {
            assert!(!is_number(n), "{n}");
        }
    }

    #[test]
    fn values_are_hobatois() {
        let cases: [(&str, i64); 20] = [
            ("42", 42),
            ("-42", -42),
            ("+42", 42),
            ("0x1F", 31),
            ("0X1f", 31),
            ("-0x10", -16),
            ("0xFFFFFFFF", -1),
            ("0x80000000", i64::from(i32::MIN)),
            ("0x123456789", -1),
            ("0b101", 5),
            ("0o17", 15),
            ("017", 15),
            ("09", 0),
            ("12abc", 12),
            ("1.5", 1),
            ("0x", 0),
            ("2147483648", i64::from(i32::MAX)),
            ("-2147483649", i64::from(i32::MIN)),
            ("'A'", 65),
            ("'\\n'", 10),
        ];
        for (text, value) in cases {
            assert_eq!(number(text), Some(value), "{text}");
        }
        assert_eq!(number("'AB'"), None);
        assert_eq!(number("'\u{e9}'"), Some(-23), "a signed char");
    }
}
