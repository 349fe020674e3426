//! Which scans the timing chart shows (found by a fresh-eyes review: it
//! opened on the last 600 scans, 60 ms of a MINASEC-U, with flat traces,
//! and stayed where it was while the travel bar moved). Until the user
//! zooms, it shows everything recorded, up to the newest
//! [`AUTO_MAX_SCANS`] scans (each pixel column still shows every value its
//! scans took, so a one-scan pulse is never lost); it follows the newest
//! scan while running, and a scan travelled to outside the view brings
//! the view to it.
//! A function block's current value is named by its pin on the box
//! (`TON0.ET`, not the machine's `TON0.v`).

use engine::record::Mark;
use engine::SimTime;

use crate::editor::LadderCtx;

/// The most scans shown until the user zooms (a fast machine records a
/// million scans in a minute; every redraw reads those in view).
pub const AUTO_MAX_SCANS: u64 = 5_000;
/// What a chart read: the scans `from..=end`, its devices, the drawing's
/// revision.
pub type Read = (Mark, Mark, Vec<String>, u64);

/// The fewest scans in view.
pub const MIN_SPAN: u64 = 8;

/// Which scans are in view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// How many scans wide; `None` until the user zooms: all that was
    /// recorded, up to [`AUTO_MAX_SCANS`].
    pub span: Option<u64>,
    /// The last scan in view; `None` follows the newest.
    pub end: Option<Mark>,
}

impl Window {
    /// A new chart's: all that was recorded, following.
    pub const FOLLOW: Window = Window {
        span: None,
        end: None,
    };
}

/// The scans a chart shows until the user zooms, in a recording of
/// `first..=last`.
pub fn auto_span((first, last): (Mark, Mark)) -> u64 {
    (last.saturating_sub(first) + 1).clamp(MIN_SPAN, AUTO_MAX_SCANS)
}

/// The scans `from..=end` in view for `w`, `span` scans wide, in a
/// recording of `first..=last`, with scan `shown` travelled to: a scan
/// travelled to outside the view brings the view to it (in its middle,
/// or at its end when that is the newest scans).
pub fn in_view(
    w: Window,
    span: u64,
    (first, last): (Mark, Mark),
    shown: Option<Mark>,
) -> (Mark, Mark) {
    let span = span.max(1);
    let view = |end: Mark| {
        let end = end.clamp(first, last);
        (end.saturating_sub(span - 1).max(first), end)
    };
    let (from, end) = view(w.end.unwrap_or(last));
    match shown {
        Some(m) if m < from || m > end => view(m.saturating_add(span / 2)),
        _ => (from, end),
    }
}

/// Each function block's current value as the machine names it
/// (`TON0.v`) with the name its box shows (`TON0.ET`, `c0.CV`).
pub fn pin_names(ladder: &engine::ladder::Ladder) -> Vec<(String, String)> {
    use engine::ladder::element::Element;
    let mut out = Vec::new();
    for (_, e) in ladder.rungs.iter().flat_map(|r| r.elements()) {
        if let Element::Block(b) | Element::OutputBlock(b) = e {
            for (pin, device) in b.watched() {
                if let Some(instance) = device.strip_suffix(".v") {
                    out.push((device.clone(), format!("{instance}.{pin}")));
                }
            }
        }
    }
    out
}

/// The name a chart row shows for `device`.
pub fn row_name(pins: &[(String, String)], device: &str) -> String {
    pins.iter()
        .find(|(d, _)| d.eq_ignore_ascii_case(device))
        .map_or_else(|| device.to_string(), |(_, shown)| shown.clone())
}

/// A simulated time as people read it: seconds with two decimals, the
/// thousands set apart by a thin space (`20 320.24 s`); below a second,
/// milliseconds (`16.5 ms`).
pub fn clock(t: SimTime) -> String {
    let ns = t.as_nanos();
    if ns < 1_000_000_000 {
        let ms = ns as f64 / 1e6;
        return format!("{} ms", (ms * 10.0).round() / 10.0);
    }
    let centis = (ns + 5_000_000) / 10_000_000;
    let (whole, frac) = (centis / 100, centis % 100);
    let digits = whole.to_string();
    let mut grouped = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            grouped.push('\u{2009}');
        }
        grouped.push(c);
    }
    format!("{grouped}.{frac:02} s")
}

/// Fills rows `which`, names the machine lacks, with the plant's values
/// at `times` (issue #52: `tank.level`, `conveyor.motor`, as `hashigo
/// test` reads them; docs/plants.md "In the page"); the others stay empty.
pub fn plant_rows(
    ctx: LadderCtx,
    rows: &mut [(String, Vec<Option<i64>>)],
    times: &[SimTime],
    which: &[usize],
) {
    if which.is_empty() {
        return;
    }
    ctx.with_rig(|_, rig| {
        let Some(rig) = rig else { return };
        for (i, (name, values)) in rows.iter_mut().enumerate() {
            if which.contains(&i) {
                if let Some(v) = rig.series(name, times) {
                    *values = v;
                }
            }
        }
    });
}

/// Whether the plant coupled to the machine has a device `name`.
pub fn plant_has(ctx: LadderCtx, name: &str) -> bool {
    let mut has = false;
    ctx.with_rig(|_, rig| has = rig.as_ref().is_some_and(|r| r.series(name, &[]).is_some()));
    has
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_blocks_value_is_named_by_its_pin() {
        // The parts example: a CTU counter `c0` on its first rung.
        let ladder = engine::ladder::decompile::decompile_text(
            engine::MachineId::SoftPlc,
            include_str!("../../../../engine/programs/soft-plc/parts.il"),
            10,
        );
        let Ok(ladder) = ladder else {
            panic!("decompiles: {ladder:?}");
        };
        let pins = pin_names(&ladder);
        assert_eq!(row_name(&pins, "c0.v"), "c0.CV", "{pins:?}");
        assert_eq!(row_name(&pins, "sensor"), "sensor");
    }

    #[test]
    fn a_new_chart_shows_all_that_was_recorded_up_to_a_cap() {
        assert_eq!(auto_span((0, 2_999)), 3_000);
        assert_eq!(auto_span((500, 2_999)), 2_500);
        assert_eq!(auto_span((0, 2_000_000)), AUTO_MAX_SCANS);
        assert_eq!(auto_span((0, 0)), MIN_SPAN);
    }

    #[test]
    fn the_view_follows_the_newest_and_goes_to_a_scan_travelled_to() {
        let w = Window::FOLLOW;
        assert_eq!(in_view(w, 100, (0, 1_000), None), (901, 1_000));
        // Fewer recorded than the span: all of it.
        assert_eq!(in_view(w, 100, (0, 40), None), (0, 40));
        // Travelled into the view: it stays.
        assert_eq!(in_view(w, 100, (0, 1_000), Some(950)), (901, 1_000));
        // Travelled to before it: the view centres on the scan.
        assert_eq!(in_view(w, 100, (0, 1_000), Some(300)), (251, 350));
        // Panned away, then travelled to the newest: the view comes back.
        let panned = Window {
            span: Some(100),
            end: Some(200),
        };
        assert_eq!(in_view(panned, 100, (0, 1_000), Some(999)), (901, 1_000));
        assert_eq!(in_view(panned, 100, (0, 1_000), None), (101, 200));
    }
}
