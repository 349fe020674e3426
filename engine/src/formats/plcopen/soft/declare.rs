//! The variables a PLCopen project declares, as the soft PLC's `VAR`
//! lines: names stay names, located variables keep their addresses,
//! initial values and retain are kept, a comment is the variable's
//! documentation. The chosen programs' own variables and the
//! configuration's globals share one name space; a program's variable
//! whose name another program already declared is renamed
//! `<program>_<name>` within that program.

use std::collections::HashMap;

use super::error::DeclarationWhy;
use super::SoftError;
use crate::error::Located;
use crate::formats::plcopen::dom::Node;
use crate::iec::data::DataType;
use crate::iec::pins::is_block_type;
use crate::iec::vars::Direction;
use crate::iec::{parse_literal, Address};

/// What a declared name holds.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Held {
    Value(DataType),
    /// A standard function block instance (its type, upper-case).
    Block(String),
    /// An instance of one of the project's own function blocks (its type
    /// as written).
    User(String),
}

/// The project's own POUs: every name with what it is (`function block
/// in ST`), and those that are function blocks drawn in LD or FBD (the
/// ones the soft PLC runs as blocks).
#[derive(Debug, Default)]
pub(super) struct OwnTypes {
    pub names: Vec<(String, String)>,
    pub blocks: Vec<String>,
    /// The functions written in ST or IL: each runs as a block whose
    /// output of its own name is its result (issue #54).
    pub functions: Vec<String>,
}

/// A function block's inputs and outputs with their types.
#[derive(Clone, Debug, Default)]
pub(super) struct Interface {
    pub inputs: Vec<(String, DataType)>,
    pub outputs: Vec<(String, DataType)>,
    /// A function's: its output of its own name is its result.
    pub function: bool,
    /// Its external variables (`externalVars`): each global's name, type
    /// and whether it is copied back out (not a `constant` one). Each
    /// call passes them ([`Declarations::external_args`]).
    pub externals: Vec<External>,
}

/// A function block's or function's external variable: the global it
/// reaches, copied in at each call as an input of its name and, unless
/// it is `constant`, out by a hidden output (`st_io_<name>`, the ST
/// lowering's in-out copy) when the body ends.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct External {
    pub name: String,
    pub ty: DataType,
    pub copied_out: bool,
}

impl Interface {
    /// The type of input or output `pin` (any case).
    pub fn pin(&self, pin: &str) -> Option<DataType> {
        self.inputs
            .iter()
            .chain(&self.outputs)
            .find(|(p, _)| p.eq_ignore_ascii_case(pin))
            .map(|&(_, t)| t)
    }
}

/// One declaration, ready to write.
#[derive(Clone, Debug)]
pub(super) struct Declared {
    pub name: String,
    pub held: Held,
    /// `name [AT %address] : TYPE [:= value]; [(* doc *)]`.
    pub line: String,
    pub retain: bool,
    pub address: Option<Address>,
    /// Where the file declares it.
    pub xml_line: usize,
    /// In a function block: which way it faces.
    pub direction: Direction,
}

/// Every declaration, and each POU's renamings.
#[derive(Debug, Default)]
pub(super) struct Declarations {
    pub list: Vec<Declared>,
    /// Per POU (lower-case name): the file's name (lower-case) → the
    /// soft PLC's.
    renamed: HashMap<String, HashMap<String, String>>,
    /// Each name (upper-case) → its place in `list`.
    index: HashMap<String, usize>,
    /// Each located variable's address → its type.
    addresses: HashMap<Address, DataType>,
    /// A function block's external variables (its section declares each
    /// as an input, and the copied-out ones' hidden outputs).
    pub externals: Vec<External>,
}

impl Declarations {
    /// The soft PLC's name for `name` as written in POU `pou`.
    pub fn name_in(&self, pou: &str, name: &str) -> String {
        self.renamed
            .get(&pou.to_ascii_lowercase())
            .and_then(|m| m.get(&name.to_ascii_lowercase()))
            .cloned()
            .unwrap_or_else(|| name.to_string())
    }

    /// POU `pou`'s renamings: each name as the file writes it (lower-case)
    /// with the soft PLC's name for it.
    pub fn renamings(&self, pou: &str) -> Vec<(String, String)> {
        let m = self.renamed.get(&pou.to_ascii_lowercase());
        m.into_iter()
            .flatten()
            .map(|(f, s)| (f.clone(), s.clone()))
            .collect()
    }

    /// `instance.pin` of POU `pou`, an output of a block instance read
    /// by name as the IL reads it (`TON0.ET`, `CTU0.CV`): its soft PLC
    /// name and type (`user`: the project's own blocks' interfaces).
    pub fn block_output(
        &self,
        pou: &str,
        instance: &str,
        pin: &str,
        user: &HashMap<String, Interface>,
    ) -> Option<(String, DataType)> {
        let name = self.name_in(pou, instance);
        let t = match self.held(&name)? {
            Held::Block(kind) => crate::iec::pins::outputs(kind)
                .into_iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|(_, t)| t),
            Held::User(kind) => user
                .get(&kind.to_ascii_uppercase())?
                .outputs
                .iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(pin))
                .map(|&(_, t)| t),
            Held::Value(_) => None,
        }?;
        Some((format!("{name}.{pin}"), t))
    }

    /// What a (soft PLC) name holds, if declared.
    pub fn held(&self, name: &str) -> Option<&Held> {
        let &i = self.index.get(&name.to_ascii_uppercase())?;
        Some(&self.list[i].held)
    }

    /// The type of the variable at `address`, if one is declared there.
    pub fn at_address(&self, address: Address) -> Option<DataType> {
        self.addresses.get(&address).copied()
    }

    /// A function block's interface, from its declarations.
    pub fn interface(&self) -> Interface {
        // An external and its hidden output are no pin a call names.
        let external = |name: &str| {
            self.externals.iter().any(|e| {
                e.name.eq_ignore_ascii_case(name)
                    || crate::iec::st::io_pin(&e.name).eq_ignore_ascii_case(name)
            })
        };
        let faced = |d: Direction| -> Vec<(String, DataType)> {
            self.list
                .iter()
                .filter(|v| v.direction == d && !external(&v.name))
                .filter_map(|v| match v.held {
                    Held::Value(t) => Some((v.name.clone(), t)),
                    _ => None,
                })
                .collect()
        };
        Interface {
            inputs: faced(Direction::Input),
            outputs: faced(Direction::Output),
            function: false,
            externals: self.externals.clone(),
        }
    }

    /// The arguments a call of a block with interface `iface` passes for
    /// its externals, in POU `pou` (a program: the globals it sees; a
    /// block: its own externals of those names): `g := g` and, for one
    /// copied out, `st_io_g => g`, as the ST lowering's calls do. Refused
    /// when `pou` has no variable of an external's name (`ty`: the
    /// callee's type).
    pub fn external_args(
        &self,
        pou: &str,
        ty: &str,
        iface: &Interface,
    ) -> Result<Vec<String>, SoftError> {
        let mut args = Vec::new();
        for e in &iface.externals {
            let here = self.name_in(pou, &e.name);
            if self.held(&here).is_none() {
                return Err(SoftError::NoGlobal(ty.into(), e.name.clone(), pou.into()));
            }
            args.push(format!("{} := {here}", e.name));
            if e.copied_out {
                let pin = crate::iec::st::io_pin(&e.name);
                args.push(format!("{pin} => {here}"));
            }
        }
        Ok(args)
    }

    /// The lines that copy the copied-out externals back out when the
    /// body ends (`LD g` / `ST st_io_g`).
    pub fn copy_out(&self) -> Vec<String> {
        let copied = self.externals.iter().filter(|e| e.copied_out);
        copied
            .flat_map(|e| {
                let pin = crate::iec::st::io_pin(&e.name);
                [format!("LD {}", e.name), format!("ST {pin}")]
            })
            .collect()
    }

    /// The project's own function block types its instances have.
    pub fn user_types(&self) -> Vec<String> {
        self.list
            .iter()
            .filter_map(|d| match &d.held {
                Held::User(t) => Some(t.clone()),
                _ => None,
            })
            .collect()
    }

    fn push(&mut self, d: Declared) {
        if let (Some(a), Held::Value(t)) = (d.address, &d.held) {
            self.addresses.insert(a, *t);
        }
        self.index
            .insert(d.name.to_ascii_uppercase(), self.list.len());
        self.list.push(d);
    }

    /// Declares a name the file uses without declaring it (its
    /// declaration line is written by the caller).
    pub fn declare(&mut self, name: &str, held: Held) {
        self.push(Declared {
            name: name.to_string(),
            held,
            line: String::new(),
            retain: false,
            address: None,
            xml_line: 0,
            direction: Direction::Local,
        });
    }

    fn taken(&self, name: &str) -> bool {
        self.held(name).is_some()
    }
}

type Errors = Vec<Located<SoftError>>;

/// The declarations of the configuration's globals and of `pous`.
pub(super) fn declarations(
    root: &Node,
    pous: &[&Node],
    own: &OwnTypes,
) -> Result<Declarations, Errors> {
    let mut out = Declarations::default();
    let mut errors = Vec::new();
    let mut globals = Vec::new();
    root.descendants("configuration", &mut globals);
    for scope in globals.iter().flat_map(|c| scopes(c, true)) {
        for v in scope.all("variable") {
            if let Err(e) = declare(&mut out, scope, v, None, own, Direction::Local) {
                errors.push(e);
            }
        }
    }
    for pou in pous {
        let Some(interface) = pou.child("interface") else {
            continue;
        };
        let pou_name = pou.attr("name").unwrap_or_default();
        for scope in scopes(interface, false) {
            for v in scope.all("variable") {
                if let Err(e) = declare(&mut out, scope, v, Some(pou_name), own, Direction::Local) {
                    errors.push(e);
                }
            }
        }
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// The variable blocks under `node` (globals: every `globalVars` of the
/// configuration and its resources).
fn scopes(node: &Node, globals: bool) -> Vec<&Node> {
    let names: &[&str] = if globals {
        &["globalVars"]
    } else {
        &[
            "localVars",
            "inputVars",
            "outputVars",
            "inOutVars",
            "tempVars",
            "externalVars",
            "globalVars",
        ]
    };
    let mut out = Vec::new();
    for name in names {
        node.descendants(name, &mut out);
    }
    out
}

/// Declares variable `v` of `scope` (for POU `pou`, or a global).
fn declare(
    out: &mut Declarations,
    scope: &Node,
    v: &Node,
    pou: Option<&str>,
    own: &OwnTypes,
    direction: Direction,
) -> Result<(), Located<SoftError>> {
    let at = |e: SoftError| Located::new(v.line, e);
    let name = v.attr("name").unwrap_or_default().to_string();
    if !crate::iec::is_identifier(&name) {
        return Err(at(SoftError::Declaration(name, DeclarationWhy::NotIecName)));
    }
    let (held, type_name) = held(v, &name, own).map_err(at)?;
    let Some(soft_name) = soft_name(out, &name, scope, pou) else {
        return Ok(());
    };
    let mut line = soft_name.clone();
    let address = match v.attr("address") {
        Some(text) => {
            let a = Address::parse(text).map_err(|e| {
                at(SoftError::Declaration(
                    name.clone(),
                    DeclarationWhy::Address(e),
                ))
            })?;
            line.push_str(&format!(" AT {a}"));
            Some(a)
        }
        None => None,
    };
    line.push_str(&format!(" : {type_name}"));
    let initial = v
        .child("initialValue")
        .and_then(|i| i.child("simpleValue"))
        .and_then(|s| s.attr("value"));
    if let (Some(value), Held::Value(t)) = (initial, &held) {
        let d = parse_literal(value, Some(*t)).map_err(|e| {
            at(SoftError::Declaration(
                name.clone(),
                DeclarationWhy::Initial(e),
            ))
        })?;
        line.push_str(&format!(" := {d}"));
    }
    line.push(';');
    if let Some(doc) = v.child("documentation").map(Node::deep_text) {
        let doc = doc.split_whitespace().collect::<Vec<_>>().join(" ");
        if !doc.is_empty() {
            line.push_str(&format!(" (* {} *)", doc.replace("*)", "* )")));
        }
    }
    let retain = scope.attr("retain") == Some("true") || scope.attr("persistent") == Some("true");
    out.push(Declared {
        name: soft_name,
        held,
        line,
        retain,
        address,
        xml_line: v.line,
        direction,
    });
    Ok(())
}

/// What variable `v` (named `name`) holds, and its type's name.
fn held(v: &Node, name: &str, own: &OwnTypes) -> Result<(Held, String), SoftError> {
    let ty = v
        .child("type")
        .and_then(|t| t.children.first())
        .ok_or_else(|| SoftError::Declaration(name.to_string(), DeclarationWhy::NoType))?;
    let written = match ty.name.as_str() {
        "derived" => ty.attr("name").unwrap_or_default(),
        other => other,
    };
    let type_name = written.to_ascii_uppercase();
    let held = if let Some(t) = DataType::from_name(&type_name) {
        Held::Value(t)
    } else if is_block_type(&type_name) {
        Held::Block(type_name.clone())
    } else if let Some(b) = own
        .blocks
        .iter()
        .find(|b| b.eq_ignore_ascii_case(&type_name))
    {
        Held::User(b.clone())
    } else if let Some((_, how)) = own
        .names
        .iter()
        .find(|(p, _)| p.eq_ignore_ascii_case(&type_name))
    {
        return Err(SoftError::ProjectBlock(written.to_string(), how.clone()));
    } else if ty.name == "derived" {
        return Err(SoftError::Block(written.to_string()));
    } else {
        return Err(SoftError::Declaration(
            name.to_string(),
            DeclarationWhy::UnknownType(type_name),
        ));
    };
    Ok((held, type_name))
}

/// The soft PLC's name for `name` declared in `scope` of POU `pou`;
/// `None` when it is a global seen again (an external). A program's own
/// variable whose name is taken becomes `<program>_<name>`.
fn soft_name(
    out: &mut Declarations,
    name: &str,
    scope: &Node,
    pou: Option<&str>,
) -> Option<String> {
    if !out.taken(name) {
        return Some(name.to_string());
    }
    let pou = pou.filter(|_| scope.name != "externalVars")?;
    let mut soft_name = format!("{pou}_{name}");
    let mut n = 2;
    while out.taken(&soft_name) {
        soft_name = format!("{pou}_{name}{n}");
        n += 1;
    }
    out.renamed
        .entry(pou.to_ascii_lowercase())
        .or_default()
        .insert(name.to_ascii_lowercase(), soft_name.clone());
    Some(soft_name)
}

/// Declares the external variables of a function block's `scope` (an
/// `externalVars`): each an input of its name, copied in from the
/// caller's global at each call, and unless the scope is `constant` a
/// hidden output that copies it back out (as IL has no reference, so a
/// `.st` block's VAR_EXTERNAL is; `iec::st::lower_io`).
fn block_externals(out: &mut Declarations, scope: &Node, own: &OwnTypes) -> Errors {
    let mut errors = Vec::new();
    let copied_out = scope.attr("constant") != Some("true");
    for v in scope.all("variable") {
        if let Err(e) = declare(out, scope, v, None, own, Direction::Input) {
            errors.push(e);
            continue;
        }
        let Some(d) = out.list.last() else { continue };
        let Held::Value(ty) = d.held else {
            let why = DeclarationWhy::ExternalBlock;
            errors.push(Located::new(
                v.line,
                SoftError::Declaration(d.name.clone(), why),
            ));
            continue;
        };
        let name = d.name.clone();
        if copied_out {
            let pin = crate::iec::st::io_pin(&name);
            out.push(Declared {
                name: pin.clone(),
                held: Held::Value(ty),
                line: format!("{pin} : {};", ty.name()),
                retain: false,
                address: None,
                xml_line: v.line,
                direction: Direction::Output,
            });
        }
        out.externals.push(External {
            name,
            ty,
            copied_out,
        });
    }
    errors
}

/// The declarations of function block `pou`: its inputs, outputs and
/// locals, in a name space of its own.
pub(super) fn block_declarations(pou: &Node, own: &OwnTypes) -> Result<Declarations, Errors> {
    let mut out = Declarations::default();
    let mut errors = Vec::new();
    let Some(interface) = pou.child("interface") else {
        return Ok(out);
    };
    for scope in &interface.children {
        let direction = match scope.name.as_str() {
            "inputVars" => Direction::Input,
            "outputVars" => Direction::Output,
            "localVars" | "tempVars" => Direction::Local,
            "externalVars" => {
                errors.extend(block_externals(&mut out, scope, own));
                continue;
            }
            "inOutVars" => {
                let why = DeclarationWhy::Section(scope.name.clone());
                errors.push(Located::new(
                    scope.line,
                    SoftError::Declaration(String::new(), why),
                ));
                continue;
            }
            _ => continue,
        };
        for v in scope.all("variable") {
            if let Err(e) = declare(&mut out, scope, v, None, own, direction) {
                errors.push(e);
            }
        }
    }
    // A function's result: an output of its own name, of its type.
    if let Some(r) = interface.child("returnType") {
        let v = Node {
            name: "variable".into(),
            attrs: vec![("name".into(), pou.attr("name").unwrap_or_default().into())],
            children: vec![Node {
                name: "type".into(),
                children: r.children.clone(),
                ..Node::default()
            }],
            line: r.line,
            ..Node::default()
        };
        if let Err(e) = declare(&mut out, r, &v, None, own, Direction::Output) {
            errors.push(e);
        }
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}
