//! "Declare as" (issue #49): the names a soft PLC box uses that nothing
//! declares, each with the type its use there needs, so the page can
//! declare one in a click. A contact's or coil's name needs no
//! declaration (it is a BOOL), nor does a box's instance (declared by its
//! kind) or an address.

use crate::iec::data::DataType;
use crate::iec::literal::literal_type;
use crate::ladder::block::{is_block_output, is_variable, BlockCall, Shape};
use crate::ladder::grid::{Ladder, Pos};
use crate::ladder::user_blocks as pins;

/// Each undeclared name the box at `pos` of rung index `rung` uses, with
/// the type it needs: its pin's when one type fits (a counter's PV:
/// INT), else the type of the box's other operands (a declared variable
/// or a typed literal), else INT, the word type a box computes in.
pub fn undeclared_in_box(ladder: &Ladder, rung: usize, pos: Pos) -> Vec<(String, DataType)> {
    let Some(call) = ladder
        .rungs
        .get(rung)
        .and_then(|r| r.get(pos))
        .and_then(|e| e.block())
    else {
        return Vec::new();
    };
    let mut out: Vec<(String, DataType)> = Vec::new();
    let kind = call.kind();
    let typed: Vec<_> = pins::inputs(&kind)
        .into_iter()
        .chain(pins::outputs(&kind))
        .collect();
    let shared = shared_type(ladder, call);
    for (pin, name) in call.inputs.iter().chain(&call.outputs) {
        if !needs_declaring(ladder, name) || out.iter().any(|(n, _)| n.eq_ignore_ascii_case(name)) {
            continue;
        }
        let own = typed
            .iter()
            .find(|(p, _)| p.eq_ignore_ascii_case(pin))
            .map(|(_, t)| *t);
        let ty = match call.shape() {
            Some(Shape::FunctionBlock) => own,
            _ => None,
        };
        out.push((name.clone(), ty.or(shared).unwrap_or(DataType::Int)));
    }
    out
}

/// Whether `name` is a plain name nothing declares: not an address, a
/// literal, an instance's output, a declared variable, a box's instance
/// or a contact's or coil's device.
fn needs_declaring(ladder: &Ladder, name: &str) -> bool {
    let name = name.trim();
    if name.starts_with('%') || !is_variable(name) || is_block_output(name) {
        return false;
    }
    let same = |other: &str| other.trim().eq_ignore_ascii_case(name);
    let declared = ladder.variables.iter().any(|v| same(&v.name));
    let used_as_bit = ladder.rungs.iter().any(|r| {
        r.elements().any(|(_, e)| {
            e.block().is_some_and(|b| same(&b.instance))
                || e.read_device().is_some_and(same)
                || e.written_device().is_some_and(same)
        })
    });
    !declared && !used_as_bit
}

/// The type a function's or comparison's operands already have: the
/// first declared variable's, else the first typed literal's.
fn shared_type(ladder: &Ladder, call: &BlockCall) -> Option<DataType> {
    let operands = || {
        call.inputs
            .iter()
            .chain(&call.outputs)
            .map(|(_, o)| o.trim())
    };
    let declared = operands().find_map(|o| {
        ladder
            .variables
            .iter()
            .find(|v| v.name.eq_ignore_ascii_case(o))
            .and_then(|v| v.elementary())
    });
    declared.or_else(|| operands().find_map(|o| literal_type(o).ok().and_then(|(_, t)| t)))
}

#[cfg(test)]
mod tests {
    use super::super::block_entry::parse_box;
    use super::*;
    use crate::ladder::grid::Rung;
    use crate::ladder::variables::Variable;

    fn ladder_with(text: &str, variables: Vec<Variable>) -> Ladder {
        let mut rung = Rung::default();
        rung.set(
            Pos { row: 0, col: 1 },
            Some(parse_box(text).expect("a box")),
        );
        rung.set(
            Pos { row: 0, col: 0 },
            Some(crate::ladder::element::Element::no("start")),
        );
        Ladder {
            rungs: vec![rung],
            variables,
            ..Ladder::default()
        }
    }

    #[test]
    fn an_undeclared_name_gets_the_type_its_use_needs() {
        let at = Pos { row: 0, col: 1 };
        // A counter's PV is an INT; its R is a BOOL; the instance c0 is
        // the box's own.
        let l = ladder_with("CTU c0 reset preset", Vec::new());
        assert_eq!(
            undeclared_in_box(&l, 0, at),
            [
                ("reset".to_string(), DataType::Bool),
                ("preset".to_string(), DataType::Int)
            ]
        );
        // A function's operands share the declared one's type.
        let l = ladder_with("ADD level 1 count", vec![Variable::new("level", "REAL")]);
        assert_eq!(
            undeclared_in_box(&l, 0, at),
            [("count".to_string(), DataType::Real)]
        );
        // With nothing to go by, a word: INT.
        let l = ladder_with("MOVE 42 count", Vec::new());
        assert_eq!(
            undeclared_in_box(&l, 0, at),
            [("count".to_string(), DataType::Int)]
        );
        // A contact's name, an address and a declared name need nothing.
        let l = ladder_with("CTU c0 start %IW0", Vec::new());
        assert!(undeclared_in_box(&l, 0, at).is_empty());
        // No box there: nothing.
        assert!(undeclared_in_box(&l, 0, Pos { row: 0, col: 0 }).is_empty());
        assert!(undeclared_in_box(&l, 5, at).is_empty());
    }
}
