//! Located variables (`%IX0.3`, `%QX0.5`, `%MX1.2`) to each machine's
//! devices, by rule (docs/ladder.md, "Declarations").

use std::fmt;

use crate::ladder::element::Element;
use crate::ladder::target::{check_element, ElementError};
use crate::MachineId;

/// Why a located variable's address has no device on a machine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AddressError {
    /// Not `%IX0.0`, `%QX0.0` or `%MX0.0` (the address, shown).
    NotAnAddress(String),
    /// A word address (`%IW2`) where a bit is needed.
    Word(String),
    /// `%MX` on the Arduino PLC.
    NoRelays,
    /// Past the AVR PLC's registers for its kind.
    PastAvr {
        /// The address, shown.
        address: String,
        /// inputs, outputs or relays.
        what: &'static str,
        /// The first and last register.
        first: u8,
        /// The last register.
        last: u8,
    },
    /// A device the machine does not have (the address, shown; why).
    NotOnMachine(String, ElementError),
}

impl fmt::Display for AddressError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AddressError::NotAnAddress(a) => {
                write!(f, "address {a} is not %IX0.0, %QX0.0 or %MX0.0")
            }
            AddressError::Word(a) => write!(
                f,
                "{} is a word: Hashigo's ladders import bit variables only (and IO86A's analog inputs %IW0, %IW1)",
                a.trim_matches('"')
            ),
            AddressError::NoRelays => f.write_str("the Arduino PLC has no internal relays"),
            AddressError::PastAvr {
                address,
                what,
                first,
                last,
            } => write!(
                f,
                "{} is past the AVR PLC's {what} (R{first}.0-R{last}.7 in Hashigo)",
                address.trim_matches('"')
            ),
            AddressError::NotOnMachine(a, e) => write!(f, "{} is {e}", a.trim_matches('"')),
        }
    }
}

impl std::error::Error for AddressError {}

/// The device a located variable's address stands for on `machine`:
/// `%IX0.n` input n, `%QX0.n` output n, `%MX0.n` (or `%M0.n`) internal
/// relay n (byte b, bit n: b × 8 + n), within the machine's sizes.
pub fn located(machine: MachineId, address: &str) -> Result<String, AddressError> {
    let a = address.trim().to_ascii_uppercase();
    let bad = || AddressError::NotAnAddress(crate::shown(address));
    let rest = a.strip_prefix('%').ok_or_else(bad)?;
    let mut chars = rest.chars();
    let area = chars.next().ok_or_else(bad)?;
    let rest = chars.as_str();
    // IO86A reads X04 / X05 as analog words into D06 / D07.
    if machine == MachineId::Io86a && area == 'I' {
        match rest {
            "W0" => return Ok("D06".to_string()),
            "W1" => return Ok("D07".to_string()),
            _ => {}
        }
    }
    let rest = match rest.chars().next() {
        Some('X') => &rest[1..],
        Some('B' | 'W' | 'D' | 'L') => return Err(AddressError::Word(crate::shown(address))),
        _ => rest,
    };
    let (byte, bit) = rest.split_once('.').ok_or_else(bad)?;
    let (byte, bit): (u32, u32) = (
        byte.parse().map_err(|_| bad())?,
        bit.parse().map_err(|_| bad())?,
    );
    if bit > 7 {
        return Err(bad());
    }
    let n = byte.saturating_mul(8).saturating_add(bit);
    let device = match (machine, area) {
        (MachineId::Io86a | MachineId::MinasecU, 'I') => format!("X{n:02}"),
        (MachineId::Io86a | MachineId::MinasecU, 'Q') => format!("Y{n:02}"),
        (MachineId::Io86a, 'M') => format!("M{n:02}"),
        // MINASEC-U's relays are M00-M07 and M10-M13.
        (MachineId::MinasecU, 'M') => format!("M{}{}", n / 8, n % 8),
        (MachineId::ArduinoPlc, 'I') => format!("X{n:03}"),
        (MachineId::ArduinoPlc, 'Q') => format!("Y{n:03}"),
        (MachineId::ArduinoPlc, 'M') => return Err(AddressError::NoRelays),
        (MachineId::AvrPlc, 'I' | 'Q' | 'M') => return avr_located(area, n, address),
        _ => return Err(bad()),
    };
    check_element(machine, &Element::no(&device))
        .map(|_| device)
        .map_err(|e| AddressError::NotOnMachine(crate::shown(address), e))
}

/// The AVR PLC has no fixed inputs or outputs (any register bit may be
/// either); Hashigo follows the seed's own program, inputs in R4 and
/// coils in R5, relays after them, and leaves R16-R25 to the compiler's
/// temporaries: `%IX0.n` → R4.n, `%QX0.n` → R5.n, `%MXb.n` → R(6+b).n
/// up to R15.7.
fn avr_located(area: char, n: u32, address: &str) -> Result<String, AddressError> {
    let (registers, what) = match area {
        'I' => (AVR_INPUTS, "inputs"),
        'Q' => (AVR_OUTPUTS, "outputs"),
        _ => (AVR_RELAYS, "relays"),
    };
    let bits = registers.len() as u32 * 8;
    if n >= bits {
        let (first, last) = (registers.start, registers.end - 1);
        return Err(AddressError::PastAvr {
            address: crate::shown(address),
            what,
            first,
            last,
        });
    }
    Ok(format!("R{}.{}", registers.start as u32 + n / 8, n % 8))
}

/// The AVR PLC's registers for inputs, outputs and relays
/// ([`avr_located`], and what `propose` hands out).
pub(super) const AVR_INPUTS: std::ops::Range<u8> = 4..5;
pub(super) const AVR_OUTPUTS: std::ops::Range<u8> = 5..6;
pub(super) const AVR_RELAYS: std::ops::Range<u8> = 6..16;

/// Whether variable `name` is what Hashigo's PLCopen export declares for
/// a soft PLC ladder's bare `address` (`IX0_0` at `%IX0.0`): read back
/// as the address, so a ladder exported and opened again is the same.
pub(super) fn stands_for(name: &str, address: &str) -> bool {
    crate::iec::Address::parse(address.trim()).is_ok_and(|a| {
        let written = a.to_string();
        written.trim_start_matches('%').replace('.', "_") == name.trim()
            && written == address.trim()
    })
}
