//! `hashigo why` (cli.md): runs to `--at` and explains a device's state
//! at the end of that scan with the page's own explanation
//! (`engine::ladder::why`): the elements that block or carry its power,
//! each device's state, the rungs that drive it and when it last changed.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write;

use engine::clock::PeriodicClock;
use engine::ladder::compile::Options;
use engine::ladder::live::LiveLadder;
use engine::ladder::target::check_element;
use engine::ladder::why::{box_output, causes, deciding_output, Explanation};
use engine::ladder::Ladder;
use engine::machines::new_plc;
use engine::plc::{Command, Device, Plc, PlcError, Value};
use engine::record::run_whole_scans;
use engine::{MachineId, SimTime};

use crate::args::Args;
use crate::commands::read_events;
use crate::input::Format;
use crate::plant::PlantOptions;
use crate::source::{self, apply_settings, ladder_project, load, located, one, Problems};

/// A watched device: its handle, its value, and when it last changed
/// (time, scan), if it did.
type Watched = (Device, Value, Option<(SimTime, u64)>);
/// Every watched device by name.
type Changes = BTreeMap<String, Watched>;

/// `hashigo why`.
pub fn why(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(
        rest,
        &[
            "machine", "program", "format", "set", "input", "at", "device", "map", "pou", "plant",
            "wiring", "fault",
        ],
    )
    .map_err(one)?;
    let explained = Explained::load(&args)?;
    let mut plc = explained.plc;
    let (ladder, live) = (&explained.ladder, &explained.live);
    let mut problems = Vec::new();
    let held = explained
        .plant
        .as_ref()
        .map(|p| (explained.name.as_str(), p));
    let plant = PlantOptions::read(&args, held, &mut problems);
    let machine_args = PlantOptions::machine_args_of(plant.as_ref(), &args);
    let defaults = (explained.name.as_str(), explained.settings.as_slice());
    problems.extend(apply_settings(plc.as_mut(), &machine_args, defaults));
    let mut wired = String::new();
    if let Some(plant) = &plant {
        let mut planted = plant.attach(plc)?;
        problems.extend(plant.set_params(&mut planted, &args));
        wired = crate::plant::wired_lines(&planted);
        plc = Box::new(planted);
    }
    let names = Names::new(ladder, explained.written.as_ref(), plc.as_ref());
    let events = read_events(&args, &mut problems);
    let at = args
        .required("at")
        .and_then(|t| SimTime::parse(t).map_err(|e| format!("--at: {e}")))
        .map_err(|p| problems.push(p))
        .ok();
    let asked = args.required("device").map_err(|p| problems.push(p)).ok();
    let device = asked.map(|n| {
        names
            .resolve(plc.as_ref(), n)
            .map_err(|e| problems.push(format!("--device: {e}")))
    });
    let mut inputs = Vec::new();
    if let Some((file, list)) = &events {
        for e in list {
            let checked = names
                .resolve(plc.as_ref(), &e.device)
                .and_then(|(_, d)| plc.check_input(d, e.value).map(|()| d));
            match checked {
                Ok(d) => inputs.push((e.time, d, e.value)),
                Err(err) => problems.push(format!("{}:{}: {err}", file.name, e.line)),
            }
        }
    }
    let (Some(at), Some(Ok((name, device)))) = (at, device) else {
        return Err(problems);
    };
    if !problems.is_empty() {
        return Err(problems);
    }
    let changes = run_to(plc.as_mut(), ladder, (&name, device), &inputs, at);
    let il = explained
        .il
        .as_deref()
        .map(|text| (explained.name.as_str(), text));
    let out = report(ladder, live, plc.as_ref(), (&name, il), &changes);
    print!("{out}{wired}");
    Ok(())
}

/// The ladder `why` explains, compiled and loaded, and the program as
/// written (which still names its devices: an AVR source's `.equ` names).
struct Explained {
    ladder: Ladder,
    live: LiveLadder,
    plc: Box<dyn Plc>,
    written: Box<dyn Plc>,
    name: String,
    settings: source::Settings,
    /// The soft PLC's Instruction List as written, when that is the
    /// program: a variable its ladder does not show is found at its line.
    il: Option<String>,
    /// The plant the project holds, if any.
    plant: Option<engine::formats::project::PlantSetup>,
}

impl Explained {
    fn load(args: &Args) -> Result<Explained, Problems> {
        let mut source = load(args)?;
        let machine = source.plc.id();
        let scan_ms = if machine == MachineId::AvrPlc {
            source::avr_scan_ms(args, &source.name, &source.settings)?
        } else {
            10
        };
        let plant = source.project.as_ref().and_then(|p| p.plant.clone());
        let project = match source.project.take() {
            Some(project) => project,
            None => ladder_project(args, &source.file, source.format, Some(machine), scan_ms)?,
        };
        // Device names in the machine's own spelling, so that `Y0`, `y00`
        // and `Y00` are one device wherever they are compared.
        let ladder = canonical(project.ladder, machine);
        // The ladder's own compiled program runs, so that its source map
        // names each contact's step (a text program is its decompiled
        // ladder).
        let options = Options {
            avr_scan_ms: scan_ms,
        };
        let live = LiveLadder::new(&ladder, machine, options).map_err(|errors| {
            errors
                .iter()
                .map(|e| format!("{}: {e}", source.name))
                .collect::<Vec<_>>()
        })?;
        let origin = match source.format {
            Format::Il | Format::Asm | Format::St => format!("{} (as its ladder)", source.name),
            Format::Json | Format::Xml | Format::Ld => format!("{} (compiled)", source.name),
        };
        let mut plc = new_plc(machine);
        plc.load_text(&live.listing.text)
            .map_err(|e| located(&origin, e))?;
        let il = (source.format == Format::Il && machine == MachineId::SoftPlc)
            .then(|| source.file.text.clone());
        Ok(Explained {
            plant,
            il,
            ladder,
            live,
            plc,
            written: source.plc,
            name: source.name,
            settings: source.settings,
        })
    }
}

/// Runs `plc` with its `inputs` to `at`, tracing, and says when each
/// device a contact reads (and the `asked` one) last changed. Devices are
/// looked at only where a scan ends: the state explained is the one at the
/// end of the scan the trace is of, and "last changed" comes from the same
/// samples (the Arduino sketch's pins change mid-pass).
fn run_to(
    plc: &mut (dyn Plc + 'static),
    ladder: &Ladder,
    asked: (&str, Device),
    inputs: &[(SimTime, Device, engine::events::InputValue)],
    at: SimTime,
) -> Changes {
    let mut changes: Changes = BTreeMap::new();
    for rung in &ladder.rungs {
        for (_, e) in rung.elements() {
            if let Some(device) = e.read_device() {
                if let Ok(d) = plc.device(device) {
                    changes.insert(device.to_string(), (d, plc.read(d), None));
                }
            }
        }
    }
    changes.insert(asked.0.to_string(), (asked.1, plc.read(asked.1), None));
    let mut observe = |m: &(dyn Plc + 'static)| {
        for (d, last, changed) in changes.values_mut() {
            let now = m.read(*d);
            if now != *last {
                *last = now;
                *changed = Some((m.now(), m.scans()));
            }
        }
        true
    };
    plc.set_tracing(true);
    for &(t, d, value) in inputs.iter().filter(|(t, _, _)| *t <= at) {
        // Everything due strictly before the event runs first.
        run_whole_scans(plc, PeriodicClock::just_before(t), &mut observe);
        plc.run_before(t);
        // Checked above: the machine takes it.
        let _ = plc.apply(Command::SetInput(d, value));
    }
    run_whole_scans(plc, at, &mut observe);
    plc.run_until(at);
    changes
}

/// A ladder with each element's devices in the machine's own spelling
/// (elements the machine refuses are left as written: `LiveLadder::new`
/// reports them).
fn canonical(mut ladder: Ladder, machine: MachineId) -> Ladder {
    for rung in &mut ladder.rungs {
        for cell in rung.cells.iter_mut().flatten().flatten() {
            if let Ok(e) = check_element(machine, cell) {
                *cell = e;
            }
        }
    }
    ladder
}

/// Device names as the user gives them, resolved once: trimmed, looked up
/// in the program as written (which knows an AVR source's `.equ` names)
/// and given the ladder's own spelling of the same device.
struct Names<'a> {
    written: &'a dyn Plc,
    /// The ladder's spelling of each device it names.
    spelled: HashMap<Device, String>,
}

impl<'a> Names<'a> {
    fn new(ladder: &Ladder, written: &'a dyn Plc, running: &dyn Plc) -> Names<'a> {
        let mut spelled = HashMap::new();
        for rung in &ladder.rungs {
            for (_, e) in rung.elements() {
                // A box's operands too: `%QW0` is the `level` a DIV writes.
                let operands = e.block().into_iter().flat_map(|b| {
                    b.inputs
                        .iter()
                        .chain(&b.outputs)
                        .map(|(_, o)| o.as_str())
                        .filter(|o| engine::ladder::block::is_variable(o))
                });
                let names = e.read_device().or(e.written_device()).into_iter();
                for name in names.chain(operands) {
                    if let Ok(d) = running.device(name) {
                        spelled.entry(d).or_insert_with(|| name.to_string());
                    }
                }
            }
        }
        Names { written, spelled }
    }

    /// The ladder's name for `name` and its handle on the `running`
    /// machine.
    fn resolve(&self, running: &dyn Plc, name: &str) -> Result<(String, Device), PlcError> {
        let name = name.trim();
        let device = match running.device(name) {
            Ok(d) => d,
            Err(e) => self.written.device(name).map_err(|_| e)?,
        };
        let spelled = self.spelled.get(&device).cloned();
        Ok((spelled.unwrap_or_else(|| name.to_string()), device))
    }
}

/// The explanation as text.
/// `il`: the IL program as written (its file's name, its text), when it
/// is one.
fn report(
    ladder: &Ladder,
    live: &LiveLadder,
    plc: &dyn Plc,
    (name, il): (&str, Option<(&str, &str)>),
    changes: &Changes,
) -> String {
    let mut out = String::new();
    let value = changes
        .get(name)
        .map_or(Value::Int(0), |(_, v, _)| v.clone());
    let scans = plc.scans();
    let _ = writeln!(
        out,
        "{name} = {value} at {} ms, end of scan {scans}{}",
        plc.now(),
        since(changes.get(name))
    );
    let Some((rung, pos)) = deciding_output(ladder, name) else {
        if let Some((rung, pos, pin)) = box_output(ladder, name) {
            box_report(
                &mut out,
                (ladder, live, plc),
                name,
                (rung, pos, &pin),
                changes,
            );
            return out;
        }
        // The ladder drew the variable away (a box's output carried on as
        // its power): the program's own line still writes it.
        if let Some((file, (line, code))) = il.and_then(|(f, t)| Some((f, il_writer(t, name)?))) {
            let _ = writeln!(out, "Line {line} of {file} writes {name}: {code}");
            return out;
        }
        let _ = writeln!(
            out,
            "No output of the ladder writes {name}: it is an input or driven from outside."
        );
        return out;
    };
    let why = plc.trace().and_then(|t| live.explain(t, rung, pos));
    let Some(why) = why else {
        let _ = writeln!(out, "Rung {} did not run in that scan.", rung + 1);
        return out;
    };
    let element = ladder.rungs[rung]
        .get(pos)
        .map_or_else(String::new, ToString::to_string);
    let _ = writeln!(
        out,
        "Rung {}, row {}, column {}: {element} {}.",
        rung + 1,
        pos.row + 1,
        pos.col + 1,
        if why.powered {
            "gets power"
        } else {
            "gets no power"
        }
    );
    let _ = writeln!(out, "{}", lead(&why));
    for cause in causes(ladder, rung, &why) {
        cause_line(&mut out, ladder, rung, &cause, plc, changes);
    }
    out
}

/// The box at `pos` of rung `rung` that writes `name` through its output
/// `pin` (`CV => parts`, or `c0.CV` itself): where it is, whether its
/// power input was on in the scan, what it reads and, when off, what
/// would give it power.
fn box_report(
    out: &mut String,
    (ladder, live, plc): (&Ladder, &LiveLadder, &dyn Plc),
    name: &str,
    (rung, pos, pin): (usize, engine::ladder::Pos, &str),
    changes: &Changes,
) {
    let Some(b) = ladder.rungs[rung]
        .get(pos)
        .and_then(engine::ladder::Element::block)
    else {
        return;
    };
    let what = format!("{} {}", b.kind(), b.instance.trim());
    let powered = plc.trace().and_then(|t| {
        let (_, power) = live.power(t).into_iter().find(|(i, _)| *i == rung)?;
        power.iter().find(|p| p.pos == pos).map(|p| p.power_in)
    });
    let state = match powered {
        Some(true) => "on",
        Some(false) => "off",
        None => "not run",
    };
    let _ = writeln!(
        out,
        "Rung {}, row {}, column {}: box {} writes {name} through its {pin} output; its power ({}) is {state} in this scan.",
        rung + 1,
        pos.row + 1,
        pos.col + 1,
        what.trim(),
        b.power_in()
    );
    let reads: Vec<String> = b
        .inputs
        .iter()
        .map(|(p, operand)| match plc.device(operand) {
            Ok(d) => format!("{p} {operand} = {}", plc.read(d)),
            Err(_) => format!("{p} {operand}"),
        })
        .collect();
    if !reads.is_empty() {
        let _ = writeln!(out, "It reads {}.", reads.join("; "));
    }
    if powered != Some(false) {
        return;
    }
    let why = plc.trace().and_then(|t| live.explain(t, rung, pos));
    if let Some(why) = why.filter(|w| !w.causes.is_empty()) {
        let lead = if why.together {
            "Its power would come on only if all of these changed:"
        } else {
            "Its power would come on if any one of these changed:"
        };
        let _ = writeln!(out, "{lead}");
        for cause in causes(ladder, rung, &why) {
            cause_line(out, ladder, rung, &cause, plc, changes);
        }
    }
}

/// One cause: its cell and element, a box's operands' values, a
/// contact's device with its state, when it changed and what drives it.
fn cause_line(
    out: &mut String,
    ladder: &Ladder,
    rung: usize,
    cause: &engine::ladder::why::Cause,
    plc: &dyn Plc,
    changes: &Changes,
) {
    let _ = write!(
        out,
        "  rung {}, row {}, column {}: {}",
        rung + 1,
        cause.pos.row + 1,
        cause.pos.col + 1,
        cause.element
    );
    // A box: its operands' values, which decide it.
    if let Some(b) = ladder.rungs[rung]
        .get(cause.pos)
        .and_then(engine::ladder::Element::block)
    {
        for (pin, operand) in &b.inputs {
            if let Ok(d) = plc.device(operand) {
                let _ = write!(out, "; {pin} {operand} = {}", plc.read(d));
            }
        }
    }
    if let Some(d) = &cause.device {
        let state = changes
            .get(d)
            .map_or_else(|| "?".to_string(), |(_, v, _)| v.to_string());
        let _ = write!(out, "; {d} = {state}{}", since(changes.get(d)));
        let drivers = if cause.drivers.is_empty() {
            "an input or driven from outside".to_string()
        } else {
            let list: Vec<String> = cause.drivers.iter().map(|r| (r + 1).to_string()).collect();
            format!("driven by rung {}", list.join(", "))
        };
        let _ = write!(out, "; {drivers}");
    }
    let _ = writeln!(out);
}

/// The line before the causes.
fn lead(why: &Explanation) -> &'static str {
    match (why.powered, why.together) {
        (false, false) => "It would get power if any one of these changed:",
        (false, true) => "It would get power only if all of these changed:",
        (true, false) => "It would lose power if any one of these changed:",
        (true, true) => "It would lose power only if all of these changed:",
    }
}

/// `, since 1200 ms (scan 120)` or `, unchanged since power-on`.
fn since(change: Option<&Watched>) -> String {
    match change.and_then(|(_, _, c)| *c) {
        Some((t, scan)) => format!(", since {t} ms (scan {scan})"),
        None => ", unchanged since power-on".to_string(),
    }
}

/// The last line of an IL text that writes `name`: a `CAL` giving it an
/// output (`Q => name`), or `ST`, `STN`, `S`, `R` of it (its line, the
/// instruction as written).
fn il_writer(il: &str, name: &str) -> Option<(usize, String)> {
    let wanted = |word: &str| {
        word.trim_end_matches([',', ')', ';'])
            .eq_ignore_ascii_case(name)
    };
    let mut found = None;
    for (i, line) in il.lines().enumerate() {
        let code = line.split("(*").next().unwrap_or_default().trim();
        // A label (`_skip0: LD x`) is not the instruction.
        let code = match code.split_once(':') {
            Some((label, rest)) if !label.contains(' ') && !rest.starts_with('=') => rest.trim(),
            _ => code,
        };
        let words: Vec<&str> = code.split_whitespace().collect();
        let stores = matches!(
            words.first().map(|w| w.to_ascii_uppercase()).as_deref(),
            Some("ST" | "STN" | "S" | "R")
        ) && words.get(1).is_some_and(|w| wanted(w));
        let output = words.windows(2).any(|w| w[0] == "=>" && wanted(w[1]))
            || words.iter().any(|w| {
                w.strip_prefix("=>")
                    .is_some_and(|w| !w.is_empty() && wanted(w))
            });
        if stores || output {
            found = Some((i + 1, code.to_string()));
        }
    }
    found
}
