//! `hashigo share` and `hashigo unshare` (cli.md): a project as the page's
//! link fragment and back, so scripts can make and check links.

use engine::formats::share;

use crate::args::Args;
use crate::input::{Format, SourceFile};
use crate::source::{ladder_project, machine_flag, one, Problems};

/// `hashigo share --program P [--machine ID]`: prints the fragment.
/// A ladder (`.json`, `.xml`) goes as it is; a program text is
/// decompiled to its ladder first.
pub fn share(rest: &[String]) -> Result<(), Problems> {
    let args = Args::parse(rest, &["machine", "program", "format", "map", "pou"]).map_err(one)?;
    let flag = machine_flag(&args)?;
    let path = args.required("program").map_err(one)?;
    let format = Format::choose(args.optional("format").map_err(one)?, path).map_err(one)?;
    let source = SourceFile::read(path).map_err(one)?;
    let project = ladder_project(&args, &source, format, flag, 10)?;
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
