//! LDmicro's timers, counters and one-shots as the soft PLC's blocks
//! (issue #32; docs/ldmicro.md, "Elements"): each does what LDmicro 4.x's
//! intermediate code does for its element, scan by scan, so that an
//! `.ld` file runs here as it runs on LDmicro's microcontroller.
//!
//! LDmicro keeps a timer's or counter's count in a variable of the
//! element's name, which other elements read and write (`EQU Cwhich 3`,
//! `MOVE Tdelay 0`), so a block here takes that count as an input (`T`,
//! `C`) and gives it back as an output of the same name, written to the
//! same variable: `CAL Tdelay_ld(IN := …, P := 49, T := Tdelay, T =>
//! Tdelay)`. Periods are counts of scans (LDmicro's `TimerPeriod`,
//! worked out when the file is read); a block's own memory (LDmicro's
//! generated one-shot bits) lives in its instance.

pub mod format;
pub mod printf;
pub mod segments;
mod words;

use super::uart::Uart;
use crate::iec::data::{Data, DataType};
use crate::iec::pins::ldmicro::NAMES;
use format::{Format, Sender};
use words::word_op;

/// What an LDmicro block reaches beyond its inputs: the serial port and,
/// for a formatted string, its text.
pub struct Io<'a> {
    pub uart: &'a mut Uart,
    pub format: Option<&'a Format>,
}

/// LDmicro's timers: all count scans of the file's cycle in a variable of
/// their own name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TimerKind {
    /// On-delay.
    Ton,
    /// Off-delay.
    Tof,
    /// Retentive on-delay.
    Rto,
    /// Retentive on-delay counting while the input is off.
    Rtl,
    /// Cyclic: a one-scan pulse every period while on.
    Tcy,
    /// High for its delay after the input's rise.
    Thi,
    /// Low for its delay after the input's fall.
    Tlo,
}

/// Which LDmicro element a block is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Timer(TimerKind),
    Ctu,
    Ctd,
    Ctc,
    Ctr,
    Osl,
    Osc,
    Toggle,
    /// A word operation (its name after `LD_`).
    Op(&'static str),
    /// A segment digit (`LD_SEG7` … `LD_SEG16`): how many segments.
    Segments(u8),
    UartSend,
    UartRecv,
    UartAvail,
    UartReady,
    FormattedString,
    Text,
}

/// One instance: its kind, its memory, and what it gave out last.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LdBlock {
    kind: Kind,
    /// LDmicro's one-shot bit of the element (`$..._TON` and the like).
    store: bool,
    /// LDmicro's second bit (`ONE_SHOT_HI`) of TLO and OSL.
    hi: bool,
    /// Whether the first call has been made (TOF starts its count at its
    /// period, a counter at its start, as LDmicro's `INIT VARS` does once).
    started: bool,
    /// The power passed on.
    pub q: bool,
    /// The count (T, C), the toggled bit or the byte received (V).
    pub value: i64,
    /// A formatted string's progress.
    sender: Sender,
    /// A several-byte send or receive: the word being moved and how many
    /// of its bytes have gone (LDmicro's `saved_` and `numb_`).
    word: i64,
    moved: i64,
}

impl LdBlock {
    /// A new instance of `block` (one of [`NAMES`]).
    pub fn new(block: &str) -> LdBlock {
        let kind = match block {
            "LD_TON" => Kind::Timer(TimerKind::Ton),
            "LD_TOF" => Kind::Timer(TimerKind::Tof),
            "LD_RTO" => Kind::Timer(TimerKind::Rto),
            "LD_RTL" => Kind::Timer(TimerKind::Rtl),
            "LD_TCY" => Kind::Timer(TimerKind::Tcy),
            "LD_THI" => Kind::Timer(TimerKind::Thi),
            "LD_TLO" => Kind::Timer(TimerKind::Tlo),
            "LD_CTU" => Kind::Ctu,
            "LD_CTD" => Kind::Ctd,
            "LD_CTC" => Kind::Ctc,
            "LD_CTR" => Kind::Ctr,
            "LD_OSL" => Kind::Osl,
            "LD_OSC" => Kind::Osc,
            "LD_TOGGLE" => Kind::Toggle,
            "LD_UART_SEND" => Kind::UartSend,
            "LD_UART_RECV" => Kind::UartRecv,
            "LD_UART_AVAIL" => Kind::UartAvail,
            "LD_UART_READY" => Kind::UartReady,
            "LD_FMTSTR" => Kind::FormattedString,
            "LD_STRING" => Kind::Text,
            seg if seg.starts_with("LD_SEG") => Kind::Segments(seg[6..].parse().unwrap_or(7)),
            other => Kind::Op(NAMES.iter().find(|n| **n == other).map_or("", |n| &n[3..])),
        };
        LdBlock {
            kind,
            store: false,
            hi: false,
            started: false,
            q: false,
            value: 0,
            sender: Sender::default(),
            word: 0,
            moved: 0,
        }
    }

    /// Whether it is LDmicro's STRING (its text output is the
    /// instance's).
    pub fn is_text(&self) -> bool {
        self.kind == Kind::Text
    }

    /// Output `i` (in the order of [`crate::iec::pins::ldmicro::outputs`]).
    pub fn output(&self, i: usize) -> Data {
        match (self.kind, i) {
            (_, 0) => Data::Bool(self.q),
            (Kind::Toggle, _) => Data::Bool(self.value != 0),
            (Kind::Segments(_), 2) => Data::integer(DataType::Dint, i128::from(self.word)),
            _ => Data::integer(DataType::Dint, i128::from(self.value)),
        }
    }

    /// One call with the block's inputs in the order of [`crate::iec::pins::ldmicro::inputs`].
    pub fn call(&mut self, inputs: &[Data], io: Io<'_>) {
        let bool_in = |i: usize| matches!(inputs.get(i), Some(Data::Bool(true)));
        let word = |i: usize| match inputs.get(i) {
            Some(Data::Int(_, v)) => *v,
            Some(Data::Bool(b)) => i64::from(*b),
            _ => 0,
        };
        let s = bool_in(0);
        self.q = match self.kind {
            Kind::Timer(_) => {
                let (period, count) = (word(1), word(2));
                self.timer(s, period, count)
            }
            Kind::Ctu | Kind::Ctd | Kind::Ctc | Kind::Ctr => {
                let (max, init, count, edge) = (word(1), word(2), word(3), word(4));
                self.counter(s, (max, init), count, edge)
            }
            Kind::Osl | Kind::Osc => self.shot(s),
            Kind::Op(_) | Kind::Segments(_) => {
                let (a, b, d, w) = (word(1), word(2), word(3), word(4));
                let w = if w <= 0 { 16 } else { w };
                (self.word, self.value) = (a, d);
                match self.kind {
                    Kind::Op("IFBIT") => s && (a >> b.clamp(0, 63)) & 1 == 1,
                    Kind::Op("IFNBIT") => s && (a >> b.clamp(0, 63)) & 1 == 0,
                    // B: 0 common cathode, else common anode.
                    Kind::Segments(n) if s => {
                        let (index, segments) = segments::convert(n, a, b != 0);
                        (self.word, self.value) = (index, word_op("MOVE", segments, 0, d, w));
                        s
                    }
                    Kind::Op(op) if s => {
                        self.value = word_op(op, a, b, d, w);
                        s
                    }
                    // Unpowered: the values stay as they were.
                    _ => s,
                }
            }
            Kind::UartSend => self.send(s, word(1), word(2).max(1), io.uart),
            Kind::UartRecv => self.receive(s, word(1), word(2).max(1), io.uart),
            // The text itself is the instance's (a block's state is
            // plain words); the power passes on.
            Kind::Text => s,
            Kind::UartAvail => s && io.uart.available(),
            Kind::UartReady => s && io.uart.ready(),
            Kind::FormattedString => match io.format {
                Some(format) => self.sender.call(s, word(1), format, io.uart),
                None => false,
            },
            Kind::Toggle => {
                let v = bool_in(1);
                self.value = i64::from(v);
                if s && !self.store {
                    self.value = i64::from(!v);
                }
                self.store = s;
                s
            }
        };
        self.started = true;
    }

    /// `UART_SEND v [n]`, LDmicro 4.x's code: one byte — sent while the
    /// power is on and the port free, the power out the transmitter's
    /// busy bit whatever the power in; `n` bytes — a rise takes the
    /// word, its bytes go one a scan as the port frees, the lowest first,
    /// and the power is on until the last has gone.
    fn send(&mut self, s: bool, v: i64, n: i64, uart: &mut Uart) -> bool {
        if n == 1 {
            if s {
                uart.send(v as u8);
            }
            return !uart.ready();
        }
        if s && !self.store {
            self.store = true;
            self.word = v;
            self.moved = 0;
        }
        if self.store {
            if self.moved < n && uart.ready() {
                uart.send((self.word >> (8 * self.moved).min(63)) as u8);
                self.moved += 1;
            }
            if self.moved >= n {
                self.store = false;
            }
        }
        self.store || !uart.ready()
    }

    /// `UART_RECV v [n]`: with power, one byte received into `v` passes
    /// power for that scan; `n` bytes are gathered the lowest first, a
    /// byte a scan, into `v` when the last has come (power for that
    /// scan). Without power nothing is taken from the port.
    fn receive(&mut self, s: bool, v: i64, n: i64, uart: &mut Uart) -> bool {
        self.value = v;
        if !s {
            return false;
        }
        if n == 1 {
            return match uart.receive() {
                Some(byte) => {
                    self.value = i64::from(byte);
                    true
                }
                None => false,
            };
        }
        if self.moved < n {
            if let Some(byte) = uart.receive() {
                let shift = (8 * self.moved).min(56);
                self.word = (self.word & !(0xFF << shift)) | (i64::from(byte) << shift);
                self.moved += 1;
            }
        }
        if self.moved >= n {
            self.value = self.word;
            self.moved = 0;
            true
        } else {
            false
        }
    }

    /// A timer's step: `s` the power in, the count `t` as the variable
    /// holds it; the count written back to `value`.
    fn timer(&mut self, s: bool, period: i64, t: i64) -> bool {
        let mut t = t;
        if self.kind == Kind::Timer(TimerKind::Tof) && !self.started {
            // LDmicro starts a TOF's count at its period: off at power-up.
            t = period;
        }
        let Kind::Timer(kind) = self.kind else {
            return false;
        };
        let out = match kind {
            TimerKind::Ton => {
                if !s {
                    t = 0;
                    false
                } else if t < period {
                    t += 1;
                    false
                } else {
                    true
                }
            }
            TimerKind::Tof => {
                if s {
                    t = 0;
                    true
                } else if t < period {
                    t += 1;
                    true
                } else {
                    false
                }
            }
            TimerKind::Rto => {
                if t < period {
                    if s {
                        t += 1;
                    }
                    false
                } else {
                    true
                }
            }
            TimerKind::Rtl => {
                if t < period {
                    if !s {
                        t += 1;
                    }
                    false
                } else {
                    true
                }
            }
            TimerKind::Tcy => self.tcy(s, period, &mut t),
            TimerKind::Thi => self.thi(s, period, &mut t),
            TimerKind::Tlo => self.tlo(s, period, &mut t),
        };
        self.value = t;
        out
    }

    /// TCY: while on, the output turns over each time the count passes
    /// the period.
    fn tcy(&mut self, s: bool, period: i64, t: &mut i64) -> bool {
        if !s {
            *t = 0;
            return false;
        }
        if *t < period {
            *t += 1;
        } else {
            *t = 0;
            self.store = !self.store;
        }
        self.store
    }

    /// THI: high for its period after the input rises.
    fn thi(&mut self, s: bool, period: i64, t: &mut i64) -> bool {
        if s {
            self.store = true;
        }
        if !self.store {
            false
        } else if *t < period {
            *t += 1;
            true
        } else {
            if !s {
                *t = 0;
                self.store = false;
            }
            false
        }
    }

    /// TLO: low for its period after the input falls (LDmicro's code,
    /// step for step).
    fn tlo(&mut self, s: bool, period: i64, t: &mut i64) -> bool {
        if !s {
            if self.hi {
                self.store = true;
            }
        } else {
            self.hi = true;
        }
        if self.store {
            if *t < period {
                *t += 1;
                false
            } else {
                if s {
                    *t = 0;
                    self.store = false;
                }
                true
            }
        } else {
            s || self.hi
        }
    }

    /// A counter's step: which change of `s` counts is `edge` (0 a rise,
    /// 1 a fall, 2 every scan on, 3 every scan off).
    fn counter(&mut self, s: bool, (max, init): (i64, i64), count: i64, edge: i64) -> bool {
        let mut c = if self.started { count } else { init };
        // Whether this scan counts, and the one-shot bit kept as LDmicro
        // keeps it for each kind of input.
        let counts = match edge {
            1 => {
                let fell = !s && self.store;
                self.store = s;
                fell
            }
            2 => s,
            3 => !s,
            _ => {
                let rose = s && !self.store;
                self.store = s;
                rose
            }
        };
        let out = match self.kind {
            Kind::Ctu => {
                if counts && c < max {
                    c += 1;
                }
                c >= max
            }
            Kind::Ctd => {
                if counts && c > max {
                    c -= 1;
                }
                c > max
            }
            Kind::Ctc => {
                let mut pulse = false;
                if counts {
                    c += 1;
                    if c > max {
                        c = init;
                        pulse = true;
                    }
                }
                // The power passes only in the scan it wraps.
                pulse
            }
            _ => {
                let mut pulse = false;
                if counts {
                    c -= 1;
                    if c < max {
                        c = init;
                        pulse = true;
                    }
                }
                pulse
            }
        };
        self.value = c;
        out
    }

    /// OSL (one scan low at the input's fall) and OSC (on every other
    /// scan while on).
    fn shot(&mut self, s: bool) -> bool {
        match self.kind {
            Kind::Osl => {
                if s {
                    self.store = false;
                    self.hi = true;
                    true
                } else {
                    let out = self.store;
                    if self.hi {
                        self.store = true;
                    }
                    out
                }
            }
            _ => {
                // Off, or on the scan after it passed: nothing passes.
                let out = s && !self.store;
                self.store = out;
                out
            }
        }
    }
}
