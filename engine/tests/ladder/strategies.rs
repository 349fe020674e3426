//! Random ladders for the property tests: contact networks over a few
//! devices per machine, in-line boxes for the AVR PLC, every coil kind.

use engine::ladder::{CoilKind, ContactKind, Element, Net, Pos, RungLogic, TimerKind};
use engine::MachineId;
use proptest::prelude::*;

/// The devices a machine's random ladders use.
pub struct Pool {
    pub inputs: &'static [&'static str],
    pub outputs: &'static [&'static str],
    pub contacts: &'static [ContactKind],
    pub inline_boxes: bool,
}

pub fn pool(machine: MachineId) -> Pool {
    const EDGES: &[ContactKind] = &[
        ContactKind::No,
        ContactKind::No,
        ContactKind::Nc,
        ContactKind::No,
        ContactKind::Nc,
        ContactKind::Rising,
        ContactKind::Falling,
    ];
    match machine {
        MachineId::MinasecU => Pool {
            inputs: &["X00", "X01", "X02", "X03"],
            outputs: &["Y00", "Y01", "Y02", "M00", "M01"],
            contacts: EDGES,
            inline_boxes: false,
        },
        MachineId::Io86a => Pool {
            inputs: &["X00", "X01", "X02", "X03"],
            outputs: &["Y00", "Y01", "Y02", "M00", "M01", "S00"],
            contacts: EDGES,
            inline_boxes: false,
        },
        MachineId::AvrPlc => Pool {
            inputs: &["R0.0", "R0.1", "R0.2", "R0.3"],
            outputs: &["R1.0", "R1.1", "R1.2", "R2.0", "R2.7"],
            contacts: EDGES,
            inline_boxes: true,
        },
        MachineId::ArduinoPlc => Pool {
            inputs: &["X000", "X001", "X002", "X003"],
            outputs: &["Y000", "Y001", "Y002", "Y003"],
            contacts: &[ContactKind::No, ContactKind::Nc],
            inline_boxes: false,
        },
        MachineId::SoftPlc => Pool {
            inputs: &["%IX0.0", "%IX0.1", "%IX0.2", "%IX0.3"],
            outputs: &["%QX0.0", "%QX0.1", "%QX0.2", "relay", "m1"],
            contacts: EDGES,
            inline_boxes: true,
        },
    }
}

fn contact_net(p: &'static Pool) -> impl Strategy<Value = Net> {
    let devices: Vec<&'static str> = p.inputs.iter().chain(p.outputs).copied().collect();
    let leaf = (
        prop::sample::select(devices),
        prop::sample::select(p.contacts),
    )
        .prop_map(|(d, kind)| {
            Net::Leaf(
                Element::Contact {
                    kind,
                    device: d.to_string(),
                },
                Pos::new(0, 0),
            )
        });
    leaf.prop_recursive(3, 12, 3, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 2..4).prop_map(Net::Series),
            prop::collection::vec(inner, 2..4).prop_map(Net::Parallel),
        ]
    })
}

fn inline_box() -> impl Strategy<Value = Element> {
    prop_oneof![
        Just(Element::Not),
        any::<bool>().prop_map(|falling| Element::Edge { falling }),
        (
            prop::sample::select(vec![TimerKind::Ton, TimerKind::Tof, TimerKind::Tp]),
            1u32..5
        )
            .prop_map(|(kind, n)| Element::Timer {
                kind,
                name: "t".into(),
                preset_ms: n * 10,
            }),
    ]
}

fn condition(p: &'static Pool) -> BoxedStrategy<Net> {
    if !p.inline_boxes {
        return contact_net(p).boxed();
    }
    // AVR: in-line boxes on the main line between contact networks.
    (
        contact_net(p),
        prop::collection::vec((inline_box(), prop::option::of(contact_net(p))), 0..3),
    )
        .prop_map(|(first, rest)| {
            let mut items = vec![first];
            for (b, n) in rest {
                items.push(Net::Leaf(b, Pos::new(0, 0)));
                items.extend(n);
            }
            Net::Series(items)
        })
        .boxed()
}

pub fn rung(p: &'static Pool) -> impl Strategy<Value = RungLogic> {
    let coil = (
        prop::sample::select(vec![
            CoilKind::Normal,
            CoilKind::Normal,
            CoilKind::Inverted,
            CoilKind::Set,
            CoilKind::Reset,
        ]),
        prop::sample::select(p.outputs),
    )
        .prop_map(|(kind, d)| {
            (
                Element::Coil {
                    kind,
                    device: d.to_string(),
                },
                Pos::new(0, 0),
            )
        });
    (condition(p), prop::collection::vec(coil, 1..3)).prop_map(|(condition, outputs)| RungLogic {
        condition: condition.normalised(),
        outputs,
        comment: String::new(),
        sides: Vec::new(),
    })
}

pub type Case = (Vec<RungLogic>, Vec<Vec<bool>>);

pub fn case(p: &'static Pool) -> impl Strategy<Value = Case> {
    (
        prop::collection::vec(rung(p), 1..5),
        prop::collection::vec(prop::collection::vec(any::<bool>(), 4), 1..24),
    )
}
