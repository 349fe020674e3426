//! "Why is this coil off (or on)?" on the reference evaluator: on random
//! rungs of contacts, the elements it names flip the answer exactly as it
//! says (each alone, or all together and no fewer), and none it leaves
//! out would flip it alone.

use engine::ladder::element::{ContactKind, Element};
use engine::ladder::eval::{power_flow, ElementPower, FlowState};
use engine::ladder::grid::Pos;
use engine::ladder::net::{Net, RungLogic};
use engine::ladder::why::{explain, leaf_conducts};
use engine::scan_timer::ScanTimer;
use proptest::prelude::*;

/// Each leaf reads a bit of its own, so "flip this contact" is "flip this
/// leaf's bit".
struct Bits(Vec<bool>, Vec<bool>);

impl FlowState for Bits {
    fn bit(&self, _rung: usize, leaf: usize) -> bool {
        self.0[leaf]
    }
    fn edge_memory(&mut self, _rung: usize, leaf: usize) -> &mut bool {
        &mut self.1[leaf]
    }
    fn timer(&mut self, _rung: usize, _leaf: usize) -> Option<&mut ScanTimer> {
        None
    }
}

fn contacts() -> impl Strategy<Value = Net> {
    let leaf = any::<bool>().prop_map(|nc| {
        let kind = if nc { ContactKind::Nc } else { ContactKind::No };
        let e = Element::Contact {
            kind,
            device: "X00".into(),
        };
        Net::Leaf(e, Pos::new(0, 0))
    });
    leaf.prop_recursive(4, 16, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 2..4).prop_map(Net::Series),
            prop::collection::vec(inner, 2..4).prop_map(Net::Parallel),
        ]
    })
}

/// Gives every leaf a cell of its own (row = its place).
fn number(net: &mut Net, next: &mut usize) {
    match net {
        Net::Leaf(_, p) => {
            *p = Pos::new(*next, 0);
            *next += 1;
        }
        Net::Series(v) | Net::Parallel(v) => v.iter_mut().for_each(|n| number(n, next)),
    }
}

fn rung() -> impl Strategy<Value = (RungLogic, Vec<bool>)> {
    contacts().prop_flat_map(|mut net| {
        let mut n = 0;
        number(&mut net, &mut n);
        let logic = RungLogic {
            condition: net,
            outputs: vec![(Element::coil("Y00"), Pos::new(0, 99))],
            comment: String::new(),
            sides: Vec::new(),
        };
        (Just(logic), prop::collection::vec(any::<bool>(), n))
    })
}

/// The reference evaluator's report with the leaves at `flip` changed.
fn run(logic: &RungLogic, bits: &[bool], flip: &[usize]) -> Vec<ElementPower> {
    let mut bits = bits.to_vec();
    for &i in flip {
        bits[i] = !bits[i];
    }
    let mut state = Bits(bits, vec![false; 64]);
    let mut report = Vec::new();
    power_flow(logic, 0, &mut state, 10, &mut report);
    report
}

/// The power at `target` (a leaf's right side, or the coil's input).
fn power_at(report: &[ElementPower], target: Pos) -> bool {
    report
        .iter()
        .find(|p| p.pos == target)
        .is_some_and(|p| p.power_out)
}

fn check(logic: &RungLogic, bits: &[bool], target: Pos) -> Result<(), TestCaseError> {
    let leaves = logic.condition.leaves();
    let report = run(logic, bits, &[]);
    let conducts: Vec<bool> = leaves
        .iter()
        .enumerate()
        .map(|(i, (e, _))| leaf_conducts(e, bits[i], report[i].power_in, report[i].power_out))
        .collect();
    let why = explain(logic, target, &conducts).expect("a leaf or the coil");
    let powered = power_at(&report, target);
    prop_assert_eq!(why.powered, powered, "as the reference evaluator says");
    prop_assert!(!why.causes.is_empty(), "something decides it");
    let index = |p: &Pos| leaves.iter().position(|(_, q)| q == p).expect("a leaf");
    let causes: Vec<usize> = why.causes.iter().map(index).collect();
    let flips = |set: &[usize]| power_at(&run(logic, bits, set), target) != powered;
    if why.together {
        prop_assert!(flips(&causes), "all together flip it");
        for skip in 0..causes.len() {
            let mut fewer = causes.clone();
            fewer.remove(skip);
            prop_assert!(
                !flips(&fewer),
                "no fewer would: without {:?}",
                why.causes[skip]
            );
        }
        for i in 0..leaves.len() {
            prop_assert!(!flips(&[i]), "no leaf flips it alone");
        }
    } else {
        for i in 0..leaves.len() {
            prop_assert_eq!(flips(&[i]), causes.contains(&i), "leaf {} alone", i);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { failure_persistence: None, cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn what_it_names_flips_the_coil_and_each_contact_as_it_says((logic, bits) in rung()) {
        check(&logic, &bits, Pos::new(0, 99))?;
        for (_, pos) in logic.condition.leaves() {
            check(&logic, &bits, pos)?;
        }
    }
}

fn leaf(device: &str, nc: bool, row: usize, col: usize) -> Net {
    let e = if nc {
        Element::nc(device)
    } else {
        Element::no(device)
    };
    Net::Leaf(e, Pos::new(row, col))
}

fn why_coil(net: Net, conducts: &[bool]) -> engine::ladder::why::Explanation {
    let logic = RungLogic {
        condition: net,
        outputs: vec![(Element::coil("Y00"), Pos::new(0, 9))],
        comment: String::new(),
        sides: Vec::new(),
    };
    explain(&logic, Pos::new(0, 9), conducts).expect("the coil")
}

#[test]
fn series_names_the_open_contact_or_both_together() {
    let net = || Net::Series(vec![leaf("X00", false, 0, 0), leaf("X01", false, 0, 1)]);
    let one = why_coil(net(), &[true, false]);
    assert!(!one.powered);
    assert_eq!((one.causes, one.together), (vec![Pos::new(0, 1)], false));
    let both = why_coil(net(), &[false, false]);
    assert_eq!(both.causes, vec![Pos::new(0, 0), Pos::new(0, 1)]);
    assert!(both.together, "neither alone would power it");
    let on = why_coil(net(), &[true, true]);
    assert!(on.powered && !on.together, "either contact alone cuts it");
    assert_eq!(on.causes.len(), 2);
}

#[test]
fn parallel_names_each_branch_that_alone_would_power_it() {
    let net = Net::Parallel(vec![leaf("X00", false, 0, 0), leaf("X01", false, 1, 0)]);
    let off = why_coil(net.clone(), &[false, false]);
    assert!(!off.powered && !off.together, "any one branch would do");
    assert_eq!(off.causes.len(), 2);
    let on = why_coil(net, &[true, true]);
    assert!(on.powered && on.together, "both branches carry it");
}

#[test]
fn a_latch_is_held_by_its_own_contact_and_the_stop_button() {
    // X00 (start) or Y00 (self-hold), then NC X01 (stop), into Y00.
    let net = Net::Series(vec![
        Net::Parallel(vec![leaf("X00", false, 0, 0), leaf("Y00", false, 1, 0)]),
        leaf("X01", true, 0, 1),
    ]);
    // Started and released: X00 off, Y00 on, X01 off (the NC conducts).
    let held = why_coil(net.clone(), &[false, true, true]);
    assert!(held.powered && !held.together);
    assert_eq!(
        held.causes,
        vec![Pos::new(0, 1), Pos::new(1, 0)],
        "stop and self-hold"
    );
    // Stop pressed: the NC X01 blocks, alone.
    let stopped = why_coil(net, &[false, true, false]);
    assert!(!stopped.powered);
    assert_eq!(stopped.causes, vec![Pos::new(0, 1)]);
}
