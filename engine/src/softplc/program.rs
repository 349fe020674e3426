//! A soft PLC program loaded and running: its IL resolved against its
//! declarations into steps over one table of values, type-checked once
//! at load (nothing is checked while it runs), and its scan.

use std::collections::HashMap;

use crate::error::Located;
use crate::iec::address::{Address, Area};
use crate::iec::data::{Arith, Bitwise, Data, DataType};
use crate::iec::il::{parse_il, Function, IlError, Line, Operand, Operator};
use crate::iec::literal::string_value;
use crate::iec::vars::{parse_vars_at, Kind, VarError, Variable};
use crate::iec::Comparison;
use crate::runtime::instance::Instance;
use check::{binary_type, describe, invertible, jump, need_cr};
use element::is_element_line;
use flex::{Flex, Flow, Open, Pending};

/// Instructions one scan may run before it is cut short (a backward JMP
/// that never ends): the scan ends there and [`Program::overran`] says so.
pub const STEPS_PER_SCAN: usize = 1_000_000;

/// Where an operand's value comes from.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Src {
    Slot(usize),
    Const(Data),
}

/// An operation that works on the current result and an operand.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Binary {
    Logic(Bitwise, bool),
    Arith(Arith),
    Cmp(Comparison),
}

/// One resolved instruction.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Step {
    Ld(Src, bool),
    St(usize, bool),
    Set(usize),
    Reset(usize),
    Not,
    Binary(Binary, Src),
    /// `OP(`: the operation waits, with the current result, for `)`; the
    /// new current result is the operand's, if it has one.
    Open(Binary, Option<Src>),
    Close,
    /// A standard function of the current result and its operands.
    Func(Function, Vec<Src>),
    Jmp(Option<bool>, usize),
    /// LD, ST of an element at a run-time index ([`element`]).
    LdAt(Box<element::Element>, bool),
    StAt(Box<element::Element>),
    Ret(Option<bool>),
    Cal {
        when: Option<bool>,
        block: usize,
        inputs: Vec<(usize, Src)>,
        outputs: Vec<(usize, usize)>,
    },
    /// A call of an instance of the program's own function block: its
    /// inputs copied in, its body run, its outputs copied out.
    CallUser {
        when: Option<bool>,
        instance: usize,
        inputs: Vec<(usize, Src)>,
        outputs: Vec<(usize, usize)>,
    },
    /// The end of a function block's body: back to its caller.
    Return,
}

/// Why a program does not load.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LoadError {
    Var(VarError),
    Il(IlError),
    /// A name no declaration gives.
    Undeclared(String),
    /// A byte address used without a declaration (no type is a byte).
    UntypedAddress(String),
    /// A JMP to a label no line has.
    NoLabel(String),
    /// The instruction needs a current result or an operand of a type
    /// it does not have.
    Type(TypeWhy),
    /// A call that does not fit: what is called, its texts, the
    /// program's own blocks' limits.
    Call(CallWhy),
    /// An instruction that needs the current result where it is not
    /// known (after a label or a jump).
    UnknownResult,
    /// A `)` with no `(`.
    Unbalanced,
    /// A `(` never closed (at its line).
    Unclosed,
    /// The function blocks' sections do not pair.
    Pou(super::pou::PouError),
    /// Two types where one is needed (convert one, `*_TO_*`).
    Mix(DataType, DataType),
    /// An inversion (the operator, as written) of a type that has no bits.
    NotBits(String, DataType),
    /// An operation that does not apply to the type.
    NotFor(DataType),
    /// A conditional instruction (CALC, JMPC, RETC) after a non-BOOL.
    NeedsBool(&'static str),
    /// A block (its type) without that parameter (as written): an
    /// output when `output`, else an input.
    NoPin {
        block: String,
        pin: String,
        output: bool,
    },
    /// A CAL of a name that is not a block instance.
    NotAnInstance(String),
    /// An element operand (`a[i:1:3:1]`) that does not fit: elsewhere
    /// than LD or ST, or reaching slots of other types.
    BadElement(String),
}

impl std::error::Error for LoadError {}

/// A loaded program with its values.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Every value: declared variables, then undeclared bit addresses.
    pub(super) values: Vec<Data>,
    pub(super) initial: Vec<Data>,
    pub(super) names: Vec<(String, usize)>,
    pub(super) addresses: Vec<(Address, usize)>,
    /// What the inputs' terminals give, read at each scan's start.
    pub(super) input_terminals: Vec<(usize, Data)>,
    pub(super) blocks: Vec<Instance>,
    pub(super) block_names: Vec<(String, String)>,
    pub(super) steps: Vec<Step>,
    pub(super) overran: bool,
    /// The step an index outside its array stopped the last scan at.
    pub(super) fault: Option<usize>,
    /// The slots declared in VAR_RETAIN.
    pub(super) retained: Vec<usize>,
    /// The text as read, for the listing.
    pub(super) vars: Vec<Variable>,
    pub(super) lines: Vec<Line>,
    /// Names (upper-case) to their slot or block, addresses to their
    /// slot: every look-up at load and from the front ends is one hash.
    pub(super) by_name: HashMap<String, Named>,
    pub(super) by_address: HashMap<Address, usize>,
    /// The program's own function blocks, their instances, and where
    /// each instance's body starts among the steps.
    pub(super) user_types: Vec<user::UserType>,
    pub(super) instances: Vec<user::UserInstance>,
    pub(super) entries: Vec<usize>,
    /// The serial port LDmicro's UART blocks use.
    pub(super) uart: crate::runtime::uart::Uart,
    /// The standard blocks' outputs read as operands: (block, output,
    /// the slot each call writes it to).
    pub(super) shadows: Vec<(usize, usize, usize)>,
    /// A Structured Text program's place (line, column) of each step.
    pub(super) st_places: Vec<(u32, u32)>,
}

/// What a declared name is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Named {
    Slot(usize),
    Block(usize),
    /// An instance of the program's own function block.
    User(usize),
}

type Errors = Vec<Located<LoadError>>;

impl Program {
    /// Loads `text` (VAR blocks, then IL). Every error at its line.
    pub fn load(text: &str) -> Result<Program, Errors> {
        let sections = super::pou::split(text).map_err(|es| {
            es.into_iter()
                .map(|e| Located::new(e.line, LoadError::Pou(e.error)))
                .collect::<Errors>()
        })?;
        let types: Vec<String> = sections.blocks.iter().map(|b| b.name.clone()).collect();
        let (vars, lines) = read(&sections.program, &types)?;
        let mut p = Program {
            values: Vec::new(),
            initial: Vec::new(),
            names: Vec::new(),
            addresses: Vec::new(),
            input_terminals: Vec::new(),
            blocks: Vec::new(),
            block_names: Vec::new(),
            steps: Vec::new(),
            overran: false,
            fault: None,
            retained: Vec::new(),
            vars: Vec::new(),
            lines: Vec::new(),
            by_name: HashMap::new(),
            by_address: HashMap::new(),
            user_types: Vec::new(),
            instances: Vec::new(),
            entries: Vec::new(),
            uart: crate::runtime::uart::Uart::default(),
            shadows: Vec::new(),
            st_places: Vec::new(),
        };
        for b in &sections.blocks {
            let (vars, lines) = read(&b.text, &types)?;
            let (vars, var_lines) = vars.into_iter().unzip();
            p.user_types.push(user::UserType {
                name: b.name.clone(),
                vars,
                var_lines,
                lines,
                line: b.line,
            });
        }
        // The instances' variables counted before any is made: said
        // once, at the declaration that passes a limit, and nothing else.
        p.budget(&vars).map_err(|e| vec![e])?;
        let vars: Vec<Variable> = vars.into_iter().map(|(v, _)| v).collect();
        let mut errors = Vec::new();
        if let Err(e) = p.declare(&vars, "", 0) {
            errors.push(Located::new(1, e));
        }
        p.compile_lines(&lines, &mut errors);
        if !p.instances.is_empty() {
            // The program ends here; the blocks' bodies follow.
            p.steps.push(Step::Ret(None));
        }
        p.compile_bodies(&mut errors);
        if !errors.is_empty() {
            return Err(errors);
        }
        p.wire_outputs();
        p.initial = p.values.clone();
        p.vars = vars;
        p.lines = lines;
        p.input_terminals = p
            .addresses
            .iter()
            .filter(|(a, _)| a.area == Area::Input)
            .map(|&(_, s)| (s, p.values[s].clone()))
            .collect();
        Ok(p)
    }

    /// Gives every declared variable its slot (and index), every block
    /// instance its state, every instance of the program's own blocks
    /// its variables (named `prefix` + name for the front ends).
    fn declare(&mut self, vars: &[Variable], prefix: &str, depth: usize) -> Result<(), LoadError> {
        for v in vars.iter().cloned() {
            let upper = v.name.to_ascii_uppercase();
            let shown = format!("{prefix}{}", v.name);
            match v.kind {
                Kind::Value { init, .. } => {
                    let slot = self.values.len();
                    self.values.push(init);
                    self.by_name.insert(upper, Named::Slot(slot));
                    // An ST member's or element's name as written
                    // (`(* st: a[1, 2] *)`, `iec::st::lower_flat`).
                    if let Some(st) = v.comment.strip_prefix("st: ") {
                        let alias = st.replace(' ', "");
                        self.by_name
                            .insert(alias.to_ascii_uppercase(), Named::Slot(slot));
                    }
                    self.names.push((shown, slot));
                    if v.retain {
                        self.retained.push(slot);
                    }
                    if let Some(a) = v.address {
                        self.addresses.push((a, slot));
                        self.by_address.insert(a, slot);
                    }
                }
                Kind::Block(block) => match self.user_type(&block) {
                    Some(ty) => {
                        let u = self.instantiate(&shown, ty, depth)?;
                        self.by_name.insert(upper, Named::User(u));
                    }
                    None => {
                        let b = self.blocks.len();
                        self.by_name.insert(upper, Named::Block(b));
                        self.block_names.push((shown, block.clone()));
                        self.blocks.push(Instance::new(&block));
                    }
                },
            }
        }
        Ok(())
    }

    /// The program in its canonical text, which loads back to the same
    /// program (`hashigo asm`).
    pub fn listing(&self) -> String {
        let mut out = String::new();
        for t in self.user_types() {
            out.push_str(&format!("FUNCTION_BLOCK {}\n", t.name));
            out.push_str(&crate::iec::listing::listing(&t.vars, &t.lines));
            out.push_str("END_FUNCTION_BLOCK\n");
        }
        out.push_str(&crate::iec::listing::listing(&self.vars, &self.lines));
        out
    }

    /// Its declarations and IL lines as read.
    pub fn source(&self) -> (&[Variable], &[Line]) {
        (&self.vars, &self.lines)
    }

    /// Whether it uses the serial port (LDmicro's UART blocks and
    /// formatted strings): the page shows a serial monitor then.
    pub fn uses_serial(&self) -> bool {
        self.block_names
            .iter()
            .any(|(_, kind)| kind.starts_with("LD_UART") || kind == "LD_FMTSTR")
    }

    /// How many steps (IL instructions) it has.
    pub fn len(&self) -> usize {
        self.steps.len()
    }

    /// Whether it has no step.
    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    /// The slot of a name (any case) or an address.
    fn slot(&mut self, operand: &Operand) -> Result<Src, LoadError> {
        match operand {
            Operand::Literal(d) => Ok(Src::Const(d.clone())),
            Operand::Number(v) => Ok(Program::number(*v)),
            Operand::Text(t) => string_value(t)
                .map(Src::Const)
                .map_err(|e| LoadError::Type(TypeWhy::Text(e))),
            // `instance.output`: only a block's outputs are read so (the
            // front ends' `c0.count` names reach inside; IL does not).
            Operand::Name(n) if n.contains('.') => match n.split_once('.') {
                Some((instance, pin)) => self.output_slot(instance, pin),
                None => Err(LoadError::Undeclared(n.clone())),
            },
            Operand::Name(n) if n.contains('[') => Err(LoadError::BadElement(n.clone())),
            Operand::Name(n) => match self.by_name.get(&n.to_ascii_uppercase()) {
                Some(Named::Slot(s)) => Ok(Src::Slot(*s)),
                Some(_) => Err(LoadError::Type(TypeWhy::BlockAsValue(n.clone()))),
                None => Err(LoadError::Undeclared(n.clone())),
            },
            Operand::Address(a) => {
                if let Some(&s) = self.by_address.get(a) {
                    return Ok(Src::Slot(s));
                }
                let t = a
                    .default_type()
                    .ok_or_else(|| LoadError::UntypedAddress(a.to_string()))?;
                let slot = self.values.len();
                self.values.push(t.zero());
                self.addresses.push((*a, slot));
                self.by_address.insert(*a, slot);
                Ok(Src::Slot(slot))
            }
        }
    }

    /// The untyped literal `line` loads (as the step about to be pushed),
    /// waiting for the type its use needs; none for any other operand.
    fn literal_of(&self, line: &Line) -> Pending {
        match line.operand {
            Some(Operand::Number(value)) => Pending::one(Flex {
                step: self.steps.len(),
                arg: None,
                line: line.line,
                value,
            }),
            _ => Pending::default(),
        }
    }

    fn type_of(&self, src: &Src) -> DataType {
        match src {
            Src::Slot(s) => self.values[*s].data_type(),
            Src::Const(d) => d.data_type(),
        }
    }

    /// The slot or constant of the line's operand, if it has one.
    fn operand(&mut self, line: &Line) -> Result<Option<Src>, LoadError> {
        line.operand.as_ref().map(|o| self.slot(o)).transpose()
    }

    /// One line resolved and checked; `flow` knows the current result.
    fn resolve(
        &mut self,
        line: &Line,
        labels: &HashMap<String, usize>,
        flow: &mut Flow,
    ) -> Result<Step, LoadError> {
        let step = match line.operator {
            Operator::Ld | Operator::St if is_element_line(line) => {
                self.element_step(line, flow)?
            }
            Operator::Ld => {
                let src = self.operand(line)?.ok_or(LoadError::Unbalanced)?;
                let t = self.type_of(&src);
                if line.negated {
                    invertible("LDN", t)?;
                }
                flow.cr = Some(t);
                flow.flex = self.literal_of(line);
                Step::Ld(src, line.negated)
            }
            Operator::St | Operator::S | Operator::R => self.store(line, flow)?,
            Operator::Not => {
                invertible("NOT", need_cr(flow.cr)?)?;
                Step::Not
            }
            Operator::Close => self.close(flow)?,
            Operator::Jmp => {
                let step = jump(line, labels, &mut flow.cr)?;
                if flow.cr.is_none() {
                    flow.flex.clear();
                }
                step
            }
            Operator::Ret => {
                if line.condition.is_some() && need_cr(flow.cr)? != DataType::Bool {
                    return Err(LoadError::NeedsBool("RETC"));
                }
                Step::Ret(line.condition)
            }
            Operator::Cal => self.call(line, &mut flow.cr)?,
            Operator::Function(f) => self.function(f, line, flow)?,
            op => self.binary(op, line, flow)?,
        };
        Ok(step)
    }

    /// ST, S, R: the current result into a variable (untyped literals
    /// taken at its type).
    fn store(&mut self, line: &Line, flow: &mut Flow) -> Result<Step, LoadError> {
        need_cr(flow.cr)?;
        let Some(Src::Slot(slot)) = self.operand(line)? else {
            return Err(LoadError::Type(TypeWhy::StoreLiteral));
        };
        let what = line.operand.as_ref().map_or(String::new(), describe);
        self.writable(slot, &what)?;
        let target = self.values[slot].data_type();
        let bool_only = line.operator != Operator::St;
        if bool_only && target != DataType::Bool {
            return Err(LoadError::Type(TypeWhy::SetBool {
                op: line.operator.mnemonic(),
                what,
                is: target,
            }));
        }
        self.settle(flow, target);
        let t = need_cr(flow.cr)?;
        if line.negated {
            invertible("STN", t)?;
        }
        if target != t {
            return Err(LoadError::Type(TypeWhy::Store {
                current: t,
                what,
                needs: target,
            }));
        }
        Ok(match line.operator {
            Operator::St => Step::St(slot, line.negated),
            Operator::S => Step::Set(slot),
            _ => Step::Reset(slot),
        })
    }

    /// AND … LT, now or deferred by `(`.
    fn binary(&mut self, op: Operator, line: &Line, flow: &mut Flow) -> Result<Step, LoadError> {
        let binary = match op {
            Operator::And => Binary::Logic(Bitwise::And, line.negated),
            Operator::Or => Binary::Logic(Bitwise::Or, line.negated),
            Operator::Xor => Binary::Logic(Bitwise::Xor, line.negated),
            Operator::Add => Binary::Arith(Arith::Add),
            Operator::Sub => Binary::Arith(Arith::Sub),
            Operator::Mul => Binary::Arith(Arith::Mul),
            Operator::Div => Binary::Arith(Arith::Div),
            Operator::Mod => Binary::Arith(Arith::Mod),
            Operator::Gt => Binary::Cmp(Comparison::Gt),
            Operator::Ge => Binary::Cmp(Comparison::Ge),
            Operator::Eq => Binary::Cmp(Comparison::Eq),
            Operator::Ne => Binary::Cmp(Comparison::Ne),
            Operator::Le => Binary::Cmp(Comparison::Le),
            _ => Binary::Cmp(Comparison::Lt),
        };
        need_cr(flow.cr)?;
        if line.deferred {
            // `OP( operand`: the operand starts what the `)` applies.
            let src = self.operand(line)?;
            flow.open.push(Open {
                op: binary,
                saved: flow.cr,
                flex: std::mem::take(&mut flow.flex),
                line: line.line,
            });
            flow.cr = src.as_ref().map(|s| self.type_of(s));
            flow.flex = self.literal_of(line);
            return Ok(Step::Open(binary, src));
        }
        let operand = line.operand.as_ref().ok_or(LoadError::Unbalanced)?;
        let mut src = [self.slot(operand)?];
        let t = self.join(flow, line, &[(None, operand)], &mut src)?;
        let [src] = src;
        let result = binary_type(binary, t, self.type_of(&src))?;
        if matches!(binary, Binary::Cmp(_)) {
            flow.flex.clear();
        }
        flow.cr = Some(result);
        Ok(Step::Binary(binary, src))
    }
}

mod calls;
mod check;
mod element;
mod flex;
mod functions;
mod lines;
mod outputs;
mod said;
mod shown;
mod user;
mod why;

pub use user::{
    InstanceBody, MAX_BLOCK_NESTING, MAX_BODY_STEPS, MAX_INSTANCES, MAX_INSTANCE_VARIABLES,
};
pub use why::{CallWhy, TypeWhy};

/// A section's declarations and IL lines (`blocks`: the types the
/// text's own function blocks give).
/// Declarations, each with its line.
type Declared = Vec<(Variable, usize)>;

fn read(text: &str, blocks: &[String]) -> Result<(Declared, Vec<Line>), Errors> {
    let vars = parse_vars_at(text, blocks).map_err(|es| {
        es.into_iter()
            .map(|e| Located::new(e.line, LoadError::Var(e.error)))
            .collect::<Errors>()
    })?;
    let lines = parse_il(text).map_err(|es| {
        es.into_iter()
            .map(|e| Located::new(e.line, LoadError::Il(e.error)))
            .collect::<Errors>()
    })?;
    Ok((vars, lines))
}

impl crate::iec::il::IlSource for Program {
    fn source(&self) -> (&[Variable], &[Line]) {
        Program::source(self)
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_english;
