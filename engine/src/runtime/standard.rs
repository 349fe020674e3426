//! The standard function blocks (IEC 61131-3 §2.5.2.3): timers, counters,
//! edge detectors and bistables, each a small state machine the soft PLC
//! calls once a scan with its inputs. Times are nanoseconds of simulated
//! time (the scan's start, as OpenPLC samples its clock once a scan);
//! counts are INT, as the standard's CTU, CTD and CTUD, or the type a
//! typed counter names (CTU_DINT, CTUD_ULINT …).

use crate::iec::data::DataType;

/// The least and greatest count of an INT counter.
pub(super) const COUNT_MIN: i128 = i16::MIN as i128;
pub(super) const COUNT_MAX: i128 = i16::MAX as i128;

/// A counter's limits: the least and greatest value of its count type
/// (held in an `i128`, so a ULINT counter's whole range is one: a PV of
/// 2^63 or more is not read as a negative number).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub min: i128,
    pub max: i128,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            min: COUNT_MIN,
            max: COUNT_MAX,
        }
    }
}

impl Limits {
    /// The limits of a count of type `t` (an integer type).
    pub fn of(t: DataType) -> Limits {
        let (min, max) = t.range().unwrap_or((COUNT_MIN, COUNT_MAX));
        Limits { min, max }
    }
}

/// An on-delay timer: Q comes on once IN has been on for PT, and goes off
/// with IN. ET counts from 0 to PT while IN is on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ton {
    pub q: bool,
    pub et: i64,
    /// When IN came on, while it is.
    start: Option<i64>,
}

impl Ton {
    /// One call at time `now`.
    pub fn call(&mut self, input: bool, pt: i64, now: i64) {
        if !input {
            *self = Ton::default();
            return;
        }
        let start = *self.start.get_or_insert(now);
        self.et = (now - start).clamp(0, pt.max(0));
        self.q = self.et >= pt;
    }
}

/// An off-delay timer: Q follows IN on at once and stays on for PT after
/// IN goes off. ET counts from 0 to PT while IN is off after being on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tof {
    pub q: bool,
    pub et: i64,
    /// When IN went off, while the delay runs or has run.
    fell: Option<i64>,
}

impl Tof {
    /// One call at time `now`.
    pub fn call(&mut self, input: bool, pt: i64, now: i64) {
        if input {
            *self = Tof {
                q: true,
                et: 0,
                fell: None,
            };
            return;
        }
        if !self.q && self.fell.is_none() {
            return; // never on: nothing to delay
        }
        let fell = *self.fell.get_or_insert(now);
        self.et = (now - fell).clamp(0, pt.max(0));
        self.q = self.et < pt;
    }
}

/// A pulse timer: a rising IN, while no pulse runs, makes Q on for PT.
/// ET counts to PT and holds there until IN is off, then goes back to 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tp {
    pub q: bool,
    pub et: i64,
    start: Option<i64>,
    last_in: bool,
}

impl Tp {
    /// One call at time `now`.
    pub fn call(&mut self, input: bool, pt: i64, now: i64) {
        if input && !self.last_in && self.start.is_none() {
            self.start = Some(now);
        }
        self.last_in = input;
        match self.start {
            Some(start) => {
                self.et = (now - start).clamp(0, pt.max(0));
                self.q = self.et < pt;
                if !self.q && !input {
                    // The pulse is over and IN is off: ready again.
                    self.start = None;
                    self.et = 0;
                }
            }
            None => {
                self.q = false;
                self.et = 0;
            }
        }
    }
}

/// An up counter: R clears CV; otherwise each rising CU adds one, up to
/// the greatest INT. Q is CV ≥ PV.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ctu {
    pub q: bool,
    pub cv: i128,
    last_cu: bool,
    pub limits: Limits,
}

impl Ctu {
    /// A counter that counts within `limits`.
    pub fn counting(limits: Limits) -> Ctu {
        Ctu {
            limits,
            ..Ctu::default()
        }
    }

    pub fn call(&mut self, cu: bool, reset: bool, pv: i128) {
        let rising = cu && !self.last_cu;
        self.last_cu = cu;
        if reset {
            self.cv = 0;
        } else if rising && self.cv < self.limits.max {
            self.cv += 1;
        }
        self.q = self.cv >= pv;
    }
}

/// A down counter: LD loads PV into CV; otherwise each rising CD takes one
/// off, down to the least INT. Q is CV ≤ 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ctd {
    pub q: bool,
    pub cv: i128,
    last_cd: bool,
    pub limits: Limits,
}

impl Ctd {
    /// A counter that counts within `limits`.
    pub fn counting(limits: Limits) -> Ctd {
        Ctd {
            limits,
            ..Ctd::default()
        }
    }

    pub fn call(&mut self, cd: bool, load: bool, pv: i128) {
        let rising = cd && !self.last_cd;
        self.last_cd = cd;
        if load {
            self.cv = pv.clamp(self.limits.min, self.limits.max);
        } else if rising && self.cv > self.limits.min {
            self.cv -= 1;
        }
        self.q = self.cv <= 0;
    }
}

/// An up-down counter: R clears CV (and wins over LD), LD loads PV; else a
/// rising CU adds one and a rising CD takes one off (both at once: no
/// change). QU is CV ≥ PV, QD is CV ≤ 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ctud {
    pub qu: bool,
    pub qd: bool,
    pub cv: i128,
    last_cu: bool,
    last_cd: bool,
    pub limits: Limits,
}

impl Ctud {
    /// A counter that counts within `limits`.
    pub fn counting(limits: Limits) -> Ctud {
        Ctud {
            limits,
            ..Ctud::default()
        }
    }

    pub fn call(&mut self, cu: bool, cd: bool, reset: bool, load: bool, pv: i128) {
        let up = cu && !self.last_cu;
        let down = cd && !self.last_cd;
        self.last_cu = cu;
        self.last_cd = cd;
        if reset {
            self.cv = 0;
        } else if load {
            self.cv = pv.clamp(self.limits.min, self.limits.max);
        } else if up && !down && self.cv < self.limits.max {
            self.cv += 1;
        } else if down && !up && self.cv > self.limits.min {
            self.cv -= 1;
        }
        self.qu = self.cv >= pv;
        self.qd = self.cv <= 0;
    }
}

/// A rising-edge detector: Q is on for the one call in which CLK turns on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RTrig {
    pub q: bool,
    last: bool,
}

impl RTrig {
    pub fn call(&mut self, clk: bool) {
        self.q = clk && !self.last;
        self.last = clk;
    }
}

/// A falling-edge detector: Q is on for the one call in which CLK turns
/// off. Like OpenPLC, it starts as if CLK had been off.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FTrig {
    pub q: bool,
    last: bool,
}

impl FTrig {
    pub fn call(&mut self, clk: bool) {
        self.q = !clk && self.last;
        self.last = clk;
    }
}

/// A set-dominant bistable: Q1 = S1 OR (NOT R AND Q1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sr {
    pub q1: bool,
}

impl Sr {
    pub fn call(&mut self, s1: bool, r: bool) {
        self.q1 = s1 || (!r && self.q1);
    }
}

/// A reset-dominant bistable: Q1 = NOT R1 AND (S OR Q1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rs {
    pub q1: bool,
}

impl Rs {
    pub fn call(&mut self, s: bool, r1: bool) {
        self.q1 = !r1 && (s || self.q1);
    }
}

#[cfg(test)]
mod tests;
