//! LDmicro's `FORMATTED_STRING`: a text with at most one number in it,
//! sent over the serial port one character a scan (docs/ldmicro.md, "The
//! serial port"). The text is LDmicro's, escapes and all (`\r`, `\n`,
//! `\x41`, `\-5` for a signed five-digit number, `\3` unsigned three);
//! read here as LDmicro 4.x's compiler reads it (`intcode.cpp`), and sent
//! as its generated code sends it: from a rise of the power in, one
//! character a scan while the transmitter is free, the number's digits
//! worked out one per character with its leading zeros as spaces.

use crate::runtime::uart::Uart;

/// One character of the text as sent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Piece {
    /// A byte as it stands.
    Byte(u8),
    /// The number's sign: `-`, or a space.
    Sign,
    /// The number's `k`-th digit of `of` (the most significant first).
    Digit { k: u8, of: u8 },
}

/// A formatted string, read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Format {
    pieces: Vec<Piece>,
    /// `\-n`: the sign is sent before the digits.
    signed: bool,
    /// The text as written (for the listing and the ladder).
    text: String,
}

/// Why a text is no formatted string (LDmicro's own messages, in
/// substance).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FormatError {
    /// A second `\n` number in one text.
    TwoNumbers,
    /// `\` followed by something LDmicro has no escape for.
    BadEscape(String),
    /// A number (`\3`) with no variable to take it from.
    NoVariable,
    /// A variable given and no `\n` to put it in.
    NoNumber,
    /// A character that is no byte (LDmicro's texts are bytes).
    NotAByte(char),
}

impl std::fmt::Display for FormatError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FormatError::TwoNumbers => {
                f.write_str("a formatted string holds one number (`\\3`, `\\-5`), not two")
            }
            FormatError::BadEscape(e) => write!(
                f,
                "`\\{e}` is no escape of a formatted string (\\r \\n \\t \\a \\b \\e \\f \\v \\\\ \
                 \\xAB, or \\1 … \\5 and \\-1 … \\-5 for the number); a backslash is `\\\\`"
            ),
            FormatError::NoVariable => f.write_str(
                "the formatted string shows a number (`\\3`) but names no variable to take it from",
            ),
            FormatError::NoNumber => f.write_str(
                "a variable is given but the formatted string has no `\\3` or `\\-5` to show it",
            ),
            FormatError::NotAByte(c) => write!(
                f,
                "`{c}` is not a byte: a formatted string is sent as bytes (write `\\xAB`)"
            ),
        }
    }
}

impl std::error::Error for FormatError {}

impl Format {
    /// Reads LDmicro's `text`.
    pub fn parse(text: &str) -> Result<Format, FormatError> {
        let bytes = text
            .chars()
            .map(|c| u8::try_from(u32::from(c)).map_err(|_| FormatError::NotAByte(c)))
            .collect::<Result<Vec<u8>, _>>()?;
        let mut pieces = Vec::new();
        let mut signed = false;
        let mut digits: Option<u8> = None;
        let mut p = 0;
        while p < bytes.len() {
            let next = bytes.get(p + 1).copied();
            if bytes[p] != b'\\' {
                pieces.push(Piece::Byte(bytes[p]));
                p += 1;
                continue;
            }
            if matches!(next, Some(b'1'..=b'9' | b'-')) {
                if digits.is_some() {
                    return Err(FormatError::TwoNumbers);
                }
                p += 1;
                let sign = if bytes[p] == b'-' {
                    signed = true;
                    pieces.push(Piece::Sign);
                    p += 1;
                    "-"
                } else {
                    ""
                };
                let n = match bytes.get(p) {
                    Some(d @ b'1'..=b'5') => d - b'0',
                    other => {
                        let seen = other.map_or(String::new(), |b| char::from(*b).to_string());
                        return Err(FormatError::BadEscape(format!("{sign}{seen}")));
                    }
                };
                digits = Some(n);
                pieces.extend((0..n).map(|k| Piece::Digit { k, of: n }));
                p += 1;
                continue;
            }
            let (byte, used) = escape(&bytes[p + 1..])?;
            pieces.push(Piece::Byte(byte));
            p += 1 + used;
        }
        Ok(Format {
            pieces,
            signed,
            text: text.to_string(),
        })
    }

    /// Reads LDmicro's `text` for an element that names a variable or
    /// not (`has_variable`): it must exactly when the text shows a number.
    pub fn for_element(text: &str, has_variable: bool) -> Result<Format, FormatError> {
        let format = Format::parse(text)?;
        let shows = format
            .pieces
            .iter()
            .any(|p| matches!(p, Piece::Digit { .. }));
        match (shows, has_variable) {
            (true, false) => Err(FormatError::NoVariable),
            (false, true) => Err(FormatError::NoNumber),
            _ => Ok(format),
        }
    }

    /// The text as written.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// How many characters it sends.
    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    /// Whether it sends nothing.
    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }
}

/// The escape after a `\` (LDmicro 4.x: `\0` before another escape is
/// skipped): its byte and how many bytes it took.
fn escape(rest: &[u8]) -> Result<(u8, usize), FormatError> {
    let bad =
        |n: usize| FormatError::BadEscape(rest.iter().take(n).map(|&b| char::from(b)).collect());
    let byte = match rest.first() {
        Some(b'0') => {
            let (b, used) = escape(&rest[1..]).map_err(|_| bad(2))?;
            return Ok((b, used + 1));
        }
        Some(b'a') => 0x07,
        Some(b'b') => 0x08,
        Some(b'e') => 0x1B,
        Some(b'f') => 0x0C,
        Some(b'n') => b'\n',
        Some(b'r') => b'\r',
        Some(b't') => b'\t',
        Some(b'v') => 0x0B,
        Some(&c @ (b'\'' | b'"' | b'?' | b'\\')) => c,
        Some(b'x' | b'X') => {
            let hex = |i: usize| rest.get(i).and_then(|&b| char::from(b).to_digit(16));
            return match (hex(1), hex(2)) {
                (Some(h), Some(l)) => Ok(((h * 16 + l) as u8, 3)),
                _ => Err(bad(3)),
            };
        }
        _ => return Err(bad(1)),
    };
    Ok((byte, 1))
}

/// One `FORMATTED_STRING` instance's memory: LDmicro's one-shot,
/// `doSend`, sequencer, conversion state and leading-zero bit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sender {
    shot: bool,
    sending: bool,
    seq: usize,
    rest: i64,
    leading_zero: bool,
}

impl Sender {
    /// One scan with power `s` and the variable's value `v`: starts at a
    /// rise, sends the next character when the port is free; on while
    /// the text is going out.
    pub fn call(&mut self, s: bool, v: i64, format: &Format, uart: &mut Uart) -> bool {
        if s {
            if !self.shot {
                self.shot = true;
                self.seq = 0;
                self.sending = true;
            }
        } else {
            self.shot = false;
        }
        if self.sending && uart.ready() {
            if let Some(&piece) = format.pieces.get(self.seq) {
                let byte = self.character(piece, v, format.signed);
                uart.send(byte);
                self.seq += 1;
            }
        }
        if self.seq < format.len() {
            self.sending
        } else {
            self.sending = false;
            false
        }
    }

    /// The byte `piece` stands for now, the number's state moved on.
    fn character(&mut self, piece: Piece, v: i64, signed: bool) -> u8 {
        match piece {
            Piece::Byte(b) => b,
            Piece::Sign => {
                self.rest = v.wrapping_abs();
                if v < 0 {
                    b'-'
                } else {
                    b' '
                }
            }
            Piece::Digit { k, of } => {
                if k == 0 {
                    if !signed {
                        self.rest = v;
                    }
                    self.leading_zero = true;
                }
                let scale = 10i64.pow(u32::from(of - k - 1));
                let digit = self.rest / scale;
                self.rest -= digit * scale;
                let c = digit.wrapping_add(i64::from(b'0'));
                // All but the last leading zero are spaces.
                if k + 1 != of {
                    if c == i64::from(b'0') {
                        if self.leading_zero {
                            return b' ';
                        }
                    } else {
                        self.leading_zero = false;
                    }
                }
                c as u8
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Everything `text` sends with the variable at `v`, power on from
    /// the first scan, scan by scan: (bytes, scans taken).
    fn send_all(text: &str, v: Option<i64>) -> (String, usize) {
        let format = Format::for_element(text, v.is_some()).expect("a format");
        let (mut sender, mut uart) = (Sender::default(), Uart::default());
        let mut scans = 0;
        loop {
            uart.begin_scan();
            scans += 1;
            if !sender.call(true, v.unwrap_or(0), &format, &mut uart) || scans > 1000 {
                break;
            }
        }
        let sent: Vec<u8> = uart.sent_after(0).collect();
        (sent.iter().map(|&b| char::from(b)).collect(), scans)
    }

    #[test]
    fn a_number_goes_out_with_its_leading_zeros_as_spaces() {
        assert_eq!(
            send_all("Hello, world: \\-5\\r\\n", Some(42)).0,
            "Hello, world:     42\r\n"
        );
        assert_eq!(send_all("\\-5", Some(-1234)).0, "- 1234");
        assert_eq!(send_all("\\3", Some(0)).0, "  0");
        assert_eq!(send_all("\\2:", Some(7)).0, " 7:");
        assert_eq!(send_all("\\2", Some(123)).0, "<3", "LDmicro's digit past 9");
    }

    #[test]
    fn escapes_are_read_as_ldmicro_4_reads_them() {
        assert_eq!(send_all("a\\tb\\x41\\0x42\\\\", None).0, "a\tbAB\\");
        assert!(matches!(Format::parse("\\q"), Err(FormatError::BadEscape(e)) if e == "q"));
        assert_eq!(Format::parse("\\3\\2"), Err(FormatError::TwoNumbers));
        assert_eq!(
            Format::for_element("\\3", false),
            Err(FormatError::NoVariable)
        );
        assert_eq!(Format::for_element("abc", true), Err(FormatError::NoNumber));
        assert_eq!(
            Format::parse("\\-9").map(|_| ()),
            Err(FormatError::BadEscape("-9".into()))
        );
    }

    #[test]
    fn one_character_goes_every_other_scan_and_the_power_stays_on_meanwhile() {
        // Sent in scans 1, 3, 5; the fourth call (scan 6) finds it done.
        let (sent, scans) = send_all("abc", None);
        assert_eq!(sent, "abc");
        assert_eq!(scans, 5);
    }

    #[test]
    fn it_starts_again_only_at_a_new_rise() {
        let format = Format::parse("x").expect("a format");
        let (mut sender, mut uart) = (Sender::default(), Uart::default());
        for _ in 0..10 {
            uart.begin_scan();
            sender.call(true, 0, &format, &mut uart);
        }
        assert_eq!(uart.sent_total(), 1, "held on: sent once");
        uart.begin_scan();
        sender.call(false, 0, &format, &mut uart);
        uart.begin_scan();
        sender.call(true, 0, &format, &mut uart);
        assert_eq!(uart.sent_total(), 2);
    }
}
