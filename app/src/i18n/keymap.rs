//! The key map (the `?` overlay) and the keys named in menus, in both
//! languages (issue #49: they were English in Japanese mode). Key names
//! are the keyboard's own (Ctrl, Shift, F5) in both.

/// The keys' texts of one language.
pub struct KeyTexts {
    /// The zoom's wheel gesture, as a menu item names it.
    pub ctrl_wheel: &'static str,
    /// The key map: (keys, what they do).
    pub key_map: &'static [(&'static str, &'static str)],
}

/// English.
pub const EN: KeyTexts = KeyTexts {
    ctrl_wheel: "Ctrl+wheel",
    key_map: &[
        (
            "← → ↑ ↓, Home/End, PgUp/PgDn, Ctrl+Home/End",
            "move the cursor",
        ),
        ("Shift + arrows", "select cells (across rungs: whole rungs)"),
        ("W", "why is the cell under the cursor on or off"),
        ("F5 / F6 (c / Shift+C)", "normally open / closed contact"),
        ("Shift+F5 / Shift+F6", "the contact as an OR branch"),
        ("F7 (l)", "output coil in the output column"),
        (
            "F8 (s, r, o, f, m)",
            "instruction: SET Y00, RST C0, OUT T00 K10, MOV K50 D00, LDP X00, TON t 500ms",
        ),
        ("F9 (-) / Shift+F9 (|)", "horizontal wire / vertical link"),
        ("Ctrl+F9 / Ctrl+F10", "delete the wire / the link"),
        ("Delete, Enter", "clear the cell, edit the cell"),
        (
            "Insert / Shift+Insert, Ctrl+Delete",
            "rung above / below, delete the rung",
        ),
        ("Alt+↑ / Alt+↓", "move the rung"),
        ("Ctrl+Z / Ctrl+Y (Ctrl+Shift+Z)", "undo / redo"),
        (
            "Ctrl+C / Ctrl+X / Ctrl+V",
            "copy / cut / paste (between tabs too)",
        ),
        ("Ctrl+F, ?", "find and replace, this key map"),
    ],
};

/// 日本語.
pub const JA: KeyTexts = KeyTexts {
    ctrl_wheel: "Ctrl+ホイール",
    key_map: &[
        (
            "← → ↑ ↓, Home/End, PgUp/PgDn, Ctrl+Home/End",
            "カーソルの移動",
        ),
        ("Shift + 矢印", "セルの選択 (回路をまたぐと回路単位)"),
        ("W", "カーソルのセルがオン・オフの理由"),
        ("F5 / F6 (c / Shift+C)", "a接点 / b接点"),
        ("Shift+F5 / Shift+F6", "OR 分岐の接点"),
        ("F7 (l)", "出力列のコイル"),
        (
            "F8 (s, r, o, f, m)",
            "命令: SET Y00, RST C0, OUT T00 K10, MOV K50 D00, LDP X00, TON t 500ms",
        ),
        ("F9 (-) / Shift+F9 (|)", "横線 / 縦線"),
        ("Ctrl+F9 / Ctrl+F10", "横線 / 縦線の削除"),
        ("Delete, Enter", "セルを消す、セルを編集する"),
        (
            "Insert / Shift+Insert, Ctrl+Delete",
            "上 / 下に回路を挿入、回路の削除",
        ),
        ("Alt+↑ / Alt+↓", "回路の移動"),
        ("Ctrl+Z / Ctrl+Y (Ctrl+Shift+Z)", "元に戻す / やり直す"),
        (
            "Ctrl+C / Ctrl+X / Ctrl+V",
            "コピー / 切り取り / 貼り付け (タブの間でも)",
        ),
        ("Ctrl+F, ?", "検索と置換、このキー一覧"),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_key_maps_name_the_same_keys_and_the_japanese_says_no_english() {
        assert_eq!(EN.key_map.len(), JA.key_map.len());
        for ((en_keys, _), (ja_keys, what)) in EN.key_map.iter().zip(JA.key_map) {
            // The keys are the keyboard's; only "arrows" is a word.
            assert_eq!(en_keys.replace("arrows", "矢印"), *ja_keys);
            assert!(what.chars().any(|c| c > '\u{3000}'), "{what}");
            assert_eq!(crate::i18n::errors::english_run(what), None, "{what}");
        }
        assert_ne!(EN.ctrl_wheel, JA.ctrl_wheel);
    }
}
