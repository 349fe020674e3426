//! Structured Text's refusals in Japanese (issue #54): every
//! `StErrorKind` (a match with no catch-all, so a new kind does not
//! compile until it is said here) and a `.st` program's load error. The
//! parser's and lowering's phrases (`after the IF condition`, what does
//! not run yet) come from a table; one not in it stays as written.
//! Keywords and names are kept as written.

use engine::iec::st::StErrorKind;
use engine::softplc::st::{StLoadError, StWhy};

use crate::said_iec_ja::{address_ja, literal_ja};
use crate::said_program_ja::load_ja;

/// A `.st` program's load error, in Japanese, after its line and column.
pub fn st_load_ja(e: &StLoadError) -> String {
    let why = match &e.why {
        StWhy::St(kind) => st_ja(kind),
        StWhy::Load(load) => load_ja(load),
    };
    format!("{} 行 {} 桁: {why}", e.line, e.column)
}

/// A Structured Text refusal, in Japanese.
pub fn st_ja(k: &StErrorKind) -> String {
    match k {
        StErrorKind::UnexpectedChar(c) => format!("予期しない文字 '{c}'"),
        StErrorKind::UnclosedComment => "この (* コメントが *) で閉じられていません".into(),
        StErrorKind::UnclosedString => "この文字列がその行で閉じられていません".into(),
        StErrorKind::BadLiteral(text, why) => format!("`{text}` は値ではありません: {}", literal_ja(why)),
        StErrorKind::LiteralOutOfRange(text, t) => match t.range() {
            Some((lo, hi)) => format!("`{text}` は {} の範囲外です ({lo} … {hi})", t.name()),
            None => format!("`{text}` は {} の値ではありません", t.name()),
        },
        StErrorKind::BadAddress(e) => address_ja(e),
        StErrorKind::BadLiteralType(t) => format!("`{t}#` は値に付けられる型ではありません"),
        StErrorKind::Expected {
            what,
            context,
            found,
        } => format!(
            "{} {} が必要ですが、{} があります",
            phrase(context),
            phrase(what),
            phrase(found)
        ),
        StErrorKind::Unsupported(what) => {
            format!("{} は Hashigo の Structured Text では扱いません", phrase(what))
        }
        StErrorKind::NotYet(what) => format!("{} はまだソフトPLCで動きません", phrase(what)),
        StErrorKind::InOutArgument(pin) => format!("VAR_IN_OUT {pin} には変数を渡します"),
        StErrorKind::ReservedWord(w) => format!("`{w}` はキーワードです: 名前には使えません"),
        StErrorKind::TooDeep => format!(
            "入れ子が {} 段を超えています (括弧、呼び出し、文)",
            engine::iec::st::error::MAX_DEPTH
        ),
        StErrorKind::BadBound(t) => format!(
            "`{t}` は長さや個数になりません (STRING の長さは 1 以上、繰り返しの個数は 0 以上)"
        ),
        StErrorKind::EmptyRange(lo, hi) => {
            format!("範囲 {lo}..{hi} は空です: 下限が上限より大きいです")
        }
        StErrorKind::PositionalAfterNamed => {
            "名前付きの引数の後に位置による引数は置けません (すべてに名前を付けるか、どれにも付けません)".into()
        }
        StErrorKind::UnknownName(n) => format!("`{n}` は宣言されていません"),
        StErrorKind::UnknownType(n) => format!(
            "`{n}` は型ではありません (基本型、TYPE、ファンクションブロックのどれでもありません)"
        ),
        StErrorKind::DuplicateName(n) => format!("`{n}` が 2 回宣言されています"),
        StErrorKind::NoMember { member, of } => format!("{of} にメンバー `{member}` はありません"),
        StErrorKind::BadIndex { name, dims: 0, .. } => format!("`{name}` は配列ではありません"),
        StErrorKind::BadIndex { name, dims, given } => {
            format!("`{name}` は {dims} 次元です: 添字が {given} 個あります")
        }
        StErrorKind::IndexOutOfRange(e) => format!("`{e}` は配列の範囲外です"),
        StErrorKind::Mismatch { place, want, found } => {
            let (want, found) = (phrase(want), phrase(found));
            format!("{}は {want} でなければなりません ({found} ではなく)", phrase(place))
        }
        StErrorKind::ExitOutsideLoop => "EXIT はループの中でだけ使えます".into(),
        StErrorKind::ReadOnly(n) => format!(
            "`{n}` には代入できません (定数か、ブロック自身だけが書くブロックの出力です)"
        ),
        StErrorKind::NotCallable(n) => {
            format!("`{n}` は関数でもファンクションブロックのインスタンスでもありません")
        }
        StErrorKind::NoSuchArg { callee, arg } => {
            format!("`{callee}` に入力または出力 `{arg}` はありません")
        }
    }
}

/// The parser's, checker's and lowering's phrases in Japanese; one not
/// in the table (a token as written, a keyword) stays as it is.
fn phrase(english: &str) -> String {
    PHRASES
        .iter()
        .find(|(en, _)| *en == english)
        .map_or_else(|| english.to_string(), |(_, ja)| (*ja).to_string())
}

/// English phrase, Japanese phrase.
const PHRASES: &[(&str, &str)] = &[
    // Where something is expected.
    ("here", "ここに"),
    ("at the top level", "最上位に"),
    ("after AT", "AT の後に"),
    ("as a bound", "範囲の境界として"),
    ("after the expression", "式の後に"),
    ("to close the statements", "文を閉じる"),
    ("to close the CASE", "CASE を閉じる"),
    ("after NOT and an output's name", "NOT と出力の名前の後に"),
    ("after the IF condition", "IF の条件の後に"),
    ("after the FOR range", "FOR の範囲の後に"),
    ("after the WHILE condition", "WHILE の条件の後に"),
    ("to close the IF", "IF を閉じる"),
    ("after the UNTIL condition", "UNTIL の条件の後に"),
    ("after the CASE selector", "CASE のセレクタの後に"),
    ("after the array's bounds", "配列の範囲の後に"),
    ("after the FOR start value", "FOR の開始値の後に"),
    ("the end of the text", "テキストの終わり"),
    // What is expected.
    ("an expression", "式"),
    ("a statement", "文"),
    ("a name", "名前"),
    ("a whole number", "整数"),
    ("an address (%IX0.0)", "アドレス (%IX0.0)"),
    // Where a type is checked.
    ("the IF condition", "IF の条件"),
    ("the value assigned", "代入する値"),
    ("the WHILE condition", "WHILE の条件"),
    ("the UNTIL condition", "UNTIL の条件"),
    ("the initial value", "初期値"),
    ("the operand", "オペランド"),
    ("the right operand", "右のオペランド"),
    ("the FOR variable", "FOR の変数"),
    ("the CASE selector", "CASE のセレクタ"),
    ("an index", "添字"),
    ("an output's target", "出力の行き先"),
    ("`**`'s base", "`**` の底"),
    ("`**`'s power", "`**` の指数"),
    ("a CASE label", "CASE のラベル"),
    ("a FOR bound or step", "FOR の境界や増分"),
    ("an argument", "引数"),
    ("an operand of this operator", "この演算子のオペランド"),
    ("a number", "数"),
    ("an integer", "整数"),
    ("a number or BOOL", "数か BOOL"),
    // Left out of Hashigo's ST.
    ("WSTRING (wide strings)", "WSTRING (ワイド文字列)"),
    ("a pragma `{…}`", "プラグマ `{…}`"),
    // What does not run on the soft PLC yet.
    ("a file without a PROGRAM", "PROGRAM のないファイル"),
    (
        "an assignment to a member or element",
        "メンバーや要素への代入",
    ),
    ("an array element", "配列の要素"),
    (
        "a call of the program's own function here",
        "ここでのプログラム自身の関数の呼び出し",
    ),
    ("a function called without inputs", "入力なしで呼ばれた関数"),
    (
        "an expression of no known type as a function's second or later input (assign it to a variable first)",
        "関数の 2 番目以降の入力としての型の分からない式 (先に変数に代入してください)",
    ),
    (
        "an expression as `**`'s power (assign it to a variable first)",
        "`**` の指数としての式 (先に変数に代入してください)",
    ),
    (
        "an argument past the function's inputs",
        "関数の入力の数を超える引数",
    ),
    ("an output of a function call", "関数呼び出しの出力"),
    (
        "this function's input as an expression",
        "この関数の入力としての式",
    ),
    (
        "this block's input as an expression",
        "このブロックの入力としての式",
    ),
    (
        "a negated output or one to a member",
        "否定された出力、またはメンバーへの出力",
    ),
    ("a block's input by position", "位置によるブロックの入力"),
    ("VAR_IN_OUT in a PROGRAM", "PROGRAM の VAR_IN_OUT"),
    ("VAR_GLOBAL", "VAR_GLOBAL"),
    ("VAR_EXTERNAL", "VAR_EXTERNAL"),
    (
        "a STRUCT or ARRAY as a block's input or output",
        "ブロックの入力や出力としての STRUCT や ARRAY",
    ),
    (
        "a whole STRUCT or ARRAY here (name one value of it)",
        "ここでの STRUCT や ARRAY 全体 (その値の 1 つを指定してください)",
    ),
    (
        "a variable of more than 4096 values",
        "4096 個を超える値を持つ変数",
    ),
    (
        "an index that is an expression (compute it into a variable first)",
        "式である添字 (先に変数に計算してください)",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Every "not yet" phrase the engine's ST lowering writes as a
    /// literal has its Japanese (read from the lowering's source, so a
    /// new phrase fails here until the table has it).
    #[test]
    fn every_lowering_refusal_has_its_japanese() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../engine/src/iec/st");
        let mut missing = Vec::new();
        let mut seen = 0;
        for entry in std::fs::read_dir(dir).expect("the engine's ST sources") {
            let path = entry.expect("an entry").path();
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if !name.starts_with("lower") {
                continue;
            }
            let text = std::fs::read_to_string(&path).expect("a source");
            // `not_yet(span, "…")` and `let what = "…";` on one line.
            for line in text.lines() {
                let quoted =
                    line.contains("not_yet(") || line.trim_start().starts_with("let what = \"");
                let literal = line
                    .split('"')
                    .nth(1)
                    .filter(|_| quoted && line.matches('"').count() >= 2);
                if let Some(p) = literal {
                    seen += 1;
                    if !PHRASES.iter().any(|(en, _)| *en == p) {
                        missing.push(format!("{name}: {p}"));
                    }
                }
            }
        }
        assert!(seen >= 10, "found only {seen} phrases: the scan is broken");
        assert!(missing.is_empty(), "no Japanese for {missing:#?}");
    }

    #[test]
    fn st_refusals_are_said_in_japanese() {
        let e = engine::softplc::Program::load_st(
            "PROGRAM t\nVAR a : ARRAY [1..3] OF INT; i, r : INT; END_VAR\nr := a[4];\nr := a[ABS(i)];\nEND_PROGRAM\n",
        )
        .expect_err("refused");
        let said: Vec<String> = e.iter().map(st_load_ja).collect();
        assert_eq!(said[0], "3 行 6 桁: `A[4]` は配列の範囲外です");
        assert_eq!(
            said[1],
            "4 行 6 桁: 式である添字 (先に変数に計算してください) はまだソフトPLCで動きません"
        );
        let e = engine::softplc::Program::load_st(
            "PROGRAM t\nVAR n : INT; END_VAR\nIF n THEN n := 1; END_IF;\nEND_PROGRAM\n",
        )
        .expect_err("refused");
        assert_eq!(
            st_load_ja(&e[0]),
            "3 行 4 桁: IF の条件は BOOL でなければなりません (INT ではなく)"
        );
    }
}
