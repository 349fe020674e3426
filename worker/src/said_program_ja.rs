//! A soft PLC program that does not load, in Japanese (issue #49): the
//! loader's kinds with their arguments, written once for the page and
//! the files worker. Keywords, types and names are kept as written.

use engine::runtime::ldmicro::format::FormatError;
use engine::runtime::ldmicro::printf::PrintfError;
use engine::softplc::program::{
    CallWhy, TypeWhy, MAX_BLOCK_NESTING, MAX_BODY_STEPS, MAX_INSTANCES, MAX_INSTANCE_VARIABLES,
};
use engine::softplc::LoadError;

use crate::said_iec_ja::{il_ja, literal_ja, pou_ja, var_ja};

/// Why a soft PLC program does not load, in Japanese.
pub fn load_ja(e: &LoadError) -> String {
    match e {
        LoadError::Var(e) => var_ja(e),
        LoadError::Il(e) => il_ja(e),
        LoadError::Undeclared(n) => format!("`{n}` は宣言されていません"),
        LoadError::UntypedAddress(a) => format!("{a}: ソフトPLCにはバイト型がありません"),
        LoadError::NoLabel(l) => format!("ラベル `{l}` の行がありません"),
        LoadError::Type(why) => type_ja(why),
        LoadError::Call(why) => call_ja(why),
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
        LoadError::BadElement(e) => format!(
            "`{e}`: 要素オペランドは LD と ST だけが取り、添字は整数の変数、要素はすべて宣言済みで同じ型でなければなりません"
        ),
    }
}

/// An instruction's types that do not fit, in Japanese.
pub fn type_ja(e: &TypeWhy) -> String {
    use TypeWhy as T;
    match e {
        T::NegNumber => "NEG には数が必要です".into(),
        T::ShiftIntegers => "SHL, SHR, ROL, ROR は整数を整数ぶんシフトします".into(),
        T::StringConversion => "STRING との変換はソフトPLCではまだ実行できません".into(),
        T::Convert { current, from } => format!(
            "現在値は {} で、{} ではありません",
            current.name(),
            from.name()
        ),
        T::SelectBool => "SEL の最初の入力 (現在値) は BOOL です".into(),
        T::SelectOneType => "SEL の 2 つの値は同じ型にしてください".into(),
        T::TextInput { block, pin } => {
            format!("{block} の {pin} は文字列です: '…' と書いてください")
        }
        T::Pin { block, pin, is } => format!("{block} の {pin} は {} です", is.name()),
        T::NotInstance { name, pin } => format!(
            "`{name}` はブロックのインスタンスではありません: `{name}.{pin}` はブロックの出力を読みます"
        ),
        T::ReadOnly(what) => {
            format!("`{what}` はブロックの出力です: 読むだけで、書き込めません")
        }
        T::JumpBrings {
            line,
            label,
            used,
            brings,
        } => {
            let brings = match brings {
                Some(t) => format!("このジャンプは {} を持ってきます", t.name()),
                None => "このジャンプでは現在値がわかりません".into(),
            };
            format!(
                "{line} 行目 (ラベル `{label}` の後) は現在値を {} として使いますが、{brings}: 型をそろえるか、そこを LD で始めてください",
                used.name()
            )
        }
        T::LabelTypes { label, types } => format!(
            "現在値がラベル `{label}` に {} と {} で届きます: 型をそろえる (*_TO_*) か、LD で始めてください",
            types.0.name(),
            types.1.name()
        ),
        T::Text(e) => literal_ja(e),
        T::BlockAsValue(n) => format!(
            "`{n}` はブロックのインスタンスで、値ではありません: その出力を読んでください (`{n}.Q`)"
        ),
        T::StoreLiteral => "値を格納するのは変数で、リテラルには格納できません".into(),
        T::SetBool { op, what, is } => format!(
            "{op} は BOOL をセット・リセットします: {what} は {} です",
            is.name()
        ),
        T::Store {
            current,
            what,
            needs,
        } => format!(
            "現在値は {} ですが、{what} には {} が必要です",
            current.name(),
            needs.name()
        ),
    }
}

/// A call that does not fit, in Japanese.
pub fn call_ja(e: &CallWhy) -> String {
    use CallWhy as C;
    match e {
        C::NeedsInstance => "CAL にはブロックのインスタンスが必要です".into(),
        C::Printf { pin, error } => format!("{pin}: {}", printf_ja(error)),
        C::Format { pin, error } => format!("{pin}: {}", format_ja(error)),
        C::TextTwice { instance, pin } => format!(
            "{instance} にはすでに別の文字列があります: {pin} はインスタンスごとに 1 つです"
        ),
        C::NotVariable(target) => format!("`{target}` は変数ではありません"),
        C::InputRead {
            instance,
            pin,
            block,
        } => format!(
            "`{instance}.{pin}`: {pin} は {block} の入力です: ソフトPLCではブロックの入力は CAL で与え (CAL {instance}({pin} := …))、読めるのは出力だけです"
        ),
        C::Instances(name) => format!(
            "{name}: プログラム自身のブロックのインスタンスが上限 {MAX_INSTANCES} 個を超えます"
        ),
        C::Nesting { name, holds } => {
            let holds = holds
                .as_ref()
                .map_or(String::new(), |t| format!(" ({t} が自分自身を持っていませんか?)"));
            format!(
                "{name}: ファンクションブロックのインスタンスの入れ子が {MAX_BLOCK_NESTING} 段を超えます{holds}"
            )
        }
        C::BodySteps => format!(
            "インスタンスのためのブロック本体のステップが上限 {MAX_BODY_STEPS} を超えます"
        ),
        C::Variables(name) => format!(
            "{name}: プログラム自身のブロックのインスタンスの変数が上限 {MAX_INSTANCE_VARIABLES} 個を超えます"
        ),
    }
}

/// A C format (LDmicro's STRING element's) refused, in Japanese.
pub fn printf_ja(e: &PrintfError) -> String {
    match e {
        PrintfError::Conversion(c) => {
            format!("`{c}` は整数を表示しません: 使えるのは %d %i %u %x %X %o %c と %% です")
        }
        PrintfError::Second => "2 つ目の % があります: STRING が表示する変数は 1 つです".into(),
        PrintfError::Star => "* の幅・精度には 2 つ目の引数が必要です".into(),
        PrintfError::NoValue => "値 (%…) を表示しますが、変数が指定されていません".into(),
        PrintfError::Length(c) => format!(
            "`{c}`: 長さ指定は h, hh, l, ll で、%d %i %u %x %X %o に付けます (%c には付けません)"
        ),
    }
}

/// A formatted string (LDmicro's) refused, in Japanese.
pub fn format_ja(e: &FormatError) -> String {
    match e {
        FormatError::TwoNumbers => {
            "書式文字列に入る数は 1 つです (`\\3`, `\\-5`): 2 つはありません".into()
        }
        FormatError::BadEscape(x) => format!(
            "`\\{x}` は書式文字列のエスケープではありません (\\r \\n \\t \\a \\b \\e \\f \\v \\\\ \\xAB、数には \\1 … \\5 と \\-1 … \\-5): バックスラッシュは `\\\\` と書きます"
        ),
        FormatError::NoVariable => {
            "書式文字列は数 (`\\3`) を表示しますが、値を取る変数がありません".into()
        }
        FormatError::NoNumber => {
            "変数が指定されていますが、書式文字列にそれを表示する `\\3` や `\\-5` がありません".into()
        }
        FormatError::NotAByte(c) => format!(
            "`{c}` は 1 バイトではありません: 書式文字列はバイトで送られます (`\\xAB` と書いてください)"
        ),
    }
}
