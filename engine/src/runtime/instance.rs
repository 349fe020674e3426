//! One block instance's state, with the inputs it keeps between calls
//! (IEC: an input not given in a call keeps its last value), for every
//! block [`crate::iec::pins`] names.

use super::ldmicro::{format::Format, printf::Printf, Io, LdBlock};
use super::standard::{Ctd, Ctu, Ctud, FTrig, Limits, RTrig, Rs, Sr, Tof, Ton, Tp};
use super::uart::Uart;
use crate::iec::data::{Data, DataType};
use crate::iec::pins::{counter, inputs};

/// One instance of a standard block.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    pub state: State,
    /// A counter's count type (INT for other blocks).
    count: DataType,
    /// Its inputs' values, in the order of [`inputs`].
    pub inputs: Vec<Data>,
    /// Its text input's value, fixed at load (an LDmicro formatted
    /// string's, [`crate::iec::pins::ldmicro::text_input`]).
    pub format: Option<std::sync::Arc<Format>>,
    /// LDmicro's STRING's C format, fixed at load like `format`, and
    /// what it gave out last (boxed: most blocks have none, and a scan
    /// walks the instances).
    pub printing: Option<Box<Printing>>,
}

/// The state of each kind of block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum State {
    Ton(Ton),
    Tof(Tof),
    Tp(Tp),
    Ctu(Ctu),
    Ctd(Ctd),
    Ctud(Ctud),
    RTrig(RTrig),
    FTrig(FTrig),
    Sr(Sr),
    Rs(Rs),
    /// One of LDmicro's elements ([`super::ldmicro`]).
    Ld(LdBlock),
}

/// LDmicro's STRING's format and its last text.
#[derive(Clone, Debug, PartialEq)]
pub struct Printing {
    pub printf: Printf,
    printed: Data,
}

impl Printing {
    /// A STRING printing `printf`, nothing printed yet.
    pub fn new(printf: Printf) -> Printing {
        Printing {
            printf,
            printed: DataType::String.zero(),
        }
    }
}

impl Instance {
    /// A new instance of `block` (one [`crate::iec::pins::is_block_type`] knows).
    pub fn new(block: &str) -> Instance {
        let (base, count) = counter(block).unwrap_or((block, DataType::Int));
        let limits = Limits::of(count);
        let state = match base {
            ld if ld.starts_with("LD_") => State::Ld(LdBlock::new(ld)),
            "TON" => State::Ton(Ton::default()),
            "TOF" => State::Tof(Tof::default()),
            "TP" => State::Tp(Tp::default()),
            "CTU" => State::Ctu(Ctu::counting(limits)),
            "CTD" => State::Ctd(Ctd::counting(limits)),
            "CTUD" => State::Ctud(Ctud::counting(limits)),
            "R_TRIG" => State::RTrig(RTrig::default()),
            "F_TRIG" => State::FTrig(FTrig::default()),
            "SR" => State::Sr(Sr::default()),
            _ => State::Rs(Rs::default()),
        };
        Instance {
            state,
            count,
            inputs: inputs(block).iter().map(|(_, t)| t.zero()).collect(),
            format: None,
            printing: None,
        }
    }

    fn bool_in(&self, i: usize) -> bool {
        matches!(self.inputs.get(i), Some(Data::Bool(true)))
    }

    /// Input `i` as a number: an integer's value (a ULINT's above 2^63
    /// too), a TIME's nanoseconds.
    fn word_in(&self, i: usize) -> i128 {
        match self.inputs.get(i) {
            Some(Data::Time(v)) => i128::from(*v),
            Some(d) => d.int().unwrap_or(0),
            None => 0,
        }
    }

    /// Runs the block with its inputs at time `now` (ns); LDmicro's
    /// serial blocks use `uart`.
    pub fn call(&mut self, now: i64, uart: &mut Uart) {
        let (b0, b1, b2, b3) = (
            self.bool_in(0),
            self.bool_in(1),
            self.bool_in(2),
            self.bool_in(3),
        );
        let (w2, w4) = (self.word_in(2), self.word_in(4));
        // A TIME's nanoseconds, or (LDmicro's STRING) an integer's bits.
        let w1 = self.word_in(1) as i64;
        match &mut self.state {
            State::Ton(t) => t.call(b0, w1, now),
            State::Tof(t) => t.call(b0, w1, now),
            State::Tp(t) => t.call(b0, w1, now),
            State::Ctu(c) => c.call(b0, b1, w2),
            State::Ctd(c) => c.call(b0, b1, w2),
            State::Ctud(c) => c.call(b0, b1, b2, b3, w4),
            State::RTrig(t) => t.call(b0),
            State::FTrig(t) => t.call(b0),
            State::Sr(s) => s.call(b0, b1),
            State::Rs(s) => s.call(b0, b1),
            State::Ld(b) => {
                b.call(
                    &self.inputs,
                    Io {
                        uart,
                        format: self.format.as_deref(),
                    },
                );
                if let Some(p) = self.printing.as_deref_mut().filter(|_| b.is_text()) {
                    p.printed = match self.inputs.get(2) {
                        Some(unpowered) if !b0 => unpowered.clone(),
                        _ => Data::text(p.printf.print(w1)),
                    };
                }
            }
        }
    }

    /// Output `i` (in the order of [`outputs`]).
    pub fn output(&self, i: usize) -> Data {
        let int = |v: i128| Data::integer(self.count, v);
        match (&self.state, i) {
            (
                State::Ton(Ton { q, .. }) | State::Tof(Tof { q, .. }) | State::Tp(Tp { q, .. }),
                0,
            ) => Data::Bool(*q),
            (
                State::Ton(Ton { et, .. }) | State::Tof(Tof { et, .. }) | State::Tp(Tp { et, .. }),
                _,
            ) => Data::Time(*et),
            (State::Ctu(Ctu { q, .. }) | State::Ctd(Ctd { q, .. }), 0) => Data::Bool(*q),
            (State::Ctu(Ctu { cv, .. }) | State::Ctd(Ctd { cv, .. }), _) => int(*cv),
            (State::Ctud(c), 0) => Data::Bool(c.qu),
            (State::Ctud(c), 1) => Data::Bool(c.qd),
            (State::Ctud(c), _) => int(c.cv),
            (State::RTrig(RTrig { q, .. }) | State::FTrig(FTrig { q, .. }), _) => Data::Bool(*q),
            (State::Sr(Sr { q1 }) | State::Rs(Rs { q1 }), _) => Data::Bool(*q1),
            (State::Ld(b), 1) if b.is_text() => self
                .printing
                .as_ref()
                .map_or(Data::Bool(false), |p| p.printed.clone()),
            (State::Ld(b), i) => b.output(i),
        }
    }
}
