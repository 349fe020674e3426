//! A project's declarations as the soft PLC ladder's variables (issue
//! #31): what the variables pane shows after a PLCopen project is opened
//! on the soft PLC — each variable of the POUs that run and of the
//! configurations, with its type, address, start value, retain and
//! documentation.

use crate::error::Located;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::error::{Errors, ImportError};
use crate::ladder::variables::Variable;

/// The interface sections whose variables a POU's body reads and writes
/// (an external is declared as the POU says, when no global is).
const SCOPES: [&str; 7] = [
    "externalVars",
    "localVars",
    "inputVars",
    "outputVars",
    "inOutVars",
    "tempVars",
    "globalVars",
];

/// [`declared`] when the project is read for the soft PLC; nothing on
/// the bit machines (their devices have no declarations).
pub(in crate::formats::plcopen) fn declared_for(
    machine: Option<crate::MachineId>,
    root: &Node,
    chosen: &[&Node],
) -> Result<Vec<Variable>, Errors> {
    match machine {
        Some(m) if m.target().capabilities().word_boxes => declared(root, chosen),
        _ => Ok(Vec::new()),
    }
}

/// The ladder's variables once its bodies are read: without the BOOLs
/// that carried box input networks now drawn under their boxes (a
/// PLCopen export declares them), with those made to carry one box's
/// output into another ([`super::rungs::temp_variables`]).
pub(in crate::formats::plcopen) fn settle(
    variables: &mut Vec<Variable>,
    carriers: &[String],
    temps: &[crate::formats::plcopen::lower::body::Temp],
    names: &crate::formats::plcopen::declare::Names,
) {
    variables.retain(|v| {
        let plain = v.address.is_empty() && v.initial.is_empty() && v.comment.is_empty();
        !(plain && carriers.contains(&v.name.to_ascii_uppercase()))
    });
    variables.extend(super::rungs::temp_variables(temps, names));
}

/// Drops the R_TRIG / F_TRIG instances an export named (`R_TRIG3`) that
/// nothing names any more: their boxes were drawn as in-line edges.
pub(in crate::formats::plcopen) fn drop_edge_instances(ladder: &mut crate::ladder::Ladder) {
    let mut used = std::collections::HashSet::new();
    for rung in &ladder.rungs {
        for (_, element) in rung.elements() {
            let mut e = element.clone();
            e.names_mut(|n| {
                let stem = n.split('.').next().unwrap_or(n);
                used.insert(stem.to_ascii_uppercase());
            });
        }
    }
    ladder.variables.retain(|v| {
        let generated = ["R_TRIG", "F_TRIG"].iter().any(|kind| {
            v.data_type.eq_ignore_ascii_case(kind)
                && v.name
                    .strip_prefix(kind)
                    .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()))
        });
        !generated || used.contains(&v.name.to_ascii_uppercase())
    });
}

/// The variables the `chosen` POUs and the project's configurations
/// declare, in file order, each once; a declaration the soft PLC does not
/// take (an array, a structure, a bad address or start value) or a name
/// declared twice with different types is an error at its line.
fn declared(root: &Node, chosen: &[&Node]) -> Result<Vec<Variable>, Errors> {
    let mut sections: Vec<&Node> = Vec::new();
    for pou in chosen {
        if let Some(interface) = pou.child("interface") {
            sections.extend(
                interface
                    .children
                    .iter()
                    .filter(|c| SCOPES.contains(&c.name.as_str())),
            );
        }
    }
    if let Some(instances) = root.child("instances") {
        instances.descendants("globalVars", &mut sections);
    }
    let mut out: Vec<(Variable, usize)> = Vec::new();
    let mut errors = Vec::new();
    let own = own_blocks_not_boxes(root);
    for section in sections {
        let retain = section.attr("retain") == Some("true");
        for v in section.all("variable") {
            let (name, address) = (v.attr("name"), v.attr("address"));
            if crate::formats::plcopen::address::stands_for(
                name.unwrap_or_default(),
                address.unwrap_or_default(),
            ) {
                // Drawn as the address itself.
                continue;
            }
            if own.contains(&derived_type(v)) {
                // Its block is refused where it is called, with why.
                continue;
            }
            let variable = match variable(v, retain) {
                Ok(variable) => variable,
                Err(e) => {
                    errors.push(Located::new(v.line, e));
                    continue;
                }
            };
            let same = out
                .iter()
                .find(|(o, _)| o.name.eq_ignore_ascii_case(&variable.name));
            match same {
                None => out.push((variable, v.line)),
                Some((o, _)) if o.data_type.eq_ignore_ascii_case(&variable.data_type) => {}
                Some((o, first)) => errors.push(Located::new(
                    v.line,
                    ImportError::SoftVariableTwice {
                        name: variable.name.clone(),
                        first: *first,
                        types: (o.data_type.clone(), variable.data_type.clone()),
                    },
                )),
            }
        }
    }
    if errors.is_empty() {
        Ok(out.into_iter().map(|(v, _)| v).collect())
    } else {
        Err(errors)
    }
}

/// The project's own POUs (upper-case) that are not the soft PLC's
/// boxes ([`crate::ladder::user_blocks`]): an instance of one is said
/// at the block that calls it (`ImportError::ProjectBlock`), not as a
/// variable of an unknown type.
fn own_blocks_not_boxes(root: &Node) -> std::collections::HashSet<String> {
    let mut pous = Vec::new();
    root.descendants("pou", &mut pous);
    pous.iter()
        .filter_map(|p| p.attr("name"))
        .map(|n| n.trim().to_ascii_uppercase())
        .filter(|n| !crate::ladder::user_blocks::is_block_type(n))
        .collect()
}

/// The type a `<variable>` derives (upper-case; empty for another).
fn derived_type(v: &Node) -> String {
    v.child("type")
        .and_then(|t| t.child("derived"))
        .and_then(|d| d.attr("name"))
        .unwrap_or_default()
        .trim()
        .to_ascii_uppercase()
}

/// One `<variable>` as the ladder declares it.
fn variable(v: &Node, retain: bool) -> Result<Variable, ImportError> {
    let name = v.attr("name").unwrap_or_default().trim();
    let ty = v.child("type").and_then(|t| t.children.first());
    let data_type = match ty {
        Some(t) if t.name == "derived" => t.attr("name").unwrap_or_default().to_string(),
        Some(t) => t.name.to_ascii_uppercase(),
        None => String::new(),
    };
    let initial = v
        .child("initialValue")
        .and_then(|i| i.child("simpleValue"))
        .and_then(|s| s.attr("value"))
        .unwrap_or_default();
    let variable = Variable {
        name: name.to_string(),
        data_type: data_type.trim().to_ascii_uppercase(),
        address: v.attr("address").unwrap_or_default().trim().to_string(),
        initial: initial.trim().to_string(),
        retain,
        comment: v
            .child("documentation")
            .map(|d| d.deep_text().trim().to_string())
            .unwrap_or_default(),
    };
    variable.check().map_err(ImportError::SoftVariable)?;
    Ok(variable)
}
