//! The element operand (`LD st_v1[i:1:3:2,j:0:2:1]`, `ST …`): Structured
//! Text's array element at an index known only when the scan runs. The
//! lowering flattens an array into consecutive slots; this operand names
//! the first element a pattern reaches and, for each run-time index, the
//! index variable, its dimension's low bound and length, and the slots
//! between one index and the next (the stride). The scan computes the
//! slot; an index outside its dimension stops the scan there
//! ([`Program::fault`]), as an IEC runtime's exception stops its task.

use super::check::{invertible, need_cr};
use super::flex::{Flow, Pending};
use super::why::TypeWhy;
use super::{LoadError, Named, Program, Step};
use crate::iec::data::Data;
use crate::iec::il::{Line, Operand, Operator};

/// An element operand, resolved.
#[derive(Clone, Debug, PartialEq)]
pub(in crate::softplc) struct Element {
    /// The slot of the element every index at its low bound reaches.
    first: usize,
    /// Each run-time index: its variable's slot, low bound, length and
    /// stride.
    dims: Vec<(usize, i64, i64, usize)>,
}

impl Element {
    /// The slot the indices' values reach, or `None` when one is outside
    /// its dimension (or not an integer).
    #[inline(always)]
    pub(in crate::softplc) fn slot(&self, values: &[Data]) -> Option<usize> {
        let mut at = self.first;
        for &(index, low, len, stride) in &self.dims {
            let Some(Data::Int(_, v)) = values.get(index) else {
                return None;
            };
            let k = v.checked_sub(low)?;
            if !(0..len).contains(&k) {
                return None;
            }
            at += usize::try_from(k).ok()? * stride;
        }
        Some(at)
    }
}

impl Program {
    /// `text` (`first[i:low:len:stride,…]`) resolved: every slot it can
    /// reach declared and of one type, every index an integer variable.
    pub(super) fn element(&self, text: &str) -> Result<Element, LoadError> {
        let bad = || LoadError::BadElement(text.to_string());
        let (name, rest) = text.split_once('[').ok_or_else(bad)?;
        let dims_text = rest.strip_suffix(']').ok_or_else(bad)?;
        let slot_of = |n: &str| match self.by_name.get(&n.to_ascii_uppercase()) {
            Some(Named::Slot(s)) => Ok(*s),
            _ => Err(LoadError::Undeclared(n.to_string())),
        };
        let first = slot_of(name)?;
        let mut dims = Vec::new();
        for d in dims_text.split(',') {
            let parts: Vec<&str> = d.split(':').collect();
            let [index, low, len, stride] = parts.as_slice() else {
                return Err(bad());
            };
            let index = slot_of(index)?;
            if !matches!(self.values[index], Data::Int(..)) {
                return Err(bad());
            }
            let low = low.parse::<i64>().map_err(|_| bad())?;
            let len = len.parse::<u32>().map_err(|_| bad())?;
            let stride = stride.parse::<u32>().map_err(|_| bad())?;
            dims.push((index, low, i64::from(len), stride as usize));
        }
        let e = Element { first, dims };
        self.same_type(&e).ok_or_else(bad)?;
        Ok(e)
    }

    /// Whether every slot `e` reaches exists and has its first's type
    /// (at most the lowering's 4096 values per variable are walked).
    fn same_type(&self, e: &Element) -> Option<()> {
        let ty = self.values.get(e.first)?.data_type();
        let mut reach = vec![e.first];
        for &(_, _, len, stride) in &e.dims {
            let mut next = Vec::new();
            for &at in &reach {
                for k in 0..usize::try_from(len).ok()? {
                    next.push(at.checked_add(k.checked_mul(stride)?)?);
                }
                if next.len() > 4096 {
                    return None;
                }
            }
            reach = next;
        }
        reach
            .iter()
            .all(|&s| self.values.get(s).is_some_and(|v| v.data_type() == ty))
            .then_some(())
    }

    /// The type of what `e` reaches.
    pub(super) fn element_type(&self, e: &Element) -> crate::iec::data::DataType {
        self.values[e.first].data_type()
    }
}

/// Whether `line` is an LD or ST of an element operand.
pub(super) fn is_element_line(line: &Line) -> bool {
    matches!(&line.operand, Some(Operand::Name(n)) if n.contains('['))
}

impl Program {
    /// `LD a[…]` (`LDN` too) or `ST a[…]`: its step, the current result's
    /// type checked as a variable's.
    pub(super) fn element_step(&mut self, line: &Line, flow: &mut Flow) -> Result<Step, LoadError> {
        let Some(Operand::Name(text)) = &line.operand else {
            return Err(LoadError::Unbalanced);
        };
        let e = self.element(text)?;
        let t = self.element_type(&e);
        if line.negated {
            invertible(
                if line.operator == Operator::Ld {
                    "LDN"
                } else {
                    "STN"
                },
                t,
            )?;
        }
        if line.operator == Operator::Ld {
            flow.cr = Some(t);
            flow.flex = Pending::default();
            return Ok(Step::LdAt(Box::new(e), line.negated));
        }
        need_cr(flow.cr)?;
        self.settle(flow, t);
        let cr = need_cr(flow.cr)?;
        if cr != t || line.negated {
            let what = text.clone();
            return Err(LoadError::Type(TypeWhy::Store {
                current: cr,
                what,
                needs: t,
            }));
        }
        Ok(Step::StAt(Box::new(e)))
    }
}
