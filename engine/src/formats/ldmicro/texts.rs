//! LDmicro's serial-port and text elements as the soft PLC's blocks
//! (docs/ldmicro.md, "The serial port" and "Strings"): the UART's byte
//! and several-byte forms, its ready and available tests, a formatted
//! string sent, and STRING printing into a STRING variable.

use super::element::Element as Ld;
use super::error::LdError;
use super::parts::{ld_box, operand, Part};
use crate::ladder::element::Element;
use crate::ladder::BlockCall;
use crate::runtime::ldmicro::printf::{Printf, PrintfError};

/// `STRING dest var text` as `LD_STRING`: `dest := sprintf(text, var)`
/// while powered, the text checked as a C format of the one variable.
pub(super) fn string(
    dest: &str,
    var: &str,
    text: &str,
    instance: &mut dyn FnMut(&str) -> String,
) -> Result<BlockCall, LdError> {
    let printf = Printf::parse(text).map_err(LdError::Printf)?;
    let mut inputs = Vec::new();
    if !var.trim().is_empty() {
        inputs.push(("V", operand(var)?));
    } else if printf.takes_value() {
        return Err(LdError::Printf(PrintfError::NoValue));
    }
    inputs.push(("D", dest.to_string()));
    inputs.push(("FMT", crate::iec::literal::text_literal(text)));
    let out = vec![("D", dest.to_string())];
    Ok(ld_box("LD_STRING", instance("_str"), inputs, out))
}

/// The serial port's other elements as LDmicro's serial blocks (a
/// byte's send and receive are [`uart_block`]).
pub(super) fn serial(
    e: &Ld,
    instance: &mut dyn FnMut(&str) -> String,
) -> Result<BlockCall, LdError> {
    Ok(match e {
        Ld::UartRecvAvail => ld_box("LD_UART_AVAIL", instance("_avail"), Vec::new(), Vec::new()),
        Ld::UartSendReady => ld_box("LD_UART_READY", instance("_ready"), Vec::new(), Vec::new()),
        Ld::FormattedString { var, text } => {
            crate::runtime::ldmicro::format::Format::for_element(text, !var.trim().is_empty())
                .map_err(LdError::Format)?;
            let mut inputs = Vec::new();
            if !var.trim().is_empty() {
                inputs.push(("V", operand(var)?));
            }
            inputs.push(("FMT", crate::iec::literal::text_literal(text)));
            ld_box("LD_FMTSTR", instance("_fmt"), inputs, Vec::new())
        }
        other => return Err(LdError::NotYet(other.keyword().into())),
    })
}

/// `UART_SEND v [n wait]`, `UART_RECV …` and the `…n` forms (all of the
/// variable's bytes, its `VAR LIST` size by `bits`) as `LD_UART_SEND` /
/// `LD_UART_RECV` with `N` bytes; waiting (the chip stopped until every
/// byte has gone) is not run. `None` for any other element.
pub(super) fn uart_block(
    e: &Ld,
    bits: &dyn Fn(&str) -> u16,
    instance: &mut dyn FnMut(&str) -> String,
) -> Option<Result<Part, LdError>> {
    let (Ld::UartSend {
        name,
        bytes,
        wait,
        whole,
    }
    | Ld::UartRecv {
        name,
        bytes,
        wait,
        whole,
    }) = e
    else {
        return None;
    };
    let built = (|| {
        if *wait {
            return Err(LdError::NoScanMeaning(
                format!("{} waiting for its bytes", e.keyword()),
                "LDmicro's code loops on the port inside the scan, stopping the chip until every byte has gone or come; the soft PLC's scans always run to their end",
            ));
        }
        let n = if *whole {
            u32::from(bits(name))
        } else {
            *bytes
        };
        let mut inputs = vec![("V", operand(name)?)];
        if n > 1 {
            inputs.push(("N", n.to_string()));
        }
        let call = if matches!(e, Ld::UartSend { .. }) {
            ld_box("LD_UART_SEND", instance("_send"), inputs, Vec::new())
        } else {
            let out = vec![("V", operand(name)?)];
            ld_box("LD_UART_RECV", instance("_recv"), inputs, out)
        };
        Ok(Part::Condition(Element::Block(call)))
    })();
    Some(built)
}
