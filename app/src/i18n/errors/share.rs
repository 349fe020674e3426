//! Why a share link does not open, in Japanese. Where a link is damaged
//! inside, the byte is said and the engine's note of what it found there
//! is left out (it helps a developer, not the user: the link is broken
//! either way).

use engine::formats::share::ShareError;

/// `e` in Japanese.
pub fn share_ja(e: &ShareError) -> String {
    match e {
        ShareError::Version(v) => format!(
            "この共有リンクの形式 {} はこの Hashigo では読めません",
            engine::shown(v)
        ),
        ShareError::Base64 => "この共有リンクは壊れています: base64url の文字列ではありません".into(),
        ShareError::Inflate => "この共有リンクは壊れています: データを展開できません".into(),
        ShareError::TooLong(n) => format!(
            "この共有リンクは {n} 文字あり、リンクの上限 {} 文字を超えています",
            engine::limits::MAX_SHARE_FRAGMENT
        ),
        ShareError::RungTooLarge {
            rung,
            rows,
            columns,
        } => format!(
            "回路 {rung} は {rows} 行 {columns} 列あります: 共有リンクに入る回路は 64 × 64 セルまでです"
        ),
        ShareError::TooMany { what, count, limit } => format!(
            "この共有リンクには{}が {count} 個あり、プロジェクトの上限 {limit} 個を超えています",
            counted_ja(what)
        ),
        ShareError::Data { at, .. } => {
            format!("この共有リンクは {at} バイト目で壊れています")
        }
    }
}

/// What a link counts, as the engine names it (`Reader::count`).
fn counted_ja(what: &str) -> &'static str {
    match what {
        "rungs" => "回路",
        "links in one rung" => "1 つの回路のつながり",
        "test cases" => "テストケース",
        "expectations in one test case" => "1 つのテストケースの期待値",
        "plant wiring lines" => "プラントの配線",
        "plant faults" => "プラントの故障",
        "plant parameters" => "プラントのパラメータ",
        "pins of one box" => "1 つのボックスのピン",
        "variables" => "変数",
        "settings" => "設定",
        "device comments" => "デバイスコメント",
        _ => "項目",
    }
}
