//! The ladder as a picture: SVG drawn from the same rung drawings the
//! screen shows (`model::RungData`), comments included. Every text from
//! the project is escaped. The PNG is this SVG rendered by the browser.

use std::fmt::Write as _;

use crate::editor::model::{CellData, RungData};

const CELL_W: usize = 80;
const CELL_H: usize = 48;
const HEAD_W: usize = 72;
const COMMENT_H: usize = 16;
const GAP: usize = 8;

/// XML-escapes `text` for an SVG text node or attribute.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// The rungs as an SVG document: number, first step, comment, cells,
/// links and the two rails; the free row each rung shows on screen is
/// left out.
pub fn svg(rungs: &[(usize, Option<usize>, &RungData)]) -> String {
    let rows_of = |d: &RungData| d.rows.saturating_sub(1).max(1);
    let width = HEAD_W
        + rungs
            .iter()
            .map(|(_, _, d)| d.cols * CELL_W)
            .max()
            .unwrap_or(CELL_W * 10)
        + 2 * GAP;
    let height: usize = rungs
        .iter()
        .map(|(_, _, d)| {
            rows_of(d) * CELL_H + GAP + if d.comment.is_empty() { 0 } else { COMMENT_H }
        })
        .sum::<usize>()
        + GAP;
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\" font-family=\"monospace\" font-size=\"11\">\
         <rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>"
    );
    let mut y = GAP;
    for (number, first_step, d) in rungs {
        if !d.comment.is_empty() {
            let _ = write!(
                s,
                "<text x=\"{}\" y=\"{}\" fill=\"#2d6a4f\">{}</text>",
                HEAD_W,
                y + 11,
                escape(&d.comment)
            );
            y += COMMENT_H;
        }
        let rows = rows_of(d);
        let _ = write!(
            s,
            "<text x=\"4\" y=\"{}\" font-weight=\"bold\">{}</text>",
            y + 14,
            number + 1
        );
        if let Some(step) = first_step {
            let _ = write!(
                s,
                "<text x=\"4\" y=\"{}\" fill=\"#555\">{step}</text>",
                y + 28
            );
        }
        let right = HEAD_W + d.cols * CELL_W;
        let bottom = y + rows * CELL_H;
        let _ = write!(
            s,
            "<line x1=\"{HEAD_W}\" y1=\"{y}\" x2=\"{HEAD_W}\" y2=\"{bottom}\" stroke=\"#000\" stroke-width=\"3\"/>\
             <line x1=\"{right}\" y1=\"{y}\" x2=\"{right}\" y2=\"{bottom}\" stroke=\"#000\" stroke-width=\"3\"/>"
        );
        for c in d.cells.iter().filter(|c| c.row < rows) {
            cell(&mut s, c, HEAD_W + c.col * CELL_W, y + c.row * CELL_H);
        }
        y = bottom + GAP;
    }
    s.push_str("</svg>\n");
    s
}

fn cell(s: &mut String, c: &CellData, x: usize, y: usize) {
    let mid = y + CELL_H / 2;
    if c.link_down {
        let _ = write!(s, "<line x1=\"{x}\" y1=\"{mid}\" x2=\"{x}\" y2=\"{}\" stroke=\"#000\" stroke-width=\"2\"/>", y + CELL_H);
    }
    if c.link_up {
        let _ = write!(s, "<line x1=\"{x}\" y1=\"{y}\" x2=\"{x}\" y2=\"{mid}\" stroke=\"#000\" stroke-width=\"2\"/>");
    }
    if c.kind.is_empty() {
        return;
    }
    let _ = write!(
        s,
        "<line x1=\"{x}\" y1=\"{mid}\" x2=\"{}\" y2=\"{mid}\" stroke=\"#000\" stroke-width=\"2\"/>",
        x + CELL_W
    );
    if c.kind == crate::editor::model::CellKind::Wire {
        return;
    }
    let cx = x + CELL_W / 2;
    let _ = write!(
        s,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"16\" fill=\"#ffffff\"/>\
         <text x=\"{cx}\" y=\"{}\" text-anchor=\"middle\" font-weight=\"bold\">{}</text>",
        cx - c.symbol.chars().count() * 4,
        mid - 8,
        c.symbol.chars().count() * 8,
        mid + 4,
        escape(&c.symbol)
    );
    if !c.device.is_empty() {
        let _ = write!(
            s,
            "<text x=\"{cx}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            y + 11,
            escape(&c.device)
        );
    }
    if !c.comment.is_empty() {
        let _ = write!(
            s,
            "<text x=\"{cx}\" y=\"{}\" text-anchor=\"middle\" font-size=\"9\" fill=\"#2d6a4f\">{}</text>",
            y + CELL_H - 3,
            escape(&c.comment)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::editor::model::rung_data;
    use engine::ladder::{Element, Link, Rung};
    use std::collections::BTreeMap;

    #[test]
    fn the_picture_holds_every_element_and_escapes_the_projects_text() {
        let rung = Rung {
            comment: "<script>alert(1)</script> & more".into(),
            cells: vec![
                vec![Some(Element::no("X00")), Some(Element::coil("Y00"))],
                vec![Some(Element::no("Y00"))],
            ],
            links: vec![Link { row: 0, col: 1 }],
        };
        let comments = BTreeMap::from([("X00".to_string(), "start \"now\"".to_string())]);
        let d = rung_data(&rung, 9, &[], &comments);
        let svg = svg(&[(0, Some(0), &d)]);
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert!(!svg.contains("<script>"), "{svg}");
        assert!(svg.contains("&lt;script&gt;alert(1)&lt;/script&gt; &amp; more"));
        assert!(svg.contains("start &quot;now&quot;"));
        assert_eq!(svg.matches(">X00<").count(), 1);
        assert_eq!(svg.matches(">Y00<").count(), 2, "the coil and the contact");
        assert!(svg.contains("┤ ├") && svg.contains("( )"));
        // The free row is not drawn: two rows of 48 px, no third.
        assert_eq!(d.rows, 3);
        assert!(
            svg.contains("y2=\"120\""),
            "rails end after two rows: {svg}"
        );
        assert!(!svg.contains("y2=\"168\""), "{svg}");
    }
}
