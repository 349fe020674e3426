//! The IEC texts' refusals in Japanese: a declaration, an IL line, a
//! function block's sections, an address, a literal, a soft PLC
//! ladder's variable. Written once for the page and the files worker
//! (the page calls these; issue #49). Keywords and names are kept as
//! written.

use engine::iec::il::IlError;
use engine::iec::{AddressError, LiteralError, VarError};
use engine::ladder::variables::VariableError;
use engine::softplc::pou::PouError;

/// A declaration refused, in Japanese.
pub fn var_ja(e: &VarError) -> String {
    use engine::iec::data::STRING_CAPACITY;
    match e {
        VarError::Syntax(l) => {
            format!("`{l}` は宣言ではありません (名前 [AT %アドレス] : 型 [:= 値];)")
        }
        VarError::BadName(n) => {
            format!("`{n}` は名前ではありません (英字か _ で始め、英数字と _ で書きます)")
        }
        VarError::Duplicate { name, first } => {
            format!("`{name}` が 2 回宣言されています (最初は {first} 行目)")
        }
        VarError::UnknownType(t) => format!("不明な型 `{t}`"),
        VarError::StringLength(t) => format!(
            "`{t}`: STRING は長さなしで書きます (どの STRING も最大 {STRING_CAPACITY} 文字です)"
        ),
        VarError::Address(e) => address_ja(e),
        VarError::Literal(e) => literal_ja(e),
        VarError::BlockWithValue(n) => {
            format!("`{n}` はファンクションブロックです: アドレスも値も持ちません")
        }
        VarError::Unbalanced(w) => format!("`{w}` の対がありません"),
    }
}

/// A line that is not IL, in Japanese.
pub fn il_ja(e: &IlError) -> String {
    match e {
        IlError::UnknownOperator(o) => format!("不明な命令 `{o}`"),
        IlError::BadModifier(o) => format!("`{o}`: この命令にその修飾子はありません"),
        IlError::LabelAlone => "ラベルの行には命令も書いてください".into(),
        IlError::NoOperand(w) => format!("`{w}` はオペランドを取りません"),
        IlError::NeedsLabel(w) => format!("`{w}` にはラベルが必要です"),
        IlError::NeedsOperand(w) => format!("`{w}` にはオペランドが必要です"),
        IlError::OperandCount(w, n) => {
            format!("`{w}` は現在値の後に {n} 個のオペランドを取ります")
        }
        IlError::BadName(n) => format!("`{n}` は名前ではありません"),
        IlError::Address(e) => address_ja(e),
        IlError::Literal(e) => literal_ja(e),
        IlError::BadCall(c) => {
            format!("`{c}`: 呼び出しは CAL 名前(入力 := 値, 出力 => 変数) と書きます")
        }
        IlError::OpenComment => "コメント `(*` が `*)` で閉じられていません".into(),
        IlError::DuplicateLabel { label, first } => {
            format!("ラベル `{label}` が 2 回使われています (最初は {first} 行目)")
        }
        IlError::SecondProgram(first) => format!(
            "2 つ目の PROGRAM です: 1 つのテキストには 1 つのプログラムです (最初は {first} 行目)"
        ),
        IlError::TwiceGiven(p) => format!("入力 `{p}` が 2 回与えられています"),
        IlError::EmptyParameter => {
            "空のパラメータがあります: 名前 := 値 か 名前 => 変数 と書きます".into()
        }
    }
}

pub fn pou_ja(e: &PouError) -> String {
    match e {
        PouError::BadName(n) => format!("`{n}` はファンクションブロックの名前ではありません"),
        PouError::Nested => "FUNCTION_BLOCK の中に別の FUNCTION_BLOCK があります".into(),
        PouError::NoStart => "FUNCTION_BLOCK のない END_FUNCTION_BLOCK です".into(),
        PouError::NeverEnded(n) => format!("FUNCTION_BLOCK {n} に END_FUNCTION_BLOCK がありません"),
        PouError::Duplicate { name, first } => {
            format!("ファンクションブロック {name} が 2 回定義されています (最初は {first} 行目)")
        }
    }
}

/// A soft PLC ladder's declaration refused, in Japanese.
pub fn variable_ja(e: &VariableError) -> String {
    match e {
        VariableError::BadName(n) => {
            format!("`{n}` は名前ではありません (英字か _ で始め、英数字と _ で書きます)")
        }
        VariableError::Address(n, e) => format!("{n}: {}", address_ja(e)),
        VariableError::Initial(n, e) => format!("{n}: {}", literal_ja(e)),
        VariableError::BlockWithValue(n, t) => {
            format!("{n} は {t} です: アドレスも値も持ちません")
        }
        VariableError::UnknownType(n, t) => format!("{n}: 不明な型 `{t}`"),
    }
}

/// An IEC address refused, in Japanese.
pub fn address_ja(e: &AddressError) -> String {
    match e {
        AddressError::NoArea(a) => {
            format!("`{a}` はアドレスではありません (%I, %Q, %M: %IX0.0, %QW2 など)")
        }
        AddressError::BadSize(a) => {
            format!("`{a}`: %I, %Q, %M の後のサイズは X, B, W, D, L のどれかです")
        }
        AddressError::BadNumber(a) => {
            format!("`{a}`: ビットは バイト.ビット (%IX0.1)、ワードは数 1 つ (%QW2) で書きます")
        }
        AddressError::BitOutOfRange(a) => format!("`{a}`: ビット番号は 0-7 です"),
        AddressError::WrongType { address, data_type } => {
            format!("{} 型は {address} に置けません", data_type.name())
        }
    }
}

/// An IEC literal refused, in Japanese.
pub fn literal_ja(e: &LiteralError) -> String {
    use engine::iec::data::STRING_CAPACITY;
    match e {
        LiteralError::Empty => "値がありません".into(),
        LiteralError::UnknownType(t) => format!("不明な型 `{t}`"),
        LiteralError::BadNumber(t) => format!("`{t}` は数ではありません"),
        LiteralError::OutOfRange { text, data_type } => {
            format!("`{text}` は {} の範囲外です", data_type.name())
        }
        LiteralError::BadTime(t) => {
            format!("`{t}` は時間ではありません (T#500ms, T#1h2m3.5s など)")
        }
        LiteralError::WrongType { text, expected } => {
            format!("`{text}` は {} の値ではありません", expected.name())
        }
        LiteralError::BadText(t) => format!(
            "`{t}` は文字列ではありません: ' で囲み、' は $'、$ は $$ と書きます"
        ),
        LiteralError::TooLong(n) => format!(
            "STRING は最大 {STRING_CAPACITY} 文字です: この文字列は {n} 文字です"
        ),
        LiteralError::WideChar(c) => format!(
            "`{c}` (U+{:04X}) は 1 バイトの文字ではありません: STRING は U+0000 … U+00FF を持ちます",
            u32::from(*c)
        ),
    }
}
