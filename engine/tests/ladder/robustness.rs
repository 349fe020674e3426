//! Never a panic: arbitrary text into the project and PLCopen readers,
//! arbitrary grids into the analysis, every compiler and the exporter.

use engine::formats::plcopen::export;
use engine::formats::plcopen::Document;
use engine::formats::Project;
use engine::ladder::compile::{compile, Options};
use engine::ladder::{CoilKind, ContactKind, Element, Ladder, Link, Pos, Rung, TimerKind};
use engine::MachineId;
use proptest::prelude::*;

fn element() -> impl Strategy<Value = Option<Element>> {
    let device = prop::sample::select(vec![
        "X00", "Y01", "M10", "T0", "C0", "R1.2", "X000", "Y000", "D00", "K5", "??", "",
    ]);
    prop_oneof![
        3 => Just(None),
        2 => Just(Some(Element::Wire)),
        3 => (device.clone(), prop::sample::select(vec![ContactKind::No, ContactKind::Nc, ContactKind::Rising, ContactKind::Falling]))
            .prop_map(|(d, kind)| Some(Element::Contact { kind, device: d.into() })),
        2 => (device.clone(), prop::sample::select(vec![CoilKind::Normal, CoilKind::Inverted, CoilKind::Set, CoilKind::Reset]))
            .prop_map(|(d, kind)| Some(Element::Coil { kind, device: d.into() })),
        1 => Just(Some(Element::Not)),
        1 => any::<bool>().prop_map(|falling| Some(Element::Edge { falling })),
        1 => (0u32..3000).prop_map(|preset_ms| Some(Element::Timer { kind: TimerKind::Tof, name: "t".into(), preset_ms })),
        1 => (device.clone(), any::<u16>()).prop_map(|(d, preset)| Some(Element::TimerCoil { device: d.into(), preset })),
        1 => (device.clone(), device.clone()).prop_map(|(a, b)| Some(Element::Mov { src: a.into(), dst: b.into() })),
        1 => (any::<bool>(), device).prop_map(|(falling, d)| Some(Element::Pulse { falling, device: d.into() })),
    ]
}

fn grid() -> impl Strategy<Value = Rung> {
    (
        prop::collection::vec(prop::collection::vec(element(), 0..6), 0..5),
        prop::collection::vec((0usize..6, 0usize..8), 0..8),
    )
        .prop_map(|(cells, links)| Rung {
            comment: String::new(),
            cells,
            links: links
                .into_iter()
                .map(|(row, col)| Link { row, col })
                .collect(),
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_grids_never_panic(rungs in prop::collection::vec(grid(), 1..4)) {
        let ladder = Ladder { rungs, ..Ladder::default() };
        for m in MachineId::ALL {
            let _ = compile(&ladder, m, Options::default());
        }
        if let Ok(xml) = export(&ladder, "x") {
            // What exports must import back.
            prop_assert!(Document::read(&xml).and_then(|document| document.import(None, None, None)).map(|i| i.ladder).is_ok(), "{}", xml);
        }
    }

    #[test]
    fn arbitrary_text_never_panics(s in "\\PC{0,300}") {
        let _ = Project::from_json(&s);
        let _ = Document::read(&s).and_then(|document| document.import(None, None, None)).map(|i| i.ladder);
        let _ = Document::read(&format!("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><types><pous><pou><body><LD>{s}</LD></body></pou></pous></types></project>")).and_then(|document| document.import(None, None, None)).map(|i| i.ladder);
    }
}

#[test]
fn a_cell_past_every_row_is_fine() {
    let mut r = Rung::default();
    r.set(Pos::new(3, 7), Some(Element::coil("Y00")));
    let l = Ladder {
        rungs: vec![r],
        ..Ladder::default()
    };
    let e = compile(&l, MachineId::MinasecU, Options::default()).expect_err("no contact");
    assert!(
        e[0].message
            .contains("no path of contacts joins the left rail"),
        "{e:?}"
    );
}
