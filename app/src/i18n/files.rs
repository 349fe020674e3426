//! The words of issue #49's files and boxes: the import dialog's offer to
//! switch machine, the box entry's fields, "declare as". A table of its own, reached through
//! [`super::Lang::files`], so work on the big [`super::Texts`] table
//! does not collide with it.

use super::Lang;

/// The strings of opening files on the machine that runs them.
pub struct FilesTexts {
    /// Said when the file does not import here but does on `{machine}`.
    pub switch_offer: &'static str,
    /// The one-click switch (`{machine}`: the product name).
    pub switch_button: &'static str,
    /// The box entry's field label for a block's instance.
    pub box_instance: &'static str,
    /// The box entry's field label for a function's result.
    pub box_result: &'static str,
    /// The entry's placeholder for a box: how one is typed.
    pub box_usage: &'static str,
    /// The problems list's one-click declaration (`{name}`, `{type}`).
    pub declare_as: &'static str,
}

/// English.
pub const EN: FilesTexts = FilesTexts {
    switch_offer: "This file runs on the {machine}. Nothing was changed here.",
    switch_button: "Switch to the {machine} and import",
    box_instance: "instance",
    box_result: "result",
    box_usage: "e.g. CTU c0 reset 10 · ADD a 1 c · GT level 100 · MOVE 42 d",
    declare_as: "Declare {name} as {type}",
};

/// Japanese.
pub const JA: FilesTexts = FilesTexts {
    switch_offer: "このファイルは {machine} で動きます。ここでは何も変更していません。",
    switch_button: "{machine} に切り替えて読み込む",
    box_instance: "インスタンス",
    box_result: "結果",
    box_usage: "例: CTU c0 reset 10 · ADD a 1 c · GT level 100 · MOVE 42 d",
    declare_as: "{name} を {type} として宣言",
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
