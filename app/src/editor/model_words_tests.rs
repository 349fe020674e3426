//! The words a cell and an element are said in (model.rs), tested
//! apart so that model.rs stays short.

use super::*;

mod cells {
    use super::*;
    use engine::ladder::Rung;

    #[test]
    fn cells_are_named_in_both_languages_with_their_state() {
        let rung = Rung {
            cells: vec![vec![
                Some(Element::no("X00")),
                Some(Element::TimerCoil {
                    device: "T00".into(),
                    preset: 10,
                }),
            ]],
            ..Rung::default()
        };
        let d = rung_data(&rung, 1, &[], &BTreeMap::new());
        assert_eq!(
            cell_words(&d.cells[0], Lang::En),
            "normally open contact X00"
        );
        assert_eq!(cell_words(&d.cells[0], Lang::Ja), "a接点 X00");
        assert_eq!(cell_words(&d.cells[1], Lang::Ja), "タイマコイル T00 K10");
        assert_eq!(cell_words(&d.cells[2], Lang::Ja), "空き");
        assert_eq!(
            live_words(Some(true), Some(true), Lang::En),
            ", on, powered"
        );
        assert_eq!(live_words(Some(false), None, Lang::Ja), ", オフ");
        assert_eq!(live_words(None, Some(false), Lang::En), "");
    }
}

mod elements {
    use super::*;

    /// Why? names each deciding cell in the page's language: in Japanese
    /// no English word of its kind (`coil`, `contact`) is left.
    #[test]
    fn an_element_is_named_in_japanese_as_its_cell_says_it() {
        let elements = [
            Element::Contact {
                kind: ContactKind::No,
                device: "X00".into(),
            },
            Element::Contact {
                kind: ContactKind::Nc,
                device: "X01".into(),
            },
            Element::Contact {
                kind: ContactKind::Rising,
                device: "X02".into(),
            },
            Element::Coil {
                kind: CoilKind::Normal,
                device: "Y00".into(),
            },
            Element::Coil {
                kind: CoilKind::Set,
                device: "Y01".into(),
            },
            Element::TimerCoil {
                device: "T0".into(),
                preset: 10,
            },
            Element::CounterCoil {
                device: "C0".into(),
                preset: 3,
            },
        ];
        for e in &elements {
            let en = element_words(e, Lang::En);
            assert_eq!(en, e.to_string());
            let ja = element_words(e, Lang::Ja);
            let english: Vec<&str> = ja
                .split(|c: char| !c.is_ascii_alphabetic())
                .filter(|w| w.len() > 1 && w.chars().all(|c| c.is_ascii_lowercase()))
                .collect();
            assert!(english.is_empty(), "{en} in Japanese: {ja}");
            let device = en.rsplit(' ').next().unwrap_or_default();
            assert!(ja.contains(device), "{ja} names {device}");
        }
        assert_eq!(element_words(&elements[3], Lang::Ja), "コイル Y00");
    }
}
