//! The types of a body's function outputs, found before any element is
//! emitted. An element in a loop of wires runs reading what the loop
//! left in the last scan (docs/soft-plc.md), so the first element of a
//! loop reads an output not written yet: its type has to be known from
//! the drawing (a conversion's target, a comparison's BOOL, an ADD's
//! typed input), not from the output's emission.

use std::collections::HashMap;

use super::declare::Interface;
use crate::formats::plcopen::graph::{order, Element, Graph, Kind, Source};
use crate::iec::data::DataType;
use crate::iec::functions::{Function, Operand};
use crate::iec::pins::outputs as fb_outputs;

/// Passes over the body's functions at most: each pass settles every
/// function whose inputs are settled, so a drawing needs one per loop
/// nested in another; past this, the loop is refused as before (its type
/// is not known).
const MAX_PASSES: usize = 64;

/// The type of a standard block's output pin, if fixed.
pub(super) fn output_type(type_name: &str, pin: &str) -> Option<DataType> {
    if pin.eq_ignore_ascii_case("ENO") {
        return Some(DataType::Bool);
    }
    fb_outputs(&type_name.to_ascii_uppercase())
        .iter()
        .find(|(p, _)| p.eq_ignore_ascii_case(pin))
        .map(|(_, t)| *t)
}

/// The EN of the block feeding output variable `e`, when it has one
/// wired (its `_n<id>_EN` copy).
pub(super) fn guard(g: &Graph, e: &Element, index: usize) -> Option<String> {
    let [s] = e.inputs.first()?.1.as_slice() else {
        return None;
    };
    let from = &g.elements[*g.by_id.get(&s.from)?];
    if !matches!(from.kind, Kind::Block { .. }) || s.pin.as_deref() == Some("ENO") {
        return None;
    }
    let wired = from
        .inputs
        .iter()
        .any(|(p, s)| p.eq_ignore_ascii_case("EN") && !s.is_empty());
    wired.then(|| format!("_{}_n{}_EN", index, from.id))
}

/// The output a wire from block `e` that names no pin reads: the first
/// that is not ENO, or ENO when it has no other (CODESYS's EXECUTE).
pub(super) fn unnamed_output(e: &Element) -> Option<String> {
    let mut pins = e.outputs.iter();
    pins.find(|p| *p != "ENO").or(e.outputs.first()).cloned()
}

/// A function's output pin as the file names it (`OUT` when it names
/// none).
pub(super) fn function_output(e: &Element) -> String {
    e.outputs
        .iter()
        .find(|p| !p.eq_ignore_ascii_case("ENO"))
        .cloned()
        .unwrap_or_else(|| "OUT".into())
}

/// What the types are found from: the type of a variable, address or
/// literal as the file writes it (`None`: not one; `Some(None)`: an
/// untyped literal), and the project's own blocks by type (upper-case).
pub(super) struct Known<'a> {
    pub operand: &'a dyn Fn(&str) -> Option<Option<DataType>>,
    pub user: &'a HashMap<String, Interface>,
}

/// The output type of every function of `g` (the body's place `index`)
/// the drawing settles, by its output variable's name (`_<index>_n<id>_OUT`).
pub(super) fn output_types(em: &Known, g: &Graph, index: usize) -> Vec<(String, DataType)> {
    let functions: Vec<(usize, Function)> = order(g)
        .into_iter()
        .filter_map(|i| match &g.elements[i].kind {
            Kind::Block { type_name, .. } => {
                Function::named(&type_name.to_ascii_uppercase()).map(|f| (i, f))
            }
            _ => None,
        })
        .collect();
    let mut known: HashMap<&str, DataType> = HashMap::new();
    for _ in 0..MAX_PASSES {
        let before = known.len();
        for &(i, f) in &functions {
            let e = &g.elements[i];
            if known.contains_key(e.id.as_str()) {
                continue;
            }
            if let Some(t) = settled(em, g, e, f, &known) {
                known.insert(&e.id, t);
            }
        }
        if known.len() == before {
            break;
        }
    }
    known
        .into_iter()
        .map(|(id, t)| {
            let e = &g.elements[g.by_id[id]];
            (format!("_{index}_n{id}_{}", function_output(e)), t)
        })
        .collect()
}

/// Function `f`'s result type at `e`, if its inputs settle it.
fn settled(
    em: &Known,
    g: &Graph,
    e: &Element,
    f: Function,
    known: &HashMap<&str, DataType>,
) -> Option<DataType> {
    match f {
        Function::Convert(_, to) => return Some(to),
        Function::Compare(_) => return Some(DataType::Bool),
        _ => {}
    }
    let inputs: Vec<&(String, Vec<Source>)> = e
        .inputs
        .iter()
        .filter(|(p, _)| !p.eq_ignore_ascii_case("EN"))
        .collect();
    // The inputs that give the function its type (SEL's G does not).
    let data = match f {
        Function::Sel => 1..inputs.len(),
        Function::Shift(_) => 0..inputs.len().min(1),
        _ => 0..inputs.len(),
    };
    let mut typed = false;
    let mut args = Vec::new();
    for (n, (pin, sources)) in inputs.iter().enumerate() {
        let ty = match sources.as_slice() {
            [s] => source_type(em, g, s, known, 0),
            // A wired OR of several: a BOOL.
            [_, _, ..] => Some(Some(DataType::Bool)),
            [] => None,
        };
        typed |= data.contains(&n) && matches!(ty, Some(Some(_)));
        let operand = Operand {
            text: "0".into(),
            ty: ty.flatten(),
            literal: !matches!(ty, Some(Some(_))),
        };
        args.push((pin.clone(), operand));
    }
    if !typed {
        return None;
    }
    f.code(&args, None).ok().map(|(_, t)| t)
}

/// The type of what `s` carries: `None` not known yet, `Some(None)` an
/// untyped literal.
fn source_type(
    em: &Known,
    g: &Graph,
    s: &Source,
    known: &HashMap<&str, DataType>,
    depth: usize,
) -> Option<Option<DataType>> {
    let from = &g.elements[*g.by_id.get(&s.from)?];
    match &from.kind {
        Kind::LeftRail | Kind::Contact { .. } | Kind::Coil { .. } => Some(Some(DataType::Bool)),
        Kind::InVariable(x) | Kind::InOutVariable(x) => (em.operand)(x),
        Kind::Continuation(name) if depth <= crate::limits::MAX_CONNECTOR_CHAIN => {
            let c = &g.elements[*g.connectors.get(&name.to_ascii_lowercase())?];
            match c.inputs.first()?.1.as_slice() {
                [s] => source_type(em, g, s, known, depth + 1),
                _ => None,
            }
        }
        Kind::Block { type_name, .. } => {
            let pin = s.pin.clone().unwrap_or_else(|| function_output(from));
            output_type(type_name, &pin)
                .or_else(|| em.user.get(&type_name.to_ascii_uppercase())?.pin(&pin))
                .or_else(|| known.get(from.id.as_str()).copied())
                .map(Some)
        }
        _ => None,
    }
}
