//! The soft PLC's text written back: values as IEC literals, IL lines and
//! declarations in one canonical form that loads back to the same program
//! (`hashigo asm`, the program pane, the ladder compiler's output).

use std::fmt;

use super::il::{Function, Line, Operand, Operator};
use super::vars::{Direction, Kind, Variable};
use crate::iec::data::{Data, DataType};

impl fmt::Display for Data {
    /// As a typed IEC literal: `TRUE`, `INT#-5`, `UINT#65535`,
    /// `REAL#1.5`, `T#500ms`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Data::Bool(b) => f.write_str(if b { "TRUE" } else { "FALSE" }),
            Data::Text(ref t) => f.write_str(&crate::iec::literal::text_literal(t)),
            Data::Int(t, _) => write!(f, "{}#{}", t.name(), self.to_value()),
            Data::Real(r) => real_literal(f, "REAL", &format!("{r:?}")),
            Data::Lreal(r) => real_literal(f, "LREAL", &format!("{r:?}")),
            Data::Time(ns) => {
                let (n, unit) = if ns % 1_000_000 == 0 {
                    (ns / 1_000_000, "ms")
                } else if ns % 1_000 == 0 {
                    (ns / 1_000, "us")
                } else {
                    (ns, "ns")
                };
                write!(f, "T#{n}{unit}")
            }
        }
    }
}

/// `REAL#…` / `LREAL#…` of a real's Debug text, which is the shortest
/// that reads back exactly; IEC wants a point before any exponent.
fn real_literal(f: &mut fmt::Formatter<'_>, ty: &str, text: &str) -> fmt::Result {
    match text.split_once('e') {
        Some((m, e)) if !m.contains('.') => write!(f, "{ty}#{m}.0E{e}"),
        _ => write!(f, "{ty}#{}", text.replace('e', "E")),
    }
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Operand::Name(n) => f.write_str(n),
            Operand::Address(a) => a.fmt(f),
            // An untyped integer reads back as a DINT, or at the type of
            // its place: the same value either way.
            Operand::Literal(Data::Int(DataType::Dint, v)) => write!(f, "{v}"),
            Operand::Literal(d) => d.fmt(f),
            Operand::Number(v) => write!(f, "{v}"),
            Operand::Text(t) => f.write_str(&crate::iec::literal::text_literal(t)),
        }
    }
}

impl Function {
    /// Its IEC name (`LIMIT`, `INT_TO_DINT`).
    pub fn name(self) -> String {
        match self {
            Function::Neg => "NEG".into(),
            Function::Move => "MOVE".into(),
            Function::Shl => "SHL".into(),
            Function::Shr => "SHR".into(),
            Function::Rol => "ROL".into(),
            Function::Ror => "ROR".into(),
            Function::Min => "MIN".into(),
            Function::Max => "MAX".into(),
            Function::Limit => "LIMIT".into(),
            Function::Sel => "SEL".into(),
            Function::Abs => "ABS".into(),
            Function::Sqrt => "SQRT".into(),
            Function::Trunc => "TRUNC".into(),
            Function::Expt => "EXPT".into(),
            Function::Mux => "MUX".into(),
            Function::Convert { from, to } => format!("{}_TO_{}", from.name(), to.name()),
        }
    }
}

impl Operator {
    /// Its mnemonic without modifiers (`)` for [`Operator::Close`]).
    pub fn mnemonic(self) -> String {
        match self {
            Operator::Close => ")".into(),
            Operator::Function(function) => function.name(),
            op => Operator::ALL
                .iter()
                .find(|(_, o)| *o == op)
                .map_or(String::new(), |(m, _)| (*m).to_string()),
        }
    }
}

impl fmt::Display for Line {
    /// `[label: ]OPERATOR[N|C|CN][(] [operand]`, a function's operands
    /// comma-separated, a call's parameters in parentheses.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(label) = &self.label {
            write!(f, "{label}: ")?;
        }
        f.write_str(&self.operator.mnemonic())?;
        if self.negated {
            f.write_str("N")?;
        }
        match self.condition {
            Some(true) => f.write_str("C")?,
            Some(false) => f.write_str("CN")?,
            None => {}
        }
        if self.deferred {
            f.write_str("(")?;
        }
        if let Some(operand) = &self.operand {
            write!(f, " {operand}")?;
        }
        for (i, arg) in self.args.iter().enumerate() {
            write!(f, "{}{arg}", if i == 0 { " " } else { ", " })?;
        }
        if self.operator == Operator::Cal && !(self.inputs.is_empty() && self.outputs.is_empty()) {
            let params = self
                .inputs
                .iter()
                .map(|(pin, v)| format!("{pin} := {v}"))
                .chain(self.outputs.iter().map(|(pin, t)| format!("{pin} => {t}")));
            write!(f, "({})", params.collect::<Vec<_>>().join(", "))?;
        }
        Ok(())
    }
}

impl fmt::Display for Variable {
    /// `name [AT %address] : TYPE [:= value]; [(* comment *)]`; the value
    /// only where it is not the type's zero.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.name)?;
        if let Some(a) = self.address {
            write!(f, " AT {a}")?;
        }
        match &self.kind {
            Kind::Value { data_type, init } => {
                write!(f, " : {}", data_type.name())?;
                if *init != data_type.zero() {
                    write!(f, " := {init}")?;
                }
            }
            Kind::Block(block) => write!(f, " : {block}")?,
        }
        f.write_str(";")?;
        if !self.comment.is_empty() {
            write!(f, " (* {} *)", self.comment.replace("*)", "* )"))?;
        }
        Ok(())
    }
}

/// The declarations and lines as one text: the `VAR` block, the
/// `VAR_RETAIN` block (each only when it has a variable), then the IL.
pub fn listing(vars: &[Variable], lines: &[Line]) -> String {
    let declared = |retain: bool| -> Vec<String> {
        vars.iter()
            .filter(|v| v.retain == retain && v.direction == Direction::Local)
            .map(|v| v.to_string())
            .collect()
    };
    let mut out = String::new();
    for (header, direction) in [
        ("VAR_INPUT", Direction::Input),
        ("VAR_OUTPUT", Direction::Output),
    ] {
        let block: Vec<String> = vars
            .iter()
            .filter(|v| v.direction == direction)
            .map(|v| v.to_string())
            .collect();
        if !block.is_empty() {
            out.push_str(&format!("{header}\n"));
            for v in block {
                out.push_str(&format!("  {v}\n"));
            }
            out.push_str("END_VAR\n");
        }
    }
    out.push_str(&var_blocks(&declared(false), &declared(true)));
    for line in lines {
        out.push_str(&format!("{line}\n"));
    }
    out
}

/// Declaration lines as a `VAR` block and a `VAR_RETAIN` block, each
/// only when it has a line.
pub fn var_blocks(plain: &[String], retained: &[String]) -> String {
    let mut out = String::new();
    for (header, block) in [("VAR", plain), ("VAR_RETAIN", retained)] {
        if block.is_empty() {
            continue;
        }
        out.push_str(header);
        out.push('\n');
        for v in block {
            out.push_str(&format!("  {v}\n"));
        }
        out.push_str("END_VAR\n");
    }
    out
}
