//! Input timelines: the `TIME,DEVICE,VALUE` CSV of `hashigo run --input`.

use std::fmt;

use crate::error::Located;
use crate::time::{SimTime, TimeError};

/// A value an input takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputValue {
    /// A bit (`0`/`1`) or a word (any integer).
    Int(i64),
    /// An analog voltage in millivolts (`2.5V` = 2500).
    Millivolts(i64),
    /// A real number (`2.5`): the soft PLC's REAL variables.
    Real(Real),
}

/// A finite real number as an input takes it, compared bit for bit so
/// that events and commands stay `Eq`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Real(u64);

impl Real {
    /// `x`, if it is finite (an input is never infinite or NaN).
    pub fn new(x: f64) -> Option<Real> {
        x.is_finite().then_some(Real(x.to_bits()))
    }

    /// The number.
    pub fn get(self) -> f64 {
        f64::from_bits(self.0)
    }
}

impl fmt::Display for InputValue {
    /// As an events file writes it: `1`, `2.5V`, `2.5`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputValue::Int(n) => write!(f, "{n}"),
            InputValue::Millivolts(mv) => write!(f, "{}V", *mv as f64 / 1000.0),
            InputValue::Real(x) => write!(f, "{:?}", x.get()),
        }
    }
}

/// At `time`, the input `device` takes `value`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputEvent {
    /// When.
    pub time: SimTime,
    /// The device name as written (the machine checks it).
    pub device: String,
    /// The value.
    pub value: InputValue,
    /// The 1-based line it came from, for errors found later.
    pub line: usize,
}

/// A problem with one line of an events file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EventError {
    /// Not three comma-separated fields.
    FieldCount(usize),
    /// The time field is malformed.
    Time(TimeError),
    /// The device field is empty.
    MissingDevice,
    /// The value is neither an integer nor a voltage like `2.5V`.
    BadValue(String),
    /// More lines than [`crate::limits::MAX_EVENTS`] (how many).
    TooMany(usize),
}

impl fmt::Display for EventError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EventError::FieldCount(n) => {
                write!(f, "expected TIME,DEVICE,VALUE but found {n} field(s)")
            }
            EventError::Time(e) => e.fmt(f),
            EventError::MissingDevice => f.write_str("the device field is empty"),
            EventError::TooMany(n) => write!(
                f,
                "the file has {n} lines, more than the {} an events file may have (docs/limits.md)",
                crate::limits::MAX_EVENTS
            ),
            EventError::BadValue(v) => write!(
                f,
                "bad value {}: write 0 or 1 for a bit, an integer for a word, a voltage such as 2.5V, or a decimal such as 2.5 for a REAL", crate::error::shown(v)
            ),
        }
    }
}

impl std::error::Error for EventError {}

/// Parses an events file. Returns the events sorted by time, keeping file
/// order at equal times; or every bad line.
pub fn parse_events(text: &str) -> Result<Vec<InputEvent>, Vec<Located<EventError>>> {
    let lines = text.lines().count();
    if lines > crate::limits::MAX_EVENTS {
        return Err(vec![Located::new(
            crate::limits::MAX_EVENTS + 1,
            EventError::TooMany(lines),
        )]);
    }
    let mut events = Vec::new();
    let mut errors = Vec::new();
    let mut seen_data = false;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let code = raw.split('#').next().unwrap_or("").trim();
        if code.is_empty() {
            continue;
        }
        let fields: Vec<&str> = code.split(',').map(str::trim).collect();
        if !seen_data && fields.len() == 3 && fields[0].eq_ignore_ascii_case("time") {
            seen_data = true; // the optional header line
            continue;
        }
        seen_data = true;
        match parse_event(&fields, line) {
            Ok(event) => events.push(event),
            Err(error) => errors.push(Located::new(line, error)),
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    crate::sort::by_key(&mut events, |e| e.time); // stable: file order at equal times
    Ok(events)
}

fn parse_event(fields: &[&str], line: usize) -> Result<InputEvent, EventError> {
    let [time, device, value] = fields else {
        return Err(EventError::FieldCount(fields.len()));
    };
    let time = SimTime::parse(time).map_err(EventError::Time)?;
    if device.is_empty() {
        return Err(EventError::MissingDevice);
    }
    Ok(InputEvent {
        time,
        device: device.to_string(),
        value: parse_value(value)?,
        line,
    })
}

fn parse_value(text: &str) -> Result<InputValue, EventError> {
    let bad = || EventError::BadValue(text.to_string());
    if let Some(volts) = text.strip_suffix(['V', 'v']) {
        let negative = volts.starts_with('-');
        let magnitude =
            SimTime::parse(&format!("{}s", volts.trim_start_matches('-'))).map_err(|_| bad())?;
        // Volts → millivolts through the exact decimal parser (1 s = 1e9 ns).
        let nanos = magnitude.as_nanos();
        if !nanos.is_multiple_of(1_000_000) {
            return Err(bad()); // finer than a millivolt
        }
        let mv = i64::try_from(nanos / 1_000_000).map_err(|_| bad())?;
        return Ok(InputValue::Millivolts(if negative { -mv } else { mv }));
    }
    if text.contains(['.', 'e', 'E']) {
        // A decimal: only a REAL takes it (the machine checks).
        return text
            .parse::<f64>()
            .ok()
            .and_then(Real::new)
            .map(InputValue::Real)
            .ok_or_else(bad);
    }
    text.parse::<i64>().map(InputValue::Int).map_err(|_| bad())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_header_comments_units_and_sorts_stably() {
        let text =
            "time,device,value\n# start\n1s,X00,1\n500ms,X01,1 # early\n1s,X00,0\n250,X04,2.5V\n";
        let events = parse_events(text).unwrap();
        let summary: Vec<(u64, &str, InputValue)> = events
            .iter()
            .map(|e| (e.time.as_nanos() / 1_000_000, e.device.as_str(), e.value))
            .collect();
        assert_eq!(
            summary,
            vec![
                (250, "X04", InputValue::Millivolts(2500)),
                (500, "X01", InputValue::Int(1)),
                (1000, "X00", InputValue::Int(1)),
                (1000, "X00", InputValue::Int(0)),
            ]
        );
        assert_eq!(events[2].line, 3);
    }

    #[test]
    fn every_bad_line_is_reported() {
        let text = "1s,X00\nxs,X00,1\n1s,,1\n1s,X00,on\n1s,X00,1.2.3V\n1s,X00,1\n";
        let errors = parse_events(text).unwrap_err();
        let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![1, 2, 3, 4, 5]);
        assert_eq!(errors[0].error, EventError::FieldCount(2));
        assert!(matches!(errors[1].error, EventError::Time(_)));
        assert_eq!(errors[2].error, EventError::MissingDevice);
        assert!(matches!(errors[3].error, EventError::BadValue(_)));
    }
}
