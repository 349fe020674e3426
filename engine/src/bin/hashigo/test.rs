//! `hashigo test` (cli.md): every test case stored in a project, each on
//! a fresh machine; one line per case, a summary, and exit 0 when all
//! pass, 1 when one fails, 2 on bad input (nothing printed then).

use std::process::ExitCode;

use engine::cases::{prepare_all, run_prepared, Outcome};
use engine::machines::new_plc;

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::plant::PlantOptions;
use crate::source::{apply_settings, compile_project, machine_flag, one, read_project, Problems};
use engine::plc::Plc;

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

/// The flags `hashigo test` takes: `--set` and the plant's besides cli.md's.
const FLAGS: [&str; 8] = [
    "machine", "program", "format", "junit", "plant", "wiring", "fault", "set",
];

/// Whether every case passed; `Err` on bad input.
fn test(rest: &[String]) -> Result<bool, Problems> {
    let args = Args::parse(rest, &FLAGS).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    if format != Format::Json {
        return Err(one(format!(
            "{path}: hashigo test takes a project (.json): its test cases travel in it"
        )));
    }
    let source = SourceFile::read(path).map_err(one)?;
    let (opened, document) = read_project(&source, format, flag, &Default::default())?;
    if opened.project.tests.is_empty() {
        return Err(one(format!(
            "{}: the project has no test cases",
            source.name
        )));
    }
    let text = compile_project(&args, &source, &document, &opened)?;
    let (project, settings) = (opened.project, opened.settings);
    let held = project.plant.as_ref().map(|p| (source.name.as_str(), p));
    let plant = PlantOptions::read_alone(&args, held)?;
    // Every case is read and the work of all of them counted before any
    // runs (docs/limits.md).
    let prepared = prepare_all(&project.tests).map_err(|e| one(format!("{}: {e}", source.name)))?;
    let machine = project.machine;
    let mut results = Vec::new();
    let mut problems = Vec::new();
    for (case, ready) in project.tests.iter().zip(&prepared) {
        let mut plc = fresh(
            machine,
            &text,
            &args,
            plant.as_ref(),
            (&source.name, &settings),
        )?;
        match ready
            .as_ref()
            .map_err(Clone::clone)
            .and_then(|ready| run_prepared(plc.as_mut(), ready))
        {
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
            Outcome::Pass => println!("pass {}", one_line(name)),
            Outcome::Fail {
                expectation,
                observed,
                ..
            } => {
                failed += 1;
                println!(
                    "fail {}",
                    one_line(&format!("{name}: {expectation}: {observed}"))
                );
            }
        }
    }
    println!("{} passed, {failed} failed", results.len() - failed);
    Ok(failed == 0)
}

/// A fresh machine for one case: the settings, the program, the plant.
fn fresh(
    machine: engine::MachineId,
    text: &str,
    args: &Args,
    plant: Option<&PlantOptions>,
    (name, settings): (&str, &crate::source::Settings),
) -> Result<Box<dyn Plc>, Problems> {
    let mut plc = new_plc(machine);
    let machine_args = PlantOptions::machine_args_of(plant, args);
    let mut setup = apply_settings(plc.as_mut(), &machine_args, (name, settings));
    if let Err(e) = plc.load_text(text) {
        setup.push(format!("{name} (compiled): {e}"));
    }
    if !setup.is_empty() {
        return Err(setup);
    }
    let Some(p) = plant else {
        return Ok(plc);
    };
    let mut planted = p.attach(plc)?;
    let setup = p.set_params(&mut planted, args);
    if !setup.is_empty() {
        return Err(setup);
    }
    Ok(Box::new(planted))
}

/// A JUnit XML report: one suite, one test case per case.
fn junit(suite: &str, results: &[(String, Outcome)]) -> String {
    let failures = results
        .iter()
        .filter(|(_, o)| matches!(o, Outcome::Fail { .. }))
        .count();
    let mut xml = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\">\n",
        escape(suite, true),
        results.len()
    );
    for (name, outcome) in results {
        match outcome {
            Outcome::Pass => xml.push_str(&format!("  <testcase name=\"{}\"/>\n", escape(name, true))),
            Outcome::Fail {
                expectation,
                observed,
                ..
            } => xml.push_str(&format!(
                "  <testcase name=\"{}\">\n    <failure message=\"{}\">{}</failure>\n  </testcase>\n",
                escape(name, true),
                escape(expectation, true),
                escape(observed, false)
            )),
        }
    }
    xml.push_str("</testsuite>\n");
    xml
}

/// Text safe inside XML 1.0: markup escaped; characters XML 1.0 cannot
/// carry even as references (most control characters, U+FFFE, U+FFFF,
/// lone surrogates cannot occur in a `str`) written as U+FFFD; in an
/// attribute, line breaks and tabs as references so that they survive
/// attribute-value normalisation.
fn escape(text: &str, attribute: bool) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\n' | '\t' if !attribute => out.push(c),
            '\n' | '\t' | '\r' => out.push_str(&format!("&#{};", u32::from(c))),
            '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..='\u{10FFFF}' => {
                out.push(c)
            }
            _ => out.push('\u{fffd}'),
        }
    }
    out
}

/// A case's line as the terminal shows it: one line, control characters
/// (newlines, escape sequences) and backslashes escaped, so that a name
/// can neither forge another line nor drive the terminal.
fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() || c == '\\' {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}
