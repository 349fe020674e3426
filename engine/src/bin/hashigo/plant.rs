//! The plant options of `run`, `test` and `why` (cli.md, "Plants"):
//! `--plant`, `--wiring`, `--fault`, `--set NAME.KEY=VALUE`; and
//! `hashigo plants`.

use engine::formats::project::PlantSetup;
use engine::machines::new_plc;
use engine::plant::wiring::{self, WireEntry};
use engine::plant::{any::ALL, AnyPlant, Fault, Plant, PlantInfo, Planted, ALARMS};
use engine::plc::{Command, Plc};
use engine::MachineId;

use crate::args::Args;
use crate::input::SourceFile;
use crate::source::{one, Problems};

/// A project file's plant, with the file's name, when it holds one.
pub type Held<'a> = Option<(&'a str, &'a PlantSetup)>;

/// Where a wiring came from, for its errors.
#[derive(Clone)]
enum From {
    /// A `--wiring` file: `FILE:LINE:`.
    File(String),
    /// A project's plant: `FILE: plant wiring entry N:`.
    Project(String),
}

/// A plant as the options (or the project file) ask for it, checked
/// against the plant.
#[derive(Clone)]
pub struct PlantOptions {
    plant: AnyPlant,
    wiring: Option<(From, Vec<WireEntry>)>,
    faults: Vec<Fault>,
    /// The project's parameters: `NAME.KEY`, value, where from.
    params: Vec<(String, String, String)>,
}

impl PlantOptions {
    /// `--plant`, `--wiring` and `--fault`, over the plant the project
    /// holds (`held`): `--plant` replaces it, `--wiring` replaces its
    /// wiring, `--fault` adds to its faults. `None` without either (then
    /// `--wiring` and `--fault` are problems). Problems go to `problems`.
    pub fn read(args: &Args, held: Held, problems: &mut Problems) -> Option<PlantOptions> {
        let name = match args.optional("plant") {
            Ok(n) => n,
            Err(e) => {
                problems.push(e);
                return None;
            }
        };
        let (name, held, origin) = match (name, held) {
            (Some(name), _) => (name, None, "--plant".to_string()),
            (None, Some((file, setup))) => (
                setup.name.as_str(),
                Some((file, setup)),
                format!("{file}: plant"),
            ),
            (None, None) => {
                for flag in ["wiring", "fault"] {
                    if args.all(flag).next().is_some() {
                        problems.push(format!("--{flag} needs --plant NAME"));
                    }
                }
                return None;
            }
        };
        let Some(plant) = AnyPlant::new(name.trim()) else {
            problems.push(format!(
                "{origin}: no plant {} (plants: {})",
                engine::shown(name),
                AnyPlant::names()
            ));
            return None;
        };
        let mut options = PlantOptions {
            plant,
            wiring: None,
            faults: Vec::new(),
            params: Vec::new(),
        };
        if let Some((file, setup)) = held {
            options.hold(file, setup, problems);
        }
        for text in args.all("fault") {
            match Fault::parse(text, options.plant.info()) {
                Ok(f) => options.faults.push(f),
                Err(e) => problems.push(format!("--fault {}: {e}", engine::shown(text))),
            }
        }
        let stdin_taken = ["program", "input"]
            .iter()
            .any(|f| args.optional(f) == Ok(Some("-")));
        match args.optional("wiring") {
            Ok(Some("-")) if stdin_taken => problems.push(
                "--wiring - and another option both read standard input: give the wiring as a file"
                    .to_string(),
            ),
            Ok(Some(path)) => options.wiring = read_wiring(path, problems),
            Ok(None) => {}
            Err(e) => problems.push(e),
        }
        Some(options)
    }

    /// Takes the project's faults, parameters and wiring.
    fn hold(&mut self, file: &str, setup: &PlantSetup, problems: &mut Problems) {
        let name = self.name();
        for text in &setup.faults {
            match Fault::parse(text, self.plant.info()) {
                Ok(f) => self.faults.push(f),
                Err(e) => {
                    problems.push(format!("{file}: plant fault {}: {e}", engine::shown(text)))
                }
            }
        }
        for (key, value) in &setup.params {
            let place = format!("{file}: plant parameter {}", engine::shown(key));
            self.params
                .push((format!("{name}.{key}"), value.clone(), place));
        }
        if let Some(pairs) = &setup.wiring {
            let entries = pairs
                .iter()
                .enumerate()
                .map(|(i, [signal, device])| WireEntry {
                    signal: signal.clone(),
                    device: device.clone(),
                    line: i + 1,
                })
                .collect();
            self.wiring = Some((From::Project(file.to_string()), entries));
        }
    }

    /// [`PlantOptions::read`] when nothing else is checked: its problems
    /// as the error.
    pub fn read_alone(args: &Args, held: Held) -> Result<Option<PlantOptions>, Problems> {
        let mut problems = Vec::new();
        let plant = PlantOptions::read(args, held, &mut problems);
        if problems.is_empty() {
            Ok(plant)
        } else {
            Err(problems)
        }
    }

    /// The flags with `plant`'s parameters taken out of `--set` (all
    /// of `--set` without a plant).
    pub fn machine_args_of(plant: Option<&PlantOptions>, args: &Args) -> Args {
        match plant {
            Some(p) => p.machine_args(args),
            None => args.without("set", |_| false),
        }
    }

    /// The plant's name.
    pub fn name(&self) -> &'static str {
        self.plant.info().name
    }

    /// Attaches the plant to `plc`; the wiring's problems at its lines.
    pub fn attach<M: Plc>(&self, plc: M) -> Result<Planted<M>, Problems> {
        let machine = plc.id();
        let entries = self.wiring.as_ref().map(|(_, e)| e.as_slice());
        Planted::new(plc, self.plant.clone(), entries, self.faults.clone()).map_err(|errors| {
            errors
                .iter()
                .map(|e| match &self.wiring {
                    Some((From::File(file), _)) => format!("{file}:{}: {}", e.line, e.error),
                    Some((From::Project(file), _)) => {
                        format!("{file}: plant wiring entry {}: {}", e.line, e.error)
                    }
                    None => format!(
                        "--plant {} (its default wiring on {}): {}",
                        self.name(),
                        machine.name(),
                        e.error
                    ),
                })
                .collect()
        })
    }

    /// Whether `setting` (`NAME.KEY=VALUE`) is this plant's parameter.
    pub fn is_param(&self, setting: &str) -> bool {
        is_param_of(self.name(), setting)
    }

    /// `--set` without this plant's parameters: the machine's settings.
    pub fn machine_args(&self, args: &Args) -> Args {
        args.without("set", |s| self.is_param(s))
    }

    /// Sets this plant's `--set` parameters on `plc`.
    pub fn set_params(&self, plc: &mut dyn Plc, args: &Args) -> Problems {
        let mut problems = Vec::new();
        for (name, value, place) in &self.params {
            let command = Command::Setting {
                name: name.clone(),
                value: value.clone(),
            };
            if let Err(e) = plc.apply(command) {
                problems.push(format!("{place}: {e}"));
            }
        }
        for setting in args.all("set").filter(|s| self.is_param(s)) {
            let Some((name, value)) = setting.split_once('=') else {
                continue;
            };
            let command = Command::Setting {
                name: name.trim().to_string(),
                value: value.trim().to_string(),
            };
            if let Err(e) = plc.apply(command) {
                problems.push(format!("--set {setting}: {e}"));
            }
        }
        problems
    }
}

/// Whether `setting` names a parameter of the plant `plant`.
fn is_param_of(plant: &str, setting: &str) -> bool {
    let name = setting.split('=').next().unwrap_or("").trim();
    name.strip_prefix(plant).is_some_and(|k| k.starts_with('.'))
}

fn read_wiring(path: &str, problems: &mut Problems) -> Option<(From, Vec<WireEntry>)> {
    let source = match SourceFile::read(path) {
        Ok(s) => s,
        Err(e) => {
            problems.push(e);
            return None;
        }
    };
    match wiring::parse(&source.text) {
        Ok(entries) => Some((From::File(source.name), entries)),
        Err(errors) => {
            problems.extend(
                errors
                    .iter()
                    .map(|e| format!("{}:{}: {}", source.name, e.line, e.error)),
            );
            None
        }
    }
}

/// The alarms a run raised, as `run` prints them on standard error.
pub fn alarm_lines<M: Plc>(planted: &Planted<M>) -> Vec<String> {
    let name = planted.plant().info().name;
    planted
        .alarm_log()
        .iter()
        .map(|a| {
            let ms = a.at.as_nanos() / 1_000_000;
            format!("alarm: {ms}: {name}: {}", a.message)
        })
        .collect()
}

/// What Why? adds with a plant: the plant signal behind each wired
/// device (`plant: X00 is conveyor.infeed (in)`), one a line.
pub fn wired_lines<M: Plc>(planted: &Planted<M>) -> String {
    let info = planted.plant().info();
    let mut out = String::new();
    for w in planted.wires() {
        let s = &info.signals[w.signal];
        let (verb, dir) = match s.direction {
            engine::plant::Direction::In => ("is", "the PLC reads it"),
            engine::plant::Direction::Out => ("drives", "the PLC drives it"),
        };
        out.push_str(&format!(
            "plant: {} {verb} {}.{} ({dir})\n",
            w.name, info.name, s.name
        ));
    }
    out
}

/// `hashigo plants [--machine ID]`.
pub fn plants(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine"]).map_err(one)?;
    let machine = match args.optional("machine").map_err(one)? {
        Some(m) => Some(MachineId::parse(m).map_err(|e| one(e.to_string()))?),
        None => None,
    };
    let mut out = String::new();
    for info in ALL {
        describe(info, &mut out);
        if let Some(id) = machine {
            default_wiring(info, id, &mut out);
        }
    }
    print!("{out}");
    Ok(())
}

fn describe(info: &PlantInfo, out: &mut String) {
    use std::fmt::Write;
    let _ = writeln!(out, "plant {}: {}", info.name, info.description);
    for s in info.signals {
        let dir = match s.direction {
            engine::plant::Direction::In => "in",
            engine::plant::Direction::Out => "out",
        };
        let kind = match s.kind {
            engine::plant::Kind::Bit => "bit",
            engine::plant::Kind::Analog => "analog",
        };
        let _ = writeln!(out, "  {dir} {kind} {}: {}", s.name, s.description);
    }
    for q in info.quantities.iter().chain([&ALARMS]) {
        let _ = writeln!(out, "  quantity {}: {} ({})", q.name, q.description, q.unit);
    }
    for p in info.params {
        let unit = if p.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", p.unit)
        };
        let _ = writeln!(
            out,
            "  parameter {}={}: {} ({}..{}{unit})",
            p.key, p.default, p.description, p.min, p.max
        );
    }
}

fn default_wiring(info: &PlantInfo, id: MachineId, out: &mut String) {
    use std::fmt::Write;
    let plc = new_plc(id);
    let (wired, left) = wiring::default_wiring(info, plc.as_ref());
    for w in &wired {
        let _ = writeln!(out, "  {},{}", w.signal, w.device);
    }
    let terminals = plc.terminals();
    for i in left {
        let s = &info.signals[i];
        let why = if terminals.by_name {
            format!(
                "{} wires by name: the program's bit {}",
                id.name(),
                s.name.to_ascii_uppercase()
            )
        } else if s.kind == engine::plant::Kind::Analog && terminals.analog.is_empty() {
            format!("{} has no analog input", id.name())
        } else {
            format!("{} has no terminal left for it", id.name())
        };
        let _ = writeln!(out, "  # {} not connected: {why}", s.name);
    }
}
