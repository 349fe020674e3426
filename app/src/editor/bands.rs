//! The timing chart's layout in plain Rust (issue #46): a word row as
//! bands, each a stretch of pixel columns over which the value held,
//! with the value written in the band when it is wide enough; a bit row
//! as steps. The chart (`super::chart`) only draws what these return.

/// One band of a word row: pixel columns `[from, to)` over which every
/// scan had `value` (`None`: not recorded), or a stretch of columns each
/// holding several values (`busy`: the value changes faster than a
/// pixel can show).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Band {
    /// First pixel column.
    pub from: usize,
    /// One past the last pixel column.
    pub to: usize,
    /// The value held (when not busy).
    pub value: Option<i64>,
    /// Several values within each of its columns.
    pub busy: bool,
}

/// About how wide (px) a character of the band's text is drawn (0.75rem
/// monospace), and the room left at its ends.
const CHAR_PX: f64 = 7.5;
const PAD_PX: f64 = 6.0;

/// Pixel column `c` of `width` columns: its scans `[start, end)` of `n`.
pub fn column(c: usize, n: usize, width: usize) -> (usize, usize) {
    let start = c * n / width;
    let end = ((c + 1) * n / width).max(start + 1).min(n.max(1));
    (start.min(n.saturating_sub(1)), end)
}

/// A word row's bands over `width` pixel columns.
pub fn bands(values: &[Option<i64>], width: usize) -> Vec<Band> {
    let mut out: Vec<Band> = Vec::new();
    if values.is_empty() {
        return out;
    }
    for c in 0..width {
        let (start, end) = column(c, values.len(), width);
        let slice = values.get(start..end).unwrap_or(&[]);
        let Some(first) = slice.first().copied() else {
            continue;
        };
        let busy = slice.iter().any(|v| *v != first);
        let value = if busy { None } else { first };
        match out.last_mut() {
            Some(b) if b.busy == busy && b.value == value && b.to == c => b.to = c + 1,
            _ => out.push(Band {
                from: c,
                to: c + 1,
                value,
                busy,
            }),
        }
    }
    out
}

/// The text written in `band` when it is wide enough at `px_per_col`
/// pixels a column; `None` for a busy band, an unknown value, or one
/// too narrow (the value is then read at the cursor).
pub fn band_text(band: &Band, px_per_col: f64) -> Option<String> {
    if band.busy {
        return None;
    }
    let text = band.value?.to_string();
    let need = text.chars().count() as f64 * CHAR_PX + PAD_PX;
    ((band.to - band.from) as f64 * px_per_col >= need).then_some(text)
}

/// A word row's outline in a row `row` px high: each band's top and
/// bottom edges, a crossing where one value gives way to the next, a
/// filled block where it changes within columns, a middle line where
/// nothing was recorded.
pub fn word_path(bands: &[Band], row: usize) -> (String, String) {
    let (top, bot) = (5.0, row as f64 - 5.0);
    let mid = row as f64 / 2.0;
    let (mut lines, mut busy) = (String::new(), String::new());
    for (i, b) in bands.iter().enumerate() {
        let (x0, x1) = (b.from, b.to);
        if b.busy {
            busy.push_str(&format!("M{x0} {top}H{x1}V{bot}H{x0}Z"));
            continue;
        }
        match b.value {
            Some(_) => lines.push_str(&format!("M{x0} {top}H{x1}M{x0} {bot}H{x1}")),
            None => lines.push_str(&format!("M{x0} {mid}H{x1}")),
        }
        if i > 0 && b.value.is_some() {
            lines.push_str(&format!("M{x0} {top}V{bot}"));
        }
    }
    (lines, busy)
}

/// A bit row as steps over `width` pixel columns in a row `row` px high:
/// high while on, low while off, a vertical at each change, and a
/// full-height stroke in a column whose scans took both levels (a pulse
/// of one scan among thousands still shows).
pub fn bit_path(values: &[Option<i64>], width: usize, row: usize) -> String {
    let (high, low) = (4.0, row as f64 - 5.0);
    let y = |on: bool| if on { high } else { low };
    let bit = |v: &Option<i64>| v.is_some_and(|v| v != 0);
    let mut d = String::new();
    let mut level: Option<bool> = None;
    for x in 0..width {
        let (start, end) = column(x, values.len(), width);
        let slice = values.get(start..end).unwrap_or(&[]);
        let (Some(first), Some(last)) = (slice.first(), slice.last()) else {
            continue;
        };
        let (first, last) = (bit(first), bit(last));
        match level {
            None => d.push_str(&format!("M{x} {}", y(first))),
            Some(l) if l != first => d.push_str(&format!("H{x}V{}", y(first))),
            _ => {}
        }
        if slice.iter().any(|v| bit(v) != first) {
            d.push_str(&format!("H{x}V{}V{}", y(!first), y(last)));
        }
        level = Some(last);
    }
    if level.is_some() {
        d.push_str(&format!("H{width}"));
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_counters_values_are_bands_with_their_value_written_when_wide_enough() {
        // 0 for 10 scans, 1 for 10, then 2 for 180: over 200 columns.
        let mut values = vec![Some(0); 10];
        values.extend(vec![Some(1); 10]);
        values.extend(vec![Some(2); 180]);
        let b = bands(&values, 200);
        assert_eq!(
            b.iter()
                .map(|b| (b.from, b.to, b.value))
                .collect::<Vec<_>>(),
            vec![(0, 10, Some(0)), (10, 20, Some(1)), (20, 200, Some(2))]
        );
        // At two pixels a column: 20 px hold one digit, 360 px too; at
        // one, 10 px do not.
        assert_eq!(band_text(&b[0], 2.0).as_deref(), Some("0"));
        assert_eq!(band_text(&b[2], 2.0).as_deref(), Some("2"));
        assert_eq!(band_text(&b[0], 1.0), None);
        // Squeezed to a third: the 10-column bands are too narrow to write in.
        assert_eq!(band_text(&b[1], 0.3), None);
        assert_eq!(band_text(&b[2], 0.3).as_deref(), Some("2"));
        let wide = Band {
            from: 0,
            to: 20,
            value: Some(-12345),
            busy: false,
        };
        assert_eq!(band_text(&wide, 1.0), None, "six characters need 51 px");
        assert!(band_text(&wide, 3.0).is_some());
    }

    #[test]
    fn a_value_changing_within_a_column_is_a_busy_band_with_no_text() {
        let values: Vec<Option<i64>> = (0..10_000).map(|i| Some(i % 7)).collect();
        let b = bands(&values, 100);
        assert_eq!(b.len(), 1);
        assert!(b[0].busy && b[0].value.is_none());
        assert_eq!(band_text(&b[0], 50.0), None);
        let (lines, busy) = word_path(&b, 30);
        assert!(lines.is_empty() && busy.ends_with('Z'), "{busy}");
        assert!(bands(&[], 100).is_empty());
    }

    #[test]
    fn word_bands_cross_where_the_value_changes() {
        let b = bands(&[Some(3), Some(3), Some(4), None], 4);
        assert_eq!(b.len(), 3);
        let (lines, busy) = word_path(&b, 30);
        assert!(busy.is_empty());
        // The second band starts with a crossing at column 2; the unknown
        // last band is a middle line.
        assert!(lines.contains("M2 5V25"), "{lines}");
        assert!(lines.ends_with("M3 15H4"), "{lines}");
    }

    #[test]
    fn bits_are_steps_and_a_one_scan_pulse_among_thousands_still_shows() {
        let d = bit_path(&[Some(0), Some(1), Some(1), Some(0)], 8, 30);
        // Low, up at column 2, down at column 6, on to the end.
        assert_eq!(d, "M0 25H2V4H6V25H8");
        let mut values = vec![Some(0); 100_000];
        values[54_321] = Some(1);
        let d = bit_path(&values, 600, 30);
        assert_eq!(d.matches("V4").count(), 1, "{}", &d[..d.len().min(200)]);
        assert!(d.starts_with("M0 25") && d.ends_with("H600"));
        assert!(bit_path(&[], 600, 30).is_empty());
    }
}
