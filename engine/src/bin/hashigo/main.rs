//! `hashigo`: the engine's command-line front (../shared/spec/cli.md).
//!
//! Exit status 0 on success, 2 on bad input, with one `error: ...` line per
//! problem on standard error and nothing partial on standard output.

mod args;
mod commands;
mod input;
mod map;
mod plant;
mod share;
mod source;
mod test;
mod why;

use std::process::ExitCode;

const USAGE: &str = "\
usage: hashigo <command> [options]
  run      --machine ID --program FILE [--set NAME=VALUE]... [--input EVENTS.csv]
           --until TIME [--every TIME] --watch DEV[,DEV...]
           (a .st file, Structured Text, runs on soft-plc: --machine may be left out;
            a PLCopen .xml on soft-plc runs its LD, FBD, IL and ST bodies as written;
            ST's members and array elements are watched as NAME.MEMBER, NAME[I,J])
           [--plant NAME [--wiring WIRING.csv] [--fault FAULT]... [--set NAME.KEY=VALUE]...]
           (run, test and why take the plant options; alarms go to stderr)
  bench    --machine ID --program FILE --steps N
  asm      --machine ID --program FILE
  compile  [--machine ID] --program LADDER.json|LADDER.xml|LADDER.ld [--map MAP.csv] [--pou NAME]
  console  --machine io86a|arduino-plc [--program FILE] [--step TIME]
  share    --program FILE [--machine ID]      (prints the share link's fragment)
  unshare  FRAGMENT|URL                       (prints the project as JSON)
  test     --program P.json [--machine ID] [--junit FILE] [plant options]
  map      --machine ID --program FILE.xml [--map MAP.csv] [--pou NAME]  (proposes a --map file)
  why      --machine ID --program FILE [--input EVENTS.csv] [--set NAME=VALUE]...
           --at TIME --device DEV       (why DEV is on or off at the end of that scan)
  plants   [--machine ID]             (the plants: signals, quantities, parameters, default wiring)
faults:  'SIGNAL stuck 0|1 [from TIME]', 'SIGNAL dead [from TIME]'; watch NAME.SIGNAL, NAME.QUANTITY, NAME.alarms
machines: minasec-u, io86a, avr-plc, arduino-plc, soft-plc
plants: conveyor, tank, traffic, door, sorter, room-light";

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    let Some((command, rest)) = argv.split_first() else {
        eprintln!("{USAGE}");
        return ExitCode::from(2);
    };
    if command == "test" {
        return test::main(rest);
    }
    let result = match command.as_str() {
        "run" => commands::run(rest),
        "bench" => commands::bench(rest),
        "asm" => commands::asm(rest),
        "console" => commands::console(rest),
        "compile" => commands::compile(rest),
        "share" => share::share(rest),
        "unshare" => share::unshare(rest),
        "why" => why::why(rest),
        "map" => map::map(rest),
        "plants" => plant::plants(rest),
        "help" | "--help" | "-h" => {
            println!("{USAGE}");
            Ok(())
        }
        other => Err(vec![format!(
            "unknown command {}\n{USAGE}",
            engine::shown(other)
        )]),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(problems) => {
            for problem in problems {
                eprintln!("error: {}", printable(&problem));
            }
            ExitCode::from(2)
        }
    }
}

/// A problem as one printable line: control characters (a raw newline,
/// NUL, ESC from a hostile file) escaped, and cut at 2 000 characters.
/// The messages themselves already quote and shorten what they repeat;
/// this is the last guard for the terminal.
pub(crate) fn printable(problem: &str) -> String {
    // The usage text after an unknown command is the one intended multi-line message.
    if let Some((first, usage)) = problem.split_once("\nusage: ") {
        return format!("{}\nusage: {usage}", printable(first));
    }
    let mut out = String::new();
    for (i, c) in problem.chars().enumerate() {
        if i == 2000 {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}
