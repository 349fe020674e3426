//! The text of LDmicro's `STRING dest var text`: a C `sprintf(dest, text,
//! var)` format, as LDmicro's C output passes it on. It prints one
//! integer (`var`, LDmicro's 32-bit SDWORD) at most once, with C's
//! integer conversions: `%d %i %u %x %X %o %c`, flags `- + space 0 #`, a
//! width and a precision; `%%` is a `%`. The length modifiers are C's:
//! `h` and `hh` print the value converted to a `short` and a `char`, `l`
//! and `ll` as a `long` and a `long long` (64 bits, as on the machines
//! Hashigo's tests compare with glibc). A format C would take a second
//! argument, a string or a real for, or a length C gives no meaning to,
//! is refused when the program loads, never printed wrong.

use std::fmt;

/// Why a text is not a format the element can print.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PrintfError {
    /// A conversion of something other than an integer (`%s`, `%f` …),
    /// or none at all after `%`.
    Conversion(String),
    /// A second conversion: the element prints one variable.
    Second,
    /// A width or precision given as `*` (an argument the element has
    /// not).
    Star,
    /// A conversion, where the element names no variable (`(none)`).
    NoValue,
    /// A length modifier C has not, or one on `%c` (the conversion as
    /// written).
    Length(String),
}

impl fmt::Display for PrintfError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PrintfError::Conversion(c) => write!(
                f,
                "`{c}` prints no integer: the text takes %d %i %u %x %X %o %c or %%"
            ),
            PrintfError::Second => write!(f, "a second %: STRING prints one variable"),
            PrintfError::Star => write!(f, "a * width or precision needs a second argument"),
            PrintfError::NoValue => {
                write!(f, "the text prints a value (%…) but no variable is named")
            }
            PrintfError::Length(c) => write!(
                f,
                "`{c}`: the lengths are h, hh, l and ll, on %d %i %u %x %X %o (%c takes none)"
            ),
        }
    }
}

impl std::error::Error for PrintfError {}

/// One `%…` conversion.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Spec {
    left: bool,
    plus: bool,
    space: bool,
    zero: bool,
    alternate: bool,
    width: usize,
    precision: Option<usize>,
    /// The length modifier: "", "h", "hh", "l" or "ll".
    length: &'static str,
    conversion: char,
}

/// A parsed format: the text before its conversion, the conversion, the
/// text after (`%%` already a `%`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Printf {
    text: String,
    before: String,
    spec: Option<Spec>,
    after: String,
}

impl Printf {
    /// Reads a format.
    pub fn parse(text: &str) -> Result<Printf, PrintfError> {
        let mut before = String::new();
        let mut after = String::new();
        let mut spec = None;
        let mut chars = text.chars().peekable();
        while let Some(c) = chars.next() {
            let out = if spec.is_some() {
                &mut after
            } else {
                &mut before
            };
            if c != '%' {
                out.push(c);
                continue;
            }
            if chars.peek() == Some(&'%') {
                chars.next();
                out.push('%');
                continue;
            }
            if spec.is_some() {
                return Err(PrintfError::Second);
            }
            spec = Some(conversion(&mut chars)?);
        }
        Ok(Printf {
            text: text.to_string(),
            before,
            spec,
            after,
        })
    }

    /// The text as written.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Whether it prints the variable.
    pub fn takes_value(&self) -> bool {
        self.spec.is_some()
    }

    /// The text with `value` (as a 32-bit C `int`) printed in it, up to
    /// a NUL (`%c` of 0 ends a C string there).
    pub fn print(&self, value: i64) -> String {
        let mut out = self.before.clone();
        if let Some(spec) = &self.spec {
            out.push_str(&spec.print(value as i32));
        }
        out.push_str(&self.after);
        if let Some(end) = out.find('\0') {
            out.truncate(end);
        }
        out
    }
}

/// The conversion after a `%`: flags, width, precision, length, letter.
fn conversion(chars: &mut std::iter::Peekable<std::str::Chars<'_>>) -> Result<Spec, PrintfError> {
    let mut spec = Spec {
        left: false,
        plus: false,
        space: false,
        zero: false,
        alternate: false,
        width: 0,
        precision: None,
        length: "",
        conversion: 'd',
    };
    let mut seen = String::from("%");
    while let Some(&c) = chars.peek() {
        match c {
            '-' => spec.left = true,
            '+' => spec.plus = true,
            ' ' => spec.space = true,
            '0' => spec.zero = true,
            '#' => spec.alternate = true,
            _ => break,
        }
        seen.push(c);
        chars.next();
    }
    spec.width = number(chars, &mut seen)?;
    if chars.peek() == Some(&'.') {
        seen.push('.');
        chars.next();
        spec.precision = Some(number(chars, &mut seen)?);
    }
    let mut length = String::new();
    while let Some(&c) = chars.peek() {
        if !matches!(c, 'h' | 'l') {
            break;
        }
        seen.push(c);
        length.push(c);
        chars.next();
    }
    match chars.next() {
        Some(c @ ('d' | 'i' | 'u' | 'x' | 'X' | 'o' | 'c')) => {
            seen.push(c);
            spec.length = match length.as_str() {
                "" => "",
                "h" if c != 'c' => "h",
                "hh" if c != 'c' => "hh",
                "l" if c != 'c' => "l",
                "ll" if c != 'c' => "ll",
                _ => return Err(PrintfError::Length(seen)),
            };
            spec.conversion = c;
            Ok(spec)
        }
        Some(c) => {
            seen.push(c);
            Err(PrintfError::Conversion(seen))
        }
        None => Err(PrintfError::Conversion(seen)),
    }
}

/// Decimal digits (a width or precision); `*` is refused.
fn number(
    chars: &mut std::iter::Peekable<std::str::Chars<'_>>,
    seen: &mut String,
) -> Result<usize, PrintfError> {
    if chars.peek() == Some(&'*') {
        return Err(PrintfError::Star);
    }
    let mut n: usize = 0;
    while let Some(d) = chars.peek().and_then(|c| c.to_digit(10)) {
        seen.push(char::from_digit(d, 10).unwrap_or('0'));
        // A width past a STRING's length prints no more than it holds.
        n = (n * 10 + d as usize).min(1000);
        chars.next();
    }
    Ok(n)
}

impl Spec {
    /// `v` printed as C's `printf` prints it for this conversion.
    fn print(&self, v: i32) -> String {
        if self.conversion == 'c' {
            // C prints the low byte as a character.
            let c = char::from(v as u8);
            return self.pad(String::new(), c.to_string(), false);
        }
        // The value as the type the length names (C converts it so).
        let signed: i64 = match self.length {
            "h" => i64::from(v as i16),
            "hh" => i64::from(v as i8),
            _ => i64::from(v),
        };
        let unsigned: u64 = match self.length {
            "h" => u64::from(v as u16),
            "hh" => u64::from(v as u8),
            "l" | "ll" => i64::from(v) as u64,
            _ => u64::from(v as u32),
        };
        let (sign, digits) = match self.conversion {
            'd' | 'i' => {
                let sign = if signed < 0 {
                    "-"
                } else if self.plus {
                    "+"
                } else if self.space {
                    " "
                } else {
                    ""
                };
                (sign, signed.unsigned_abs().to_string())
            }
            'u' => ("", unsigned.to_string()),
            'o' => ("", format!("{unsigned:o}")),
            'x' => ("", format!("{unsigned:x}")),
            _ => ("", format!("{unsigned:X}")),
        };
        let zero_value = digits == "0";
        // A precision is the least count of digits; `.0` prints 0 as
        // nothing.
        let mut digits = match self.precision {
            Some(0) if zero_value => String::new(),
            Some(p) if digits.len() < p => format!("{}{digits}", "0".repeat(p - digits.len())),
            _ => digits,
        };
        // `#`: octal's first digit is a 0 (after the precision: `%#.0o`
        // of 0 is `0`); hexadecimal other than 0 gets `0x`.
        let prefix = match self.conversion {
            'o' if self.alternate && !digits.starts_with('0') => {
                digits.insert(0, '0');
                ""
            }
            'x' if self.alternate && !zero_value => "0x",
            'X' if self.alternate && !zero_value => "0X",
            _ => "",
        };
        let zero = self.zero && !self.left && self.precision.is_none();
        self.pad(format!("{sign}{prefix}"), digits, zero)
    }

    /// `head` (sign, prefix) and `body` filled out to the width: spaces on
    /// the left (or right for `-`), or zeros after the head for `0`.
    fn pad(&self, head: String, body: String, zero: bool) -> String {
        let len = head.chars().count() + body.chars().count();
        let fill = self.width.saturating_sub(len);
        if self.left {
            format!("{head}{body}{}", " ".repeat(fill))
        } else if zero {
            format!("{head}{}{body}", "0".repeat(fill))
        } else {
            format!("{}{head}{body}", " ".repeat(fill))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Printf, PrintfError};

    fn print(format: &str, v: i64) -> String {
        Printf::parse(format).expect("a format").print(v)
    }

    #[test]
    fn integers_print_as_c_prints_them() {
        // What glibc's printf gives for each (checked against C's rules).
        assert_eq!(print("count=%d", 42), "count=42");
        assert_eq!(print("%i", -7), "-7");
        assert_eq!(print("[%5d]", 42), "[   42]");
        assert_eq!(print("[%-5d]", 42), "[42   ]");
        assert_eq!(print("[%05d]", -42), "[-0042]");
        assert_eq!(print("[%+d]", 5), "[+5]");
        assert_eq!(print("[% d]", 5), "[ 5]");
        assert_eq!(print("[%.3d]", 7), "[007]");
        assert_eq!(print("[%6.3d]", -7), "[  -007]");
        assert_eq!(print("[%.0d]", 0), "[]");
        assert_eq!(print("%u", -1), "4294967295");
        assert_eq!(print("%x", 255), "ff");
        assert_eq!(print("%#X", 255), "0XFF");
        assert_eq!(print("%#x", 0), "0");
        assert_eq!(print("%08x", -1), "ffffffff");
        assert_eq!(print("%o", 8), "10");
        assert_eq!(print("%#o", 8), "010");
        assert_eq!(print("%c!", 65), "A!");
        assert_eq!(print("ab%cd", 0), "ab", "a NUL ends the text");
        assert_eq!(print("%ld", 3), "3");
        assert_eq!(print("%hhx", 255), "ff");
        assert_eq!(print("%hhx", 511), "ff");
        assert_eq!(print("%#.4o", 8), "0010");
    }

    #[test]
    fn the_value_is_a_32_bit_int_and_percent_signs_stay() {
        assert_eq!(print("%d", 4_294_967_296 + 5), "5");
        assert_eq!(print("100%% at %d%%", 9), "100% at 9%");
        assert_eq!(print("no value", 9), "no value");
        assert!(!Printf::parse("50%%").expect("a format").takes_value());
        assert!(Printf::parse("%3d").expect("a format").takes_value());
    }

    #[test]
    fn formats_c_would_read_another_argument_for_are_refused() {
        assert_eq!(
            Printf::parse("%s"),
            Err(PrintfError::Conversion("%s".into()))
        );
        assert_eq!(
            Printf::parse("%5.2f"),
            Err(PrintfError::Conversion("%5.2f".into()))
        );
        assert_eq!(Printf::parse("%d and %d"), Err(PrintfError::Second));
        assert_eq!(Printf::parse("%*d"), Err(PrintfError::Star));
        assert_eq!(
            Printf::parse("ends in %"),
            Err(PrintfError::Conversion("%".into()))
        );
        assert_eq!(
            Printf::parse("%s").map_err(|e| e.to_string()),
            Err("`%s` prints no integer: the text takes %d %i %u %x %X %o %c or %%".into())
        );
    }
}
