//! The timing chart's data: bits or bands, the CSV export, the clock.

use super::*;

#[test]
fn rows_are_bits_only_when_every_value_is_0_or_1() {
    let values = [Some(0), Some(1), Some(1), Some(0)];
    assert_eq!(rises(&values), 1);
    assert!(is_bits(&values));
    assert!(!is_bits(&[Some(5)]));
}

#[test]
fn the_export_is_a_csv_of_the_scans_in_view() {
    let d = ChartData {
        from: 3,
        times: vec![SimTime::from_millis(10), SimTime::from_millis(20)],
        rows: vec![
            ("Y00".into(), vec![Some(0), Some(1)]),
            ("D00".into(), vec![None, Some(-7)]),
        ],
    };
    let csv = csv_of(&d);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "time_ms,Y00,D00");
    assert_eq!(lines.len(), 3);
    assert!(lines[1].ends_with(",0,"), "{csv}");
    assert!(lines[2].ends_with(",1,-7"), "{csv}");
}

#[test]
fn times_read_as_seconds_with_their_thousands_apart() {
    assert_eq!(
        clock(SimTime::from_nanos(20_320_240_471_743)),
        "20\u{2009}320.24 s"
    );
    assert_eq!(clock(SimTime::from_millis(1_500)), "1.50 s");
    assert_eq!(clock(SimTime::from_micros(16_500)), "16.5 ms");
    assert_eq!(clock(SimTime::ZERO), "0 ms");
}
