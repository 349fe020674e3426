//! IEC 61131-3 elementary types and typed values, and what the soft PLC's
//! blocks compute with them. Integers wrap in their type's width (as the
//! C that OpenPLC's runtime compiles to does); an integer divided by zero
//! gives 0 (as its MOD does), a REAL follows IEEE 754; nothing panics.

use std::cmp::Ordering;
use std::sync::Arc;

use crate::plc::Value;

/// The most characters a STRING holds (each one byte, as IEC's STRING
/// has them): what a Siemens S7 STRING holds; a longer text is cut there.
pub const STRING_CAPACITY: usize = 254;

/// An elementary type the soft PLC holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DataType {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Ulint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    /// A 64-bit real (IEC's LREAL, issue #54).
    Lreal,
    /// A duration, held in nanoseconds, printed in milliseconds.
    Time,
    /// A text of up to [`STRING_CAPACITY`] characters.
    String,
}

impl DataType {
    /// Every type, in the order docs/soft-plc.md lists them.
    pub const ALL: [DataType; 17] = [
        DataType::Bool,
        DataType::Sint,
        DataType::Int,
        DataType::Dint,
        DataType::Lint,
        DataType::Usint,
        DataType::Uint,
        DataType::Udint,
        DataType::Ulint,
        DataType::Byte,
        DataType::Word,
        DataType::Dword,
        DataType::Lword,
        DataType::Real,
        DataType::Lreal,
        DataType::Time,
        DataType::String,
    ];

    /// The IEC name (`INT`, `UDINT` …).
    pub const fn name(self) -> &'static str {
        match self {
            DataType::Bool => "BOOL",
            DataType::Sint => "SINT",
            DataType::Int => "INT",
            DataType::Dint => "DINT",
            DataType::Lint => "LINT",
            DataType::Usint => "USINT",
            DataType::Uint => "UINT",
            DataType::Udint => "UDINT",
            DataType::Ulint => "ULINT",
            DataType::Byte => "BYTE",
            DataType::Word => "WORD",
            DataType::Dword => "DWORD",
            DataType::Lword => "LWORD",
            DataType::Real => "REAL",
            DataType::Lreal => "LREAL",
            DataType::Time => "TIME",
            DataType::String => "STRING",
        }
    }

    /// The type an IEC name names, in any case.
    pub fn from_name(name: &str) -> Option<DataType> {
        DataType::ALL
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(name))
    }

    /// Bits of an integer or bit-string type (`None` for BOOL, REAL, TIME,
    /// STRING).
    pub const fn bits(self) -> Option<u32> {
        match self {
            DataType::Sint | DataType::Usint | DataType::Byte => Some(8),
            DataType::Int | DataType::Uint | DataType::Word => Some(16),
            DataType::Dint | DataType::Udint | DataType::Dword => Some(32),
            DataType::Lint | DataType::Ulint | DataType::Lword => Some(64),
            DataType::Bool
            | DataType::Real
            | DataType::Lreal
            | DataType::Time
            | DataType::String => None,
        }
    }

    /// The least and greatest integer of this type (`None` for BOOL, REAL,
    /// TIME).
    pub const fn range(self) -> Option<(i128, i128)> {
        match self.bits() {
            Some(bits) if self.is_signed() => {
                Some((-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1))
            }
            Some(bits) => Some((0, (1i128 << bits) - 1)),
            None => None,
        }
    }

    /// Whether an integer of this type is signed.
    pub const fn is_signed(self) -> bool {
        matches!(
            self,
            DataType::Sint | DataType::Int | DataType::Dint | DataType::Lint
        )
    }

    /// The value a variable of this type starts at without an initial value.
    pub fn zero(self) -> Data {
        match self {
            DataType::Bool => Data::Bool(false),
            DataType::Real => Data::Real(0.0),
            DataType::Lreal => Data::Lreal(0.0),
            DataType::Time => Data::Time(0),
            DataType::String => Data::Text(Arc::default()),
            _ => Data::Int(self, 0),
        }
    }
}

/// A typed value.
#[derive(Clone, Debug, PartialEq)]
pub enum Data {
    Bool(bool),
    /// An integer or bit string of the type: its bits in the low end of an
    /// `i64`, sign-extended for a signed type (always in range).
    Int(DataType, i64),
    Real(f32),
    /// An LREAL.
    Lreal(f64),
    /// Nanoseconds.
    Time(i64),
    /// A STRING (at most [`STRING_CAPACITY`] characters): shared, so moving it
    /// between a variable and the accumulator copies no characters; behind
    /// one thin pointer, so a value stays 16 bytes (the scan copies values
    /// all the time, texts seldom).
    Text(Arc<String>),
}

/// Keeps the low `bits` of `v`, sign-extended when `signed`: two's
/// complement wrapping in that width.
const fn wrap(v: i128, bits: u32, signed: bool) -> i64 {
    let shift = 128 - bits;
    if signed {
        ((v << shift) >> shift) as i64
    } else {
        ((v << shift) as u128 >> shift) as i64
    }
}

impl Data {
    /// `v` as an integer of type `t`, wrapped into its width (`t` must be
    /// an integer or bit-string type; any other gives its zero).
    #[inline]
    pub fn integer(t: DataType, v: i128) -> Data {
        match t.bits() {
            Some(bits) => Data::Int(t, wrap(v, bits, t.is_signed())),
            None => t.zero(),
        }
    }

    /// A STRING of `text`, cut at [`STRING_CAPACITY`] characters (as
    /// IEC cuts a text assigned to a shorter STRING).
    pub fn text(text: impl Into<String>) -> Data {
        let mut text = text.into();
        if let Some((end, _)) = text.char_indices().nth(STRING_CAPACITY) {
            text.truncate(end);
        }
        Data::Text(Arc::new(text))
    }

    /// Its type.
    pub const fn data_type(&self) -> DataType {
        match self {
            Data::Bool(_) => DataType::Bool,
            Data::Int(t, _) => *t,
            Data::Real(_) => DataType::Real,
            Data::Lreal(_) => DataType::Lreal,
            Data::Time(_) => DataType::Time,
            Data::Text(_) => DataType::String,
        }
    }

    /// As a device value for `--watch` and the page: unsigned types
    /// unsigned, TIME in milliseconds.
    pub fn to_value(&self) -> Value {
        match *self {
            Data::Bool(b) => Value::Bit(b),
            Data::Int(t, v) if !t.is_signed() => Value::Uint(v as u64 & mask(t)),
            Data::Int(_, v) => Value::Int(v),
            // Through its shortest decimal: 0.1 stays 0.1, not the
            // f32's 0.10000000149011612.
            Data::Real(r) => Value::Real(r.to_string().parse().unwrap_or(f64::from(r))),
            Data::Lreal(r) => Value::Real(r),
            Data::Time(ns) => Value::Int(ns / 1_000_000),
            Data::Text(ref t) => Value::Text(Arc::clone(t)),
        }
    }

    /// Whether it is on: TRUE, or a number other than zero (what a
    /// contact on it would pass; what the tracer records).
    #[inline(always)]
    pub fn is_on(&self) -> bool {
        match *self {
            Data::Bool(b) => b,
            Data::Int(_, v) | Data::Time(v) => v != 0,
            Data::Real(r) => r != 0.0,
            Data::Lreal(r) => r != 0.0,
            Data::Text(_) => false,
        }
    }

    /// The integer, widened (`None` for BOOL, REAL, TIME, STRING).
    #[inline]
    pub(crate) fn int(&self) -> Option<i128> {
        match *self {
            Data::Int(t, v) if !t.is_signed() => Some(i128::from(v as u64 & mask(t))),
            Data::Int(_, v) => Some(i128::from(v)),
            _ => None,
        }
    }

    /// ADD, SUB, MUL, DIV, MOD of two values of one type; `None` when the
    /// types differ or the operation does not apply to them (the compiler
    /// refuses those before a program runs).
    #[inline]
    pub fn arith(&self, op: Arith, other: &Data) -> Option<Data> {
        match (self, other) {
            (&Data::Int(t, _), &Data::Int(u, _)) if t == u => {
                let (a, b) = (self.int()?, other.int()?);
                let v = match op {
                    Arith::Add => a + b,
                    Arith::Sub => a - b,
                    Arith::Mul => a.wrapping_mul(b),
                    Arith::Div if b == 0 => 0,
                    Arith::Div => a / b,
                    Arith::Mod if b == 0 => 0,
                    Arith::Mod => a % b,
                };
                Some(Data::integer(t, v))
            }
            (&Data::Real(a), &Data::Real(b)) => Some(Data::Real(match op {
                Arith::Add => a + b,
                Arith::Sub => a - b,
                Arith::Mul => a * b,
                Arith::Div => a / b,
                Arith::Mod => return None,
            })),
            (&Data::Lreal(a), &Data::Lreal(b)) => Some(Data::Lreal(match op {
                Arith::Add => a + b,
                Arith::Sub => a - b,
                Arith::Mul => a * b,
                Arith::Div => a / b,
                Arith::Mod => return None,
            })),
            (&Data::Time(a), &Data::Time(b)) => match op {
                Arith::Add => Some(Data::Time(a.wrapping_add(b))),
                Arith::Sub => Some(Data::Time(a.wrapping_sub(b))),
                _ => None,
            },
            _ => None,
        }
    }

    /// NEG: the negation, wrapped (`-32768` stays `-32768` as an INT).
    pub fn negate(&self) -> Option<Data> {
        match *self {
            Data::Int(t, _) => Some(Data::integer(t, -self.int()?)),
            Data::Real(r) => Some(Data::Real(-r)),
            Data::Lreal(r) => Some(Data::Lreal(-r)),
            Data::Time(ns) => Some(Data::Time(ns.wrapping_neg())),
            Data::Bool(_) | Data::Text(_) => None,
        }
    }

    /// ABS: the magnitude, wrapped as NEG's (`-32768` stays `-32768` as
    /// an INT); an unsigned integer is its own.
    pub fn abs(&self) -> Option<Data> {
        match *self {
            Data::Int(t, _) => Some(Data::integer(t, self.int()?.abs())),
            Data::Real(r) => Some(Data::Real(r.abs())),
            Data::Lreal(r) => Some(Data::Lreal(r.abs())),
            _ => None,
        }
    }

    /// A REAL's value.
    pub fn real(&self) -> Option<f32> {
        match *self {
            Data::Real(r) => Some(r),
            _ => None,
        }
    }

    /// EXPT: a REAL (or LREAL) to the power of a real or of an integer
    /// (an integer power multiplies, exactly as far as the type holds it).
    pub fn expt(&self, power: &Data) -> Option<Data> {
        if let Data::Lreal(base) = *self {
            return Some(Data::Lreal(match *power {
                Data::Real(p) => base.powf(f64::from(p)),
                Data::Lreal(p) => base.powf(p),
                Data::Int(..) => {
                    let p = power.int()?.clamp(i32::MIN.into(), i32::MAX.into());
                    base.powi(p as i32)
                }
                _ => return None,
            }));
        }
        let base = self.real()?;
        Some(Data::Real(match *power {
            Data::Real(p) => base.powf(p),
            Data::Lreal(p) => base.powf(p as f32),
            Data::Int(..) => {
                let p = power.int()?.clamp(i32::MIN.into(), i32::MAX.into());
                base.powi(p as i32)
            }
            _ => return None,
        }))
    }

    /// AND, OR, XOR of two values of one type: BOOL, or an integer's bits
    /// in its width (`None` for other types, or types that differ).
    #[inline]
    pub fn bitwise(&self, op: Bitwise, other: &Data) -> Option<Data> {
        match (self, other) {
            (&Data::Bool(a), &Data::Bool(b)) => Some(Data::Bool(match op {
                Bitwise::And => a & b,
                Bitwise::Or => a | b,
                Bitwise::Xor => a ^ b,
            })),
            (&Data::Int(t, a), &Data::Int(u, b)) if t == u => Some(Data::integer(
                t,
                i128::from(match op {
                    Bitwise::And => a & b,
                    Bitwise::Or => a | b,
                    Bitwise::Xor => a ^ b,
                }),
            )),
            _ => None,
        }
    }

    /// NOT: every bit of an integer in its width, or a BOOL.
    pub fn invert(&self) -> Option<Data> {
        match *self {
            Data::Bool(b) => Some(Data::Bool(!b)),
            Data::Int(t, v) => Some(Data::integer(t, i128::from(!v))),
            _ => None,
        }
    }

    /// SHL, SHR, ROL, ROR of an integer's bits in its width by the
    /// integer `n` (any integer type, its whole value): shifts fill with
    /// zeros (SHR too, on a signed type: it moves bits, it does not
    /// divide) and give 0 from `n` ≥ the width, or for a negative `n`;
    /// rotations take `n` modulo the width (ROL by −1 is ROR by 1).
    /// `None` for other types.
    pub fn shift(&self, op: Shift, n: &Data) -> Option<Data> {
        let Data::Int(t, v) = *self else {
            return None;
        };
        let bits = t.bits()?;
        let n = n.int()?;
        let pattern = v as u64 & mask_bits(bits);
        let moved = match op {
            Shift::Shl | Shift::Shr if !(0..i128::from(bits)).contains(&n) => 0,
            Shift::Shl => pattern << n,
            Shift::Shr => pattern >> n,
            Shift::Rol | Shift::Ror => {
                // In 0 … width − 1: the cast cannot lose anything.
                let r = n.rem_euclid(i128::from(bits)) as u32;
                let n = if op == Shift::Rol {
                    r
                } else {
                    (bits - r) % bits
                };
                if n == 0 {
                    pattern
                } else {
                    pattern << n | pattern >> (bits - n)
                }
            }
        };
        Some(Data::integer(t, i128::from(moved & mask_bits(bits))))
    }

    /// EQ, GT … : how two values of one type compare (`None` for types
    /// that differ, or a REAL NaN, which no comparison holds for); two
    /// STRINGs compare by their bytes, as IEC's comparison of texts does.
    #[inline]
    pub fn compare(&self, other: &Data) -> Option<Ordering> {
        match (self, other) {
            (Data::Bool(a), Data::Bool(b)) => Some(a.cmp(b)),
            (Data::Int(t, _), Data::Int(u, _)) if t == u => Some(self.int()?.cmp(&other.int()?)),
            (Data::Real(a), Data::Real(b)) => a.partial_cmp(b),
            (Data::Lreal(a), Data::Lreal(b)) => a.partial_cmp(b),
            (Data::Time(a), Data::Time(b)) => Some(a.cmp(b)),
            (Data::Text(a), Data::Text(b)) => Some(a.as_bytes().cmp(b.as_bytes())),
            _ => None,
        }
    }

    /// The value converted to `to` (`*_TO_*`): an integer wraps into the
    /// narrower width, a REAL rounds to the nearest integer (halves away
    /// from zero) and saturates at the type's limits (NaN gives 0), BOOL
    /// is 0 or 1, TIME converts from and to milliseconds.
    pub fn convert(&self, to: DataType) -> Data {
        let whole: i128 = match *self {
            Data::Bool(b) => i128::from(b),
            Data::Int(..) => self.int().unwrap_or(0),
            // A text is no number: the type's zero (the compiler refuses
            // a conversion of a STRING before a program runs).
            Data::Text(_) => return to.zero(),
            Data::Real(r) => return Data::Lreal(f64::from(r)).convert_real(to),
            Data::Lreal(_) => return self.convert_real(to),
            Data::Time(ns) => i128::from(ns / 1_000_000),
        };
        match to {
            DataType::Bool => Data::Bool(whole != 0),
            DataType::Real => Data::Real(whole as f32),
            DataType::Lreal => Data::Lreal(whole as f64),
            DataType::String => to.zero(),
            DataType::Time => Data::Time(match *self {
                Data::Time(ns) => ns,
                _ => (whole as i64).wrapping_mul(1_000_000),
            }),
            _ => Data::integer(to, whole),
        }
    }
}

impl Data {
    /// A real (REAL or LREAL, as this LREAL: a REAL widens exactly)
    /// converted to `to`: to a REAL the nearest f32, to an integer
    /// rounded (halves away from zero) and saturated, to TIME from ms.
    fn convert_real(&self, to: DataType) -> Data {
        let Data::Lreal(r) = *self else {
            return self.clone();
        };
        match to {
            DataType::Real => Data::Real(r as f32),
            DataType::Lreal => Data::Lreal(r),
            DataType::Bool => Data::Bool(r != 0.0),
            DataType::Time => Data::Time((r * 1e6).round() as i64),
            DataType::String => to.zero(),
            _ => Data::integer(to, saturate(to, r)),
        }
    }
}

/// The bits of an unsigned type, as a mask.
const fn mask(t: DataType) -> u64 {
    match t.bits() {
        Some(bits) => mask_bits(bits),
        None => u64::MAX,
    }
}

/// The low `bits` bits, as a mask.
const fn mask_bits(bits: u32) -> u64 {
    if bits >= 64 {
        u64::MAX
    } else {
        (1 << bits) - 1
    }
}

/// MIN, MAX and LIMIT of values of one type (`None` for types that
/// differ or a NaN); LIMIT(MN, IN, MX) is IN held within MN … MX.
pub fn min(a: &Data, b: &Data) -> Option<Data> {
    Some(if a.compare(b)? == Ordering::Greater {
        b.clone()
    } else {
        a.clone()
    })
}

/// See [`min`].
pub fn max(a: &Data, b: &Data) -> Option<Data> {
    Some(if a.compare(b)? == Ordering::Less {
        b.clone()
    } else {
        a.clone()
    })
}

/// See [`min`].
pub fn limit(mn: &Data, input: &Data, mx: &Data) -> Option<Data> {
    min(&max(input, mn)?, mx)
}

/// SEL: `in0` when `g` is FALSE, else `in1`.
pub fn select(g: bool, in0: &Data, in1: &Data) -> Data {
    if g {
        in1.clone()
    } else {
        in0.clone()
    }
}

/// A real rounded and held within integer type `t`'s range.
fn saturate(t: DataType, r: f64) -> i128 {
    let Some((lo, hi)) = t.range() else {
        return 0;
    };
    if r.is_nan() {
        return 0;
    }
    // `as` saturates at i128's range, far beyond every type's.
    (r.round() as i128).clamp(lo, hi)
}

/// The bitwise blocks on two operands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bitwise {
    And,
    Or,
    Xor,
}

/// The shift and rotate blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shift {
    Shl,
    Shr,
    Rol,
    Ror,
}

/// The arithmetic blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arith {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
}

#[cfg(test)]
mod tests;

// The scan copies values all the time: a text must not make them wider.
const _: () = assert!(std::mem::size_of::<Data>() == 16);
