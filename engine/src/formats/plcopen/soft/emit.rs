//! A body's graph as the soft PLC's Instruction List. Each element runs
//! once a scan, after every element that feeds it (then top to bottom,
//! left to right, as the file draws it): a contact ANDs its variable into
//! the power it is given, a coil stores it, a block is called with its
//! inputs (a function's EN jumps over it while off, its outputs then
//! keeping their last values, as IEC says). Every output that feeds
//! something is a generated variable `_<pou>_n<id>[_<PIN>]`, so any
//! wiring the file draws runs as drawn: branches, wired ORs, one output
//! feeding many inputs, feedback through variables.

use std::collections::HashMap;

use super::declare::{Declarations, Held, Interface};
use super::infer::output_type;
use super::SoftError;
use crate::error::Located;
use crate::formats::plcopen::graph::{order, Element, Graph, Kind, Source};
use crate::formats::plcopen::warning::ImportWarning;
use crate::iec::data::DataType;
use crate::iec::functions::{Function, Operand};
use crate::iec::is_identifier;
use crate::iec::pins::is_block_type;
use crate::iec::pins::{inputs as fb_inputs, outputs as fb_outputs};
use crate::iec::{literal_type, Address};

/// What the emission of every body gives.
#[derive(Debug, Default)]
pub(super) struct Output {
    /// Generated declarations (`name : TYPE;`) with their file lines.
    pub vars: Vec<(String, usize)>,
    /// IL lines with the file line each comes from.
    pub lines: Vec<(String, usize)>,
    /// What was taken on trust, each at its line.
    pub warnings: Vec<Located<ImportWarning>>,
    /// Each generated variable's type.
    pub(super) types: HashMap<String, DataType>,
    /// Problems each at a line of its own (an EXECUTE block's ST).
    pub(super) errors: Vec<Located<SoftError>>,
}

/// Emits one body.
pub(super) struct Emitter<'a> {
    pub decl: &'a mut Declarations,
    pub out: &'a mut Output,
    /// The POU's name (its renamings) and its place (its temporaries).
    pub pou: String,
    pub index: usize,
    pub own_blocks: &'a super::declare::OwnTypes,
    /// The project's own function blocks the soft PLC runs, by type
    /// (upper-case).
    pub user: &'a HashMap<String, Interface>,
    /// The body's elements each output feeds: (element, pin) by the
    /// feeding element's id.
    pub consumers: HashMap<String, Vec<(usize, String)>>,
    /// The ids of the body's elements refused so far: what they feed is
    /// not refused again (it was called a loop of wires).
    pub failed: std::collections::HashSet<String>,
}

type Result<T> = std::result::Result<T, SoftError>;

/// A block's inputs or outputs, each with its type.
type Pins = Vec<(String, DataType)>;

impl Emitter<'_> {
    /// Emits `g` in its running order; every error at its element.
    pub fn body(&mut self, g: &Graph) -> std::result::Result<(), Vec<Located<SoftError>>> {
        let mut errors = Vec::new();
        self.consumers.clear();
        for (i, e) in g.elements.iter().enumerate() {
            for (pin, sources) in &e.inputs {
                for s in sources {
                    self.consumers
                        .entry(s.from.clone())
                        .or_default()
                        .push((i, pin.clone()));
                }
            }
        }
        self.failed.clear();
        let known = super::infer::Known {
            operand: &|x| self.expression(x).ok().map(|o| o.ty),
            user: self.user,
        };
        let types = super::infer::output_types(&known, g, self.index);
        self.out.types.extend(types);
        for i in order(g) {
            let e = &g.elements[i];
            if let Err(err) = self.element(g, e) {
                self.failed.insert(e.id.clone());
                if err != SoftError::Follows {
                    errors.push(Located::new(e.line, err));
                }
            }
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(errors)
        }
    }

    pub(super) fn emit(&mut self, line: String, at: usize) {
        self.out.lines.push((line, at));
    }

    pub(super) fn temp(&mut self, stem: &str, ty: &str, at: usize) -> String {
        let name = format!("_{}_{stem}", self.index);
        self.out.vars.push((format!("{name} : {ty};"), at));
        if let Some(t) = DataType::from_name(ty) {
            self.out.types.insert(name.clone(), t);
        }
        name
    }

    fn element(&mut self, g: &Graph, e: &Element) -> Result<()> {
        match &e.kind {
            Kind::Contact {
                variable,
                negated,
                edge,
            } => {
                let power = self.required(g, e, "")?;
                let mut v = self.bit(variable, e.line)?;
                if let Some(falling) = edge {
                    v = self.edge(&v.text, *falling, &e.id, e.line)?;
                }
                let n = if *negated { "N" } else { "" };
                if power.is_true() {
                    self.emit(format!("LD{n} {}", v.text), e.line);
                } else {
                    self.emit(format!("LD {}", power.text), e.line);
                    self.emit(format!("AND{n} {}", v.text), e.line);
                }
                let t = self.temp(&format!("n{}", e.id), "BOOL", e.line);
                self.emit(format!("ST {t}"), e.line);
            }
            Kind::Coil {
                variable,
                negated,
                storage,
                edge,
            } => {
                let mut power = self.required(g, e, "")?;
                let v = self.bit(variable, e.line)?;
                if let Some(falling) = edge {
                    power = self.edge(&power.text, *falling, &e.id, e.line)?;
                }
                self.emit(format!("LD {}", power.text), e.line);
                let op = match (storage, negated) {
                    (Some(true), _) => "S",
                    (Some(false), _) => "R",
                    (None, true) => "STN",
                    (None, false) => "ST",
                };
                self.emit(format!("{op} {}", v.text), e.line);
                let t = self.temp(&format!("n{}", e.id), "BOOL", e.line);
                self.emit(format!("ST {t}"), e.line);
            }
            Kind::OutVariable(target) | Kind::InOutVariable(target) => {
                let Some(value) = self.input(g, e, "")? else {
                    return match e.kind {
                        Kind::InOutVariable(_) => Ok(()),
                        _ => Err(SoftError::Unconnected(format!("output variable {target}"))),
                    };
                };
                let target = self.expression(target)?;
                if target.literal {
                    return Err(SoftError::Expression(target.text));
                }
                let value = value.at(target.ty);
                // Fed by a block whose EN is off: the variable keeps its
                // value (target := SEL(EN, target, value)).
                match super::infer::guard(g, e, self.index) {
                    Some(en) => {
                        self.emit(format!("LD {en}"), e.line);
                        self.emit(format!("SEL {}, {}", target.text, value.text), e.line);
                    }
                    None => self.emit(format!("LD {}", value.text), e.line),
                }
                self.emit(format!("ST {}", target.text), e.line);
            }
            Kind::Block {
                type_name,
                instance,
            } => self.block(g, e, type_name, instance)?,
            _ => {}
        }
        Ok(())
    }

    /// A contact's or coil's variable: a BOOL. A name the file never
    /// declares is taken as a BOOL of its own, with a warning (the file
    /// would not build in its own tool; its intent is plain).
    fn bit(&mut self, variable: &str, at: usize) -> Result<Operand> {
        let v = match self.expression(variable) {
            Err(SoftError::Undeclared(name)) => {
                self.out.vars.push((format!("{name} : BOOL;"), at));
                self.decl.declare(&name, Held::Value(DataType::Bool));
                self.out
                    .warnings
                    .push(Located::new(at, ImportWarning::TakenAsBool(name.clone())));
                Operand::temp(name, DataType::Bool)
            }
            other => other?,
        };
        match v.ty {
            Some(DataType::Bool) if !v.literal => Ok(v),
            _ => Err(SoftError::NotABit(variable.to_string())),
        }
    }

    /// The Q of a new R_TRIG / F_TRIG called on `clk`.
    fn edge(&mut self, clk: &str, falling: bool, stem: &str, at: usize) -> Result<Operand> {
        let block = if falling { "F_TRIG" } else { "R_TRIG" };
        let trig = self.temp(&format!("e{stem}"), block, at);
        let q = self.temp(&format!("q{stem}"), "BOOL", at);
        self.emit(format!("CAL {trig}(CLK := {clk}, Q => {q})"), at);
        Ok(Operand::temp(q, DataType::Bool))
    }

    /// A variable, an address or a literal as the file writes it.
    pub(super) fn expression(&self, text: &str) -> Result<Operand> {
        let text = text.trim();
        if text.starts_with('%') {
            let a =
                Address::parse(text).map_err(|e| SoftError::Expression(format!("{text}: {e}")))?;
            let ty = self
                .decl
                .at_address(a)
                .or_else(|| a.default_type())
                .ok_or_else(|| SoftError::Expression(format!("{text}: a byte has no type here")))?;
            return Ok(Operand::temp(a.to_string(), ty));
        }
        if is_identifier(text)
            && !text.eq_ignore_ascii_case("TRUE")
            && !text.eq_ignore_ascii_case("FALSE")
        {
            let name = self.decl.name_in(&self.pou, text);
            return match self.decl.held(&name) {
                Some(Held::Value(t)) => Ok(Operand::temp(name, *t)),
                Some(Held::Block(_) | Held::User(_)) => Err(SoftError::Expression(format!(
                    "{text} is a function block instance, not a value"
                ))),
                None => Err(SoftError::Undeclared(text.to_string())),
            };
        }
        let output = text
            .split_once('.')
            .filter(|(i, p)| is_identifier(i) && is_identifier(p));
        if let Some((instance, pin)) = output {
            let (name, t) = (self.decl.block_output(&self.pou, instance, pin, self.user))
                .ok_or_else(|| SoftError::Expression(text.to_string()))?;
            return Ok(Operand::temp(name, t));
        }
        let (_, ty) = literal_type(text).map_err(|_| SoftError::Expression(text.to_string()))?;
        Ok(Operand {
            text: text.to_string(),
            ty,
            literal: true,
        })
    }

    /// The value at input `pin` of `e`, if anything is connected: one
    /// source's output, or the OR of several (a wired OR).
    pub(super) fn input(&mut self, g: &Graph, e: &Element, pin: &str) -> Result<Option<Operand>> {
        let Some((_, sources)) = e.inputs.iter().find(|(p, _)| p.eq_ignore_ascii_case(pin)) else {
            return Ok(None);
        };
        let value = self
            .joined(g, sources, &format!("w{}_{pin}", e.id), e.line, 0)
            .map_err(|err| match err {
                SoftError::NoOutput(_, block, p, has) => {
                    SoftError::NoOutput(e.describe(pin), block, p, has)
                }
                other => other,
            })?;
        let Some(&(_, negated, edge)) = e
            .modifiers
            .iter()
            .find(|(p, ..)| p.eq_ignore_ascii_case(pin))
        else {
            return Ok(value);
        };
        let Some(mut value) = value else {
            return Ok(None);
        };
        if negated {
            let t = self.temp(&format!("m{}_{pin}", e.id), "BOOL", e.line);
            self.emit(
                format!("LDN {}", value.at(Some(DataType::Bool)).text),
                e.line,
            );
            self.emit(format!("ST {t}"), e.line);
            value = Operand::temp(t, DataType::Bool);
        }
        if let Some(falling) = edge {
            let stem = format!("{}_{pin}", e.id);
            value = self.edge(&value.text, falling, &stem, e.line)?;
        }
        Ok(Some(value))
    }

    fn required(&mut self, g: &Graph, e: &Element, pin: &str) -> Result<Operand> {
        self.input(g, e, pin)?
            .ok_or_else(|| SoftError::Unconnected(e.describe(pin)))
    }

    fn joined(
        &mut self,
        g: &Graph,
        sources: &[Source],
        stem: &str,
        at: usize,
        depth: usize,
    ) -> Result<Option<Operand>> {
        let mut ops = Vec::new();
        for s in sources {
            ops.push(self.source(g, s, depth)?);
        }
        match ops.len() {
            0 => Ok(None),
            1 => Ok(ops.pop()),
            _ => {
                let first = ops.remove(0);
                self.emit(format!("LD {}", first.text), at);
                for o in &ops {
                    self.emit(format!("OR {}", o.text), at);
                }
                let t = self.temp(stem, "BOOL", at);
                self.emit(format!("ST {t}"), at);
                Ok(Some(Operand::temp(t, DataType::Bool)))
            }
        }
    }

    /// The output `s` names.
    fn source(&mut self, g: &Graph, s: &Source, depth: usize) -> Result<Operand> {
        let &i = g
            .by_id
            .get(&s.from)
            .ok_or_else(|| SoftError::Missing(s.from.clone()))?;
        let from = &g.elements[i];
        if self.failed.contains(&from.id) {
            return Err(SoftError::Follows);
        }
        let k = self.index;
        Ok(match &from.kind {
            Kind::LeftRail => Operand {
                text: "TRUE".into(),
                ty: Some(DataType::Bool),
                literal: true,
            },
            Kind::InVariable(x) | Kind::InOutVariable(x) => self.expression(x)?,
            Kind::Continuation(name) => {
                if depth > crate::limits::MAX_CONNECTOR_CHAIN {
                    return Err(SoftError::ConnectorLoop(name.clone()));
                }
                let c = g
                    .connectors
                    .get(&name.to_ascii_lowercase())
                    .map(|&c| &g.elements[c])
                    .ok_or_else(|| SoftError::Missing(format!("connector {name}")))?;
                let sources = c.inputs.first().map(|(_, s)| s.clone()).unwrap_or_default();
                self.joined(g, &sources, &format!("c{}", c.id), c.line, depth + 1)?
                    .ok_or_else(|| SoftError::Unconnected(format!("connector {name}")))?
            }
            Kind::Contact { .. } | Kind::Coil { .. } => {
                Operand::temp(format!("_{k}_n{}", from.id), DataType::Bool)
            }
            Kind::Block { type_name, .. } => {
                let pin = s
                    .pin
                    .clone()
                    .or_else(|| super::infer::unnamed_output(from))
                    .unwrap_or_else(|| "OUT".into());
                // A function's result is read by the pin drawn (`OUT`).
                let user = self.user.get(&type_name.to_ascii_uppercase());
                let user = user.filter(|i| !i.function);
                super::formal::check_output(from, type_name, &pin, user)?;
                let ty = output_type(type_name, &pin)
                    .or_else(|| user.and_then(|i| i.pin(&pin)))
                    .or_else(|| {
                        self.out
                            .types
                            .get(&format!("_{k}_n{}_{pin}", from.id))
                            .copied()
                    })
                    .ok_or_else(|| SoftError::Feedback(type_name.clone()))?;
                Operand::temp(format!("_{k}_n{}_{pin}", from.id), ty)
            }
            // An unknown element is refused before a body is emitted.
            Kind::RightRail | Kind::OutVariable(_) | Kind::Connector(_) | Kind::Other(_) => {
                return Err(SoftError::Missing(s.from.clone()));
            }
        })
    }

    fn block(&mut self, g: &Graph, e: &Element, type_name: &str, instance: &str) -> Result<()> {
        let upper = type_name.to_ascii_uppercase();
        if upper == "EXECUTE" {
            return self.execute(g, e);
        }
        if is_block_type(&upper) {
            return self.function_block(g, e, &upper, instance);
        }
        if let Some(f) = Function::named(&upper) {
            return self.function(g, e, f);
        }
        if let Some(iface) = self.user.get(&upper).filter(|i| i.function) {
            return self.own_function(g, e, type_name, &iface.clone());
        }
        if let Some(iface) = self.user.get(&upper) {
            return self.user_block(g, e, type_name, instance, &iface.clone());
        }
        super::formal::check_own_instance(self.own_blocks, type_name, instance)?;
        if let Some((_, how)) = self
            .own_blocks
            .names
            .iter()
            .find(|(b, _)| b.eq_ignore_ascii_case(type_name))
        {
            return Err(SoftError::ProjectBlock(type_name.to_string(), how.clone()));
        }
        Err(SoftError::Block(type_name.to_string()))
    }

    /// Jumps over what follows while EN is off; gives EN.
    pub(super) fn enable(&mut self, g: &Graph, e: &Element) -> Result<Option<Operand>> {
        let en = self.input(g, e, "EN")?;
        let wired = e
            .inputs
            .iter()
            .any(|(p, s)| p.eq_ignore_ascii_case("EN") && !s.is_empty());
        let Some(en) = en.filter(|_| wired) else {
            return Ok(None);
        };
        // Kept for the output variables it feeds (see `guard`).
        let copy = self.temp(&format!("n{}_EN", e.id), "BOOL", e.line);
        self.emit(format!("LD {}", en.text), e.line);
        self.emit(format!("ST {copy}"), e.line);
        self.emit(format!("JMPCN _{}_skip{}", self.index, e.id), e.line);
        Ok(Some(Operand::temp(copy, DataType::Bool)))
    }

    /// After the block: the label EN jumps to, and ENO.
    pub(super) fn enabled(&mut self, e: &Element, en: Option<Operand>) {
        let eno = e.outputs.iter().any(|p| p.eq_ignore_ascii_case("ENO"));
        match en {
            Some(en) => {
                let label = format!("_{}_skip{}", self.index, e.id);
                self.emit(format!("{label}: LD {}", en.text), e.line);
            }
            None if eno => self.emit("LD TRUE".into(), e.line),
            None => return,
        }
        if eno {
            let t = self.temp(&format!("n{}_ENO", e.id), "BOOL", e.line);
            self.emit(format!("ST {t}"), e.line);
        }
    }

    fn function_block(&mut self, g: &Graph, e: &Element, kind: &str, instance: &str) -> Result<()> {
        let name = self.decl.name_in(&self.pou, instance);
        match self.decl.held(&name) {
            Some(Held::Block(k)) if k == kind => {}
            Some(_) => return Err(SoftError::Instance(instance.to_string(), kind.to_string())),
            None => {
                self.out.vars.push((format!("{name} : {kind};"), e.line));
                self.decl.declare(&name, Held::Block(kind.to_string()));
            }
        }
        let en = self.enable(g, e)?;
        let owned = |pins: Vec<(&str, DataType)>| -> Vec<(String, DataType)> {
            pins.into_iter().map(|(p, t)| (p.to_string(), t)).collect()
        };
        // An LDmicro block's text (FMT) is an input of the block's box.
        let mut inputs = fb_inputs(kind);
        inputs.extend(crate::iec::pins::ldmicro::text_input(kind).map(|p| (p, DataType::String)));
        let pins = (owned(inputs), owned(fb_outputs(kind)));
        self.cal(g, e, &name, pins, Vec::new(), en)
    }

    /// A call of an instance of the project's own function block: `CAL
    /// inst(input := …, output => _n<id>_<PIN>)`, EN as for any block.
    fn user_block(
        &mut self,
        g: &Graph,
        e: &Element,
        type_name: &str,
        instance: &str,
        iface: &Interface,
    ) -> Result<()> {
        let name = self.decl.name_in(&self.pou, instance);
        match self.decl.held(&name) {
            Some(Held::User(t)) if t.eq_ignore_ascii_case(type_name) => {}
            _ => {
                return Err(SoftError::Instance(
                    instance.to_string(),
                    type_name.to_string(),
                ));
            }
        }
        let en = self.enable(g, e)?;
        // Its externals: this POU's globals (or own externals) of their names.
        let externals = self.decl.external_args(&self.pou, type_name, iface)?;
        let pins = (iface.inputs.clone(), iface.outputs.clone());
        self.cal(g, e, &name, pins, externals, en)
    }

    /// `CAL name(input := …, output => _n<id>_<PIN>, extra…)` of a block
    /// with these pins (each input wired, each output something reads),
    /// then the label EN jumps to and ENO.
    fn cal(
        &mut self,
        g: &Graph,
        e: &Element,
        name: &str,
        (inputs, outputs): (Pins, Pins),
        extra: Vec<String>,
        en: Option<Operand>,
    ) -> Result<()> {
        super::formal::check_inputs(e, &inputs)?;
        let mut params = Vec::new();
        for (pin, ty) in &inputs {
            if let Some(v) = self.input(g, e, pin)? {
                params.push(format!("{pin} := {}", v.at(Some(*ty)).text));
            }
        }
        for (pin, ty) in &outputs {
            if e.outputs.iter().any(|p| p.eq_ignore_ascii_case(pin)) {
                let t = self.temp(&format!("n{}_{pin}", e.id), ty.name(), e.line);
                params.push(format!("{pin} => {t}"));
            }
        }
        params.extend(extra);
        self.emit(format!("CAL {name}({})", params.join(", ")), e.line);
        self.enabled(e, en);
        Ok(())
    }

    fn function(&mut self, g: &Graph, e: &Element, f: Function) -> Result<()> {
        let mut args = Vec::new();
        for (pin, _) in e
            .inputs
            .iter()
            .filter(|(p, _)| !p.eq_ignore_ascii_case("EN"))
        {
            let v = self
                .input(g, e, pin)?
                .ok_or_else(|| SoftError::Unconnected(e.describe(pin)))?;
            args.push((pin.clone(), v));
        }
        let consumer = consumer_type(g, e, self);
        let (code, result) = f
            .code(&args, consumer)
            .map_err(|why| SoftError::Function(e.block_type(), why))?;
        let out = e
            .outputs
            .iter()
            .find(|p| !p.eq_ignore_ascii_case("ENO"))
            .cloned()
            .unwrap_or_else(|| "OUT".into());
        let t = self.temp(&format!("n{}_{out}", e.id), result.name(), e.line);
        let wired = e
            .inputs
            .iter()
            .any(|(p, s)| p.eq_ignore_ascii_case("EN") && !s.is_empty());
        if wired {
            // Off, a function gives its type's zero to what its output
            // feeds, as OpenPLC's runtime does (a comparison in a rung
            // then passes no power); variables keep theirs (`guard`).
            self.emit(format!("LD {}", result.zero()), e.line);
            self.emit(format!("ST {t}"), e.line);
        }
        let en = self.enable(g, e)?;
        for line in code {
            self.emit(line, e.line);
        }
        self.emit(format!("ST {t}"), e.line);
        self.enabled(e, en);
        Ok(())
    }
}

/// The type the elements fed by `e`'s output want (an output variable's,
/// a block input's), for a function whose inputs are all untyped.
fn consumer_type(g: &Graph, e: &Element, em: &Emitter) -> Option<DataType> {
    em.consumers
        .get(&e.id)?
        .iter()
        .find_map(|(c, pin)| match &g.elements[*c].kind {
            Kind::OutVariable(x) | Kind::InOutVariable(x) => em.expression(x).ok()?.ty,
            Kind::Block { type_name, .. } => fb_inputs(&type_name.to_ascii_uppercase())
                .iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|(_, t)| *t),
            _ => None,
        })
}
