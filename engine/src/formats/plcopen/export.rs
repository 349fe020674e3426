//! Rungs to a PLCopen TC6 v2.01 project: one `main` program with an LD
//! body, one left and right rail a rung, elements at their grid places.

use std::fmt::Write as _;

use quick_xml::escape::escape;

use super::time_literal;
use crate::ladder::element::{CoilKind, ContactKind, Element};
use crate::ladder::grid::{Ladder, LadderError, Pos};
use crate::ladder::net::{analyse, Net, RungLogic};

const CELL_W: usize = 80;
const CELL_H: usize = 60;

/// The ladder as a PLCopen project named `name`. Outputs PLCopen has no
/// LD form for (MOV, CMP, INC, DEC) are errors at their cells.
pub fn export(ladder: &Ladder, name: &str) -> Result<String, Vec<LadderError>> {
    let mut errors = Vec::new();
    let mut logic = Vec::new();
    for (i, rung) in ladder.rungs.iter().enumerate() {
        match analyse(rung, i) {
            Ok(Some(l)) => logic.push((i, l)),
            Ok(None) => {}
            Err(e) => errors.extend(e),
        }
    }
    let mut w = Writer::default();
    w.declare(&ladder.variables);
    let mut y0 = 20;
    for (i, l) in &logic {
        y0 = write_sides(&mut w, l, *i, y0, &mut errors);
        if let Err((p, m)) = w.rung(l, y0) {
            errors.push(LadderError::at(*i, p, m));
        }
        let rows = ladder.rungs[*i].cells.len().max(l.outputs.len());
        y0 += rows * CELL_H + CELL_H;
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let mut vars = String::new();
    for v in &ladder.variables {
        let _ = writeln!(vars, "          {}", declared_variable(v));
    }
    for (v, ty) in &w.variables {
        let address = w
            .located
            .iter()
            .find(|(n, _)| n == v)
            .map(|(_, a)| format!(" address=\"{}\"", escape(a.as_str())))
            .unwrap_or_default();
        let _ = writeln!(
            vars,
            "          <variable name=\"{}\"{address}><type>{ty}</type></variable>",
            escape(v.as_str())
        );
    }
    Ok(format!(
        r#"{head}    <dataTypes/>
    <pous>
      <pou name="main" pouType="program">
        <interface>
          <localVars>
{vars}          </localVars>
        </interface>
        <body>
          <LD>
{body}          </LD>
        </body>
      </pou>
    </pous>
  </types>
  <instances>
    <configurations/>
  </instances>
</project>
"#,
        head = super::project_head(name),
        body = w.body
    ))
}

#[derive(Default)]
struct Writer {
    body: String,
    next_id: usize,
    variables: Vec<(String, String)>,
    /// The soft PLC's declared names (upper-case), written by
    /// [`declared_variable`], and located ones by address.
    declared: std::collections::HashSet<String>,
    at_address: std::collections::HashMap<String, String>,
    /// Addresses a rung names directly, and the variable that stands for
    /// each (PLCopen's tools want every variable declared).
    located: Vec<(String, String)>,
}

/// A connection source: an element's id and, for blocks, its output pin.
type Source = (usize, Option<&'static str>);

impl Writer {
    fn id(&mut self) -> usize {
        self.next_id += 1;
        self.next_id
    }

    fn variable(&mut self, name: &str, ty: &str) {
        if self.declared.contains(&name.to_ascii_uppercase()) {
            return;
        }
        if !self.variables.iter().any(|(v, _)| v == name) {
            self.variables.push((name.to_string(), ty.to_string()));
        }
    }

    /// The ladder's declared variables (written as they are).
    fn declare(&mut self, variables: &[crate::ladder::Variable]) {
        for v in variables {
            self.declared.insert(v.name.to_ascii_uppercase());
            if let Ok(a) = crate::iec::Address::parse(&v.address) {
                self.at_address.insert(a.to_string(), v.name.clone());
            }
        }
    }

    /// The variable for a device or operand: an address (`%IX0.0`) is
    /// the variable located there, or a new one named after it
    /// (`IX0_0`); a name stays, declared `ty` unless the ladder declares
    /// it.
    fn name_for(&mut self, device: &str, ty: &str) -> String {
        let device = device.trim();
        let Ok(a) = crate::iec::Address::parse(device) else {
            self.variable(device, ty);
            return device.to_string();
        };
        if let Some(name) = self.at_address.get(&a.to_string()) {
            return name.clone();
        }
        let name = a.to_string().trim_start_matches('%').replace('.', "_");
        let t = a.default_type().map_or("BOOL", |t| t.name());
        self.variable(&name, &format!("<{t}/>"));
        if !self.located.iter().any(|(n, _)| *n == name) {
            self.located.push((name.clone(), a.to_string()));
        }
        name
    }

    fn connections(sources: &[Source]) -> String {
        let mut s = String::new();
        for (id, pin) in sources {
            match pin {
                Some(p) => {
                    let _ = write!(
                        s,
                        "<connection refLocalId=\"{id}\" formalParameter=\"{p}\"/>"
                    );
                }
                None => {
                    let _ = write!(s, "<connection refLocalId=\"{id}\"/>");
                }
            }
        }
        s
    }

    fn rung(&mut self, l: &RungLogic, y0: usize) -> Result<(), (Pos, String)> {
        let at = |p: Pos| (40 + p.col * CELL_W, y0 + p.row * CELL_H);
        if !l.comment.is_empty() {
            let id = self.id();
            let _ = writeln!(
                self.body,
                "            <comment localId=\"{id}\" height=\"30\" width=\"400\"><position x=\"40\" y=\"{}\"/><content><xhtml:p><![CDATA[{}]]></xhtml:p></content></comment>",
                y0.saturating_sub(40),
                l.comment.replace("]]>", "]] >")
            );
        }
        let rail = self.id();
        let _ = writeln!(
            self.body,
            "            <leftPowerRail localId=\"{rail}\" height=\"40\" width=\"10\"><position x=\"0\" y=\"{y0}\"/><connectionPointOut formalParameter=\"\"><relPosition x=\"10\" y=\"20\"/></connectionPointOut></leftPowerRail>"
        );
        let ends = self.net(&l.condition, &[(rail, None)], &at)?;
        let mut outs = Vec::new();
        let mut right_x = 0;
        for (e, p) in &l.outputs {
            let (x, y) = at(*p);
            right_x = right_x.max(x + CELL_W);
            outs.push(self.output(e, &ends, x, y).map_err(|m| (*p, m))?);
        }
        let id = self.id();
        let _ = writeln!(
            self.body,
            "            <rightPowerRail localId=\"{id}\" height=\"40\" width=\"10\"><position x=\"{right_x}\" y=\"{y0}\"/><connectionPointIn><relPosition x=\"0\" y=\"20\"/>{}</connectionPointIn></rightPowerRail>",
            Self::connections(&outs)
        );
        Ok(())
    }

    /// Writes a network fed from `from`; returns the points it ends on.
    fn net(
        &mut self,
        net: &Net,
        from: &[Source],
        at: &dyn Fn(Pos) -> (usize, usize),
    ) -> Result<Vec<Source>, (Pos, String)> {
        Ok(match net {
            Net::Series(v) => {
                let mut cur = from.to_vec();
                for n in v {
                    cur = self.net(n, &cur, at)?;
                }
                cur
            }
            Net::Parallel(v) => {
                let mut all = Vec::new();
                for n in v {
                    all.extend(self.net(n, from, at)?);
                }
                all
            }
            // A wire passes the power on as it comes: a box whose rung is
            // a wire from the rail has its input on the rail.
            Net::Leaf(Element::Wire, _) => from.to_vec(),
            Net::Leaf(e, p) => {
                let (x, y) = at(*p);
                vec![self.leaf(e, from, x, y).map_err(|m| (*p, m))?]
            }
        })
    }

    fn leaf(&mut self, e: &Element, from: &[Source], x: usize, y: usize) -> Result<Source, String> {
        named(e)?;
        let id = self.id();
        let conns = Self::connections(from);
        match e {
            Element::Contact { kind, device } => {
                let device = &self.name_for(device, "<BOOL/>");
                let (negated, edge) = match kind {
                    ContactKind::No => ("false", ""),
                    ContactKind::Nc => ("true", ""),
                    ContactKind::Rising => ("false", " edge=\"rising\""),
                    ContactKind::Falling => ("false", " edge=\"falling\""),
                };
                let _ = writeln!(
                    self.body,
                    "            <contact localId=\"{id}\" negated=\"{negated}\"{edge} height=\"20\" width=\"30\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"10\"/>{conns}</connectionPointIn><connectionPointOut><relPosition x=\"30\" y=\"10\"/></connectionPointOut><variable>{}</variable></contact>",
                    escape(device.as_str())
                );
                Ok((id, None))
            }
            Element::Not => {
                self.block(id, "NOT", None, "IN", &conns, None, "OUT", x, y);
                Ok((id, Some("OUT")))
            }
            Element::Edge { falling } => {
                let ty = if *falling { "F_TRIG" } else { "R_TRIG" };
                let inst = format!("{ty}{id}");
                self.variable(
                    &inst,
                    if *falling {
                        "<derived name=\"F_TRIG\"/>"
                    } else {
                        "<derived name=\"R_TRIG\"/>"
                    },
                );
                self.block(id, ty, Some(&inst), "CLK", &conns, None, "Q", x, y);
                Ok((id, Some("Q")))
            }
            Element::Timer {
                kind,
                name,
                preset_ms,
            } => {
                let ty = kind.name();
                self.timer(id, ty, name, &conns, *preset_ms, x, y);
                Ok((id, Some("Q")))
            }
            Element::Block(b) => self.call(id, b, &conns, x, y),
            other => Err(format!("{other} cannot stand in a condition")),
        }
    }

    #[allow(clippy::too_many_arguments)] // one XML element's parts
    fn block(
        &mut self,
        id: usize,
        ty: &str,
        instance: Option<&str>,
        pin_in: &str,
        conns: &str,
        extra: Option<(&str, usize)>,
        pin_out: &str,
        x: usize,
        y: usize,
    ) {
        let inst = instance
            .map(|i| format!(" instanceName=\"{}\"", escape(i)))
            .unwrap_or_default();
        let extra = extra
            .map(|(p, lit)| format!("<variable formalParameter=\"{p}\"><connectionPointIn><relPosition x=\"0\" y=\"40\"/><connection refLocalId=\"{lit}\"/></connectionPointIn></variable>"))
            .unwrap_or_default();
        let _ = writeln!(
            self.body,
            "            <block localId=\"{id}\" typeName=\"{ty}\"{inst} height=\"60\" width=\"60\"><position x=\"{x}\" y=\"{y}\"/><inputVariables><variable formalParameter=\"{pin_in}\"><connectionPointIn><relPosition x=\"0\" y=\"20\"/>{conns}</connectionPointIn></variable>{extra}</inputVariables><inOutVariables/><outputVariables><variable formalParameter=\"{pin_out}\"><connectionPointOut><relPosition x=\"60\" y=\"20\"/></connectionPointOut></variable></outputVariables></block>"
        );
    }

    #[allow(clippy::too_many_arguments)] // one XML element's parts
    fn timer(
        &mut self,
        id: usize,
        ty: &'static str,
        name: &str,
        conns: &str,
        ms: u32,
        x: usize,
        y: usize,
    ) {
        let lit = self.literal(&time_literal(ms), x, y);
        self.variable(
            name,
            match ty {
                "TON" => "<derived name=\"TON\"/>",
                "TOF" => "<derived name=\"TOF\"/>",
                _ => "<derived name=\"TP\"/>",
            },
        );
        self.block(
            id,
            ty,
            Some(name),
            "IN",
            conns,
            Some(("PT", lit)),
            "Q",
            x,
            y,
        );
    }

    /// An IO86A counter coil as a CTU with its set value.
    fn counter(&mut self, device: &str, preset: u16, conns: &str, x: usize, y: usize) -> Source {
        let id = self.id();
        let lit = self.literal(&preset.to_string(), x, y);
        self.variable(device, "<derived name=\"CTU\"/>");
        self.block(
            id,
            "CTU",
            Some(device),
            "CU",
            conns,
            Some(("PV", lit)),
            "Q",
            x,
            y,
        );
        (id, Some("Q"))
    }

    fn literal(&mut self, text: &str, x: usize, y: usize) -> usize {
        let id = self.id();
        let _ = writeln!(
            self.body,
            "            <inVariable localId=\"{id}\" height=\"20\" width=\"60\" negated=\"false\"><position x=\"{}\" y=\"{}\"/><connectionPointOut><relPosition x=\"60\" y=\"10\"/></connectionPointOut><expression>{}</expression></inVariable>",
            x.saturating_sub(70),
            y + 40,
            escape(text)
        );
        id
    }

    fn output(
        &mut self,
        e: &Element,
        from: &[Source],
        x: usize,
        y: usize,
    ) -> Result<Source, String> {
        let conns = Self::connections(from);
        let coil = |w: &mut Writer, attrs: &str, device: &str| {
            let device = &w.name_for(device, "<BOOL/>");
            let id = w.id();
            let _ = writeln!(
                w.body,
                "            <coil localId=\"{id}\"{attrs} height=\"20\" width=\"30\"><position x=\"{x}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"10\"/>{conns}</connectionPointIn><connectionPointOut><relPosition x=\"30\" y=\"10\"/></connectionPointOut><variable>{}</variable></coil>",
                escape(device)
            );
            (id, None)
        };
        named(e)?;
        if let Element::TimerCoil { preset, .. } | Element::CounterCoil { preset, .. } = e {
            if *preset > 32767 {
                return Err(format!("{e}: set values go up to K32767"));
            }
        }
        Ok(match e {
            Element::Coil { kind, device } => {
                let attrs = match kind {
                    CoilKind::Normal => " negated=\"false\"",
                    CoilKind::Inverted => " negated=\"true\"",
                    CoilKind::Set => " negated=\"false\" storage=\"set\"",
                    CoilKind::Reset => " negated=\"false\" storage=\"reset\"",
                };
                coil(self, attrs, device)
            }
            Element::Pulse { falling, device } => {
                let attrs = if *falling {
                    " negated=\"false\" edge=\"falling\""
                } else {
                    " negated=\"false\" edge=\"rising\""
                };
                coil(self, attrs, device)
            }
            Element::TimerCoil { device, preset } => {
                // Import reads a TON whose Q drives nothing back as this
                // coil only when it is named like a timer.
                let base = match crate::io86a::isa::parse_bit(device) {
                    Ok(crate::io86a::Bit::T(n)) if n >= 24 => 10,
                    Ok(crate::io86a::Bit::T(_)) => 100,
                    _ => return Err(format!("{e}: a timer coil must name a timer T00-T31")),
                };
                let id = self.id();
                self.timer(id, "TON", device, &conns, u32::from(*preset) * base, x, y);
                (id, Some("Q"))
            }
            Element::CounterCoil { device, preset } => self.counter(device, *preset, &conns, x, y),
            Element::OutputBlock(b) => {
                let id = self.id();
                self.call(id, b, &conns, x, y)?
            }
            other => {
                return Err(format!(
                    "{other} has no PLCopen LD form here: keep it in a Hashigo project (.json)"
                ))
            }
        })
    }
}

/// A device-bearing element must name its device: PLCopen has no empty
/// variable.
fn named(e: &Element) -> Result<(), String> {
    let device = e.read_device().or(e.written_device());
    match device {
        Some(d) if d.trim().is_empty() => Err(format!("{e}names no device")),
        _ => Ok(()),
    }
}

/// A declared soft PLC variable as PLCopen declares it.
fn declared_variable(v: &crate::ladder::Variable) -> String {
    let ty = v.data_type.trim().to_ascii_uppercase();
    // TC6's schema writes STRING as `<string/>`, the others as named.
    let ty = if ty == "STRING" {
        "<string/>".to_string()
    } else if v.elementary().is_some() {
        format!("<{ty}/>")
    } else {
        format!("<derived name=\"{}\"/>", escape(ty.as_str()))
    };
    let address = if v.address.is_empty() {
        String::new()
    } else {
        format!(" address=\"{}\"", escape(v.address.trim()))
    };
    let initial = if v.initial.is_empty() {
        String::new()
    } else {
        format!(
            "<initialValue><simpleValue value=\"{}\"/></initialValue>",
            escape(v.initial.trim())
        )
    };
    let doc = if v.comment.is_empty() {
        String::new()
    } else {
        format!(
            "<documentation><xhtml:p><![CDATA[{}]]></xhtml:p></documentation>",
            v.comment.replace("]]>", "]] >")
        )
    };
    format!(
        "<variable name=\"{}\"{address}><type>{ty}</type>{initial}{doc}</variable>",
        escape(v.name.as_str())
    )
}

impl Writer {
    /// A soft PLC box: its power pin fed from `conns`, its other inputs
    /// from `inVariable`s, its outputs into `outVariable`s; returns its
    /// power out.
    fn call(
        &mut self,
        id: usize,
        b: &crate::ladder::BlockCall,
        conns: &str,
        x: usize,
        y: usize,
    ) -> Result<Source, String> {
        let kind = b.kind();
        let shape = b
            .shape()
            .ok_or_else(|| format!("{kind} is no box the soft PLC has"))?;
        let instance = if b.instance.is_empty() {
            String::new()
        } else {
            self.variable(
                &b.instance,
                &format!("<derived name=\"{}\"/>", escape(kind.as_str())),
            );
            format!(" instanceName=\"{}\"", escape(b.instance.as_str()))
        };
        let (power_in, power_out) = (b.power_in(), b.power_out());
        let mut inputs = format!(
            "<variable formalParameter=\"{power_in}\"><connectionPointIn><relPosition x=\"0\" y=\"20\"/>{conns}</connectionPointIn></variable>"
        );
        for (k, pin) in b.data_pins().iter().enumerate() {
            let Some(operand) = b.input(pin) else {
                continue;
            };
            let expression = if crate::ladder::block::is_variable(operand) {
                self.name_for(operand, "<BOOL/>")
            } else {
                operand.to_string()
            };
            let lit = self.literal(&expression, x, y + 20 * k);
            let _ = write!(
                inputs,
                "<variable formalParameter=\"{pin}\"><connectionPointIn><relPosition x=\"0\" y=\"{}\"/><connection refLocalId=\"{lit}\"/></connectionPointIn></variable>",
                40 + 20 * k
            );
        }
        let mut pins: Vec<&str> = vec![power_out];
        if shape != crate::ladder::block::Shape::FunctionBlock && power_out == "ENO" {
            pins.push("OUT");
        }
        for (pin, _) in &b.outputs {
            if !pins.iter().any(|p| p.eq_ignore_ascii_case(pin)) {
                pins.push(pin.as_str());
            }
        }
        let outputs: String = pins
            .iter()
            .map(|p| format!("<variable formalParameter=\"{p}\"><connectionPointOut><relPosition x=\"60\" y=\"20\"/></connectionPointOut></variable>"))
            .collect();
        let _ = writeln!(
            self.body,
            "            <block localId=\"{id}\" typeName=\"{}\"{instance} height=\"80\" width=\"80\"><position x=\"{x}\" y=\"{y}\"/><inputVariables>{inputs}</inputVariables><inOutVariables/><outputVariables>{outputs}</outputVariables></block>",
            escape(kind.as_str())
        );
        // Each output variable at the box's own height, just right of
        // it: what runs the file top to bottom, left to right (the soft
        // PLC, OpenPLC) writes it before the next cell, as the ladder does.
        for (k, (pin, variable)) in b.outputs.iter().enumerate() {
            let name = self.name_for(variable, "<BOOL/>");
            let out = self.id();
            let _ = writeln!(
                self.body,
                "            <outVariable localId=\"{out}\" height=\"20\" width=\"60\" negated=\"false\"><position x=\"{}\" y=\"{y}\"/><connectionPointIn><relPosition x=\"0\" y=\"10\"/><connection refLocalId=\"{id}\" formalParameter=\"{pin}\"/></connectionPointIn><expression>{}</expression></outVariable>",
                x + 1 + k,
                escape(name.as_str())
            );
        }
        Ok((id, Some(power_out)))
    }
}

/// A box's inputs wired as networks (rung `index`'s), each written first
/// at `y0` as a network of its own ending in a coil on the BOOL the box
/// reads (the same in every reader); where the rung's own goes next.
fn write_sides(
    w: &mut Writer,
    l: &crate::ladder::net::RungLogic,
    index: usize,
    mut y0: usize,
    errors: &mut Vec<LadderError>,
) -> usize {
    for side in &l.sides {
        let own = side.as_rung();
        if let Err((p, m)) = w.rung(&own, y0) {
            errors.push(LadderError::at(index, p, m));
        }
        let leaves = side.net.leaves();
        let rows = |f: fn(usize, usize) -> usize| leaves.iter().map(|(_, p)| p.row).reduce(f);
        let high = rows(usize::max).unwrap_or(0) - rows(usize::min).unwrap_or(0) + 1;
        y0 += high * CELL_H + CELL_H;
    }
    y0
}
