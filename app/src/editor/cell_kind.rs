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
    /// A contact: a click on it drives its input.
    pub contact: bool,
    /// Its device's state is shown live (`data-on`).
    pub shows_state: bool,
    /// A coil: when its device is a timer or counter, its current value
    /// is shown live.
    pub shows_value: bool,
}

const fn look(hook: &'static str, symbol: &'static str, words: &'static str) -> Look {
    Look {
        hook,
        symbol,
        words,
        contact: false,
        shows_state: true,
        shows_value: false,
    }
}

const fn contact(hook: &'static str, symbol: &'static str, words: &'static str) -> Look {
    Look {
        contact: true,
        ..look(hook, symbol, words)
    }
}

const EMPTY: Look = Look {
    shows_state: false,
    ..look("", "", "empty")
};
const WIRE: Look = Look {
    shows_state: false,
    ..look("hwire", "", "wire")
};
const NO: Look = contact("no", "┤ ├", "normally open contact");
const NC: Look = contact("nc", "┤/├", "normally closed contact");
const RISE: Look = contact("rise", "┤↑├", "rising edge contact");
const FALL: Look = contact("fall", "┤↓├", "falling edge contact");
const COIL: Look = Look {
    shows_value: true,
    ..look("coil", "( )", "coil")
};
const COIL_NOT: Look = look("coil-not", "(/)", "inverted coil");
const SET: Look = look("set", "(S)", "set coil");
const RESET: Look = look("reset", "(R)", "reset coil");
// Drawn with the `coil` hook: to the eye and to the tests it is a coil.
const COUNT_COIL: Look = Look {
    shows_value: true,
    ..look("coil", "", "coil")
};
const BOX: Look = Look {
    shows_state: false,
    ..look("box", "", "box")
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
        }
    }

    /// Its hook (`data-kind`).
    pub const fn hook(self) -> &'static str {
        self.look().hook
    }

    /// Nothing drawn.
    pub const fn is_empty(self) -> bool {
        matches!(self, CellKind::Empty)
    }
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
}
