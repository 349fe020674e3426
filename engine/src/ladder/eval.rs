//! The reference evaluator: a ladder run by power flow, as the textbook
//! defines it, with no machine in between. Rungs run top to bottom, each
//! output written at once; every element reports its power in and out.
//! The compilers' differential tests compare each machine against it; the
//! editor colours elements from the same [`power_flow`].

use std::collections::{BTreeMap, HashMap};

use super::element::{CoilKind, ContactKind, Element};
use super::grid::{LadderError, Pos};
use super::net::{Net, RungLogic};
use crate::avr::{TimerKind as AvrTimerKind, TimerWord};

/// Power into and out of one element in the last evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ElementPower {
    /// The element's cell.
    pub pos: Pos,
    /// Power at its left side.
    pub power_in: bool,
    /// Power at its right side (for an output: what it received).
    pub power_out: bool,
}

/// What the evaluator reads and keeps between scans.
pub trait FlowState {
    /// A bit device's state.
    fn bit(&self, device: &str) -> bool;
    /// The one-bit memory of an edge element (its last input).
    fn edge_memory(&mut self, rung: usize, pos: Pos) -> &mut bool;
    /// An in-line timer's word (a scan counter), when timers are simulated.
    fn timer(&mut self, rung: usize, pos: Pos) -> Option<&mut TimerWord>;
}

/// Evaluates rung `rung`'s condition and returns the power reaching its
/// outputs, appending each element's power to `report`.
pub fn power_flow(
    logic: &RungLogic,
    rung: usize,
    state: &mut dyn FlowState,
    scan_ms: u32,
    report: &mut Vec<ElementPower>,
) -> bool {
    let power = eval(&logic.condition, true, rung, state, scan_ms, report);
    for (_, pos) in &logic.outputs {
        report.push(ElementPower {
            pos: *pos,
            power_in: power,
            power_out: power,
        });
    }
    power
}

fn eval(
    net: &Net,
    pin: bool,
    rung: usize,
    st: &mut dyn FlowState,
    scan_ms: u32,
    report: &mut Vec<ElementPower>,
) -> bool {
    match net {
        Net::Series(v) => v
            .iter()
            .fold(pin, |p, n| eval(n, p, rung, st, scan_ms, report)),
        // Every branch is evaluated (no short cut): edge memories must see
        // every scan.
        Net::Parallel(v) => v
            .iter()
            .map(|n| eval(n, pin, rung, st, scan_ms, report))
            .fold(false, |a, b| a | b),
        Net::Leaf(e, pos) => {
            let out = match e {
                Element::Contact { kind, device } => {
                    let on = st.bit(device);
                    match kind {
                        ContactKind::No => pin & on,
                        ContactKind::Nc => pin & !on,
                        ContactKind::Rising | ContactKind::Falling => {
                            let m = st.edge_memory(rung, *pos);
                            let before = std::mem::replace(m, on);
                            let edge = if *kind == ContactKind::Rising {
                                on && !before
                            } else {
                                !on && before
                            };
                            pin & edge
                        }
                    }
                }
                Element::Not => !pin,
                Element::Edge { falling } => {
                    let m = st.edge_memory(rung, *pos);
                    let before = std::mem::replace(m, pin);
                    if *falling {
                        !pin && before
                    } else {
                        pin && !before
                    }
                }
                Element::Timer {
                    kind, preset_ms, ..
                } => match st.timer(rung, *pos) {
                    Some(t) => t.run(avr_kind(*kind), pin, preset_scans(*preset_ms, scan_ms)),
                    None => false,
                },
                _ => pin,
            };
            report.push(ElementPower {
                pos: *pos,
                power_in: pin,
                power_out: out,
            });
            out
        }
    }
}

/// A set time in whole scans (at least one), as the AVR PLC counts it.
pub fn preset_scans(preset_ms: u32, scan_ms: u32) -> u16 {
    let scans = preset_ms / scan_ms.max(1);
    u16::try_from(scans.max(1)).unwrap_or(u16::MAX)
}

fn avr_kind(k: super::element::TimerKind) -> AvrTimerKind {
    match k {
        super::element::TimerKind::Ton => AvrTimerKind::Ton,
        super::element::TimerKind::Tof => AvrTimerKind::Tof,
        super::element::TimerKind::Tp => AvrTimerKind::Tp,
    }
}

/// A ladder run by the book on bit devices: the reference the machines'
/// compiled programs are compared with.
#[derive(Clone, Debug)]
pub struct Reference {
    rungs: Vec<RungLogic>,
    scan_ms: u32,
    state: RefState,
}

#[derive(Clone, Debug, Default)]
struct RefState {
    bits: BTreeMap<String, bool>,
    memory: HashMap<(usize, Pos), bool>,
    timers: HashMap<(usize, Pos), TimerWord>,
}

impl FlowState for RefState {
    fn bit(&self, device: &str) -> bool {
        self.bits.get(device).copied().unwrap_or(false)
    }
    fn edge_memory(&mut self, rung: usize, pos: Pos) -> &mut bool {
        self.memory.entry((rung, pos)).or_default()
    }
    fn timer(&mut self, rung: usize, pos: Pos) -> Option<&mut TimerWord> {
        Some(self.timers.entry((rung, pos)).or_default())
    }
}

impl Reference {
    /// A reference run of `rungs` (checked logic) with every bit off and
    /// in-line timers counting scans of `scan_ms`. Outputs it cannot run
    /// by itself (timer and counter coils, data boxes: their meaning is the
    /// machine's) are errors at their cells.
    pub fn new(rungs: Vec<RungLogic>, scan_ms: u32) -> Result<Reference, Vec<LadderError>> {
        let mut errors = Vec::new();
        for (i, r) in rungs.iter().enumerate() {
            for (e, p) in &r.outputs {
                if !matches!(e, Element::Coil { .. } | Element::Pulse { .. }) {
                    errors.push(LadderError::at(
                        i,
                        *p,
                        format!("the reference evaluator does not run {e}: the machine defines it"),
                    ));
                }
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(Reference {
            rungs,
            scan_ms,
            state: RefState::default(),
        })
    }

    /// Sets a bit device (an input, between scans).
    pub fn set(&mut self, device: &str, on: bool) {
        self.state.bits.insert(device.to_string(), on);
    }

    /// A bit device's state.
    pub fn get(&self, device: &str) -> bool {
        self.state.bit(device)
    }

    /// Runs one scan; returns every element's power, rung by rung.
    pub fn scan(&mut self) -> Vec<Vec<ElementPower>> {
        let mut all = Vec::with_capacity(self.rungs.len());
        for (i, logic) in self.rungs.iter().enumerate() {
            let mut report = Vec::new();
            let power = power_flow(logic, i, &mut self.state, self.scan_ms, &mut report);
            for (e, pos) in &logic.outputs {
                match e {
                    Element::Coil { kind, device } => {
                        let bit = self.state.bits.entry(device.clone()).or_default();
                        match kind {
                            CoilKind::Normal => *bit = power,
                            CoilKind::Inverted => *bit = !power,
                            CoilKind::Set => *bit |= power,
                            CoilKind::Reset => *bit &= !power,
                        }
                    }
                    Element::Pulse { falling, device } => {
                        let m = self.state.memory.entry((i, *pos)).or_default();
                        let before = std::mem::replace(m, power);
                        let on = if *falling {
                            !power && before
                        } else {
                            power && !before
                        };
                        self.state.bits.insert(device.clone(), on);
                    }
                    _ => {}
                }
            }
            all.push(report);
        }
        all
    }
}
