//! Compiling to the accumulator machines, MINASEC-U and the AVR PLC.
//!
//! A pure network (contacts only) is computed into the accumulator: a
//! series is `LD` then `AND`s, a parallel `LD` then `OR`s. A block that
//! is itself a group goes first when it can (the seed's own trick: no
//! temporary needed); any further group is computed beforehand into a
//! temporary relay and ANDed / ORed back. Edge contacts are computed into
//! temporaries before the rung; in-line boxes (AVR) act on the running
//! result, so they must stand on the rung's main line.

use super::{contact, is_pure, replace_edges, series_items, size, Mapped, Options, Temps};
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{LadderError, Pos};
use crate::ladder::net::{Net, RungLogic};
use crate::MachineId;

/// MINASEC-U's program memory.
const MINASEC_STEPS: usize = 256;

/// Which accumulator machine's text a ladder compiles to (its target
/// picks it): the two differ in temporaries, edges, latches and format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// MINASEC-U: M10-M13 for temporaries, edges from a relay's memory,
    /// set / reset change the accumulator, 256 steps, its listing.
    Minasec,
    /// The AVR PLC: register bits for temporaries, its pulse instruction,
    /// timers in scans, its assembler source.
    Avr,
}

/// One accumulator operation; the bool is "inverted".
#[derive(Clone, Debug, PartialEq, Eq)]
enum Op {
    Ld(String, bool),
    And(String, bool),
    Or(String, bool),
    St(String, bool),
    Set(String),
    Reset(String),
    Not,
    Pulse(String, bool),
    Timer(TimerKind, usize, u32),
    Comment(String),
}

struct Compiler {
    machine: MachineId,
    dialect: Dialect,
    /// The AVR PLC's scan period in ms: in-line timers count scans.
    scan_ms: u32,
    ops: Vec<Op>,
    temps: Temps,
    timers: Vec<String>,
    /// The rung being compiled (its index among the rungs given).
    rung_index: usize,
    /// For each leaf: its rung, its cell, and the op that reads its
    /// device (a contact) or computes its output (an in-line box).
    sources: Vec<(usize, Pos, usize)>,
}

/// Compiles checked rung logic for MINASEC-U or the AVR PLC (`machine`
/// names it in messages), with the step each rung starts at and each
/// leaf's line.
pub(crate) fn compile_mapped(
    rungs: &[RungLogic],
    machine: MachineId,
    dialect: Dialect,
    options: Options,
) -> Result<Mapped, Vec<LadderError>> {
    let candidates = match dialect {
        Dialect::Minasec => ["M10", "M11", "M12", "M13"]
            .into_iter()
            .map(String::from)
            .chain((0..8).map(|n| format!("M{n:02}")))
            .collect(),
        _ => (16..=25)
            .rev()
            .flat_map(|r| (0..8).map(move |b| format!("R{r}.{b}")))
            .collect(),
    };
    let what = match dialect {
        Dialect::Minasec => "M10-M13, then unused M00-M07",
        _ => "unused bits of R25 down to R16",
    };
    let mut c = Compiler {
        machine,
        dialect,
        scan_ms: options.avr_scan_ms,
        ops: Vec::new(),
        temps: Temps::new(candidates, rungs, what),
        timers: Vec::new(),
        rung_index: 0,
        sources: Vec::new(),
    };
    let mut errors = Vec::new();
    let mut starts = Vec::with_capacity(rungs.len());
    for (i, logic) in rungs.iter().enumerate() {
        starts.push(c.steps());
        c.rung_index = i;
        if let Err((pos, m)) = c.rung(logic) {
            errors.push(match pos {
                Some(p) => LadderError::at(i, p, m),
                None => LadderError::rung(i, m),
            });
        }
        if dialect == Dialect::Minasec && c.steps() > MINASEC_STEPS && errors.is_empty() {
            errors.push(LadderError::rung(
                i,
                format!(
                    "the program needs {} steps by this rung: MINASEC-U has {MINASEC_STEPS}",
                    c.steps()
                ),
            ));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let (text, op_lines) = match dialect {
        Dialect::Minasec => c.minasec_text(),
        Dialect::Avr => c.avr_text(options),
    };
    let sources = c
        .sources
        .iter()
        .filter_map(|&(rung, pos, op)| Some((rung, pos, op_lines.get(op).copied().flatten()?)))
        .collect();
    Ok(Mapped {
        text,
        starts,
        sources,
    })
}

type RungResult = Result<(), (Option<Pos>, String)>;

impl Compiler {
    /// Notes that the next op reads (or computes) the leaf at `pos`.
    fn source(&mut self, pos: Pos) {
        self.sources.push((self.rung_index, pos, self.ops.len()));
    }

    fn steps(&self) -> usize {
        self.ops
            .iter()
            .filter(|o| !matches!(o, Op::Comment(_)))
            .count()
    }

    fn rung(&mut self, logic: &RungLogic) -> RungResult {
        if !logic.comment.is_empty() {
            self.ops.push(Op::Comment(logic.comment.clone()));
        }
        let items = series_items(&logic.condition);
        check_main_line(&items)?;
        // Edge contacts: computed before the rung into temporaries.
        let mut held = Vec::new();
        let items = self.edges_first(&items, &mut held)?;
        // Groups after the first in-line box: computed beforehand too.
        let first_box = items
            .iter()
            .position(|n| matches!(n, Net::Leaf(e, _) if !matches!(e, Element::Contact { .. })));
        let mut later = Vec::new();
        if let Some(b) = first_box {
            for item in &items[b + 1..] {
                if matches!(item, Net::Series(_) | Net::Parallel(_)) {
                    self.acc(item).map_err(|m| (Some(item.first_pos()), m))?;
                    let t = self.temps.take().map_err(|m| (Some(item.first_pos()), m))?;
                    self.ops.push(Op::St(t.clone(), false));
                    later.push((item.first_pos(), t));
                }
            }
        }
        // The main line.
        let head_end = first_box.unwrap_or(items.len());
        let head = match head_end {
            1 => items[0].clone(),
            _ => Net::Series(items[..head_end].to_vec()),
        };
        self.acc(&head).map_err(|m| (Some(head.first_pos()), m))?;
        for item in items.iter().skip(head_end) {
            match item {
                Net::Leaf(Element::Contact { .. }, p) => {
                    let (d, inv) = contact(item).unwrap_or(("", false));
                    self.source(*p);
                    self.ops.push(Op::And(d.to_string(), inv));
                }
                Net::Leaf(e, p) => {
                    self.source(*p);
                    self.inline_box(e).map_err(|m| (Some(*p), m))?;
                }
                _ => {
                    let p = item.first_pos();
                    if let Some(i) = later.iter().position(|(q, _)| *q == p) {
                        let (_, t) = later.remove(i);
                        self.ops.push(Op::And(t.clone(), false));
                        held.push(t);
                    }
                }
            }
        }
        self.outputs(&logic.outputs)
            .map_err(|(p, m)| (Some(p), m))?;
        for t in held {
            self.temps.give(t);
        }
        Ok(())
    }

    /// The rung's series items with each edge contact replaced by a
    /// temporary computed before the rung (its name added to `held`).
    fn edges_first(
        &mut self,
        items: &[Net],
        held: &mut Vec<String>,
    ) -> Result<Vec<Net>, (Option<Pos>, String)> {
        let mut edge_error = None;
        let out: Vec<Net> = {
            let mut edge = |kind: ContactKind, device: &str| -> Result<String, String> {
                let t = self.edge_prelude(kind, device)?;
                held.push(t.clone());
                Ok(t)
            };
            let mut out = Vec::new();
            for item in items {
                match replace_edges(item, &mut edge) {
                    Ok(n) => out.push(n),
                    Err(m) => {
                        edge_error = Some((Some(item.first_pos()), m));
                        break;
                    }
                }
            }
            out
        };
        match edge_error {
            Some(e) => Err(e),
            None => Ok(out),
        }
    }

    /// Code computing a rising / falling contact into a temporary.
    fn edge_prelude(&mut self, kind: ContactKind, device: &str) -> Result<String, String> {
        let memory = self.temps.take_for_good()?; // last scan's state
        let t = self.temps.take()?;
        let falling = kind == ContactKind::Falling;
        if self.dialect == Dialect::Minasec {
            self.ops.push(Op::Ld(device.to_string(), falling));
            self.ops.push(Op::And(memory.clone(), !falling));
            self.ops.push(Op::St(t.clone(), false));
            self.ops.push(Op::Ld(device.to_string(), false));
            self.ops.push(Op::St(memory, false));
        } else {
            self.ops.push(Op::Ld(device.to_string(), false));
            self.ops.push(Op::Pulse(memory, falling));
            self.ops.push(Op::St(t.clone(), false));
        }
        Ok(t)
    }

    fn inline_box(&mut self, e: &Element) -> Result<(), String> {
        match e {
            Element::Not => self.ops.push(Op::Not),
            Element::Edge { falling } => {
                let memory = self.temps.take_for_good()?;
                self.ops.push(Op::Pulse(memory, *falling));
            }
            Element::Timer {
                kind,
                name,
                preset_ms,
            } => {
                timer_scans(*kind, *preset_ms, self.scan_ms)?;
                let index = self.timers.len();
                self.timers.push(name.clone());
                self.ops.push(Op::Timer(*kind, index, *preset_ms));
            }
            other => return Err(format!("{other} cannot stand in a rung's condition")),
        }
        Ok(())
    }

    /// Leaves A = `net` (contacts only).
    fn acc(&mut self, net: &Net) -> Result<(), String> {
        match net {
            Net::Leaf(_, p) => {
                let (d, inv) = contact(net).ok_or("only contacts can stand here")?;
                self.source(*p);
                self.ops.push(Op::Ld(d.to_string(), inv));
                Ok(())
            }
            Net::Series(v) => self.combine(v, true),
            Net::Parallel(v) => self.combine(v, false),
        }
    }

    fn combine(&mut self, items: &[Net], and: bool) -> Result<(), String> {
        let op = |d: &str, inv: bool| {
            if and {
                Op::And(d.to_string(), inv)
            } else {
                Op::Or(d.to_string(), inv)
            }
        };
        let groups: Vec<&Net> = items
            .iter()
            .filter(|n| !matches!(n, Net::Leaf(..)))
            .collect();
        let leaves: Vec<&Net> = items
            .iter()
            .filter(|n| matches!(n, Net::Leaf(..)))
            .collect();
        // The largest group goes first, straight into A; the others are
        // computed beforehand into temporaries.
        let head = groups
            .iter()
            .enumerate()
            .max_by_key(|(i, n)| (size(n), usize::MAX - i))
            .map(|(i, _)| i);
        let mut held = Vec::new();
        for (i, g) in groups.iter().enumerate() {
            if Some(i) != head {
                self.acc(g)?;
                let t = self.temps.take()?;
                self.ops.push(Op::St(t.clone(), false));
                held.push(t);
            }
        }
        let mut rest = leaves.iter();
        match head {
            Some(h) => self.acc(groups[h])?,
            None => {
                if let Some(first) = rest.next() {
                    self.acc(first)?;
                }
            }
        }
        for l in rest {
            let (d, inv) = contact(l).ok_or("only contacts can stand here")?;
            self.source(l.first_pos());
            self.ops.push(op(d, inv));
        }
        for t in held {
            self.ops.push(op(&t, false));
            self.temps.give(t);
        }
        Ok(())
    }

    fn outputs(&mut self, outputs: &[(Element, Pos)]) -> Result<(), (Pos, String)> {
        let minasec = self.dialect == Dialect::Minasec;
        // MINASEC-U's set / reset change A; if another output follows, A
        // is kept in a temporary and reloaded.
        let changes_a = |e: &Element| {
            minasec
                && matches!(
                    e,
                    Element::Coil {
                        kind: CoilKind::Set | CoilKind::Reset,
                        device,
                    } if device != "C0"
                )
        };
        let mut saved: Option<String> = None;
        for (i, (e, pos)) in outputs.iter().enumerate() {
            let last = i + 1 == outputs.len();
            if changes_a(e) && !last && saved.is_none() {
                let t = self.temps.take().map_err(|m| (*pos, m))?;
                self.ops.push(Op::St(t.clone(), false));
                saved = Some(t);
            }
            let Element::Coil { kind, device } = e else {
                return Err((*pos, format!("{e} is not an output of {}", self.machine)));
            };
            let d = device.clone();
            match (kind, minasec) {
                // The counter's clear latch follows the power (FX `RST C`).
                (CoilKind::Reset, true) if d == "C0" => self.ops.push(Op::St("C0R".into(), false)),
                (CoilKind::Normal, _) => self.ops.push(Op::St(d, false)),
                (CoilKind::Inverted, _) => self.ops.push(Op::St(d, true)),
                (CoilKind::Set, false) => self.ops.push(Op::Set(d)),
                (CoilKind::Reset, false) => self.ops.push(Op::Reset(d)),
                // d = A | d
                (CoilKind::Set, true) => {
                    self.ops.push(Op::Or(d.clone(), false));
                    self.ops.push(Op::St(d, false));
                }
                // A | !d, stored inverted: d = !A & d
                (CoilKind::Reset, true) => {
                    self.ops.push(Op::Or(d.clone(), true));
                    self.ops.push(Op::St(d, true));
                }
            }
            if changes_a(e) && !last {
                if let Some(t) = &saved {
                    self.ops.push(Op::Ld(t.clone(), false));
                }
            }
        }
        if let Some(t) = saved {
            self.temps.give(t);
        }
        Ok(())
    }

    /// The MINASEC-U sheet, and the text line of each op.
    fn minasec_text(&self) -> (String, Vec<Option<usize>>) {
        let mut out = String::from("; compiled by hashigo from a ladder\n");
        let mut lines = Vec::with_capacity(self.ops.len());
        let mut line = 1;
        let mut step = 0;
        for op in &self.ops {
            let (m, d) = match op {
                Op::Ld(d, inv) => (if *inv { "LDI" } else { "LD" }, d),
                Op::And(d, inv) => (if *inv { "ANDI" } else { "AND" }, d),
                Op::Or(d, inv) => (if *inv { "ORI" } else { "OR" }, d),
                Op::St(d, inv) => (if *inv { "STI" } else { "ST" }, d),
                Op::Comment(c) => {
                    out.push_str(&format!("; {}\n", one_line(c)));
                    lines.push(None);
                    line += 1;
                    continue;
                }
                // Not offered on MINASEC-U (the capability table says so).
                _ => {
                    lines.push(None);
                    continue;
                }
            };
            out.push_str(&format!("{step:03} {m:<4} {d}\n"));
            lines.push(Some(line));
            line += 1;
            step += 1;
        }
        (out, lines)
    }

    /// The AVR source, and the text line of each op.
    fn avr_text(&self, options: Options) -> (String, Vec<Option<usize>>) {
        let mut out = String::from("; compiled by hashigo from a ladder\n");
        out.push_str(&format!(
            "; timer presets are ms/Scan (compiled for a {} ms scan)\n",
            options.avr_scan_ms
        ));
        if !self.timers.is_empty() {
            out.push_str(".dseg\nPLC_Timer_Top:\n");
            for (i, name) in self.timers.iter().enumerate() {
                out.push_str(&format!("Timer{i}: .byte 2 ; {}\n", one_line(name)));
            }
            out.push_str(".cseg\n");
        }
        // Devices are checked (`R3.4`) before they get here.
        let bit = |d: &str| {
            d.strip_prefix('R')
                .and_then(|rb| rb.split_once('.'))
                .map_or_else(|| "0,0".to_string(), |(r, b)| format!("{r},Bit{b}"))
        };
        let mut lines = Vec::with_capacity(self.ops.len());
        // The next line's number (the header is written above).
        let mut next = out.matches('\n').count();
        for op in &self.ops {
            let line = match op {
                Op::Ld(d, inv) => {
                    format!("{},{},0", if *inv { "Load_B" } else { "Load_A" }, bit(d))
                }
                Op::And(d, inv) => format!("{},{},0", if *inv { "And_B" } else { "And_A" }, bit(d)),
                Op::Or(d, inv) => format!("{},{},0", if *inv { "Or_B" } else { "Or_A" }, bit(d)),
                Op::St(d, inv) => {
                    format!("{},{},0", if *inv { "Coil_B" } else { "Coil_A" }, bit(d))
                }
                Op::Set(d) => format!("Set_Coil,{},0", bit(d)),
                Op::Reset(d) => format!("Reset_Coil,{},0", bit(d)),
                Op::Not => "Not,0,0,0".to_string(),
                Op::Pulse(d, falling) => {
                    format!(
                        "{},{},0",
                        if *falling { "Pulse_B" } else { "Pulse_A" },
                        bit(d)
                    )
                }
                Op::Timer(kind, index, ms) => {
                    let k = kind.name();
                    format!("{k},LOW(Timer{index}),LOW({ms}/Scan),HIGH({ms}/Scan)")
                }
                Op::Comment(c) => {
                    out.push_str(&format!("; {}\n", one_line(c)));
                    lines.push(None);
                    next += 1;
                    continue;
                }
            };
            lines.push(Some(next));
            next += 1;
            out.push_str(".db ");
            out.push_str(&line);
            out.push('\n');
        }
        out.push_str(".db End_PLC,0,0,0\n");
        (out, lines)
    }
}

/// The preset of an AVR in-line timer in scans: its record holds a 16-bit
/// count of scans (`LOW(ms/Scan), HIGH(ms/Scan)`), so a set time that is
/// not a whole number of scans, is under one scan, or needs more than
/// 65 535 scans would run for another time than the one drawn: refused.
fn timer_scans(kind: TimerKind, preset_ms: u32, scan_ms: u32) -> Result<u16, String> {
    let name = kind.name();
    let scan_ms = scan_ms.max(1);
    if preset_ms < scan_ms || !preset_ms.is_multiple_of(scan_ms) {
        return Err(format!(
            "{name} {preset_ms} ms is not a whole number of {scan_ms} ms scans: the AVR PLC's timers count scans"
        ));
    }
    u16::try_from(preset_ms / scan_ms).map_err(|_| {
        format!(
            "{name} {preset_ms} ms is {} scans of {scan_ms} ms: the AVR PLC's timers count at most 65535",
            preset_ms / scan_ms
        )
    })
}

/// A comment on one line (newlines would end the `;` comment).
pub(crate) fn one_line(text: &str) -> String {
    text.replace(['\n', '\r'], " ")
}

/// In-line boxes act on the running result: they stand on the rung's
/// main line only, after a contact.
fn check_main_line(items: &[Net]) -> Result<(), (Option<Pos>, String)> {
    for item in items {
        if matches!(item, Net::Series(_) | Net::Parallel(_)) && !is_pure(item) {
            let pos = item
                .leaves()
                .into_iter()
                .find(|(e, _)| !matches!(e, Element::Contact { .. }))
                .map(|(_, p)| p);
            return Err((
                pos,
                "an in-line box (NOT, edge, timer) must stand on the rung's main line, not in a parallel branch".into(),
            ));
        }
    }
    if let Some(Net::Leaf(e, p)) = items.first() {
        if !matches!(e, Element::Contact { .. }) {
            return Err((Some(*p), "an in-line box needs a contact before it".into()));
        }
    }
    Ok(())
}
