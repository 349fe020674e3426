//! One element line read as LDmicro's loader reads it (`loadsave.cpp`'s
//! `LoadLeafFromFile`), in either argument form: the keyword picks the
//! family, and each family reads its arguments.

use super::element::*;
use super::error::LdError;
use super::file::Version;
use crate::limits::MAX_LD_TABLE;
use crate::runtime::ldmicro::TimerKind;

/// An element line being read: its keyword, arguments and whole text.
struct Line<'a> {
    keyword: &'a str,
    args: Vec<&'a str>,
    text: &'a str,
}

impl Line<'_> {
    fn wrong(&self, takes: &'static str) -> LdError {
        LdError::Arguments {
            element: self.keyword.into(),
            takes,
        }
    }

    fn int(&self, text: &str) -> Result<i64, LdError> {
        text.parse::<i64>().map_err(|_| LdError::BadNumber {
            element: self.keyword.into(),
            text: text.into(),
        })
    }

    fn flag(&self, text: &str) -> Result<bool, LdError> {
        self.int(text).map(|v| v != 0)
    }

    /// An optional flag argument `i` (false when absent).
    fn flag_at(&self, i: usize) -> Result<bool, LdError> {
        self.args.get(i).map_or(Ok(false), |v| self.flag(v))
    }

    fn s(&self, i: usize) -> String {
        self.args.get(i).map_or(String::new(), |a| a.to_string())
    }

    /// Nothing after the keyword.
    fn bare(&self, e: Element) -> Result<Element, LdError> {
        if self.args.is_empty() {
            Ok(e)
        } else {
            Err(self.wrong("nothing"))
        }
    }
}

/// One element line (trimmed) of a file of `version`.
pub fn leaf(text: &str, version: Version) -> Result<Element, LdError> {
    let mut words = text.split_whitespace();
    let Some(keyword) = words.next() else {
        return Err(LdError::UnknownElement(String::new()));
    };
    let l = Line {
        keyword,
        args: words.collect(),
        text,
    };
    if keyword == "COMMENT" {
        return Ok(Element::Comment(unescape(text.get(8..).unwrap_or(""))));
    }
    if let Some(kind) = TimerKind::from_keyword(keyword) {
        return timer(&l, kind, version);
    }
    if let Some(kind) = CounterKind::from_keyword(keyword) {
        return counter(&l, kind);
    }
    if let Some(e) = operation(&l) {
        return e;
    }
    if HARDWARE.contains(&keyword) || keyword == "TCSFR" {
        return Ok(Element::Hardware {
            keyword: keyword.into(),
            args: text[keyword.len()..].trim().to_string(),
        });
    }
    match keyword {
        "CONTACTS" | "COIL" => contact_or_coil(&l),
        "PLACEHOLDER" => l.bare(Element::Placeholder),
        "SHORT" => l.bare(Element::Short),
        "OPEN" => l.bare(Element::Open),
        "MASTER_RELAY" => l.bare(Element::MasterRelay),
        "UART_RECV_AVAIL" => l.bare(Element::UartRecvAvail),
        "UART_SEND_READY" | "UART_SEND_BUSY" | "UART_UDRE" => l.bare(Element::UartSendReady),
        "LOOK_UP_TABLE" | "PIECEWISE_LINEAR" => table(&l),
        "FORMATTED_STRING" | "STRING" => string(&l),
        _ => device(&l),
    }
}

/// `TON name delay [adjust]`: without an adjust, a 0.1 file's TON, TOF
/// and RTO are one cycle shorter (LDmicro 4.x reads 2.x's files so).
fn timer(l: &Line, kind: TimerKind, version: Version) -> Result<Element, LdError> {
    let takes = "name delay [adjust]";
    let adjust = match l.args.len() {
        2 if version == Version::V01
            && matches!(kind, TimerKind::Ton | TimerKind::Tof | TimerKind::Rto) =>
        {
            -1
        }
        2 => 0,
        3 => i32::try_from(l.int(l.args[2])?).map_err(|_| l.wrong(takes))?,
        _ => return Err(l.wrong(takes)),
    };
    Ok(Element::Timer {
        kind,
        name: l.s(0),
        delay: l.s(1),
        adjust,
    })
}

/// `CTU name max [start [input]]` (`CTR` needs its start).
fn counter(l: &Line, kind: CounterKind) -> Result<Element, LdError> {
    let takes = "name max [start [input]] (input one of / \\ - o)";
    let (init, input) = match l.args.len() {
        2 if kind != CounterKind::Ctr => ("0".to_string(), '/'),
        3 => (l.s(2), '/'),
        4 => match l.args[3] {
            k @ ("/" | "\\" | "-" | "o") => (l.s(2), k.chars().next().unwrap_or('/')),
            _ => return Err(l.wrong(takes)),
        },
        _ => return Err(l.wrong(takes)),
    };
    Ok(Element::Counter {
        kind,
        name: l.s(0),
        max: l.s(1),
        init,
        input,
    })
}

/// The arithmetic, one-operand, comparison and one-shot families, if the
/// keyword is one of theirs.
fn operation(l: &Line) -> Option<Result<Element, LdError>> {
    let args = l.args.as_slice();
    if let Some(op) = MathOp::from_keyword(l.keyword) {
        return Some(match args {
            [d, a, b] => Ok(Element::Math {
                op,
                dest: d.to_string(),
                a: a.to_string(),
                b: b.to_string(),
            }),
            _ => Err(l.wrong("dest a b")),
        });
    }
    if let Some(op) = UnaryOp::from_keyword(l.keyword) {
        return Some(match args {
            [d, src] => Ok(Element::Unary {
                op,
                dest: d.to_string(),
                src: src.to_string(),
            }),
            _ => Err(l.wrong("dest src")),
        });
    }
    if let Some(op) = compare_from_keyword(l.keyword) {
        return Some(match args {
            [a, b] => Ok(Element::Compare {
                op,
                a: a.to_string(),
                b: b.to_string(),
            }),
            _ => Err(l.wrong("a b")),
        });
    }
    OneShotKind::from_keyword(l.keyword).map(|k| l.bare(Element::OneShot(k)))
}

/// `CONTACTS name negated [set1]`, `COIL name negated setOnly resetOnly
/// [toggle]`.
fn contact_or_coil(l: &Line) -> Result<Element, LdError> {
    if l.keyword == "CONTACTS" {
        if !(2..=3).contains(&l.args.len()) {
            return Err(l.wrong("name negated [set1]"));
        }
        return Ok(Element::Contacts {
            name: l.s(0),
            negated: l.flag(l.args[1])?,
            set1: l.flag_at(2)?,
        });
    }
    if !(4..=5).contains(&l.args.len()) {
        return Err(l.wrong("name negated setOnly resetOnly [toggle]"));
    }
    Ok(Element::Coil {
        name: l.s(0),
        negated: l.flag(l.args[1])?,
        set_only: l.flag(l.args[2])?,
        reset_only: l.flag(l.args[3])?,
        toggle: l.flag_at(4)?,
    })
}

/// The elements on a variable and the microcontroller's devices: `RES`,
/// `RANDOM`, `PERSIST`, `TIME2COUNT`, `SHIFT_REGISTER`, `READ_ADC`,
/// `SET_PWM`, the UART, the segment displays, the bit tests.
fn device(l: &Line) -> Result<Element, LdError> {
    let args = l.args.as_slice();
    match (l.keyword, args) {
        ("RES", [n]) => Ok(Element::Res(n.to_string())),
        ("RANDOM", [n]) => Ok(Element::Random(n.to_string())),
        ("PERSIST", [n]) => Ok(Element::Persist(n.to_string())),
        ("RES" | "RANDOM" | "PERSIST", _) => Err(l.wrong("a name")),
        // LDmicro 4.x writes a timer's adjust after the delay and reads
        // only the name and delay back (its `sscanf` of two fields): the
        // adjust, a whole number, changes nothing.
        ("TIME2COUNT" | "TIME2DELAY", [name, delay, adjust @ ..])
            if adjust.len() <= 1 && adjust.iter().all(|a| l.int(a).is_ok()) =>
        {
            Ok(Element::TimeConvert {
                to_delay: l.keyword == "TIME2DELAY",
                name: name.to_string(),
                delay: delay.to_string(),
            })
        }
        ("TIME2COUNT" | "TIME2DELAY", _) => Err(l.wrong("name delay [adjust]")),
        ("SHIFT_REGISTER", [name, stages]) => {
            let stages = u32::try_from(l.int(stages)?)
                .ok()
                .filter(|&n| (1..=MAX_LD_TABLE as u32).contains(&n))
                .ok_or_else(|| l.wrong("name stages (1 or more)"))?;
            Ok(Element::ShiftRegister {
                name: name.to_string(),
                stages,
            })
        }
        ("SHIFT_REGISTER", _) => Err(l.wrong("name stages")),
        ("READ_ADC", [name, rest @ ..]) if rest.len() <= 1 => Ok(Element::ReadAdc {
            name: name.to_string(),
            refs: match rest.first() {
                Some(r) => i32::try_from(l.int(r)?).map_err(|_| l.wrong("name [refs]"))?,
                None => 0,
            },
        }),
        ("READ_ADC", _) => Err(l.wrong("name [refs]")),
        ("SET_PWM", _) => pwm(l),
        ("UART_RECV" | "UART_SEND" | "UART_RECVn" | "UART_SENDn", _) => uart(l),
        ("7SEGMENTS" | "9SEGMENTS" | "14SEGMENTS" | "16SEGMENTS", [dest, src, common])
            if matches!(*common, "C" | "A" | "c" | "a") =>
        {
            Ok(Element::Segments {
                segments: l.keyword.trim_end_matches("SEGMENTS").parse().unwrap_or(7),
                dest: dest.to_string(),
                src: src.to_string(),
                common: common.chars().next().unwrap_or('C'),
            })
        }
        ("7SEGMENTS" | "9SEGMENTS" | "14SEGMENTS" | "16SEGMENTS", _) => {
            Err(l.wrong("dest src common (C or A)"))
        }
        ("SET_BIT" | "CLEAR_BIT" | "IF_BIT_SET" | "IF_BIT_CLEAR", [var, bit]) => Ok(Element::Bit {
            write: !l.keyword.starts_with("IF_"),
            set: l.keyword.contains("SET"),
            var: var.to_string(),
            bit: bit.to_string(),
        }),
        ("SET_BIT" | "CLEAR_BIT" | "IF_BIT_SET" | "IF_BIT_CLEAR", _) => Err(l.wrong("var bit")),
        _ => Err(LdError::UnknownElement(l.keyword.into())),
    }
}

/// `SET_PWM duty frequency [name [resolution]]`: an old file's name
/// without its `P` gets it; a frequency's decimals are dropped.
fn pwm(l: &Line) -> Result<Element, LdError> {
    let [duty, freq, rest @ ..] = l.args.as_slice() else {
        return Err(l.wrong("duty frequency [name [resolution]]"));
    };
    if rest.len() > 2 {
        return Err(l.wrong("duty frequency [name [resolution]]"));
    }
    let name = rest.first().map_or(String::new(), |n| {
        if n.starts_with('P') {
            n.to_string()
        } else {
            format!("P{n}")
        }
    });
    Ok(Element::SetPwm {
        duty: duty.to_string(),
        frequency: freq.split('.').next().unwrap_or(freq).to_string(),
        name,
        resolution: rest.get(1).map_or(String::new(), |r| r.to_string()),
    })
}

/// `UART_RECV name [bytes wait]` and `UART_RECVn name` (and the sends).
fn uart(l: &Line) -> Result<Element, LdError> {
    let whole = l.keyword.ends_with('n');
    let takes = "name [bytes wait]";
    let (name, bytes, wait) = match (l.args.as_slice(), whole) {
        ([name], _) => (name.to_string(), 1, false),
        ([name, bytes, wait], false) => (
            name.to_string(),
            u32::try_from(l.int(bytes)?).map_err(|_| l.wrong(takes))?,
            l.flag(wait)?,
        ),
        _ => return Err(l.wrong(takes)),
    };
    Ok(if l.keyword.starts_with("UART_RECV") {
        Element::UartRecv {
            name,
            bytes,
            wait,
            whole,
        }
    } else {
        Element::UartSend {
            name,
            bytes,
            wait,
            whole,
        }
    })
}

/// A look-up table's or piecewise-linear table's arguments.
fn table(l: &Line) -> Result<Element, LdError> {
    let lut = l.keyword == "LOOK_UP_TABLE";
    let fixed = if lut { 4 } else { 3 };
    let takes = if lut {
        "dest index count asString values… [name]"
    } else {
        "dest index count x y … [name]"
    };
    let args = l.args.as_slice();
    if args.len() < fixed {
        return Err(l.wrong(takes));
    }
    let bad = |t: &str| LdError::BadNumber {
        element: l.keyword.into(),
        text: t.into(),
    };
    let count: usize = args[2].parse().map_err(|_| bad(args[2]))?;
    if count > MAX_LD_TABLE {
        return Err(LdError::TableTooLong(l.keyword.into()));
    }
    let entries = if lut { count } else { 2 * count };
    let rest = &args[fixed..];
    if rest.len() < entries || rest.len() > entries + 1 {
        return Err(LdError::TableCount {
            element: l.keyword.into(),
            says: count,
            has: if lut { rest.len() } else { rest.len() / 2 },
        });
    }
    let values = rest[..entries]
        .iter()
        .map(|v| number(v).filter(|_| is_number(v)).ok_or_else(|| bad(v)))
        .collect::<Result<Vec<i64>, LdError>>()?;
    let name = rest
        .get(entries)
        .map_or_else(|| format!("{}{count}", args[0]), |n| n.to_string());
    let (dest, index) = (args[0].to_string(), args[1].to_string());
    Ok(if lut {
        Element::LookUpTable {
            dest,
            index,
            values,
            as_string: args[3] != "0",
            name,
        }
    } else {
        Element::PiecewiseLinear {
            dest,
            index,
            points: values.chunks(2).map(|p| (p[0], p[1])).collect(),
            name,
        }
    })
}

/// `FORMATTED_STRING var …` and `STRING dest var …`: the leading names
/// (`(none)` read as empty) and the text, either a count and that many
/// character codes (a code below 32 reads as `X`, as in LDmicro) or the
/// rest of the line with LDmicro's escapes.
fn string(l: &Line) -> Result<Element, LdError> {
    let names = if l.keyword == "STRING" { 2 } else { 1 };
    let takes = if names == 1 {
        "var (count codes… or text)"
    } else {
        "dest var (count codes… or text)"
    };
    let mut rest = l.text[l.keyword.len()..].trim_start();
    let mut out = Vec::new();
    for _ in 0..names {
        let (word, tail) = rest
            .split_once(char::is_whitespace)
            .ok_or_else(|| l.wrong(takes))?;
        out.push(if word == "(none)" {
            String::new()
        } else {
            word.into()
        });
        rest = tail.trim_start();
    }
    let text = codes(l, rest)?.unwrap_or_else(|| unescape(rest));
    let mut names = out.into_iter();
    let first = names.next().unwrap_or_default();
    Ok(match names.next() {
        Some(var) => Element::Text {
            dest: first,
            var,
            text,
        },
        None => Element::FormattedString { var: first, text },
    })
}

/// A string written as a count and character codes, if it is.
fn codes(l: &Line, rest: &str) -> Result<Option<String>, LdError> {
    let words: Vec<&str> = rest.split_whitespace().collect();
    let Some(count) = words.first().and_then(|c| c.parse::<usize>().ok()) else {
        return Ok(None);
    };
    if count > MAX_LD_TABLE {
        return Err(LdError::TableTooLong(l.keyword.into()));
    }
    let codes = &words[1..];
    if codes.len() != count {
        return Err(LdError::TableCount {
            element: l.keyword.into(),
            says: count,
            has: codes.len(),
        });
    }
    codes
        .iter()
        .map(|c| match c.parse::<u8>() {
            Ok(b) if b >= 32 => Ok(char::from(b)),
            Ok(_) => Ok('X'),
            Err(_) => Err(LdError::BadNumber {
                element: l.keyword.into(),
                text: c.to_string(),
            }),
        })
        .collect::<Result<String, LdError>>()
        .map(Some)
}
