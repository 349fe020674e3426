//! Reading an `.ld` file as LDmicro's own loader does (its `loadsave.cpp`
//! for versions 2.x and 4.x): the settings before `PROGRAM`, its lists,
//! then each `RUNG` … `END` with `SERIES` and `PARALLEL` groups, one
//! element per line in either argument form. Lines end in LF or CRLF;
//! blank lines and `;` lines are skipped in the program. Groups are read
//! with a stack of their own, never by recursion.

use super::error::LdError;
use super::file::{IoEntry, LdFile, LdRung, Node, VarSize, Version};
use super::leaf::leaf;
use crate::error::Located;
use crate::limits::{MAX_NESTING, MAX_RUNGS};

type Errors = Vec<Located<LdError>>;

/// An `.ld` file's bytes as text: UTF-8 when they are, else Latin-1 (the
/// Windows code page LDmicro's users wrote their comments in: `é` in a
/// French note of the `VAR LIST`), so that no file is refused for its
/// encoding; the elements themselves are ASCII either way.
pub fn decode(bytes: &[u8]) -> std::borrow::Cow<'_, str> {
    match std::str::from_utf8(bytes) {
        Ok(text) => std::borrow::Cow::Borrowed(text),
        Err(_) => std::borrow::Cow::Owned(bytes.iter().map(|&b| char::from(b)).collect()),
    }
}

/// Reads an `.ld` file. Every problem is an error at its line; nothing
/// is read partly.
pub fn parse(text: &str) -> Result<LdFile, Errors> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim_end_matches('\r')));
    let first = lines.by_ref().find(|(_, l)| !l.trim().is_empty());
    let version = match first {
        Some((_, l)) if l.trim() == "LDmicro0.1" => Version::V01,
        Some((_, l)) if l.trim().starts_with("LDmicro") => Version::V02,
        Some((n, l)) => return Err(vec![Located::new(n, LdError::NotLdmicro(l.into()))]),
        None => return Err(vec![Located::new(1, LdError::NotLdmicro(String::new()))]),
    };
    let mut file = LdFile {
        version,
        micro: String::new(),
        cycle_us: 10_000,
        crystal_hz: 0,
        baud: 0,
        compiled: String::new(),
        compiler: String::new(),
        vars: Vec::new(),
        io: Vec::new(),
        pull_ups: Vec::new(),
        rungs: Vec::new(),
    };
    let mut lines = lines.peekable();
    let mut errors = Vec::new();
    settings(&mut file, &mut lines, &mut errors)?;
    while let Some((n, line)) = lines.next() {
        let t = line.trim();
        if t.is_empty() || t.starts_with(';') {
            continue;
        }
        if !t.contains("RUNG") {
            errors.push(Located::new(n, LdError::NotARung(t.into())));
            break;
        }
        if file.rungs.len() == MAX_RUNGS {
            return Err(vec![Located::new(n, LdError::TooManyRungs)]);
        }
        match rung(n, &mut lines, version) {
            Ok(series) => file.rungs.push(LdRung { line: n, series }),
            Err(e) => errors.extend(e),
        }
    }
    if errors.is_empty() {
        Ok(file)
    } else {
        Err(errors)
    }
}

/// The settings and lists before `PROGRAM`. A line LDmicro would not
/// understand there is skipped, as LDmicro skips it; a `CYCLE=` the soft
/// PLC cannot scan at is an error in `errors`, at its line.
fn settings<'a>(
    file: &mut LdFile,
    lines: &mut impl Iterator<Item = (usize, &'a str)>,
    errors: &mut Errors,
) -> Result<(), Errors> {
    while let Some((n, line)) = lines.next() {
        let t = line.trim();
        let number = |rest: &str| -> u64 {
            let digits: String = rest
                .trim()
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            digits.parse().unwrap_or(0)
        };
        match t {
            "PROGRAM" => return Ok(()),
            "IO LIST" => file.io = list(lines, "IO LIST")?,
            "PULL-UP LIST" => file.pull_ups = list(lines, "PULL-UP LIST")?,
            "VAR LIST" => file.vars = var_list(lines)?,
            _ => {
                if let Some(rest) = t.strip_prefix("CYCLE=") {
                    match cycle(rest) {
                        Ok(us) => file.cycle_us = us,
                        Err(e) => errors.push(Located::new(n, e)),
                    }
                } else if let Some(rest) = t.strip_prefix("CRYSTAL=") {
                    file.crystal_hz = number(rest);
                } else if let Some(rest) = t.strip_prefix("BAUD=") {
                    file.baud = number(rest);
                } else if let Some(rest) = t.strip_prefix("MICRO=") {
                    file.micro = rest.into();
                } else if let Some(rest) = t.strip_prefix("COMPILED=") {
                    file.compiled = rest.into();
                } else if let Some(rest) = t.strip_prefix("COMPILER=") {
                    file.compiler = rest.into();
                }
            }
        }
    }
    Err(vec![Located::new(1, LdError::NoProgram)])
}

/// `CYCLE=`'s scan period in µs, read as LDmicro's `sscanf("%lld")` reads
/// it (spaces, a sign, digits; its `us at Timer1, …` tail after them),
/// and within the soft PLC's scan periods: above 0, at most
/// [`crate::softplc::machine::MAX_SCAN`].
fn cycle(rest: &str) -> Result<u64, LdError> {
    let t = rest.trim_start();
    let unsigned = t.strip_prefix(['-', '+']).unwrap_or(t);
    let digits: String = unsigned.chars().take_while(char::is_ascii_digit).collect();
    let negative = t.starts_with('-');
    if digits.is_empty() {
        return Err(LdError::Cycle {
            text: rest.trim().into(),
            why: "not a number (LDmicro writes the scan period in µs: CYCLE=10000)",
        });
    }
    let max = crate::softplc::machine::MAX_SCAN.as_nanos() / 1000;
    match digits.parse::<u64>() {
        Ok(us) if !negative && (1..=max).contains(&us) => Ok(us),
        Ok(0) => Err(LdError::Cycle {
            text: rest.trim().into(),
            why: "LDmicro's untimed cycle (the chip scans as fast as it runs); the soft PLC scans every 1 µs to 10 s (docs/limits.md)",
        }),
        _ => Err(LdError::Cycle {
            text: rest.trim().into(),
            why: "no scan period in µs the soft PLC has: it scans every 1 µs to 10 s (docs/limits.md)",
        }),
    }
}

/// A list's entries up to its `END`, each non-blank line read by `entry`
/// (its line number and trimmed text).
fn section<'a, T>(
    lines: &mut impl Iterator<Item = (usize, &'a str)>,
    name: &'static str,
    mut entry: impl FnMut(usize, &str) -> Result<T, LdError>,
) -> Result<Vec<T>, Errors> {
    let mut out = Vec::new();
    let mut last = 0;
    for (n, line) in lines.by_ref() {
        last = n;
        match line.trim() {
            "" => continue,
            "END" => return Ok(out),
            t => out.push(entry(n, t).map_err(|e| vec![Located::new(n, e)])?),
        }
    }
    Err(vec![Located::new(last, LdError::Unclosed(name))])
}

/// An `IO LIST` or `PULL-UP LIST`: a name and the rest of its line.
fn list<'a>(
    lines: &mut impl Iterator<Item = (usize, &'a str)>,
    name: &'static str,
) -> Result<Vec<IoEntry>, Errors> {
    section(lines, name, |n, t| {
        let (name, rest) = t.split_once(char::is_whitespace).unwrap_or((t, ""));
        Ok(IoEntry {
            name: name.into(),
            rest: rest.trim().into(),
            line: n,
        })
    })
}

/// The `VAR LIST`: `2 bytes name [note]`.
fn var_list<'a>(
    lines: &mut impl Iterator<Item = (usize, &'a str)>,
) -> Result<Vec<VarSize>, Errors> {
    section(lines, "VAR LIST", |n, t| {
        let mut words = t.split_whitespace();
        let bytes = words.next().and_then(|b| b.parse::<u16>().ok());
        match (bytes, words.next(), words.next()) {
            (Some(b @ 1..), Some("bytes" | "byte"), Some(name)) => Ok(VarSize {
                name: name.into(),
                bytes: b,
                note: t.split_once(name).map_or("", |(_, r)| r.trim()).into(),
                line: n,
            }),
            _ => Err(LdError::BadListLine {
                list: "VAR LIST",
                text: t.into(),
            }),
        }
    })
}

/// An open group while a rung is read.
struct Frame {
    parallel: bool,
    nodes: Vec<Node>,
    line: usize,
}

/// One rung's series, after its `RUNG` line `start`, up to its `END`.
fn rung<'a>(
    start: usize,
    lines: &mut impl Iterator<Item = (usize, &'a str)>,
    version: Version,
) -> Result<Vec<Node>, Errors> {
    let mut stack = vec![Frame {
        parallel: false,
        nodes: Vec::new(),
        line: start,
    }];
    let mut errors = Vec::new();
    for (n, line) in lines.by_ref() {
        let t = line.trim();
        if t.is_empty() || t.starts_with(';') {
            continue;
        }
        let in_parallel = stack.last().is_some_and(|f| f.parallel);
        match t {
            "SERIES" | "PARALLEL" => {
                if t == "PARALLEL" && in_parallel {
                    errors.push(Located::new(n, LdError::ParallelInParallel));
                }
                if stack.len() > MAX_NESTING {
                    return Err(vec![Located::new(n, LdError::TooDeep)]);
                }
                stack.push(Frame {
                    parallel: t == "PARALLEL",
                    nodes: Vec::new(),
                    line: n,
                });
            }
            "END" => {
                let Some(frame) = stack.pop() else {
                    break;
                };
                let node = match (frame.parallel, stack.last_mut()) {
                    (_, None) if errors.is_empty() => return Ok(frame.nodes),
                    (_, None) => return Err(errors),
                    (true, Some(_)) => Node::Parallel(frame.nodes, frame.line),
                    (false, Some(_)) => Node::Series(frame.nodes, frame.line),
                };
                if let Some(parent) = stack.last_mut() {
                    let empty =
                        matches!(&node, Node::Parallel(v, _) | Node::Series(v, _) if v.is_empty());
                    if empty {
                        let what = if frame.parallel { "PARALLEL" } else { "SERIES" };
                        errors.push(Located::new(frame.line, LdError::Empty(what)));
                    }
                    parent.nodes.push(node);
                }
            }
            _ => match leaf(t, version) {
                Ok(e) => {
                    if let Some(frame) = stack.last_mut() {
                        frame.nodes.push(Node::Leaf(e, n));
                    }
                }
                Err(e) => errors.push(Located::new(n, e)),
            },
        }
    }
    let open = stack.last().map_or(start, |f| f.line);
    let what = match stack.len() {
        0 | 1 => "RUNG",
        _ if stack.last().is_some_and(|f| f.parallel) => "PARALLEL",
        _ => "SERIES",
    };
    errors.push(Located::new(open, LdError::Unclosed(what)));
    Err(errors)
}
