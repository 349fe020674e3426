//! The soft PLC's boxes in the body's graph once it is read (issue
//! #31): a box feeding several rungs gets one of its own, boxes on the
//! rail each a rung, and the variables carrying one box's output into
//! another declared with their types.

use std::collections::{BTreeMap, HashMap};

use crate::formats::plcopen::declare::Names;
use crate::formats::plcopen::lower::body::{Body, Temp, RAIL};
use crate::iec::data::DataType;
use crate::iec::pins;
use crate::ladder::block::Shape;
use crate::ladder::element::Element;
use crate::ladder::grid::Pos;
use crate::ladder::net::{Edge, Net};
use crate::ladder::variables::Variable;
use crate::limits::MAX_NESTING;

impl Body {
    /// The soft PLC boxes (edge indices) whose power out leads to more
    /// than one group of outputs: each group's rung would call the box
    /// again, so the box gets a rung of its own into a BOOL whose contact
    /// gives its output where it went (`timer_through_relay`). Every
    /// point learns up to two of the outputs' points it leads to, walking
    /// back from those (linear in the body's size).
    pub(in crate::formats::plcopen) fn shared_boxes(&mut self) -> Vec<usize> {
        let mut back: Vec<Vec<usize>> = vec![Vec::new(); self.parent.len()];
        let mut boxes = Vec::new();
        for i in 0..self.edges.len() {
            let (a, b) = (self.edges[i].from, self.edges[i].to);
            let (a, b) = (self.find(a), self.find(b));
            back[b].push(a);
            if matches!(
                self.edges[i].net,
                Net::Leaf(Element::Block(_) | Element::Timer { .. }, _)
            ) {
                boxes.push((i, b));
            }
        }
        let outs: Vec<usize> = self.outputs.iter().map(|o| o.from).collect();
        let mut reaches: Vec<Vec<usize>> = vec![Vec::new(); self.parent.len()];
        let mut todo: Vec<(usize, usize)> = Vec::new();
        for from in outs {
            let bus = self.find(from);
            todo.push((bus, bus));
        }
        while let Some((p, bus)) = todo.pop() {
            if reaches[p].len() >= 2 || reaches[p].contains(&bus) {
                continue;
            }
            reaches[p].push(bus);
            todo.extend(back[p].iter().map(|&q| (q, bus)));
        }
        boxes
            .into_iter()
            .filter(|&(_, b)| reaches[b].len() >= 2)
            .map(|(i, _)| i)
            .collect()
    }
}

impl Body {
    /// Soft PLC output boxes on the rail (EN open or on the rail: they
    /// always run), each a rung of its own fed by a wire from the rail,
    /// as the editor draws one.
    #[allow(clippy::type_complexity)] // the groups and graph being built, named at the call
    pub(in crate::formats::plcopen) fn boxes_on_rail(
        &mut self,
        groups: &mut BTreeMap<usize, Vec<(Element, Pos, usize)>>,
        (edges, lines): (&mut Vec<Edge>, &mut HashMap<Pos, usize>),
    ) {
        let rail = self.find(RAIL);
        let all_boxes = groups.get(&rail).is_some_and(|outs| {
            outs.iter()
                .all(|(e, _, _)| matches!(e, Element::OutputBlock(_)))
        });
        if !all_boxes {
            return;
        }
        for (e, p, line) in groups.remove(&rail).unwrap_or_default() {
            let q = self.fresh();
            let at = Pos::new(p.row, p.col.wrapping_sub(1));
            lines.insert(at, line);
            edges.push(Edge {
                from: rail,
                to: q,
                net: Net::Leaf(Element::Wire, at),
            });
            groups.insert(q, vec![(e, p, line)]);
        }
    }
}

/// The variables `temps` carry, each declared with the type its box
/// gives: a conversion's target, a comparison's BOOL, a block's output
/// type, else its first typed operand's (a declared variable, a typed
/// literal, another such variable); an untyped number's DINT otherwise,
/// which the soft PLC's check of the compiled ladder then holds to.
/// Each is worked out once (a chain of boxes is linear work).
pub(in crate::formats::plcopen) fn temp_variables(temps: &[Temp], names: &Names) -> Vec<Variable> {
    let mut typing = Typing {
        temps,
        names,
        by_name: temps
            .iter()
            .enumerate()
            .map(|(k, t)| (t.name.as_str(), k))
            .collect(),
        known: vec![None; temps.len()],
    };
    (0..temps.len())
        .map(|k| {
            let t = &temps[k];
            let mut v = Variable::new(&t.name, typing.of(k, 0).name());
            v.comment = format!("{}'s {} (carried between boxes)", t.kind, t.pin);
            v
        })
        .collect()
}

/// The carried variables' types as they are worked out.
struct Typing<'a> {
    temps: &'a [Temp],
    names: &'a Names,
    by_name: HashMap<&'a str, usize>,
    known: Vec<Option<DataType>>,
}

impl Typing<'_> {
    /// The type of carried variable `k` (`depth`: boxes followed back).
    fn of(&mut self, k: usize, depth: usize) -> DataType {
        if let Some(t) = self.known[k] {
            return t;
        }
        let t = self.work_out(k, depth);
        self.known[k] = Some(t);
        t
    }

    fn work_out(&mut self, k: usize, depth: usize) -> DataType {
        let (temps, names) = (self.temps, self.names);
        let t = &temps[k];
        if let Some(to) = t
            .kind
            .split_once("_TO_")
            .and_then(|(_, to)| DataType::from_name(to))
        {
            return to;
        }
        match Shape::of(&t.kind) {
            Some(Shape::Compare) => return DataType::Bool,
            Some(Shape::FunctionBlock) => {
                let outputs = pins::outputs(&t.kind);
                if let Some((_, ty)) = outputs.into_iter().find(|(p, _)| *p == t.pin) {
                    return ty;
                }
            }
            _ => {}
        }
        for (pin, operand) in &t.inputs {
            if matches!(pin.as_str(), "G" | "N") {
                continue;
            }
            let operand = operand.trim();
            let found = match self.by_name.get(operand).copied() {
                Some(other) if depth < MAX_NESTING => Some(self.of(other, depth + 1)),
                Some(_) => None,
                None => names
                    .declared_type(operand)
                    .and_then(DataType::from_name)
                    .or_else(|| crate::iec::literal_type(operand).ok()?.1),
            };
            if let Some(ty) = found {
                return ty;
            }
        }
        DataType::Dint
    }
}
