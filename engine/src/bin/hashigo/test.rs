//! `hashigo test` (cli.md): every test case stored in a project, each on
//! a fresh machine; one line per case, a summary, and exit 0 when all
//! pass, 1 when one fails, 2 on bad input (nothing printed then).

use std::process::ExitCode;

use engine::cases::{run_case, Outcome};
use engine::plc::new_plc;

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::source::{apply_settings, compile_project, machine_flag, one, read_project, Problems};

/// Runs the command; the exit code as cli.md gives it.
pub fn main(rest: &[String]) -> ExitCode {
    match test(rest) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(problems) => {
            for p in problems {
                eprintln!("error: {}", crate::printable(&p));
            }
            ExitCode::from(2)
        }
    }
}

/// Whether every case passed; `Err` on bad input.
fn test(rest: &[String]) -> Result<bool, Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "junit"]).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    if format != Format::Json {
        return Err(one(format!(
            "{path}: hashigo test takes a project (.json): its test cases travel in it"
        )));
    }
    let source = SourceFile::read(path).map_err(one)?;
    let (project, settings) = read_project(&source, format, flag, &Default::default())?;
    if project.tests.is_empty() {
        return Err(one(format!(
            "{}: the project has no test cases",
            source.name
        )));
    }
    let text = compile_project(&args, &source, &project, &settings)?;
    let machine = project.machine;
    let mut results = Vec::new();
    let mut problems = Vec::new();
    for case in &project.tests {
        let mut plc = new_plc(machine);
        let mut setup = apply_settings(plc.as_mut(), &Args::empty(), (&source.name, &settings));
        if let Err(e) = plc.load_text(&text) {
            setup.push(format!("{} (compiled): {e}", source.name));
        }
        if !setup.is_empty() {
            return Err(setup);
        }
        match run_case(plc.as_mut(), case) {
            Ok(outcome) => results.push((case.name.clone(), outcome)),
            Err(e) => problems.push(format!(
                "{}: test {}: {e}",
                source.name,
                engine::shown(&case.name)
            )),
        }
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    if let Some(file) = args.optional("junit").map_err(one)? {
        std::fs::write(file, junit(&source.name, &results))
            .map_err(|e| one(format!("{file}: cannot write: {e}")))?;
    }
    let mut failed = 0;
    for (name, outcome) in &results {
        match outcome {
            Outcome::Pass => println!("pass {name}"),
            Outcome::Fail {
                expectation,
                observed,
                ..
            } => {
                failed += 1;
                println!("fail {name}: {expectation}: {observed}");
            }
        }
    }
    println!("{} passed, {failed} failed", results.len() - failed);
    Ok(failed == 0)
}

/// A JUnit XML report: one suite, one test case per case.
fn junit(suite: &str, results: &[(String, Outcome)]) -> String {
    let failures = results
        .iter()
        .filter(|(_, o)| matches!(o, Outcome::Fail { .. }))
        .count();
    let mut xml = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\">\n",
        escape(suite),
        results.len()
    );
    for (name, outcome) in results {
        match outcome {
            Outcome::Pass => xml.push_str(&format!("  <testcase name=\"{}\"/>\n", escape(name))),
            Outcome::Fail {
                expectation,
                observed,
                ..
            } => xml.push_str(&format!(
                "  <testcase name=\"{}\">\n    <failure message=\"{}\">{}</failure>\n  </testcase>\n",
                escape(name),
                escape(expectation),
                escape(observed)
            )),
        }
    }
    xml.push_str("</testsuite>\n");
    xml
}

/// Text safe inside XML attributes and elements.
fn escape(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '&' => "&amp;".to_string(),
            '<' => "&lt;".to_string(),
            '>' => "&gt;".to_string(),
            '"' => "&quot;".to_string(),
            // XML 1.0 has no way to write most control characters.
            c if c.is_control() && c != '\n' && c != '\t' => "\u{fffd}".to_string(),
            c => c.to_string(),
        })
        .collect()
}
