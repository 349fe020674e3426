//! The device entry's soft PLC boxes (issue #31): a function, comparison
//! or function block typed in one of two forms.
//!
//! - The call form, as the box shows itself and as IEC writes a call:
//!   `ADD(IN1 := a, IN2 := 1, OUT => c)`, `c0: CTU(R := reset, PV := 10)`.
//! - Operands in order, as FX mnemonics are typed: `ADD a 1 c` (the last
//!   operand of a function is where its result goes: `c := a + 1`),
//!   `MOVE 42 d`, `GT level 100` (a comparison; a third operand takes its
//!   result), `CTU c0 reset 10` (a block's instance, then its inputs after
//!   the one the power enters, in order: CTU's R and PV; `-` leaves one
//!   unwired: `CTU c0 - 10`, its R wired below the box as a network).
//!
//! A function goes to the rung's right end ([`Element::OutputBlock`], as
//! FX's MOV is an output); a comparison or a function block stands in the
//! condition ([`Element::Block`]) and passes its power on.

use crate::iec::data::DataType;
use crate::ladder::block::{BlockCall, Shape};
use crate::ladder::element::Element;

use super::entry_error::EntryError;

/// How a box is written by its operands in order.
pub const BOX_USAGE: &str =
    "ADD a 1 c, MOVE 42 d, GT level 100, CTU c0 reset 10 or ADD(IN1 := a, IN2 := 1, OUT => c)";

/// Whether `text` asks for a box: its first word names a function,
/// comparison or block, or it is written in the call form.
pub fn is_box(text: &str) -> bool {
    let head = text
        .split(|c: char| c.is_whitespace() || c == '(')
        .find(|w| !w.is_empty())
        .unwrap_or("");
    text.contains('(') || text.contains(":=") || Shape::of(&head.to_ascii_uppercase()).is_some()
}

/// The box `text` writes, placed where its kind stands.
pub fn parse_box(text: &str) -> Result<Element, EntryError> {
    let call = if text.contains('(') {
        call_form(text)?
    } else {
        operands_in_order(text)?
    };
    Ok(match call.shape() {
        Some(Shape::Function(..)) => Element::OutputBlock(call),
        _ => Element::Block(call),
    })
}

/// `[instance:] KIND(PIN := operand, PIN => variable, …)`.
fn call_form(text: &str) -> Result<BlockCall, EntryError> {
    let usage = || EntryError::Usage(BOX_USAGE);
    let (head, rest) = text.split_once('(').ok_or_else(usage)?;
    let body = rest.trim_end().strip_suffix(')').ok_or_else(usage)?;
    let (instance, kind) = match head.split_once(':') {
        Some((i, k)) => (i.trim(), k.trim()),
        None => ("", head.trim()),
    };
    if kind.is_empty() || kind.contains(char::is_whitespace) {
        return Err(usage());
    }
    let mut call = new_call(kind, instance);
    for param in crate::iec::il::split_params(body)
        .into_iter()
        .map(str::trim)
        .filter(|p| !p.is_empty())
    {
        // The first of `:=` and `=>` decides (a text may hold the other).
        let input = param.find(":=");
        match (input, param.find("=>")) {
            (Some(i), out) if out.is_none_or(|o| i < o) => {
                let (pin, operand) = (&param[..i], &param[i + 2..]);
                call.inputs
                    .push((pin.trim().to_string(), operand.trim().to_string()));
            }
            (_, Some(o)) => {
                let (pin, variable) = (&param[..o], &param[o + 2..]);
                call.outputs
                    .push((pin.trim().to_string(), variable.trim().to_string()));
            }
            _ => return Err(usage()),
        }
    }
    Ok(call)
}

fn new_call(kind: &str, instance: &str) -> BlockCall {
    BlockCall {
        kind: kind.to_ascii_uppercase(),
        instance: instance.to_string(),
        inputs: Vec::new(),
        outputs: Vec::new(),
    }
}

/// `KIND operand …`, read by the kind's pins (module doc).
fn operands_in_order(text: &str) -> Result<BlockCall, EntryError> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let Some((kind, operands)) = words.split_first() else {
        return Err(EntryError::Empty);
    };
    let shape = Shape::of(&kind.to_ascii_uppercase())
        .ok_or_else(|| EntryError::UnknownWord(kind.to_string()))?;
    let mut call = new_call(kind, "");
    let operands: Vec<String> = operands.iter().map(|o| o.to_string()).collect();
    // `-` (or the `·` a box shows) leaves a block's input unwired: CTU's
    // R wired below the box, `CTU c0 - 10`.
    let wire = |call: &mut BlockCall, pins: &[String], given: &[String]| {
        for (pin, operand) in pins.iter().zip(given) {
            if operand != "-" && operand != "·" {
                call.inputs.push((pin.clone(), operand.clone()));
            }
        }
    };
    match shape {
        Shape::Function(pins, many) => {
            let (result, inputs) = operands.split_last().ok_or(EntryError::Usage(BOX_USAGE))?;
            let fits = if many {
                inputs.len() >= pins.len()
            } else {
                inputs.len() == pins.len()
            };
            if !fits {
                return Err(EntryError::Usage(BOX_USAGE));
            }
            let pins = call.data_pins_for(inputs.len());
            wire(&mut call, &pins, inputs);
            call.outputs.push(("OUT".into(), result.clone()));
        }
        Shape::Compare => {
            if !(2..=3).contains(&operands.len()) {
                return Err(EntryError::Usage(BOX_USAGE));
            }
            let pins = call.data_pins();
            wire(&mut call, &pins, &operands[..2]);
            if let Some(result) = operands.get(2) {
                call.outputs.push(("OUT".into(), result.clone()));
            }
        }
        Shape::FunctionBlock => {
            let (instance, inputs) = operands.split_first().ok_or(EntryError::Usage(BOX_USAGE))?;
            call.instance = instance.clone();
            let pins = call.data_pins();
            if inputs.len() > pins.len() {
                return Err(EntryError::Usage(BOX_USAGE));
            }
            wire(&mut call, &pins, inputs);
            // LDmicro's blocks give their count back where they took it
            // from (`LD_TON Tw_ld 49 Tw`: T := Tw, T => Tw).
            let both: Vec<(String, String)> = call
                .inputs
                .iter()
                .filter(|(pin, operand)| {
                    // A constant given (a digit's source) is only read.
                    crate::ladder::block::is_variable(operand)
                        && crate::ladder::user_blocks::outputs(&call.kind())
                            .iter()
                            .any(|(o, _)| o == pin)
                })
                .cloned()
                .collect();
            call.outputs.extend(both);
        }
    }
    Ok(call)
}

/// What one operand of a box typed by its operands in order is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OperandRole {
    /// A function block's instance (`c0` of `CTU c0 reset 10`).
    Instance,
    /// A data input (its pin).
    Input,
    /// Where a function's result goes (`OUT`; a comparison's is optional).
    Result,
}

/// One operand of a box's kind, in the order [`parse_box`] reads them:
/// the entry offers a field for each, labelled by its pin (issue #49).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BoxOperand {
    /// What it is.
    pub role: OperandRole,
    /// The pin it wires (`""` for the instance).
    pub pin: String,
    /// The type its pin needs, when one type does (a counter's PV: INT;
    /// a function's pins take several: `None`).
    pub needs: Option<DataType>,
}

/// The operands a box of `kind` takes in order (`None`: no box has that
/// name): `CTU` → instance, R, PV; `ADD` → IN1, IN2, OUT.
pub fn box_operands(kind: &str) -> Option<Vec<BoxOperand>> {
    let call = new_call(kind, "");
    let shape = call.shape()?;
    let operand = |role, pin: &str, needs| BoxOperand {
        role,
        pin: pin.to_string(),
        needs,
    };
    let mut all = Vec::new();
    if shape == Shape::FunctionBlock {
        all.push(operand(OperandRole::Instance, "", None));
    }
    let typed = crate::ladder::user_blocks::inputs(&call.kind());
    for pin in call.data_pins() {
        let needs = typed.iter().find(|(p, _)| *p == pin).map(|(_, t)| *t);
        all.push(operand(OperandRole::Input, &pin, needs));
    }
    if shape != Shape::FunctionBlock {
        all.push(operand(OperandRole::Result, "OUT", None));
    }
    Some(all)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_boxs_operands_are_listed_in_the_order_they_are_typed() {
        let pins = |kind: &str| -> Vec<(OperandRole, String, Option<DataType>)> {
            box_operands(kind)
                .expect("a box")
                .into_iter()
                .map(|o| (o.role, o.pin, o.needs))
                .collect()
        };
        use OperandRole::*;
        assert_eq!(
            pins("ctu"),
            [
                (Instance, String::new(), None),
                (Input, "R".into(), Some(DataType::Bool)),
                (Input, "PV".into(), Some(DataType::Int)),
            ]
        );
        assert_eq!(
            pins("ADD"),
            [
                (Input, "IN1".into(), None),
                (Input, "IN2".into(), None),
                (Result, "OUT".into(), None)
            ]
        );
        assert_eq!(pins("GT").len(), 3);
        assert_eq!(box_operands("X00"), None);
        // What the fields list is what the entry reads back.
        let ctu = parse_box("CTU c0 reset 10").expect("reads");
        let names: Vec<_> = ctu
            .block()
            .expect("a box")
            .inputs
            .iter()
            .map(|(p, _)| p.clone())
            .collect();
        assert_eq!(names, ["R", "PV"]);
    }

    fn call(e: &Element) -> &BlockCall {
        e.block().expect("a box")
    }

    #[test]
    fn operands_in_order_wire_a_function_its_result_last() {
        let e = parse_box("ADD a 1 c").expect("reads");
        assert!(matches!(e, Element::OutputBlock(_)));
        assert_eq!(
            call(&e).to_string(),
            "ADD(IN1 := a, IN2 := 1, OUT => c)",
            "c := a + 1"
        );
        let three = parse_box("add a b 2 total").expect("ADD takes more");
        assert_eq!(call(&three).inputs.len(), 3);
        let mv = parse_box("MOVE 42 d").expect("reads");
        assert_eq!(call(&mv).to_string(), "MOVE(IN := 42, OUT => d)");
        assert!(parse_box("MOVE 42").is_err(), "no result");
        assert!(parse_box("SUB a b c d").is_err(), "SUB takes two");
    }

    #[test]
    fn a_comparison_and_a_block_stand_in_the_condition() {
        let gt = parse_box("GT level 100").expect("reads");
        assert!(matches!(gt, Element::Block(_)));
        assert_eq!(call(&gt).to_string(), "GT(IN1 := level, IN2 := 100)");
        let ctu = parse_box("CTU c0 reset 10").expect("reads");
        assert!(matches!(ctu, Element::Block(_)));
        assert_eq!(call(&ctu).to_string(), "c0: CTU(R := reset, PV := 10)");
        assert_eq!(
            call(&parse_box("TON t0 T#2s").expect("reads")).to_string(),
            "t0: TON(PT := T#2s)"
        );
        assert!(parse_box("CTU c0 r 10 5").is_err(), "CTU takes R and PV");
        let skipped = parse_box("CTU c0 - 10").expect("R left unwired");
        assert_eq!(call(&skipped).to_string(), "c0: CTU(PV := 10)");
    }

    #[test]
    fn the_call_form_reads_back_what_a_box_shows() {
        for text in [
            "ADD(IN1 := a, IN2 := 1, OUT => c)",
            "c0: CTU(R := reset, PV := 10)",
            "GT(IN1 := level, IN2 := 100)",
            "LIMIT(MN := 0, IN := raw, MX := 1000, OUT => level)",
        ] {
            let e = parse_box(text).expect(text);
            assert_eq!(call(&e).to_string(), text);
        }
        assert!(parse_box("ADD(IN1 := a").is_err(), "unclosed");
        assert!(parse_box("ADD(IN1 a)").is_err(), "no := or =>");
    }

    #[test]
    fn an_ldmicro_block_gives_its_count_back_to_where_it_took_it() {
        let e = parse_box("LD_TON Tw_ld 49 Tw").expect("reads");
        let c = call(&e);
        assert_eq!(c.instance, "Tw_ld");
        assert_eq!(
            c.inputs,
            vec![("P".into(), "49".into()), ("T".into(), "Tw".into())]
        );
        assert_eq!(c.outputs, vec![("T".into(), "Tw".into())]);
        assert!(
            matches!(e, Element::Block(_)),
            "in the condition, passing power on"
        );
        let e = parse_box("LD_CTC Cw_ld 4 0 Cw").expect("reads");
        assert_eq!(call(&e).outputs, vec![("C".into(), "Cw".into())]);
        // The serial port's: a byte received goes back where it came from,
        // one sent is only read.
        let e = parse_box("LD_UART_RECV recv_ld ch").expect("reads");
        assert_eq!(call(&e).outputs, vec![("V".into(), "ch".into())]);
        // A digit: the source's index back first, then the segments.
        let e = parse_box("LD_SEG7 seg_ld n 0 seg 8").expect("reads");
        assert_eq!(
            call(&e).outputs,
            vec![("A".into(), "n".into()), ("D".into(), "seg".into())]
        );
        let e = parse_box("LD_SEG7 seg_ld 72 1 seg 8").expect("reads");
        assert_eq!(call(&e).outputs, vec![("D".into(), "seg".into())]);
        let e = parse_box("f_ld: LD_FMTSTR(V := n, FMT := 'Hi, \\3 $'x$' => ')").expect("reads");
        assert_eq!(
            call(&e).inputs,
            vec![
                ("V".into(), "n".into()),
                ("FMT".into(), "'Hi, \\3 $'x$' => '".into())
            ]
        );
        let e = parse_box("LD_UART_SEND send_ld ch").expect("reads");
        assert_eq!(call(&e).inputs, vec![("V".into(), "ch".into())]);
        assert!(call(&e).outputs.is_empty());
    }

    #[test]
    fn boxes_are_told_from_devices() {
        assert!(is_box("ADD a 1 c") && is_box("gt x 1") && is_box("c0: CTU(PV := 1)"));
        assert!(!is_box("%IX0.0") && !is_box("start") && !is_box("SET %QX0.0"));
    }
}
