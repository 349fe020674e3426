//! `hashigo map` (an extension of cli.md): proposes a `--map` file for a
//! PLCopen project — every declared variable and block instance with no
//! device yet gets a free one of the machine's (`name,device` a line), the
//! entries of a `--map` given are kept first. The user edits it and passes
//! it back as `--map` to compile, run, asm, share or why.

use engine::formats::plcopen::Document;
use engine::MachineId;

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::source::{one, Problems, XmlOptions};

/// `hashigo map --machine ID --program FILE.xml [--map MAP.csv] [--pou NAME]`.
pub fn map(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "map", "pou"]).map_err(one)?;
    let machine =
        MachineId::parse(args.required("machine").map_err(one)?).map_err(|e| one(e.to_string()))?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    if format != Format::Xml {
        return Err(one(format!(
            "{path}: hashigo map takes a PLCopen file (.xml)"
        )));
    }
    let source = SourceFile::read(path).map_err(one)?;
    if machine == MachineId::SoftPlc {
        // Its variables keep their names and addresses: nothing to map.
        println!(
            "# {} runs on soft-plc with no map: every variable keeps its name and address",
            source.name
        );
        return Ok(());
    }
    let document = Document::read(&source.text).map_err(|errors| source.located(&errors))?;
    let xml = XmlOptions::read(&args)?;
    let given = xml.map.as_ref().map(|(_, m)| m);
    let mut out = format!(
        "# name,device for {} on {}: check each, then pass this file as --map\n",
        source.name,
        machine.name()
    );
    for (name, device, _) in given.map(|m| m.entries.as_slice()).unwrap_or(&[]) {
        out.push_str(&format!("{name},{device}\n"));
    }
    // `--pou NAME`: what that POU uses only.
    let pou = args.optional("pou").map_err(one)?;
    let proposed = document
        .propose(machine, given, pou)
        .map_err(|e| one(format!("{}: {e}", source.name)))?;
    for (name, device) in proposed {
        out.push_str(&format!("{name},{device}\n"));
    }
    print!("{out}");
    Ok(())
}
