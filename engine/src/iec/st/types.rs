//! The types the checker gives declarations and expressions, and which
//! value fits which place: one type per operation, as the soft PLC's
//! compiler has it (docs/soft-plc.md, "Arithmetic"), an untyped integer
//! literal taking the type of its use and an untyped real literal REAL or
//! LREAL.

use std::collections::HashMap;

use super::ast::{Elementary, Ident, Span, TypeRef, VarKind};
use super::error::{StError, StErrorKind};
use crate::iec::pins;

/// A checked type.
#[derive(Clone, Debug, PartialEq)]
pub enum Ty {
    /// An elementary type.
    Elem(Elementary),
    /// A STRING.
    Str,
    /// An array: its dimensions and its element.
    Array(usize, Box<Ty>),
    /// A structure declared by `TYPE` (its name, upper-case).
    Struct(String),
    /// A function block instance (the block's name, upper-case).
    Block(String),
    /// An untyped integer literal (or an expression of them only).
    AnyInt,
    /// An untyped real literal.
    AnyReal,
    /// Not known here (a standard function's result): fits anywhere.
    Unknown,
}

impl Ty {
    /// The type's name in messages.
    pub fn describe(&self) -> String {
        match self {
            Ty::Elem(e) => e.name().to_string(),
            Ty::Str => "STRING".to_string(),
            Ty::Array(n, of) => format!("an array of {n} dimension(s) of {}", of.describe()),
            Ty::Struct(n) | Ty::Block(n) => n.clone(),
            Ty::AnyInt => "an integer".to_string(),
            Ty::AnyReal => "a real".to_string(),
            Ty::Unknown => "a value".to_string(),
        }
    }

    /// Whether a value of type `self` may go where `want` is needed.
    pub fn fits(&self, want: &Ty) -> bool {
        use Elementary::{Lreal, Real};
        match (self, want) {
            (Ty::Unknown, _) | (_, Ty::Unknown) => true,
            (Ty::AnyInt, Ty::Elem(e)) => e.is_integer() || matches!(e, Real | Lreal),
            (Ty::AnyInt | Ty::AnyReal, Ty::AnyInt | Ty::AnyReal) => true,
            (Ty::AnyReal, Ty::Elem(Real | Lreal)) => true,
            (Ty::Elem(_), Ty::AnyInt | Ty::AnyReal) => want.fits(self),
            (a, b) => a == b,
        }
    }

    /// Whether it is BOOL (or could be).
    pub fn is_bool(&self) -> bool {
        matches!(self, Ty::Elem(Elementary::Bool) | Ty::Unknown)
    }

    /// Whether it is an integer or bit string (or could be).
    pub fn is_integer(&self) -> bool {
        match self {
            Ty::Elem(e) => e.is_integer(),
            Ty::AnyInt | Ty::Unknown => true,
            _ => false,
        }
    }

    /// Whether arithmetic applies to it.
    pub fn is_number(&self) -> bool {
        match self {
            Ty::Elem(e) => *e != Elementary::Bool,
            Ty::AnyInt | Ty::AnyReal | Ty::Unknown => true,
            _ => false,
        }
    }
}

/// A declared variable.
#[derive(Clone, Debug)]
pub struct Var {
    /// Its type.
    pub ty: Ty,
    /// Its section.
    pub kind: VarKind,
    /// Declared `CONSTANT`.
    pub constant: bool,
}

/// What a source declares: structures, aliases and POUs, by upper-case
/// name.
#[derive(Default)]
pub struct Decls {
    /// Each structure's members.
    pub structs: HashMap<String, Vec<(String, Ty)>>,
    /// Each other name for a type.
    pub aliases: HashMap<String, TypeRef>,
    /// Each function block's inputs, outputs and in-outs.
    pub blocks: HashMap<String, Vec<(String, Ty, VarKind)>>,
    /// Each function's result and inputs in order.
    pub functions: HashMap<String, (Ty, Vec<(String, Ty)>)>,
}

/// The elementary type an engine `DataType` names.
pub(super) fn elem_of(name: &str) -> Ty {
    match Elementary::from_name(name) {
        Some(e) => Ty::Elem(e),
        None if name.eq_ignore_ascii_case("STRING") => Ty::Str,
        None => Ty::Unknown,
    }
}

impl Decls {
    /// The type `t` names, or why not.
    pub fn resolve(&self, t: &TypeRef) -> Result<Ty, StError> {
        self.resolve_in(t, 0)
    }

    fn resolve_in(&self, t: &TypeRef, depth: usize) -> Result<Ty, StError> {
        Ok(match t {
            TypeRef::Elementary(e) => Ty::Elem(*e),
            TypeRef::String(_) => Ty::Str,
            TypeRef::Array { dims, of } => {
                Ty::Array(dims.len(), Box::new(self.resolve_in(of, depth)?))
            }
            TypeRef::Named(n) => return self.named(n, depth),
        })
    }

    fn named(&self, n: &Ident, depth: usize) -> Result<Ty, StError> {
        let upper = n.name.to_ascii_uppercase();
        let unknown = || StError {
            span: n.span,
            kind: StErrorKind::UnknownType(n.name.clone()),
        };
        if self.structs.contains_key(&upper) {
            return Ok(Ty::Struct(upper));
        }
        if self.blocks.contains_key(&upper) || pins::is_block_type(&upper) {
            return Ok(Ty::Block(upper));
        }
        match self.aliases.get(&upper) {
            // An alias of an alias … deeper than 16 is a circle.
            Some(t) if depth < 16 => self.resolve_in(t, depth + 1),
            _ => Err(unknown()),
        }
    }

    /// The members of a value of type `ty` (a structure's, or a block's
    /// inputs and outputs), `None` when it has none.
    pub fn members(&self, ty: &Ty) -> Option<Vec<(String, Ty, bool)>> {
        match ty {
            Ty::Struct(n) => self.structs.get(n).map(|m| {
                m.iter()
                    .map(|(n, t)| (n.clone(), t.clone(), false))
                    .collect()
            }),
            Ty::Block(n) => match self.blocks.get(n) {
                Some(pins) => Some(
                    pins.iter()
                        .map(|(p, t, k)| (p.clone(), t.clone(), *k == VarKind::Output))
                        .collect(),
                ),
                None => {
                    let ins = pins::inputs(n).into_iter().map(|(p, t)| (p, t, false));
                    let outs = pins::outputs(n).into_iter().map(|(p, t)| (p, t, true));
                    Some(
                        ins.chain(outs)
                            .map(|(p, t, out)| (p.to_string(), elem_of(t.name()), out))
                            .collect(),
                    )
                }
            },
            _ => None,
        }
    }
}

/// The refusal at `span`.
pub fn at(span: Span, kind: StErrorKind) -> StError {
    StError { span, kind }
}
