//! The subcommands. Each returns the problem lines (without `error: `) on
//! failure and prints nothing to standard output unless it succeeds.

use std::io::{BufRead, Write};
use std::time::Instant;

use engine::arduino;
use engine::avr;
use engine::events::parse_events;
use engine::headless::Simulation;
use engine::headless::{self, RunError, Schedule};
use engine::io86a;
use engine::ladder::compile::{compile as compile_ladder, Options};
use engine::ladder::{plcopen, Ladder, Project};
use engine::minasec::{self, Machine};
use engine::{MachineId, SimTime};

use crate::args::Args;
use crate::input::{Format, SourceFile};

type Problems = Vec<String>;
/// `--set`-style settings a project file holds: name, value, line.
type Settings = Vec<(String, String, usize)>;

fn one(problem: String) -> Problems {
    vec![problem]
}

/// A program parsed for its machine.
enum Loaded {
    MinasecU(Box<minasec::Program>),
    Io86a(io86a::Program),
    Arduino(arduino::Program),
    Avr(avr::Program),
}

/// A program ready for its machine, and the settings its project holds.
struct Source {
    loaded: Loaded,
    /// `--set`-style settings from a project file, applied before `--set`.
    settings: Settings,
    /// Where those settings came from, for their errors.
    name: String,
}

/// Reads `--machine`, `--program` and `--format` and parses the program for
/// that machine, compiling a ladder (`.json`, `.xml`) first; `Err` holds
/// every problem found.
fn load(args: &Args) -> Result<Source, Problems> {
    let flag = machine_flag(args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    let source = SourceFile::read(path).map_err(one)?;
    let (machine, compiled, settings) = match format {
        Format::Il | Format::Asm => {
            let machine = match flag {
                Some(m) => m,
                None => MachineId::parse(args.required("machine").map_err(one)?).map_err(one)?,
            };
            if format == Format::Asm && machine != MachineId::AvrPlc {
                return Err(one(format!(
                    "{}: {} programs are mnemonic text (.il), not .asm",
                    source.name,
                    machine.name()
                )));
            }
            (machine, None, Vec::new())
        }
        Format::Json | Format::Xml => {
            let (machine, text, settings) = compile_source(args, &source, format, flag)?;
            (machine, Some(text), settings)
        }
    };
    // A compiled ladder is parsed like a listing; its errors would be the
    // compiler's, so they name the compiled text.
    let (text, origin) = match &compiled {
        Some(t) => (t.as_str(), format!("{} (compiled)", source.name)),
        None => (source.text.as_str(), source.name.clone()),
    };
    let parsed = SourceFile {
        name: origin,
        text: text.to_string(),
    };
    let loaded = match machine {
        MachineId::MinasecU => minasec::Program::parse(text)
            .map(|p| Loaded::MinasecU(Box::new(p)))
            .map_err(|errors| parsed.located(&errors)),
        MachineId::AvrPlc => {
            let scan = avr_scan_ms(args, &source.name, &settings)?;
            avr::Program::parse(text, i64::from(scan))
                .map(Loaded::Avr)
                .map_err(|errors| parsed.located(&errors))
        }
        MachineId::ArduinoPlc => arduino::Program::parse(text, arduino::Chip::Atmega328.capacity())
            .map(Loaded::Arduino)
            .map_err(|errors| parsed.located(&errors)),
        MachineId::Io86a => io86a::Program::parse(text)
            .map(Loaded::Io86a)
            .map_err(|errors| parsed.located(&errors)),
    }?;
    Ok(Source {
        loaded,
        settings,
        name: source.name,
    })
}

/// A ladder file compiled for its machine: the machine, the program text
/// and the project's settings. Errors name the file, rung and cell.
fn compile_source(
    args: &Args,
    source: &SourceFile,
    format: Format,
    flag: Option<MachineId>,
) -> Result<(MachineId, String, Settings), Problems> {
    let (ladder, machine, settings) = read_ladder(source, format, flag)?;
    let avr_scan_ms = if machine == MachineId::AvrPlc {
        avr_scan_ms(args, &source.name, &settings)?
    } else {
        10
    };
    let options = Options { avr_scan_ms };
    let text = compile_ladder(&ladder, machine, options).map_err(|errors| {
        errors
            .iter()
            .map(|e| format!("{}: {e}", source.name))
            .collect::<Vec<_>>()
    })?;
    Ok((machine, text, settings))
}

/// `--machine`, when given.
fn machine_flag(args: &Args) -> Result<Option<MachineId>, Problems> {
    args.optional("machine")
        .map_err(one)?
        .map(MachineId::parse)
        .transpose()
        .map_err(one)
}

/// A ladder from a project (`.json`, naming its machine) or PLCopen XML
/// (which does not: `--machine` says). `--machine` wins over the project's.
fn read_ladder(
    source: &SourceFile,
    format: Format,
    flag: Option<MachineId>,
) -> Result<(Ladder, MachineId, Settings), Problems> {
    if format == Format::Json {
        let project = Project::from_json(&source.text).map_err(|e| source.located(&[e]))?;
        let machine = flag.unwrap_or(project.machine);
        let settings = project
            .settings
            .into_iter()
            .map(|(n, v)| {
                let line = Project::setting_line(&source.text, &n);
                (n, v, line)
            })
            .collect();
        return Ok((project.ladder, machine, settings));
    }
    let machine = flag.ok_or_else(|| {
        one(format!(
            "{}: a PLCopen file does not name its machine: give --machine",
            source.name
        ))
    })?;
    let ladder = plcopen::import_for(&source.text, Some(machine))
        .map_err(|errors| source.located(&errors))?;
    Ok((ladder, machine, Vec::new()))
}

/// The `Scan` symbol of AVR sources: the scan period in ms from the last
/// `--set scan=`, else the project's, else 10. A bad value is one problem,
/// worded as the settings check words it (so a run that also applies the
/// settings reports it once).
fn avr_scan_ms(
    args: &Args,
    source: &str,
    project: &[(String, String, usize)],
) -> Result<u32, Problems> {
    let from_project = project
        .iter()
        .filter(|(n, _, _)| n.trim().eq_ignore_ascii_case("scan"))
        .map(|(n, v, line)| (setting_place(source, *line, n, v), v.as_str()));
    let from_flags = args.all("set").filter_map(|s| {
        let (n, v) = s.split_once('=')?;
        n.trim()
            .eq_ignore_ascii_case("scan")
            .then(|| (format!("--set {s}"), v))
    });
    let Some((what, value)) = from_project.chain(from_flags).last() else {
        return Ok(10);
    };
    SimTime::parse(value.trim())
        .map_err(|e| e.to_string())
        .and_then(avr::scan_ms)
        .map_err(|e| one(format!("{what}: {e}")))
}

/// Where a project's setting stands, as its errors name it:
/// `FILE:LINE: setting NAME=VALUE`.
fn setting_place(file: &str, line: usize, name: &str, value: &str) -> String {
    format!(
        "{file}:{line}: setting {}={}",
        engine::shown(name).trim_matches('"'),
        engine::shown(value).trim_matches('"')
    )
}

/// `hashigo run`.
pub fn run(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(
        rest,
        &[
            "machine", "program", "format", "set", "input", "until", "every", "watch",
        ],
    )
    .map_err(one)?;
    // An unknown machine is the only thing worth saying.
    let flag = machine_flag(&args)?;
    match load(&args) {
        Ok(source) => {
            let defaults = (source.name.as_str(), source.settings.as_slice());
            match source.loaded {
                Loaded::MinasecU(p) => {
                    let mut m = Machine::for_run();
                    m.load(&p);
                    run_with(&args, m, defaults, Vec::new())
                }
                Loaded::Io86a(p) => run_with(&args, io86a::Machine::new(p), defaults, Vec::new()),
                Loaded::Arduino(p) => run_with(&args, arduino_for_run(&p), defaults, Vec::new()),
                Loaded::Avr(p) => run_with(&args, avr::Machine::new(p), defaults, Vec::new()),
            }
        }
        // Still check everything else, on a machine with an empty program.
        Err(problems) => match flag {
            Some(MachineId::MinasecU) => run_with(&args, Machine::for_run(), ("", &[]), problems),
            Some(MachineId::ArduinoPlc) => run_with(
                &args,
                arduino_for_run(&arduino::Program::default()),
                ("", &[]),
                problems,
            ),
            Some(MachineId::Io86a) => run_with(
                &args,
                io86a::Machine::new(io86a::Program::default()),
                ("", &[]),
                problems,
            ),
            Some(MachineId::AvrPlc) => run_with(
                &args,
                avr::Machine::new(avr::Program::default()),
                ("", &[]),
                problems,
            ),
            None => Err(problems),
        },
    }
}

/// An Arduino as `hashigo run` starts it: enabled from t = 0 (the sketch
/// itself waits for `e`).
fn arduino_for_run(program: &arduino::Program) -> arduino::Machine {
    let mut m = arduino::Machine::new(program, arduino::Chip::Atmega328);
    m.set_enabled(true);
    m
}

/// Checks the rest of `hashigo run`'s options against `sim` and runs it;
/// `problems` already found are reported with any new ones.
fn run_with<S: Simulation>(
    args: &Args,
    mut sim: S,
    (file, defaults): (&str, &[(String, String, usize)]),
    mut problems: Problems,
) -> Result<(), Problems> {
    let until = args
        .required("until")
        .and_then(|t| SimTime::parse(t).map_err(|e| format!("--until: {e}")));
    let every = args.optional("every").and_then(|t| {
        t.map(|t| SimTime::parse(t).map_err(|e| format!("--every: {e}")))
            .transpose()
    });
    let watch: Vec<String> = args
        .all("watch")
        .flat_map(|w| w.split(','))
        .map(|w| w.trim().to_string())
        .collect();
    if watch.is_empty() || watch.iter().any(String::is_empty) {
        problems.push("--watch needs device names, e.g. --watch Y00,Y01,C0.v".to_string());
    }
    for (name, value, line) in defaults {
        if let Err(e) = sim.setting(name, value) {
            problems.push(format!("{}: {e}", setting_place(file, *line, name, value)));
        }
    }
    for setting in args.all("set") {
        let result = match setting.split_once('=') {
            Some((name, value)) => sim.setting(name.trim(), value.trim()),
            None => Err("expected NAME=VALUE".to_string()),
        };
        if let Err(e) = result {
            problems.push(format!("--set {setting}: {e}"));
        }
    }
    let events = match args.optional("input") {
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
    };
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
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    headless::run(&mut sim, event_list, schedule, &watch, &mut out).map_err(|errors| {
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

/// `hashigo bench`.
pub fn bench(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "steps"]).map_err(one)?;
    let loaded = load(&args)?.loaded;
    let steps_text = args.required("steps").map_err(one)?;
    let steps: u64 = steps_text.parse().ok().filter(|&n| n > 0).ok_or_else(|| {
        one(format!(
            "--steps {steps_text}: expected a whole number above 0"
        ))
    })?;

    let program = match loaded {
        Loaded::MinasecU(program) => *program,
        Loaded::Io86a(program) => return bench_io86a(program, steps),
        Loaded::Arduino(program) => return bench_arduino(&program, steps),
        Loaded::Avr(program) => return bench_avr(program, steps),
    };
    let mut machine = Machine::for_run();
    machine.load(&program);
    let period = machine.speed().period().as_nanos();
    // Exactly `steps` clocks: the n-th clock's falling edge is n periods on.
    let end = steps
        .checked_mul(period)
        .map(SimTime::from_nanos)
        .ok_or_else(|| one(format!("--steps {steps}: too many for the simulated clock")))?;
    let started = Instant::now();
    machine.run_until(end);
    let seconds = started.elapsed().as_secs_f64();
    debug_assert_eq!(machine.clocks(), steps);
    print_bench(steps, seconds);
    Ok(())
}

fn print_bench(steps: u64, seconds: f64) {
    let rate = if seconds > 0.0 {
        steps as f64 / seconds
    } else {
        f64::INFINITY
    };
    println!("steps={steps} seconds={seconds:.6} steps_per_second={rate:.0}");
}

/// Arduino: `steps` words executed back to back.
fn bench_arduino(program: &arduino::Program, steps: u64) -> Result<(), Problems> {
    let mut machine = arduino_for_run(program);
    let end = steps
        .checked_mul(arduino::machine::DEFAULT_STEP.as_nanos())
        .map(SimTime::from_nanos)
        .ok_or_else(|| one(format!("--steps {steps}: too many for the simulated clock")))?;
    let started = Instant::now();
    machine.run_until(end);
    let seconds = started.elapsed().as_secs_f64();
    print_bench(machine.steps(), seconds);
    Ok(())
}

/// AVR: whole scans of records, back to back.
fn bench_avr(program: avr::Program, steps: u64) -> Result<(), Problems> {
    let per_scan = program.instructions().len() as u64;
    let mut machine = avr::Machine::new(program);
    let period = machine.scan_period();
    bench_scans(steps, per_scan, period, |t| machine.run_until(t))
}

/// IO86A: whole scans of instructions (END included), back to back.
fn bench_io86a(program: io86a::Program, steps: u64) -> Result<(), Problems> {
    let mut machine = io86a::Machine::new(program);
    let per_scan = machine.steps_per_scan() as u64;
    let period = machine.scan_period();
    bench_scans(steps, per_scan, period, |t| machine.run_until(t))
}

/// Runs whole scans (the devices cannot stop mid-scan) until at least
/// `steps` steps ran, and prints the steps actually executed.
fn bench_scans(
    steps: u64,
    per_scan: u64,
    period: SimTime,
    mut run_until: impl FnMut(SimTime),
) -> Result<(), Problems> {
    if per_scan == 0 {
        return Err(one("--program: the program has nothing to run".to_string()));
    }
    let scans = steps.div_ceil(per_scan);
    let end = scans
        .checked_mul(period.as_nanos())
        .map(SimTime::from_nanos)
        .ok_or_else(|| one(format!("--steps {steps}: too many for the simulated clock")))?;
    let started = Instant::now();
    run_until(end);
    let seconds = started.elapsed().as_secs_f64();
    print_bench(scans * per_scan, seconds);
    Ok(())
}

/// `hashigo asm`.
pub fn asm(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format"]).map_err(one)?;
    match load(&args)?.loaded {
        Loaded::MinasecU(program) => print!("{}", program.sheet()),
        Loaded::Io86a(program) => print!("{}", program.listing()),
        Loaded::Arduino(program) => {
            let machine = arduino::Machine::new(&program, arduino::Chip::Atmega328);
            print!("{}", arduino::monitor::hex_dump(machine.eeprom()));
        }
        Loaded::Avr(program) => print!("{}", program.listing()),
    }
    Ok(())
}

/// `hashigo console`: the device's serial terminal on standard input and
/// output. After each line the simulated clock advances by `--step`.
pub fn console(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "step"]).map_err(one)?;
    let id = MachineId::parse(args.required("machine").map_err(one)?).map_err(one)?;
    match id {
        MachineId::Io86a => {}
        MachineId::MinasecU | MachineId::AvrPlc => {
            return Err(one(format!(
                "{} has no serial terminal: console is for io86a and arduino-plc",
                id.name()
            )))
        }
        MachineId::ArduinoPlc => return arduino_console(&args),
    }
    let step = match args.optional("step").map_err(one)? {
        Some(t) => SimTime::parse(t).map_err(|e| one(format!("--step: {e}")))?,
        None => SimTime::from_millis(10),
    };
    let program = match args.optional("program").map_err(one)? {
        Some(_) => match load(&args)?.loaded {
            Loaded::Io86a(program) => program,
            _ => return Err(one("--machine io86a needs an io86a program".to_string())),
        },
        None => io86a::Program::default(),
    };
    let mut machine = io86a::Machine::new(program);
    let mut terminal = io86a::Terminal::new(&machine);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let _ = write!(out, "{}", terminal.prompt(&machine));
    for line in std::io::stdin().lock().lines() {
        let line = line.map_err(|e| one(format!("<stdin>: cannot read: {e}")))?;
        for typed in typed_lines(&line) {
            let _ = write!(out, "{}", terminal.type_line(&mut machine, typed));
            let _ = out.flush();
            machine.run_until(advance(machine.now(), step)?);
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
            engine::limits::MAX_SIM_TIME.as_nanos() / 1_000_000_000
        ))
    })
}

/// The lines typed in one line of standard input: LF and CR LF end a line
/// (cli.md), and a bare CR, which serial terminals send, does too.
fn typed_lines(line: &str) -> impl Iterator<Item = &str> {
    line.strip_suffix('\r').unwrap_or(line).split('\r')
}

/// The Arduino sketch's serial monitor: no echo, no prompt; the PLC waits
/// for `e` as after power-up.
fn arduino_console(args: &Args) -> Result<(), Problems> {
    let step = match args.optional("step").map_err(one)? {
        Some(t) => SimTime::parse(t).map_err(|e| one(format!("--step: {e}")))?,
        None => SimTime::from_millis(10),
    };
    let program = match args.optional("program").map_err(one)? {
        Some(_) => match load(args)?.loaded {
            Loaded::Arduino(program) => program,
            _ => {
                return Err(one(
                    "--machine arduino-plc needs an arduino-plc program".to_string()
                ))
            }
        },
        None => arduino::Program::default(),
    };
    let mut machine = arduino::Machine::new(&program, arduino::Chip::Atmega328);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    for line in std::io::stdin().lock().lines() {
        let line = line.map_err(|e| one(format!("<stdin>: cannot read: {e}")))?;
        for typed in typed_lines(&line) {
            let _ = write!(out, "{}", arduino::monitor::type_line(&mut machine, typed));
            let _ = out.flush();
            machine.run_until(advance(machine.now(), step)?);
        }
    }
    Ok(())
}

/// `hashigo compile`: a ladder (`.json` project or PLCopen `.xml`) to
/// the machine's program text, which `hashigo run` takes back.
pub fn compile(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "set"]).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    if !matches!(format, Format::Json | Format::Xml) {
        return Err(one(format!(
            "{path}: hashigo compile takes a ladder (.json project or PLCopen .xml)"
        )));
    }
    let source = SourceFile::read(path).map_err(one)?;
    let (machine, text, _) = compile_source(&args, &source, format, flag)?;
    check_settings(&args, machine)?;
    print!("{text}");
    Ok(())
}

/// Checks every `--set` against `machine` (compile takes them for the
/// AVR PLC's scan period; a setting the machine lacks is still an error).
fn check_settings(args: &Args, machine: MachineId) -> Result<(), Problems> {
    let mut problems = Vec::new();
    let mut check = |sim: &mut dyn FnMut(&str, &str) -> Result<(), String>| {
        for setting in args.all("set") {
            let result = match setting.split_once('=') {
                Some((name, value)) => sim(name.trim(), value.trim()),
                None => Err("expected NAME=VALUE".to_string()),
            };
            if let Err(e) = result {
                problems.push(format!("--set {setting}: {e}"));
            }
        }
    };
    match machine {
        MachineId::MinasecU => {
            let mut m = Machine::for_run();
            check(&mut |n, v| m.apply_setting(n, v));
        }
        MachineId::Io86a => {
            let mut m = io86a::Machine::new(io86a::Program::default());
            check(&mut |n, v| m.apply_setting(n, v));
        }
        MachineId::AvrPlc => {
            let mut m = avr::Machine::new(avr::Program::default());
            check(&mut |n, v| m.apply_setting(n, v));
        }
        MachineId::ArduinoPlc => {
            let mut m = arduino_for_run(&arduino::Program::default());
            check(&mut |n, v| m.apply_setting(n, v));
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems)
    }
}
