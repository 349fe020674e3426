//! The words of files that land where they run (issue #49): the import
//! dialog's offer to switch machine. A table of its own, reached through
//! [`super::Lang::files`], so work on the big [`super::Texts`] table
//! does not collide with it.

use super::Lang;

/// The strings of opening files on the machine that runs them.
pub struct FilesTexts {
    /// Said when the file does not import here but does on `{machine}`.
    pub switch_offer: &'static str,
    /// The one-click switch (`{machine}`: the product name).
    pub switch_button: &'static str,
}

/// English.
pub const EN: FilesTexts = FilesTexts {
    switch_offer: "This file runs on the {machine}. Nothing was changed here.",
    switch_button: "Switch to the {machine} and import",
};

/// Japanese.
pub const JA: FilesTexts = FilesTexts {
    switch_offer: "このファイルは {machine} で動きます。ここでは何も変更していません。",
    switch_button: "{machine} に切り替えて読み込む",
};

impl Lang {
    /// This language's strings for opening files where they run.
    pub const fn files(self) -> &'static FilesTexts {
        match self {
            Lang::Ja => &JA,
            Lang::En => &EN,
        }
    }
}
