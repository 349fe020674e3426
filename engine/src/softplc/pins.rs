//! The standard blocks' parameters by name, and one instance's state
//! with the inputs it keeps between calls (IEC: an input not given in a
//! call keeps its last value).

use super::blocks::{Ctd, Ctu, Ctud, FTrig, RTrig, Rs, Sr, Tof, Ton, Tp};
use super::data::{Data, DataType};

/// One instance of a standard block.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    pub state: State,
    /// Its inputs' values, in the order of [`inputs`].
    pub inputs: Vec<Data>,
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
}

/// A block's inputs (name, type), in order.
pub fn inputs(block: &str) -> &'static [(&'static str, DataType)] {
    use DataType::{Bool, Int, Time};
    match block {
        "TON" | "TOF" | "TP" => &[("IN", Bool), ("PT", Time)],
        "CTU" => &[("CU", Bool), ("R", Bool), ("PV", Int)],
        "CTD" => &[("CD", Bool), ("LD", Bool), ("PV", Int)],
        "CTUD" => &[
            ("CU", Bool),
            ("CD", Bool),
            ("R", Bool),
            ("LD", Bool),
            ("PV", Int),
        ],
        "R_TRIG" | "F_TRIG" => &[("CLK", Bool)],
        "SR" => &[("S1", Bool), ("R", Bool)],
        "RS" => &[("S", Bool), ("R1", Bool)],
        _ => &[],
    }
}

/// A block's outputs (name, type), in order.
pub fn outputs(block: &str) -> &'static [(&'static str, DataType)] {
    use DataType::{Bool, Int, Time};
    match block {
        "TON" | "TOF" | "TP" => &[("Q", Bool), ("ET", Time)],
        "CTU" | "CTD" => &[("Q", Bool), ("CV", Int)],
        "CTUD" => &[("QU", Bool), ("QD", Bool), ("CV", Int)],
        "R_TRIG" | "F_TRIG" => &[("Q", Bool)],
        "SR" | "RS" => &[("Q1", Bool)],
        _ => &[],
    }
}

impl Instance {
    /// A new instance of `block` (one of `vars::BLOCK_TYPES`).
    pub fn new(block: &str) -> Instance {
        let state = match block {
            "TON" => State::Ton(Ton::default()),
            "TOF" => State::Tof(Tof::default()),
            "TP" => State::Tp(Tp::default()),
            "CTU" => State::Ctu(Ctu::default()),
            "CTD" => State::Ctd(Ctd::default()),
            "CTUD" => State::Ctud(Ctud::default()),
            "R_TRIG" => State::RTrig(RTrig::default()),
            "F_TRIG" => State::FTrig(FTrig::default()),
            "SR" => State::Sr(Sr::default()),
            _ => State::Rs(Rs::default()),
        };
        Instance {
            state,
            inputs: inputs(block).iter().map(|(_, t)| t.zero()).collect(),
        }
    }

    fn bool_in(&self, i: usize) -> bool {
        matches!(self.inputs.get(i), Some(Data::Bool(true)))
    }

    fn word_in(&self, i: usize) -> i64 {
        match self.inputs.get(i) {
            Some(Data::Int(_, v) | Data::Time(v)) => *v,
            _ => 0,
        }
    }

    /// Runs the block with its inputs at time `now` (ns).
    pub fn call(&mut self, now: i64) {
        let (b0, b1, b2, b3) = (
            self.bool_in(0),
            self.bool_in(1),
            self.bool_in(2),
            self.bool_in(3),
        );
        let (w1, w2, w4) = (self.word_in(1), self.word_in(2), self.word_in(4));
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
        }
    }

    /// Output `i` (in the order of [`outputs`]).
    pub fn output(&self, i: usize) -> Data {
        let int = |v: i64| Data::integer(DataType::Int, i128::from(v));
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
        }
    }
}
