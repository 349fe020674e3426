//! The loader's checks that need no program: the current result's type,
//! jumps to labels, block pins by name, an operation's result type.

use std::collections::HashMap;

use super::{Binary, LoadError, Step};
use crate::iec::data::{Arith, DataType};
use crate::iec::il::{Line, Operand};

/// The current result's type, where an instruction needs one.
pub(super) fn need_cr(cr: Option<DataType>) -> Result<DataType, LoadError> {
    cr.ok_or(LoadError::UnknownResult)
}

/// Whether `op` (LDN, STN, NOT) can invert a `t`: a BOOL or a bit
/// string can, a REAL, TIME or STRING cannot.
pub(super) fn invertible(op: &str, t: DataType) -> Result<(), LoadError> {
    if t.bits().is_none() && t != DataType::Bool {
        return Err(LoadError::NotBits(op.to_string(), t));
    }
    Ok(())
}

/// JMP, JMPC, JMPCN to a label of `lines`.
pub(super) fn jump(
    line: &Line,
    labels: &HashMap<String, usize>,
    cr: &mut Option<DataType>,
) -> Result<Step, LoadError> {
    if line.condition.is_some() && need_cr(*cr)? != DataType::Bool {
        return Err(LoadError::NeedsBool("JMPC"));
    }
    let Some(Operand::Name(label)) = &line.operand else {
        return Err(LoadError::NoLabel(String::new()));
    };
    let &target = labels
        .get(&label.to_ascii_uppercase())
        .ok_or_else(|| LoadError::NoLabel(label.clone()))?;
    if line.condition.is_none() {
        *cr = None;
    }
    Ok(Step::Jmp(line.condition, target))
}

/// A block parameter's place in `pins` and its type, by name (any case).
pub(super) fn find_pin(pins: &[(&str, DataType)], name: &str) -> Option<(usize, DataType)> {
    pins.iter()
        .position(|(p, _)| p.eq_ignore_ascii_case(name))
        .map(|i| (i, pins[i].1))
}

pub(super) fn describe(o: &Operand) -> String {
    match o {
        Operand::Name(n) => n.clone(),
        Operand::Address(a) => a.to_string(),
        Operand::Literal(_) | Operand::Number(_) | Operand::Text(_) => "a literal".into(),
    }
}

/// The type an operation gives for operands of types `a` and `b`, or why
/// it does not apply.
pub(super) fn binary_type(op: Binary, a: DataType, b: DataType) -> Result<DataType, LoadError> {
    if a != b {
        return Err(LoadError::Mix(a, b));
    }
    let fits = match op {
        Binary::Logic(..) => a == DataType::Bool || a.bits().is_some(),
        Binary::Arith(Arith::Add | Arith::Sub) => !matches!(a, DataType::Bool | DataType::String),
        Binary::Arith(Arith::Mod) => a.bits().is_some(),
        Binary::Arith(_) => a.bits().is_some() || matches!(a, DataType::Real | DataType::Lreal),
        Binary::Cmp(_) => true,
    };
    if !fits {
        return Err(LoadError::NotFor(a));
    }
    Ok(if matches!(op, Binary::Cmp(_)) {
        DataType::Bool
    } else {
        a
    })
}
