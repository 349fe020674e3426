//! What the ladder view shows, computed in plain Rust from the engine's
//! ladder: each rung's cells with their kind, device, symbol, comment,
//! links and error. The view keeps one signal per rung and one component
//! per cell, keyed by this data, so an edit re-renders only the cells it
//! changed (tested natively below and in the browser).

use std::collections::{BTreeMap, HashMap};

use engine::ladder::edit::{Cursor, EntryKind, MAX_ROWS};
use engine::ladder::{CoilKind, ContactKind, Element, Pos, Rung};

pub use super::cell_kind::CellKind;
use crate::i18n::Lang;

/// One cell as drawn.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct CellData {
    /// Row within the rung (0-based).
    pub row: usize,
    /// Column (0-based).
    pub col: usize,
    /// Columns in its rung (the cell is `row * cols + col` in its rung's
    /// cells).
    pub cols: usize,
    /// What it holds (its hook, symbol and words: [`CellKind::look`]).
    pub kind: CellKind,
    /// The device, when the element has one.
    pub device: String,
    /// The symbol (`┤ ├`, `( )`, `[MOV K50 D00]`).
    pub symbol: String,
    /// Words for screen readers ("normally open contact X00").
    pub words: String,
    /// The device's comment.
    pub comment: String,
    /// A vertical link at the left edge from the row above.
    pub link_up: bool,
    /// A vertical link at the left edge to the row below.
    pub link_down: bool,
    /// The compiler's message for this cell.
    pub error: Option<String>,
    /// A soft PLC box's operands shown live: (label, device).
    pub watched: Vec<(String, String)>,
}

/// One rung as drawn.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct RungData {
    /// The rung comment.
    pub comment: String,
    /// Rows shown (the rung's rows and one free row to draw a branch in).
    pub rows: usize,
    /// Columns shown.
    pub cols: usize,
    /// Every cell shown, row by row.
    pub cells: Vec<CellData>,
    /// Problems of the rung that have no cell.
    pub errors: Vec<String>,
}

/// The rows a rung shows: its own, those its links reach, and one free
/// row below (at most [`MAX_ROWS`]).
pub fn shown_rows(rung: &Rung) -> usize {
    let linked = rung.links.iter().map(|l| l.row + 2).max().unwrap_or(0);
    (rung.cells.len().max(linked).max(1) + 1).min(MAX_ROWS)
}

/// The columns a rung shows: up to the output column, wider when drawn so.
pub fn shown_cols(rung: &Rung, output_column: usize) -> usize {
    let linked = rung.links.iter().map(|l| l.col + 1).max().unwrap_or(0);
    rung.width().max(linked).max(output_column + 1)
}

/// The drawing of `rung`, with `errors` (by cell, or `None` for the
/// rung) and the ladder's device comments.
pub fn rung_data(
    rung: &Rung,
    output_column: usize,
    errors: &[(Option<Pos>, String)],
    comments: &BTreeMap<String, String>,
) -> RungData {
    let rows = shown_rows(rung);
    let cols = shown_cols(rung, output_column);
    let mut cells = Vec::with_capacity(rows * cols);
    for row in 0..rows {
        for col in 0..cols {
            let pos = Pos::new(row, col);
            let mut cell = match rung.get(pos) {
                Some(e) => drawn(e),
                None => CellData::default(),
            };
            cell.row = row;
            cell.col = col;
            cell.cols = cols;
            cell.comment = comments.get(&cell.device).cloned().unwrap_or_default();
            cell.link_down = rung.links.iter().any(|l| l.row == row && l.col == col);
            cell.link_up = row > 0 && rung.links.iter().any(|l| l.row + 1 == row && l.col == col);
            let here: Vec<&str> = errors
                .iter()
                .filter(|(p, _)| *p == Some(pos))
                .map(|(_, m)| m.as_str())
                .collect();
            if !here.is_empty() {
                cell.error = Some(here.join("; "));
            }
            cells.push(cell);
        }
    }
    RungData {
        comment: rung.comment.clone(),
        rows,
        cols,
        cells,
        errors: errors
            .iter()
            .filter(|(p, _)| p.is_none_or(|p| p.row >= rows || p.col >= cols))
            .map(|(_, m)| m.clone())
            .collect(),
    }
}

/// Kind, device, symbol and words of an element (the fixed ones from
/// [`CellKind::look`]).
fn drawn(e: &Element) -> CellData {
    if let Some(cell) = soft_box(e) {
        return cell;
    }
    let fixed = |kind: CellKind, device: &str| {
        let look = kind.look();
        (
            kind,
            device.to_string(),
            look.symbol.to_string(),
            format!("{} {device}", look.words),
        )
    };
    let (kind, device, symbol, words) = match e {
        Element::Wire => (CellKind::Wire, String::new(), String::new(), "wire".into()),
        Element::Contact { kind, device } => fixed(
            match kind {
                ContactKind::No => CellKind::No,
                ContactKind::Nc => CellKind::Nc,
                ContactKind::Rising => CellKind::Rise,
                ContactKind::Falling => CellKind::Fall,
            },
            device,
        ),
        Element::Coil { kind, device } => fixed(
            match kind {
                CoilKind::Normal => CellKind::Coil,
                CoilKind::Inverted => CellKind::CoilNot,
                CoilKind::Set => CellKind::Set,
                CoilKind::Reset => CellKind::Reset,
            },
            device,
        ),
        Element::TimerCoil { device, preset } => (
            CellKind::CountCoil,
            device.clone(),
            format!("(K{preset})"),
            format!("timer coil {device} K{preset}"),
        ),
        Element::CounterCoil { device, preset } => (
            CellKind::CountCoil,
            device.clone(),
            format!("(K{preset})"),
            format!("counter coil {device} K{preset}"),
        ),
        other => {
            let (_, words) = entry_for(other);
            let device = match other {
                Element::Pulse { device, .. } => device.as_str(),
                Element::Mov { dst, .. } | Element::Inc { dst } | Element::Dec { dst } => {
                    dst.as_str()
                }
                _ => "",
            };
            (
                CellKind::Box,
                device.to_string(),
                format!("[{words}]"),
                format!("box {words}"),
            )
        }
    };
    CellData {
        kind,
        device,
        symbol,
        words,
        ..CellData::default()
    }
}

/// A soft PLC box or a block's input below it, as a cell.
fn soft_box(e: &Element) -> Option<CellData> {
    match e {
        // A block's input wired from the network on its left: the pin named.
        Element::BoxInput { pin } => Some(CellData {
            kind: CellKind::BoxInput,
            symbol: format!("▸{pin}"),
            words: format!("box input {pin}"),
            ..CellData::default()
        }),
        Element::Block(b) | Element::OutputBlock(b) => Some(CellData {
            kind: CellKind::Box,
            symbol: format!("[{}]", b.label()),
            words: format!("box {b}"),
            watched: b.watched(),
            ..CellData::default()
        }),
        _ => None,
    }
}

/// An element in words in `lang`, as its cell says it (`coil Y00`,
/// `コイル Y00`); in English the engine's own words.
pub fn element_words(e: &Element, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => cell_words(&drawn(e), lang),
    }
}

/// A cell's words for screen readers in `lang`: what it is, and its
/// device's comment.
pub fn cell_words(c: &CellData, lang: Lang) -> String {
    let what = match (lang, c.kind) {
        (_, CellKind::Empty) => return c.kind.look_words(lang).to_string(),
        (Lang::En, _) => c.words.clone(),
        (Lang::Ja, CellKind::CountCoil) => {
            let kind = if c.device.starts_with('C') {
                "カウンタコイル"
            } else {
                "タイマコイル"
            };
            format!("{kind} {} {}", c.device, c.symbol.trim_matches(['(', ')']))
        }
        (Lang::Ja, CellKind::Box) => format!("命令 {}", c.symbol.trim_matches(['[', ']'])),
        (Lang::Ja, CellKind::BoxInput) => {
            format!("ブロック入力 {}", c.symbol.trim_start_matches('▸'))
        }
        (Lang::Ja, kind) => format!("{} {}", kind.look().words_ja, c.device),
    };
    if c.comment.is_empty() {
        what
    } else {
        format!("{what}, {}", c.comment)
    }
}

/// A cell's live state in words, after its name: its device on, and
/// whether power reaches through it (so the state is not said by colour
/// only).
pub fn live_words(on: Option<bool>, powered: Option<bool>, lang: Lang) -> String {
    let (on_w, off_w, powered_w) = match lang {
        Lang::En => ("on", "off", "powered"),
        Lang::Ja => ("オン", "オフ", "導通"),
    };
    let mut out = String::new();
    if let Some(on) = on {
        out.push_str(", ");
        out.push_str(if on { on_w } else { off_w });
    }
    if powered == Some(true) {
        out.push_str(", ");
        out.push_str(powered_w);
    }
    out
}

/// A cell's classes: `filled k-<hook>`, its links and an error.
pub fn cell_class(c: &CellData) -> String {
    let mut class = String::from("cell");
    if !c.kind.is_empty() {
        class.push_str(" filled k-");
        class.push_str(c.kind.hook());
    }
    for (has, name) in [
        (c.link_up, " link-up"),
        (c.link_down, " link-down"),
        (c.error.is_some(), " has-error"),
    ] {
        if has {
            class.push_str(name);
        }
    }
    class
}

/// Whether `at` is inside the block from `a` to `z`: cells within one
/// rung, whole rungs across several.
pub fn within(a: Cursor, z: Cursor, at: Cursor) -> bool {
    if a.rung == z.rung {
        at.rung == a.rung
            && (a.row.min(z.row)..=a.row.max(z.row)).contains(&at.row)
            && (a.col.min(z.col)..=a.col.max(z.col)).contains(&at.col)
    } else {
        (a.rung.min(z.rung)..=a.rung.max(z.rung)).contains(&at.rung)
    }
}

/// The device entry that edits `e` (Enter on a cell): its kind and text.
pub fn entry_for(e: &Element) -> (EntryKind, String) {
    let words = |w: &str, d: &str| (EntryKind::Instruction, format!("{w} {d}"));
    match e {
        Element::Wire => (EntryKind::Instruction, String::new()),
        Element::Contact { kind, device } => match kind {
            ContactKind::No => (EntryKind::Open, device.clone()),
            ContactKind::Nc => (EntryKind::Closed, device.clone()),
            ContactKind::Rising => words("LDP", device),
            ContactKind::Falling => words("LDF", device),
        },
        Element::Coil { kind, device } => match kind {
            CoilKind::Normal => (EntryKind::Coil, device.clone()),
            CoilKind::Inverted => words("STI", device),
            CoilKind::Set => words("SET", device),
            CoilKind::Reset => words("RST", device),
        },
        Element::Not => words("NOT", "").trimmed(),
        Element::Edge { falling: false } => words("R_TRIG", "").trimmed(),
        Element::Edge { falling: true } => words("F_TRIG", "").trimmed(),
        Element::Timer {
            kind,
            name,
            preset_ms,
        } => words(kind.name(), &format!("{name} {preset_ms}ms")),
        Element::Pulse { falling, device } => words(if *falling { "PLF" } else { "PLS" }, device),
        Element::TimerCoil { device, preset } | Element::CounterCoil { device, preset } => {
            words("OUT", &format!("{device} K{preset}"))
        }
        Element::Mov { src, dst } => words("MOV", &format!("{src} {dst}")),
        Element::Cmp { a, b } => words("CMP", &format!("{a} {b}")),
        Element::Inc { dst } => words("INC", dst),
        Element::Dec { dst } => words("DEC", dst),
        // The call form, which the entry reads back (`c0: CTU(PV := 10)`).
        Element::Block(b) | Element::OutputBlock(b) => (EntryKind::Instruction, b.to_string()),
        Element::BoxInput { pin } => words("PIN", pin),
    }
}

trait Trimmed {
    fn trimmed(self) -> Self;
}

impl Trimmed for (EntryKind, String) {
    fn trimmed(self) -> Self {
        (self.0, self.1.trim().to_string())
    }
}

/// Which old rung each new rung takes its view from: a rung drawn the
/// same keeps its view (so moving or inserting rungs redraws nothing
/// else), an edited rung takes the view that stood at its place (so only
/// its changed cells are redrawn), and the rest are new. Returns, for
/// each new rung, the index of the old one it reuses, if any.
pub fn reuse(old: &[&RungData], new: &[RungData]) -> Vec<Option<usize>> {
    let mut same: HashMap<&RungData, Vec<usize>> = HashMap::new();
    for (i, d) in old.iter().enumerate().rev() {
        same.entry(*d).or_default().push(i);
    }
    let mut used = vec![false; old.len()];
    let mut out: Vec<Option<usize>> = new
        .iter()
        .map(|d| {
            let i = same.get_mut(d)?.pop()?;
            used[i] = true;
            Some(i)
        })
        .collect();
    let mut spare = (0..old.len())
        .filter(|&i| !used[i])
        .collect::<Vec<_>>()
        .into_iter();
    for (i, slot) in out.iter_mut().enumerate() {
        if slot.is_some() {
            continue;
        }
        // The view that stood here, unless a same-drawn rung took it.
        if i < used.len() && !used[i] {
            used[i] = true;
            *slot = Some(i);
        }
    }
    for slot in out.iter_mut().filter(|s| s.is_none()) {
        *slot = spare
            .by_ref()
            .find(|&i| !used[i])
            .inspect(|&i| used[i] = true);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::ladder::Link;

    fn rung(cells: Vec<Vec<Option<Element>>>, links: Vec<Link>) -> Rung {
        Rung {
            comment: String::new(),
            cells,
            links,
        }
    }

    #[test]
    fn cells_carry_kind_device_comment_links_and_errors() {
        let r = rung(
            vec![
                vec![Some(Element::no("X00")), None, Some(Element::coil("Y00"))],
                vec![Some(Element::no("Y00"))],
            ],
            vec![Link { row: 0, col: 1 }],
        );
        let comments = BTreeMap::from([("X00".to_string(), "start".to_string())]);
        let errors = vec![
            (Some(Pos::new(0, 1)), "a gap".to_string()),
            (None, "no output".to_string()),
        ];
        let d = rung_data(&r, 9, &errors, &comments);
        assert_eq!((d.rows, d.cols), (3, 10));
        assert_eq!(d.cells.len(), 30);
        let at = |row: usize, col: usize| -> &CellData { &d.cells[row * 10 + col] };
        assert_eq!(at(0, 0).kind, CellKind::No);
        assert_eq!(at(0, 0).device, "X00");
        assert_eq!(at(0, 0).comment, "start");
        assert_eq!(at(0, 0).words, "normally open contact X00");
        assert_eq!(at(0, 2).kind, CellKind::Coil);
        assert!(at(0, 1).link_down && at(1, 1).link_up && !at(1, 1).link_down);
        assert_eq!(at(0, 1).error.as_deref(), Some("a gap"));
        assert_eq!(d.errors, vec!["no output".to_string()]);
        assert_eq!(at(2, 5).kind, CellKind::Empty);
    }

    #[test]
    fn boxes_read_back_as_the_words_that_made_them() {
        let mov = Element::Mov {
            src: "K50".into(),
            dst: "D00".into(),
        };
        let d = drawn(&mov);
        assert_eq!(
            (d.kind, d.symbol.as_str()),
            (CellKind::Box, "[MOV K50 D00]")
        );
        assert_eq!(
            entry_for(&mov),
            (EntryKind::Instruction, "MOV K50 D00".into())
        );
        assert_eq!(
            entry_for(&Element::Not),
            (EntryKind::Instruction, "NOT".into())
        );
        assert_eq!(
            entry_for(&Element::nc("X01")),
            (EntryKind::Closed, "X01".into())
        );
    }

    fn data(n: u8) -> RungData {
        RungData {
            comment: n.to_string(),
            ..RungData::default()
        }
    }

    #[test]
    fn unchanged_rungs_keep_their_views_when_rungs_move() {
        let old = [data(0), data(1), data(2)];
        let refs: Vec<&RungData> = old.iter().collect();
        // A rung inserted at the top: the others keep theirs, the new one
        // has no view to take.
        let new = [data(9), data(0), data(1), data(2)];
        assert_eq!(reuse(&refs, &new), vec![None, Some(0), Some(1), Some(2)]);
        // Rung 1 edited in place: it takes the view that stood there.
        let new = [data(0), data(7), data(2)];
        assert_eq!(reuse(&refs, &new), vec![Some(0), Some(1), Some(2)]);
        // Two swapped.
        let new = [data(1), data(0), data(2)];
        assert_eq!(reuse(&refs, &new), vec![Some(1), Some(0), Some(2)]);
        // One deleted.
        let new = [data(0), data(2)];
        assert_eq!(reuse(&refs, &new), vec![Some(0), Some(2)]);
    }
}

/// The power in the last scan (`data-powered`) of cell `index` of `d`:
/// an element's from `powers` (the machine's, see `engine::ladder::live`),
/// a wire's from what feeds it on its left (the rail at column 0), an
/// empty cell none. Allocates nothing: the live frame calls it for each
/// cell.
pub fn power_of(d: &RungData, powers: &[(Pos, bool)], index: usize) -> Option<bool> {
    let c = d.cells.get(index)?;
    let at = |row: usize, col: usize| d.cells.get(row * d.cols + col);
    let element = |row: usize, col: usize| {
        powers
            .iter()
            .find(|(p, _)| p.row == row && p.col == col)
            .map(|(_, on)| *on)
    };
    match c.kind {
        CellKind::Empty => None,
        CellKind::Wire => {
            let mut col = c.col;
            loop {
                if col == 0 {
                    return Some(true);
                }
                col -= 1;
                match at(c.row, col).map(|x| x.kind) {
                    Some(CellKind::Wire) => continue,
                    Some(CellKind::Empty) | None => return Some(false),
                    Some(_) => return Some(element(c.row, col).unwrap_or(false)),
                }
            }
        }
        _ => element(c.row, c.col),
    }
}

#[cfg(test)]
mod power_tests {
    use super::*;
    use engine::ladder::{Element, Rung};

    /// Every cell's power, by place.
    fn cell_power(d: &RungData, powers: &[(Pos, bool)]) -> Vec<Option<bool>> {
        (0..d.cells.len()).map(|i| power_of(d, powers, i)).collect()
    }

    #[test]
    fn wires_take_the_power_of_what_feeds_them() {
        let rung = Rung {
            cells: vec![vec![
                Some(Element::no("X00")),
                Some(Element::Wire),
                Some(Element::Wire),
                Some(Element::coil("Y00")),
            ]],
            ..Rung::default()
        };
        let d = rung_data(&rung, 3, &[], &BTreeMap::new());
        let off = cell_power(&d, &[(Pos::new(0, 0), false), (Pos::new(0, 3), false)]);
        assert_eq!(
            &off[..4],
            &[Some(false), Some(false), Some(false), Some(false)]
        );
        let on = cell_power(&d, &[(Pos::new(0, 0), true), (Pos::new(0, 3), true)]);
        assert_eq!(&on[..4], &[Some(true), Some(true), Some(true), Some(true)]);
        assert_eq!(on[4], None, "the free row's cells show nothing");
        let from_rail = Rung {
            cells: vec![vec![Some(Element::Wire), Some(Element::coil("Y00"))]],
            ..Rung::default()
        };
        let d = rung_data(&from_rail, 1, &[], &BTreeMap::new());
        assert_eq!(cell_power(&d, &[(Pos::new(0, 1), true)])[0], Some(true));
    }
}

#[cfg(test)]
#[path = "model_words_tests.rs"]
mod words_tests;
