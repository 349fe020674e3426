//! Located variables' addresses (IEC 61131-3 "directly represented
//! variables"): `%IX0.0`, `%IX100.1`, `%I0.0`, `%QX0.0`, `%QW2`, `%IW0`,
//! `%MD10`, `%ML3`. The soft PLC's I/O is the set of addresses its program
//! names, so any address of this form is one.

use std::fmt;

use super::data::DataType;

/// Which image an address is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Area {
    /// `%I`: inputs, read at the start of a scan.
    Input,
    /// `%Q`: outputs, written at its end.
    Output,
    /// `%M`: memory.
    Memory,
}

/// How wide the addressed item is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Size {
    /// `X` (or none): a bit, `byte.bit`.
    Bit,
    /// `B`: 8 bits.
    Byte,
    /// `W`: 16 bits.
    Word,
    /// `D`: 32 bits.
    Double,
    /// `L`: 64 bits.
    Long,
}

/// A located variable's address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Address {
    pub area: Area,
    pub size: Size,
    /// The byte (bits) or item (others) number.
    pub index: u32,
    /// The bit in its byte, 0-7, for a bit address.
    pub bit: Option<u8>,
}

/// Why an address is not one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AddressError {
    /// It does not start with `%I`, `%Q` or `%M`.
    NoArea(String),
    /// The size letter is not X, B, W, D or L.
    BadSize(String),
    /// The numbers are missing or not numbers, or a bit address lacks
    /// `.bit` (or another has one).
    BadNumber(String),
    /// A bit number above 7.
    BitOutOfRange(String),
    /// A variable of this type cannot live at an address of this size.
    WrongType {
        address: String,
        data_type: DataType,
    },
}

impl fmt::Display for AddressError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AddressError::NoArea(a) => {
                write!(
                    f,
                    "`{a}` is not an address (%I, %Q or %M, e.g. %IX0.0, %QW2)"
                )
            }
            AddressError::BadSize(a) => {
                write!(f, "`{a}`: the size after %I, %Q or %M is X, B, W, D or L")
            }
            AddressError::BadNumber(a) => write!(
                f,
                "`{a}`: a bit is byte.bit (%IX0.1), a word one number (%QW2)"
            ),
            AddressError::BitOutOfRange(a) => write!(f, "`{a}`: a bit number is 0-7"),
            AddressError::WrongType { address, data_type } => {
                write!(f, "a {} cannot be at {address}", data_type.name())
            }
        }
    }
}

impl std::error::Error for AddressError {}

impl Address {
    /// Reads an address like `%IX0.0` or `%QW2` (letters in any case).
    pub fn parse(text: &str) -> Result<Address, AddressError> {
        let text = text.trim();
        let upper = text.to_ascii_uppercase();
        let rest = upper
            .strip_prefix('%')
            .ok_or_else(|| AddressError::NoArea(text.into()))?;
        let area = match rest.as_bytes().first() {
            Some(b'I') => Area::Input,
            Some(b'Q') => Area::Output,
            Some(b'M') => Area::Memory,
            _ => return Err(AddressError::NoArea(text.into())),
        };
        let rest = &rest[1..];
        let (size, numbers) = match rest.as_bytes().first() {
            Some(b'X') => (Size::Bit, &rest[1..]),
            Some(b'B') => (Size::Byte, &rest[1..]),
            Some(b'W') => (Size::Word, &rest[1..]),
            Some(b'D') => (Size::Double, &rest[1..]),
            Some(b'L') => (Size::Long, &rest[1..]),
            Some(c) if c.is_ascii_digit() => (Size::Bit, rest),
            _ => return Err(AddressError::BadSize(text.into())),
        };
        let number = |s: &str| -> Result<u32, AddressError> {
            if s.is_empty() || !s.bytes().all(|c| c.is_ascii_digit()) {
                return Err(AddressError::BadNumber(text.into()));
            }
            s.parse().map_err(|_| AddressError::BadNumber(text.into()))
        };
        match (size, numbers.split_once('.')) {
            (Size::Bit, Some((byte, bit))) => {
                let bit = number(bit)?;
                if bit > 7 {
                    return Err(AddressError::BitOutOfRange(text.into()));
                }
                Ok(Address {
                    area,
                    size,
                    index: number(byte)?,
                    bit: Some(bit as u8),
                })
            }
            (Size::Bit, None) | (_, Some(_)) => Err(AddressError::BadNumber(text.into())),
            (_, None) => Ok(Address {
                area,
                size,
                index: number(numbers)?,
                bit: None,
            }),
        }
    }

    /// Whether a variable of `t` can be at this address: a bit holds a
    /// BOOL; a word INT, UINT or WORD; a double word DINT, UDINT, DWORD,
    /// REAL or TIME; a long word LINT or ULINT; a byte none of the types
    /// the soft PLC has.
    pub fn holds(self, t: DataType) -> bool {
        use DataType::*;
        match self.size {
            Size::Bit => t == Bool,
            Size::Byte => false,
            Size::Word => matches!(t, Int | Uint | Word),
            Size::Double => matches!(t, Dint | Udint | Dword | Real | Time),
            Size::Long => matches!(t, Lint | Ulint | Lword | Lreal),
        }
    }

    /// The type of an address a program uses without declaring it: a
    /// bit is a BOOL, a word an INT, a double word a DINT, a long word a
    /// LINT (as OpenPLC's located variables default); a byte has none.
    pub fn default_type(self) -> Option<DataType> {
        match self.size {
            Size::Bit => Some(DataType::Bool),
            Size::Byte => None,
            Size::Word => Some(DataType::Int),
            Size::Double => Some(DataType::Dint),
            Size::Long => Some(DataType::Lint),
        }
    }

    /// The address checked for a variable of type `t`.
    pub fn for_type(self, t: DataType) -> Result<Address, AddressError> {
        if self.holds(t) {
            Ok(self)
        } else {
            Err(AddressError::WrongType {
                address: self.to_string(),
                data_type: t,
            })
        }
    }
}

impl fmt::Display for Address {
    /// As IEC writes it, with the size letter: `%IX0.0`, `%QW2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let area = match self.area {
            Area::Input => 'I',
            Area::Output => 'Q',
            Area::Memory => 'M',
        };
        let size = match self.size {
            Size::Bit => 'X',
            Size::Byte => 'B',
            Size::Word => 'W',
            Size::Double => 'D',
            Size::Long => 'L',
        };
        write!(f, "%{area}{size}{}", self.index)?;
        if let Some(bit) = self.bit {
            write!(f, ".{bit}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_addresses_real_projects_use() {
        for (text, shown) in [
            ("%IX0.0", "%IX0.0"),
            ("%IX100.1", "%IX100.1"),
            ("%I0.0", "%IX0.0"),
            ("%qx0.7", "%QX0.7"),
            ("%QW2", "%QW2"),
            ("%IW0", "%IW0"),
            ("%MD10", "%MD10"),
            ("%ML3", "%ML3"),
            ("%MB4", "%MB4"),
        ] {
            let a = Address::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(a.to_string(), shown);
            assert_eq!(Address::parse(shown), Ok(a), "{shown} reads back");
        }
        let a = Address::parse("%IX100.1").expect("an address");
        assert_eq!(
            (a.area, a.size, a.index, a.bit),
            (Area::Input, Size::Bit, 100, Some(1))
        );
    }

    #[test]
    fn bad_addresses_say_why() {
        let err = |t| Address::parse(t).expect_err(t);
        assert!(matches!(err("IX0.0"), AddressError::NoArea(_)));
        assert!(matches!(err("%AX0.0"), AddressError::NoArea(_)));
        assert!(matches!(err("%IZ0"), AddressError::BadSize(_)));
        assert!(
            matches!(err("%IX0"), AddressError::BadNumber(_)),
            "a bit needs .bit"
        );
        assert!(matches!(err("%QW2.1"), AddressError::BadNumber(_)));
        assert!(matches!(err("%IX0.8"), AddressError::BitOutOfRange(_)));
        assert!(matches!(err("%IX.1"), AddressError::BadNumber(_)));
        assert!(matches!(
            err("%IX99999999999.0"),
            AddressError::BadNumber(_)
        ));
        assert!(matches!(err("%"), AddressError::NoArea(_)));
        assert_eq!(err("%IX0.9").to_string(), "`%IX0.9`: a bit number is 0-7");
    }

    #[test]
    fn each_size_holds_its_types() {
        let at = |t| Address::parse(t).expect("an address");
        assert!(at("%IX0.0").holds(DataType::Bool));
        assert!(!at("%IX0.0").holds(DataType::Int));
        assert!(at("%IW0").holds(DataType::Int) && at("%QW1").holds(DataType::Word));
        assert!(at("%MD0").holds(DataType::Real) && at("%MD0").holds(DataType::Dint));
        assert!(at("%ML0").holds(DataType::Lint) && !at("%ML0").holds(DataType::Dint));
        assert_eq!(
            at("%QW2")
                .for_type(DataType::Bool)
                .map_err(|e| e.to_string()),
            Err("a BOOL cannot be at %QW2".to_string())
        );
    }
}
