//! Each LDmicro element as the soft PLC's ladder has it (docs/ldmicro.md,
//! "Elements"): contacts and coils as they are, one-shots as edge
//! boxes, comparisons and arithmetic as the soft PLC's boxes, timers and
//! counters as LDmicro's own blocks ([`crate::runtime::ldmicro`]) on
//! the variable of their name.

use super::element::{is_number, number, Element as Ld, MathOp, OneShotKind, UnaryOp};
use super::error::LdError;
use super::parts::{ld_box, operand, Part};
use super::texts::{serial, string, uart_block};
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::BlockCall;

/// A timer's period in cycles: LDmicro 4.x's `TimerPeriod`,
/// `(delay + cycle × adjust) / cycle` in whole cycles (a 0.1 file's
/// TON, TOF and RTO written without an adjust take −1: the cycle LDmicro
/// 2.x subtracted). A delay that is a variable's name is a count already.
pub(super) fn period(name: &str, delay: &str, cycle: u64, adjust: i32) -> Result<String, LdError> {
    if !is_number(delay) {
        return Ok(delay.trim().to_string());
    }
    let bad = || LdError::TimerPeriod {
        name: name.into(),
        delay: delay.into(),
        cycle,
        adjust,
    };
    let us = number(delay).ok_or_else(bad)?;
    let cycle_i = i64::try_from(cycle).map_err(|_| bad())?;
    if us <= 0 || cycle_i <= 0 {
        return Err(bad());
    }
    let periods = (us + cycle_i * i64::from(adjust)).div_euclid(cycle_i);
    if periods < 1 || us / cycle_i < 1 {
        return Err(bad());
    }
    Ok(periods.to_string())
}

/// A function box (`ADD`, `MOVE`) writing `dest`.
fn function(kind: &str, inputs: Vec<(&str, String)>, dest: &str) -> BlockCall {
    ld_box(
        kind,
        String::new(),
        inputs,
        vec![("OUT", dest.trim().to_string())],
    )
}

/// Element `e` of a file whose cycle is `cycle` µs; `instance` names a
/// block's instance for the element's name (`Tdelay` → `Tdelay_ld`, a
/// second element on it `Tdelay_ld2`).
pub(super) fn part(
    e: &Ld,
    cycle: u64,
    instance: &mut impl FnMut(&str) -> String,
) -> Result<Part, LdError> {
    Ok(match e {
        Ld::Comment(text) => Part::Comment(text.clone()),
        Ld::Placeholder | Ld::Short => Part::Nothing,
        Ld::Open => Part::Condition(Element::no(OPEN)),
        Ld::Contacts { name, negated, .. } => Part::Condition(Element::Contact {
            kind: if *negated {
                ContactKind::Nc
            } else {
                ContactKind::No
            },
            device: name.clone(),
        }),
        Ld::Coil { .. } => coil(e, instance),
        Ld::OneShot(OneShotKind::Rising) => Part::Condition(Element::Edge { falling: false }),
        Ld::OneShot(OneShotKind::Falling) => Part::Condition(Element::Edge { falling: true }),
        Ld::OneShot(k) => {
            let kind = if *k == OneShotKind::Low {
                "LD_OSL"
            } else {
                "LD_OSC"
            };
            let call = ld_box(kind, instance("_shot"), Vec::new(), Vec::new());
            Part::Condition(Element::Block(call))
        }
        Ld::Timer { .. } | Ld::Counter { .. } => {
            Part::Condition(Element::Block(timer_or_counter(e, cycle, instance)?))
        }
        Ld::Unary { .. } | Ld::Math { .. } | Ld::Compare { .. } => {
            Part::Condition(Element::Block(operation(e)?))
        }
        Ld::ShiftRegister { .. } | Ld::LookUpTable { .. } | Ld::PiecewiseLinear { .. } => {
            Part::Network(as_boxes(e)?)
        }
        Ld::TimeConvert {
            to_delay: false,
            name,
            delay,
        } => {
            // The delay's count of cycles (no adjust), as LDmicro's
            // TIME2COUNT gives it.
            let count = period(name, delay, cycle, 0)?;
            Part::Condition(Element::Block(function("MOVE", vec![("IN", count)], name)))
        }
        Ld::UartRecvAvail | Ld::UartSendReady | Ld::FormattedString { .. } => {
            Part::Condition(Element::Block(serial(e, instance)?))
        }
        // A count of the chip's own delay loop, for DELAY, which stops the
        // chip: nothing to count on the soft PLC.
        Ld::TimeConvert { to_delay: true, .. } => {
            return Err(LdError::Hardware("TIME2DELAY".into()))
        }
        Ld::Hardware { keyword, .. } => return Err(LdError::Hardware(keyword.clone())),
        Ld::Text { dest, var, text } => {
            Part::Condition(Element::Block(string(dest, var, text, instance)?))
        }
        other => return Err(LdError::NotYet(other.keyword().into())),
    })
}

/// An element the soft PLC runs as boxes of its own (docs/ldmicro.md):
/// `SHIFT_REGISTER r 4` as a rising edge and MOVEs from `r2` into `r3`
/// down to `r0` into `r1`; `LOOK_UP_TABLE d i …` as one branch per entry,
/// `EQ i k` then `MOVE` of the entry into `d`.
fn as_boxes(e: &Ld) -> Result<crate::ladder::net::Net, LdError> {
    use crate::ladder::grid::Pos;
    use crate::ladder::net::Net;
    let leaf = |el: Element| Net::Leaf(el, Pos::new(0, 0));
    let mv = |src: String, dest: String| {
        leaf(Element::Block(function("MOVE", vec![("IN", src)], &dest)))
    };
    match e {
        Ld::ShiftRegister { name, stages } => {
            let mut chain = vec![leaf(Element::Edge { falling: false })];
            for k in (1..*stages).rev() {
                chain.push(mv(format!("{name}{}", k - 1), format!("{name}{k}")));
            }
            Ok(Net::Series(chain))
        }
        Ld::LookUpTable {
            dest,
            index,
            values,
            ..
        } => {
            let index = operand(index)?;
            let branches: Vec<Net> = values
                .iter()
                .enumerate()
                .map(|(k, v)| {
                    let inputs = vec![("IN1", index.clone()), ("IN2", k.to_string())];
                    let eq = ld_box("EQ", String::new(), inputs, Vec::new());
                    Net::Series(vec![
                        leaf(Element::Block(eq)),
                        mv(v.to_string(), dest.clone()),
                    ])
                })
                .collect();
            Ok(match branches.len() {
                1 => branches
                    .into_iter()
                    .next()
                    .unwrap_or_else(|| leaf(Element::Wire)),
                _ => Net::Parallel(branches),
            })
        }
        Ld::PiecewiseLinear {
            dest,
            index,
            points,
            ..
        } => Ok(piecewise(dest, &operand(index)?, points)),
        other => Err(LdError::NotYet(other.keyword().into())),
    }
}

/// The DINT a piecewise-linear table computes in.
pub(super) const PWL: &str = "_pwl";

/// `PIECEWISE_LINEAR d i …` as one branch per segment between points
/// (x0, y0) and (x1, y1): while `x0 <= i <= x1`, `d := y0 + (i - x0) *
/// (y1 - y0) / (x1 - x0)` in boxes (a later segment wins at a shared
/// point, where both give y1).
fn piecewise(dest: &str, index: &str, points: &[(i64, i64)]) -> crate::ladder::net::Net {
    use crate::ladder::grid::Pos;
    use crate::ladder::net::Net;
    let leaf = |b: BlockCall| Net::Leaf(Element::Block(b), Pos::new(0, 0));
    let cmp = |kind: &str, a: String, b: String| {
        leaf(ld_box(
            kind,
            String::new(),
            vec![("IN1", a), ("IN2", b)],
            Vec::new(),
        ))
    };
    let math = |kind: &str, a: String, b: String, out: &str| {
        leaf(function(kind, vec![("IN1", a), ("IN2", b)], out))
    };
    let branches: Vec<Net> = points
        .windows(2)
        .map(|w| {
            let ((x0, y0), (x1, y1)) = (w[0], w[1]);
            Net::Series(vec![
                cmp("GE", index.to_string(), x0.to_string()),
                cmp("LE", index.to_string(), x1.to_string()),
                math("SUB", index.to_string(), x0.to_string(), PWL),
                math("MUL", PWL.into(), (y1 - y0).to_string(), PWL),
                math("DIV", PWL.into(), (x1 - x0).max(1).to_string(), PWL),
                math("ADD", PWL.into(), y0.to_string(), dest),
            ])
        })
        .collect();
    match branches.len() {
        0 => Net::Leaf(Element::Wire, Pos::new(0, 0)),
        1 => branches
            .into_iter()
            .next()
            .unwrap_or(Net::Leaf(Element::Wire, Pos::new(0, 0))),
        _ => Net::Parallel(branches),
    }
}

/// A coil: the soft PLC's coil of that kind, or a toggle's box.
fn coil(e: &Ld, instance: &mut impl FnMut(&str) -> String) -> Part {
    let Ld::Coil {
        name,
        negated,
        set_only,
        reset_only,
        toggle,
    } = e
    else {
        return Part::Nothing;
    };
    if *toggle {
        let v = || vec![("V", name.clone())];
        let call = ld_box("LD_TOGGLE", instance(name), v(), v());
        return Part::Output(Element::OutputBlock(call));
    }
    let kind = match (negated, set_only, reset_only) {
        (true, _, _) => CoilKind::Inverted,
        (_, true, _) => CoilKind::Set,
        (_, _, true) => CoilKind::Reset,
        _ => CoilKind::Normal,
    };
    Part::Output(Element::Coil {
        kind,
        device: name.clone(),
    })
}

/// A timer's or counter's box: LDmicro's block on the count variable of
/// the element's name.
fn timer_or_counter(
    e: &Ld,
    cycle: u64,
    instance: &mut impl FnMut(&str) -> String,
) -> Result<BlockCall, LdError> {
    match e {
        Ld::Timer {
            kind,
            name,
            delay,
            adjust,
        } => {
            let p = period(name, delay, cycle, *adjust)?;
            let block = format!("LD_{}", kind.keyword());
            let t = || name.clone();
            Ok(ld_box(
                &block,
                instance(name),
                vec![("P", p), ("T", t())],
                vec![("T", t())],
            ))
        }
        Ld::Counter {
            kind,
            name,
            max,
            init,
            input,
        } => {
            let mut inputs = vec![
                ("MAX", operand(max)?),
                ("INIT", operand(init)?),
                ("C", name.clone()),
            ];
            let edge = match input {
                '\\' => 1,
                '-' => 2,
                'o' => 3,
                _ => 0,
            };
            if edge != 0 {
                inputs.push(("EDGE", edge.to_string()));
            }
            let block = format!("LD_{}", kind.keyword());
            Ok(ld_box(
                &block,
                instance(name),
                inputs,
                vec![("C", name.clone())],
            ))
        }
        other => Err(LdError::NotYet(other.keyword().into())),
    }
}

/// LDmicro's word operations the IEC functions lack (`BIN2BCD`,
/// `BCD2BIN`, `SWAP`, `OPPOSITE`, `SR0`, `SET_BIT`, `CLEAR_BIT`,
/// `7SEGMENTS`) as its
/// `LD_` block on the destination, in the destination's width from the
/// `VAR LIST` (`bits`, in bytes); `IF_BIT_SET`/`IF_BIT_CLEAR` as a block
/// passing power while the bit is as asked; arithmetic and `MOVE` into a
/// destination narrower than the soft PLC's DINT as `LD_ADD` … `LD_MOVE`,
/// wrapping in its width. `None` for any other element.
pub(super) fn word_op(
    e: &Ld,
    bits: &dyn Fn(&str) -> u16,
    instance: &mut dyn FnMut(&str) -> String,
) -> Option<Result<Part, LdError>> {
    if let Some(built) = uart_block(e, bits, instance) {
        return Some(built);
    }
    let (kind, a, b, dest) = word_op_operands(e, &|dest| bits(dest) < 4)?;
    let built = (|| -> Result<Part, LdError> {
        let mut inputs = vec![("A", operand(a)?), ("B", operand(b)?)];
        let mut outputs = Vec::new();
        if kind.starts_with("LD_SEG") && !is_number(a) {
            // LDmicro writes the source's table index back first (a
            // source that is the destination too ends as the segments).
            outputs.push(("A", a.trim().to_string()));
        }
        if let Some(d) = dest {
            inputs.push(("D", d.to_string()));
            inputs.push(("W", (bits(d) * 8).to_string()));
            outputs.push(("D", d.to_string()));
        }
        let call = ld_box(kind, instance("op"), inputs, outputs);
        Ok(Part::Condition(Element::Block(call)))
    })();
    Some(built)
}

/// Which `LD_` block a word operation is, and its operands `A`, `B` and
/// destination (none for a bit test); `narrow` says whether a
/// destination is narrower than a DINT.
fn word_op_operands<'e>(
    e: &'e Ld,
    narrow: &dyn Fn(&str) -> bool,
) -> Option<(&'static str, &'e str, &'e str, Option<&'e str>)> {
    Some(match e {
        Ld::Math { op, dest, a, b } if *op != MathOp::Sr0 && narrow(dest) => {
            let kind = narrow_math(*op);
            (kind, a.as_str(), b.as_str(), Some(dest.as_str()))
        }
        Ld::Unary { op, dest, src }
            if matches!(op, UnaryOp::Move | UnaryOp::Not | UnaryOp::Neg) && narrow(dest) =>
        {
            let kind = match op {
                UnaryOp::Move => "LD_MOVE",
                UnaryOp::Not => "LD_NOT",
                _ => "LD_NEG",
            };
            (kind, src.as_str(), "0", Some(dest.as_str()))
        }
        Ld::Unary { op, dest, src } => {
            let kind = match op {
                UnaryOp::Bin2Bcd => "LD_BIN2BCD",
                UnaryOp::Bcd2Bin => "LD_BCD2BIN",
                UnaryOp::Swap => "LD_SWAP",
                UnaryOp::Opposite => "LD_OPPOSITE",
                _ => return None,
            };
            (kind, src.as_str(), "0", Some(dest.as_str()))
        }
        Ld::Math {
            op: MathOp::Sr0,
            dest,
            a,
            b,
        } => ("LD_SR0", a.as_str(), b.as_str(), Some(dest.as_str())),
        Ld::Bit {
            write: true,
            set,
            var,
            bit,
        } => {
            let kind = if *set { "LD_SETBIT" } else { "LD_CLRBIT" };
            (kind, "0", bit.as_str(), Some(var.as_str()))
        }
        Ld::Bit { set, var, bit, .. } => {
            let kind = if *set { "LD_IFBIT" } else { "LD_IFNBIT" };
            (kind, var.as_str(), bit.as_str(), None)
        }
        Ld::Segments {
            segments,
            dest,
            src,
            common,
        } => {
            // B: 1 for a common-anode digit (LDmicro saves C or A).
            let anode = if common.eq_ignore_ascii_case(&'A') {
                "1"
            } else {
                "0"
            };
            let kind = match segments {
                9 => "LD_SEG9",
                14 => "LD_SEG14",
                16 => "LD_SEG16",
                _ => "LD_SEG7",
            };
            (kind, src.as_str(), anode, Some(dest.as_str()))
        }
        _ => return None,
    })
}

/// The `LD_` block of arithmetic into a destination narrower than a DINT.
fn narrow_math(op: MathOp) -> &'static str {
    match op {
        MathOp::Add => "LD_ADD",
        MathOp::Sub => "LD_SUB",
        MathOp::Mul => "LD_MUL",
        MathOp::Div => "LD_DIV",
        MathOp::Mod => "LD_MOD",
        MathOp::And => "LD_AND",
        MathOp::Or => "LD_OR",
        MathOp::Xor => "LD_XOR",
        MathOp::Shl => "LD_SHL",
        MathOp::Shr => "LD_SHR",
        MathOp::Rol => "LD_ROL",
        _ => "LD_ROR",
    }
}

/// An arithmetic, move or comparison element as the soft PLC's box.
fn operation(e: &Ld) -> Result<BlockCall, LdError> {
    let not_yet = || LdError::NotYet(e.keyword().into());
    match e {
        Ld::Unary { op, dest, src } => {
            let kind = match op {
                UnaryOp::Move => "MOVE",
                UnaryOp::Not => "NOT",
                UnaryOp::Neg => "NEG",
                _ => return Err(not_yet()),
            };
            Ok(function(kind, vec![("IN", operand(src)?)], dest))
        }
        Ld::Math { op, dest, a, b } => {
            let kind = match op {
                MathOp::Sr0 => return Err(not_yet()),
                other => other.keyword(),
            };
            let pins = match op {
                MathOp::Shl | MathOp::Shr | MathOp::Rol | MathOp::Ror => ["IN", "N"],
                _ => ["IN1", "IN2"],
            };
            let inputs = vec![(pins[0], operand(a)?), (pins[1], operand(b)?)];
            Ok(function(kind, inputs, dest))
        }
        Ld::Compare { op, a, b } => {
            let kind = op.name();
            let inputs = vec![("IN1", operand(a)?), ("IN2", operand(b)?)];
            Ok(ld_box(kind, String::new(), inputs, Vec::new()))
        }
        _ => Err(not_yet()),
    }
}

/// The BOOL an `OPEN` element reads: declared, never written, so never
/// on.
pub(super) const OPEN: &str = "_OPEN";
