//! Lines resolved in order, and what the current result is at a label
//! (issue #44): the one every way there brings, the line before (when
//! it falls through) and each jump to it from above, when they agree in
//! type, as Beremiz's `QuitFb:` / `ST Cnt` needs (reached from `JMP
//! QuitFb` with `Cnt + 1` and from `LD ResetCounterValue` above it).
//! Ways that disagree, or a way that brings none, leave it unknown: the
//! instruction there must start with LD, and says why when it does not.
//! A jump back to a label whose instruction used the current result
//! must bring that type too (it is refused at the jump otherwise). When
//! the current result at that label is a run of untyped literals, its
//! type is the one the run settles to, maybe many lines later: such
//! jumps are checked once every line is read.

use std::collections::HashMap;

use super::flex::{becomes, Flex, Flow, Pending};
use super::said::{self, Said};
use super::{Errors, LoadError, Program, Step, TypeWhy};
use crate::error::Located;
use crate::iec::data::DataType;
use crate::iec::il::{Line, Operator};

/// The current result one way brings to a label.
struct Way {
    cr: Option<DataType>,
    flex: Pending,
}

/// What a label passed went on with: a type, or a run of untyped
/// literals (one of them: the type they all settle to is known once
/// every line is read).
#[derive(Clone, Copy)]
enum Held {
    Typed(DataType),
    Run(Flex),
}

/// A label passed whose instruction used the current result: what it
/// held, its name and its instruction's line.
struct Passed {
    held: Held,
    label: String,
    at: usize,
}

/// A jump back to a label that held a run: its step, what it brings and
/// its line, checked once the run has its type.
struct Back {
    target: usize,
    way: Way,
    line: usize,
}

/// The jumps read so far: what they bring to each label below them, the
/// labels above, and the jumps back checked at the end.
#[derive(Default)]
struct Jumps {
    ways: HashMap<usize, Vec<Way>>,
    passed: HashMap<usize, Passed>,
    back: Vec<Back>,
}

/// Whether `line` uses the current result it is given (an LD or an
/// unconditional JMP, RET or CAL does not).
fn uses_result(line: &Line) -> bool {
    match line.operator {
        Operator::Ld => false,
        Operator::Jmp | Operator::Ret | Operator::Cal => line.condition.is_some(),
        _ => true,
    }
}

impl Program {
    /// Resolves `lines` into steps (their labels numbered from the first
    /// step they get); every error into `errors` at its line.
    pub(super) fn compile_lines(&mut self, lines: &[Line], errors: &mut Errors) {
        let base = self.steps.len();
        let mut flow = Flow::default();
        let labels: HashMap<String, usize> = lines
            .iter()
            .enumerate()
            .filter_map(|(i, l)| Some((l.label.as_ref()?.to_ascii_uppercase(), base + i)))
            .collect();
        let mut jumps = Jumps::default();
        let mut falls = true;
        for (i, line) in lines.iter().enumerate() {
            if line.label.is_some() || line.operator == Operator::Ld {
                flow.refused = false;
            }
            let mut disagree = None;
            if let Some(label) = &line.label {
                let mut came = jumps.ways.remove(&(base + i)).unwrap_or_default();
                if falls {
                    let flex = std::mem::take(&mut flow.flex);
                    came.push(Way { cr: flow.cr, flex });
                }
                disagree = self.meet(&mut flow, came, label);
                let held = match flow.flex.first() {
                    Some(f) => flow.cr.map(|_| Held::Run(f)),
                    None => flow.cr.map(Held::Typed),
                };
                if let (Some(held), true) = (held, uses_result(line)) {
                    let (label, at) = (label.clone(), line.line);
                    jumps.passed.insert(base + i, Passed { held, label, at });
                }
            }
            // What a jump brings (its literals for jumps alone: a long
            // run of them is not copied at every line). An unconditional
            // JMP ends the current result, so it hands its literals on
            // (a run through `JMP l` / `l: ADD 1` is never copied); a
            // JMPC has a BOOL, none.
            let before = Way {
                cr: flow.cr,
                flex: match (line.operator, line.condition) {
                    (Operator::Jmp, None) => std::mem::take(&mut flow.flex),
                    (Operator::Jmp, Some(_)) => flow.flex.clone(),
                    _ => Pending::default(),
                },
            };
            let resolved = self.resolve(line, &labels, &mut flow).and_then(|step| {
                if let Step::Jmp(_, target) = step {
                    self.arrive(target, before, line.line, &mut jumps, &mut flow.late)?;
                }
                Ok(step)
            });
            match resolved {
                Ok(step) => self.steps.push(step),
                Err(e) => {
                    let e = match (e, disagree) {
                        (LoadError::UnknownResult, Some(why)) => why,
                        (e, _) => e,
                    };
                    // After a refused line the current result is not
                    // known: the lines that use it are not refused again
                    // for that (no cascade), until an LD or a label.
                    if !(flow.refused && e == LoadError::UnknownResult) {
                        errors.push(Located::new(line.line, e));
                    }
                    flow.refused = true;
                    flow.cr = None;
                    flow.flex.clear();
                    self.steps.push(Step::Ret(None));
                }
            }
            falls =
                !matches!(line.operator, Operator::Jmp | Operator::Ret) || line.condition.is_some();
        }
        // Each `(` never closed, at its own line.
        for open in &flow.open {
            errors.push(Located::new(open.line, LoadError::Unclosed));
        }
        self.check_back(jumps, errors, &mut flow.late);
        said::after(errors, flow.late);
    }

    /// The jumps back to a label that held a run of untyped literals,
    /// checked against the type the run settled to: a literal the jump
    /// brings that does not fit it is refused at its line.
    fn check_back(&mut self, jumps: Jumps, errors: &mut Errors, late: &mut Said) {
        for back in jumps.back {
            let Some(passed) = jumps.passed.get(&back.target) else {
                continue;
            };
            let Held::Run(f) = passed.held else {
                continue;
            };
            // None only for a literal whose place is gone: nothing to check.
            let Some(t) = self.written(&f) else {
                continue;
            };
            if let Err(e) = self.brings(t, passed, back.way, late) {
                errors.push(Located::new(back.line, e));
            }
        }
    }

    /// A jump to step `target` bringing `way`: kept for a label below,
    /// checked against what a label above went on with (its untyped
    /// literals taken at that type, each that does not fit into `late`),
    /// or, when that was a run of untyped literals, kept to be checked
    /// against the type the run settles to.
    fn arrive(
        &mut self,
        target: usize,
        way: Way,
        line: usize,
        jumps: &mut Jumps,
        late: &mut Said,
    ) -> Result<(), LoadError> {
        if target >= self.steps.len() {
            jumps.ways.entry(target).or_default().push(way);
            return Ok(());
        }
        let Some(passed) = jumps.passed.get(&target) else {
            return Ok(());
        };
        match passed.held {
            Held::Typed(t) => self.brings(t, passed, way, late),
            Held::Run(_) => {
                jumps.back.push(Back { target, way, line });
                Ok(())
            }
        }
    }

    /// Whether `way` brings a `t`, as the label `passed` went on with:
    /// its untyped literals taken at `t`, each that does not fit into
    /// `late`.
    fn brings(
        &mut self,
        t: DataType,
        passed: &Passed,
        mut way: Way,
        late: &mut Said,
    ) -> Result<(), LoadError> {
        if !way.flex.is_empty() {
            let mut f = Flow {
                cr: way.cr,
                flex: std::mem::take(&mut way.flex),
                ..Flow::default()
            };
            self.settle(&mut f, t);
            // A literal that does not fit is refused at its line, as
            // everywhere (it was dropped here, and loaded).
            late.append(&mut f.late);
            way.cr = f.cr;
        }
        if way.cr == Some(t) {
            return Ok(());
        }
        Err(LoadError::Type(TypeWhy::JumpBrings {
            line: passed.at,
            label: passed.label.clone(),
            used: t,
            brings: way.cr,
        }))
    }

    /// The current result at a label, from what `came` there; why the
    /// ways disagree, when they do.
    fn meet(&mut self, flow: &mut Flow, came: Vec<Way>, label: &str) -> Option<LoadError> {
        flow.cr = None;
        flow.flex.clear();
        if came.is_empty() || came.iter().any(|w| w.cr.is_none()) {
            return None;
        }
        let mut typed = came
            .iter()
            .filter(|w| w.flex.is_empty())
            .filter_map(|w| w.cr);
        let Some(t) = typed.next() else {
            // Untyped literals every way: they wait together for a use.
            let ways = came.into_iter().map(|w| w.flex).collect();
            flow.flex = self.merge(ways, &mut flow.late);
            flow.cr = Some(flow.flex.at());
            return None;
        };
        let untyped = came.iter().find(|w| !w.flex.is_empty() && !becomes(t));
        let other = typed.find(|&u| u != t).or(untyped.and_then(|w| w.cr));
        if let Some(u) = other {
            return Some(LoadError::Type(TypeWhy::LabelTypes {
                label: label.to_string(),
                types: (t, u),
            }));
        }
        for w in came.into_iter().filter(|w| !w.flex.is_empty()) {
            let mut f = Flow {
                cr: w.cr,
                flex: w.flex,
                ..Flow::default()
            };
            self.settle(&mut f, t);
            flow.late.append(&mut f.late);
        }
        flow.cr = Some(t);
        None
    }
}
