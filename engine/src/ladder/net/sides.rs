//! A soft PLC block's other Boolean inputs wired as contact networks
//! (issue #31), as OpenPLC and GX Works draw a counter's reset: the box
//! stands in its rung's condition, and below it, in its column, a cell
//! [`Element::BoxInput`] for each further input (`R`, `LD`, `R1`), fed by
//! the network to its left on its own rows.
//!
//! [`split`] takes those networks off the grid before the rung is read:
//! each becomes a [`Side`] (its network, computed into a BOOL of its own
//! before the rung runs), and the box is given that BOOL at the pin. A
//! side network keeps to its rows: a link joining it to the rows above
//! (the box's own power) is refused at the link's cell.

use std::collections::HashMap;

use crate::iec::data::DataType;
use crate::ladder::block::Shape;
use crate::ladder::element::Element;
use crate::ladder::grid::{LadderError, LadderErrorKind, Link, Pos, Rung};
use crate::ladder::problem::RungProblem;

use super::Net;

/// One box input's network.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Side {
    /// The network, its leaves at their cells of the rung.
    pub net: Net,
    /// The BOOL it is computed into (`_c0_R`), which the box reads.
    pub variable: String,
    /// The input's cell.
    pub pos: Pos,
}

impl Side {
    /// The network as a rung of its own: its condition driving a coil on
    /// the BOOL the box reads (how the compiler and the PLCopen export
    /// write it, before the box's rung).
    pub fn as_rung(&self) -> super::RungLogic {
        super::RungLogic {
            condition: self.net.clone(),
            outputs: vec![(Element::coil(&self.variable), self.pos)],
            comment: String::new(),
            sides: Vec::new(),
        }
    }
}

/// The BOOL that carries box `instance`'s input `pin` (`_c0_R`).
pub fn carrier(instance: &str, pin: &str) -> String {
    format!("_{}_{}", instance.trim(), pin.to_ascii_uppercase())
}

/// Joins to their boxes the networks other readers write as rungs of
/// their own (the compiled IL, a PLCopen export, a PLCopen reader): a
/// rung whose one output is a coil on a box input's carrier (`_c0_R`,
/// [`carrier`]) that a box reads at that pin, and that nothing else
/// writes or reads, becomes that box's [`Side`], where it can be drawn
/// under the box ([`super::sides_fit`]). Returns the indices of the
/// rungs joined (for the caller to drop), in order.
pub fn attach_sides(rungs: &mut [super::RungLogic]) -> Vec<usize> {
    // Each name's uses, and the rung whose box reads each carrier: one
    // pass over the ladder.
    let mut uses: HashMap<String, usize> = HashMap::new();
    let mut readers: HashMap<String, usize> = HashMap::new();
    for (j, r) in rungs.iter().enumerate() {
        let elements = r.leaves().into_iter().map(|(e, _)| e);
        for e in elements.chain(r.outputs.iter().map(|(e, _)| e)) {
            for name in names(e) {
                *uses.entry(name.to_ascii_uppercase()).or_default() += 1;
            }
            for carried in e.block().map(carried_inputs).unwrap_or_default() {
                readers.insert(carried, j);
            }
        }
    }
    let mut joined = Vec::new();
    for i in 0..rungs.len() {
        let Some((device, pos)) = carrier_coil(&rungs[i]) else {
            continue;
        };
        let key = device.to_ascii_uppercase();
        // The coil and the box's operand, nothing else.
        let (Some(2), Some(&j)) = (uses.get(&key).copied(), readers.get(&key)) else {
            continue;
        };
        if j == i {
            continue;
        }
        let side = Side {
            net: rungs[i].condition.clone(),
            variable: device,
            pos,
        };
        let mut with = rungs[j].clone();
        with.sides.push(side);
        if super::sides_fit(&with) {
            rungs[j] = with;
            joined.push(i);
        }
    }
    joined
}

/// The carrier a rung's only output, a plain coil, writes.
fn carrier_coil(r: &super::RungLogic) -> Option<(String, Pos)> {
    match r.outputs.as_slice() {
        [(Element::Coil { kind, device }, pos)]
            if *kind == crate::ladder::element::CoilKind::Normal
                && device.starts_with('_')
                && r.sides.is_empty() =>
        {
            Some((device.trim().to_string(), *pos))
        }
        _ => None,
    }
}

/// The names element `e` reads or writes (a contact's, a coil's, a
/// box's operands).
fn names(e: &Element) -> Vec<&str> {
    match e.block() {
        Some(b) => b
            .inputs
            .iter()
            .chain(&b.outputs)
            .map(|(_, o)| o.trim())
            .collect(),
        None => e.read_device().or(e.written_device()).into_iter().collect(),
    }
}

/// The carriers box `b` reads (upper case): its Boolean inputs a network
/// may feed, given the BOOL named for that input ([`carrier`]).
fn carried_inputs(b: &crate::ladder::BlockCall) -> Vec<String> {
    crate::ladder::block::block_data_inputs(&b.kind())
        .iter()
        .filter(|(_, t)| *t == DataType::Bool)
        .filter_map(|(pin, _)| {
            let carrier = carrier(&b.instance, pin);
            b.input(pin)
                .filter(|o| o.eq_ignore_ascii_case(&carrier))
                .map(|_| carrier.to_ascii_uppercase())
        })
        .collect()
}

/// The rung without its box inputs' networks, each box given the
/// BOOLs that carry them, and the networks; `None` when it has none.
pub(super) fn split(
    rung: &Rung,
    index: usize,
) -> Result<Option<(Rung, Vec<Side>)>, Vec<LadderError>> {
    let pins: Vec<(Pos, String)> = rung
        .elements()
        .filter_map(|(p, e)| match e {
            Element::BoxInput { pin } => Some((p, pin.clone())),
            _ => None,
        })
        .collect();
    if pins.is_empty() {
        return Ok(None);
    }
    let mut main = rung.clone();
    let mut sides = Vec::new();
    let mut errors = Vec::new();
    for (pos, pin) in pins {
        match side(rung, &mut main, index, pos, &pin) {
            Ok(s) => sides.push(s),
            Err(e) => errors.extend(e),
        }
    }
    if errors.is_empty() {
        Ok(Some((main, sides)))
    } else {
        Err(errors)
    }
}

fn at(index: usize, pos: Pos, problem: RungProblem) -> Vec<LadderError> {
    vec![LadderError::wiring(
        index,
        Some(pos),
        LadderErrorKind::Wiring,
        problem,
    )]
}

/// The box above the input at `pos`, in its column (other inputs of it
/// between): its row.
fn box_above(rung: &Rung, pos: Pos) -> Option<usize> {
    for row in (0..pos.row).rev() {
        match rung.get(Pos::new(row, pos.col)) {
            Some(Element::BoxInput { .. }) => continue,
            Some(e) if e.block().is_some() => return Some(row),
            _ => return None,
        }
    }
    None
}

/// Input `pin` at `pos`: checked against its box, its network read off
/// `rung` and taken out of `main` (whose box gets the carrier).
fn side(
    rung: &Rung,
    main: &mut Rung,
    index: usize,
    pos: Pos,
    pin: &str,
) -> Result<Side, Vec<LadderError>> {
    let Some(box_row) = box_above(rung, pos) else {
        return Err(at(index, pos, RungProblem::InputInBoxColumn(pin.into())));
    };
    let box_pos = Pos::new(box_row, pos.col);
    let Some(call) = rung.get(box_pos).and_then(Element::block).cloned() else {
        return Err(at(index, pos, RungProblem::InputWithoutBox(pin.into())));
    };
    let kind = call.kind();
    let takes: Vec<&str> = crate::ladder::block::block_data_inputs(&kind)
        .iter()
        .filter(|(_, t)| *t == DataType::Bool)
        .map(|(p, _)| *p)
        .collect();
    let Some(pin) = takes.iter().find(|p| p.eq_ignore_ascii_case(pin)) else {
        let why = match call.shape() {
            Some(Shape::FunctionBlock) => {
                RungProblem::NoBoolInput(kind.to_string(), pin.into(), takes.join(", "))
            }
            _ => RungProblem::FunctionInput(kind.to_string()),
        };
        return Err(at(index, pos, why));
    };
    if call.input(pin).is_some() {
        return Err(at(
            index,
            pos,
            RungProblem::InputTwice(kind.to_string(), pin.to_string()),
        ));
    }
    let rows = side_rows(rung, pos);
    if let Some(link) = rung
        .links
        .iter()
        .find(|l| l.row + 1 == pos.row && l.col <= pos.col && l.col > 0)
    {
        let cell = Pos::new(link.row, link.col);
        return Err(at(
            index,
            cell,
            RungProblem::InputLinkedAbove(kind.to_string(), pin.to_string()),
        ));
    }
    let variable = carrier(&call.instance, pin);
    let net = read_side(rung, index, pos, rows.clone(), &variable)?;
    take_out(main, pos, rows);
    if let Some(Element::Block(b) | Element::OutputBlock(b)) = main
        .cells
        .get_mut(box_pos.row)
        .and_then(|r| r.get_mut(box_pos.col))
        .and_then(Option::as_mut)
    {
        b.inputs.push((pin.to_string(), variable.clone()));
    }
    Ok(Side { net, variable, pos })
}

/// The rows of the network at `pos`: its own, and those below it that
/// links join to it left of the input (up to another input's row).
fn side_rows(rung: &Rung, pos: Pos) -> std::ops::RangeInclusive<usize> {
    let mut last = pos.row;
    while rung.links.iter().any(|l| l.row == last && l.col <= pos.col)
        && !matches!(
            rung.get(Pos::new(last + 1, pos.col)),
            Some(Element::BoxInput { .. })
        )
        && last + 1 < rung.cells.len()
    {
        last += 1;
    }
    pos.row..=last
}

/// The network of rows `rows` left of the input at `pos`, read as a rung
/// of its own ending in a coil on `variable`; its cells and errors at
/// their places in the rung.
fn read_side(
    rung: &Rung,
    index: usize,
    pos: Pos,
    rows: std::ops::RangeInclusive<usize>,
    variable: &str,
) -> Result<Net, Vec<LadderError>> {
    let top = *rows.start();
    let mut own = Rung::default();
    for row in rows.clone() {
        let cells = rung.cells.get(row).map_or(&[][..], |r| r.as_slice());
        let mut left: Vec<Option<Element>> = cells.iter().take(pos.col).cloned().collect();
        left.resize(pos.col, None);
        own.cells.push(left);
    }
    if let Some(first) = own.cells.first_mut() {
        first.push(Some(Element::coil(variable)));
    }
    own.links = rung
        .links
        .iter()
        .filter(|l| rows.contains(&l.row) && l.row < *rows.end() && l.col <= pos.col)
        .map(|l| Link {
            row: l.row - top,
            col: l.col,
        })
        .collect();
    let back = |p: Pos| Pos::new(p.row + top, p.col);
    match super::analyse(&own, index) {
        Ok(Some(logic)) => Ok(shifted(logic.condition, &back)),
        Ok(None) => Err(at(index, pos, RungProblem::InputWithoutNetwork)),
        Err(errors) => Err(errors
            .into_iter()
            .map(|mut e| {
                e.pos = e.pos.map(back);
                e
            })
            .collect()),
    }
}

fn shifted(net: Net, back: &impl Fn(Pos) -> Pos) -> Net {
    match net {
        Net::Leaf(e, p) => Net::Leaf(e, back(p)),
        Net::Series(v) => Net::Series(v.into_iter().map(|n| shifted(n, back)).collect()),
        Net::Parallel(v) => Net::Parallel(v.into_iter().map(|n| shifted(n, back)).collect()),
    }
}

/// Empties the network's cells (and the input's) and its links in `main`.
fn take_out(main: &mut Rung, pos: Pos, rows: std::ops::RangeInclusive<usize>) {
    for row in rows.clone() {
        if let Some(cells) = main.cells.get_mut(row) {
            for cell in cells.iter_mut().take(pos.col + 1) {
                *cell = None;
            }
        }
    }
    main.links
        .retain(|l| !(rows.contains(&l.row) && l.row < *rows.end() && l.col <= pos.col));
}

#[cfg(test)]
mod tests {
    use crate::events::InputValue;
    use crate::ladder::compile::{compile, Options};
    use crate::ladder::edit::{parse_entry, Cursor, Edit, Editor, EntryKind};
    use crate::ladder::{Element, Ladder};
    use crate::machines::SoftPlc;
    use crate::plc::{Command, Plc};
    use crate::{MachineId, SimTime};

    fn entry(text: &str) -> Element {
        parse_entry(MachineId::SoftPlc, EntryKind::Instruction, text).expect(text)
    }

    /// `%IX0.0 → [c0: CTU PV 3] → %QX0.0`, and CTU's R wired below it
    /// from `%IX0.1` OR `%IX0.2`.
    fn counter(pin: &str, link_up: bool) -> Ladder {
        let mut e = Editor::new(Ladder::default());
        let place = |e: &mut Editor, row, col, element| {
            let at = Cursor::new(0, row, col);
            e.apply(Edit::Place { at, element }).expect("places");
        };
        place(&mut e, 0, 0, Element::no("%IX0.0"));
        place(&mut e, 0, 1, entry("CTU c0 · 3").clone());
        place(&mut e, 0, 2, Element::coil("%QX0.0"));
        place(&mut e, 1, 0, Element::no("%IX0.1"));
        place(&mut e, 1, 1, entry(&format!("PIN {pin}")));
        let at = Cursor::new(0, 2, 0);
        e.apply(Edit::PlaceBranch {
            at,
            element: Element::no("%IX0.2"),
        })
        .expect("the OR below");
        if link_up {
            e.apply(Edit::ToggleLink {
                at: Cursor::new(0, 0, 1),
            })
            .expect("a link");
        }
        e.ladder().clone()
    }

    fn set(plc: &mut SoftPlc, name: &str, on: bool) {
        let d = plc.device(name).expect(name);
        let v = InputValue::Int(i64::from(on));
        plc.apply(Command::SetInput(d, v)).expect(name);
    }

    #[test]
    fn a_counters_reset_wired_from_its_own_network_resets_it() {
        let ladder = counter("R", false);
        let text = compile(&ladder, MachineId::SoftPlc, Options::default())
            .unwrap_or_else(|e| panic!("{e:?}"));
        assert!(text.contains("_c0_R"), "{text}");
        let mut plc = SoftPlc::new();
        plc.load_text(&text).expect("loads");
        let read = |plc: &SoftPlc, n: &str| plc.read(plc.device(n).expect(n)).as_i64();
        let mut t = 0;
        let mut step = |plc: &mut SoftPlc, name: &str, on: bool| {
            set(plc, name, on);
            t += 30;
            plc.run_until(SimTime::from_millis(t));
        };
        for _ in 0..3 {
            step(&mut plc, "%IX0.0", true);
            step(&mut plc, "%IX0.0", false);
        }
        assert_eq!((read(&plc, "c0.v"), read(&plc, "%QX0.0")), (3, 1));
        // Either contact of the network resets it.
        for reset in ["%IX0.1", "%IX0.2"] {
            step(&mut plc, reset, true);
            assert_eq!(
                (read(&plc, "c0.v"), read(&plc, "%QX0.0")),
                (0, 0),
                "{reset}"
            );
            step(&mut plc, reset, false);
            step(&mut plc, "%IX0.0", true);
            step(&mut plc, "%IX0.0", false);
            assert_eq!(read(&plc, "c0.v"), 1, "counting again after {reset}");
        }
    }

    #[test]
    fn a_box_input_is_refused_where_it_cannot_be_wired() {
        let problems = |l: &Ladder| {
            compile(l, MachineId::SoftPlc, Options::default())
                .expect_err("refused")
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("; ")
        };
        let pv = problems(&counter("PV", false));
        assert!(
            pv.contains("no Boolean input PV") && pv.contains("row 2, column 2"),
            "{pv}"
        );
        let joined = problems(&counter("R", true));
        assert!(joined.contains("joins CTU's R network"), "{joined}");
        let mut alone = Editor::new(Ladder::default());
        let at = Cursor::new(0, 0, 1);
        alone
            .apply(Edit::Place {
                at,
                element: entry("PIN R"),
            })
            .expect("places");
        let text = problems(alone.ladder());
        assert!(text.contains("below its box"), "{text}");
    }

    #[test]
    fn a_box_input_network_goes_out_as_plcopen_and_in_a_share_link() {
        use crate::formats::plcopen;
        let ladder = counter("R", false);
        let xml = plcopen::export(&ladder, "main").expect("exports");
        assert!(xml.contains("_c0_R"), "the network's BOOL is in the export");
        let il = plcopen::Document::read(&xml)
            .and_then(|document| document.soft_program(None))
            .expect("the soft PLC reads it back");
        assert!(il.text.contains("_c0_R"));
        let project = crate::formats::Project::new(MachineId::SoftPlc, ladder.clone());
        let link = crate::formats::share::encode(&project).expect("encodes");
        assert!(link.starts_with("3."), "{link}");
        let back = crate::formats::share::decode(&link).expect("decodes");
        assert_eq!(back.ladder, ladder, "the box input comes back");
        let json = project.to_json();
        let again = crate::formats::Project::from_json(&json).expect("JSON reads back");
        assert_eq!(again.ladder, ladder);
    }

    #[test]
    fn why_follows_into_a_box_inputs_network() {
        use crate::ladder::grid::Pos;
        use crate::ladder::live::LiveLadder;
        let ladder = counter("R", false);
        let live = LiveLadder::new(&ladder, MachineId::SoftPlc, Options::default())
            .unwrap_or_else(|e| panic!("{e:?}"));
        let mut plc = SoftPlc::new();
        plc.load_text(&live.listing.text).expect("loads");
        plc.set_tracing(true);
        plc.run_until(SimTime::from_millis(30));
        let trace = plc.trace().expect("traced");
        let why = live
            .explain(trace, 0, Pos::new(1, 1))
            .expect("the input explained");
        assert!(
            !why.powered && !why.together,
            "off: either contact would reset it"
        );
        assert_eq!(why.causes, [Pos::new(1, 0), Pos::new(2, 0)]);
        set(&mut plc, "%IX0.2", true);
        plc.run_until(SimTime::from_millis(60));
        let trace = plc.trace().expect("traced");
        let why = live.explain(trace, 0, Pos::new(1, 1)).expect("explained");
        assert!(why.powered);
        assert_eq!(why.causes, [Pos::new(2, 0)], "the contact that resets it");
        // The box's own rung is explained as before.
        let main = live.explain(trace, 0, Pos::new(0, 9)).expect("the coil");
        assert!(!main.causes.is_empty());
    }
}
