//! Programs back to ladders: each machine's mnemonic text read as rungs.
//!
//! Accumulator machines (MINASEC-U, AVR PLC): `LD` starts a condition,
//! `AND` / `OR` grow it, each store is an output of the rung. When the
//! program goes on from a stored result (`ST Y00` then `ANDI T1`), the
//! next rung starts from a contact on that output, which holds the same
//! value. A temporary relay (M10-M13 on MINASEC-U) stored once and read
//! once later is folded back into the rung that reads it; other relays
//! stay visible as rungs of their own.
//!
//! Block-stack machines (IO86A, Arduino sketch): `LD` opens a block, `ORB`
//! / `ANB` join the top two, outputs close the rung.

use std::fmt;

use super::compile::negate;
use super::element::{CoilKind, ContactKind, Element, TimerKind};
use super::grid::{Ladder, Pos};
use super::net::{try_layout, Net, RungLogic, TooLarge};
use crate::limits::MAX_NESTING;
use crate::{arduino, avr, io86a, minasec, MachineId};

/// Why a program has no ladder form, at its step (0-based, as listed).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StepError {
    /// The step.
    pub step: usize,
    /// What cannot be drawn.
    pub message: String,
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "step {}: {}", self.step, self.message)
    }
}

impl std::error::Error for StepError {}

/// Why a program could not be decompiled.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DecompileError {
    /// A step has no ladder form.
    Step(StepError),
    /// A rung (1-based) is too large to draw (docs/limits.md).
    Drawing {
        /// The rung, 1-based.
        rung: usize,
        /// How large it would be.
        size: TooLarge,
    },
}

impl From<StepError> for DecompileError {
    fn from(e: StepError) -> Self {
        DecompileError::Step(e)
    }
}

impl fmt::Display for DecompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DecompileError::Step(e) => e.fmt(f),
            DecompileError::Drawing { rung, size } => write!(f, "rung {rung}: {size}"),
        }
    }
}

impl std::error::Error for DecompileError {}

/// The rungs drawn on grids, each refused past the rung size limit.
fn drawn(rungs: &[RungLogic]) -> Result<Ladder, DecompileError> {
    let mut ladder = Ladder::default();
    for (i, logic) in rungs.iter().enumerate() {
        let rung =
            try_layout(logic).map_err(|size| DecompileError::Drawing { rung: i + 1, size })?;
        ladder.rungs.push(rung);
    }
    Ok(ladder)
}

/// A program parsed for its machine.
pub enum Source<'a> {
    /// A MINASEC-U listing.
    Minasec(&'a minasec::Program),
    /// An AVR PLC program and its scan period in ms (for timer presets).
    Avr(&'a avr::Program, u32),
    /// An IO86A listing.
    Io86a(&'a io86a::Program),
    /// An Arduino sketch program.
    Arduino(&'a arduino::Program),
}

/// The program as a ladder.
pub fn decompile(source: Source<'_>) -> Result<Ladder, DecompileError> {
    let mut ladder = match source {
        Source::Minasec(p) => minasec_ladder(p)?,
        Source::Avr(p, scan) => avr_ladder(p, scan)?,
        Source::Io86a(p) => io86a_ladder(p)?,
        Source::Arduino(p) => arduino_ladder(p)?,
    };
    if let Source::Avr(p, _) = source {
        for (name, bit) in p.names() {
            ladder.device_comments.insert(bit.to_string(), name.clone());
        }
    }
    Ok(ladder)
}

/// The machine a [`Source`] is for.
pub fn machine_of(source: &Source<'_>) -> MachineId {
    match source {
        Source::Minasec(_) => MachineId::MinasecU,
        Source::Avr(..) => MachineId::AvrPlc,
        Source::Io86a(_) => MachineId::Io86a,
        Source::Arduino(_) => MachineId::ArduinoPlc,
    }
}

fn contact(device: String, inverted: bool) -> Net {
    let kind = if inverted {
        ContactKind::Nc
    } else {
        ContactKind::No
    };
    Net::Leaf(Element::Contact { kind, device }, Pos::new(0, 0))
}

/// A condition being built, with how deeply it nests, so that a program
/// that nests blocks past [`MAX_NESTING`] is refused at the step that
/// would (and no deeper network is ever built).
struct Part {
    net: Net,
    depth: usize,
}

impl Part {
    fn of(net: Net) -> Part {
        let depth = net.depth();
        Part { net, depth }
    }

    /// `self` and `b` in series (`and`) or in parallel.
    fn join(self, b: Part, and: bool, step: usize) -> Result<Part, StepError> {
        let merges = |p: &Part| match p.net {
            Net::Series(_) => and,
            Net::Parallel(_) => !and,
            Net::Leaf(..) => false,
        };
        let level = |p: &Part| if merges(p) { p.depth } else { p.depth + 1 };
        let depth = level(&self).max(level(&b));
        if depth > MAX_NESTING {
            return Err(StepError {
                step,
                message: format!(
                    "blocks nest more than {MAX_NESTING} deep here: a ladder cannot draw it (docs/limits.md)"
                ),
            });
        }
        let net = if and {
            Net::series(self.net, b.net)
        } else {
            Net::parallel(self.net, b.net)
        };
        Ok(Part { net, depth })
    }
}

/// Ends a rung: its condition drives the outputs collected (a condition
/// with no output drives nothing and is dropped, as the machine ignores it).
fn close_rung(rungs: &mut Vec<RungLogic>, condition: Option<Part>, outputs: &mut Vec<Element>) {
    if let Some(Part { net: condition, .. }) = condition {
        if !outputs.is_empty() {
            rungs.push(RungLogic {
                condition,
                outputs: outputs.drain(..).map(|e| (e, Pos::new(0, 0))).collect(),
                comment: String::new(),
            });
        }
    }
    outputs.clear();
}

/// Adds an output to the open rung; the first output that holds the
/// rung's result becomes the anchor a continuation starts from.
fn add_output<T>(
    open: bool,
    outputs: &mut Vec<Element>,
    anchor: &mut Option<T>,
    e: Element,
    holds: Option<T>,
    step: usize,
) -> Result<(), StepError> {
    if !open {
        return Err(StepError {
            step,
            message: "an output with no LD before it".into(),
        });
    }
    if anchor.is_none() {
        *anchor = holds;
    }
    outputs.push(e);
    Ok(())
}

/// The accumulator walk shared by MINASEC-U and the AVR PLC.
#[derive(Default)]
struct Acc {
    rungs: Vec<RungLogic>,
    a: Option<Part>,
    outputs: Vec<Element>,
    /// An output holding the accumulator's value: (device, inverted).
    anchor: Option<(String, bool)>,
}

impl Acc {
    fn flush(&mut self) {
        close_rung(&mut self.rungs, self.a.take(), &mut self.outputs);
    }

    fn load(&mut self, n: Net) {
        self.flush();
        self.anchor = None;
        self.a = Some(Part::of(n));
    }

    /// The running result, restarting from the anchor after outputs.
    fn current(&mut self, step: usize) -> Result<Part, StepError> {
        if !self.outputs.is_empty() {
            let Some((d, inv)) = self.anchor.clone() else {
                return Err(StepError {
                    step,
                    message: "the result is used again after outputs none of which holds it: store it in a relay first".into(),
                });
            };
            self.flush();
            self.a = Some(Part::of(contact(d, inv)));
        }
        self.a.take().ok_or(StepError {
            step,
            message: "no LD before this step".into(),
        })
    }

    fn and(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), true, step)?);
        Ok(())
    }

    fn or(&mut self, n: Net, step: usize) -> Result<(), StepError> {
        let a = self.current(step)?;
        self.a = Some(a.join(Part::of(n), false, step)?);
        Ok(())
    }

    fn output(
        &mut self,
        e: Element,
        holds: Option<(String, bool)>,
        step: usize,
    ) -> Result<(), StepError> {
        let open = self.a.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}

fn minasec_ladder(p: &minasec::Program) -> Result<Ladder, DecompileError> {
    use minasec::isa::Device;
    use minasec::Opcode;
    let mut acc = Acc::default();
    for (step, i) in p.instructions().enumerate() {
        let d = i.address.to_string();
        let plain = matches!(i.address.device(), Device::Output(_) | Device::Relay(_));
        match i.opcode {
            Opcode::Ld | Opcode::Ldi => acc.load(contact(d, i.opcode == Opcode::Ldi)),
            Opcode::And | Opcode::Andi => acc.and(contact(d, i.opcode == Opcode::Andi), step)?,
            Opcode::Or | Opcode::Ori => acc.or(contact(d, i.opcode == Opcode::Ori), step)?,
            Opcode::St | Opcode::Sti => {
                let inv = i.opcode == Opcode::Sti;
                let kind = if inv {
                    CoilKind::Inverted
                } else {
                    CoilKind::Normal
                };
                let holds = plain.then(|| (d.clone(), inv));
                acc.output(Element::Coil { kind, device: d }, holds, step)?;
            }
        }
    }
    acc.flush();
    let rungs = fold_temporaries(acc.rungs, &["M10", "M11", "M12", "M13"]);
    drawn(&rungs)
}

fn avr_ladder(p: &avr::Program, scan_ms: u32) -> Result<Ladder, DecompileError> {
    use avr::Instruction as I;
    let mut acc = Acc::default();
    for (step, &i) in p.instructions().iter().enumerate() {
        match i {
            I::Load(b, inv) => acc.load(contact(b.to_string(), inv)),
            I::And(b, inv) => acc.and(contact(b.to_string(), inv), step)?,
            I::Or(b, inv) => acc.or(contact(b.to_string(), inv), step)?,
            I::Coil(b, inv) => {
                let kind = if inv {
                    CoilKind::Inverted
                } else {
                    CoilKind::Normal
                };
                acc.output(
                    Element::Coil {
                        kind,
                        device: b.to_string(),
                    },
                    Some((b.to_string(), inv)),
                    step,
                )?;
            }
            I::Set(b) | I::Reset(b) => {
                let kind = if matches!(i, I::Set(_)) {
                    CoilKind::Set
                } else {
                    CoilKind::Reset
                };
                acc.output(
                    Element::Coil {
                        kind,
                        device: b.to_string(),
                    },
                    None,
                    step,
                )?;
            }
            I::Timer {
                kind,
                index,
                preset,
            } => {
                let name = format!("Timer{index}");
                let kind = match kind {
                    avr::TimerKind::Ton => TimerKind::Ton,
                    avr::TimerKind::Tof => TimerKind::Tof,
                    avr::TimerKind::Tp => TimerKind::Tp,
                };
                let leaf = Element::Timer {
                    kind,
                    name,
                    preset_ms: u32::from(preset) * scan_ms,
                };
                acc.and(Net::Leaf(leaf, Pos::new(0, 0)), step)?;
            }
            I::Not => acc.and(Net::Leaf(Element::Not, Pos::new(0, 0)), step)?,
            I::Pulse(_, falling) => {
                acc.and(Net::Leaf(Element::Edge { falling }, Pos::new(0, 0)), step)?
            }
            I::End => break,
        }
    }
    acc.flush();
    drawn(&acc.rungs)
}

/// Folds a temporary stored by one rung and read once by a later one back
/// into the reader, when nothing in between changes what it was made of.
fn fold_temporaries(mut rungs: Vec<RungLogic>, temps: &[&str]) -> Vec<RungLogic> {
    let reads = |r: &RungLogic, d: &str| {
        r.condition
            .leaves()
            .iter()
            .filter(|(e, _)| e.read_device() == Some(d))
            .count()
    };
    let writes =
        |r: &RungLogic, d: &str| r.outputs.iter().any(|(e, _)| e.written_device() == Some(d));
    let mut i = 0;
    while i < rungs.len() {
        let foldable = match rungs[i].outputs.as_slice() {
            [(
                Element::Coil {
                    kind: CoilKind::Normal,
                    device,
                },
                _,
            )] if temps.contains(&device.as_str()) => Some(device.clone()),
            _ => None,
        };
        if let Some(t) = foldable {
            let total: usize = rungs.iter().map(|r| reads(r, &t)).sum();
            let written: usize = rungs.iter().filter(|r| writes(r, &t)).count();
            let reader = (i + 1..rungs.len()).find(|&j| reads(&rungs[j], &t) > 0);
            if let (1, 1, Some(j)) = (total, written, reader) {
                let inputs: Vec<String> = rungs[i]
                    .condition
                    .leaves()
                    .iter()
                    .filter_map(|(e, _)| e.read_device().map(String::from))
                    .collect();
                let untouched = (i + 1..j).all(|k| inputs.iter().all(|d| !writes(&rungs[k], d)))
                    && inputs.iter().all(|d| d != &t);
                if untouched {
                    let cond = rungs[i].condition.clone();
                    let folded = substitute(&rungs[j].condition, &t, &cond).normalised();
                    // Folding stacks one rung's logic into another; a fold
                    // that would nest too deep is not made.
                    if folded.depth() > MAX_NESTING {
                        i += 1;
                        continue;
                    }
                    rungs[j].condition = folded;
                    rungs.remove(i);
                    continue;
                }
            }
        }
        i += 1;
    }
    rungs
}

fn substitute(net: &Net, device: &str, with: &Net) -> Net {
    match net {
        Net::Leaf(Element::Contact { kind, device: d }, _) if d == device => match kind {
            ContactKind::Nc => negate(with),
            _ => with.clone(),
        },
        Net::Leaf(..) => net.clone(),
        Net::Series(v) => Net::Series(v.iter().map(|n| substitute(n, device, with)).collect()),
        Net::Parallel(v) => Net::Parallel(v.iter().map(|n| substitute(n, device, with)).collect()),
    }
}

/// The block-stack walk shared by IO86A and the Arduino sketch.
#[derive(Default)]
struct Stack {
    rungs: Vec<RungLogic>,
    blocks: Vec<Part>,
    cur: Option<Part>,
    outputs: Vec<Element>,
    anchor: Option<String>,
}

impl Stack {
    fn flush(&mut self) {
        close_rung(&mut self.rungs, self.cur.take(), &mut self.outputs);
        self.blocks.clear();
        self.anchor = None;
    }

    fn load(&mut self, n: Net) {
        if !self.outputs.is_empty() {
            self.flush();
        } else if let Some(c) = self.cur.take() {
            self.blocks.push(c);
        }
        self.cur = Some(Part::of(n));
    }

    fn grow(&mut self, n: Net, and: bool, step: usize) -> Result<(), StepError> {
        if !self.outputs.is_empty() {
            let Some(d) = self.anchor.clone() else {
                return Err(StepError {
                    step,
                    message: "the rung goes on after outputs none of which holds its result".into(),
                });
            };
            self.flush();
            self.cur = Some(Part::of(contact(d, false)));
        }
        let cur = self.cur.take().ok_or(StepError {
            step,
            message: "no LD before this step".into(),
        })?;
        self.cur = Some(cur.join(Part::of(n), and, step)?);
        Ok(())
    }

    fn join(&mut self, and: bool, step: usize) -> Result<(), StepError> {
        let (Some(a), Some(b)) = (self.blocks.pop(), self.cur.take()) else {
            return Err(StepError {
                step,
                message: "ORB / ANB needs two blocks".into(),
            });
        };
        self.cur = Some(a.join(b, and, step)?);
        Ok(())
    }

    fn output(&mut self, e: Element, holds: Option<String>, step: usize) -> Result<(), StepError> {
        let open = self.cur.is_some();
        add_output(open, &mut self.outputs, &mut self.anchor, e, holds, step)
    }
}

fn word(w: io86a::Word) -> String {
    match w {
        io86a::Word::K(k) => format!("K{k}"),
        io86a::Word::D(n) => format!("D{n:02}"),
        io86a::Word::T(n) => format!("T{n:02}"),
        io86a::Word::C(n) => format!("C{n:02}"),
    }
}

fn io86a_ladder(p: &io86a::Program) -> Result<Ladder, DecompileError> {
    use io86a::{Bit, Instruction as I};
    let mut s = Stack::default();
    for (step, &i) in p.instructions().iter().enumerate() {
        let bit = |b: Bit, inv: bool| contact(b.to_string(), inv);
        let coil = |kind: CoilKind, b: Bit| Element::Coil {
            kind,
            device: b.to_string(),
        };
        match i {
            I::Ld(b) | I::Ldi(b) => s.load(bit(b, matches!(i, I::Ldi(_)))),
            I::And(b) | I::Ani(b) => s.grow(bit(b, matches!(i, I::Ani(_))), true, step)?,
            I::Or(b) | I::Ori(b) => s.grow(bit(b, matches!(i, I::Ori(_))), false, step)?,
            I::Orb => s.join(false, step)?,
            I::Anb => s.join(true, step)?,
            I::Out(b) => s.output(coil(CoilKind::Normal, b), Some(b.to_string()), step)?,
            I::Set(b) => s.output(coil(CoilKind::Set, b), None, step)?,
            I::Rst(b) => s.output(coil(CoilKind::Reset, b), None, step)?,
            I::Pls(b) | I::Plf(b) => s.output(
                Element::Pulse {
                    falling: matches!(i, I::Plf(_)),
                    device: b.to_string(),
                },
                None,
                step,
            )?,
            I::OutTimer(n, w) | I::OutCounter(n, w) => {
                let io86a::Word::K(k) = w else {
                    return Err(DecompileError::Step(StepError {
                        step,
                        message: "a set value from a data register has no ladder form here: use a K constant".into(),
                    }));
                };
                let preset = u16::try_from(k).unwrap_or(0);
                let e = if matches!(i, I::OutTimer(..)) {
                    Element::TimerCoil {
                        device: format!("T{n:02}"),
                        preset,
                    }
                } else {
                    Element::CounterCoil {
                        device: format!("C{n:02}"),
                        preset,
                    }
                };
                s.output(e, None, step)?;
            }
            I::Mov(w, d) => s.output(
                Element::Mov {
                    src: word(w),
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Cmp(a, b) => s.output(
                Element::Cmp {
                    a: word(a),
                    b: word(b),
                },
                None,
                step,
            )?,
            I::Inc(d) => s.output(
                Element::Inc {
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Dec(d) => s.output(
                Element::Dec {
                    dst: format!("D{d:02}"),
                },
                None,
                step,
            )?,
            I::Sets(_) | I::Rsts(_) => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: "SETS / RSTS drive a second device: they have no ladder form here"
                        .into(),
                }))
            }
            I::End => break,
        }
    }
    s.flush();
    drawn(&s.rungs)
}

fn arduino_ladder(p: &arduino::Program) -> Result<Ladder, DecompileError> {
    use arduino::isa::{io_name, Op};
    let words = p.words();
    let mut s = Stack::default();
    for (step, &w) in words.iter().enumerate() {
        if w == arduino::isa::ERASED {
            break;
        }
        let operand = (w & 0xFF) as u8;
        let dev = || io_name(operand);
        match Op::decode(w) {
            Some(Op::Ld) | Some(Op::Ldn) => {
                s.load(contact(dev(), Op::decode(w) == Some(Op::Ldn)));
            }
            Some(op @ (Op::And | Op::Andn | Op::Or | Op::Orn)) => s.grow(
                contact(dev(), matches!(op, Op::Andn | Op::Orn)),
                matches!(op, Op::And | Op::Andn),
                step,
            )?,
            Some(Op::Andb) => s.join(true, step)?,
            Some(Op::Orb) => s.join(false, step)?,
            Some(Op::Out) => {
                s.output(Element::coil(&dev()), None, step)?;
                // The pop: this rung ends here, the block below (if any)
                // becomes the current one.
                let below = s.blocks.pop();
                let rest = std::mem::take(&mut s.blocks);
                s.flush();
                s.blocks = rest;
                s.cur = below;
            }
            Some(Op::End) => break,
            Some(Op::Jump) if operand == 0 => break,
            Some(Op::Jump) => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: format!(
                        "JUMP {operand} has no ladder form: only a final JUMP 0 (or END)"
                    ),
                }))
            }
            None => {
                return Err(DecompileError::Step(StepError {
                    step,
                    message: format!("word {w:04X} is no instruction"),
                }))
            }
        }
    }
    s.flush();
    drawn(&s.rungs)
}
