//! The reference evaluator: a ladder run by power flow, as the textbook
//! defines it, with no machine in between. Rungs run top to bottom, each
//! output written at once; every element reports its power in and out.
//! The compilers' differential tests compare each machine against it; the
//! editor colours elements from the same [`power_flow`].
//!
//! Devices are resolved once: a contact is read by its place among the
//! rung's leaves (`Net::leaves` order), and whoever implements
//! [`FlowState`] maps that place to a device handle of its own, so no
//! name is looked up while a scan runs.

mod words;

use std::collections::HashMap;

use super::block::BlockCall;
use super::element::{CoilKind, ContactKind, Element};
use super::grid::{LadderError, Pos};
use super::net::{Net, RungLogic};
use super::variables::Variable;
use crate::iec::data::Data;
use crate::scan_timer::ScanTimer;

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

/// What the evaluator reads and keeps between scans, by leaf: `leaf` is
/// the element's place among its rung's leaves, in [`Net::leaves`] order.
pub trait FlowState {
    /// The state of the device the contact at `leaf` reads.
    fn bit(&self, rung: usize, leaf: usize) -> bool;
    /// The one-bit memory of the edge element at `leaf` (its last input).
    fn edge_memory(&mut self, rung: usize, leaf: usize) -> &mut bool;
    /// The in-line timer at `leaf`, when timers are simulated.
    fn timer(&mut self, rung: usize, leaf: usize) -> Option<&mut ScanTimer>;
    /// The soft PLC box at `leaf` run with `power`: its power out (where
    /// word data is not simulated, the power passes).
    fn block(&mut self, rung: usize, leaf: usize, call: &BlockCall, power: bool) -> bool {
        let _ = (rung, leaf, call);
        power
    }
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
    let mut walk = Walk {
        rung,
        state,
        scan_ms,
        report,
        leaf: 0,
    };
    let power = walk.eval(&logic.condition, true);
    for (_, pos) in &logic.outputs {
        walk.report.push(ElementPower {
            pos: *pos,
            power_in: power,
            power_out: power,
        });
    }
    power
}

/// One rung's evaluation: the state, and the next leaf's place.
struct Walk<'a> {
    rung: usize,
    state: &'a mut dyn FlowState,
    scan_ms: u32,
    report: &'a mut Vec<ElementPower>,
    leaf: usize,
}

impl Walk<'_> {
    fn eval(&mut self, net: &Net, pin: bool) -> bool {
        match net {
            Net::Series(v) => v.iter().fold(pin, |p, n| self.eval(n, p)),
            // Every branch is evaluated (no short cut): edge memories must
            // see every scan.
            Net::Parallel(v) => v.iter().fold(false, |a, n| self.eval(n, pin) | a),
            Net::Leaf(e, pos) => {
                let leaf = self.leaf;
                self.leaf += 1;
                let out = self.leaf_power(e, leaf, pin);
                self.report.push(ElementPower {
                    pos: *pos,
                    power_in: pin,
                    power_out: out,
                });
                out
            }
        }
    }

    fn leaf_power(&mut self, e: &Element, leaf: usize, pin: bool) -> bool {
        let rung = self.rung;
        match e {
            Element::Contact { kind, .. } => {
                let on = self.state.bit(rung, leaf);
                match kind {
                    ContactKind::No => pin & on,
                    ContactKind::Nc => pin & !on,
                    ContactKind::Rising | ContactKind::Falling => {
                        let before = std::mem::replace(self.state.edge_memory(rung, leaf), on);
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
                let before = std::mem::replace(self.state.edge_memory(rung, leaf), pin);
                if *falling {
                    !pin && before
                } else {
                    pin && !before
                }
            }
            Element::Timer {
                kind, preset_ms, ..
            } => {
                let preset = preset_scans(*preset_ms, self.scan_ms);
                match self.state.timer(rung, leaf) {
                    Some(t) => t.run(*kind, pin, preset),
                    None => false,
                }
            }
            Element::Block(b) => self.state.block(rung, leaf, b, pin),
            _ => pin,
        }
    }
}

/// A set time in whole scans (at least one), as the AVR PLC counts it.
pub fn preset_scans(preset_ms: u32, scan_ms: u32) -> u16 {
    let scans = preset_ms / scan_ms.max(1);
    u16::try_from(scans.max(1)).unwrap_or(u16::MAX)
}

/// A ladder run by the book on bit devices: the reference the machines'
/// compiled programs are compared with.
#[derive(Clone, Debug)]
pub struct Reference {
    rungs: Vec<RungLogic>,
    scan_ms: u32,
    /// Each output's device index, per rung (`None` for outputs that
    /// drive no bit).
    outputs: Vec<Vec<Option<usize>>>,
    /// Each pulse output's memory, per rung and output.
    pulse_memory: Vec<Vec<bool>>,
    state: RefState,
}

/// The devices and memories, by index: what [`FlowState`] reads.
#[derive(Clone, Debug, Default)]
struct RefState {
    bits: Vec<bool>,
    /// Per rung, per leaf: the device index a contact reads.
    contacts: Vec<Vec<usize>>,
    /// Per rung, per leaf: edge memories and timers.
    memory: Vec<Vec<bool>>,
    timers: Vec<Vec<ScanTimer>>,
    /// Device names to their index in `bits`.
    names: HashMap<String, usize>,
    /// The soft PLC's word data and block instances.
    words: words::Words,
    /// The scan's time (ns): the scans run times the scan period.
    now: i64,
}

impl RefState {
    /// The index of device `name`, added (off) if new.
    fn device(&mut self, name: &str) -> usize {
        if let Some(&i) = self.names.get(name) {
            return i;
        }
        self.bits.push(false);
        let i = self.bits.len() - 1;
        self.names.insert(name.to_string(), i);
        i
    }
}

impl words::Bits for RefState {
    fn get_bit(&mut self, name: &str) -> bool {
        let i = self.device(name);
        self.bits[i]
    }

    fn set_bit(&mut self, name: &str, on: bool) {
        let i = self.device(name);
        self.bits[i] = on;
    }
}

impl FlowState for RefState {
    fn bit(&self, rung: usize, leaf: usize) -> bool {
        let device = self.contacts[rung][leaf];
        self.bits[device]
    }
    fn edge_memory(&mut self, rung: usize, leaf: usize) -> &mut bool {
        &mut self.memory[rung][leaf]
    }
    fn timer(&mut self, rung: usize, leaf: usize) -> Option<&mut ScanTimer> {
        Some(&mut self.timers[rung][leaf])
    }
    fn block(&mut self, _rung: usize, _leaf: usize, call: &BlockCall, power: bool) -> bool {
        let mut words = std::mem::take(&mut self.words);
        let out = words.run(call, power, self.now, self);
        self.words = words;
        out
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
            if let Some(side) = r.sides.first() {
                // Differential tests draw no such inputs; the soft PLC
                // runs them (net/sides.rs has their tests).
                errors.push(LadderError::at(
                    i,
                    side.pos,
                    "the reference evaluator does not run a box input wired as a network",
                ));
            }
            for (e, p) in &r.outputs {
                if !matches!(
                    e,
                    Element::Coil { .. } | Element::Pulse { .. } | Element::OutputBlock(_)
                ) {
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
        let mut r = Reference {
            rungs: Vec::new(),
            scan_ms,
            outputs: Vec::new(),
            pulse_memory: Vec::new(),
            state: RefState::default(),
        };
        for logic in &rungs {
            let leaves = logic.condition.leaves();
            let contacts = leaves
                .iter()
                .map(|(e, _)| e.read_device().map_or(0, |d| r.device(d)))
                .collect();
            r.state.contacts.push(contacts);
            r.state.memory.push(vec![false; leaves.len()]);
            r.state
                .timers
                .push(vec![ScanTimer::default(); leaves.len()]);
            let outputs = logic
                .outputs
                .iter()
                .map(|(e, _)| e.written_device().map(|d| r.device(d)))
                .collect();
            r.outputs.push(outputs);
            r.pulse_memory.push(vec![false; logic.outputs.len()]);
        }
        r.rungs = rungs;
        Ok(r)
    }

    /// The same run with IEC's TOF, which is off at power-up until its
    /// input has been on (the soft PLC's); the AVR PLC's TOF is on for
    /// its set time after power-up.
    pub fn with_iec_timers(mut self) -> Reference {
        for (r, logic) in self.rungs.iter().enumerate() {
            for (leaf, (e, _)) in logic.condition.leaves().iter().enumerate() {
                if let Element::Timer {
                    kind: super::element::TimerKind::Tof,
                    ..
                } = e
                {
                    self.state.timers[r][leaf].count = u16::MAX;
                }
            }
        }
        self
    }

    /// The index of device `name`, added (off) if new.
    fn device(&mut self, name: &str) -> usize {
        self.state.device(name)
    }

    /// The same run with the soft PLC's declared variables (word data
    /// and block instances, issue #30).
    pub fn with_variables(mut self, variables: &[Variable]) -> Reference {
        self.state.words = words::Words::new(variables);
        self
    }

    /// Sets a word variable or address (an input, between scans).
    pub fn set_value(&mut self, name: &str, value: Data) {
        self.state.words.set(name, value);
    }

    /// A word variable's value, if `name` is one.
    pub fn value(&self, name: &str) -> Option<Data> {
        self.state.words.get(name)
    }

    /// Sets a bit device (an input, between scans).
    pub fn set(&mut self, device: &str, on: bool) {
        let i = self.device(device);
        self.state.bits[i] = on;
    }

    /// A bit device's state.
    pub fn get(&self, device: &str) -> bool {
        self.state
            .names
            .get(device)
            .is_some_and(|&i| self.state.bits[i])
    }

    /// Runs one scan; returns every element's power, rung by rung.
    pub fn scan(&mut self) -> Vec<Vec<ElementPower>> {
        let mut all = Vec::with_capacity(self.rungs.len());
        self.state.now += i64::from(self.scan_ms) * 1_000_000;
        for (i, logic) in self.rungs.iter().enumerate() {
            let mut report = Vec::new();
            let power = power_flow(logic, i, &mut self.state, self.scan_ms, &mut report);
            for (k, (e, _)) in logic.outputs.iter().enumerate() {
                if let Element::OutputBlock(b) = e {
                    self.state.block(i, usize::MAX, b, power);
                    continue;
                }
                let Some(device) = self.outputs[i][k] else {
                    continue;
                };
                let bit = &mut self.state.bits[device];
                match e {
                    Element::Coil { kind, .. } => match kind {
                        CoilKind::Normal => *bit = power,
                        CoilKind::Inverted => *bit = !power,
                        CoilKind::Set => *bit |= power,
                        CoilKind::Reset => *bit &= !power,
                    },
                    Element::Pulse { falling, .. } => {
                        let before = std::mem::replace(&mut self.pulse_memory[i][k], power);
                        *bit = if *falling {
                            !power && before
                        } else {
                            power && !before
                        };
                    }
                    _ => {}
                }
            }
            all.push(report);
        }
        all
    }
}
