//! A PLCopen project's Structured Text as one `.st` text (issue #54):
//! its data types, the configuration's globals and every POU whose body
//! is ST (programs, functions, function blocks) with its interface, the
//! bodies as the file writes them. What [`super::export_st`] writes back.

use std::fmt::Write as _;

use super::dom::Node;

/// The ST text of project `root`: `TYPE`s, `VAR_GLOBAL`s, then the ST
/// POUs in file order (POUs in other languages are left out).
pub fn st_source(root: &Node) -> String {
    let mut out = String::new();
    let mut types = Vec::new();
    root.descendants("dataType", &mut types);
    if !types.is_empty() {
        out.push_str("TYPE\n");
        for t in types {
            let name = t.attr("name").unwrap_or_default();
            let base = t.child("baseType").and_then(|b| b.children.first());
            match base {
                Some(s) if s.name == "struct" => {
                    let _ = writeln!(out, "    {name} : STRUCT");
                    for v in s.all("variable") {
                        out.push_str(&declaration(v, 2));
                    }
                    out.push_str("    END_STRUCT;\n");
                }
                _ => {
                    let init = t.child("initialValue").map(value_text);
                    let init = init.map(|v| format!(" := {v}")).unwrap_or_default();
                    let _ = writeln!(out, "    {name} : {}{init};", type_text(base));
                }
            }
        }
        out.push_str("END_TYPE\n\n");
    }
    // The configurations' and their resources' globals (a POU's own
    // `globalVars` stay in its interface).
    let mut configurations = Vec::new();
    root.descendants("configuration", &mut configurations);
    let resources = configurations.iter().flat_map(|c| c.all("resource"));
    let scopes = configurations.iter().copied().chain(resources);
    for g in scopes.flat_map(|s| s.all("globalVars")) {
        out.push_str(&block(g, "VAR_GLOBAL", 0));
        out.push('\n');
    }
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    pous.retain(|p| p.child("body").and_then(|b| b.child("ST")).is_some());
    in_task_order(root, &mut pous);
    for p in pous {
        if let Some(text) = p.child("body").and_then(|b| b.child("ST")) {
            out.push_str(&pou(p, text.child("p").unwrap_or(text)));
        }
    }
    out
}

/// The programs among `pous` in the order the tasks run them (their
/// `pouInstance`s in file order; one no task runs after those, in file
/// order), each in a program's place: a `.st` text runs its programs in
/// text order (`iec::st::rename`). The other POUs keep their places.
fn in_task_order(root: &Node, pous: &mut [&Node]) {
    let mut instances = Vec::new();
    root.descendants("pouInstance", &mut instances);
    let rank = |p: &Node| {
        let name = p.attr("name").unwrap_or_default();
        instances
            .iter()
            .position(|i| {
                i.attr("typeName")
                    .is_some_and(|t| t.eq_ignore_ascii_case(name))
            })
            .unwrap_or(usize::MAX)
    };
    let is_program = |p: &&Node| p.attr("pouType") == Some("program");
    let slots: Vec<usize> = (0..pous.len()).filter(|&i| is_program(&pous[i])).collect();
    let mut programs: Vec<&Node> = slots.iter().map(|&i| pous[i]).collect();
    // Stable: programs of one rank (none run by a task) keep file order.
    crate::sort::by_key(&mut programs, |p| rank(p));
    for (slot, p) in slots.into_iter().zip(programs) {
        pous[slot] = p;
    }
}

/// One POU: its header, interface, body and end.
fn pou(p: &Node, body: &Node) -> String {
    let name = p.attr("name").unwrap_or_default();
    let interface = p.child("interface");
    let (kw, end) = match p.attr("pouType") {
        Some("function") => ("FUNCTION", "END_FUNCTION"),
        Some("functionBlock") => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        _ => ("PROGRAM", "END_PROGRAM"),
    };
    let mut out = format!("{kw} {name}");
    if let Some(r) = interface.and_then(|i| i.child("returnType")) {
        let _ = write!(out, " : {}", type_text(r.children.first()));
    }
    out.push('\n');
    for scope in interface.map(|i| i.children.as_slice()).unwrap_or_default() {
        let keyword = match scope.name.as_str() {
            "inputVars" => "VAR_INPUT",
            "outputVars" => "VAR_OUTPUT",
            "inOutVars" => "VAR_IN_OUT",
            "localVars" => "VAR",
            "tempVars" => "VAR_TEMP",
            "externalVars" => "VAR_EXTERNAL",
            "globalVars" => "VAR_GLOBAL",
            _ => continue,
        };
        out.push_str(&block(scope, keyword, 1));
    }
    let _ = write!(out, "{}\n{end}\n\n", body.text);
    out
}

/// A `VAR…` block from its PLCopen element (`constant`, `retain`).
fn block(scope: &Node, keyword: &str, level: usize) -> String {
    let pad = "    ".repeat(level);
    let mut out = format!("{pad}{keyword}");
    if scope.attr("constant") == Some("true") {
        out.push_str(" CONSTANT");
    }
    if scope.attr("retain") == Some("true") {
        out.push_str(" RETAIN");
    }
    out.push('\n');
    for v in scope.all("variable") {
        out.push_str(&declaration(v, level + 1));
    }
    let _ = writeln!(out, "{pad}END_VAR");
    out
}

/// `name [AT %…] : TYPE [:= value];` for `<variable>` `v`.
fn declaration(v: &Node, level: usize) -> String {
    let mut out = format!(
        "{}{}",
        "    ".repeat(level),
        v.attr("name").unwrap_or_default()
    );
    if let Some(a) = v.attr("address") {
        let _ = write!(out, " AT {a}");
    }
    let ty = v.child("type").and_then(|t| t.children.first());
    let _ = write!(out, " : {}", type_text(ty));
    if let Some(init) = v.child("initialValue") {
        let _ = write!(out, " := {}", value_text(init));
    }
    out.push_str(";\n");
    out
}

/// A `<type>`'s element as ST (`INT`, `TON`, `ARRAY [1..3] OF INT`,
/// `STRING[20]`).
fn type_text(ty: Option<&Node>) -> String {
    let Some(ty) = ty else {
        return String::new();
    };
    match ty.name.as_str() {
        "derived" => ty.attr("name").unwrap_or_default().to_string(),
        "string" | "wstring" => {
            let kw = ty.name.to_ascii_uppercase();
            match ty.attr("length") {
                Some(n) => format!("{kw}[{n}]"),
                None => kw,
            }
        }
        "array" => {
            let dims: Vec<String> = ty
                .all("dimension")
                .map(|d| {
                    let low = d.attr("lower").unwrap_or_default();
                    format!("{low}..{}", d.attr("upper").unwrap_or_default())
                })
                .collect();
            let of = ty.child("baseType").and_then(|b| b.children.first());
            format!("ARRAY [{}] OF {}", dims.join(", "), type_text(of))
        }
        other => other.to_string(),
    }
}

/// An `<initialValue>` (or a `<value>` inside one) as ST.
fn value_text(v: &Node) -> String {
    let Some(inner) = v.children.first() else {
        return String::new();
    };
    match inner.name.as_str() {
        "arrayValue" => {
            let items: Vec<String> = inner
                .all("value")
                .map(|x| match x.attr("repetitionValue") {
                    Some(n) => format!("{n}({})", value_text(x)),
                    None => value_text(x),
                })
                .collect();
            format!("[{}]", items.join(", "))
        }
        "structValue" => {
            let members: Vec<String> = inner
                .all("value")
                .map(|x| {
                    let m = x.attr("member").unwrap_or_default();
                    format!("{m} := {}", value_text(x))
                })
                .collect();
            // No member given: every one its default (`n()` in a list).
            if members.is_empty() {
                return String::new();
            }
            format!("({})", members.join(", "))
        }
        _ => inner.attr("value").unwrap_or_default().to_string(),
    }
}
