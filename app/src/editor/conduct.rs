//! What a contact's colour says (issue #46): by default a contact is lit
//! when it conducts (is closed), as GX Works' monitor and most ladder
//! tools draw it: a normally-open contact while its device is on, a
//! normally-closed one while its device is off, an edge contact in the
//! scan its edge passes. The old colouring, by the device's own value,
//! is a setting ([`Colouring::ByValue`]); either way the device's value
//! stays on the cell (`data-on`, a mark on the label).

use super::model::CellKind;
use crate::i18n::Lang;

/// How contacts are coloured (remembered under [`COLOURING_KEY`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Colouring {
    /// Lit while closed (the default).
    #[default]
    ByConduction,
    /// Lit while the device is on (Hashigo before issue #46).
    ByValue,
}

/// The storage key of the colouring.
pub const COLOURING_KEY: &str = "hashigo.colouring";

impl Colouring {
    /// Its stored word.
    pub const fn code(self) -> &'static str {
        match self {
            Colouring::ByConduction => "conduction",
            Colouring::ByValue => "value",
        }
    }

    /// The colouring stored as `code`; anything else (nothing stored, an
    /// older or damaged value) is the default.
    pub fn parse(code: Option<&str>) -> Colouring {
        match code {
            Some("value") => Colouring::ByValue,
            _ => Colouring::ByConduction,
        }
    }
}

/// Whether a cell of `kind` conducts (`data-conducts`): `None` for what
/// is not a contact, or while the device's state is unknown (`on` is
/// `None`: the machine does not run the drawing). `edge` is whether an
/// edge contact's step passed in the last scan (its trace), `None` when
/// there is no trace: the edge is then taken as not passing, since it
/// lasts one scan.
pub fn conducts(kind: CellKind, on: Option<bool>, edge: Option<bool>) -> Option<bool> {
    let on = on?;
    match kind {
        CellKind::No => Some(on),
        CellKind::Nc => Some(!on),
        CellKind::Rise | CellKind::Fall => Some(edge.unwrap_or(false)),
        _ => None,
    }
}

/// Whether a cell is drawn lit: a contact by `conducts` (or, coloured by
/// value, by its device), anything else by its device's value.
pub fn lit(kind: CellKind, on: Option<bool>, conducts: Option<bool>, by: Colouring) -> bool {
    if kind.look().contact && by == Colouring::ByConduction {
        conducts == Some(true)
    } else {
        on == Some(true)
    }
}

/// A contact's conduction in words, after its live state in its
/// accessible name (so it is not said by colour only).
pub fn conduct_words(conducts: Option<bool>, lang: Lang) -> &'static str {
    match (conducts, lang) {
        (None, _) => "",
        (Some(true), Lang::En) => ", closed",
        (Some(false), Lang::En) => ", open",
        (Some(true), Lang::Ja) => ", 閉",
        (Some(false), Lang::Ja) => ", 開",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_contact_conducts_by_its_kind() {
        assert_eq!(conducts(CellKind::No, Some(true), None), Some(true));
        assert_eq!(conducts(CellKind::No, Some(false), None), Some(false));
        // The point of issue #46: NC conducts while its input is OFF.
        assert_eq!(conducts(CellKind::Nc, Some(false), None), Some(true));
        assert_eq!(conducts(CellKind::Nc, Some(true), None), Some(false));
        // An edge contact only in the scan its edge passes, whatever
        // the device's level.
        assert_eq!(
            conducts(CellKind::Rise, Some(true), Some(false)),
            Some(false)
        );
        assert_eq!(conducts(CellKind::Rise, Some(true), Some(true)), Some(true));
        assert_eq!(
            conducts(CellKind::Fall, Some(false), Some(true)),
            Some(true)
        );
        assert_eq!(conducts(CellKind::Fall, Some(false), None), Some(false));
        // Not running: nothing known; not a contact: nothing to say.
        assert_eq!(conducts(CellKind::Nc, None, None), None);
        assert_eq!(conducts(CellKind::Coil, Some(true), None), None);
        assert_eq!(conducts(CellKind::Box, Some(true), Some(true)), None);
    }

    #[test]
    fn the_old_colouring_lights_contacts_by_value_and_coils_are_alike_in_both() {
        let nc_off = (Some(false), conducts(CellKind::Nc, Some(false), None));
        assert!(lit(
            CellKind::Nc,
            nc_off.0,
            nc_off.1,
            Colouring::ByConduction
        ));
        assert!(!lit(CellKind::Nc, nc_off.0, nc_off.1, Colouring::ByValue));
        let no_on = (Some(true), conducts(CellKind::No, Some(true), None));
        assert!(lit(CellKind::No, no_on.0, no_on.1, Colouring::ByConduction));
        assert!(lit(CellKind::No, no_on.0, no_on.1, Colouring::ByValue));
        for by in [Colouring::ByConduction, Colouring::ByValue] {
            assert!(lit(CellKind::Coil, Some(true), None, by));
            assert!(!lit(CellKind::Coil, Some(false), None, by));
            assert!(!lit(CellKind::Nc, None, None, by), "not running: unlit");
        }
    }

    #[test]
    fn the_colouring_is_kept_as_a_word_and_falls_back_to_conduction() {
        for c in [Colouring::ByConduction, Colouring::ByValue] {
            assert_eq!(Colouring::parse(Some(c.code())), c);
        }
        assert_eq!(Colouring::parse(None), Colouring::ByConduction);
        assert_eq!(Colouring::parse(Some("garbage")), Colouring::ByConduction);
        assert_eq!(conduct_words(Some(true), Lang::En), ", closed");
        assert_eq!(conduct_words(None, Lang::Ja), "");
    }
}
