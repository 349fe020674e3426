//! Share URLs: a project as compact binary, deflated, in base64url.
//!
//! The text starts with the format version (`1.`) so later versions can
//! still read old links. Decoding never panics: every length is checked
//! against what is left, inflation is capped, and the result is a
//! [`Project`] or an error naming the byte where the data went wrong.

mod exercise;
mod plant;
mod program;
mod words;

use std::collections::BTreeMap;
use std::fmt;

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine as _;
use miniz_oxide::deflate::compress_to_vec;
use miniz_oxide::inflate::decompress_to_vec_with_limit;

use crate::formats::project::Project;
use crate::ladder::element::{CoilKind, ContactKind, Element, TimerKind};
use crate::ladder::grid::{Ladder, Link, Rung};
use crate::limits::{MAX_EXPECTATIONS, MAX_MAP_ENTRIES, MAX_RUNGS, MAX_TEST_CASES};
use crate::MachineId;

/// The prefix of version-1 share texts.
pub const PREFIX: &str = "1.";
/// The prefix of a link that also carries test cases (and the exercise flag).
pub const PREFIX_TESTS: &str = "2.";
/// The prefix of a link with the soft PLC's boxes or variables: a
/// version 2 link followed by the variables.
pub const PREFIX_WORDS: &str = "3.";
/// The prefix of a link with an exercise's task, hidden tests or a
/// case's hint (issue #49): a version 3 link followed by them.
pub const PREFIX_EXERCISE: &str = "4.";
/// The prefix of a link with a plant (issue #50): a version 4 link
/// followed by it.
pub const PREFIX_PLANT: &str = "5.";
/// The prefix of a link with a program text (issue #55).
pub const PREFIX_PROGRAM: &str = "6.";
/// The most bytes a share text may inflate to.
const MAX_INFLATED: usize = 1 << 20;
/// Grid limits a decoded rung must respect (the editor's own).
const MAX_ROWS: usize = 64;
const MAX_COLS: usize = 64;

/// Why a share text could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ShareError {
    /// The text does not start with a version this build reads.
    Version(String),
    /// Not base64url.
    Base64,
    /// Not deflate data, or more than the cap when inflated.
    Inflate,
    /// Longer than [`crate::limits::MAX_SHARE_FRAGMENT`] (the length).
    TooLong(usize),
    /// A rung larger than a link holds (64 × 64 cells), when encoding.
    RungTooLarge {
        /// The rung, 1-based.
        rung: usize,
        /// Its rows.
        rows: usize,
        /// Its columns (or a link's column past them).
        columns: usize,
    },
    /// The link holds more of something than a project may have
    /// (docs/limits.md), refused before any of them is built.
    TooMany {
        /// What: "rungs", "test cases", …
        what: &'static str,
        /// How many the link says it holds.
        count: u64,
        /// The most a project may have.
        limit: usize,
    },
    /// The binary is cut short or holds a bad value at this byte.
    Data {
        /// The byte offset in the inflated data.
        at: usize,
        /// What was wrong there.
        what: &'static str,
    },
}

impl fmt::Display for ShareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShareError::Version(v) => write!(
                f,
                "this share link is format {}, which this Hashigo does not read (it reads {PREFIX}…)", crate::error::shown(v)
            ),
            ShareError::Base64 => f.write_str("this share link is damaged: it is not base64url text"),
            ShareError::Inflate => f.write_str("this share link is damaged: its data does not unpack"),
            ShareError::RungTooLarge { rung, rows, columns } => write!(
                f,
                "rung {rung} spans {rows} rows and {columns} columns: a share link holds rungs of at most {MAX_ROWS} × {MAX_COLS} cells"
            ),
            ShareError::TooLong(n) => write!(
                f,
                "this share link is {n} characters long, more than the {} a link may have (docs/limits.md)",
                crate::limits::MAX_SHARE_FRAGMENT
            ),
            ShareError::TooMany { what, count, limit } => write!(
                f,
                "this share link holds {count} {what}, more than the {limit} a project may have (docs/limits.md)"
            ),
            ShareError::Data { at, what } => {
                write!(f, "this share link is damaged at byte {at}: {what}")
            }
        }
    }
}

impl std::error::Error for ShareError {}

/// Encodes a project as share text (`1.` + base64url of deflated binary;
/// a project with test cases, or marked as an exercise, is `2.`: the same
/// binary followed by the exercise flag and the cases, so that links
/// without tests stay what they were; `3.` adds the soft PLC's variables
/// `4.` an exercise's task, hidden flag and hints, `5.` a plant). A rung larger than a link holds is
/// refused, so that no link is made that would not open.
pub fn encode(project: &Project) -> Result<String, ShareError> {
    for (i, rung) in project.ladder.rungs.iter().enumerate() {
        let rows = rung.cells.len();
        let columns = rung
            .width()
            .max(rung.links.iter().map(|l| l.col).max().unwrap_or(0));
        let link_rows = rung.links.iter().map(|l| l.row).max().unwrap_or(0);
        if rows > MAX_ROWS || columns > MAX_COLS || link_rows > MAX_ROWS {
            return Err(ShareError::RungTooLarge {
                rung: i + 1,
                rows: rows.max(link_rows),
                columns,
            });
        }
    }
    let mut w = Vec::new();
    w.push(machine_code(project.machine));
    put_map(&mut w, &project.settings);
    put_map(&mut w, &project.ladder.device_comments);
    put_len(&mut w, project.ladder.rungs.len());
    for rung in &project.ladder.rungs {
        put_str(&mut w, &rung.comment);
        put_len(&mut w, rung.cells.len());
        for row in &rung.cells {
            put_len(&mut w, row.len());
            for cell in row {
                put_cell(&mut w, cell.as_ref());
            }
        }
        put_len(&mut w, rung.links.len());
        for l in &rung.links {
            put_len(&mut w, l.row);
            put_len(&mut w, l.col);
        }
    }
    let with_program = project.program.is_some();
    let with_plant = with_program || project.plant.is_some();
    let with_exercise = with_plant || exercise::needed(project);
    let words = with_exercise || words::needed(&project.ladder);
    let prefix = if project.tests.is_empty() && project.exercise.is_none() && !words {
        PREFIX
    } else {
        w.push(u8::from(project.exercise.is_some()));
        put_len(&mut w, project.tests.len());
        for case in &project.tests {
            put_str(&mut w, &case.name);
            put_str(&mut w, &case.events);
            put_len(&mut w, case.expect.len());
            for line in &case.expect {
                put_str(&mut w, line);
            }
        }
        if with_exercise {
            words::put_variables(&mut w, &project.ladder.variables);
            exercise::put(&mut w, project);
            if with_program {
                program::put(&mut w, project);
                PREFIX_PROGRAM
            } else if with_plant {
                plant::put(&mut w, project);
                PREFIX_PLANT
            } else {
                PREFIX_EXERCISE
            }
        } else if words {
            words::put_variables(&mut w, &project.ladder.variables);
            PREFIX_WORDS
        } else {
            PREFIX_TESTS
        }
    };
    Ok(format!(
        "{prefix}{}",
        URL_SAFE_NO_PAD.encode(compress_to_vec(&w, 10))
    ))
}

/// Decodes share text back into a project.
pub fn decode(text: &str) -> Result<Project, ShareError> {
    let text = text.trim();
    if text.len() > crate::limits::MAX_SHARE_FRAGMENT {
        return Err(ShareError::TooLong(text.len()));
    }
    let with_program = text.starts_with(PREFIX_PROGRAM);
    let with_plant = with_program || text.starts_with(PREFIX_PLANT);
    let with_exercise = with_plant || text.starts_with(PREFIX_EXERCISE);
    let with_words = with_exercise || text.starts_with(PREFIX_WORDS);
    let with_tests = with_words || text.starts_with(PREFIX_TESTS);
    let Some(body) = text
        .strip_prefix(PREFIX)
        .or_else(|| text.strip_prefix(PREFIX_TESTS))
        .or_else(|| text.strip_prefix(PREFIX_WORDS))
        .or_else(|| text.strip_prefix(PREFIX_EXERCISE))
        .or_else(|| text.strip_prefix(PREFIX_PLANT))
        .or_else(|| text.strip_prefix(PREFIX_PROGRAM))
    else {
        let version = text
            .split('.')
            .next()
            .unwrap_or("")
            .chars()
            .take(8)
            .collect();
        return Err(ShareError::Version(version));
    };
    let packed = URL_SAFE_NO_PAD
        .decode(body.trim_end_matches('='))
        .map_err(|_| ShareError::Base64)?;
    let data =
        decompress_to_vec_with_limit(&packed, MAX_INFLATED).map_err(|_| ShareError::Inflate)?;
    let mut r = Reader { data: &data, at: 0 };
    let code = r.byte()?;
    let Some(machine) = MachineId::ALL
        .into_iter()
        .find(|m| m.target().share_code() == code)
    else {
        return Err(r.bad("unknown machine"));
    };
    let settings = r.map("settings")?;
    let device_comments = r.map("device comments")?;
    let rungs = r.rungs()?;
    let mut project = Project::new(
        machine,
        Ladder {
            rungs,
            device_comments,
            variables: Vec::new(),
        },
    );
    if with_tests {
        project.exercise = match r.byte()? {
            0 => None,
            1 => Some(crate::formats::project::Exercise::default()),
            _ => return Err(r.bad("the exercise flag is neither 0 nor 1")),
        };
        project.tests = r.cases()?;
    }
    if with_words {
        project.ladder.variables = r.variables()?;
    }
    if with_exercise {
        r.exercise(&mut project)?;
    }
    if with_program {
        r.program(&mut project)?;
    } else if with_plant {
        project.plant = Some(r.plant()?);
    }
    if r.at != data.len() {
        return Err(r.bad("data after the last rung"));
    }
    project.settings = settings;
    Ok(project)
}

fn machine_code(m: MachineId) -> u8 {
    m.target().share_code()
}

/// LEB128 unsigned.
fn put_len(w: &mut Vec<u8>, mut n: usize) {
    loop {
        let b = (n & 0x7F) as u8;
        n >>= 7;
        if n == 0 {
            w.push(b);
            return;
        }
        w.push(b | 0x80);
    }
}

fn put_str(w: &mut Vec<u8>, s: &str) {
    put_len(w, s.len());
    w.extend_from_slice(s.as_bytes());
}

fn put_map(w: &mut Vec<u8>, m: &BTreeMap<String, String>) {
    put_len(w, m.len());
    for (k, v) in m {
        put_str(w, k);
        put_str(w, v);
    }
}

// Cell tags: 0 empty, 1 wire, 2-5 contacts, 6-9 coils, 10 NOT, 11-12
// R_TRIG/F_TRIG, 13-15 TON/TOF/TP, 16-17 PLS/PLF, 18 timer coil,
// 19 counter coil, 20 MOV, 21 CMP, 22 INC, 23 DEC, 24-25 the soft PLC's
// in-line and output boxes, 26 a box's input wired as a network
// (version 3: words.rs).
fn put_cell(w: &mut Vec<u8>, cell: Option<&Element>) {
    let Some(e) = cell else {
        w.push(0);
        return;
    };
    match e {
        Element::Wire => w.push(1),
        Element::Contact { kind, device } => {
            w.push(2 + *kind as u8);
            put_str(w, device);
        }
        Element::Coil { kind, device } => {
            w.push(6 + *kind as u8);
            put_str(w, device);
        }
        Element::Not => w.push(10),
        Element::Edge { falling } => w.push(11 + u8::from(*falling)),
        Element::Timer {
            kind,
            name,
            preset_ms,
        } => {
            w.push(13 + *kind as u8);
            put_str(w, name);
            put_len(w, *preset_ms as usize);
        }
        Element::Pulse { falling, device } => {
            w.push(16 + u8::from(*falling));
            put_str(w, device);
        }
        Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
            w.push(if matches!(e, Element::TimerCoil { .. }) {
                18
            } else {
                19
            });
            put_str(w, device);
            put_len(w, usize::from(*preset));
        }
        Element::Mov { src: a, dst: b } | Element::Cmp { a, b } => {
            w.push(if matches!(e, Element::Mov { .. }) {
                20
            } else {
                21
            });
            put_str(w, a);
            put_str(w, b);
        }
        Element::Block(b) | Element::OutputBlock(b) => {
            w.push(words::BLOCK + u8::from(matches!(e, Element::OutputBlock(_))));
            words::put_block(w, b);
        }
        Element::BoxInput { pin } => {
            w.push(words::BOX_INPUT);
            put_str(w, pin);
        }
        Element::Inc { dst } | Element::Dec { dst } => {
            w.push(if matches!(e, Element::Inc { .. }) {
                22
            } else {
                23
            });
            put_str(w, dst);
        }
    }
}

struct Reader<'a> {
    data: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn bad(&self, what: &'static str) -> ShareError {
        ShareError::Data { at: self.at, what }
    }

    fn byte(&mut self) -> Result<u8, ShareError> {
        let b = *self.data.get(self.at).ok_or(self.bad("cut short"))?;
        self.at += 1;
        Ok(b)
    }

    /// A length or number up to `max`.
    fn len(&mut self, max: usize) -> Result<usize, ShareError> {
        let n = self.varint()?;
        usize::try_from(n)
            .ok()
            .filter(|&v| v <= max)
            .ok_or(self.bad("a number out of range"))
    }

    /// An unsigned LEB128 number.
    fn varint(&mut self) -> Result<u64, ShareError> {
        let mut n: u64 = 0;
        for shift in (0..64).step_by(7) {
            let b = self.byte()?;
            n |= u64::from(b & 0x7F) << shift;
            if b & 0x80 == 0 {
                return Ok(n);
            }
        }
        Err(self.bad("a number too long"))
    }

    fn string(&mut self) -> Result<String, ShareError> {
        let n = self.len(self.data.len() - self.at.min(self.data.len()))?;
        let bytes = self
            .data
            .get(self.at..self.at + n)
            .ok_or(self.bad("cut short"))?;
        let s = std::str::from_utf8(bytes).map_err(|_| self.bad("text that is not UTF-8"))?;
        self.at += n;
        Ok(s.to_string())
    }

    /// The rungs: a count, then each rung's comment, rows of cells and
    /// links.
    fn rungs(&mut self) -> Result<Vec<Rung>, ShareError> {
        let count = self.count("rungs", MAX_RUNGS)?;
        let mut rungs = Vec::with_capacity(count);
        for _ in 0..count {
            let comment = self.string()?;
            let rows = self.len(MAX_ROWS)?;
            let mut cells = Vec::with_capacity(rows);
            for _ in 0..rows {
                let width = self.len(MAX_COLS)?;
                let mut row = Vec::with_capacity(width);
                for _ in 0..width {
                    row.push(self.cell()?);
                }
                cells.push(row);
            }
            let links = self.count("links in one rung", MAX_ROWS * MAX_COLS)?;
            let mut rung = Rung {
                comment,
                cells,
                links: Vec::new(),
            };
            for _ in 0..links {
                let (row, col) = (self.len(MAX_ROWS)?, self.len(MAX_COLS)?);
                rung.links.push(Link { row, col });
            }
            rungs.push(rung);
        }
        Ok(rungs)
    }

    /// The test cases: a count, then each case's name, events and
    /// expectation lines.
    fn cases(&mut self) -> Result<Vec<crate::cases::TestCase>, ShareError> {
        let count = self.count("test cases", MAX_TEST_CASES)?;
        let mut cases = Vec::with_capacity(count);
        for _ in 0..count {
            let name = self.string()?;
            let events = self.string()?;
            let lines = self.count("expectations in one test case", MAX_EXPECTATIONS)?;
            let mut expect = Vec::with_capacity(lines);
            for _ in 0..lines {
                expect.push(self.string()?);
            }
            cases.push(crate::cases::TestCase {
                name,
                events,
                expect,
                hint: String::new(),
            });
        }
        Ok(cases)
    }

    /// A count of items that may not exceed `limit` (a documented limit:
    /// refused with [`ShareError::TooMany`] before any item is read).
    fn count(&mut self, what: &'static str, limit: usize) -> Result<usize, ShareError> {
        let n = self.varint()?;
        match usize::try_from(n) {
            Ok(n) if n <= limit => {
                // Each item takes at least one byte.
                if n > self.data.len() - self.at {
                    return Err(self.bad("cut short"));
                }
                Ok(n)
            }
            _ => Err(ShareError::TooMany {
                what,
                count: n,
                limit,
            }),
        }
    }

    /// Names and texts (settings, device comments): each name once.
    fn map(&mut self, what: &'static str) -> Result<BTreeMap<String, String>, ShareError> {
        let n = self.count(what, MAX_MAP_ENTRIES)?;
        let mut m = BTreeMap::new();
        for _ in 0..n {
            let k = self.string()?;
            let v = self.string()?;
            if m.insert(k, v).is_some() {
                return Err(self.bad("a name given twice"));
            }
        }
        Ok(m)
    }

    fn number<T: TryFrom<usize>>(&mut self) -> Result<T, ShareError> {
        let n = self.len(u32::MAX as usize)?;
        T::try_from(n).map_err(|_| self.bad("a number out of range"))
    }

    fn cell(&mut self) -> Result<Option<Element>, ShareError> {
        const CONTACTS: [ContactKind; 4] = [
            ContactKind::No,
            ContactKind::Nc,
            ContactKind::Rising,
            ContactKind::Falling,
        ];
        const COILS: [CoilKind; 4] = [
            CoilKind::Normal,
            CoilKind::Inverted,
            CoilKind::Set,
            CoilKind::Reset,
        ];
        const TIMERS: [TimerKind; 3] = [TimerKind::Ton, TimerKind::Tof, TimerKind::Tp];
        let tag = self.byte()?;
        Ok(Some(match tag {
            0 => return Ok(None),
            1 => Element::Wire,
            2..=5 => Element::Contact {
                kind: CONTACTS[usize::from(tag - 2)],
                device: self.string()?,
            },
            6..=9 => Element::Coil {
                kind: COILS[usize::from(tag - 6)],
                device: self.string()?,
            },
            10 => Element::Not,
            11 | 12 => Element::Edge { falling: tag == 12 },
            13..=15 => Element::Timer {
                kind: TIMERS[usize::from(tag - 13)],
                name: self.string()?,
                preset_ms: self.number()?,
            },
            16 | 17 => Element::Pulse {
                falling: tag == 17,
                device: self.string()?,
            },
            18 => Element::TimerCoil {
                device: self.string()?,
                preset: self.number()?,
            },
            19 => Element::CounterCoil {
                device: self.string()?,
                preset: self.number()?,
            },
            20 => Element::Mov {
                src: self.string()?,
                dst: self.string()?,
            },
            21 => Element::Cmp {
                a: self.string()?,
                b: self.string()?,
            },
            22 => Element::Inc {
                dst: self.string()?,
            },
            23 => Element::Dec {
                dst: self.string()?,
            },
            24 | 25 => self.block(tag)?,
            words::BOX_INPUT => Element::BoxInput {
                pin: self.string()?,
            },
            _ => return Err(self.bad("an unknown element")),
        }))
    }
}
