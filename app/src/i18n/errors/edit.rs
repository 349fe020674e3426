//! The editor's refusals and a rung's wiring problems in Japanese.

use engine::ladder::edit::{
    ClipError, EditError, ReplaceError, VariableEditError, MAX_COLUMNS, MAX_ROWS,
};
use engine::ladder::problem::RungProblem;
use engine::limits::{MAX_INPUT_BYTES, MAX_NESTING, MAX_RUNG_CELLS};

use super::super::engine::element_ja;
use files_worker::said_iec_ja::variable_ja;

/// An edit's refusal in Japanese.
pub fn edit_ja(e: &EditError) -> String {
    match e {
        EditError::NoSuchRung(r) => format!("回路 {} はありません", r + 1),
        EditError::OutsideGrid(c) => format!(
            "行 {}、列 {} は枠の外です: 回路は最大 {MAX_ROWS} 行 {MAX_COLUMNS} 列です",
            c.row + 1,
            c.col + 1
        ),
        EditError::BranchOnTopRow => {
            "OR 分岐は別の行の下に置きます: 先にカーソルを下へ動かしてください".into()
        }
        EditError::BranchNotContact => "OR 分岐にできるのは接点だけです".into(),
        EditError::NothingToDo => "ここには変えるものがありません".into(),
        EditError::BlockAcrossRungs => {
            "セルの範囲は 1 つの回路の中だけです: 回路ごと選んでください".into()
        }
        EditError::Clip(e) => clip_ja(e),
        EditError::Replace(e) => replace_ja(e),
        EditError::Variable(e) => variable_edit_ja(e),
    }
}

pub(super) fn clip_ja(e: &ClipError) -> String {
    match e {
        // The JSON parser's words are English and about the text's
        // syntax, which a user pasting did not write: left out.
        ClipError::NotAClip(_) => "クリップボードにラダーがありません".into(),
        ClipError::TooLarge => {
            format!("クリップボードの文字列がラダーの上限 {MAX_INPUT_BYTES} バイトを超えています")
        }
        ClipError::Element { rung, pos, error } => format!(
            "コピーした回路 {}、行 {}、列 {}: {}",
            rung + 1,
            pos.row + 1,
            pos.col + 1,
            element_ja(error)
        ),
        ClipError::OutsideGrid => {
            format!("ここに貼り付けるとセルが {MAX_ROWS} 行か {MAX_COLUMNS} 列を超えます")
        }
    }
}

pub(super) fn replace_ja(e: &ReplaceError) -> String {
    match e {
        ReplaceError::Empty => "デバイスか範囲 (M00-M07 など) を入力してください".into(),
        ReplaceError::Range(spec) => {
            format!("{spec}: 範囲は同じ種類の 2 つの名前を小さい順に書きます (M00-M07 など)")
        }
        ReplaceError::Counts { from, old, to, new } => {
            format!("{from} は {old} 個、{to} は {new} 個のデバイスです: 同じ数にしてください")
        }
    }
}

fn variable_edit_ja(e: &VariableEditError) -> String {
    match e {
        VariableEditError::Declaration(e) => variable_ja(e),
        VariableEditError::NoSuchVariable(n) => format!("変数 {n} はありません"),
        VariableEditError::NameTaken(n) => format!("{n} はもう宣言されています"),
        VariableEditError::UseNoLongerFits(e) => format!(
            "使っている箇所に合わなくなります: {}",
            super::super::engine::ladder_error(super::super::Lang::Ja, e)
        ),
    }
}

/// A rung's wiring or placement problem in Japanese.
pub fn rung_problem_ja(p: &RungProblem) -> String {
    use RungProblem as P;
    match p {
        P::NoOutput => "回路に出力がありません: コイルか出力ボックスで終えてください".into(),
        P::OutputNotLast => {
            "出力は回路の最後の列にそろえます: この出力を右へ動かしてください".into()
        }
        P::AfterOutput => {
            "出力の後には何も置けません: コイルと出力ボックスが回路の終わりです".into()
        }
        P::LinkPastRung => "縦線が回路の最後の行か列を越えています".into(),
        P::OutputNotJoined => {
            "この出力は最初の出力の条件につながっていません: 別の回路にするか線でつないでください"
                .into()
        }
        P::ShortCircuit => "短絡: 線がこの要素の両側をつないでいます".into(),
        P::OutputOnRail => {
            "出力が左の母線に直接つながっています: 前に接点を置いてください".into()
        }
        P::Dangling => "浮いています: この要素は左の母線から出力への経路上にありません".into(),
        P::DanglingWire => "浮いた線: 左の母線と出力をつないでいません".into(),
        P::NoPath => "左の母線からこの出力へ接点の経路がありません".into(),
        P::TooLarge { rows, width } => format!(
            "回路が {rows} 行 {width} 列あり、1 回路の上限 {MAX_RUNG_CELLS} セルを超えています"
        ),
        P::InputInBoxColumn(pin) => {
            format!("入力 {pin} がボックスの真下 (ボックスの列) にあります")
        }
        P::InputWithoutBox(pin) => format!("入力 {pin} の上にボックスがありません"),
        P::NoBoolInput(kind, pin, takes) => {
            let takes = if takes.is_empty() { "なし" } else { takes };
            format!("{kind} には回路でつなぐ BOOL 入力 {pin} がありません (入力: {takes})")
        }
        P::FunctionInput(kind) => {
            format!("{kind} は関数です: 入力はオペランドで、回路ではつなげません")
        }
        P::InputTwice(kind, pin) => {
            format!("{kind} の {pin} がオペランドとこの回路の 2 回与えられています")
        }
        P::InputLinkedAbove(kind, pin) => format!(
            "この縦線が {kind} の {pin} の回路を上の行につないでいます: その行の中だけにしてください"
        ),
        P::InputWithoutNetwork => "この入力には回路がありません".into(),
        P::NotSeriesParallel => {
            "この回路は直列・並列になっていません (分岐の間のブリッジ): 直列と並列のブロックで描き直してください"
                .into()
        }
        P::TooDeep => format!("直列と並列のブロックの入れ子が {MAX_NESTING} 段を超えています"),
    }
}
