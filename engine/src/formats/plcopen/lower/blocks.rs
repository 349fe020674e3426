//! Blocks from other tools read into the body's graph (issue #18): the
//! timers, counters and edge boxes as elements, the boolean blocks and
//! flip-flops as gates to lower (gates.rs), CTD / CTUD on the machines'
//! up-counters and the comparisons as IO86A's `CMP`; a block's EN
//! honoured or refused; an unknown block named as such.

use super::body::{Body, Gate, GateKind, PinRef};
use crate::formats::plcopen::compare::compare_flag;
use crate::formats::plcopen::declare::Names;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::error::ImportError;
use crate::formats::plcopen::gate_why::GateWhy;
use crate::formats::plcopen::kinds::BlockKind;
use crate::formats::plcopen::parts::{coil, edge, negated, timer_coil};
use crate::iec::literal::parse_time_literal;
use crate::ladder::element::{CoilKind, Element, TimerKind};
use crate::ladder::grid::Pos;
use crate::ladder::net::Net;

/// The boolean block `ty` as a gate, if it is one; a flip-flop needs a
/// relay from the map for its instance.
fn gate_kind(ty: BlockKind, relay: &str, written: &str) -> Result<Option<GateKind>, ImportError> {
    Ok(Some(match ty {
        BlockKind::And => GateKind::And,
        BlockKind::Or => GateKind::Or,
        BlockKind::Xor => GateKind::Xor,
        BlockKind::Sr | BlockKind::Rs => {
            if relay == written {
                return Err(ImportError::Gate(
                    format!("{ty} block {written}"),
                    GateWhy::NeedsRelay(written.to_string()),
                ));
            }
            GateKind::Flip {
                relay: relay.to_string(),
                set_wins: ty == BlockKind::Sr,
            }
        }
        _ => return Ok(None),
    }))
}

/// `TOF block TOF0`, with the device the map gives it when another
/// (`TOF block TOF0 (T01+M20)`).
fn block_label(ty: BlockKind, written: &str, instance: &str) -> String {
    match (written.trim(), instance) {
        ("", d) => format!("{ty} block {d}"),
        (w, d) if w == d => format!("{ty} block {w}"),
        (w, d) => format!("{ty} block {w} ({d})"),
    }
}

/// A literal that never carries power: `FALSE`, `0`, `BOOL#FALSE`.
fn is_false(expr: &str) -> bool {
    let v = expr.trim();
    let v = v
        .get(..5)
        .filter(|p| p.eq_ignore_ascii_case("BOOL#"))
        .map_or(v, |_| &v[5..]);
    v.eq_ignore_ascii_case("FALSE") || v == "0"
}

/// A counter's PV: a whole number 1..32767, or a variable declared with one.
fn counter_preset(expr: &str, names: &Names, what: &str) -> Result<u16, ImportError> {
    let value = names.initial(expr).unwrap_or(expr).trim();
    value
        .parse()
        .ok()
        // PV 0 is done from the start in IEC, while the machines' reset
        // turns a counter's contact off: not the same program.
        .filter(|&k: &u16| (1..=crate::io86a::isa::K_MAX).contains(&i32::from(k)))
        .ok_or_else(|| ImportError::BadCounterPreset(what.to_string(), expr.to_string()))
}

/// A block's input pin `name`.
pub(in crate::formats::plcopen) fn pin_of<'a>(n: &'a Node, name: &str) -> Option<&'a Node> {
    n.child("inputVariables")?
        .all("variable")
        .find(|v| v.attr("formalParameter") == Some(name))
}

/// Refuses a block whose pins carry a negation circle or an edge mark
/// (FBD draws them on the pin; the block would read the pin as drawn
/// without it): a NOT, R_TRIG or F_TRIG block in front says the same.
/// A rising mark on a counter's CU or CD is what the counter does.
/// A mark that is no XML boolean or edge is refused, as on a contact.
pub(in crate::formats::plcopen) fn plain_pins(n: &Node, ty: BlockKind) -> Result<(), ImportError> {
    known_inputs(n, ty)?;
    let pins = ["inputVariables", "outputVariables"]
        .into_iter()
        .filter_map(|side| n.child(side))
        .flat_map(|side| side.all("variable"));
    for pin in pins {
        let name = pin.attr("formalParameter").unwrap_or("?");
        // A counter counts CU's / CD's rises already: OpenPLC marks them
        // rising (their R_EDGE declaration), and a rise of that is the same.
        let counts_rises = matches!(name, "CU" | "CD");
        let edge = edge(pin)?.filter(|e| !(counts_rises && *e == "rising"));
        let negated = negated(pin)?;
        let why = match (negated, edge) {
            (true, _) => GateWhy::Negated(name.to_string()),
            (false, Some(e)) => GateWhy::Edge(name.to_string(), e),
            (false, None) => continue,
        };
        return Err(ImportError::Gate(format!("{ty} block"), why));
    }
    Ok(())
}

/// Refuses an input of a standard function block (`ty`: TON … RS) that
/// the block does not have (EN aside): a misspelled CTU `RESET` was
/// dropped and the counter never reset. Functions (AND, GT …) take
/// their inputs in order, whatever their names.
fn known_inputs(n: &Node, ty: BlockKind) -> Result<(), ImportError> {
    let has = crate::iec::pins::inputs(ty.name());
    if has.is_empty() {
        return Ok(());
    }
    let inputs = n
        .child("inputVariables")
        .into_iter()
        .flat_map(|v| v.all("variable"));
    for pin in inputs {
        let name = pin.attr("formalParameter").unwrap_or_default();
        let known = name.eq_ignore_ascii_case("EN")
            || has.iter().any(|(p, _)| p.eq_ignore_ascii_case(name));
        if !known {
            let list: Vec<&str> = has.iter().map(|(p, _)| *p).collect();
            let instance = n.attr("instanceName").unwrap_or_default();
            return Err(ImportError::Gate(
                format!("{ty} block {instance}").trim_end().to_string(),
                GateWhy::NoInput(
                    crate::error::shown(name).trim_matches('"').to_string(),
                    list.join(", "),
                ),
            ));
        }
    }
    Ok(())
}

/// A pin's name for messages ('static, as the errors keep it).
fn pin_name(name: &str) -> &'static str {
    match name {
        "S1" => "S1",
        "S" => "S",
        "R" => "R",
        "R1" => "R1",
        "CU" => "CU",
        "CD" => "CD",
        _ => "IN",
    }
}

impl Body {
    /// A block's EN (its connections read with the body, `enables`):
    /// open, or from the rail, a literal TRUE or an always-running
    /// block's ENO, it always runs, as Hashigo's blocks do; wired to
    /// anything else it is refused (never ignored).
    fn check_enable(&self, id: &str, ty: BlockKind, instance: &str) -> Result<(), ImportError> {
        let refs = self.enables.get(id).map_or(&[][..], Vec::as_slice);
        if self.always_enabled(refs, 0) {
            return Ok(());
        }
        Err(ImportError::Gate(
            format!("{ty} block {instance}").trim().to_string(),
            GateWhy::EnableWired,
        ))
    }

    /// Whether EN connections `refs` always carry power: from the rail, a
    /// literal TRUE, or another block's ENO whose own EN always does
    /// (OpenPLC Editor chains EN to ENO); `depth` bounds the chain.
    pub(in crate::formats::plcopen) fn always_enabled(
        &self,
        refs: &[PinRef],
        depth: usize,
    ) -> bool {
        depth < 64
            && refs.iter().all(|PinRef { id: r, pin }| {
                self.rails.contains(r)
                    || self
                        .literals
                        .get(r)
                        .is_some_and(|e| e.value.trim().eq_ignore_ascii_case("TRUE"))
                    || (pin.eq_ignore_ascii_case("ENO")
                        && self
                            .enables
                            .get(r)
                            .is_some_and(|en| self.always_enabled(en, depth + 1)))
            })
    }

    /// A boolean block: its inputs joined, its output a point, lowered
    /// once the whole body is read ([`super::gates`]).
    fn gate(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        kind: GateKind,
        ty: BlockKind,
        instance: &str,
    ) -> Result<(), ImportError> {
        let what = format!("{ty} block {instance}").trim().to_string();
        let pins: Vec<&Node> = n
            .child("inputVariables")
            .map(|v| v.all("variable").collect())
            .unwrap_or_default();
        let order: Vec<&str> = match kind {
            GateKind::Flip { .. } => vec![
                if ty == BlockKind::Sr { "S1" } else { "S" },
                if ty == BlockKind::Sr { "R" } else { "R1" },
            ],
            _ => pins
                .iter()
                .filter_map(|v| v.attr("formalParameter"))
                .collect(),
        };
        let mut inputs = Vec::new();
        for name in order {
            let v = pins
                .iter()
                .find(|v| v.attr("formalParameter") == Some(name))
                .ok_or_else(|| ImportError::PinNotConnected(what.clone(), pin_name(name)))?;
            let p = self.join(v.child("connectionPointIn"), &what)?;
            self.consumed.push(p);
            inputs.push(p);
        }
        if inputs.len() < 2 {
            return Err(ImportError::Gate(what, GateWhy::NeedsTwo));
        }
        let out_pin = if matches!(kind, GateKind::Flip { .. }) {
            "Q1"
        } else {
            "OUT"
        };
        let out = self.point(id, out_pin);
        self.gates.push(Gate {
            kind,
            inputs,
            out,
            pos,
            line: n.line,
            what,
        });
        Ok(())
    }

    pub(in crate::formats::plcopen) fn block(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        names: &Names,
        ty: BlockKind,
    ) -> Result<(), ImportError> {
        let written = n.attr("instanceName").unwrap_or_default();
        // A map may give the instance a device (`TON0,T00`).
        let instance = names
            .instance(written)
            .unwrap_or_else(|| written.to_string());
        self.check_enable(id, ty, written)?;
        if let Some(kind) = gate_kind(ty, &instance, written)? {
            return self.gate(n, id, pos, kind, ty, written);
        }
        if let BlockKind::Compare(c) = ty {
            return self.compare(n, id, pos, compare_flag(c), ty, names);
        }
        if matches!(ty, BlockKind::Ctd | BlockKind::Ctud) {
            let what = block_label(ty, written, &instance);
            return self.count(n, id, pos, (ty, &instance, what), names);
        }
        let (power_in, power_out) = match ty {
            BlockKind::Ton | BlockKind::Tof | BlockKind::Tp => ("IN", "Q"),
            BlockKind::Not => ("IN", "OUT"),
            BlockKind::RTrig | BlockKind::FTrig => ("CLK", "Q"),
            BlockKind::Ctu => ("CU", "Q"),
            _ => return Err(ImportError::UnsupportedBlock(ty.name().to_string())),
        };
        let what = block_label(ty, written, &instance);
        let input = self.join(
            pin_of(n, power_in).and_then(|v| v.child("connectionPointIn")),
            &what,
        )?;
        self.consumed.push(input);
        // A counter's R: a reset coil on the counter, fed as R is (a
        // literal FALSE resets nothing).
        if ty == BlockKind::Ctu {
            if let Some(p) = self.power_pin(n, "R", &what)? {
                let at = Pos::new(pos.row, pos.col.wrapping_add(1));
                self.gates.push(Gate {
                    kind: GateKind::Reset(coil(CoilKind::Reset, instance.clone())),
                    inputs: vec![p],
                    out: p,
                    pos: at,
                    line: n.line,
                    what: what.clone(),
                });
            }
        }
        let element = match ty {
            BlockKind::Ton | BlockKind::Tof | BlockKind::Tp => {
                match self.timer_block(n, (id, pos), (ty, &instance), &what, input, names)? {
                    Some(timer) => timer,
                    // A TOF or TP built as a gate (lowered later).
                    None => return Ok(()),
                }
            }
            BlockKind::Ctu => {
                let expr = self.pin_literal(n, "PV", &what)?;
                Element::CounterCoil {
                    device: instance.clone(),
                    preset: counter_preset(&expr, names, &what)?,
                }
            }
            BlockKind::RTrig | BlockKind::FTrig => Element::Edge {
                falling: ty == BlockKind::FTrig,
            },
            _ => Element::Not,
        };
        let out = self.point(id, power_out);
        self.wire(input, out, Net::Leaf(element, pos), n.line);
        Ok(())
    }

    /// A TON, TOF or TP's element: an in-line timer, or (`None`) a TOF or
    /// TP mapped to a timer and a relay (`T01+M20`), built from the
    /// machine's on-delay timer coil as a gate lowered later.
    #[allow(clippy::too_many_arguments)] // the block as read, each part named at the call
    fn timer_block(
        &mut self,
        n: &Node,
        (id, pos): (&str, Pos),
        (ty, instance): (BlockKind, &str),
        what: &str,
        input: usize,
        names: &Names,
    ) -> Result<Option<Element>, ImportError> {
        let expr = self.pin_literal(n, "PT", what)?;
        // A literal, or a variable declared with one.
        let preset_ms = parse_time_literal(&expr)
            .or_else(|| names.initial(&expr).and_then(parse_time_literal))
            .ok_or_else(|| ImportError::BadTimeLiteral(what.to_string(), expr.to_string()))?;
        let kind = match ty {
            BlockKind::Ton => TimerKind::Ton,
            BlockKind::Tof => TimerKind::Tof,
            _ => TimerKind::Tp,
        };
        // A TOF or TP mapped to a timer and a relay (`T01+M20`):
        // built from the machine's on-delay timer coil.
        if let (Some((timer, relay)), false) = (instance.split_once('+'), ty == BlockKind::Ton) {
            let coil = timer_coil(timer.trim(), preset_ms)?;
            let kind = GateKind::Delay {
                coil,
                timer: timer.trim().to_string(),
                relay: relay.trim().to_string(),
                pulse: ty == BlockKind::Tp,
            };
            let out = self.point(id, "Q");
            self.gates.push(Gate {
                kind,
                inputs: vec![input],
                out,
                pos,
                line: n.line,
                what: what.to_string(),
            });
            return Ok(None);
        }
        Ok(Some(Element::Timer {
            kind,
            name: instance.to_string(),
            preset_ms,
        }))
    }

    /// The point a block's input pin `name` takes power from, or `None`
    /// when it is open or a literal FALSE (it never carries power).
    fn power_pin(
        &mut self,
        n: &Node,
        name: &str,
        what: &str,
    ) -> Result<Option<usize>, ImportError> {
        let Some(cpi) = pin_of(n, name)
            .and_then(|v| v.child("connectionPointIn"))
            .filter(|c| c.child("connection").is_some())
        else {
            return Ok(None);
        };
        let never = cpi
            .child("connection")
            .and_then(|c| c.attr("refLocalId"))
            .and_then(|r| self.literals.get(r))
            .is_some_and(|e| is_false(&e.value));
        if never {
            return Ok(None);
        }
        let p = self.join(Some(cpi), what)?;
        self.consumed.push(p);
        Ok(Some(p))
    }

    /// The literal (or variable) box feeding pin `name`: its text.
    pub(in crate::formats::plcopen) fn pin_literal(
        &self,
        n: &Node,
        name: &'static str,
        what: &str,
    ) -> Result<String, ImportError> {
        let unconnected = || ImportError::PinNotConnected(what.to_string(), name);
        let r = pin_of(n, name)
            .and_then(|v| v.child("connectionPointIn"))
            .and_then(|c| c.child("connection"))
            .and_then(|c| c.attr("refLocalId"))
            .ok_or_else(unconnected)?;
        self.literals
            .get(r)
            .map(|e| e.value.trim().to_string())
            .ok_or_else(|| ImportError::PinNotLiteral(what.to_string(), name))
    }

    /// CTD (count down from PV, loaded by LD) and CTUD (with CD and LD
    /// unused: counts up, QD while nothing is counted) on the machine's
    /// up-counter, lowered in gates.rs.
    fn count(
        &mut self,
        n: &Node,
        id: &str,
        pos: Pos,
        (ty, instance, what): (BlockKind, &str, String),
        names: &Names,
    ) -> Result<(), ImportError> {
        let down = ty == BlockKind::Ctd;
        let preset = counter_preset(&self.pin_literal(n, "PV", &what)?, names, &what)?;
        let count_pin = if down { "CD" } else { "CU" };
        let input = self
            .power_pin(n, count_pin, &what)?
            .ok_or_else(|| ImportError::PinNotConnected(what.clone(), pin_name(count_pin)))?;
        let (load, reset, empty) = if down {
            (self.power_pin(n, "LD", &what)?, None, None)
        } else {
            for pin in ["CD", "LD"] {
                if self.power_pin(n, pin, &what)?.is_some() {
                    return Err(ImportError::Gate(what, GateWhy::CounterWired(pin)));
                }
            }
            (
                None,
                self.power_pin(n, "R", &what)?,
                Some(self.point(id, "QD")),
            )
        };
        let out = self.point(id, if down { "Q" } else { "QU" });
        self.gates.push(Gate {
            kind: GateKind::Count {
                counter: Element::CounterCoil {
                    device: instance.to_string(),
                    preset,
                },
                load,
                reset,
                empty,
            },
            inputs: vec![input],
            out,
            pos,
            line: n.line,
            what,
        });
        Ok(())
    }
}
