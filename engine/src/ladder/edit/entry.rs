//! The device entry: what the user types after F5 / F6 / F7 / F8, read
//! into an element the machine has, or refused with the engine's message
//! before anything changes.

use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::target::check_element;
use crate::MachineId;

/// What the entry was opened for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EntryKind {
    /// F5: a normally open contact; the text is a device.
    Open,
    /// F6: a normally closed contact; the text is a device.
    Closed,
    /// F7: a coil; the text is a device.
    Coil,
    /// F8: an instruction in words (`SET Y00`, `OUT T00 K10`, `TON t 500ms`).
    Instruction,
}

pub use super::entry_error::EntryError;

/// Reads the entry's `text` for `kind` into an element of `machine`, in
/// the machine's spelling of its devices.
pub fn parse_entry(machine: MachineId, kind: EntryKind, text: &str) -> Result<Element, EntryError> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let word_boxes = crate::ladder::target::capabilities(machine).word_boxes;
    if word_boxes && words.len() > 1 && super::block_entry::is_box(text) {
        // A box; else (`AND %IX0.0`, `TON t1 500ms`) an instruction.
        let boxed = super::block_entry::parse_box(text)
            .and_then(|e| check_element(machine, &e).map_err(EntryError::Element));
        return boxed.or_else(|box_error| {
            instruction(&words)
                .and_then(|e| check_element(machine, &e).map_err(EntryError::Element))
                .map_err(|_| box_error)
        });
    }
    let element = match (kind, words.as_slice()) {
        (_, []) => return Err(EntryError::Empty),
        (EntryKind::Open, [d]) => Element::no(d),
        (EntryKind::Closed, [d]) => Element::nc(d),
        (EntryKind::Coil, [d]) => Element::coil(d),
        // A device entry given words reads them as an instruction.
        _ => instruction(&words)?,
    };
    check_element(machine, &element).map_err(EntryError::Element)
}

/// An instruction in words: IEC / FX mnemonics and the AVR PLC's names.
fn instruction(words: &[&str]) -> Result<Element, EntryError> {
    let first = words[0].to_ascii_uppercase();
    let contact = |kind| Element::Contact {
        kind,
        device: String::new(),
    };
    let coil = |kind| Element::Coil {
        kind,
        device: String::new(),
    };
    let one = |usage, e: Element| with_device(words, usage, e);
    match first.as_str() {
        "LD" | "LOAD_A" | "AND" | "OR" => one("LD X00", contact(ContactKind::No)),
        "LDI" | "LOAD_B" | "ANDI" | "ORI" => one("LDI X00", contact(ContactKind::Nc)),
        "LDP" | "ANDP" | "ORP" => one("LDP X00", contact(ContactKind::Rising)),
        "LDF" | "ANDF" | "ORF" => one("LDF X00", contact(ContactKind::Falling)),
        "OUT" | "ST" | "COIL_A" if words.len() == 3 => preset_coil(words),
        "OUT" | "ST" | "COIL_A" => one("OUT Y00", coil(CoilKind::Normal)),
        "OUTI" | "STI" | "COIL_B" => one("STI Y00", coil(CoilKind::Inverted)),
        "SET" | "S" | "SET_COIL" => one("SET Y00", coil(CoilKind::Set)),
        "RST" | "R" | "RESET_COIL" => one("RST Y00", coil(CoilKind::Reset)),
        "PLS" => one(
            "PLS M00",
            Element::Pulse {
                falling: false,
                device: String::new(),
            },
        ),
        "PLF" => one(
            "PLF M00",
            Element::Pulse {
                falling: true,
                device: String::new(),
            },
        ),
        // Below a soft PLC block: its input wired from the network left.
        "PIN" => match words {
            [_, pin] => Ok(Element::BoxInput {
                pin: pin.to_ascii_uppercase(),
            }),
            _ => Err(EntryError::Usage("PIN R")),
        },
        "NOT" | "INV" => bare(words, "NOT", Element::Not),
        "R_TRIG" | "PULSE_A" => bare(words, "R_TRIG", Element::Edge { falling: false }),
        "F_TRIG" | "PULSE_B" => bare(words, "F_TRIG", Element::Edge { falling: true }),
        "TON" => timer(words, TimerKind::Ton),
        "TOF" => timer(words, TimerKind::Tof),
        "TP" => timer(words, TimerKind::Tp),
        "MOV" | "CMP" => match words {
            [_, a, b] if first == "MOV" => Ok(Element::Mov {
                src: a.to_string(),
                dst: b.to_string(),
            }),
            [_, a, b] => Ok(Element::Cmp {
                a: a.to_string(),
                b: b.to_string(),
            }),
            _ if first == "MOV" => Err(EntryError::Usage("MOV K50 D00")),
            _ => Err(EntryError::Usage("CMP D00 K10")),
        },
        "INC" | "DEC" => match words {
            [_, d] if first == "INC" => Ok(Element::Inc { dst: d.to_string() }),
            [_, d] => Ok(Element::Dec { dst: d.to_string() }),
            _ => Err(EntryError::Usage("INC D00")),
        },
        _ => Err(EntryError::UnknownWord(words[0].to_string())),
    }
}

/// `element` with the one operand `words` give it as its device.
fn with_device(
    words: &[&str],
    usage: &'static str,
    element: Element,
) -> Result<Element, EntryError> {
    let [_, d] = words else {
        return Err(EntryError::Usage(usage));
    };
    let d = d.to_string();
    Ok(match element {
        Element::Contact { kind, .. } => Element::Contact { kind, device: d },
        Element::Coil { kind, .. } => Element::Coil { kind, device: d },
        Element::Pulse { falling, .. } => Element::Pulse { falling, device: d },
        other => other,
    })
}

fn bare(words: &[&str], usage: &'static str, element: Element) -> Result<Element, EntryError> {
    if words.len() == 1 {
        Ok(element)
    } else {
        Err(EntryError::Usage(usage))
    }
}

/// `OUT T00 K10` / `OUT C00 K10`: a timer or counter coil with its set value.
fn preset_coil(words: &[&str]) -> Result<Element, EntryError> {
    let (device, k) = (words[1], words[2]);
    let digits = k.strip_prefix(['K', 'k']).unwrap_or(k);
    let preset: u16 = digits
        .parse()
        .map_err(|_| EntryError::BadNumber(k.to_string()))?;
    let device = device.to_string();
    match device.chars().next().map(|c| c.to_ascii_uppercase()) {
        Some('T') => Ok(Element::TimerCoil { device, preset }),
        Some('C') => Ok(Element::CounterCoil { device, preset }),
        _ => Err(EntryError::Usage("OUT T00 K10 or OUT C00 K10")),
    }
}

/// `TON name 500ms` (also `1.5s`, or plain milliseconds).
fn timer(words: &[&str], kind: TimerKind) -> Result<Element, EntryError> {
    let [_, name, time] = words else {
        return Err(EntryError::Usage("TON t1 500ms"));
    };
    Ok(Element::Timer {
        kind,
        name: name.to_string(),
        preset_ms: millis(time)?,
    })
}

/// A time in milliseconds: `500`, `500ms`, `1.5s`.
fn millis(text: &str) -> Result<u32, EntryError> {
    let bad = || EntryError::BadNumber(text.to_string());
    let lower = text.to_ascii_lowercase();
    let (number, scale) = if let Some(n) = lower.strip_suffix("ms") {
        (n, 1.0)
    } else if let Some(n) = lower.strip_suffix('s') {
        (n, 1000.0)
    } else {
        (lower.as_str(), 1.0)
    };
    let value: f64 = number.parse().map_err(|_| bad())?;
    let ms = (value * scale).round();
    if !ms.is_finite() || !(0.0..=f64::from(u32::MAX)).contains(&ms) {
        return Err(bad());
    }
    // In range and rounded just above.
    Ok(ms as u32)
}
