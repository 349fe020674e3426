//! What every LDmicro element lowers to ([`super::elements`],
//! [`super::texts`]): its part in a rung, its operands as the soft PLC
//! takes them, an LDmicro block's box.

use super::element::{is_number, number};
use super::error::LdError;
use crate::ladder::element::Element;
use crate::ladder::BlockCall;

/// What an element is in a rung: power passing through it, or an output.
pub(super) enum Part {
    /// A contact or in-line box: power in, power out.
    Condition(Element),
    /// Several, as a network (an element the soft PLC runs as boxes).
    Network(crate::ladder::net::Net),
    /// A coil or output box: where a rung ends.
    Output(Element),
    /// Nothing drawn (a placeholder, a wire).
    Nothing,
    /// A comment line.
    Comment(String),
}

/// Numbers and names as the soft PLC's boxes take them: a number in
/// decimal (`0x1F`, `'A'` worked out), a name as it is.
pub(super) fn operand(text: &str) -> Result<String, LdError> {
    if !is_number(text) {
        return Ok(text.trim().to_string());
    }
    number(text)
        .map(|v| v.to_string())
        .ok_or_else(|| LdError::BadNumber {
            element: "operand".into(),
            text: text.into(),
        })
}

/// The box of LDmicro block `kind` on instance `instance`.
pub(super) fn ld_box(
    kind: &str,
    instance: String,
    inputs: Vec<(&str, String)>,
    outputs: Vec<(&str, String)>,
) -> BlockCall {
    let pins = |v: Vec<(&str, String)>| v.into_iter().map(|(p, o)| (p.to_string(), o)).collect();
    BlockCall {
        kind: kind.into(),
        instance,
        inputs: pins(inputs),
        outputs: pins(outputs),
    }
}
