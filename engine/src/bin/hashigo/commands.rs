//! The subcommands. Each returns the problem lines (without `error: `) on
//! failure and prints nothing to standard output unless it succeeds. They
//! reach the machines only through the engine's `Plc` interface.

use std::io::{BufRead, Write};
use std::time::Instant;

use engine::events::parse_events;
use engine::headless::{self, RunError, Schedule};
use engine::machines::new_plc;
use engine::plc::{Command, Plc};
use engine::{MachineId, SimTime};

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::plant::PlantOptions;
use crate::source::{self, apply_settings, load, machine_flag, one, Problems};

/// `hashigo run`.
pub fn run(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(
        rest,
        &[
            "machine", "program", "format", "set", "input", "until", "every", "watch", "map",
            "pou", "plant", "wiring", "fault",
        ],
    )
    .map_err(one)?;
    // An unknown machine is the only thing worth saying.
    let flag = machine_flag(&args)?;
    match load(&args) {
        Ok(source) => {
            let defaults = (source.name.as_str(), source.settings.as_slice());
            let plant = source.project.as_ref().and_then(|p| p.plant.as_ref());
            let held = plant.map(|p| (source.name.as_str(), p));
            run_with(&args, source.plc, (defaults, held), Vec::new())
        }
        // Still check everything else, on the same machine with no program.
        Err(problems) => match flag {
            Some(id) => run_with(&args, new_plc(id), (("", &[]), None), problems),
            None => Err(problems),
        },
    }
}

/// `--input`'s events, if given; its problems go to `problems`.
pub fn read_events(
    args: &Args,
    problems: &mut Problems,
) -> Option<(SourceFile, Vec<engine::events::InputEvent>)> {
    match args.optional("input") {
        Ok(Some(path)) => match SourceFile::read(path) {
            Ok(source) => match parse_events(&source.text) {
                Ok(events) => Some((source, events)),
                Err(errors) => {
                    problems.extend(source.located(&errors));
                    None
                }
            },
            Err(e) => {
                problems.push(e);
                None
            }
        },
        Ok(None) => None,
        Err(e) => {
            problems.push(e);
            None
        }
    }
}

/// A project's settings with its file's name, applied before `--set`.
type Defaults<'a> = (&'a str, &'a [(String, String, usize)]);

/// Checks the rest of `hashigo run`'s options against `plc` and runs it;
/// `problems` already found are reported with any new ones.
fn run_with(
    args: &Args,
    mut plc: Box<dyn Plc>,
    (defaults, held): (Defaults, crate::plant::Held),
    mut problems: Problems,
) -> Result<(), Problems> {
    let until = args
        .required("until")
        .and_then(|t| SimTime::parse(t).map_err(|e| format!("--until: {e}")));
    let every = args.optional("every").and_then(|t| {
        t.map(|t| SimTime::parse(t).map_err(|e| format!("--every: {e}")))
            .transpose()
    });
    let watch: Vec<String> = args.all("watch").flat_map(split_devices).collect();
    if watch.is_empty() || watch.iter().any(String::is_empty) {
        problems.push("--watch needs device names, e.g. --watch Y00,Y01,C0.v".to_string());
    }
    let plant = PlantOptions::read(args, held, &mut problems);
    let machine_args = PlantOptions::machine_args_of(plant.as_ref(), args);
    problems.extend(apply_settings(plc.as_mut(), &machine_args, defaults));
    let events = read_events(args, &mut problems);
    if args.optional("program") == Ok(Some("-")) && args.optional("input") == Ok(Some("-")) {
        problems.push(
            "--program - and --input - both read standard input: give one of them as a file"
                .to_string(),
        );
    }
    let until = until.map_err(|p| problems.push(p)).ok();
    let every = every.map_err(|p| problems.push(p)).ok();
    // A problem found both while loading and while checking settings is
    // said once.
    let mut seen = std::collections::HashSet::new();
    problems.retain(|p| seen.insert(p.clone()));
    let (Some(until), Some(every)) = (until, every) else {
        return Err(problems);
    };
    if !problems.is_empty() {
        return Err(problems);
    }

    let schedule = Schedule {
        until,
        every: every.unwrap_or(until),
    };
    let (source_name, event_list) = match &events {
        Some((source, list)) => (source.name.as_str(), list.as_slice()),
        None => ("", &[][..]),
    };
    let Some(plant) = plant else {
        return print_run(plc.as_mut(), (source_name, event_list), schedule, &watch);
    };
    let mut planted = plant.attach(plc)?;
    let problems = plant.set_params(&mut planted, args);
    if !problems.is_empty() {
        return Err(problems);
    }
    let result = print_run(&mut planted, (source_name, event_list), schedule, &watch);
    if result.is_ok() {
        for line in crate::plant::alarm_lines(&planted) {
            eprintln!("{}", crate::printable(&line));
        }
    }
    result
}

/// Runs `plc` and prints the CSV on standard output.
fn print_run<P: Plc + ?Sized>(
    plc: &mut P,
    (source_name, event_list): (&str, &[engine::events::InputEvent]),
    schedule: Schedule,
    watch: &[String],
) -> Result<(), Problems> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    headless::run(plc, event_list, schedule, watch, &mut out).map_err(|errors| {
        errors
            .into_iter()
            .map(|e| match e {
                RunError::Watch(message) => format!("--watch: {message}"),
                RunError::Event(located) => {
                    format!("{source_name}:{}: {}", located.line, located.error)
                }
                RunError::ZeroInterval => "--every must be greater than zero".to_string(),
                RunError::TooManyValues(n) => format!(
                    "--every is so small that the run would print more than {n} values (rows × watched devices; docs/limits.md)"
                ),
                RunError::Output(e) => format!("<stdout>: cannot write: {e}"),
            })
            .collect::<Vec<_>>()
    })?;
    out.flush()
        .map_err(|e| one(format!("<stdout>: cannot write: {e}")))?;
    Ok(())
}

/// `hashigo bench`: `--steps` steps flat out from power-on, inputs at 0
/// (whole scans on the scan machines, so the count is rounded up).
pub fn bench(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "steps"]).map_err(one)?;
    let mut plc = load(&args)?.plc;
    let steps_text = args.required("steps").map_err(one)?;
    let steps: u64 = steps_text.parse().ok().filter(|&n| n > 0).ok_or_else(|| {
        one(format!(
            "--steps {steps_text}: expected a whole number above 0"
        ))
    })?;
    let (end, executed) = plc.time_for_steps(steps).ok_or_else(|| {
        one(format!(
            "--steps {steps}: the program has nothing to run, or that many steps are past the simulated clock's range"
        ))
    })?;
    let started = Instant::now();
    plc.run_until(end);
    let seconds = started.elapsed().as_secs_f64();
    let rate = if seconds > 0.0 {
        executed as f64 / seconds
    } else {
        f64::INFINITY
    };
    println!("steps={executed} seconds={seconds:.6} steps_per_second={rate:.0}");
    Ok(())
}

/// `hashigo asm`.
pub fn asm(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "map", "pou"]).map_err(one)?;
    print!("{}", load(&args)?.plc.listing());
    Ok(())
}

/// `hashigo console`: the device's serial terminal on standard input and
/// output. After each line the simulated clock advances by `--step`.
pub fn console(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "step"]).map_err(one)?;
    let id =
        MachineId::parse(args.required("machine").map_err(one)?).map_err(|e| one(e.to_string()))?;
    let mut plc = match args.optional("program").map_err(one)? {
        Some(_) => load(&args)?.plc,
        None => new_plc(id),
    };
    // The Arduino sketch waits for `e` after power-up.
    if id == MachineId::ArduinoPlc {
        plc.apply(Command::Run(false))
            .map_err(|e| one(e.to_string()))?;
    }
    let greeting = plc.serial_open().map_err(|e| one(e.to_string()))?;
    let step = match args.optional("step").map_err(one)? {
        Some(t) => SimTime::parse(t).map_err(|e| one(format!("--step: {e}")))?,
        None => SimTime::from_millis(10),
    };
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let _ = write!(out, "{greeting}");
    // What the program sends on its own while running (the soft PLC's
    // UART), printed after each step.
    let (mut seen, mut sent) = (0, String::new());
    for line in std::io::stdin().lock().lines() {
        let line = line.map_err(|e| one(format!("<stdin>: cannot read: {e}")))?;
        for typed in typed_lines(&line) {
            let reply = plc.serial(typed).map_err(|e| one(e.to_string()))?;
            let _ = write!(out, "{reply}");
            plc.run_until(advance(plc.now(), step)?);
            sent.clear();
            seen = plc.serial_sent(seen, &mut sent);
            let _ = write!(out, "{sent}");
            let _ = out.flush();
        }
    }
    Ok(())
}

/// `now + step` on the simulated clock, or the problem when that passes
/// the clock's limit (docs/limits.md).
fn advance(now: SimTime, step: SimTime) -> Result<SimTime, Problems> {
    now.checked_add(step).ok_or_else(|| {
        one(format!(
            "--step: the simulated clock would pass its limit of {}s (docs/limits.md)",
            engine::limits::MAX_SIM_SECONDS
        ))
    })
}

/// The lines typed in one line of standard input: LF and CR LF end a line
/// (cli.md), and a bare CR, which serial terminals send, does too.
fn typed_lines(line: &str) -> impl Iterator<Item = &str> {
    line.strip_suffix('\r').unwrap_or(line).split('\r')
}

/// `hashigo compile`: a ladder (`.json` project, PLCopen `.xml` or
/// LDmicro `.ld`) to the machine's program text, which `hashigo run`
/// takes back.
pub fn compile(rest: &[String]) -> Result<(), Problems> {
    let args =
        Args::parse(rest, &["machine", "program", "format", "set", "map", "pou"]).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    if !matches!(format, Format::Json | Format::Xml | Format::Ld) {
        return Err(one(format!(
            "{path}: hashigo compile takes a ladder (.json project, PLCopen .xml or LDmicro .ld)"
        )));
    }
    let source = SourceFile::read(path).map_err(one)?;
    let (machine, text) = if format == Format::Xml && flag == Some(MachineId::SoftPlc) {
        (MachineId::SoftPlc, source::soft_program(&args, &source)?)
    } else {
        let (project, text, _) = source::compile_source(&args, &source, format, flag)?;
        (project.machine, text)
    };
    // compile takes `--set` for the AVR PLC's scan period; a setting the
    // machine lacks is still an error.
    let problems = apply_settings(new_plc(machine).as_mut(), &args, ("", &[]));
    if !problems.is_empty() {
        return Err(problems);
    }
    print!("{text}");
    Ok(())
}

/// `--watch`'s comma-separated names, a comma inside `[…]` kept (an ST
/// array element `m[1,2]`).
fn split_devices(list: &str) -> Vec<String> {
    let (mut out, mut depth, mut name) = (Vec::new(), 0usize, String::new());
    for c in list.chars() {
        match c {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                out.push(name.trim().to_string());
                name.clear();
                continue;
            }
            _ => {}
        }
        name.push(c);
    }
    out.push(name.trim().to_string());
    out
}
