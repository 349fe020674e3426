//! Located variables (`%IX0.3`, `%QX0.5`, `%MX1.2`) to each machine's
//! devices, by rule (docs/ladder.md, "Declarations").

use std::fmt;

use crate::ladder::element::Element;
use crate::ladder::machine_target::LocatedError;
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
    let target = machine.target();
    if let Some(device) = target.located_word(area, rest) {
        return Ok(device);
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
    let device = target.located_bit(area, n).map_err(|e| match e {
        LocatedError::NotThere => bad(),
        LocatedError::NoRelays => AddressError::NoRelays,
        LocatedError::Past { what, first, last } => AddressError::PastAvr {
            address: crate::shown(address),
            what,
            first,
            last,
        },
    })?;
    check_element(machine, &Element::no(&device))
        .map(|_| device)
        .map_err(|e| AddressError::NotOnMachine(crate::shown(address), e))
}

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
