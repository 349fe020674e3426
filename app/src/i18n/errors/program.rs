//! The soft PLC's program text errors (declarations, IL, function
//! blocks) in Japanese. Keywords and names are kept as written.

use engine::iec::il::IlError;
use engine::iec::VarError;
use engine::softplc::pou::PouError;
use engine::softplc::LoadError;

use super::edit::{address_ja, literal_ja};

/// Why a soft PLC program does not load, in Japanese. A type or call
/// problem the engine says only in words keeps them (the rarer ones:
/// not yet typed).
pub fn load_ja(e: &LoadError) -> String {
    match e {
        LoadError::Var(e) => var_ja(e),
        LoadError::Il(e) => il_ja(e),
        LoadError::Undeclared(n) => format!("`{n}` は宣言されていません"),
        LoadError::UntypedAddress(a) => format!("{a}: ソフトPLCにはバイト型がありません"),
        LoadError::NoLabel(l) => format!("ラベル `{l}` の行がありません"),
        LoadError::Type(why) | LoadError::Call(why) => why.clone(),
        LoadError::UnknownResult => {
            "ここでは現在値がわかりません (ラベルやジャンプの後): LD で始めてください".into()
        }
        LoadError::Unbalanced => "`(` と `)` が対になっていません".into(),
        LoadError::Unclosed => "この `(` が `)` で閉じられていません".into(),
        LoadError::Pou(e) => pou_ja(e),
        LoadError::Mix(a, b) => format!(
            "{} と {} は混ぜられません: 一方を変換してください (*_TO_*)",
            a.name(),
            b.name()
        ),
        LoadError::NotBits(op, t) => {
            format!(
                "{op} には BOOL かビット列が必要です ({} は使えません)",
                t.name()
            )
        }
        LoadError::NotFor(t) => format!("この演算は {} には使えません", t.name()),
        LoadError::NeedsBool(op) => format!("{op} には BOOL の現在値が必要です"),
        LoadError::NoPin { block, pin, output } => {
            let side = if *output { "出力" } else { "入力" };
            format!("{block} に{side} `{pin}` はありません")
        }
        LoadError::NotAnInstance(n) => format!("`{n}` はブロックのインスタンスではありません"),
    }
}

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

fn pou_ja(e: &PouError) -> String {
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

/// A line of MINASEC-U's program text refused, in Japanese (mnemonics
/// and what the line says kept as written).
pub fn minasec_asm_ja(e: &engine::minasec::AsmError) -> String {
    use engine::minasec::asm::STEPS;
    use engine::minasec::AsmError as A;
    use engine::shown;
    match e {
        A::TooManyLines(n) => format!(
            "プログラムが {n} 行あり、上限 {} 行を超えています",
            engine::limits::MAX_PROGRAM_LINES
        ),
        A::BadStepNumber(n) => format!("不正なステップ番号 {}: ステップは 0..255 です", shown(n)),
        A::StepOutOfOrder { found, expected } => {
            format!("ステップ {found} の順序が違います: ここは {expected} 以降です")
        }
        A::MissingOpcode => "ステップ番号だけで命令がありません".into(),
        A::UnknownOpcode(w) => format!(
            "不明な命令 {}: MINASEC-U の命令は LD LDI AND ANDI OR ORI ST STI です",
            shown(w)
        ),
        A::MissingOperand(op) => format!("{op} にはオペランドが必要です ({op} X00 など)"),
        A::Operand(e) => super::super::engine::element_ja(
            &engine::ladder::target::ElementError::Minasec(e.clone()),
        ),
        A::Unexpected(w) => format!(
            "オペランドの後に {} があります (2 進の欄は 8 ビット: 100 01000 など)",
            shown(w)
        ),
        A::BinaryMismatch { written, expected } => {
            format!("2 進 {written} が命令と合いません: 命令は {expected} です")
        }
        A::TooManySteps(n) => {
            format!("ステップが多すぎます: プログラムは {n} ステップ、MINASEC-U は {STEPS} です")
        }
    }
}
