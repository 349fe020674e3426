//! A block's formal parameters as the file writes them, checked against
//! the pins the block has: an input it does not have was dropped (a
//! misspelled PT left a TON's at 0), and a wire from an output it does
//! not have was taken for a loop of wires. Both are refused at their
//! line, as the IL loader refuses an unknown `CAL` pin.

use super::declare::Interface;
use super::SoftError;
use crate::formats::plcopen::graph::Element;
use crate::iec::data::DataType;
use crate::iec::functions::Function;
use crate::iec::pins::is_block_type;
use crate::iec::pins::outputs as fb_outputs;

/// The pins' names, for a message (`IN, PT`).
fn names(pins: &[(String, DataType)]) -> String {
    pins.iter()
        .map(|(p, _)| p.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Refuses an input of block `e` (EN aside) that is not one of `pins`
/// (names match in any case, as IEC's do).
pub(super) fn check_inputs(e: &Element, pins: &[(String, DataType)]) -> Result<(), SoftError> {
    for (pin, _) in &e.inputs {
        let known =
            pin.eq_ignore_ascii_case("EN") || pins.iter().any(|(p, _)| p.eq_ignore_ascii_case(pin));
        if !known {
            return Err(SoftError::NoInput(e.describe(""), pin.clone(), names(pins)));
        }
    }
    Ok(())
}

/// The output pins block `from` has (ENO aside): a standard block's, one
/// of the project's own blocks', a function's one (as the file names
/// it); `None` for a block the soft PLC does not have (refused at its
/// own line).
fn output_pins(
    from: &Element,
    type_name: &str,
    user: Option<&Interface>,
) -> Option<Vec<(String, DataType)>> {
    let upper = type_name.to_ascii_uppercase();
    if is_block_type(&upper) {
        return Some(
            fb_outputs(&upper)
                .into_iter()
                .map(|(p, t)| (p.to_string(), t))
                .collect(),
        );
    }
    if Function::named(&upper).is_some() {
        let out = from
            .outputs
            .iter()
            .find(|p| !p.eq_ignore_ascii_case("ENO"))
            .cloned()
            .unwrap_or_else(|| "OUT".into());
        return Some(vec![(out, DataType::Bool)]);
    }
    user.map(|i| i.outputs.clone())
}

/// Refuses a wire from output `pin` of block `from` when the block has
/// no such output (the reader is filled in by the caller).
pub(super) fn check_output(
    from: &Element,
    type_name: &str,
    pin: &str,
    user: Option<&Interface>,
) -> Result<(), SoftError> {
    if pin.eq_ignore_ascii_case("ENO") {
        return Ok(());
    }
    match output_pins(from, type_name, user) {
        Some(pins) if !pins.iter().any(|(p, _)| p.eq_ignore_ascii_case(pin)) => {
            Err(SoftError::NoOutput(
                String::new(),
                from.describe(""),
                pin.to_string(),
                names(&pins),
            ))
        }
        _ => Ok(()),
    }
}

/// Refuses a call of one of the project's own function blocks drawn in
/// LD or FBD (which run) when it gets here: no variable declares its
/// instance (it was told the soft PLC runs such blocks, which it does).
pub(super) fn check_own_instance(
    own: &super::declare::OwnTypes,
    type_name: &str,
    instance: &str,
) -> Result<(), SoftError> {
    if own.blocks.iter().any(|b| b.eq_ignore_ascii_case(type_name)) {
        return Err(SoftError::UndeclaredInstance(
            instance.to_string(),
            type_name.to_string(),
        ));
    }
    Ok(())
}
