//! MINASEC-U's instruction set: one byte a step, opcode in bits 7-5 and
//! operand address in bits 4-0 (machines.md §1).

use std::fmt;

pub use crate::operand::MinasecOperandError as OperandError;

/// The eight opcodes, numbered as their three bits.
///
/// Bit 0 of the opcode means "invert"; bits 2-1 choose load / and / or /
/// store, which the seed calls OP2 OP1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Opcode {
    /// `LD a`: A = i.
    Ld = 0b000,
    /// `LDI a`: A = !i.
    Ldi = 0b001,
    /// `AND a`: A = A & i.
    And = 0b010,
    /// `ANDI a`: A = A & !i.
    Andi = 0b011,
    /// `OR a`: A = A | i.
    Or = 0b100,
    /// `ORI a`: A = A | !i.
    Ori = 0b101,
    /// `ST a`: write A to a; A unchanged.
    St = 0b110,
    /// `STI a`: write !A to a; A unchanged.
    Sti = 0b111,
}

impl Opcode {
    /// All opcodes in encoding order.
    pub const ALL: [Opcode; 8] = [
        Opcode::Ld,
        Opcode::Ldi,
        Opcode::And,
        Opcode::Andi,
        Opcode::Or,
        Opcode::Ori,
        Opcode::St,
        Opcode::Sti,
    ];

    /// The opcode whose three bits are the low bits of `bits`.
    pub const fn from_bits(bits: u8) -> Opcode {
        Opcode::ALL[(bits & 0b111) as usize]
    }

    /// The three opcode bits.
    pub const fn bits(self) -> u8 {
        self as u8
    }

    /// Opcode bit 0: the operand (or, for stores, the result) is inverted.
    pub const fn inverts(self) -> bool {
        self as u8 & 1 != 0
    }

    /// Opcode bit 1 (the seed's OP1).
    pub const fn op1(self) -> bool {
        self as u8 & 0b010 != 0
    }

    /// Opcode bit 2 (the seed's OP2).
    pub const fn op2(self) -> bool {
        self as u8 & 0b100 != 0
    }

    /// `ST` or `STI`: the step writes to its address (WE strobes low).
    pub const fn is_store(self) -> bool {
        self.op1() && self.op2()
    }

    /// The mnemonic as the seed writes it.
    pub const fn mnemonic(self) -> &'static str {
        match self {
            Opcode::Ld => "LD",
            Opcode::Ldi => "LDI",
            Opcode::And => "AND",
            Opcode::Andi => "ANDI",
            Opcode::Or => "OR",
            Opcode::Ori => "ORI",
            Opcode::St => "ST",
            Opcode::Sti => "STI",
        }
    }

    /// The opcode named by `text`, in any letter case.
    pub fn parse(text: &str) -> Option<Opcode> {
        Opcode::ALL
            .into_iter()
            .find(|op| op.mnemonic().eq_ignore_ascii_case(text))
    }
}

impl fmt::Display for Opcode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.mnemonic())
    }
}

/// The logic unit (seed, 命令セットと命令デコーダー): the accumulator's next
/// value from the opcode, the data on the input bus and the accumulator.
///
/// The seed's equation, verbatim: `D = i·(!OP1 + Q) + OP2·Q`, where `i` is
/// the input after the opcode's inversion bit and `Q` the accumulator.
pub const fn logic_unit(opcode: Opcode, data_in: bool, acc: bool) -> bool {
    let i = data_in ^ opcode.inverts();
    (i && (!opcode.op1() || acc)) || (opcode.op2() && acc)
}

/// A five-bit operand address, 0..=31.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Address(u8);

impl Address {
    /// The number of addresses.
    pub const COUNT: usize = 32;
    /// `T0`, the first timer.
    pub const T0: Address = Address(0b11100);
    /// `T1`, the second timer.
    pub const T1: Address = Address(0b11101);
    /// `C0`: write = count-up latch, read = match.
    pub const C0: Address = Address(0b11110);
    /// `C0R` (decided name): write = clear latch, read = always 0.
    pub const C0R: Address = Address(0b11111);

    /// The address `value`, if it fits in five bits.
    pub const fn new(value: u8) -> Option<Address> {
        if value < 32 {
            Some(Address(value))
        } else {
            None
        }
    }

    /// The address held in the low five bits of `bits`.
    pub const fn from_low_bits(bits: u8) -> Address {
        Address(bits & 0b1_1111)
    }

    /// The address as a number.
    pub const fn index(self) -> u8 {
        self.0
    }

    /// The device behind this address.
    pub const fn device(self) -> Device {
        match self.0 {
            0..=7 => Device::Input(self.0),
            8..=15 => Device::Output(self.0 - 8),
            16..=27 => Device::Relay(self.0 - 16),
            28 => Device::Timer(0),
            29 => Device::Timer(1),
            30 => Device::Counter,
            _ => Device::CounterClear,
        }
    }

    /// Parses a device name (`X00`, `Y7`, `M10`, `T0`, `T01`, `C0`, `C00`,
    /// `C0R`) or a raw address (`%11111`, `$1F`), in any letter case.
    pub fn parse(text: &str) -> Result<Address, OperandError> {
        let upper = text.to_ascii_uppercase();
        let bad = || OperandError::UnknownDevice(text.to_string());
        if let Some(bin) = upper.strip_prefix('%') {
            return parse_raw(bin, 2).ok_or_else(|| OperandError::BadRawAddress(text.to_string()));
        }
        if let Some(hex) = upper.strip_prefix('$') {
            return parse_raw(hex, 16).ok_or_else(|| OperandError::BadRawAddress(text.to_string()));
        }
        match upper.as_str() {
            "C0" | "C00" => return Ok(Address::C0),
            "C0R" | "C00R" => return Ok(Address::C0R),
            _ => {}
        }
        let (kind, digits) = upper.split_at(upper.chars().next().map_or(0, char::len_utf8));
        if digits.is_empty() || digits.len() > 2 || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad());
        }
        let n: u8 = digits.parse().map_err(|_| bad())?;
        let address = match (kind, n) {
            ("X", 0..=7) => n,
            ("Y", 0..=7) => 8 + n,
            ("M", 0..=7) => 16 + n,
            ("M", 10..=13) => 24 + (n - 10),
            ("T", 0..=1) => 28 + n,
            _ => return Err(bad()),
        };
        Ok(Address(address))
    }
}

fn parse_raw(digits: &str, radix: u32) -> Option<Address> {
    if digits.is_empty() {
        return None;
    }
    u8::from_str_radix(digits, radix)
        .ok()
        .and_then(Address::new)
}

impl fmt::Display for Address {
    /// The canonical device name: `X00`, `M10`, `T0`, `C0`, `C0R`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.device() {
            Device::Input(n) => write!(f, "X{n:02}"),
            Device::Output(n) => write!(f, "Y{n:02}"),
            Device::Relay(n) if n < 8 => write!(f, "M{n:02}"),
            Device::Relay(n) => write!(f, "M{}", n + 2),
            Device::Timer(n) => write!(f, "T{n}"),
            Device::Counter => f.write_str("C0"),
            Device::CounterClear => f.write_str("C0R"),
        }
    }
}

/// What sits at an address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Device {
    /// Digital input `X0n`: reads the input image; writes do nothing.
    Input(u8),
    /// Digital output `Y0n`: an output latch, read back immediately.
    Output(u8),
    /// Internal relay: index 0..=7 are `M00`-`M07`, 8..=11 are `M10`-`M13`.
    Relay(u8),
    /// RC on-delay timer `T0` / `T1`.
    Timer(u8),
    /// `C0`: write sets the count-up latch, read gives count == set value.
    Counter,
    /// `C0R`: write sets the clear latch, read gives 0.
    CounterClear,
}

/// One decoded step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Instruction {
    /// What the step does.
    pub opcode: Opcode,
    /// Where it reads or writes.
    pub address: Address,
}

impl Instruction {
    /// The erased-memory step, byte 0x00: `LD X00`.
    pub const ERASED: Instruction = Instruction {
        opcode: Opcode::Ld,
        address: Address(0),
    };

    /// Decodes a program byte. Every byte is a valid instruction.
    pub const fn decode(byte: u8) -> Instruction {
        Instruction {
            opcode: Opcode::from_bits(byte >> 5),
            address: Address::from_low_bits(byte),
        }
    }

    /// Encodes the step as its program byte.
    pub const fn encode(self) -> u8 {
        (self.opcode.bits() << 5) | self.address.index()
    }

    /// The byte as the programming sheet writes it: `100 01000`.
    pub fn binary(self) -> String {
        format!("{:03b} {:05b}", self.opcode.bits(), self.address.index())
    }
}

impl fmt::Display for Instruction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.opcode, self.address)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seed's truth table for the B part, row by row: (OP2, OP1, i, Q) -> D.
    /// The inversion bit is applied to `i` before the table.
    #[test]
    fn logic_unit_matches_the_seed_truth_table_for_all_opcodes() {
        for op in Opcode::ALL {
            for data in [false, true] {
                for q in [false, true] {
                    let i = data ^ op.inverts();
                    let expected = match (op.op2(), op.op1()) {
                        (false, false) => i,     // LD: i goes straight to D
                        (false, true) => i && q, // AND
                        (true, false) => i || q, // OR
                        (true, true) => q,       // ST: Q goes straight to D
                    };
                    assert_eq!(logic_unit(op, data, q), expected, "{op} i={data} Q={q}");
                }
            }
        }
    }

    #[test]
    fn the_seed_table_rows_literally() {
        // (mnemonic, i, Q, D) from the seed, plus the inverting twins.
        let rows = [
            (Opcode::Ld, [0, 0, 1, 1]),
            (Opcode::And, [0, 0, 0, 1]),
            (Opcode::Or, [0, 1, 1, 1]),
            (Opcode::St, [0, 1, 0, 1]),
            (Opcode::Ldi, [1, 1, 0, 0]),
            (Opcode::Andi, [0, 1, 0, 0]),
            (Opcode::Ori, [1, 1, 0, 1]),
            (Opcode::Sti, [0, 1, 0, 1]),
        ];
        for (op, ds) in rows {
            for (k, d) in ds.into_iter().enumerate() {
                let (i, q) = (k & 2 != 0, k & 1 != 0);
                assert_eq!(logic_unit(op, i, q), d == 1, "{op} i={i} Q={q}");
            }
        }
    }

    #[test]
    fn encode_decode_round_trips_every_byte() {
        for byte in 0..=255u8 {
            assert_eq!(Instruction::decode(byte).encode(), byte);
        }
        let or_y00 = Instruction {
            opcode: Opcode::Or,
            address: Address::parse("Y00").unwrap(),
        };
        assert_eq!(or_y00.encode(), 0b100_01000);
        assert_eq!(or_y00.binary(), "100 01000");
        assert_eq!(Instruction::decode(0), Instruction::ERASED);
    }

    #[test]
    fn device_names_aliases_and_raw_addresses() {
        let cases = [
            ("X00", 0),
            ("x7", 7),
            ("Y00", 8),
            ("Y07", 15),
            ("M00", 16),
            ("M07", 23),
            ("M10", 24),
            ("M13", 27),
            ("T0", 28),
            ("T00", 28),
            ("T01", 29),
            ("C0", 30),
            ("C00", 30),
            ("C0R", 31),
            ("%11111", 31),
            ("$1F", 31),
            ("$0a", 10),
        ];
        for (name, addr) in cases {
            assert_eq!(Address::parse(name).map(Address::index), Ok(addr), "{name}");
        }
        for a in 0..32u8 {
            let address = Address::new(a).unwrap();
            assert_eq!(Address::parse(&address.to_string()), Ok(address));
        }
    }

    #[test]
    fn bad_operands_are_errors() {
        for name in [
            "X08", "M08", "M14", "T2", "C1", "Z00", "", "X", "X001", "Y-1", "√",
        ] {
            assert!(
                matches!(Address::parse(name), Err(OperandError::UnknownDevice(_))),
                "{name:?}"
            );
        }
        for raw in ["%100000", "$20", "%", "$", "%12", "$G"] {
            assert!(
                matches!(Address::parse(raw), Err(OperandError::BadRawAddress(_))),
                "{raw:?}"
            );
        }
    }
}
