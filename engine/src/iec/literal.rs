//! IEC 61131-3 literals: `TRUE`, `42`, `-5`, `16#FF`, `2#1010_0101`,
//! `INT#-5`, `UINT#16#FFFF`, `1.5`, `1.0E3`, `REAL#2`, `T#500ms`,
//! `TIME#1h2m3.5s`. A literal never wraps: one outside its type's range
//! is refused.

use std::fmt;

use super::data::{Data, DataType, STRING_CAPACITY};

/// Why a literal is not one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LiteralError {
    /// Nothing was written.
    Empty,
    /// `XYZ#…` names no type the soft PLC has.
    UnknownType(String),
    /// Not a number in the base it gives.
    BadNumber(String),
    /// A number outside its type's range.
    OutOfRange { text: String, data_type: DataType },
    /// Not a duration (`T#` then numbers with d, h, m, s, ms, us, ns).
    BadTime(String),
    /// A literal of one type where another is needed.
    WrongType { text: String, expected: DataType },
    /// A string literal (`'…'`) not closed, or with a `$` escape IEC
    /// has not.
    BadText(String),
    /// A string literal of more characters (given) than a STRING holds.
    TooLong(usize),
    /// A character a STRING's one byte cannot hold (above U+00FF).
    WideChar(char),
}

impl fmt::Display for LiteralError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LiteralError::Empty => write!(f, "a value is missing"),
            LiteralError::UnknownType(t) => write!(f, "unknown type `{t}`"),
            LiteralError::BadNumber(t) => write!(f, "`{t}` is not a number"),
            LiteralError::OutOfRange { text, data_type } => {
                write!(f, "`{text}` is out of range for {}", data_type.name())
            }
            LiteralError::BadTime(t) => {
                write!(f, "`{t}` is not a duration (e.g. T#500ms, T#1h2m3.5s)")
            }
            LiteralError::WrongType { text, expected } => {
                // "an INT"; every other name starts with a consonant's
                // sound (UINT is "you-int").
                let article = if *expected == DataType::Int { "an" } else { "a" };
                write!(f, "`{text}` is not {article} {} value", expected.name())
            }
            LiteralError::TooLong(n) => write!(
                f,
                "a STRING holds at most {STRING_CAPACITY} characters; this text has {n}"
            ),
            LiteralError::WideChar(c) => write!(
                f,
                "`{c}` (U+{:04X}) is not a one-byte character: a STRING holds U+0000 … U+00FF",
                u32::from(*c)
            ),
            LiteralError::BadText(t) => write!(
                f,
                "`{t}` is not a string literal: '…' with $$ $' $R $N $L $T $P or $hh for other bytes"
            ),
        }
    }
}

impl std::error::Error for LiteralError {}

/// Reads `text` as a literal and says which type it fixes: `None` for an
/// untyped integer (`42`), which takes the type of its place; a typed
/// literal, a decimal (a REAL), a time or a BOOL fixes its own.
pub fn literal_type(text: &str) -> Result<(Data, Option<DataType>), LiteralError> {
    let d = parse_literal(text, None)?;
    let typed = text.contains('#') || text.contains('.') || d.data_type().bits().is_none();
    let fixed = typed.then(|| d.data_type());
    Ok((d, fixed))
}

/// Reads `text` as a literal. `expected` is the type the place needs: an
/// untyped number takes it (without one, an integer is a DINT and a
/// decimal a REAL); a typed literal of another type is refused.
pub fn parse_literal(text: &str, expected: Option<DataType>) -> Result<Data, LiteralError> {
    let text = text.trim();
    if text.is_empty() {
        return Err(LiteralError::Empty);
    }
    if text.starts_with('\'') || expected == Some(DataType::String) {
        return string(text, expected);
    }
    let (typed, body) = match text.split_once('#') {
        Some((prefix, rest)) if prefix.chars().all(|c| c.is_ascii_alphabetic()) => {
            let t = match prefix.to_ascii_uppercase().as_str() {
                "T" => DataType::Time,
                _ => DataType::from_name(prefix)
                    .ok_or_else(|| LiteralError::UnknownType(prefix.to_string()))?,
            };
            (Some(t), rest)
        }
        _ => (None, text),
    };
    if let (Some(t), Some(e)) = (typed, expected) {
        if t != e {
            return Err(LiteralError::WrongType {
                text: text.to_string(),
                expected: e,
            });
        }
    }
    let t = typed.or(expected);
    let value = match t {
        Some(DataType::Time) => Data::Time(time(body, text)?),
        Some(DataType::Bool) => match body.to_ascii_uppercase().as_str() {
            "TRUE" | "1" => Data::Bool(true),
            "FALSE" | "0" => Data::Bool(false),
            _ => {
                return Err(LiteralError::WrongType {
                    text: text.to_string(),
                    expected: DataType::Bool,
                })
            }
        },
        Some(DataType::Real) => {
            Data::Real(real(body).ok_or_else(|| LiteralError::BadNumber(text.into()))?)
        }
        Some(DataType::Lreal) => {
            Data::Lreal(real64(body).ok_or_else(|| LiteralError::BadNumber(text.into()))?)
        }
        Some(int_type) => {
            let v = integer(body).ok_or_else(|| LiteralError::BadNumber(text.into()))?;
            in_range(int_type, v).ok_or_else(|| LiteralError::OutOfRange {
                text: text.to_string(),
                data_type: int_type,
            })?
        }
        None => untyped(text, body)?,
    };
    Ok(value)
}

/// A literal without a type (`body`, of the literal `text`): a BOOL, a
/// decimal (a REAL), or an integer (a DINT, a LINT when it needs 64
/// bits).
fn untyped(text: &str, body: &str) -> Result<Data, LiteralError> {
    let upper = body.to_ascii_uppercase();
    if upper == "TRUE" || upper == "FALSE" {
        return Ok(Data::Bool(upper == "TRUE"));
    }
    if body.contains(['.', 'e', 'E']) && !body.contains('#') {
        let r = real(body).ok_or_else(|| LiteralError::BadNumber(text.into()))?;
        return Ok(Data::Real(r));
    }
    let too_big = || LiteralError::OutOfRange {
        text: text.to_string(),
        data_type: DataType::Lint,
    };
    // One sign at most: `--5` is not a number.
    let digits = body.strip_prefix(['-', '+']).unwrap_or(body);
    let v = match integer(body) {
        Some(v) => v,
        // All digits, yet no integer: more than 64 bits hold.
        None if !digits.is_empty()
            && underscores_between_digits(digits)
            && digits.bytes().all(|c| c.is_ascii_digit() || c == b'_') =>
        {
            return Err(too_big())
        }
        None => return Err(LiteralError::BadNumber(text.into())),
    };
    in_range(DataType::Dint, v)
        .or_else(|| in_range(DataType::Lint, v))
        .ok_or_else(too_big)
}

/// The value of an untyped integer literal (`42`, `-5`, `16#FF`,
/// `1_000`), which takes the type of its use; `None` for any other text
/// (a typed, decimal, time, BOOL or bad literal).
pub fn untyped_integer(text: &str) -> Option<i128> {
    let text = text.trim();
    let typed = text
        .split_once('#')
        .is_some_and(|(prefix, _)| prefix.chars().all(|c| c.is_ascii_alphabetic()));
    if typed {
        return None;
    }
    integer(text)
}

/// A STRING literal, where the place takes one.
fn string(text: &str, expected: Option<DataType>) -> Result<Data, LiteralError> {
    match expected {
        Some(t) if t != DataType::String => Err(LiteralError::WrongType {
            text: text.to_string(),
            expected: t,
        }),
        _ if !text.starts_with('\'') => Err(LiteralError::WrongType {
            text: text.to_string(),
            expected: DataType::String,
        }),
        _ => string_value(parse_text(text)?),
    }
}

/// A text (its `$` escapes read) as a STRING value; refused when it has
/// more characters than a STRING holds.
pub fn string_value(text: impl Into<String>) -> Result<Data, LiteralError> {
    let text = text.into();
    if let Some(c) = text.chars().find(|&c| u32::from(c) > 0xFF) {
        return Err(LiteralError::WideChar(c));
    }
    match text.chars().count() {
        n if n > STRING_CAPACITY => Err(LiteralError::TooLong(n)),
        _ => Ok(Data::text(text)),
    }
}

/// `v` as type `t` if it is within its range.
pub(crate) fn in_range(t: DataType, v: i128) -> Option<Data> {
    let (lo, hi) = t.range()?;
    (lo..=hi).contains(&v).then(|| Data::integer(t, v))
}

/// An integer: an optional sign, then decimal digits or `base#digits`
/// (base 2, 8 or 16), `_` between digits.
fn integer(s: &str) -> Option<i128> {
    let (negative, s) = match s.as_bytes().first()? {
        b'-' => (true, &s[1..]),
        b'+' => (false, &s[1..]),
        _ => (false, s),
    };
    let (base, digits) = match s.split_once('#') {
        Some(("2", d)) => (2, d),
        Some(("8", d)) => (8, d),
        Some(("16", d)) => (16, d),
        Some(_) => return None,
        None => (10, s),
    };
    if digits.is_empty() || !underscores_between_digits(digits) {
        return None;
    }
    let mut v: i128 = 0;
    for c in digits.chars().filter(|&c| c != '_') {
        v = v
            .checked_mul(base)?
            .checked_add(i128::from(c.to_digit(base as u32)?))?;
        if v > i128::from(u64::MAX) {
            return None;
        }
    }
    Some(if negative { -v } else { v })
}

/// A decimal number: digits with an optional fraction and exponent
/// (`1.5`, `-0.25`, `1.0E3`, `2`), `_` between digits.
fn real(s: &str) -> Option<f32> {
    real64(s)
        .map(|r| r as f32)
        .filter(|r| r.is_finite())
        // The f32 nearest the text itself, not the f64's rounded again.
        .and_then(|_| s.replace('_', "").parse::<f32>().ok())
}

/// An LREAL's digits (`1.5`, `2.5E-3`, `1_000.0`), finite.
fn real64(s: &str) -> Option<f64> {
    if !underscores_between_digits(s) {
        return None;
    }
    let clean: String = s.chars().filter(|&c| c != '_').collect();
    let valid = !clean.is_empty()
        && clean
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-'))
        && clean.chars().any(|c| c.is_ascii_digit());
    valid
        .then(|| clean.parse::<f64>().ok())
        .flatten()
        .filter(|r| r.is_finite())
}

/// Whether every `_` in `s` stands between two digits (of any base).
fn underscores_between_digits(s: &str) -> bool {
    let b = s.as_bytes();
    b.iter().enumerate().all(|(i, &c)| {
        c != b'_'
            || (i > 0
                && i + 1 < b.len()
                && b[i - 1].is_ascii_alphanumeric()
                && b[i + 1].is_ascii_alphanumeric())
    })
}

/// A TIME literal (`T#500ms`, `TIME#1.5s`, `t#1m30s`) in whole
/// milliseconds, as the bit machines' timer presets are kept: the one
/// TIME grammar [`parse_literal`] reads, rounded to the nearest
/// millisecond (halves up); `None` for anything else, a negative time or
/// one past `u32::MAX` ms.
pub fn parse_time_literal(text: &str) -> Option<u32> {
    let (prefix, body) = text.trim().split_once('#')?;
    if !matches!(prefix.to_ascii_uppercase().as_str(), "T" | "TIME") {
        return None;
    }
    let ns = time(body, text).ok().filter(|ns| *ns >= 0)?;
    u32::try_from((i128::from(ns) + 500_000) / 1_000_000).ok()
}

/// A duration in nanoseconds (of the literal `text`): an optional sign,
/// then one or more number-unit pairs, largest unit first, each once, an
/// `_` allowed between them (`1h2m3.5s`, `1h_2m`, `500ms`, `1_000us`).
/// This is the one IEC TIME parser: IL, declarations and PLCopen files
/// all come here (`SimTime::parse` reads the command line's own times). Summed exactly in integers (a fraction rounded
/// to the nearest nanosecond, halves up); past TIME's range it is
/// refused, not saturated.
fn time(s: &str, text: &str) -> Result<i64, LiteralError> {
    let bad = || LiteralError::BadTime(text.to_string());
    let (negative, mut rest) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    const UNITS: [(&str, i128); 7] = [
        ("d", 86_400_000_000_000),
        ("h", 3_600_000_000_000),
        ("ms", 1_000_000),
        ("m", 60_000_000_000),
        ("s", 1_000_000_000),
        ("us", 1_000),
        ("ns", 1),
    ];
    // Past i64 (either sign) is out of range; checked as it grows.
    let limit = i128::from(i64::MAX) + 1;
    let (mut total, mut last_scale) = (0i128, i128::MAX);
    while !rest.is_empty() {
        let end = rest
            .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '_'))
            .filter(|&e| e > 0)
            .ok_or_else(bad)?;
        let number = &rest[..end];
        rest = &rest[end..];
        let &(unit, scale) = UNITS
            .iter()
            .find(|(u, _)| rest.to_ascii_lowercase().starts_with(u))
            .ok_or_else(bad)?;
        // Largest first, each unit once.
        if scale >= last_scale {
            return Err(bad());
        }
        last_scale = scale;
        rest = &rest[unit.len()..];
        // IEC lets one `_` part a unit from the next number (`1h_2m`).
        if let Some(more) = rest.strip_prefix('_').filter(|m| !m.is_empty()) {
            rest = more;
        }
        total = total
            .checked_add(scaled(number, scale).ok_or_else(bad)?)
            .filter(|&t| t <= limit)
            .ok_or_else(|| LiteralError::OutOfRange {
                text: text.to_string(),
                data_type: DataType::Time,
            })?;
    }
    if last_scale == i128::MAX {
        return Err(bad());
    }
    let ns = if negative { -total } else { total };
    i64::try_from(ns).map_err(|_| LiteralError::OutOfRange {
        text: text.to_string(),
        data_type: DataType::Time,
    })
}

/// `number` (digits, `_` between them, an optional fraction) times
/// `scale`, exactly, the fraction rounded to the nearest unit; `None`
/// when it is not a number, or past what any TIME holds (`u64`).
fn scaled(number: &str, scale: i128) -> Option<i128> {
    if !underscores_between_digits(number) || number.matches('.').count() > 1 {
        return None;
    }
    let clean: String = number.chars().filter(|&c| c != '_').collect();
    let (whole, fraction) = clean.split_once('.').unwrap_or((&clean, ""));
    if whole.is_empty() && fraction.is_empty() {
        return None;
    }
    let mut v: i128 = 0;
    for d in whole.bytes() {
        v = v.checked_mul(10)?.checked_add(i128::from(d - b'0'))?;
        if v > i128::from(u64::MAX) {
            // Out of range however it is scaled: far past TIME's.
            return Some(i128::from(u64::MAX) * scale);
        }
    }
    // Digits past the 18th cannot move a nanosecond (scale < 10^14).
    let fraction = &fraction[..fraction.len().min(18)];
    let mut f: i128 = 0;
    for d in fraction.bytes() {
        f = f * 10 + i128::from(d - b'0');
    }
    let denominator = 10i128.pow(fraction.len() as u32);
    let part = (2 * f * scale + denominator) / (2 * denominator);
    v.checked_mul(scale)?.checked_add(part)
}

/// A string literal `'…'` read (IEC 61131-3's single-byte strings: `$$`,
/// `$'`, `$R`, `$N` and `$L` (LF), `$T`, `$P` and `$hh`): its bytes as
/// characters U+0000–U+00FF: a STRING's value, or an LDmicro formatted
/// string's text.
pub fn parse_text(text: &str) -> Result<String, LiteralError> {
    let bad = || LiteralError::BadText(text.to_string());
    let inner = text
        .strip_prefix('\'')
        .and_then(|t| t.strip_suffix('\''))
        .ok_or_else(bad)?;
    let mut out = String::new();
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        match c {
            '$' => {
                let e = chars.next().ok_or_else(bad)?;
                out.push(match e.to_ascii_uppercase() {
                    '$' => '$',
                    '\'' => '\'',
                    'R' => '\r',
                    'N' | 'L' => '\n',
                    'T' => '\t',
                    'P' => '\u{c}',
                    h => {
                        let l = chars.next().ok_or_else(bad)?;
                        let byte = h
                            .to_digit(16)
                            .zip(l.to_digit(16))
                            .map(|(h, l)| h * 16 + l)
                            .ok_or_else(bad)?;
                        char::from_u32(byte).ok_or_else(bad)?
                    }
                });
            }
            '\'' => return Err(bad()),
            c => out.push(c),
        }
    }
    Ok(out)
}

/// `text` as a string literal [`parse_text`] reads back: quotes and `$`
/// escaped, line ends as `$R` / `$N`, other control bytes (and a `*`
/// after `(`, which would open a comment) as `$hh`.
pub fn text_literal(text: &str) -> String {
    let mut out = String::from("'");
    let mut last = ' ';
    for c in text.chars() {
        match c {
            '$' => out.push_str("$$"),
            '\'' => out.push_str("$'"),
            '\r' => out.push_str("$R"),
            '\n' => out.push_str("$N"),
            '\t' => out.push_str("$T"),
            '*' if last == '(' => out.push_str("$2A"),
            c if (c as u32) < 0x20 || ('\u{7f}'..='\u{ff}').contains(&c) => {
                out.push_str(&format!("${:02X}", c as u32));
            }
            c => out.push(c),
        }
        last = c;
    }
    out.push('\'');
    out
}

#[cfg(test)]
mod time_tests {
    use super::{parse_literal, Data, DataType, LiteralError};

    fn ns(text: &str) -> Result<Data, LiteralError> {
        parse_literal(text, Some(DataType::Time))
    }

    #[test]
    fn a_time_is_summed_in_whole_nanoseconds() {
        assert_eq!(ns("T#1.5ns"), Ok(Data::Time(2)), "halves up");
        assert_eq!(ns("T#1.0000000005s"), Ok(Data::Time(1_000_000_001)));
        assert_eq!(ns("T#0.1s"), Ok(Data::Time(100_000_000)));
        assert_eq!(ns("T#1d1ns"), Ok(Data::Time(86_400_000_000_001)));
        assert_eq!(
            ns("T#9223372036854775807ns"),
            Ok(Data::Time(i64::MAX)),
            "exact at the top"
        );
        assert!(matches!(
            ns("T#9223372036854775808ns"),
            Err(LiteralError::OutOfRange { .. })
        ));
        assert!(matches!(
            ns("T#99999999999999999999999d"),
            Err(LiteralError::OutOfRange { .. })
        ));
        for bad in ["T#1.2.3s", "T#s", "T#1s1s", "T#1ms1s", "T#_1s", "T#"] {
            assert!(matches!(ns(bad), Err(LiteralError::BadTime(_))), "{bad}");
        }
    }

    /// One parser for IL's and PLCopen's TIME literals: IEC's grammar
    /// (largest unit first, each once, `_` between digits or after a
    /// unit), PLCopen's presets taken in whole milliseconds.
    #[test]
    fn one_parser_reads_il_and_plcopen_times() {
        assert_eq!(ns("T#1h_2m"), Ok(Data::Time(3_720_000_000_000)));
        assert_eq!(ns("t#1M30S"), Ok(Data::Time(90_000_000_000)));
        let ms = super::parse_time_literal;
        assert_eq!(ms("T#1h_2m"), Some(3_720_000));
        assert_eq!(ms("T#1500us"), Some(2), "to the nearest ms, halves up");
        assert_eq!(ms("T#499999ns"), Some(0));
        assert_eq!(ms("TIME#49d17h2m47s295ms"), Some(u32::MAX));
        for bad in ["T#-1s", "T#1s1s", "T#1ms1s", "T#49d17h2m47s296ms"] {
            assert_eq!(ms(bad), None, "{bad}");
        }
    }
}

#[cfg(test)]
mod text_tests {
    use super::{parse_text, text_literal};

    #[test]
    fn a_text_reads_back_as_written() {
        for text in [
            "Hello, world: \\-5\r\n",
            "it's $5 (*not*)",
            "\u{7}\u{ff}\t",
            "",
        ] {
            let lit = text_literal(text);
            assert_eq!(parse_text(&lit).as_deref(), Ok(text), "{lit}");
            assert!(!lit.contains("(*"), "{lit}");
        }
        assert_eq!(text_literal("a'b\r"), "'a$'b$R'");
        assert_eq!(parse_text("'$l$P$0d$$'").as_deref(), Ok("\n\u{c}\r$"));
        for bad in ["'a", "a'", "'$q'", "'$4'", "'a'b'"] {
            assert!(parse_text(bad).is_err(), "{bad}");
        }
    }
}
