//! Helpers: load an ST text, scan it, read values.

use engine::iec::data::Data;
use engine::softplc::Program;

/// Loads `text`, panicking with its errors (a test's own program).
pub fn load(text: &str) -> Program {
    match Program::load_st(text) {
        Ok(p) => p,
        Err(es) => {
            let lines: Vec<String> = es.iter().map(|e| e.to_string()).collect();
            panic!("{}\n--- lowered:\n{}", lines.join("\n"), lowered(text));
        }
    }
}

fn lowered(text: &str) -> String {
    engine::iec::st::parse_source(text)
        .ok()
        .and_then(|s| engine::iec::st::lower_source(&s).ok())
        .map(|l| l.text)
        .unwrap_or_default()
}

/// A program's body run once in a PROGRAM with `vars` declared.
pub fn run_once(vars: &str, body: &str) -> Program {
    let mut p = load(&format!(
        "PROGRAM t\nVAR\n{vars}\nEND_VAR\n{body}\nEND_PROGRAM\n"
    ));
    p.scan(0);
    p
}

/// The value of `name` as text (`42`, `TRUE`, `1.5`).
pub fn shown(p: &Program, name: &str) -> String {
    match p.value(name) {
        Some(d) => show(&d),
        None => panic!("no variable {name}"),
    }
}

fn show(d: &Data) -> String {
    match d {
        Data::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        Data::Int(_, v) => v.to_string(),
        Data::Real(r) => r.to_string(),
        Data::Lreal(r) => r.to_string(),
        Data::Time(ns) => format!("{}ms", ns / 1_000_000),
        Data::Text(t) => t.to_string(),
    }
}

/// The refusals of `text`, as `line:column: message`.
pub fn refusals(text: &str) -> Vec<String> {
    match Program::load_st(text) {
        Ok(_) => panic!("loaded:\n{text}"),
        Err(es) => es.iter().map(|e| e.to_string()).collect(),
    }
}
