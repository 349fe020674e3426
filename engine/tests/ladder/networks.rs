//! Random LD and FBD networks of contacts and boolean blocks, written as
//! another tool would (issues #18, #24): inputs shared between blocks,
//! contacts after block outputs, blocks after blocks, drawn anywhere on the
//! page, their elements in any order. Each, imported for IO86A (and,
//! without counters, for the AVR PLC and MINASEC-U), must light its coils
//! as the network says in the very scan its inputs change (MINASEC-U: the
//! scan after, its inputs being latched at a scan's end): a lowering that
//! joins what it must not, or a rung that reads a spare relay before it is
//! written, shows here. A coil may join several wires (their OR).

use engine::events::InputValue;
use engine::formats::plcopen::VarMap;
use engine::plc::{Command, Plc};
use engine::MachineId;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// One element of the network; inputs name earlier elements (0-3 are
/// the contacts X00-X03 from the rail).
#[derive(Clone, Debug)]
enum Node {
    /// A contact of X0n after the wires of elements `from` joined,
    /// negated or not.
    Contact {
        input: u8,
        from: Vec<usize>,
        negated: bool,
    },
    And(Vec<usize>),
    Or(Vec<usize>),
    Xor(usize, usize),
    Not(usize),
    /// R_TRIG (or F_TRIG) of element `from`.
    Trig {
        from: usize,
        falling: bool,
    },
    /// SR (set wins) or RS of elements `set` and `reset`.
    Flip {
        set: usize,
        reset: usize,
        set_wins: bool,
    },
    /// A counter: CTU (count, R, Q), CTD (count, LD, Q) or CTUD (CU, R;
    /// QU, or QD with `empty`), preset `pv`; `other` is R or LD, open
    /// when `None`.
    Count {
        kind: Counter,
        count: usize,
        other: Option<usize>,
        pv: u8,
        empty: bool,
    },
}

#[derive(Clone, Copy, Debug)]
enum Counter {
    Ctu,
    Ctd,
    Ctud,
}

impl Counter {
    /// Its block type, counting pin and second pin (R or LD).
    fn pins(self) -> (&'static str, &'static str, &'static str) {
        match self {
            Counter::Ctu => ("CTU", "CU", "R"),
            Counter::Ctd => ("CTD", "CD", "LD"),
            Counter::Ctud => ("CTUD", "CU", "R"),
        }
    }
}

/// A flip-flop's block type.
fn flip_type(set_wins: bool) -> &'static str {
    if set_wins {
        "SR"
    } else {
        "RS"
    }
}

/// The network: its elements after the four rail contacts, each with a
/// row to be drawn at, and the elements whose wires each coil Y00-Y03
/// joins.
#[derive(Clone, Debug)]
struct Network {
    nodes: Vec<(Node, u32)>,
    coils: Vec<Vec<usize>>,
}

/// Random networks; `counters`: with CTU / CTD / CTUD blocks (the AVR
/// PLC has no counters).
fn network(counters: bool) -> impl Strategy<Value = Network> {
    (1usize..8).prop_flat_map(move |n| {
        let nodes: Vec<BoxedStrategy<(Node, u32)>> = (0..n)
            .map(|i| {
                let before = 4 + i;
                let pick = 0..before;
                let mut kinds: Vec<BoxedStrategy<Node>> = vec![
                    (
                        0u8..4,
                        prop::collection::vec(pick.clone(), 1..3),
                        any::<bool>(),
                    )
                        .prop_map(|(input, from, negated)| Node::Contact {
                            input,
                            from,
                            negated,
                        })
                        .boxed(),
                    prop::collection::vec(pick.clone(), 2..4)
                        .prop_map(Node::And)
                        .boxed(),
                    prop::collection::vec(pick.clone(), 2..4)
                        .prop_map(Node::Or)
                        .boxed(),
                    (pick.clone(), pick.clone())
                        .prop_map(|(a, b)| Node::Xor(a, b))
                        .boxed(),
                    pick.clone().prop_map(Node::Not).boxed(),
                    (pick.clone(), any::<bool>())
                        .prop_map(|(from, falling)| Node::Trig { from, falling })
                        .boxed(),
                    (pick.clone(), pick.clone(), any::<bool>())
                        .prop_map(|(set, reset, set_wins)| Node::Flip {
                            set,
                            reset,
                            set_wins,
                        })
                        .boxed(),
                ];
                if counters {
                    kinds.push(
                        (
                            prop_oneof![
                                Just(Counter::Ctu),
                                Just(Counter::Ctd),
                                Just(Counter::Ctud)
                            ],
                            pick.clone(),
                            prop::option::of(pick),
                            1u8..4,
                            any::<bool>(),
                        )
                            .prop_map(|(kind, count, other, pv, empty)| Node::Count {
                                kind,
                                count,
                                other,
                                pv,
                                empty,
                            })
                            .boxed(),
                    );
                }
                (proptest::strategy::Union::new(kinds), 0u32..40).boxed()
            })
            .collect();
        let coils = prop::collection::vec(prop::collection::vec(0..4 + n, 1..3), 1..5);
        (nodes, coils).prop_map(|(nodes, coils)| Network { nodes, coils })
    })
}

impl Network {
    /// Each element's power for inputs `x` (bit n is X0n), one scan on
    /// from `state` (each edge's or counter's last input, each
    /// flip-flop's output) and `counts` (each counter's CV), which it
    /// updates.
    fn values(&self, x: u8, state: &mut [bool], counts: &mut [i32]) -> Vec<bool> {
        let mut v: Vec<bool> = (0..4).map(|n| x & (1 << n) != 0).collect();
        for (k, (node, _)) in self.nodes.iter().enumerate() {
            let value = match node {
                Node::Contact {
                    input,
                    from,
                    negated,
                } => from.iter().any(|&i| v[i]) && ((x & (1 << input) != 0) != *negated),
                Node::And(ins) => ins.iter().all(|&i| v[i]),
                Node::Or(ins) => ins.iter().any(|&i| v[i]),
                Node::Xor(a, b) => v[*a] != v[*b],
                Node::Not(a) => !v[*a],
                Node::Trig { from, falling } => {
                    let (now, before) = (v[*from], state[k]);
                    state[k] = now;
                    if *falling {
                        before && !now
                    } else {
                        now && !before
                    }
                }
                Node::Flip {
                    set,
                    reset,
                    set_wins,
                } => {
                    let (s, r, q) = (v[*set], v[*reset], state[k]);
                    state[k] = if *set_wins {
                        s || (q && !r)
                    } else {
                        !r && (s || q)
                    };
                    state[k]
                }
                Node::Count {
                    kind,
                    count,
                    other,
                    pv,
                    empty,
                } => {
                    let rose = v[*count] && !state[k];
                    state[k] = v[*count];
                    let other = other.is_some_and(|o| v[o]);
                    let pv = i32::from(*pv);
                    let cv = &mut counts[k];
                    match kind {
                        Counter::Ctd if other => *cv = pv,
                        Counter::Ctd if rose => *cv -= 1,
                        Counter::Ctd => {}
                        _ if other => *cv = 0,
                        _ if rose => *cv += 1,
                        _ => {}
                    }
                    match kind {
                        Counter::Ctd => *cv <= 0,
                        Counter::Ctud if *empty => *cv <= 0,
                        _ => *cv >= pv,
                    }
                }
            };
            v.push(value);
        }
        v
    }

    /// One connection list joining the outputs of elements `from`.
    fn joined(&self, from: &[usize], fbd: bool) -> String {
        let wires: Vec<String> = from.iter().map(|&i| self.from(i, fbd)).collect();
        wires
            .join("")
            .replace("</connectionPointIn><connectionPointIn>", "")
    }

    /// The connection to element `i`'s output (in FBD a contact is an
    /// AND block).
    fn from(&self, i: usize, fbd: bool) -> String {
        let pin = match i.checked_sub(4).map(|k| &self.nodes[k].0) {
            Some(Node::And(_) | Node::Or(_) | Node::Xor(..) | Node::Not(_)) => {
                r#" formalParameter="OUT""#
            }
            Some(Node::Contact { .. }) if fbd => r#" formalParameter="OUT""#,
            Some(Node::Trig { .. }) => r#" formalParameter="Q""#,
            Some(Node::Flip { .. }) => r#" formalParameter="Q1""#,
            Some(Node::Count {
                kind: Counter::Ctud,
                empty,
                ..
            }) => {
                if *empty {
                    r#" formalParameter="QD""#
                } else {
                    r#" formalParameter="QU""#
                }
            }
            Some(Node::Count { .. }) => r#" formalParameter="Q""#,
            _ => "",
        };
        format!(
            r#"<connectionPointIn><connection refLocalId="{}"{pin}/></connectionPointIn>"#,
            10 + i
        )
    }

    /// The network as PLCopen XML drawn as `layout` says: an LD body
    /// (rail, contacts, coils) or an FBD one (variable boxes, a contact
    /// after joined wires as an AND of them with its variable), its
    /// elements written in the order given.
    fn xml(&self, layout: &Layout) -> String {
        let fbd = layout.fbd;
        let mut elements: Vec<String> = Vec::new();
        if !fbd {
            elements.push(
                r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut/></leftPowerRail>"#.to_string(),
            );
        }
        for n in 0..4 {
            elements.push(if fbd {
                format!(
                    r#"<inVariable localId="{}"><position x="10" y="{}"/><connectionPointOut/><expression>X0{n}</expression></inVariable>"#,
                    10 + n,
                    n * 10
                )
            } else {
                format!(
                    r#"<contact localId="{}"><position x="10" y="{}"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>X0{n}</variable></contact>"#,
                    10 + n,
                    n * 10
                )
            });
        }
        let pins = |ins: &[usize]| -> String {
            ins.iter()
                .enumerate()
                .map(|(k, &i)| {
                    format!(
                        r#"<variable formalParameter="IN{}">{}</variable>"#,
                        k + 1,
                        self.from(i, fbd)
                    )
                })
                .collect()
        };
        for (k, (node, row)) in self.nodes.iter().enumerate() {
            let id = 14 + k;
            let (x, y) = (20 + 10 * k, row * 10);
            let named = |ty: &str, ins: String, out: &str| {
                format!(
                    r#"<block localId="{id}" typeName="{ty}" instanceName="{ty}{k}"><position x="{x}" y="{y}"/><inputVariables>{ins}</inputVariables><outputVariables><variable formalParameter="{out}"><connectionPointOut/></variable></outputVariables></block>"#
                )
            };
            let block = |ty: &str, ins: String| named(ty, ins, "OUT");
            let pin = |name: &str, i: usize| {
                format!(
                    r#"<variable formalParameter="{name}">{}</variable>"#,
                    self.from(i, fbd)
                )
            };
            match node {
                Node::Contact {
                    input,
                    from,
                    negated,
                } if fbd => {
                    let var = 700 + k;
                    elements.push(format!(
                        r#"<inVariable localId="{var}" negated="{negated}"><position x="{x}" y="{}"/><connectionPointOut/><expression>X0{input}</expression></inVariable>"#,
                        y + 5
                    ));
                    let ins = format!(
                        r#"<variable formalParameter="IN1">{}</variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{var}"/></connectionPointIn></variable>"#,
                        self.joined(from, fbd)
                    );
                    elements.push(block("AND", ins));
                }
                Node::Contact {
                    input,
                    from,
                    negated,
                } => elements.push(format!(
                    r#"<contact localId="{id}" negated="{negated}"><position x="{x}" y="{y}"/>{}<variable>X0{input}</variable></contact>"#,
                    self.joined(from, fbd)
                )),
                Node::And(ins) => elements.push(block("AND", pins(ins))),
                Node::Or(ins) => elements.push(block("OR", pins(ins))),
                Node::Xor(a, b) => elements.push(block("XOR", pins(&[*a, *b]))),
                Node::Not(a) => elements.push(block("NOT", pin("IN", *a))),
                Node::Trig { from, falling } => {
                    let ty = if *falling { "F_TRIG" } else { "R_TRIG" };
                    elements.push(named(ty, pin("CLK", *from), "Q"));
                }
                Node::Flip {
                    set,
                    reset,
                    set_wins,
                } => {
                    let (s, r) = if *set_wins { ("S1", "R") } else { ("S", "R1") };
                    elements.push(named(
                        flip_type(*set_wins),
                        pin(s, *set) + &pin(r, *reset),
                        "Q1",
                    ));
                }
                Node::Count {
                    kind,
                    count,
                    other,
                    pv,
                    ..
                } => {
                    let (ty, count_pin, other_pin) = kind.pins();
                    let pv_id = 500 + k;
                    let mut ins = pin(count_pin, *count);
                    if let Some(o) = other {
                        ins += &pin(other_pin, *o);
                    }
                    ins += &format!(
                        r#"<variable formalParameter="PV"><connectionPointIn><connection refLocalId="{pv_id}"/></connectionPointIn></variable>"#
                    );
                    let outs = if matches!(kind, Counter::Ctud) {
                        "QU"
                    } else {
                        "Q"
                    };
                    elements.push(format!(
                        r#"<inVariable localId="{pv_id}"><position x="{x}" y="{y}"/><connectionPointOut/><expression>{pv}</expression></inVariable>"#
                    ));
                    elements.push(named(ty, ins, outs).replace(
                        "</outputVariables>",
                        r#"<variable formalParameter="QD"><connectionPointOut/></variable></outputVariables>"#,
                    ));
                }
            }
        }
        for (c, on) in self.coils.iter().enumerate() {
            let joined = self.joined(on, fbd);
            elements.push(if fbd {
                format!(
                    r#"<outVariable localId="{}"><position x="200" y="{}"/>{joined}<expression>Y0{c}</expression></outVariable>"#,
                    100 + c,
                    c * 10,
                )
            } else {
                format!(
                    r#"<coil localId="{}"><position x="200" y="{}"/>{joined}<variable>Y0{c}</variable></coil>"#,
                    100 + c,
                    c * 10,
                )
            });
        }
        layout.order.apply(&mut elements);
        let language = if fbd { "FBD" } else { "LD" };
        format!(
            r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201"><types><pous><pou name="main" pouType="program"><body><{language}>
{}
</{language}></body></pou></pous></types></project>"#,
            elements.join("\n")
        )
    }
}

/// How a network is written: its body's language and the order of its
/// elements (the import must not depend on either).
#[derive(Clone, Debug)]
struct Layout {
    fbd: bool,
    order: Order,
}

/// The order a body's elements are written in.
#[derive(Clone, Debug)]
enum Order {
    /// Each element after those it reads, the rail first.
    Written,
    /// Each element before those it reads.
    Reversed,
    /// Shuffled by these keys (an element's key is `keys[i % len]` mixed
    /// with its index).
    Shuffled(Vec<u32>),
}

impl Order {
    fn apply(&self, elements: &mut Vec<String>) {
        match self {
            Order::Written => {}
            Order::Reversed => elements.reverse(),
            Order::Shuffled(keys) => {
                let mut keyed: Vec<(u64, String)> = std::mem::take(elements)
                    .into_iter()
                    .enumerate()
                    .map(|(i, e)| {
                        let k = u64::from(keys[i % keys.len()]);
                        ((k << 20 | i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15), e)
                    })
                    .collect();
                keyed.sort_by_key(|(k, _)| *k);
                elements.extend(keyed.into_iter().map(|(_, e)| e));
            }
        }
    }
}

fn layout() -> impl Strategy<Value = Layout> {
    let order = prop_oneof![
        Just(Order::Written),
        Just(Order::Reversed),
        prop::collection::vec(any::<u32>(), 1..16).prop_map(Order::Shuffled),
    ];
    (any::<bool>(), order).prop_map(|(fbd, order)| Layout { fbd, order })
}

/// A machine loaded with a program, and the program's text.
type Loaded = Result<(Box<dyn Plc>, String), String>;

/// A machine the networks run on: the devices their inputs X0n, coils
/// Y0c and flip-flop relays stand for there, and how a network's XML is
/// imported, compiled and loaded on it.
struct Target {
    /// Whether a scan sees the inputs latched at the end of the one
    /// before (MINASEC-U): a change shows a scan later.
    latched: bool,
    /// Refusals it may make, for what it lacks (as `{:?}` prints them).
    may_refuse: &'static [&'static str],
    input: fn(usize) -> String,
    coil: fn(usize) -> String,
    relay: fn(usize) -> String,
    load: fn(&str, &VarMap) -> Loaded,
}

const IO86A: Target = Target {
    latched: false,
    may_refuse: &[],
    input: |n| format!("X0{n}"),
    coil: |c| format!("Y0{c}"),
    relay: |k| format!("M{}", 10 + k),
    load: |xml, map| {
        crate::gates::io86a_loaded(xml, map).map(|(m, text)| (Box::new(m) as Box<dyn Plc>, text))
    },
};

/// The AVR PLC's bits: inputs R4.n, coils R5.c, relays R6.k.
const AVR: Target = Target {
    latched: false,
    may_refuse: &[],
    input: |n| format!("R4.{n}"),
    coil: |c| format!("R5.{c}"),
    relay: |k| format!("R6.{k}"),
    load: |xml, map| {
        crate::gates::avr_loaded(xml, map).map(|(m, text)| (Box::new(m) as Box<dyn Plc>, text))
    },
};

/// MINASEC-U's bits: inputs X0n, coils Y0c, relays M0k (its spare
/// relays are M10-M13 and the rest of M00-M07).
const MINASEC: Target = Target {
    latched: true,
    // Twelve relays in all: a network may need more than it has.
    may_refuse: &[
        "temporary relays than are free",
        "NoRelay",
        "has no edge contacts",
    ],
    input: |n| format!("X0{n}"),
    coil: |c| format!("Y0{c}"),
    relay: |k| format!("M0{k}"),
    load: |xml, map| {
        let imported = engine::formats::plcopen::Document::read(xml)
            .and_then(|document| document.import(Some(MachineId::MinasecU), Some(map), None))
            .map_err(|e| format!("{e:?}"))?;
        let text = engine::ladder::compile::compile(
            &imported.ladder,
            MachineId::MinasecU,
            Default::default(),
        )
        .map_err(|e| format!("{e:?}"))?;
        let mut m: Box<dyn Plc> = Box::new(engine::machines::MinasecPlc::new());
        m.load_text(&text).map_err(|e| format!("{e:?}"))?;
        Ok((m, text))
    },
};

/// Imports, compiles and runs `net` on `target`: after each input
/// change, one scan, and every coil must already show the network's
/// value.
fn check(
    net: &Network,
    layout: &Layout,
    inputs: &[u8],
    target: &Target,
) -> Result<(), TestCaseError> {
    let mut xml = net.xml(layout);
    for n in 0..4 {
        let (x, y) = (format!(">X0{n}<"), format!(">Y0{n}<"));
        xml = xml.replace(&x, &format!(">{}<", (target.input)(n)));
        xml = xml.replace(&y, &format!(">{}<", (target.coil)(n)));
    }
    // Each flip-flop's relay (M10 on, or R6.k); each counter's: C0k.
    let map = VarMap::from_pairs(net.nodes.iter().enumerate().filter_map(|(k, (node, _))| {
        // Instances are named type and index, as `xml` writes them.
        Some(match node {
            Node::Flip { set_wins, .. } => {
                (format!("{}{k}", flip_type(*set_wins)), (target.relay)(k))
            }
            Node::Count { kind, .. } => (format!("{}{k}", kind.pins().0), format!("C0{k}")),
            _ => return None,
        })
    }));
    let loaded = (target.load)(&xml, &map);
    // A contact after joined wires can make a network no series-parallel
    // ladder draws without copying part of it (a bridge: the wire of a
    // contact that also feeds a later join); the import refuses that at
    // its line, which is fine. Everything else must import.
    let joins_into_a_contact = net
        .nodes
        .iter()
        .any(|(n, _)| matches!(n, Node::Contact { from, .. } if from.len() > 1));
    let loaded = match loaded {
        Err(e) if joins_into_a_contact && is_only_bridges(&e) => return Ok(()),
        Err(e) if target.may_refuse.iter().any(|why| e.contains(why)) => return Ok(()),
        other => other,
    };
    let (mut m, text) = loaded.map_err(|e| TestCaseError::fail(format!("{e}\n{xml}")))?;
    let device = |m: &dyn Plc, d: &str| m.device(d).map_err(|e| TestCaseError::fail(e.to_string()));
    let xs = (0..4)
        .map(|n| device(m.as_ref(), &(target.input)(n)))
        .collect::<Result<Vec<_>, _>>()?;
    let ys = (0..net.coils.len())
        .map(|c| device(m.as_ref(), &(target.coil)(c)))
        .collect::<Result<Vec<_>, _>>()?;
    let mut state = vec![false; net.nodes.len()];
    let mut counts = vec![0; net.nodes.len()];
    let mut last = 0;
    for &x in inputs {
        for (n, &h) in xs.iter().enumerate() {
            let on = i64::from(x & (1 << n) != 0);
            m.apply(Command::SetInput(h, InputValue::Int(on)))
                .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
        }
        if target.latched {
            // The first scan still sees the inputs before the change.
            m.step_scan();
            net.values(last, &mut state, &mut counts);
        }
        last = x;
        m.step_scan();
        let values = net.values(x, &mut state, &mut counts);
        for (c, on) in net.coils.iter().enumerate() {
            let seen = m.read(ys[c]) != 0;
            prop_assert_eq!(
                seen,
                on.iter().any(|&i| values[i]),
                "Y0{} with inputs {:04b}\n{}\n{}",
                c,
                x,
                text,
                xml
            );
        }
    }
    Ok(())
}

/// Whether an import's errors (as `{:?}` prints them) are all networks
/// that are not series-parallel.
fn is_only_bridges(errors: &str) -> bool {
    let located = errors.matches("Located {").count();
    located > 0 && errors.matches("NotSeriesParallel").count() == located
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_block_networks_light_their_coils_in_the_same_scan(
        net in network(true),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &IO86A)?;
    }

    #[test]
    fn random_block_networks_light_the_avr_plcs_bits_in_the_same_scan(
        net in network(false),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &AVR)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_block_networks_light_minasec_us_lamps_a_scan_later(
        net in network(false),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &MINASEC)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20_000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    #[ignore = "20 000 networks: run with --ignored"]
    fn random_block_networks_20000(
        net in network(true),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &IO86A)?;
    }

    #[test]
    #[ignore = "20 000 networks: run with --ignored"]
    fn random_block_networks_on_the_avr_plc_20000(
        net in network(false),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &AVR)?;
    }

    #[test]
    #[ignore = "20 000 networks: run with --ignored"]
    fn random_block_networks_on_minasec_u_20000(
        net in network(false),
        layout in layout(),
        inputs in prop::collection::vec(0u8..16, 1..8),
    ) {
        check(&net, &layout, &inputs, &MINASEC)?;
    }
}
