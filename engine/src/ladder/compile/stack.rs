//! Compiling to the block-stack machines, PLC-IO86A and the Arduino
//! sketch: a series is `LD` then `AND`s, a parallel `LD` then `OR`s, and
//! a group inside either is its own block joined by `ANB` / `ORB` (the
//! Arduino sketch: `ANDB` / `ORB`).
//!
//! IO86A keeps the result after `OUT`, so one rung drives many outputs;
//! the Arduino sketch's `OUT` pops it, and the sketch has no internal
//! relays, so later outputs reload the first output's pin instead.

use super::accumulator::one_line;
use super::{contact, negate, replace_edges, size, Mapped, Temps};
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::{LadderError, Pos};
use crate::ladder::net::{Net, RungLogic};
use crate::MachineId;

/// The sketch's bit stack holds 16 bits.
const ARDUINO_STACK: usize = 16;

struct Compiler {
    arduino: bool,
    lines: Vec<String>,
    depth: usize,
    max_depth: usize,
    temps: Temps,
    /// The rung being compiled (its index among the rungs given).
    rung_index: usize,
    /// (rung, leaf's cell, 0-based line of the op reading its device).
    sources: Vec<(usize, Pos, usize)>,
}

/// Which block-stack machine's text a ladder compiles to (its target
/// picks it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// PLC-IO86A: `OUT` keeps the result; relays M00-M55 for temporaries.
    Io86a,
    /// The Arduino sketch: `OUT` pops the result; no relays, 16-bit stack.
    Arduino,
}

/// Compiles checked rung logic for IO86A or the Arduino sketch (`machine`
/// names it in messages), with the step each rung starts at and each
/// leaf's line.
pub(crate) fn compile_mapped(
    rungs: &[RungLogic],
    machine: MachineId,
    dialect: Dialect,
) -> Result<Mapped, Vec<LadderError>> {
    let arduino = dialect == Dialect::Arduino;
    let candidates = if arduino {
        Vec::new()
    } else {
        (0..56).rev().map(|n| format!("M{n:02}")).collect()
    };
    let mut c = Compiler {
        arduino,
        lines: vec!["; compiled by hashigo from a ladder".to_string()],
        depth: 0,
        max_depth: 0,
        temps: Temps::new(candidates, rungs, "unused M00-M55"),
        rung_index: 0,
        sources: Vec::new(),
    };
    let mut errors = Vec::new();
    let mut starts = Vec::with_capacity(rungs.len());
    // Steps so far, counted over the lines added since the last rung.
    let (mut steps, mut counted) = (0, 0);
    for (i, logic) in rungs.iter().enumerate() {
        steps += c.lines[counted..]
            .iter()
            .filter(|l| !l.starts_with(';'))
            .count();
        counted = c.lines.len();
        starts.push(steps);
        c.rung_index = i;
        if !logic.comment.is_empty() {
            c.lines.push(format!("; {}", one_line(&logic.comment)));
        }
        c.max_depth = 0;
        if let Err((pos, m)) = c.rung(logic) {
            errors.push(LadderError::at(i, pos, m));
        } else if arduino && c.max_depth > ARDUINO_STACK {
            errors.push(LadderError::rung(
                i,
                format!(
                    "the rung needs {} stack levels: the sketch's bit stack holds {ARDUINO_STACK}",
                    c.max_depth
                ),
            ));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    c.lines.push("END".to_string());
    let capacity = if arduino { 512 } else { 511 };
    let steps = c.lines.iter().filter(|l| !l.starts_with(';')).count();
    if steps > capacity {
        return Err(vec![LadderError::rung(
            rungs.len().saturating_sub(1),
            format!("the program needs {steps} steps: {machine} has {capacity}"),
        )]);
    }
    let mut text = c.lines.join("\n");
    text.push('\n');
    Ok(Mapped {
        text,
        starts,
        sources: c.sources,
    })
}

type RungResult = Result<(), (Pos, String)>;

impl Compiler {
    fn emit(&mut self, m: &str, operand: &str) {
        self.lines.push(if operand.is_empty() {
            m.to_string()
        } else {
            format!("{m} {operand}")
        });
    }

    fn push(&mut self) {
        self.depth += 1;
        self.max_depth = self.max_depth.max(self.depth);
    }

    /// A contact op; `pos` is the leaf it reads for (none for a reload
    /// of an output's pin).
    fn contact_op(&mut self, kind: &str, device: &str, inv: bool, pos: Option<Pos>) {
        if let Some(pos) = pos {
            self.sources.push((self.rung_index, pos, self.lines.len()));
        }
        let m = match (kind, inv, self.arduino) {
            ("LD", false, _) => "LD",
            ("LD", true, false) => "LDI",
            ("LD", true, true) => "LDN",
            ("AND", false, _) => "AND",
            ("AND", true, false) => "ANI",
            ("AND", true, true) => "ANDN",
            ("OR", false, _) => "OR",
            ("OR", true, false) => "ORI",
            _ => "ORN",
        };
        if kind == "LD" {
            self.push();
        }
        self.emit(m, device);
    }

    /// Pushes a block computing `net` (contacts only).
    fn block(&mut self, net: &Net) -> Result<(), String> {
        match net {
            Net::Leaf(_, p) => {
                let (d, inv) = contact(net).ok_or("only contacts can stand here")?;
                self.contact_op("LD", d, inv, Some(*p));
                Ok(())
            }
            Net::Series(v) => self.group(v, true),
            Net::Parallel(v) => self.group(v, false),
        }
    }

    fn group(&mut self, items: &[Net], and: bool) -> Result<(), String> {
        // The largest group first saves a block and a join.
        let mut order: Vec<&Net> = items.iter().collect();
        if let Some(i) = (0..order.len())
            .filter(|&i| !matches!(order[i], Net::Leaf(..)))
            .max_by_key(|&i| (size(order[i]), usize::MAX - i))
        {
            let g = order.remove(i);
            order.insert(0, g);
        }
        let mut it = order.into_iter();
        if let Some(first) = it.next() {
            self.block(first)?;
        }
        for n in it {
            match contact(n) {
                Some((d, inv)) => {
                    let op = if and { "AND" } else { "OR" };
                    self.contact_op(op, d, inv, Some(n.first_pos()));
                }
                None => {
                    self.block(n)?;
                    let join = match (and, self.arduino) {
                        (true, false) => "ANB",
                        (true, true) => "ANDB",
                        (false, _) => "ORB",
                    };
                    self.emit(join, "");
                    self.depth -= 1;
                }
            }
        }
        Ok(())
    }

    fn rung(&mut self, logic: &RungLogic) -> RungResult {
        // Edge contacts: IO86A computes them with PLS / PLF into relays.
        let mut held = Vec::new();
        let mut prelude = Vec::new();
        let cond = {
            let mut edge = |kind: ContactKind, device: &str| -> Result<String, String> {
                let t = self.temps.take()?;
                let m = if kind == ContactKind::Falling {
                    "PLF"
                } else {
                    "PLS"
                };
                prelude.push(format!("LD {device}"));
                prelude.push(format!("{m} {t}"));
                held.push(t.clone());
                Ok(t)
            };
            replace_edges(&logic.condition, &mut edge)
                .map_err(|m| (logic.condition.first_pos(), m))?
        };
        self.lines.extend(prelude);
        let at = |p: Pos| move |m: String| (p, m);
        let first = logic.condition.first_pos();
        if self.arduino {
            self.arduino_outputs(&cond, &logic.outputs)?;
        } else {
            self.io86a_outputs(&cond, &logic.outputs)
                .map_err(at(first))?;
        }
        for t in held {
            self.temps.give(t);
        }
        self.depth = 0;
        Ok(())
    }

    fn io86a_outputs(&mut self, cond: &Net, outputs: &[(Element, Pos)]) -> Result<(), String> {
        let inverted = |e: &Element| {
            matches!(
                e,
                Element::Coil {
                    kind: CoilKind::Inverted,
                    ..
                }
            )
        };
        // A lone inverted coil drives from the negated network; with other
        // outputs, the result goes to a relay first.
        if outputs.len() == 1 && inverted(&outputs[0].0) {
            self.block(&negate(cond))?;
            if let Element::Coil { device, .. } = &outputs[0].0 {
                self.emit("OUT", device);
            }
            return Ok(());
        }
        self.block(cond)?;
        let any_inverted = outputs.iter().any(|(e, _)| inverted(e));
        let keep = if any_inverted {
            let t = self.temps.take()?;
            self.emit("OUT", &t);
            Some(t)
        } else {
            None
        };
        // In the rung's order, reloading the relay when the sense changes.
        let mut negated = false;
        for (e, _) in outputs {
            match (&keep, inverted(e)) {
                (Some(t), true) => {
                    if !negated {
                        self.emit("LDI", t);
                        negated = true;
                    }
                    if let Element::Coil { device, .. } = e {
                        self.emit("OUT", device);
                    }
                }
                (Some(t), false) if negated => {
                    self.emit("LD", t);
                    negated = false;
                    self.io86a_output(e);
                }
                _ => self.io86a_output(e),
            }
        }
        if let Some(t) = keep {
            self.temps.give(t);
        }
        Ok(())
    }

    fn io86a_output(&mut self, e: &Element) {
        match e {
            Element::Coil { kind, device } => {
                let m = match kind {
                    CoilKind::Set => "SET",
                    CoilKind::Reset => "RST",
                    _ => "OUT",
                };
                self.emit(m, device);
            }
            Element::Pulse { falling, device } => {
                self.emit(if *falling { "PLF" } else { "PLS" }, device);
            }
            Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
                self.emit("OUT", device);
                self.emit(&format!("K{preset}"), "");
            }
            Element::Mov { src, dst } => {
                self.emit("MOV", "");
                self.emit(src, "");
                self.emit(dst, "");
            }
            Element::Cmp { a, b } => {
                self.emit("CMP", "");
                self.emit(a, "");
                self.emit(b, "");
            }
            Element::Inc { dst } => {
                self.emit("INC", "");
                self.emit(dst, "");
            }
            Element::Dec { dst } => {
                self.emit("DEC", "");
                self.emit(dst, "");
            }
            _ => {}
        }
    }

    fn arduino_outputs(&mut self, cond: &Net, outputs: &[(Element, Pos)]) -> RungResult {
        for (e, p) in outputs {
            if !matches!(e, Element::Coil { .. }) {
                return Err((*p, format!("{e} is not an output of arduino-plc")));
            }
        }
        let reads: Vec<String> = cond
            .leaves()
            .iter()
            .filter_map(|(e, _)| e.read_device().map(String::from))
            .collect();
        let (order, anchor) = arduino_order(outputs);
        let mut source: Option<(String, bool)> = None; // (pin, holds !result)
        for (n, &i) in order.iter().enumerate() {
            let (e, p) = &outputs[i];
            let Element::Coil { kind, device } = e else {
                continue;
            };
            if source.is_none() && n > 0 {
                // No pin holds the result: recompute, unless an output
                // already changed what the network reads.
                if let Some(d) = order[..n]
                    .iter()
                    .filter_map(|&j| outputs[j].0.written_device())
                    .find(|d| reads.iter().any(|r| r == d))
                {
                    return Err((
                        *p,
                        format!("the rung reads {d}, which an earlier output of it drives, and the sketch has no relay to keep the result: split the rung"),
                    ));
                }
            }
            let result = |c: &mut Compiler, negated: bool| -> Result<(), String> {
                match &source {
                    Some((pin, inv)) => {
                        c.contact_op("LD", pin, *inv ^ negated, None);
                        Ok(())
                    }
                    None if negated => c.block(&negate(cond)),
                    None => c.block(cond),
                }
            };
            let r = match kind {
                CoilKind::Normal => result(self, false),
                CoilKind::Inverted => result(self, true),
                CoilKind::Set | CoilKind::Reset => {
                    self.contact_op("LD", device, false, None);
                    let set = *kind == CoilKind::Set;
                    let r = result(self, !set);
                    self.emit(if set { "ORB" } else { "ANDB" }, "");
                    self.depth -= 1;
                    r
                }
            };
            r.map_err(|m| (*p, m))?;
            self.emit("OUT", device);
            self.depth -= 1;
            if n == 0 && anchor.is_some() {
                source = Some((device.clone(), *kind == CoilKind::Inverted));
            }
        }
        Ok(())
    }
}

/// The order an Arduino rung's outputs are written in, and the one that
/// stands for the result (first): the first normal (or inverted) coil
/// whose pin no other output of the rung drives; later outputs reload it.
fn arduino_order(outputs: &[(Element, Pos)]) -> (Vec<usize>, Option<usize>) {
    let sole = |i: usize| {
        let d = outputs[i].0.written_device();
        outputs
            .iter()
            .enumerate()
            .all(|(j, (e, _))| j == i || e.written_device() != d)
    };
    let coil_of = |kind: CoilKind| {
        (0..outputs.len()).find(|&i| {
            sole(i) && matches!(&outputs[i].0, Element::Coil { kind: k, .. } if *k == kind)
        })
    };
    let anchor = coil_of(CoilKind::Normal).or_else(|| coil_of(CoilKind::Inverted));
    let mut order: Vec<usize> = (0..outputs.len()).collect();
    if let Some(a) = anchor {
        order.retain(|&i| i != a);
        order.insert(0, a);
    }
    (order, anchor)
}
