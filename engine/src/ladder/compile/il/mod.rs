//! Compiling to the soft PLC's Instruction List. IL has what ladders
//! need: a series is `LD` then `AND`s, a parallel `LD` then `OR`s, and a
//! group inside either is deferred with `AND(` … `)` / `OR(` … `)`, so no
//! temporary relay is needed for logic. In-line boxes take the power
//! that reaches them: it is stored in a generated BOOL, the block called
//! with it (`CAL t(IN := p, PT := T#500ms, Q => q)`) and its output
//! loaded. Edge contacts are R_TRIG / F_TRIG instances called at the
//! rung's start. Every name the ladder uses is declared BOOL in the
//! header; addresses (`%IX0.0`) need no declaration.

mod blocks;

use std::collections::{BTreeSet, HashMap};

use super::accumulator::one_line;
use super::{is_pure, used_devices, Mapped};
use crate::iec::data::DataType;
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{LadderError, Pos};
use crate::ladder::net::{Net, RungLogic};
use crate::ladder::variables::Variable;

/// Where the power into a network comes from.
#[derive(Clone, Debug, PartialEq)]
enum Pin {
    /// The left rail: always on.
    Rail,
    /// The current result holds it.
    Current,
    /// A generated BOOL holds it.
    Held(String),
}

struct Compiler {
    /// Declarations of the header (`name : TYPE;`).
    vars: Vec<String>,
    /// The `VAR_RETAIN` ones.
    retained: Vec<String>,
    /// Each declared name's (upper-case) type, and each located
    /// variable's address (as IEC writes it).
    types: HashMap<String, DataType>,
    /// Block instances (upper-case) and their kinds.
    blocks: HashMap<String, String>,
    /// The IL lines.
    lines: Vec<String>,
    /// Names the ladder uses, and those generated (never given twice).
    taken: BTreeSet<String>,
    /// Timer instances declared (upper-case).
    instances: BTreeSet<String>,
    rung_index: usize,
    /// (rung, leaf's cell, index in `lines` of the op reading it).
    sources: Vec<(usize, Pos, usize)>,
}

/// Compiles checked rung logic for the soft PLC with the ladder's
/// declared `variables`; `load` says what the machine finds wrong in the
/// text (each problem's 1-based line and message), for [`loads`].
pub(crate) fn compile_mapped(
    rungs: &[RungLogic],
    variables: &[Variable],
    load: &dyn Fn(&str) -> Vec<(usize, String)>,
) -> Result<Mapped, Vec<LadderError>> {
    let used = used_devices(rungs);
    let mut c = Compiler {
        vars: Vec::new(),
        retained: Vec::new(),
        types: HashMap::new(),
        blocks: HashMap::new(),
        lines: Vec::new(),
        taken: used.iter().map(|d| d.to_ascii_uppercase()).collect(),
        instances: BTreeSet::new(),
        rung_index: 0,
        sources: Vec::new(),
    };
    let mut errors = c.declare(variables);
    for name in used.iter().filter(|d| !d.starts_with('%')) {
        if !c.types.contains_key(&name.to_ascii_uppercase()) {
            c.vars.push(format!("{name} : BOOL;"));
            c.types.insert(name.to_ascii_uppercase(), DataType::Bool);
        }
    }
    for r in rungs {
        for (e, _) in r.condition.leaves() {
            if let Element::Timer { name, .. } = e {
                c.taken.insert(name.to_ascii_uppercase());
            }
        }
    }
    let mut starts = Vec::with_capacity(rungs.len());
    let mut first_lines = Vec::with_capacity(rungs.len());
    for (i, logic) in rungs.iter().enumerate() {
        c.rung_index = i;
        starts.push(c.steps());
        first_lines.push(c.lines.len());
        if !logic.comment.is_empty() {
            c.lines.push(format!(
                "(* {} *)",
                one_line(&logic.comment).replace("*)", "* )")
            ));
        }
        c.sides(logic, i, &mut errors);
        if let Err((pos, m)) = c.rung(logic) {
            errors.push(LadderError::at(i, pos, m));
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let mut text = String::from("(* compiled by hashigo from a ladder *)\n");
    text.push_str(&crate::iec::listing::var_blocks(&c.vars, &c.retained));
    let header = text.lines().count();
    for l in &c.lines {
        text.push_str(l);
        text.push('\n');
    }
    let sources: Vec<(usize, Pos, usize)> = c
        .sources
        .into_iter()
        .map(|(r, p, line)| (r, p, line + header))
        .collect();
    let first_lines: Vec<usize> = first_lines.into_iter().map(|l| l + header).collect();
    loads(load(&text), &first_lines, &sources)?;
    Ok(Mapped {
        text,
        starts,
        sources,
    })
}

/// What the soft PLC says of the compiled `text` when it loads it (a
/// type that does not fit: ADD on a BOOL), each error at the cell whose
/// code holds its line: the first leaf of that line's rung at or after
/// it (a box's source line follows its code), else the rung.
fn loads(
    errors: Vec<(usize, String)>,
    first_lines: &[usize],
    sources: &[(usize, Pos, usize)],
) -> Result<(), Vec<LadderError>> {
    if errors.is_empty() {
        return Ok(());
    }
    Err(errors
        .into_iter()
        .map(|(line, message)| {
            let line = line.saturating_sub(1);
            let rung = first_lines
                .partition_point(|l| *l <= line)
                .saturating_sub(1);
            match sources.iter().find(|(r, _, l)| *r == rung && *l >= line) {
                Some((_, pos, _)) => LadderError::at(rung, *pos, message),
                None => LadderError::rung(rung, message),
            }
        })
        .collect())
}

type RungResult = Result<(), (Pos, String)>;

impl Compiler {
    /// A box's inputs wired as networks (rung `i`'s): each computed into
    /// its BOOL before the rung.
    fn sides(&mut self, logic: &RungLogic, i: usize, errors: &mut Vec<LadderError>) {
        for side in &logic.sides {
            let own = side.as_rung();
            if let Err((pos, m)) = self.rung(&own) {
                errors.push(LadderError::at(i, pos, m));
            }
        }
    }

    /// Steps emitted so far (comments are not steps).
    fn steps(&self) -> usize {
        self.lines.iter().filter(|l| !l.starts_with("(*")).count()
    }

    fn emit(&mut self, line: String) {
        self.lines.push(line);
    }

    /// A fresh name `<stem><n>` declared as `t` (a BOOL or a block; a
    /// label when empty); generated stems start with `_`.
    fn fresh(&mut self, stem: &str, t: &str) -> String {
        let mut n = 0;
        loop {
            let name = format!("{stem}{n}");
            if self.taken.insert(name.to_ascii_uppercase()) {
                // A label (no type) is not declared.
                if !t.is_empty() {
                    self.vars.push(format!("{name} : {t};"));
                }
                return name;
            }
            n += 1;
        }
    }

    /// The rung's power in a BOOL: stored the first time it is asked for.
    fn hold(&mut self, held: &mut Option<String>) -> String {
        if let Some(p) = held {
            return p.clone();
        }
        let p = self.fresh("_p", "BOOL");
        self.emit(format!("ST {p}"));
        *held = Some(p.clone());
        p
    }

    fn rung(&mut self, logic: &RungLogic) -> RungResult {
        let cond = self.edges(&logic.condition);
        self.net(&cond, Pin::Rail)
            .map_err(|m| (logic.condition.first_pos(), m))?;
        // The power, held for pulse outputs (R_TRIG / F_TRIG on it) and
        // output boxes (which leave their own result).
        let mut held: Option<String> = None;
        for (e, pos) in &logic.outputs {
            if let Element::OutputBlock(b) = e {
                let power = self.hold(&mut held);
                self.block(b, *pos, Pin::Held(power.clone()))
                    .map_err(|m| (*pos, m))?;
                self.emit(format!("LD {power}"));
                continue;
            }
            if let Element::Pulse { falling, device } = e {
                let power = self.hold(&mut held);
                let block = if *falling { "F_TRIG" } else { "R_TRIG" };
                let trig = self.fresh("_edge", block);
                self.emit(format!("CAL {trig}(CLK := {power}, Q => {device})"));
                continue;
            }
            let Element::Coil { kind, device } = e else {
                return Err((*pos, format!("soft-plc ladders have no {e} output yet")));
            };
            let op = match kind {
                CoilKind::Normal => "ST",
                CoilKind::Inverted => "STN",
                CoilKind::Set => "S",
                CoilKind::Reset => "R",
            };
            self.emit(format!("{op} {device}"));
        }
        Ok(())
    }

    /// Every rising / falling contact becomes a NO contact on the Q of an
    /// R_TRIG / F_TRIG called on its device at the rung's start (the
    /// reference evaluator's edge memory sees the device every scan too).
    fn edges(&mut self, net: &Net) -> Net {
        match net {
            Net::Leaf(Element::Contact { kind, device }, p)
                if matches!(kind, ContactKind::Rising | ContactKind::Falling) =>
            {
                let block = if *kind == ContactKind::Rising {
                    "R_TRIG"
                } else {
                    "F_TRIG"
                };
                let trig = self.fresh("_edge", block);
                let q = self.fresh("_q", "BOOL");
                // The contact on `q` that replaces it is the leaf's step.
                self.emit(format!("CAL {trig}(CLK := {device}, Q => {q})"));
                Net::Leaf(Element::no(&q), *p)
            }
            Net::Leaf(..) => net.clone(),
            Net::Series(v) => Net::Series(v.iter().map(|n| self.edges(n)).collect()),
            Net::Parallel(v) => Net::Parallel(v.iter().map(|n| self.edges(n)).collect()),
        }
    }

    /// Emits `net` with the power `pin` at its left; its power out is
    /// then the current result.
    fn net(&mut self, net: &Net, pin: Pin) -> Result<(), String> {
        match net {
            Net::Leaf(e, pos) => self.leaf(e, *pos, pin),
            Net::Series(items) => {
                let mut pin = pin;
                for item in items {
                    self.net(item, pin)?;
                    pin = Pin::Current;
                }
                Ok(())
            }
            Net::Parallel(branches) => self.parallel(branches, pin),
        }
    }

    fn parallel(&mut self, branches: &[Net], pin: Pin) -> Result<(), String> {
        let pure = branches.iter().all(is_pure);
        match pin {
            // Contacts only, after a power held in the current result:
            // AND( the branches ).
            Pin::Current if pure => {
                self.emit("AND(".into());
                self.parallel(branches, Pin::Rail)?;
                self.emit(")".into());
                Ok(())
            }
            // A box in a branch needs the power at the branch's left.
            Pin::Current => {
                let held = self.fresh("_p", "BOOL");
                self.emit(format!("ST {held}"));
                self.parallel(branches, Pin::Held(held))
            }
            pin => {
                for (i, branch) in branches.iter().enumerate() {
                    if i == 0 {
                        self.net(branch, pin.clone())?;
                    } else if let (Some((device, inv)), Pin::Rail) = (super::contact(branch), &pin)
                    {
                        let pos = branch.first_pos();
                        self.sources.push((self.rung_index, pos, self.lines.len()));
                        self.emit(format!("OR{} {device}", if inv { "N" } else { "" }));
                    } else {
                        self.emit("OR(".into());
                        self.net(branch, pin.clone())?;
                        self.emit(")".into());
                    }
                }
                Ok(())
            }
        }
    }

    fn leaf(&mut self, e: &Element, pos: Pos, pin: Pin) -> Result<(), String> {
        if let Pin::Held(v) = &pin {
            self.emit(format!("LD {v}"));
        }
        let chained = pin != Pin::Rail;
        match e {
            Element::Contact { kind, device } => {
                let inv = if *kind == ContactKind::Nc { "N" } else { "" };
                let op = if chained { "AND" } else { "LD" };
                self.sources.push((self.rung_index, pos, self.lines.len()));
                self.emit(format!("{op}{inv} {device}"));
            }
            Element::Wire => {
                if !chained {
                    self.emit("LD TRUE".into());
                }
            }
            Element::Not => {
                if !chained {
                    self.emit("LD TRUE".into());
                }
                self.sources.push((self.rung_index, pos, self.lines.len()));
                self.emit("NOT".into());
            }
            Element::Edge { falling } => {
                let block = if *falling { "F_TRIG" } else { "R_TRIG" };
                let trig = self.fresh("_edge", block);
                self.call_on_power(&trig, "CLK", "", chained, pos)?;
            }
            Element::Timer {
                kind,
                name,
                preset_ms,
            } => {
                let block = match kind {
                    TimerKind::Ton => "TON",
                    TimerKind::Tof => "TOF",
                    TimerKind::Tp => "TP",
                };
                // Each box is a timer of its own (as on the AVR PLC): a
                // name drawn twice gets a second instance.
                // A name the ladder declares as this timer is that one.
                let upper = name.to_ascii_uppercase();
                let declared = self.blocks.get(&upper).is_some_and(|k| k == block);
                let instance = if self.instances.insert(upper) {
                    if !declared {
                        self.vars.push(format!("{name} : {block};"));
                    }
                    name.clone()
                } else {
                    self.fresh(&format!("{name}_"), block)
                };
                let pt = format!(", PT := T#{preset_ms}ms");
                self.call_on_power(&instance, "IN", &pt, chained, pos)?;
            }
            Element::Block(b) => {
                let power = if chained { Pin::Current } else { Pin::Rail };
                self.block(b, pos, power)?
            }
            other => return Err(format!("{other} cannot stand in a soft-plc rung")),
        }
        Ok(())
    }

    /// Calls block `block` with the power in (`chained`: the current
    /// result; else the rail) at input `input`, then loads its Q.
    fn call_on_power(
        &mut self,
        block: &str,
        input: &str,
        more: &str,
        chained: bool,
        pos: Pos,
    ) -> Result<(), String> {
        let power = if chained {
            let p = self.fresh("_p", "BOOL");
            self.emit(format!("ST {p}"));
            p
        } else {
            "TRUE".to_string()
        };
        let q = self.fresh("_q", "BOOL");
        self.emit(format!("CAL {block}({input} := {power}{more}, Q => {q})"));
        // The box's step is the one that leaves its output.
        self.sources.push((self.rung_index, pos, self.lines.len()));
        self.emit(format!("LD {q}"));
        Ok(())
    }
}
