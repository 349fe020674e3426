//! An LDmicro file as a soft PLC ladder (issue #32; docs/ldmicro.md):
//! its rungs drawn ([`super::lower`]), its names declared — `X…` inputs
//! on the board's `%IX` switches and `Y…` outputs on its `%QX` lamps in
//! the order of the file's `IO LIST`, other bits as BOOLs, every number
//! a DINT, each timer's and counter's element an instance of LDmicro's
//! block ([`crate::runtime::ldmicro`]).

use std::collections::{BTreeMap, HashMap};

use super::element::{is_number, Element as Ld};
use super::elements::{part, word_op, OPEN};
use super::error::LdError;
use super::file::LdFile;
use super::lower::{Lowering, MCR};
use super::parts::{operand, Part};
use super::roles::{conflicts, roles, Role};
use crate::error::Located;
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::net::{try_layout, Net, RungLogic};
use crate::ladder::variables::Variable;
use crate::ladder::BlockCall;

/// The file as a soft PLC ladder; every element it cannot run is an
/// error at its line, and then nothing is made.
pub fn to_ladder(file: &LdFile) -> Result<Ladder, Vec<Located<LdError>>> {
    made(file).map(|(ladder, _)| ladder)
}

/// What compiling `file`'s ladder refused (`errors`, at its rungs and
/// cells), each at the line of the LDmicro rung its rung came from —
/// never at a rung number or cell the file does not have.
pub fn locate(file: &LdFile, errors: Vec<LadderError>) -> Vec<Located<LdError>> {
    let lines = made(file).map(|(_, lines)| lines).unwrap_or_default();
    errors
        .into_iter()
        .map(|e| {
            let line = e
                .rung
                .checked_sub(1)
                .and_then(|k| lines.get(k))
                .or(lines.first())
                .copied()
                .unwrap_or(1);
            Located::new(line, LdError::SoftPlc(e.message))
        })
        .collect()
}

/// The ladder, and the line of the LDmicro rung each of its rungs came
/// from.
fn made(file: &LdFile) -> Result<(Ladder, Vec<usize>), Vec<Located<LdError>>> {
    let (file, renamed) = &iec_names(file);
    // Names used as two things and every element's own error: every
    // error of the file at once, in line order, before any rung is
    // drawn (so that no refused element causes another error there).
    let mut errors = conflicts(file, renamed);
    let mut probe = Making::new(file);
    for (e, line) in file.elements() {
        if let Err(err) = probe.element(e) {
            errors.push(Located::new(line, err));
        }
    }
    if !errors.is_empty() {
        errors.sort_by_key(|e| e.line);
        return Err(errors);
    }
    let mut making = Making::new(file);
    let mut element = |e: &Ld| making.element(e);
    let mut lowering = Lowering {
        rungs: Vec::new(),
        held: 0,
        comment: String::new(),
        element: &mut element,
    };
    let mut errors = Vec::new();
    // A file with a master relay: it is on at each scan's start, and each
    // rung's power comes through it.
    let master = file.elements().any(|(e, _)| matches!(e, Ld::MasterRelay));
    let start = master.then(|| Net::Leaf(Element::no(MCR), Pos::new(0, 0)));
    if master {
        lowering.rungs.push((relay_on(), 1));
    }
    for rung in &file.rungs {
        if let Err(e) = lowering.series(&rung.series, start.clone(), true) {
            errors.extend(e);
        }
    }
    let leftover = std::mem::take(&mut lowering.comment);
    let rungs = std::mem::take(&mut lowering.rungs);
    if !errors.is_empty() {
        return Err(errors);
    }
    let (rungs, lines) = drawn(rungs, leftover)?;
    let mut ladder = Ladder {
        rungs,
        ..Ladder::default()
    };
    ladder.variables = declarations(file, &making.instances);
    // An always-on rung's coil stands on `_OPEN`'s closed contact.
    let open_used = ladder
        .rungs
        .iter()
        .any(|r| r.elements().any(|(_, e)| e.read_device() == Some(OPEN)));
    if open_used && !ladder.variables.iter().any(|v| v.name == OPEN) {
        let mut v = Variable::new(OPEN, "BOOL");
        v.comment = "LDmicro's OPEN: never on".into();
        ladder.variables.push(v);
    }
    if master && !ladder.variables.iter().any(|v| v.name == MCR) {
        ladder.variables.push(Variable::new(MCR, "BOOL"));
    }
    if let Some(v) = ladder.variables.iter_mut().find(|v| v.name == MCR) {
        v.comment = "LDmicro's master relay".into();
    }
    for v in &mut ladder.variables {
        if let Some(original) = renamed.get(&v.name) {
            let was = format!("LDmicro name: {original}");
            v.comment = if v.comment.is_empty() {
                was
            } else {
                format!("{was}; {}", v.comment)
            };
        }
    }
    Ok((ladder, lines))
}

/// The rung that turns LDmicro's master relay on at each scan's start
/// (on `_OPEN`'s closed contact: always).
fn relay_on() -> RungLogic {
    RungLogic {
        condition: Net::Leaf(Element::nc(OPEN), Pos::new(0, 0)),
        outputs: vec![(Element::coil(MCR), Pos::new(0, 0))],
        comment: String::new(),
        sides: Vec::new(),
    }
}

/// Drawn rungs and the line each came from.
type Drawn = (Vec<crate::ladder::grid::Rung>, Vec<usize>);

/// The rungs drawn on grids, with the line each came from, a comment
/// left after the last rung going to it.
fn drawn(rungs: Vec<(RungLogic, usize)>, leftover: String) -> Result<Drawn, Vec<Located<LdError>>> {
    let mut out = Vec::new();
    let mut lines = Vec::new();
    let mut errors = Vec::new();
    for (logic, line) in rungs {
        match try_layout(&logic) {
            Ok(r) => {
                out.push(r);
                lines.push(line);
            }
            Err(size) => errors.push(Located::new(line, LdError::Drawing(size.to_string()))),
        }
    }
    if let (Some(last), false) = (out.last_mut(), leftover.is_empty()) {
        if !last.comment.is_empty() {
            last.comment.push('\n');
        }
        last.comment.push_str(&leftover);
    }
    if errors.is_empty() {
        Ok((out, lines))
    } else {
        Err(errors)
    }
}

/// What making the ladder keeps between elements: counters' starts, the
/// analog I/O given out, the instances named.
struct Making {
    counters: HashMap<String, String>,
    cycle: u64,
    analog: Vec<String>,
    pwm: Vec<String>,
    /// Instance names given, by stem (upper case), and how many times.
    taken: HashMap<String, usize>,
    /// Each block instance and its kind.
    instances: BTreeMap<String, String>,
    /// The `VAR LIST`'s sizes in bytes.
    sizes: HashMap<String, u16>,
}

impl Making {
    /// Ready for `file`'s elements.
    fn new(file: &LdFile) -> Making {
        // An instance never takes a name the file uses (`T1_ld` of TON T1
        // beside a variable `T1_ld`): it gets the next number.
        let taken = roles(file)
            .into_iter()
            .map(|(name, _)| (name.to_ascii_uppercase(), 1))
            .collect();
        Making {
            counters: counter_starts(file),
            cycle: file.cycle_us,
            analog: Vec::new(),
            pwm: Vec::new(),
            taken,
            instances: BTreeMap::new(),
            sizes: file
                .vars
                .iter()
                .map(|v| (v.name.clone(), v.bytes))
                .collect(),
        }
    }

    /// Element `e` as the soft PLC has it.
    fn element(&mut self, e: &Ld) -> Result<Part, LdError> {
        if let Some(p) = hardware_io(e, &mut self.analog, &mut self.pwm) {
            return p;
        }
        if let Ld::MasterRelay = e {
            return Ok(Part::Output(Element::coil(MCR)));
        }
        if let Ld::Res(name) = e {
            // A count back to its start: a counter's, else 0.
            let start = self
                .counters
                .get(name)
                .cloned()
                .unwrap_or_else(|| "0".into());
            let call = BlockCall {
                kind: "MOVE".into(),
                instance: String::new(),
                inputs: vec![("IN".into(), start)],
                outputs: vec![("OUT".into(), name.clone())],
            };
            return Ok(Part::Output(Element::OutputBlock(call)));
        }
        let taken = &mut self.taken;
        let mut instance = |name: &str| {
            let stem = format!("{}_ld", name.trim_matches('_'));
            let n = taken.entry(stem.to_ascii_uppercase()).or_default();
            *n += 1;
            if *n == 1 {
                stem
            } else {
                format!("{stem}{n}")
            }
        };
        let sizes = &self.sizes;
        let bits = |name: &str| sizes.get(name).copied().unwrap_or(2).min(4);
        let p = match word_op(e, &bits, &mut instance) {
            Some(p) => p,
            None => part(e, self.cycle, &mut instance),
        }
        .map_err(|err| match err {
            // An operand's number is said as its element's.
            LdError::BadNumber { text, .. } => LdError::BadNumber {
                element: e.keyword().into(),
                text,
            },
            other => other,
        })?;
        let block = match &p {
            Part::Condition(Element::Block(b)) | Part::Output(Element::OutputBlock(b)) => Some(b),
            _ => None,
        };
        if let Some(b) = block.filter(|b| !b.instance.is_empty()) {
            self.instances.insert(b.instance.clone(), b.kind());
        }
        Ok(p)
    }
}

/// The file with every name that is no IEC name (`Cnew1__`, `#PORTB`)
/// given one (`Cnew1_1`), and what each new name was.
fn iec_names(file: &LdFile) -> (LdFile, HashMap<String, String>) {
    use crate::iec::is_identifier;
    let mut file = file.clone();
    // Every name, and those to give new ones in sorted order: the same
    // file, written out and read again, gives the same names.
    let mut taken: std::collections::HashSet<String> = std::collections::HashSet::new();
    let mut odd: std::collections::BTreeSet<String> = std::collections::BTreeSet::new();
    let io = file.io.iter().map(|i| i.name.clone());
    let ops = file.elements().flat_map(|(e, _)| {
        e.clone()
            .operands_mut()
            .into_iter()
            .map(|o| o.clone())
            .collect::<Vec<_>>()
    });
    for op in io.chain(ops) {
        if is_identifier(&op) {
            taken.insert(op.to_ascii_uppercase());
        } else if !op.is_empty() && !is_number(&op) {
            odd.insert(op);
        }
    }
    let mut map: HashMap<String, String> = HashMap::new();
    let mut given: HashMap<String, String> = HashMap::new();
    for op in odd {
        let mut stem: String = op
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        while stem.contains("__") {
            stem = stem.replace("__", "_");
        }
        let stem = stem.trim_end_matches('_');
        let stem = if stem.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
            stem.to_string()
        } else {
            format!("v{stem}")
        };
        let mut k = 1;
        let mut name = format!("{stem}_{k}");
        while !taken.insert(name.to_ascii_uppercase()) {
            k += 1;
            name = format!("{stem}_{k}");
        }
        given.insert(name.clone(), op.clone());
        map.insert(op, name);
    }
    let rename = |op: &mut String| {
        if let Some(n) = map.get(op.as_str()) {
            *op = n.clone();
        }
    };
    for rung in &mut file.rungs {
        let mut todo: Vec<&mut super::Node> = rung.series.iter_mut().collect();
        while let Some(n) = todo.pop() {
            match n {
                super::Node::Leaf(e, _) => e.operands_mut().into_iter().for_each(rename),
                super::Node::Series(v, _) | super::Node::Parallel(v, _) => {
                    todo.extend(v.iter_mut())
                }
            }
        }
    }
    for io in &mut file.io {
        rename(&mut io.name);
    }
    (file, given)
}

/// The I/O LDmicro's hardware elements use, on the soft PLC's board:
/// `READ_ADC Ain` reads the next analog input (`%IW0`, a 10-bit slider)
/// into `Ain` when its power comes; `SET_PWM duty f` writes the duty to
/// the next analog output (`%QW0`, a gauge); `PERSIST saved` draws
/// nothing (its variable is kept over a power cycle: RETAIN).
fn hardware_io(
    e: &Ld,
    analog: &mut Vec<String>,
    pwm: &mut Vec<String>,
) -> Option<Result<Part, LdError>> {
    let slot = |list: &mut Vec<String>, name: &str| match list.iter().position(|n| n == name) {
        Some(k) => k,
        None => {
            list.push(name.to_string());
            list.len() - 1
        }
    };
    let convert = |kind: &str, from: String, to: String| {
        Part::Condition(Element::Block(BlockCall {
            kind: kind.into(),
            instance: String::new(),
            inputs: vec![("IN".into(), from)],
            outputs: vec![("OUT".into(), to)],
        }))
    };
    Some(match e {
        Ld::ReadAdc { name, .. } => {
            let k = slot(analog, name);
            Ok(convert("INT_TO_DINT", format!("%IW{k}"), name.clone()))
        }
        Ld::SetPwm { duty, name, .. } => {
            let key = if name.is_empty() { "P" } else { name.as_str() };
            let k = slot(pwm, key);
            operand(duty).map(|d| convert("DINT_TO_INT", d, format!("%QW{k}")))
        }
        Ld::Persist(_) => Ok(Part::Nothing),
        _ => return None,
    })
}

/// Each counter's start, as a `RES` of it sets it back (the first
/// counter element of that name gives it).
fn counter_starts(file: &LdFile) -> HashMap<String, String> {
    let mut out = HashMap::new();
    for (e, _) in file.elements() {
        if let Ld::Counter { name, init, .. } = e {
            if let Ok(start) = operand(init) {
                out.entry(name.clone()).or_insert(start);
            }
        }
    }
    out
}

/// The ladder's variables: bits and numbers the elements name, the
/// blocks' instances.
fn declarations(file: &LdFile, instances: &BTreeMap<String, String>) -> Vec<Variable> {
    let roles = roles(file);
    let persist: std::collections::HashSet<&str> = file
        .elements()
        .filter_map(|(e, _)| match e {
            Ld::Persist(p) => Some(p.as_str()),
            _ => None,
        })
        .collect();
    let io: HashMap<&str, &str> = file
        .io
        .iter()
        .map(|i| (i.name.as_str(), i.rest.as_str()))
        .collect();
    let notes: HashMap<&str, &str> = file
        .vars
        .iter()
        .filter(|v| !v.note.is_empty())
        .map(|v| (v.name.as_str(), v.note.as_str()))
        .collect();
    let (mut inputs, mut outputs) = (0usize, 0usize);
    let mut out = Vec::new();
    for (name, role) in roles {
        let data_type = match role {
            Role::Bit => "BOOL",
            Role::Number => "DINT",
            Role::Text => "STRING",
        };
        let mut v = Variable::new(&name, data_type);
        if role == Role::Bit && name.starts_with('X') {
            v.address = format!("%IX{}.{}", inputs / 8, inputs % 8);
            inputs += 1;
        } else if role == Role::Bit && name.starts_with('Y') {
            v.address = format!("%QX{}.{}", outputs / 8, outputs % 8);
            outputs += 1;
        }
        if let Some(rest) = io.get(name.as_str()) {
            v.comment = format!("LDmicro pin: {rest}");
        }
        if let Some(note) = notes.get(name.as_str()) {
            v.comment = note.to_string();
        }
        if name == OPEN {
            v.comment = "LDmicro's OPEN: never on".into();
        }
        v.retain = persist.contains(name.as_str());
        out.push(v);
    }
    let names: std::collections::HashSet<String> =
        out.iter().map(|v| v.name.to_ascii_uppercase()).collect();
    for (instance, kind) in instances {
        if !names.contains(&instance.to_ascii_uppercase()) {
            out.push(Variable::new(instance, kind));
        }
    }
    out
}
