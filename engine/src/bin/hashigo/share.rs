//! `hashigo share` and `hashigo unshare` (cli.md): a project as the page's
//! link fragment and back, so scripts can make and check links.

use engine::ladder::decompile::decompile_text;
use engine::ladder::{share, Project};
use engine::MachineId;

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::source::{machine_flag, one, read_project, Problems};

/// `hashigo share --program P [--machine ID]`: prints the fragment.
/// A ladder (`.json`, `.xml`) goes as it is; a program text is
/// decompiled to its ladder first.
pub fn share(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format"]).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    let source = SourceFile::read(path).map_err(one)?;
    let project = match format {
        Format::Json | Format::Xml => read_project(&source, format, flag)?.0,
        Format::Il | Format::Asm => {
            let machine = match flag {
                Some(m) => m,
                None => MachineId::parse(args.required("machine").map_err(one)?)
                    .map_err(|e| one(e.to_string()))?,
            };
            let ladder = decompile_text(machine, &source.text, 10).map_err(|e| match e {
                engine::ladder::decompile::TextError::Program(problems) => problems
                    .iter()
                    .map(|p| format!("{}:{}: {}", source.name, p.line, p.error))
                    .collect(),
                other => one(format!("{}: {other}", source.name)),
            })?;
            Project::new(machine, ladder)
        }
    };
    let link = share::encode(&project).map_err(|e| one(format!("{}: {e}", source.name)))?;
    println!("{link}");
    Ok(())
}

/// `hashigo unshare FRAGMENT|URL`: prints the project's JSON.
pub fn unshare(rest: &[String]) -> Result<(), Problems> {
    let [link] = rest else {
        return Err(one(
            "unshare takes one argument: a link or the fragment after its #".to_string(),
        ));
    };
    // A whole URL: the fragment is what follows the first `#`.
    let fragment = link.split_once('#').map_or(link.as_str(), |(_, f)| f);
    let project = share::decode(fragment).map_err(|e| one(format!("<link>: {e}")))?;
    print!("{}", project.to_json());
    Ok(())
}
