//! A Structured Text source to a PLCopen TC6 v2.01 project that keeps
//! its ST (issue #54): each `PROGRAM`, `FUNCTION` and `FUNCTION_BLOCK`
//! a `<pou>` with its interface and an `<ST>` body holding the body as
//! the source writes it (comments kept), each `TYPE` a `<dataType>`, the
//! `VAR_GLOBAL`s the configuration's globals, each program run by a
//! task, in the form OpenPLC Editor and Beremiz write.

use std::fmt::Write as _;

use quick_xml::escape::escape;

use crate::iec::st::ast::{
    ArrayInit, Elementary, Init, Item, Pou, PouKind, Source, TypeDecl, TypeDef, TypeRef, VarBlock,
    VarKind,
};
use crate::iec::st::print::expr_text;
use crate::iec::st::{body_texts, check_source, parse_source, StError};

/// The ST text `source` (a `.st` file's) as a PLCopen project named
/// `name` whose POUs keep their ST bodies. The source is parsed and
/// checked first: what it refuses is returned, at its line and column,
/// and nothing is written.
pub fn export_st(source: &str, name: &str) -> Result<String, Vec<StError>> {
    let parsed = parse_source(source).map_err(|e| vec![e])?;
    check_source(&parsed)?;
    Ok(project(&parsed, &body_texts(source, &parsed), name))
}

/// The project's XML: its data types, POUs and configuration.
fn project(source: &Source, bodies: &[String], name: &str) -> String {
    let mut types = String::new();
    let mut pous = String::new();
    let mut globals = String::new();
    let mut programs = Vec::new();
    let mut bodies = bodies.iter();
    for item in &source.items {
        match item {
            Item::Types(decls) => types.push_str(&data_types(decls)),
            Item::Globals(block) => globals.push_str(&scope_xml(block, "globalVars", 8)),
            Item::Pou(pou) => {
                let body = bodies.next().map_or("", String::as_str);
                if pou.kind == PouKind::Program {
                    programs.push(pou.name.name.clone());
                }
                pous.push_str(&pou_xml(pou, body, &mut globals));
            }
        }
    }
    let mut tasks = String::new();
    for (i, p) in programs.iter().enumerate() {
        let _ = write!(
            tasks,
            "\n            <task name=\"task{i}\" priority=\"{i}\" interval=\"T#20ms\">\n              <pouInstance name=\"instance{i}\" typeName=\"{}\"/>\n            </task>",
            escape(p.as_str())
        );
    }
    format!(
        r#"{head}    <dataTypes>
{types}    </dataTypes>
    <pous>
{pous}    </pous>
  </types>
  <instances>
    <configurations>
      <configuration name="Config0">
        <resource name="Res0">{tasks}
        </resource>
{globals}      </configuration>
    </configurations>
  </instances>
</project>
"#,
        head = super::project_head(name),
    )
}

/// A `TYPE` block's declarations as `<dataType>`s.
fn data_types(decls: &[TypeDecl]) -> String {
    let mut types = String::new();
    for t in decls {
        let _ = write!(
            types,
            "      <dataType name=\"{}\">\n        <baseType>",
            escape(t.name.name.as_str())
        );
        let init = match &t.def {
            TypeDef::Struct(members) => {
                let block = VarBlock {
                    kind: VarKind::Local,
                    constant: false,
                    retain: false,
                    decls: members.clone(),
                    span: t.name.span,
                };
                types.push_str("<struct>\n");
                types.push_str(&variables(&block, 10));
                types.push_str("        </struct>");
                None
            }
            TypeDef::Alias(ty, init) => {
                types.push_str(&type_xml(ty));
                init.as_ref().map(|i| value_xml(i, Some(ty)))
            }
        };
        types.push_str("</baseType>\n");
        if let Some(v) = init {
            let _ = writeln!(types, "        <initialValue>{v}</initialValue>");
        }
        types.push_str("      </dataType>\n");
    }
    types
}

/// One POU: its interface and its ST body. A `VAR_GLOBAL` inside it
/// goes to the configuration's (`globals`), where PLCopen keeps them.
fn pou_xml(pou: &Pou, body: &str, globals: &mut String) -> String {
    let kind = match pou.kind {
        PouKind::Program => "program",
        PouKind::Function(_) => "function",
        PouKind::FunctionBlock => "functionBlock",
    };
    let mut out = format!(
        "      <pou name=\"{}\" pouType=\"{kind}\">\n        <interface>\n",
        escape(pou.name.name.as_str())
    );
    if let PouKind::Function(ty) = &pou.kind {
        let _ = writeln!(out, "          <returnType>{}</returnType>", type_xml(ty));
    }
    for block in &pou.vars {
        let tag = match block.kind {
            VarKind::Input => "inputVars",
            VarKind::Output => "outputVars",
            VarKind::InOut => "inOutVars",
            VarKind::Local => "localVars",
            VarKind::Temp => "tempVars",
            VarKind::External => "externalVars",
            VarKind::Global => {
                globals.push_str(&scope_xml(block, "globalVars", 8));
                continue;
            }
        };
        out.push_str(&scope_xml(block, tag, 10));
    }
    // `]]>` cannot stand in CDATA: split it across two sections.
    let body = body.replace("]]>", "]]]]><![CDATA[>");
    let _ = write!(
        out,
        "        </interface>\n        <body>\n          <ST>\n            <xhtml:p><![CDATA[{body}]]></xhtml:p>\n          </ST>\n        </body>\n      </pou>\n"
    );
    out
}

/// A `VAR…` block as the element `tag` (`CONSTANT` and `RETAIN` as its
/// attributes), indented `pad` spaces.
fn scope_xml(block: &VarBlock, tag: &str, pad: usize) -> String {
    let sp = " ".repeat(pad);
    let mut attrs = String::new();
    if block.constant {
        attrs.push_str(" constant=\"true\"");
    }
    if block.retain {
        attrs.push_str(" retain=\"true\"");
    }
    format!(
        "{sp}<{tag}{attrs}>\n{}{sp}</{tag}>\n",
        variables(block, pad + 2)
    )
}

/// A block's declarations, one `<variable>` a name.
fn variables(block: &VarBlock, pad: usize) -> String {
    let sp = " ".repeat(pad);
    let mut out = String::new();
    for d in &block.decls {
        for n in &d.names {
            let address = d
                .location
                .as_ref()
                .map(|a| format!(" address=\"{}\"", escape(a.as_str())))
                .unwrap_or_default();
            let _ = write!(
                out,
                "{sp}<variable name=\"{}\"{address}>\n{sp}  <type>{}</type>\n",
                escape(n.name.as_str()),
                type_xml(&d.ty)
            );
            if let Some(init) = &d.init {
                let _ = writeln!(
                    out,
                    "{sp}  <initialValue>{}</initialValue>",
                    value_xml(init, Some(&d.ty))
                );
            }
            let _ = writeln!(out, "{sp}</variable>");
        }
    }
    out
}

/// A type as PLCopen writes it (`<INT/>`, `<derived name="TON"/>`,
/// `<array>`).
fn type_xml(ty: &TypeRef) -> String {
    match ty {
        TypeRef::Elementary(t) => format!("<{}/>", t.name()),
        TypeRef::String(None) => "<string/>".to_string(),
        TypeRef::String(Some(n)) => format!("<string length=\"{n}\"/>"),
        TypeRef::Named(n) => format!("<derived name=\"{}\"/>", escape(n.name.as_str())),
        TypeRef::Array { dims, of } => {
            let mut out = String::from("<array>");
            for (low, high) in dims {
                let _ = write!(out, "<dimension lower=\"{low}\" upper=\"{high}\"/>");
            }
            let _ = write!(out, "<baseType>{}</baseType></array>", type_xml(of));
            out
        }
    }
}

/// An initial value (`ty`: the type it is of, when known) as PLCopen's
/// `simpleValue`, `arrayValue` or `structValue`.
fn value_xml(init: &Init, ty: Option<&TypeRef>) -> String {
    match init {
        Init::Expr(e) => format!("<simpleValue value=\"{}\"/>", escape(expr_text(e).as_str())),
        Init::Array(items) => {
            let of = match ty {
                Some(TypeRef::Array { of, .. }) => Some(&**of),
                _ => None,
            };
            let mut out = String::from("<arrayValue>");
            for item in items {
                let (count, value) = match item {
                    ArrayInit::One(v) => (None, value_xml(v, of)),
                    ArrayInit::Repeat(n, Some(v)) => (Some(*n), value_xml(v, of)),
                    ArrayInit::Repeat(n, None) => (Some(*n), default_xml(of)),
                };
                match count {
                    Some(n) => {
                        let _ = write!(out, "<value repetitionValue=\"{n}\">{value}</value>");
                    }
                    None => {
                        let _ = write!(out, "<value>{value}</value>");
                    }
                }
            }
            out.push_str("</arrayValue>");
            out
        }
        Init::Struct(members) => {
            let mut out = String::from("<structValue>");
            for (m, v) in members {
                let _ = write!(
                    out,
                    "<value member=\"{}\">{}</value>",
                    escape(m.name.as_str()),
                    value_xml(v, None)
                );
            }
            out.push_str("</structValue>");
            out
        }
    }
}

/// A type's default value, for `n()` in an array's initial value
/// (PLCopen has no empty value): an elementary type's zero, else the
/// empty structure value (every member its default).
fn default_xml(ty: Option<&TypeRef>) -> String {
    let zero = match ty {
        Some(TypeRef::Elementary(Elementary::Bool)) => "FALSE",
        Some(TypeRef::Elementary(Elementary::Real | Elementary::Lreal)) => "0.0",
        Some(TypeRef::Elementary(Elementary::Time)) => "T#0s",
        Some(TypeRef::Elementary(_)) => "0",
        Some(TypeRef::String(_)) => "''",
        _ => return "<structValue/>".to_string(),
    };
    format!("<simpleValue value=\"{zero}\"/>")
}
