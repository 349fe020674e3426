use super::*;

const MS: i64 = 1_000_000;

/// Calls `step` at 0, 10, 20 … ms with the input `input(t_ms)` until
/// `end_ms`, and returns (t, q, et) at each call.
fn timeline(
    end_ms: i64,
    input: impl Fn(i64) -> bool,
    mut step: impl FnMut(bool, i64) -> (bool, i64),
) -> Vec<(i64, bool, i64)> {
    (0..=end_ms / 10)
        .map(|k| {
            let t = k * 10;
            let (q, et) = step(input(t), t * MS);
            (t, q, et / MS)
        })
        .collect()
}

fn at(line: &[(i64, bool, i64)], t: i64) -> (bool, i64) {
    let &(_, q, et) = line.iter().find(|(u, _, _)| *u == t).expect("a call at t");
    (q, et)
}

#[test]
fn ton_comes_on_after_pt_and_off_with_in() {
    let mut ton = Ton::default();
    let line = timeline(
        400,
        |t| (100..300).contains(&t),
        |i, now| {
            ton.call(i, 100 * MS, now);
            (ton.q, ton.et)
        },
    );
    assert_eq!(at(&line, 90), (false, 0));
    assert_eq!(at(&line, 150), (false, 50));
    assert_eq!(at(&line, 200), (true, 100));
    assert_eq!(at(&line, 290), (true, 100), "ET stops at PT");
    assert_eq!(at(&line, 300), (false, 0));
}

#[test]
fn tof_holds_q_for_pt_after_in_goes_off() {
    let mut tof = Tof::default();
    let line = timeline(
        500,
        |t| (100..200).contains(&t),
        |i, now| {
            tof.call(i, 150 * MS, now);
            (tof.q, tof.et)
        },
    );
    assert_eq!(at(&line, 50), (false, 0), "never on: nothing to hold");
    assert_eq!(at(&line, 100), (true, 0));
    assert_eq!(at(&line, 250), (true, 50));
    assert_eq!(at(&line, 340), (true, 140));
    assert_eq!(at(&line, 350), (false, 150));
    assert_eq!(at(&line, 500), (false, 150), "ET stays at PT");
}

#[test]
fn tp_gives_one_pulse_of_pt_however_in_moves() {
    let mut tp = Tp::default();
    // IN on 100-130, again 150-170 (inside the pulse), again 400-500.
    let line = timeline(
        600,
        |t| (100..130).contains(&t) || (150..170).contains(&t) || (400..500).contains(&t),
        |i, now| {
            tp.call(i, 200 * MS, now);
            (tp.q, tp.et)
        },
    );
    assert_eq!(at(&line, 100), (true, 0));
    assert_eq!(at(&line, 160), (true, 60), "not restarted inside the pulse");
    assert_eq!(at(&line, 290), (true, 190));
    assert_eq!(at(&line, 300), (false, 0), "over, IN off: ready");
    assert_eq!(at(&line, 400), (true, 0));
    assert_eq!(at(&line, 600), (false, 0));
    // IN held past the pulse: ET holds PT until IN goes off.
    let mut held = Tp::default();
    held.call(true, 50 * MS, 0);
    held.call(true, 50 * MS, 80 * MS);
    assert_eq!((held.q, held.et), (false, 50 * MS));
    held.call(false, 50 * MS, 90 * MS);
    assert_eq!((held.q, held.et), (false, 0));
}

#[test]
fn counters_count_edges_and_stop_at_ints_limits() {
    let mut ctu = Ctu::default();
    for _ in 0..3 {
        ctu.call(true, false, 3);
        ctu.call(true, false, 3); // held: no second count
        ctu.call(false, false, 3);
    }
    assert_eq!((ctu.cv, ctu.q), (3, true));
    ctu.call(true, true, 3);
    assert_eq!((ctu.cv, ctu.q), (0, false), "R clears, and wins over CU");
    ctu.cv = COUNT_MAX;
    ctu.call(false, false, 3);
    ctu.call(true, false, 3);
    assert_eq!(ctu.cv, COUNT_MAX);

    let mut ctd = Ctd::default();
    ctd.call(false, true, 2);
    assert_eq!((ctd.cv, ctd.q), (2, false));
    for _ in 0..2 {
        ctd.call(true, false, 2);
        ctd.call(false, false, 2);
    }
    assert_eq!((ctd.cv, ctd.q), (0, true));

    let mut ctud = Ctud::default();
    ctud.call(true, false, false, false, 2);
    ctud.call(false, false, false, false, 2);
    ctud.call(true, true, false, false, 2);
    assert_eq!(ctud.cv, 1, "CU and CD rising together: no change");
    ctud.call(false, false, false, true, 5);
    assert_eq!((ctud.cv, ctud.qu, ctud.qd), (5, true, false));
    ctud.call(false, false, true, true, 5);
    assert_eq!(
        (ctud.cv, ctud.qu, ctud.qd),
        (0, false, true),
        "R wins over LD"
    );
}

#[test]
fn edges_and_bistables() {
    let mut r = RTrig::default();
    let mut f = FTrig::default();
    let mut seen = Vec::new();
    for clk in [false, true, true, false, false, true] {
        r.call(clk);
        f.call(clk);
        seen.push((r.q, f.q));
    }
    assert_eq!(
        seen,
        [
            (false, false),
            (true, false),
            (false, false),
            (false, true),
            (false, false),
            (true, false)
        ]
    );
    let mut sr = Sr::default();
    sr.call(true, true);
    assert!(sr.q1, "SR: set wins");
    let mut rs = Rs::default();
    rs.call(true, true);
    assert!(!rs.q1, "RS: reset wins");
    rs.call(true, false);
    rs.call(false, false);
    assert!(rs.q1, "it holds");
}
