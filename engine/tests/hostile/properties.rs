//! Property tests over the shapes that once broke the engine: deep
//! nesting, long series, extreme numbers and times, links anywhere. A
//! few dozen cases run in the normal suite; `cargo test -p engine --test
//! hostile -- --ignored` runs thousands.

use engine::avr::asm::assemble;
use engine::formats::plcopen::Document;
use engine::formats::Project;
use engine::ladder::compile::{compile, Options};
use engine::ladder::{Element, Ladder, Link, Rung};
use engine::limits::MAX_NESTING;
use engine::time::MAX_SIM_TIME;
use engine::{MachineId, SimTime};
use proptest::prelude::*;

use crate::gen::{plcopen_alternating, project, series_rung};

/// A number as the AVR assembler may be given it, extremes included.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<i64>().prop_map(|n| format!("({n})")),
        Just("(-9223372036854775807-1)".to_string()),
        Just("9223372036854775807".to_string()),
        Just("0".to_string()),
        Just("-1".to_string()),
        (0u32..300).prop_map(|d| format!("{}1{}", "(".repeat(d as usize), ")".repeat(d as usize))),
        (0u32..300).prop_map(|d| format!("{}1", "-".repeat(d as usize))),
    ]
}

fn expression() -> impl Strategy<Value = String> {
    (
        number(),
        prop::sample::select(vec!["+", "-", "*", "/"]),
        number(),
    )
        .prop_map(|(a, op, b)| format!("{a}{op}{b}"))
}

fn time_text() -> impl Strategy<Value = String> {
    (
        "[0-9]{0,25}",
        prop::option::of("[0-9]{0,12}"),
        prop::sample::select(vec!["", "ns", "us", "ms", "s", "e9", "h", " s"]),
        any::<bool>(),
    )
        .prop_map(|(whole, frac, unit, minus)| {
            let sign = if minus { "-" } else { "" };
            match frac {
                Some(f) => format!("{sign}{whole}.{f}{unit}"),
                None => format!("{sign}{whole}{unit}"),
            }
        })
}

/// A rung with links at any position, including ones far off the grid.
fn linked_rung() -> impl Strategy<Value = Rung> {
    let position = prop_oneof![
        0usize..6,
        Just(usize::MAX),
        Just(usize::MAX - 1),
        any::<usize>()
    ];
    (
        1usize..4,
        prop::collection::vec((position.clone(), position), 0..6),
    )
        .prop_map(|(width, links)| {
            let mut rung = Rung::default();
            for c in 0..width {
                rung.set(
                    engine::ladder::Pos::new(0, c),
                    Some(Element::Contact {
                        kind: engine::ladder::ContactKind::No,
                        device: "X00".into(),
                    }),
                );
            }
            rung.set(
                engine::ladder::Pos::new(0, width),
                Some(Element::coil("Y00")),
            );
            rung.links = links
                .into_iter()
                .map(|(row, col)| Link { row, col })
                .collect();
            rung
        })
}

fn check_expression(e: &str) -> Result<(), TestCaseError> {
    // Never a panic; a value or an error.
    let _ = assemble(&format!(".equ A={e}\n.db End_PLC,0,0,0\n"), 10);
    Ok(())
}

fn check_time(t: &str) -> Result<(), TestCaseError> {
    if let Ok(time) = SimTime::parse(t) {
        prop_assert!(time <= MAX_SIM_TIME, "{t} parsed past the limit");
        prop_assert!(!t.trim().starts_with('-'), "{t} parsed though negative");
    }
    Ok(())
}

fn check_depth(levels: usize) -> Result<(), TestCaseError> {
    match Document::read(&plcopen_alternating(levels))
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
    {
        Ok(ladder) => {
            prop_assert_eq!(ladder.rungs.len(), 1);
            prop_assert!(levels <= 2 * MAX_NESTING + 2, "{levels} levels imported");
        }
        Err(errors) => {
            prop_assert!(
                errors[0].error.to_string().contains("nest more than"),
                "{errors:?}"
            );
            prop_assert!(levels > MAX_NESTING, "{levels} levels refused");
        }
    }
    Ok(())
}

fn check_series(n: usize) -> Result<(), TestCaseError> {
    let json = project("avr-plc", &[series_rung(n, "R0.0", "R1.0")]);
    let p = Project::from_json(&json).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let text = compile(&p.ladder, p.machine, Options::default())
        .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
    prop_assert_eq!(text.matches("And_A").count(), n - 1);
    Ok(())
}

fn check_links(rung: Rung) -> Result<(), TestCaseError> {
    let ladder = Ladder {
        rungs: vec![rung],
        ..Ladder::default()
    };
    for m in MachineId::ALL {
        let _ = compile(&ladder, m, Options::default());
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn extreme_expressions_never_panic(e in expression()) { check_expression(&e)?; }

    #[test]
    fn any_time_text_parses_within_the_limit_or_not_at_all(t in time_text()) { check_time(&t)?; }

    #[test]
    fn deep_networks_import_or_are_refused_by_depth(levels in 1usize..400) { check_depth(levels)?; }

    #[test]
    fn long_series_compile(n in 1usize..3000) { check_series(n)?; }

    #[test]
    fn links_anywhere_never_panic(rung in linked_rung()) { check_links(rung)?; }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    #[ignore = "long run: cargo test -p engine --test hostile -- --ignored"]
    fn long_run_extreme_expressions(e in expression()) { check_expression(&e)?; }

    #[test]
    #[ignore = "long run"]
    fn long_run_times(t in time_text()) { check_time(&t)?; }

    #[test]
    #[ignore = "long run"]
    fn long_run_deep_networks(levels in 1usize..2000) { check_depth(levels)?; }

    #[test]
    #[ignore = "long run"]
    fn long_run_series(n in 1usize..20_000) { check_series(n)?; }

    #[test]
    #[ignore = "long run"]
    fn long_run_links(rung in linked_rung()) { check_links(rung)?; }
}
