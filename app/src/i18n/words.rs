//! Words of the page that were written in English in its code (issue
//! #49: Japanese mode showed them): a cell's place in the replace
//! preview, the variables pane's refusal of a value.

/// The words of one language.
pub struct Words {
    /// A cell's place: `{rung}`, `{row}` and `{col}` are its numbers.
    pub cell_at: &'static str,
    /// A cell's place in its rung: `{row}` and `{col}`.
    pub row_col: &'static str,
    /// What a variable's value is typed as, after the text refused.
    pub true_false_number: &'static str,
    /// A device's uses (cross reference): as a contact, a coil, in a box.
    pub use_roles: [&'static str; 3],
    /// A new test case's name and a recorded one's, before `{n}`.
    pub case_names: [&'static str; 2],
}

/// English.
pub const EN: Words = Words {
    cell_at: "rung {rung}, row {row}, column {col}",
    row_col: "row {row}, column {col}",
    true_false_number: "TRUE, FALSE or a number",
    use_roles: ["contact", "coil", "box"],
    case_names: ["case {n}", "recorded {n}"],
};

/// 日本語.
pub const JA: Words = Words {
    cell_at: "回路 {rung}、行 {row}、列 {col}",
    row_col: "行 {row}、列 {col}",
    true_false_number: "TRUE、FALSE または数を入力してください",
    use_roles: ["接点", "コイル", "ボックス"],
    case_names: ["ケース {n}", "記録 {n}"],
};

impl Words {
    /// The place of a cell (numbers 1-based, as shown).
    pub fn cell(&self, rung: usize, row: usize, col: usize) -> String {
        self.cell_at
            .replace("{rung}", &rung.to_string())
            .replace("{row}", &row.to_string())
            .replace("{col}", &col.to_string())
    }

    /// The place of a cell in its rung (1-based).
    pub fn row_col(&self, row: usize, col: usize) -> String {
        self.row_col
            .replace("{row}", &row.to_string())
            .replace("{col}", &col.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cells_place_is_said_in_each_language() {
        assert_eq!(EN.cell(1, 2, 3), "rung 1, row 2, column 3");
        assert_eq!(JA.cell(1, 2, 3), "回路 1、行 2、列 3");
        assert_eq!(JA.row_col(2, 3), "行 2、列 3");
        assert_eq!(EN.row_col(2, 3), "row 2, column 3");
        assert_eq!(crate::i18n::errors::english_run(JA.true_false_number), None);
    }
}
