//! What a ladder cell holds, typed, and the one table of how each kind is
//! presented: its hook (`data-kind`, the CSS class `k-<hook>`, the
//! palette's id), its symbol, its words for screen readers, and what the
//! live view reads for it. The grid, the picture, the palette and the live
//! frame all look here instead of comparing strings.

/// A cell's kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CellKind {
    /// Nothing drawn.
    #[default]
    Empty,
    /// A horizontal wire.
    Wire,
    /// Normally open contact.
    No,
    /// Normally closed contact.
    Nc,
    /// Rising edge contact.
    Rise,
    /// Falling edge contact.
    Fall,
    /// Coil.
    Coil,
    /// Inverted coil.
    CoilNot,
    /// Set coil.
    Set,
    /// Reset coil.
    Reset,
    /// A timer's or counter's coil with its preset: it shows the count.
    CountCoil,
    /// An instruction box (`[MOV K50 D00]`, NOT, a timer block …).
    Box,
    /// A soft PLC block's input wired from the network on its left,
    /// below the block (drawn as the box going on down).
    BoxInput,
}

/// How a kind is presented.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Look {
    /// `data-kind`, the class `k-<hook>` and the palette's id (empty for
    /// an empty cell).
    pub hook: &'static str,
    /// The symbol drawn (empty where the element's own text is drawn:
    /// a count coil's preset, a box's instruction).
    pub symbol: &'static str,
    /// What it is, in words ("normally open contact").
    pub words: &'static str,
    /// The same in Japanese ("a接点").
    pub words_ja: &'static str,
    /// A contact: a click on it drives its input.
    pub contact: bool,
    /// Its device's state is shown live (`data-on`).
    pub shows_state: bool,
    /// A coil: when its device is a timer or counter, its current value
    /// is shown live.
    pub shows_value: bool,
}

const fn look(hook: &'static str, symbol: &'static str, words: Words) -> Look {
    Look {
        hook,
        symbol,
        words: words.0,
        words_ja: words.1,
        contact: false,
        shows_state: true,
        shows_value: false,
    }
}

/// Words in English and Japanese.
type Words = (&'static str, &'static str);

const fn contact(hook: &'static str, symbol: &'static str, words: Words) -> Look {
    Look {
        contact: true,
        ..look(hook, symbol, words)
    }
}

const EMPTY: Look = Look {
    shows_state: false,
    ..look("", "", ("empty", "空き"))
};
const WIRE: Look = Look {
    shows_state: false,
    ..look("hwire", "", ("wire", "横線"))
};
const NO: Look = contact("no", "┤ ├", ("normally open contact", "a接点"));
const NC: Look = contact("nc", "┤/├", ("normally closed contact", "b接点"));
const RISE: Look = contact("rise", "┤↑├", ("rising edge contact", "立上りエッジ接点"));
const FALL: Look = contact("fall", "┤↓├", ("falling edge contact", "立下りエッジ接点"));
const COIL: Look = Look {
    shows_value: true,
    ..look("coil", "( )", ("coil", "コイル"))
};
const COIL_NOT: Look = look("coil-not", "(/)", ("inverted coil", "反転コイル"));
const SET: Look = look("set", "(S)", ("set coil", "セットコイル"));
const RESET: Look = look("reset", "(R)", ("reset coil", "リセットコイル"));
// Drawn with the `coil` hook: to the eye and to the tests it is a coil.
const COUNT_COIL: Look = Look {
    shows_value: true,
    ..look("coil", "", ("coil", "コイル"))
};
const BOX: Look = Look {
    shows_state: false,
    ..look("box", "", ("box", "命令"))
};
const BOX_INPUT: Look = Look {
    shows_state: false,
    ..look("box-input", "", ("box input", "ブロック入力"))
};

impl CellKind {
    /// How it is presented.
    pub const fn look(self) -> &'static Look {
        match self {
            CellKind::Empty => &EMPTY,
            CellKind::Wire => &WIRE,
            CellKind::No => &NO,
            CellKind::Nc => &NC,
            CellKind::Rise => &RISE,
            CellKind::Fall => &FALL,
            CellKind::Coil => &COIL,
            CellKind::CoilNot => &COIL_NOT,
            CellKind::Set => &SET,
            CellKind::Reset => &RESET,
            CellKind::CountCoil => &COUNT_COIL,
            CellKind::Box => &BOX,
            CellKind::BoxInput => &BOX_INPUT,
        }
    }

    /// Its hook (`data-kind`).
    pub const fn hook(self) -> &'static str {
        self.look().hook
    }

    /// What it is, in words, in `lang`.
    pub const fn look_words(self, lang: crate::i18n::Lang) -> &'static str {
        match lang {
            crate::i18n::Lang::En => self.look().words,
            crate::i18n::Lang::Ja => self.look().words_ja,
        }
    }

    /// Nothing drawn.
    pub const fn is_empty(self) -> bool {
        matches!(self, CellKind::Empty)
    }
}

/// How wide (rem) a soft PLC box's live operands (`CV=4 Q=1`, 0.62 rem
/// monospace) need their column, with room for a few digits each.
pub fn values_width_rem(watched: &[(String, String)]) -> f64 {
    let chars: usize = watched.iter().map(|(l, _)| l.chars().count() + 5).sum();
    if chars == 0 {
        return 0.0;
    }
    chars as f64 * 0.6 * 0.62 + 0.6
}

/// A box's whole text (shown on hover, on focus and in its accessible
/// name however narrow its column): its call as written (`c0: CTU(CU :=
/// X00, PV := 10)`), with its operands' live values when it has them.
pub fn whole_text(kind: CellKind, words: &str, values: Option<&str>) -> Option<String> {
    if kind != CellKind::Box {
        return None;
    }
    let call = words.strip_prefix("box ").unwrap_or(words);
    Some(match values {
        Some(v) if !v.is_empty() => format!("{call} \u{2014} {v}"),
        _ => call.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_drawn_kind_has_a_hook_and_only_contacts_drive_inputs() {
        let all = [
            CellKind::Wire,
            CellKind::No,
            CellKind::Nc,
            CellKind::Rise,
            CellKind::Fall,
            CellKind::Coil,
            CellKind::CoilNot,
            CellKind::Set,
            CellKind::Reset,
            CellKind::CountCoil,
            CellKind::Box,
            CellKind::BoxInput,
        ];
        for k in all {
            assert!(!k.hook().is_empty(), "{k:?}");
        }
        let contacts: Vec<_> = all.iter().filter(|k| k.look().contact).collect();
        assert_eq!(
            contacts,
            [
                &CellKind::No,
                &CellKind::Nc,
                &CellKind::Rise,
                &CellKind::Fall
            ]
        );
        assert!(CellKind::CountCoil.look().shows_value && !CellKind::Set.look().shows_value);
        assert!(!CellKind::Box.look().shows_state && !CellKind::Wire.look().shows_state);
        assert_eq!(CellKind::Empty.hook(), "");
    }

    #[test]
    fn a_boxs_whole_text_is_its_call_and_its_values() {
        assert_eq!(
            whole_text(
                CellKind::Box,
                "box c0: CTU(CU := X00, PV := 10)",
                Some("CV=4")
            ),
            Some("c0: CTU(CU := X00, PV := 10) \u{2014} CV=4".to_string())
        );
        assert_eq!(
            whole_text(CellKind::Box, "box MOV K50 D00", None).as_deref(),
            Some("MOV K50 D00")
        );
        assert_eq!(
            whole_text(CellKind::No, "normally open contact X00", None),
            None
        );
    }

    #[test]
    fn a_boxs_column_has_room_for_its_live_operands() {
        assert_eq!(values_width_rem(&[]), 0.0);
        let one = values_width_rem(&[("CV".into(), "c0.CV".into())]);
        let three = values_width_rem(&[
            ("CV".into(), "c0.CV".into()),
            ("Q".into(), "c0.Q".into()),
            ("%IX0.1".into(), "%IX0.1".into()),
        ]);
        assert!(one > 2.0 && three > 2.0 * one, "{one} {three}");
    }
}
