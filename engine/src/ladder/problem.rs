//! A rung's wiring and placement problems as kinds with their arguments
//! (issue #49): the command line says them in English ([`fmt::Display`]),
//! the page in its own language from the kind.

use std::fmt;

use crate::limits::{MAX_NESTING, MAX_RUNG_CELLS};

/// Why a rung does not make a circuit (a [`super::LadderError`]'s typed
/// reason, beside its English message).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RungProblem {
    /// The rung has no coil or output box.
    NoOutput,
    /// An output left of the rung's last column.
    OutputNotLast,
    /// An element right of an output.
    AfterOutput,
    /// A vertical link off the rung's rows or columns.
    LinkPastRung,
    /// An output whose condition is not the first output's.
    OutputNotJoined,
    /// A wire joins both sides of an element.
    ShortCircuit,
    /// An output wired straight to the left rail.
    OutputOnRail,
    /// An element on no path from the rail to the outputs.
    Dangling,
    /// A wire on no such path.
    DanglingWire,
    /// No path of contacts reaches the output.
    NoPath,
    /// More cells than [`MAX_RUNG_CELLS`].
    TooLarge {
        /// Its rows.
        rows: usize,
        /// Its columns.
        width: usize,
    },
    /// A box input (its pin) in the box's own column.
    InputInBoxColumn(String),
    /// A box input (its pin) with no box above it.
    InputWithoutBox(String),
    /// A block without that Boolean input (block, pin, the inputs it
    /// takes; empty when none).
    NoBoolInput(String, String, String),
    /// A function's input wired as a network (the function).
    FunctionInput(String),
    /// An input given as an operand and as a network (block, pin).
    InputTwice(String, String),
    /// A link joining an input's network to the rows above (block, pin).
    InputLinkedAbove(String, String),
    /// A box input with no network left of it.
    InputWithoutNetwork,
    /// A bridge between branches (or a loop): not series-parallel.
    NotSeriesParallel,
    /// Series and parallel blocks nested deeper than [`MAX_NESTING`].
    TooDeep,
}

impl fmt::Display for RungProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RungProblem as P;
        match self {
            P::NoOutput => f.write_str("the rung has no output: end it with a coil or an output box"),
            P::OutputNotLast => {
                f.write_str("outputs must line up in the rung's last column: move this one right")
            }
            P::AfterOutput => {
                f.write_str("nothing may follow an output: coils and output boxes end the rung")
            }
            P::LinkPastRung => {
                f.write_str("a vertical link reaches past the rung's last row or column")
            }
            P::OutputNotJoined => f.write_str(
                "this output is not joined to the first output's condition: give it its own rung or link it",
            ),
            P::ShortCircuit => f.write_str("short circuit: a wire joins both sides of this element"),
            P::OutputOnRail => f.write_str(
                "the output is wired straight to the left rail: put a contact before it",
            ),
            P::Dangling => f.write_str(
                "dangling: this element is not on a path from the left rail to the outputs",
            ),
            P::DanglingWire => {
                f.write_str("dangling wire: it does not join the left rail to the outputs")
            }
            P::NoPath => f.write_str("no path of contacts joins the left rail to this output"),
            P::TooLarge { rows, width } => write!(
                f,
                "the rung spans {rows} rows and {width} columns, more than the {MAX_RUNG_CELLS} cells a rung may have (docs/limits.md)"
            ),
            P::InputInBoxColumn(pin) => {
                write!(f, "input {pin} stands below its box, in the box's column")
            }
            P::InputWithoutBox(pin) => write!(f, "input {pin} has no box above it"),
            P::NoBoolInput(kind, pin, takes) => {
                let list = if takes.is_empty() { "none" } else { takes };
                write!(
                    f,
                    "{kind} has no Boolean input {pin} to wire here (it takes {list})"
                )
            }
            P::FunctionInput(kind) => {
                write!(f, "{kind} is a function: its inputs are operands, not networks")
            }
            P::InputTwice(kind, pin) => write!(
                f,
                "{kind}'s {pin} is given twice: as an operand and as this network"
            ),
            P::InputLinkedAbove(kind, pin) => write!(
                f,
                "this link joins {kind}'s {pin} network to the rows above: keep it to its rows"
            ),
            P::InputWithoutNetwork => f.write_str("this input has no network"),
            P::NotSeriesParallel => f.write_str(
                "this network is not series-parallel (a bridge between branches): redraw it as series and parallel blocks",
            ),
            P::TooDeep => write!(
                f,
                "series and parallel blocks nest more than {MAX_NESTING} deep here (docs/limits.md)"
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::RungProblem;
    use crate::ladder::{analyse, Element, LadderErrorKind, Pos, Rung};

    #[test]
    fn a_wiring_problem_carries_its_kind_and_says_it_in_english() {
        let mut rung = Rung::default();
        rung.set(Pos::new(0, 0), Some(Element::coil("Y00")));
        rung.set(Pos::new(0, 2), Some(Element::no("X00")));
        let errors = analyse(&rung, 0).expect_err("a contact after the coil");
        let e = &errors[0];
        assert_eq!(
            e.problem.as_deref(),
            Some(&RungProblem::AfterOutput),
            "{e:?}"
        );
        assert_eq!(e.kind, LadderErrorKind::Placement);
        assert_eq!(
            e.message,
            "nothing may follow an output: coils and output boxes end the rung"
        );
        let mut empty_out = Rung::default();
        empty_out.set(Pos::new(0, 0), Some(Element::no("X00")));
        let errors = analyse(&empty_out, 2).expect_err("no output");
        assert_eq!(errors[0].problem.as_deref(), Some(&RungProblem::NoOutput));
        assert_eq!(
            errors[0].to_string(),
            format!("rung 3: {}", RungProblem::NoOutput)
        );
    }

    #[test]
    fn a_network_problem_says_the_networks_own_words() {
        use crate::ladder::net::NetError;
        let at = Pos::new(1, 2);
        for (problem, net) in [
            (
                RungProblem::NotSeriesParallel,
                NetError::NotSeriesParallel(at),
            ),
            (RungProblem::TooDeep, NetError::TooDeep(at)),
            (RungProblem::NoPath, NetError::NoPath),
        ] {
            assert_eq!(problem.to_string(), net.to_string());
        }
    }
}
