//! Untyped integer literals take the type their use needs (IEC 61131-3,
//! as every IL tool reads them): in `LD 40` / `ADD 2` / `ST %MW0` both
//! literals are INTs, because the store needs one. While the current
//! result is made of untyped literals only, the loader keeps where each
//! of them is (its step, its line, its value); the first use that needs
//! a type (a store, an operand, a comparison, a conversion) rewrites
//! them all at that type, and one that does not fit is refused at its
//! own line. With no typed use they stay what they were loaded as: a
//! DINT (or the first of LINT, ULINT that holds the value). A typed
//! literal (`INT#5`) keeps its type, and is refused where another is
//! needed.
//!
//! Loading stays about linear in the lines (issue #44): a run of
//! untyped literals (`LD 1` and N lines `ADD 1`) is rewritten only when
//! its type widens (DINT to LINT to ULINT: at most twice per literal),
//! not at every line, and runs are joined by copying the shorter into
//! the longer (each literal copied O(log N) times). Retyping and
//! copying the whole run at every line took N² (a minute for 20 000
//! lines in a debug build).

use std::collections::VecDeque;

use super::check::binary_type;
use super::said::Said;
use super::{Binary, LoadError, Program, Src, Step};
use crate::error::Located;
use crate::iec::data::{Data, DataType};
use crate::iec::il::{Line, Operand};
use crate::iec::literal::{in_range, LiteralError};

/// One untyped literal of the current result: where its constant is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Flex {
    /// The step holding it (maybe the one being resolved).
    pub step: usize,
    /// Which of its operands: `None` the line's operand, `Some(i)` a
    /// function's `i`-th.
    pub arg: Option<usize>,
    pub line: usize,
    pub value: i128,
}

/// The untyped literals a current result is made of, in the order they
/// were read (the order their errors are said in), all written as one
/// type: the widest default of them.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Pending {
    list: VecDeque<Flex>,
    at: DataType,
}

impl Default for Pending {
    fn default() -> Self {
        Pending {
            list: VecDeque::new(),
            at: DataType::Dint,
        }
    }
}

impl Pending {
    /// One literal, written (by [`Program::number`]) as its default.
    pub fn one(f: Flex) -> Pending {
        Pending {
            at: default_type(f.value),
            list: VecDeque::from([f]),
        }
    }

    /// Whether there are none (the current result's type is fixed).
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The type they are written as.
    pub fn at(&self) -> DataType {
        self.at
    }

    /// The first of them (all are written as one type).
    pub fn first(&self) -> Option<Flex> {
        self.list.front().copied()
    }

    /// None left (their type fixed, or the current result ended).
    pub fn clear(&mut self) {
        *self = Pending::default();
    }
}

/// A deferred operation `OP(` waiting for its `)`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Open {
    pub op: Binary,
    /// The current result's type before it, and its untyped literals.
    pub saved: Option<DataType>,
    pub flex: Pending,
    /// The line of the `(`.
    pub line: usize,
}

/// What the loader knows of the current result while it reads lines.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Flow {
    pub cr: Option<DataType>,
    /// The untyped literals it is made of (empty: its type is fixed).
    pub flex: Pending,
    pub open: Vec<Open>,
    /// Errors found at other lines than the one being read (a literal
    /// that does not fit the type a later line needs).
    pub late: Said,
    /// A line since the last LD or label was refused.
    pub refused: bool,
}

/// The type an untyped literal is with no typed use: DINT, or the first
/// of LINT, ULINT that holds it.
pub(super) fn default_type(v: i128) -> DataType {
    [DataType::Dint, DataType::Lint]
        .into_iter()
        .find(|&t| in_range(t, v).is_some())
        .unwrap_or(DataType::Ulint)
}

/// The widest of several defaults (all of one type together), DINT for
/// none.
fn widest(types: impl IntoIterator<Item = DataType>) -> DataType {
    let rank = |t: DataType| {
        [DataType::Dint, DataType::Lint, DataType::Ulint]
            .iter()
            .position(|&u| u == t)
    };
    types
        .into_iter()
        .max_by_key(|&t| rank(t))
        .unwrap_or(DataType::Dint)
}

/// `parts` one after another, the longest kept and the others copied
/// before or after it: a literal is only copied into a list at least
/// twice as long as the one it was in, so a run joined at every line
/// copies each literal O(log N) times, not the whole run each time.
fn concat(mut parts: Vec<VecDeque<Flex>>) -> VecDeque<Flex> {
    let Some(big) = (0..parts.len()).max_by_key(|&i| parts[i].len()) else {
        return VecDeque::new();
    };
    let after = parts.split_off(big + 1);
    let mut list = parts.pop().unwrap_or_default();
    for f in parts.into_iter().rev().flat_map(|p| p.into_iter().rev()) {
        list.push_front(f);
    }
    list.extend(after.into_iter().flatten());
    list
}

/// Untyped literal `v` as a `t`: `None` for a type no integer becomes.
fn as_type(v: i128, t: DataType, line: usize) -> Option<Result<Data, Located<LoadError>>> {
    if t == DataType::Real {
        return Some(Ok(Data::Real(v as f32)));
    }
    if t == DataType::Lreal {
        return Some(Ok(Data::Lreal(v as f64)));
    }
    t.bits()?;
    Some(in_range(t, v).ok_or_else(|| {
        Located::new(
            line,
            LoadError::Il(crate::iec::il::IlError::Literal(LiteralError::OutOfRange {
                text: v.to_string(),
                data_type: t,
            })),
        )
    }))
}

impl Program {
    /// The constant of untyped literal `v` where nothing needs a type.
    pub(super) fn number(v: i128) -> Src {
        Src::Const(Data::integer(default_type(v), v))
    }

    /// The untyped literals `flex` rewritten as `t`s, each that does not
    /// fit refused at its line (into `late`); nothing when no integer
    /// becomes a `t` (the caller's type check says why).
    pub(super) fn retype<'a>(
        &mut self,
        flex: impl IntoIterator<Item = &'a Flex>,
        t: DataType,
        late: &mut Said,
    ) {
        for f in flex {
            let Some(d) = as_type(f.value, t, f.line) else {
                return;
            };
            let d = match d {
                Ok(d) => d,
                Err(e) => {
                    late.push_new(e);
                    continue;
                }
            };
            if let Some(src) = self.place(f) {
                *src = Src::Const(d);
            }
        }
    }

    /// Where untyped literal `f`'s constant is in the steps.
    fn place(&mut self, f: &Flex) -> Option<&mut Src> {
        match (self.steps.get_mut(f.step), f.arg) {
            (Some(Step::Ld(src, _) | Step::Binary(_, src) | Step::Open(_, Some(src))), None) => {
                Some(src)
            }
            (Some(Step::Func(_, args)), Some(i)) => args.get_mut(i),
            _ => None,
        }
    }

    /// The type untyped literal `f` is written as now: once the lines
    /// are read, the type its run settled to (every literal of a run is
    /// rewritten together).
    pub(super) fn written(&mut self, f: &Flex) -> Option<DataType> {
        match self.place(f)? {
            Src::Const(d) => Some(d.data_type()),
            _ => None,
        }
    }

    /// `p`'s literals rewritten as `t` (the widest default of them and
    /// those they join), unless they are written so already: a run is
    /// rewritten when its type widens, at most twice, not at each line.
    fn widen(&mut self, p: &mut Pending, t: DataType, late: &mut Said) {
        if p.at != t {
            self.retype(&p.list, t, late);
            p.at = t;
        }
    }

    /// Untyped literals of several sides joined (in order), all of them
    /// at the widest default.
    pub(super) fn merge(&mut self, parts: Vec<Pending>, late: &mut Said) -> Pending {
        let t = widest(parts.iter().filter(|p| !p.is_empty()).map(|p| p.at));
        let mut lists = Vec::with_capacity(parts.len());
        for mut p in parts {
            self.widen(&mut p, t, late);
            lists.push(p.list);
        }
        Pending {
            list: concat(lists),
            at: t,
        }
    }

    /// The current result (untyped literals, if it is made of them) now
    /// needed as a `t`: its literals rewritten, its type fixed.
    pub(super) fn settle(&mut self, flow: &mut Flow, t: DataType) {
        if flow.flex.is_empty() {
            return;
        }
        let flex = std::mem::take(&mut flow.flex);
        self.retype(&flex.list, t, &mut flow.late);
        if becomes(t) {
            flow.cr = Some(t);
        }
    }

    /// The line's operand, if it has one, as a `want` (where the place
    /// needs one): an untyped literal taken at `want` (refused when it
    /// does not fit), anything else as it is.
    pub(super) fn fitted(
        &mut self,
        operand: &Operand,
        want: DataType,
        line: usize,
    ) -> Result<Src, LoadError> {
        match operand {
            Operand::Number(v) => match as_type(*v, want, line) {
                Some(d) => d.map(Src::Const).map_err(|e| e.error),
                None => Ok(Program::number(*v)),
            },
            // A typed literal keeps its type: where another is needed it
            // is refused, whether or not its value would fit.
            Operand::Literal(d) if d.data_type() != want => Err(LoadError::Il(
                crate::iec::il::IlError::Literal(LiteralError::WrongType {
                    text: d.to_string(),
                    expected: want,
                }),
            )),
            _ => self.slot(operand),
        }
    }

    /// Joins the current result with `operands` (each with its place:
    /// `None` the line's operand, `Some(i)` a function's `i`-th; their
    /// sources in `srcs`) for an operation that needs them of one type:
    /// untyped literals take the type of the typed side, or all the
    /// widest default when every side is untyped (and stay untyped in
    /// `flow.flex`). The type they share.
    pub(super) fn join(
        &mut self,
        flow: &mut Flow,
        line: &Line,
        operands: &[(Option<usize>, &Operand)],
        srcs: &mut [Src],
    ) -> Result<DataType, LoadError> {
        let typed = operands
            .iter()
            .zip(srcs.iter())
            .find(|((_, o), _)| !matches!(o, Operand::Number(_)))
            .map(|(_, s)| self.type_of(s));
        let want = if flow.flex.is_empty() && flow.cr.is_some() {
            flow.cr
        } else if let Some(t) = typed {
            if becomes(t) {
                self.settle(flow, t);
                Some(t)
            } else {
                // Literals cannot be a `t`: the caller's check says so.
                flow.flex.clear();
                flow.cr.or(Some(t))
            }
        } else {
            None
        };
        let t = match want {
            Some(t) => t,
            None => {
                let step = self.steps.len();
                let new: VecDeque<Flex> = operands
                    .iter()
                    .filter_map(|&(arg, o)| match o {
                        Operand::Number(v) => Some(Flex {
                            step,
                            arg,
                            line: line.line,
                            value: *v,
                        }),
                        _ => None,
                    })
                    .collect();
                let run = (!flow.flex.is_empty()).then_some(flow.flex.at);
                let t = widest(
                    run.into_iter()
                        .chain(new.iter().map(|f| default_type(f.value))),
                );
                self.widen(&mut flow.flex, t, &mut flow.late);
                // The line's own literals always, as every literal of
                // the run was before: each that does not fit is said.
                self.retype(&new, t, &mut flow.late);
                flow.flex.list.extend(new);
                t
            }
        };
        for ((_, o), s) in operands.iter().zip(srcs.iter_mut()) {
            *s = self.fitted(o, t, line.line)?;
        }
        flow.cr = Some(t);
        Ok(t)
    }

    /// `)`: the deferred operation applied to what its parentheses
    /// left, the two sides' untyped literals joined.
    pub(super) fn close(&mut self, flow: &mut Flow) -> Result<Step, LoadError> {
        let open = flow.open.pop().ok_or(LoadError::Unbalanced)?;
        let saved = super::check::need_cr(open.saved)?;
        let inner = super::check::need_cr(flow.cr)?;
        let (a, b) = match (open.flex.is_empty(), flow.flex.is_empty()) {
            (true, true) => (saved, inner),
            (false, true) if becomes(inner) => {
                self.retype(&open.flex.list, inner, &mut flow.late);
                (inner, inner)
            }
            (false, true) => (saved, inner),
            (true, false) => {
                self.settle(flow, saved);
                (saved, super::check::need_cr(flow.cr)?)
            }
            (false, false) => {
                let inner = std::mem::take(&mut flow.flex);
                flow.flex = self.merge(vec![inner, open.flex], &mut flow.late);
                (flow.flex.at, flow.flex.at)
            }
        };
        let result = binary_type(open.op, a, b)?;
        if matches!(open.op, Binary::Cmp(_)) {
            flow.flex.clear();
        }
        flow.cr = Some(result);
        Ok(Step::Close)
    }
}

/// Whether an integer literal can be a `t` (an integer type or REAL).
pub(super) fn becomes(t: DataType) -> bool {
    t.bits().is_some() || matches!(t, DataType::Real | DataType::Lreal)
}
