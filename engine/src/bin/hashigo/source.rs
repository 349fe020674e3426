//! `--program` read, compiled when it is a ladder, and loaded into a new
//! machine of its kind, through the engine's one machine interface.

use engine::formats::plcopen;
use engine::formats::plcopen::VarMap;
use engine::formats::{Document, Kind, Opened, Project};
use engine::ladder::compile::{compile as compile_ladder, Options};
use engine::ladder::decompile::decompile_text;
use engine::machines::new_plc;
use engine::plc::{Command, Plc, PlcError};
use engine::{MachineId, SimTime};

use crate::args::Args;
use crate::input::{Format, SourceFile};

/// Problem lines, without `error: `.
pub type Problems = Vec<String>;
/// `--set`-style settings a project file holds: name, value, line.
pub type Settings = Vec<(String, String, usize)>;

/// One problem.
pub fn one(problem: String) -> Problems {
    vec![problem]
}

/// A machine with the program loaded, and the settings its project holds.
pub struct Source {
    /// The machine, powered on, program loaded.
    pub plc: Box<dyn Plc>,
    /// `--set`-style settings from a project file, applied before `--set`.
    pub settings: Settings,
    /// Where those settings came from, for their errors.
    pub name: String,
    /// The file as read, and its format.
    pub file: SourceFile,
    pub format: Format,
    /// The project a ladder file (`.json`, `.xml`) was read as, so that
    /// nothing reads it (and says its warnings) twice.
    pub project: Option<Project>,
}

/// `--machine`, when given.
pub fn machine_flag(args: &Args) -> Result<Option<MachineId>, Problems> {
    args.optional("machine")
        .map_err(one)?
        .map(|m| MachineId::parse(m).map_err(|e| e.to_string()))
        .transpose()
        .map_err(one)
}

/// Reads `--machine`, `--program` and `--format`, compiles a ladder
/// (`.json`, `.xml`) first, and loads the program into a new machine;
/// `Err` holds every problem found.
pub fn load(args: &Args) -> Result<Source, Problems> {
    let flag = machine_flag(args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    let source = SourceFile::read(path).map_err(one)?;
    let (machine, compiled, settings, project) = match format {
        Format::Il | Format::Asm => {
            let machine = match flag {
                Some(m) => m,
                None => MachineId::parse(args.required("machine").map_err(one)?)
                    .map_err(|e| one(e.to_string()))?,
            };
            if format == Format::Asm && machine != MachineId::AvrPlc {
                return Err(one(format!(
                    "{}: {} programs are mnemonic text (.il), not .asm",
                    source.name,
                    machine.name()
                )));
            }
            (machine, None, Vec::new(), None)
        }
        Format::St => (
            MachineId::SoftPlc,
            Some(st_program(&source, flag)?),
            Vec::new(),
            None,
        ),
        Format::Xml if flag == Some(MachineId::SoftPlc) => {
            let text = soft_program(args, &source)?;
            (MachineId::SoftPlc, Some(text), Vec::new(), None)
        }
        Format::Json | Format::Xml | Format::Ld => {
            let (project, text, settings) = compile_source(args, &source, format, flag)?;
            (project.machine, Some(text), settings, Some(project))
        }
    };
    let mut plc = new_plc(machine);
    if machine == MachineId::AvrPlc {
        // The AVR assembler's `Scan` symbol is the scan period: set it
        // before the source is assembled.
        let scan = avr_scan_ms(args, &source.name, &settings)?;
        let value = format!("{scan}ms");
        let setting = Command::Setting {
            name: "scan".into(),
            value,
        };
        plc.apply(setting).map_err(|e| one(e.to_string()))?;
    }
    // A compiled ladder is parsed like a listing; its errors would be the
    // compiler's, so they name the compiled text.
    let (text, origin) = match &compiled {
        Some(t) => (t.as_str(), format!("{} (compiled)", source.name)),
        None => (source.text.as_str(), source.name.clone()),
    };
    plc.load_text(text).map_err(|e| located(&origin, e))?;
    Ok(Source {
        plc,
        settings,
        name: source.name.clone(),
        file: source,
        format,
        project,
    })
}

/// A Structured Text file as the soft PLC runs it (its Instruction
/// List); errors at the file's line and column.
fn st_program(source: &SourceFile, flag: Option<MachineId>) -> Result<String, Problems> {
    if let Some(m) = flag.filter(|m| *m != MachineId::SoftPlc) {
        return Err(one(format!(
            "{}: Structured Text runs on the soft PLC (--machine soft-plc), not {}",
            source.name,
            m.name()
        )));
    }
    engine::softplc::st::st_to_il(&source.text).map_err(|errors| {
        errors
            .iter()
            .map(|e| format!("{}:{e}", source.name))
            .collect()
    })
}

/// A PLCopen project as the soft PLC runs it: no map (names stay names,
/// addresses stay addresses), its drawn bodies as Instruction List;
/// errors at the file's lines.
pub fn soft_program(args: &Args, source: &SourceFile) -> Result<String, Problems> {
    if args.optional("map").map_err(one)?.is_some() {
        return Err(one(format!(
            "{}: the soft PLC needs no --map: its variables keep their names and addresses",
            source.name
        )));
    }
    let pou = args.optional("pou").map_err(one)?;
    let program = plcopen::Document::read(&source.text)
        .and_then(|document| document.soft_program(pou))
        .map_err(|errors| source.located(&errors))?;
    for w in &program.warnings {
        eprintln!("warning: {}:{}: {}", source.name, w.line, w.error);
    }
    Ok(program.text)
}

/// A machine error as problem lines: one per program line at fault.
pub fn located(file: &str, error: PlcError) -> Problems {
    match error {
        PlcError::Program(problems) => problems
            .iter()
            .map(|p| format!("{file}:{}: {}", p.line, p.error))
            .collect(),
        other => one(format!("{file}: {other}")),
    }
}

/// A ladder file compiled for its machine: the project, the program text
/// and the project's settings. Errors name the file, rung and cell.
pub fn compile_source(
    args: &Args,
    source: &SourceFile,
    format: Format,
    flag: Option<MachineId>,
) -> Result<(Project, String, Settings), Problems> {
    let xml = XmlOptions::read(args)?;
    let (opened, document) = read_project(source, format, flag, &xml)?;
    let text = compile_project(args, source, &document, &opened)?;
    Ok((opened.project, text, opened.settings))
}

/// `opened` (imported from `document`, read from `source`) compiled for
/// its machine.
pub fn compile_project(
    args: &Args,
    source: &SourceFile,
    document: &Document,
    opened: &Opened,
) -> Result<String, Problems> {
    let project = &opened.project;
    let avr_scan_ms = if project.machine.target().scan_in_program() {
        avr_scan_ms(args, &source.name, &opened.settings)?
    } else {
        10
    };
    let options = Options { avr_scan_ms };
    compile_ladder(&project.ladder, project.machine, options).map_err(|errors| {
        // An LDmicro file's ladder is the program's own drawing: its
        // problems go at the file's lines, not at rungs it does not have.
        let at_rungs: Problems = errors
            .iter()
            .map(|e| format!("{}: {e}", source.name))
            .collect();
        document
            .locate(errors)
            .map_or(at_rungs, |located| source.located(&located))
    })
}

/// The project a ladder file stands for (`--machine` wins over the one a
/// `.json` project names; a PLCopen file names none), with its settings
/// and the line of each, and the file as read. It is not compiled: a
/// ladder with wiring errors is still a ladder to share.
pub fn read_project(
    source: &SourceFile,
    format: Format,
    flag: Option<MachineId>,
    xml: &XmlOptions,
) -> Result<(Opened, Document), Problems> {
    let kind = match format {
        Format::Json => Kind::Project,
        Format::Xml => Kind::PlcOpen,
        Format::Ld => Kind::LdMicro,
        Format::Il | Format::Asm | Format::St => {
            return Err(one(format!("{}: not a ladder file", source.name)));
        }
    };
    if let Some(m) = flag.filter(|m| kind == Kind::LdMicro && *m != MachineId::SoftPlc) {
        return Err(one(format!(
            "{}: LDmicro files run on the soft PLC (--machine soft-plc), not {}",
            source.name,
            m.name()
        )));
    }
    let map = xml.map.as_ref().filter(|_| kind == Kind::PlcOpen);
    if kind == Kind::PlcOpen {
        let machine = flag.ok_or_else(|| {
            one(format!(
                "{}: a PLCopen file does not name its machine: give --machine",
                source.name
            ))
        })?;
        if let Some((file, map)) = map {
            // A bad device is the map's fault: said at the map's line.
            map.check(machine).map_err(|errors| file.located(&errors))?;
        }
    }
    let document = Document::open(kind, &source.text).map_err(|e| source.located(&e))?;
    // A PLCopen file has its --machine (above); the others name theirs.
    let machine = flag.or(document.machine()).unwrap_or(MachineId::SoftPlc);
    let opened = document
        .import(machine, map.map(|(_, m)| m), xml.pou.as_deref())
        .map_err(|errors| source.located(&errors))?;
    for w in &opened.warnings {
        eprintln!("warning: {}:{}: {}", source.name, w.line, w.error);
    }
    if let Some((file, _)) = map {
        // Said next to errors, but they do not stop the import.
        for (name, line) in &opened.unused_map_entries {
            eprintln!(
                "warning: {}:{line}: {} is not a variable or block of {}",
                file.name,
                engine::shown(name),
                source.name
            );
        }
    }
    Ok((opened, document))
}

/// How a PLCopen file is read: `--map` (its file and entries) and
/// `--pou`.
#[derive(Default)]
pub struct XmlOptions {
    pub map: Option<(SourceFile, VarMap)>,
    pub pou: Option<String>,
}

impl XmlOptions {
    /// `--map`'s file (`name,device` a line; errors at its lines) and
    /// `--pou`, when given.
    pub fn read(args: &Args) -> Result<XmlOptions, Problems> {
        let pou = args.optional("pou").map_err(one)?.map(str::to_string);
        let Some(path) = args.optional("map").map_err(one)? else {
            return Ok(XmlOptions { map: None, pou });
        };
        let file = SourceFile::read(path).map_err(one)?;
        let map = VarMap::parse(&file.text).map_err(|errors| {
            errors
                .iter()
                .map(|e| format!("{}:{}: {}", file.name, e.line, e.error))
                .collect::<Vec<_>>()
        })?;
        Ok(XmlOptions {
            map: Some((file, map)),
            pou,
        })
    }
}

/// The ladder a `--program` stands for: a ladder file's project, or a
/// program text decompiled (an AVR source with `Scan` = `scan_ms`).
pub fn ladder_project(
    args: &Args,
    source: &SourceFile,
    format: Format,
    flag: Option<MachineId>,
    scan_ms: u32,
) -> Result<Project, Problems> {
    Ok(match format {
        Format::Json | Format::Xml | Format::Ld => {
            read_project(source, format, flag, &XmlOptions::read(args)?)?
                .0
                .project
        }
        Format::Il | Format::Asm | Format::St => {
            // Structured Text becomes a ladder through its IL (its
            // problems, if any, named at the compiled text's lines).
            let (machine, text, name) = if format == Format::St {
                let il = st_program(source, flag)?;
                let name = format!("{} (compiled)", source.name);
                (MachineId::SoftPlc, il, name)
            } else {
                let machine = match flag {
                    Some(m) => m,
                    None => MachineId::parse(args.required("machine").map_err(one)?)
                        .map_err(|e| one(e.to_string()))?,
                };
                (machine, source.text.clone(), source.name.clone())
            };
            let ladder = decompile_text(machine, &text, scan_ms).map_err(|e| match e {
                engine::ladder::decompile::TextError::Program(problems) => problems
                    .iter()
                    .map(|p| format!("{name}:{}: {}", p.line, p.error))
                    .collect(),
                other => one(format!("{name}: {other}")),
            })?;
            Project::new(machine, ladder)
        }
    })
}

/// The `Scan` symbol of AVR sources: the scan period in ms from the last
/// `--set scan=`, else the project's, else 10. A bad value is one problem,
/// worded as the settings check words it (so a run that also applies the
/// settings reports it once).
pub fn avr_scan_ms(
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
        .and_then(|t| engine::avr::scan_ms(t).map_err(|e| e.to_string()))
        .map_err(|e| one(format!("{what}: {e}")))
}

/// Where a project's setting stands, as its errors name it:
/// `FILE:LINE: setting NAME=VALUE`.
pub fn setting_place(file: &str, line: usize, name: &str, value: &str) -> String {
    format!(
        "{file}:{line}: setting {}={}",
        engine::shown(name).trim_matches('"'),
        engine::shown(value).trim_matches('"')
    )
}

/// Applies the project's settings, then every `--set`, to `plc`; the
/// problems found, each naming where the setting came from.
pub fn apply_settings(
    plc: &mut dyn Plc,
    args: &Args,
    (file, defaults): (&str, &[(String, String, usize)]),
) -> Problems {
    let mut problems = Vec::new();
    for (name, value, line) in defaults {
        let setting = Command::Setting {
            name: name.clone(),
            value: value.clone(),
        };
        if let Err(e) = plc.apply(setting) {
            problems.push(format!("{}: {e}", setting_place(file, *line, name, value)));
        }
    }
    for setting in args.all("set") {
        let result = match setting.split_once('=') {
            Some((name, value)) => plc
                .apply(Command::Setting {
                    name: name.trim().to_string(),
                    value: value.trim().to_string(),
                })
                .map_err(|e| e.to_string()),
            None => Err("expected NAME=VALUE".to_string()),
        };
        if let Err(e) = result {
            problems.push(format!("--set {setting}: {e}"));
        }
    }
    problems
}
