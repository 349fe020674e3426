//! The ST bodies of the real PLCopen projects in ../shared/fixtures
//! (when the folder is present): every one parses, as statements or, for
//! SFC transitions and actions' conditions, as one expression, or is
//! refused only for a listed reason. Prints a table of which.

use std::path::Path;

use engine::iec::st::{parse_body, parse_expr};

const REAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/fixtures/plcopen");

/// Refusals a real body may get: the features left out on purpose.
const ALLOWED: [&str; 1] = ["a pragma `{…}`"];

/// The text between each `open` and the next `close` in `xml`.
fn between<'a>(xml: &'a str, open: &str, close: &str) -> Vec<&'a str> {
    let mut out = Vec::new();
    let mut rest = xml;
    while let Some(at) = rest.find(open) {
        let after = &rest[at + open.len()..];
        let Some(end) = after.find(close) else { break };
        out.push(&after[..end]);
        rest = &after[end..];
    }
    out
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// Each ST text of a project: PLCopen's `<ST><xhtml:p><![CDATA[…]]>`
/// and CODESYS's EXECUTE block's `<STCode>`.
fn st_texts(xml: &str) -> Vec<String> {
    let mut out: Vec<String> = between(xml, "<ST>", "</ST>")
        .into_iter()
        .flat_map(|st| between(st, "<![CDATA[", "]]>"))
        .map(str::to_string)
        .collect();
    for code in between(xml, "<STCode", "</STCode>") {
        let body = code.split_once('>').map_or("", |(_, b)| b);
        out.push(unescape(body));
    }
    out
}

#[test]
fn real_projects_st_bodies() {
    let Ok(dir) = std::fs::read_dir(REAL) else {
        eprintln!("{REAL} absent: skipped");
        return;
    };
    let mut files: Vec<_> = dir.flatten().map(|e| e.path()).collect();
    files.sort();
    let mut table = vec![format!(
        "{:<28} {:>6} {:>6} {:>6}",
        "project", "bodies", "conds", "refused"
    )];
    let mut total = 0;
    for path in files
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "xml"))
    {
        let xml = std::fs::read_to_string(path).expect("readable");
        let (mut bodies, mut conds, mut refused) = (0, 0, Vec::new());
        for text in st_texts(&xml) {
            total += 1;
            match parse_body(&text) {
                Ok(_) => bodies += 1,
                Err(_) if parse_expr(&text).is_ok() => conds += 1,
                Err(e) => {
                    let allowed = ALLOWED.iter().any(|a| e.to_string().contains(a));
                    assert!(allowed, "{}: {e}\n{text}", name(path));
                    refused.push(e.to_string());
                }
            }
        }
        if bodies + conds + refused.len() > 0 {
            table.push(format!(
                "{:<28} {bodies:>6} {conds:>6} {:>6}",
                name(path),
                refused.len()
            ));
            table.extend(refused.iter().map(|r| format!("    refused: {r}")));
        }
    }
    println!("{}", table.join("\n"));
    assert!(total > 0, "no ST text found in {REAL}");
}

fn name(path: &Path) -> String {
    path.file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned())
}
