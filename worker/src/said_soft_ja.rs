//! The soft PLC's own refusals of a PLCopen project in Japanese (issue
//! #49): its project problems, a block box's wiring, a vendor element
//! that carries logic. Names and element names of the file are kept as
//! written.

use engine::formats::plcopen::soft::error::{DeclarationWhy, SoftError};
use engine::formats::plcopen::BoxProblem;
use engine::iec::functions::FunctionError;
use engine::ladder::block::BoxError;

/// `e` in Japanese.
pub fn soft_ja(e: &SoftError) -> Option<String> {
    use SoftError as S;
    Some(match e {
        S::Declaration(name, why) => format!("変数 {name}: {}", declaration_ja(why)),
        S::Load(e) => crate::said_program_ja::load_ja(e),
        S::BodySection(word) => format!(
            "IL 本体に `{word}` があります: 本体には命令だけを書きます (変数は POU のインタフェースです)"
        ),
        S::Element(el) => element_ja(el),
        S::NoLocalId(el) => format!("<{el}> に localId がありません"),
        S::DuplicateId(id) => format!("localId {id} が 2 回使われています"),
        S::Missing(id) => format!("描かれていない {id} への接続があります"),
        S::Unconnected(what) => format!("{what} がつながっていません"),
        S::ConnectorLoop(name) => format!("コネクタ {name} が自分自身につながっています"),
        S::Feedback(ty) => format!(
            "{ty} ブロック: 型の決まらない配線のループがあります: ループにリテラル (INT#1) を置くか、変数で切ってください"
        ),
        S::Expression(x) => format!("`{x}` は変数・アドレス・リテラルのどれでもありません"),
        S::Undeclared(name) => format!("`{name}` は宣言されていません"),
        S::NotABit(name) => format!("{name} は BOOL の変数ではありません"),
        S::Instance(name, ty) => format!("{name} は {ty} のインスタンスとして宣言されていません"),
        S::Function(ty, FunctionError::Inputs(n)) => format!("{ty}: 入力 {n} 個はとりません"),
        S::Function(ty, FunctionError::Missing(pin)) => {
            format!("{ty}: {pin} がつながっていません")
        }
        S::ProjectBlock(name, how) => format!(
            "{name} はプロジェクト自身の {how} です: ソフト PLC が実行するプロジェクトのファンクションブロックは LD・FBD で描いたものか IL・ST で書いたものです"
        ),
        S::Block(name) if name.eq_ignore_ascii_case("EXECUTE") => format!(
            "{name} は CODESYS のインライン ST のブロックですが、このブロックには ST がありません (STCode がありません)"
        ),
        S::Block(name) => format!(
            "{name} はソフト PLC の標準ブロックではありません (メーカーかライブラリのブロック)"
        ),
        S::NotDrawn(pous) => format!(
            "タスクが実行するプログラムに LD・FBD で描いたもの、IL・ST で書いたものがありません: {pous}"
        ),
        S::NoInput(block, pin, has) => {
            format!("{block} に入力 `{pin}` はありません (入力: {has})")
        }
        S::NoOutput(reader, block, pin, has) => format!(
            "{reader} は {block} の `{pin}` からつながっていますが、その出力はありません (出力: {has})"
        ),
        S::VendorLogic(_) => vendor_logic_ja(),
        S::Follows => "上で拒否された要素からつながっています".into(),
        S::St(column, why) => format!("ST の {column} 桁目: {}", crate::said_st_ja::st_ja(why)),
        S::NoGlobal(ty, name, pou) => format!(
            "{ty} は外部変数として `{name}` を使いますが、{pou} に渡す `{name}` がありません: `{name}` を構成かリソースの globalVars に宣言してください ({ty} を呼ぶブロックには外部変数としても)"
        ),
        S::UndeclaredInstance(name, ty) => format!(
            "{name} は宣言されていません: POU の変数に {ty} のインスタンスとして宣言してください (`{name} : {ty};`)"
        ),
    })
}

/// Why a declaration does not run on the soft PLC, in Japanese.
fn declaration_ja(why: &DeclarationWhy) -> String {
    use crate::said_iec_ja::{address_ja, literal_ja};
    match why {
        DeclarationWhy::NotIecName => {
            "IEC の名前ではありません (英字か _ で始め、英数字と _ で書きます)".into()
        }
        DeclarationWhy::NoType => "型がありません".into(),
        DeclarationWhy::UnknownType(t) => format!("型 {t} はソフトPLCにありません"),
        DeclarationWhy::Address(e) => address_ja(e),
        DeclarationWhy::Initial(e) => literal_ja(e),
        DeclarationWhy::Section(scope) => {
            format!("ファンクションブロックの {scope} にはまだ対応していません")
        }
        DeclarationWhy::ExternalBlock => {
            "ファンクションブロックの外部変数にブロックのインスタンスはまだ使えません (外部変数は値で、呼び出しのたびにコピーされます)".into()
        }
    }
}

/// An element the soft PLC does not run, with why when the kind says.
fn element_ja(el: &str) -> String {
    let why = match el {
        "vendorElement" => " (ファイルを書いたツールの要素)",
        "jump" | "label" | "return" => " (ジャンプはまだ実行しません)",
        "actionBlock"
        | "step"
        | "transition"
        | "selectionDivergence"
        | "selectionConvergence"
        | "simultaneousDivergence"
        | "simultaneousConvergence"
        | "macroStep" => " (SFC は実行しません)",
        _ => "",
    };
    format!("<{el}> はソフト PLC で実行できません{why}")
}

/// A block box's problem in Japanese: its wiring or the box's own.
pub fn box_ja(what: &str, problem: &BoxProblem) -> Option<String> {
    let why = match problem {
        BoxProblem::Box(e) => box_error_ja(e),
        BoxProblem::FedByElement(pin) => format!(
            "入力 {pin} が別の要素から直接つながっています: ページはボックスのデータ入力をオペランドとして描くので、間に変数 (outVariable と inVariable) を置いてください"
        ),
        BoxProblem::OutputToPower(pin) => format!(
            "出力 {pin} が接点かコイルにつながっています: 変数 (outVariable) に書いて、それを読んでください"
        ),
        BoxProblem::NegatedOperand(pin) => format!(
            "入力 {pin} の変数が反転されています: 代わりに NOT ブロックを置いてください"
        ),
        BoxProblem::EnableWired => "EN がつながっています: ソフト PLC のブロックは毎スキャン実行します: EN は左の母線につなぐか、開けておいてください".into(),
    };
    Some(format!("{what}: {why}"))
}

/// A box's own refusal in Japanese: the worker says it for a box in a
/// file, the page (`app/src/i18n/engine.rs`) for a box drawn on it.
pub fn box_error_ja(e: &BoxError) -> String {
    match e {
        BoxError::UnknownKind(k) => format!("{k} はソフトPLCの関数でもブロックでもありません"),
        BoxError::NoInstance(k) => format!("{k} ボックスにはインスタンス名が必要です (TON0)"),
        BoxError::FunctionInstance(k) => format!("{k} は関数です: インスタンスはありません"),
        BoxError::NoSuchInput(k, pin, takes) => {
            format!("{k} に入力 {pin} はありません (入力: {takes})")
        }
        BoxError::BadOperand(t) => format!("`{t}` は変数でもアドレスでもリテラルでもありません"),
        BoxError::NotWired(k, pin) => format!("{k} の {pin} がつながっていません"),
        BoxError::NoSuchOutput(k, pin) => format!("{k} に出力 {pin} はありません"),
        BoxError::NotAVariable(k, pin, t) => {
            format!("{k} の {pin} の書き込み先 {t:?} は変数かアドレスにしてください")
        }
    }
}

/// A vendor element that carries logic. Its reason is left out (the
/// engine gives it in words): the line says which element.
pub fn vendor_logic_ja() -> String {
    "<vendorElement> が処理を持っています: ファイルを書いたツールの要素で、Hashigo では実行できません".into()
}

#[cfg(test)]
pub(crate) mod tests {
    use engine::formats::plcopen::soft::error::{DeclarationWhy as D, SoftError};
    use engine::formats::plcopen::{BoxProblem, ImportError};
    use engine::iec::functions::FunctionError;
    use engine::iec::{AddressError, LiteralError};
    use engine::ladder::block::BoxError;
    use engine::ladder::variables::VariableError;
    use engine::softplc::program::{CallWhy, TypeWhy};
    use engine::softplc::LoadError;

    /// One of each soft PLC refusal [`super::soft_ja`] says, as the
    /// import gives it.
    pub(crate) fn every_soft() -> Vec<ImportError> {
        let s = || "X".to_string();
        let soft = [
            SoftError::Element(s()),
            SoftError::Element("vendorElement".into()),
            SoftError::Element("jump".into()),
            SoftError::Element("step".into()),
            SoftError::NoLocalId(s()),
            SoftError::DuplicateId(s()),
            SoftError::Missing(s()),
            SoftError::Unconnected(s()),
            SoftError::ConnectorLoop(s()),
            SoftError::Feedback(s()),
            SoftError::Expression(s()),
            SoftError::Undeclared(s()),
            SoftError::NotABit(s()),
            SoftError::Instance(s(), s()),
            SoftError::Function(s(), FunctionError::Inputs(3)),
            SoftError::Function(s(), FunctionError::Missing("IN")),
            SoftError::ProjectBlock(s(), s()),
            SoftError::Block(s()),
            SoftError::Block("EXECUTE".into()),
            SoftError::NotDrawn(s()),
            SoftError::NoInput(s(), s(), s()),
            SoftError::NoOutput(s(), s(), s(), s()),
            SoftError::Follows,
            SoftError::VendorLogic("it is wired into the network".into()),
            SoftError::UndeclaredInstance(s(), s()),
            SoftError::NoGlobal(s(), s(), s()),
            SoftError::BodySection("VAR_INPUT".into()),
            SoftError::Load(LoadError::Type(TypeWhy::SelectOneType)),
            SoftError::Load(LoadError::Call(CallWhy::BodySteps)),
            SoftError::Load(LoadError::Undeclared(s())),
            SoftError::Declaration(s(), D::NotIecName),
            SoftError::Declaration(s(), D::NoType),
            SoftError::Declaration(s(), D::UnknownType("BYTE".into())),
            SoftError::Declaration(s(), D::Address(AddressError::NoArea(s()))),
            SoftError::Declaration(s(), D::Initial(LiteralError::BadNumber(s()))),
            SoftError::Declaration(String::new(), D::Section("inOutVars".into())),
            SoftError::Declaration(s(), D::ExternalBlock),
        ];
        let mut all: Vec<ImportError> = soft.into_iter().map(ImportError::Soft).collect();
        let boxes = [
            BoxProblem::FedByElement("IN1".into()),
            BoxProblem::OutputToPower("OUT".into()),
            BoxProblem::NegatedOperand("IN2".into()),
            BoxProblem::EnableWired,
            BoxProblem::Box(BoxError::UnknownKind(s())),
            BoxProblem::Box(BoxError::NoInstance(s())),
            BoxProblem::Box(BoxError::FunctionInstance(s())),
            BoxProblem::Box(BoxError::NoSuchInput(s(), s(), s())),
            BoxProblem::Box(BoxError::BadOperand(s())),
            BoxProblem::Box(BoxError::NotWired(s(), s())),
            BoxProblem::Box(BoxError::NoSuchOutput(s(), s())),
            BoxProblem::Box(BoxError::NotAVariable(s(), s(), s())),
        ];
        all.extend(boxes.into_iter().map(|p| ImportError::SoftBox(s(), p)));
        all.push(ImportError::VendorLogic(
            "it is wired into the network".into(),
        ));
        all.extend(every_gate());
        let variables = [
            VariableError::BadName(s()),
            VariableError::Address(s(), AddressError::BitOutOfRange(s())),
            VariableError::Initial(s(), LiteralError::Empty),
            VariableError::BlockWithValue(s(), "TON".into()),
            VariableError::UnknownType(s(), s()),
        ];
        all.extend(variables.into_iter().map(ImportError::SoftVariable));
        all
    }

    /// One of each reason a gate is refused for.
    fn every_gate() -> Vec<ImportError> {
        use engine::formats::plcopen::gate_why::{GateWhy as G, OperandWhy as O};
        let s = || "X".to_string();
        let gates = [
            G::NeedsRelay(s()),
            G::Negated(s()),
            G::Edge(s(), "rising"),
            G::NoInput(s(), s()),
            G::EnableWired,
            G::NeedsTwo,
            G::CounterWired("CD"),
            G::Inputs(1, "GT".into(), false),
            G::Inputs(3, "NE".into(), true),
            G::InputsOrder(s()),
            G::Operand("IN1", s(), O::NotNumber),
            G::Operand("IN1", s(), O::Declared("BOOL".into())),
            G::Operand("IN1", s(), O::NoWord(s())),
        ];
        let gate = |why| ImportError::Gate("SR block X".into(), why);
        gates.into_iter().map(gate).collect()
    }
}
