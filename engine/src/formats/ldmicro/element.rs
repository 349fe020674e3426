//! LDmicro's elements as a file holds them (docs/ldmicro.md, "Elements"):
//! one variant per kind of line, its arguments typed, so that every later
//! step (drawing, running, writing back) matches on what LDmicro meant.
//! Names and numeric operands stay text: an operand is a variable's name
//! or a number (`10`, `0x1F`, `'A'`), and LDmicro decides which by its
//! first character (see [`is_number`]).

use std::fmt;

use crate::iec::Comparison;
use crate::runtime::ldmicro::TimerKind;

/// LDmicro's counters, each counting in a variable of its own name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CounterKind {
    /// Up, on while the count is at or above its limit.
    Ctu,
    /// Down, on while the count is at or above its limit.
    Ctd,
    /// Circular up: back to its start past its limit.
    Ctc,
    /// Circular down: back to its limit below its start.
    Ctr,
}

/// What a one-shot element makes of its input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OneShotKind {
    /// One scan on at the input's rise (`OSR`).
    Rising,
    /// One scan on at the input's fall (`OSF`).
    Falling,
    /// One scan off at the input's fall (`OSL`).
    Low,
    /// On every other scan while on (`OSC`).
    Oscillate,
}

/// A two-operand arithmetic or bit operation (`ADD dest a b`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MathOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Shl,
    Shr,
    /// Shift right filling with zeros.
    Sr0,
    Rol,
    Ror,
    And,
    Or,
    Xor,
}

/// A one-operand operation (`dest src`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UnaryOp {
    Move,
    Not,
    Neg,
    Bin2Bcd,
    Bcd2Bin,
    /// Reverses the order of the bits.
    Opposite,
    /// Swaps the two bytes of a 16-bit word.
    Swap,
    /// Seeds the random generator of `dest` with `src`.
    SeedRandom,
}

/// LDmicro's keyword for each comparison (`EQU a b`, passing power while
/// it holds); the comparison itself is IEC's.
const COMPARE_KEYWORDS: [(Comparison, &str); 6] = [
    (Comparison::Eq, "EQU"),
    (Comparison::Ne, "NEQ"),
    (Comparison::Gt, "GRT"),
    (Comparison::Ge, "GEQ"),
    (Comparison::Lt, "LES"),
    (Comparison::Le, "LEQ"),
];

/// LDmicro's keyword for `op`.
pub fn compare_keyword(op: Comparison) -> &'static str {
    COMPARE_KEYWORDS
        .iter()
        .find(|(c, _)| *c == op)
        .map_or("EQU", |(_, w)| w)
}

/// The comparison LDmicro's keyword `word` names.
pub fn compare_from_keyword(word: &str) -> Option<Comparison> {
    COMPARE_KEYWORDS
        .iter()
        .find(|(_, w)| *w == word)
        .map(|(c, _)| *c)
}

/// One element line of a rung.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Element {
    /// A comment line of the rung (its text, escapes read).
    Comment(String),
    /// `CONTACTS name negated [set1]`.
    Contacts {
        name: String,
        negated: bool,
        /// 4.x: an input read as set while its pin is unconnected.
        set1: bool,
    },
    /// `COIL name negated setOnly resetOnly [toggle]`.
    Coil {
        name: String,
        negated: bool,
        set_only: bool,
        reset_only: bool,
        /// 4.x: toggles at each rise of its input.
        toggle: bool,
    },
    /// An empty place in a rung being drawn.
    Placeholder,
    /// A wire: passes power.
    Short,
    /// A break: never passes power.
    Open,
    /// Opens (or closes) the master relay for the rungs below it.
    MasterRelay,
    /// `TON name delay [adjust]` (delay in µs; adjust in cycles).
    Timer {
        kind: TimerKind,
        name: String,
        delay: String,
        adjust: i32,
    },
    /// `TIME2COUNT name delay` (`to_delay`: `TIME2DELAY`): a delay in µs
    /// as a count of cycles (or of the CPU's delay loop) into `name`.
    TimeConvert {
        to_delay: bool,
        name: String,
        delay: String,
    },
    /// `CTU name max [init [input]]`; `input` is which change of the
    /// input counts: `/` rise, `\` fall, `-` every scan on, `o` every
    /// scan off.
    Counter {
        kind: CounterKind,
        name: String,
        max: String,
        init: String,
        input: char,
    },
    /// `RES name`: a timer's or counter's count back to its start.
    Res(String),
    /// `MOVE dest src` and the other one-operand operations.
    Unary {
        op: UnaryOp,
        dest: String,
        src: String,
    },
    /// `ADD dest a b` and the other two-operand operations.
    Math {
        op: MathOp,
        dest: String,
        a: String,
        b: String,
    },
    /// `EQU a b` and the other comparisons.
    Compare {
        op: Comparison,
        a: String,
        b: String,
    },
    /// `OSR`, `OSF`, `OSL`, `OSC`.
    OneShot(OneShotKind),
    /// `SHIFT_REGISTER name stages`: `name0` … `name<stages-1>`.
    ShiftRegister { name: String, stages: u32 },
    /// `LOOK_UP_TABLE dest index count asString values… [name]`.
    LookUpTable {
        dest: String,
        index: String,
        values: Vec<i64>,
        as_string: bool,
        name: String,
    },
    /// `PIECEWISE_LINEAR dest index count (x y)… [name]`.
    PiecewiseLinear {
        dest: String,
        index: String,
        points: Vec<(i64, i64)>,
        name: String,
    },
    /// `READ_ADC name [refs]`.
    ReadAdc { name: String, refs: i32 },
    /// `RANDOM name`.
    Random(String),
    /// `SET_PWM duty frequency [name [resolution]]`.
    SetPwm {
        duty: String,
        frequency: String,
        name: String,
        resolution: String,
    },
    /// `UART_RECV name [bytes wait]` (`whole`: `UART_RECVn name`, as many
    /// bytes as the variable has).
    UartRecv {
        name: String,
        bytes: u32,
        wait: bool,
        whole: bool,
    },
    /// `UART_SEND name [bytes wait]` (`whole`: `UART_SENDn`).
    UartSend {
        name: String,
        bytes: u32,
        wait: bool,
        whole: bool,
    },
    /// `UART_RECV_AVAIL`: on while a byte waits.
    UartRecvAvail,
    /// `UART_SEND_READY` (also written `UART_SEND_BUSY`, `UART_UDRE`).
    UartSendReady,
    /// `PERSIST name`: kept in EEPROM over a power cycle.
    Persist(String),
    /// `FORMATTED_STRING var text` (`var` empty for `(none)`).
    FormattedString { var: String, text: String },
    /// `STRING dest var text`.
    Text {
        dest: String,
        var: String,
        text: String,
    },
    /// `7SEGMENTS dest src common` (and 9, 14, 16 segments).
    Segments {
        segments: u8,
        dest: String,
        src: String,
        common: char,
    },
    /// `IF_BIT_SET var bit` / `IF_BIT_CLEAR` (`set`), `SET_BIT var bit` /
    /// `CLEAR_BIT` (`write`).
    Bit {
        write: bool,
        set: bool,
        var: String,
        bit: String,
    },
    /// An element that drives hardware Hashigo does not simulate (I²C,
    /// SPI, BUS, steppers, pulse trains, encoders, sleep, watchdog,
    /// jumps and subroutines, special function registers): its keyword
    /// and the rest of its line as written.
    Hardware { keyword: String, args: String },
}

impl Element {
    /// The keyword LDmicro writes the element with (`TON`, `COIL`,
    /// `7SEGMENTS`).
    pub fn keyword(&self) -> &str {
        match self {
            Element::Comment(_) => "COMMENT",
            Element::Contacts { .. } => "CONTACTS",
            Element::Coil { .. } => "COIL",
            Element::Placeholder => "PLACEHOLDER",
            Element::Short => "SHORT",
            Element::Open => "OPEN",
            Element::MasterRelay => "MASTER_RELAY",
            Element::Timer { kind, .. } => kind.keyword(),
            Element::TimeConvert {
                to_delay: false, ..
            } => "TIME2COUNT",
            Element::TimeConvert { to_delay: true, .. } => "TIME2DELAY",
            Element::Counter { kind, .. } => kind.keyword(),
            Element::Res(_) => "RES",
            Element::Unary { op, .. } => op.keyword(),
            Element::Math { op, .. } => op.keyword(),
            Element::Compare { op, .. } => compare_keyword(*op),
            Element::OneShot(k) => k.keyword(),
            Element::ShiftRegister { .. } => "SHIFT_REGISTER",
            Element::LookUpTable { .. } => "LOOK_UP_TABLE",
            Element::PiecewiseLinear { .. } => "PIECEWISE_LINEAR",
            Element::ReadAdc { .. } => "READ_ADC",
            Element::Random(_) => "RANDOM",
            Element::SetPwm { .. } => "SET_PWM",
            Element::UartRecv { whole: false, .. } => "UART_RECV",
            Element::UartRecv { whole: true, .. } => "UART_RECVn",
            Element::UartSend { whole: false, .. } => "UART_SEND",
            Element::UartSend { whole: true, .. } => "UART_SENDn",
            Element::UartRecvAvail => "UART_RECV_AVAIL",
            Element::UartSendReady => "UART_SEND_READY",
            Element::Persist(_) => "PERSIST",
            Element::FormattedString { .. } => "FORMATTED_STRING",
            Element::Text { .. } => "STRING",
            Element::Segments { segments, .. } => match segments {
                7 => "7SEGMENTS",
                9 => "9SEGMENTS",
                14 => "14SEGMENTS",
                _ => "16SEGMENTS",
            },
            Element::Bit {
                write: false,
                set: true,
                ..
            } => "IF_BIT_SET",
            Element::Bit {
                write: false,
                set: false,
                ..
            } => "IF_BIT_CLEAR",
            Element::Bit {
                write: true,
                set: true,
                ..
            } => "SET_BIT",
            Element::Bit { .. } => "CLEAR_BIT",
            Element::Hardware { keyword, .. } => keyword,
        }
    }
}

impl Element {
    /// Every name and operand the element holds (numbers included: an
    /// operand may be either), for renaming.
    pub fn operands_mut(&mut self) -> Vec<&mut String> {
        match self {
            Element::Contacts { name, .. }
            | Element::Coil { name, .. }
            | Element::Res(name)
            | Element::Random(name)
            | Element::Persist(name)
            | Element::ShiftRegister { name, .. }
            | Element::ReadAdc { name, .. }
            | Element::UartRecv { name, .. }
            | Element::UartSend { name, .. } => vec![name],
            Element::Timer { name, delay, .. } | Element::TimeConvert { name, delay, .. } => {
                vec![name, delay]
            }
            Element::Counter {
                name, max, init, ..
            } => vec![name, max, init],
            Element::Unary { dest, src, .. } => vec![dest, src],
            Element::Math { dest, a, b, .. } => vec![dest, a, b],
            Element::Compare { a, b, .. } => vec![a, b],
            Element::LookUpTable { dest, index, .. }
            | Element::PiecewiseLinear { dest, index, .. } => vec![dest, index],
            Element::SetPwm { duty, name, .. } => vec![duty, name],
            Element::FormattedString { var, .. } => vec![var],
            Element::Text { dest, var, .. } => vec![dest, var],
            Element::Segments { dest, src, .. } => vec![dest, src],
            Element::Bit { var, bit, .. } => vec![var, bit],
            _ => Vec::new(),
        }
    }
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.keyword())
    }
}

/// The keywords and kinds of a family of elements, named once.
macro_rules! keywords {
    ($ty:ident { $($variant:ident => $word:literal),* $(,)? }) => {
        impl $ty {
            /// Every kind with its keyword.
            pub const ALL: &'static [($ty, &'static str)] = &[$(($ty::$variant, $word)),*];

            /// Its keyword.
            pub fn keyword(self) -> &'static str {
                match self { $($ty::$variant => $word),* }
            }

            /// The kind `word` names.
            pub fn from_keyword(word: &str) -> Option<$ty> {
                Self::ALL.iter().find(|(_, w)| *w == word).map(|(k, _)| *k)
            }
        }
    };
}

keywords!(TimerKind { Ton => "TON", Tof => "TOF", Rto => "RTO", Rtl => "RTL", Tcy => "TCY", Thi => "THI", Tlo => "TLO" });
keywords!(CounterKind { Ctu => "CTU", Ctd => "CTD", Ctc => "CTC", Ctr => "CTR" });
keywords!(OneShotKind { Rising => "OSR", Falling => "OSF", Low => "OSL", Oscillate => "OSC" });
keywords!(MathOp {
    Add => "ADD", Sub => "SUB", Mul => "MUL", Div => "DIV", Mod => "MOD", Shl => "SHL",
    Shr => "SHR", Sr0 => "SR0", Rol => "ROL", Ror => "ROR", And => "AND", Or => "OR", Xor => "XOR",
});
keywords!(UnaryOp {
    Move => "MOVE", Not => "NOT", Neg => "NEG", Bin2Bcd => "BIN2BCD", Bcd2Bin => "BCD2BIN",
    Opposite => "OPPOSITE", Swap => "SWAP", SeedRandom => "SEED_RANDOM",
});

/// The elements that drive hardware Hashigo does not simulate, by keyword.
pub const HARDWARE: [&str; 25] = [
    "I2C_RD",
    "I2C_WR",
    "SPI",
    "SPI_WR",
    "BUS",
    "STEPPER",
    "PULSER",
    "NPULSE",
    "NPULSE_OFF",
    "QUAD_ENCOD",
    "SLEEP",
    "DELAY",
    "CLRWDT",
    "LOCK",
    "GOTO",
    "GOSUB",
    "RETURN",
    "LABEL",
    "SUBPROG",
    "ENDSUB",
    "RSFR",
    "WSFR",
    "SSFR",
    "CSFR",
    "TSFR",
];

pub use super::escape::unescape;
pub use super::numbers::{is_number, number};
