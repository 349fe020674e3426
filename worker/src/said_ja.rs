//! A PLCopen import error in Japanese (issue #49), made here from its
//! kind and arguments because the typed error does not cross to the
//! page (only text does); the page shows it in Japanese mode, the
//! English (`ImportError::in_page`) otherwise. A machine's refusal of an
//! element crosses typed ([`crate::Said::cause`]) and the page says it.
//! Names, ids and element names of the file are kept as written; the XML
//! parser's own words (English, about the file's syntax) are left out:
//! the line says where.

use engine::formats::plcopen::declare::NameError;
use engine::formats::plcopen::error::{Connection, LowerError};
use engine::formats::plcopen::{ImportError, XmlError};
use engine::ladder::net::NetError;
use engine::limits::{MAX_CONNECTOR_CHAIN, MAX_GATE_WORK, MAX_RUNGS, MAX_RUNG_CELLS};
use engine::shown;

use crate::said_soft_ja::{box_ja, soft_ja, vendor_logic_ja};

/// `e` in Japanese, or `None` for a kind said elsewhere (a machine's
/// refusal of an element, typed: [`crate::Said::cause`]).
pub fn import_ja(e: &ImportError) -> Option<String> {
    use ImportError as E;
    Some(match e {
        E::Xml(e) => xml_ja(e),
        E::NotAProject(root) => {
            format!("PLCopen のプロジェクトではありません: ルート要素が <{root}> です")
        }
        E::Namespace(ns) => format!("名前空間 {} は PLCopen TC6 のものではありません", shown(ns)),
        E::NoDrawnBody(pous) => format!(
            "LD か FBD の本体を持つ POU がありません ({pous}): Hashigo が読み込むのはラダー (LD) とファンクションブロック図 (FBD) です"
        ),
        E::TooManyRungs => format!("回路が {MAX_RUNGS} を超えています"),
        E::Drawing(t) => format!(
            "この回路はラダーにすると {} 行 {} 列になり、上限 {MAX_RUNG_CELLS} セルを超えます",
            t.rows, t.columns
        ),
        E::NoLocalId(el) => format!("<{el}> に localId がありません"),
        E::DuplicateLocalId { id, first } => format!(
            "localId {} がまた使われています (最初は {first} 行目): 要素ごとに別の id が必要です",
            shown(id)
        ),
        E::DuplicateConnector { name, first } => format!(
            "コネクタ {} がまた描かれています (最初は {first} 行目)",
            shown(name)
        ),
        E::Connection { what, problem } => connection_ja(what, problem),
        E::NoVariable(kind) => format!("変数のない {kind} があります"),
        E::Variable(why) => name_ja(why),
        E::Lower(what, why) => format!("{what}: {}", lower_ja(why)),
        E::NoSuchPou(name, all) => format!("POU {name} はありません: ファイルの POU は {all} です"),
        E::NoDrawnInPrograms(run, ld) => format!(
            "タスクが実行するプログラム ({run}) には LD も FBD の本体もありません: 本体のある POU は {ld} です (プログラムで選んでください)"
        ),
        E::NegatedEdge(d) => format!("接点 {d}: 反転したエッジ接点はラダーにできません"),
        E::CoilMix(d) => {
            format!("コイル {d}: 反転・保持・エッジの組み合わせはラダーにできません")
        }
        E::NotBoolean(v) => format!(
            "negated={} は真偽値ではありません: true, false, 1, 0 のどれかです",
            shown(v)
        ),
        E::BadEdge(v) => format!("edge={} は none, rising, falling のどれでもありません", shown(v)),
        E::BadStorage(v) => format!("storage={} は none, set, reset のどれでもありません", shown(v)),
        E::WordOutput(el) => format!(
            "<{el}> は読み込みません: Hashigo のラダーにはブロックからのワード出力がありません"
        ),
        E::Unsupported(el) => format!("<{el}> はここの LD・FBD 本体では扱えません"),
        E::UnsupportedBlock(ty) => {
            format!("ブロック {} は扱えません", shown(ty).trim_matches('"'))
        }
        E::SoftVariableTwice { name, first, types } => format!(
            "{name} がここでは {}、{first} 行目では {} と宣言されています: ラダーの変数は 1 組です",
            types.1, types.0
        ),
        E::ProjectBlock(name, language) => format!(
            "ブロック {name} はプロジェクト自身の {language} ファンクションブロックを呼んでいます: ラダーのボックスになるのはプロジェクトの ST のファンクションブロック (ピンが基本型で、入出力ピンのないもの) です (LD か FBD ならプログラムで {name} を選んでください)"
        ),
        E::PinNotConnected(..)
        | E::PinNotLiteral(..)
        | E::BadTimeLiteral(..)
        | E::BadCounterPreset(..)
        | E::CounterQWired(_)
        | E::TimerName(_)
        | E::TimerUnits { .. }
        | E::TimerTooLong(..) => return blocks_ja(e),
        E::OnRail(el) => {
            format!("{el} が左の母線に直接つながっています: 前に接点を置いてください")
        }
        E::NoPath(el) => format!("左の母線から {el} への経路がありません"),
        E::Net(_) => return blocks_ja(e),
        E::VendorLogic(_) => vendor_logic_ja(),
        E::Soft(e) => return soft_ja(e),
        E::SoftBox(what, problem) => return box_ja(what, problem),
        E::Gate(what, why) => crate::said_gate_ja::gate_ja(what, why),
        E::SoftVariable(e) => format!("変数 {}", crate::said_iec_ja::variable_ja(e)),
        E::Element(_) => return None,
    })
}

/// A block's pins, a timer's or a counter's problem, or a network's, in
/// Japanese (the kinds [`import_ja`] gives here).
fn blocks_ja(e: &ImportError) -> Option<String> {
    use ImportError as E;
    Some(match e {
        E::PinNotConnected(what, pin) => format!("{what}: 入力 {pin} がつながっていません"),
        E::PinNotLiteral(what, pin) => {
            format!("{what}: 入力 {pin} はリテラル (inVariable) から与えてください")
        }
        E::BadTimeLiteral(what, expr) => format!(
            "{what}: PT {} は T#500ms のような時間リテラルではありません",
            shown(expr)
        ),
        E::BadCounterPreset(what, expr) => format!(
            "{what}: PV {} は 1..32767 の整数ではありません",
            shown(expr)
        ),
        E::CounterQWired(d) => format!(
            "CTU {d}: Q をつなぐ代わりに {d} の接点でカウンタを読んでください"
        ),
        E::TimerName(name) => format!(
            "TON {name}: Q が何も駆動しないのでタイマコイルになり、タイマの名前 (T00-T31) が必要です"
        ),
        E::TimerUnits { name, ms, base } => format!(
            "TON {name}: {ms} ms は {name} の単位 {base} ms の整数倍ではありません"
        ),
        E::TimerTooLong(name, ms) => format!("TON {name}: {ms} ms は長すぎます"),
        E::Net(NetError::NotSeriesParallel(_)) => {
            "この回路は直列・並列になっていません: Hashigo のラダーは直列と並列のブロックです".into()
        }
        E::Net(NetError::TooDeep(_)) => "直列と並列のブロックの入れ子が深すぎます".into(),
        E::Net(NetError::NoPath) => "左の母線から出力への接点の経路がありません".into(),
        _ => return None,
    })
}

fn xml_ja(e: &XmlError) -> String {
    use engine::limits::MAX_INPUT_BYTES;
    match e {
        XmlError::TooLarge(n) => format!(
            "ファイルが {n} バイトあり、PLCopen ファイルの上限 {MAX_INPUT_BYTES} バイトを超えています"
        ),
        XmlError::NotWellFormed(_) => "XML の形が正しくありません".into(),
        XmlError::BadAttribute(el, _) => format!("<{el}> の属性が正しくありません"),
        XmlError::BadText(_) => "文字列が正しくありません".into(),
        XmlError::EndWithoutStart => "開始タグのない終了タグがあります".into(),
        XmlError::NeverClosed(el) => format!("<{el}> が閉じられていません"),
        XmlError::Empty => "XML の要素がありません".into(),
        XmlError::TooDeep => "要素の入れ子が深すぎます".into(),
        XmlError::TooManyAttributes(el) => format!("<{el}> の属性が多すぎます"),
        XmlError::DuplicateAttribute(el, a) => {
            format!("<{el}> の属性 `{a}` が 2 回書かれています")
        }
        XmlError::SecondRoot(el) => format!(
            "2 つ目のルート要素 <{el}>: XML ファイルが持つ要素はプロジェクト 1 つです"
        ),
    }
}

fn name_ja(e: &NameError) -> String {
    match e {
        NameError::Unmapped { declared, line } => format!(
            "変数 {declared} ({line} 行目で宣言) にデバイスがありません: アドレス (%IX0.0, %QX0.0, %MX0.0) を与えるか、表でデバイスを割り当ててください"
        ),
        // The address's own refusal is in words only: its place here.
        NameError::Refused { declared, line, .. } => format!(
            "変数 {declared} ({line} 行目): このマシンにはそのアドレスのデバイスがありません"
        ),
    }
}

fn lower_ja(e: &LowerError) -> String {
    match e {
        LowerError::NoPin(pin) => format!("{pin} がありません"),
        LowerError::XorInputs => "3 入力以上の XOR です: 分岐を描いてください".into(),
        LowerError::FlipPins => "フリップフロップには S と R があります".into(),
        LowerError::NoCompare => {
            "比較には IO86A の CMP とフラグ M60-M62 が必要です".into()
        }
        LowerError::NotCounter => "カウンタではありません".into(),
        LowerError::NoRelay => {
            "一部を保持するリレーが必要ですが空きがありません: リレーに割り当てる名前を減らしてください"
                .into()
        }
        LowerError::Contact(_) => "この接点は必要な種類にできません".into(),
        LowerError::OrNotJoined => "OR は線の結合で組み立てます".into(),
        LowerError::TooMuchWork => format!(
            "ファイルのブロックを組み立てるのに {MAX_GATE_WORK} ステップを超えます"
        ),
    }
}

fn connection_ja(what: &str, problem: &Connection) -> String {
    match problem {
        Connection::NoRef => format!("{what} の接続に refLocalId がありません"),
        Connection::Missing(r) => {
            format!("{what} がつながる localId {} はありません", shown(r))
        }
        Connection::FromVariable(r) => format!(
            "{what} が変数ボックス (localId {}) から電源を取っています: 母線から接点を通してつないでください",
            shown(r)
        ),
        Connection::Unconnected => format!("{what} の左側がつながっていません"),
        Connection::NoConnector(name) => format!(
            "{what} が継続 {} から電源を取っていますが、そのコネクタが描かれていません",
            shown(name)
        ),
        Connection::ConnectorChain(name) => format!(
            "{what} が {MAX_CONNECTOR_CHAIN} 個を超えるコネクタを続けて通ります ({})",
            shown(name)
        ),
        Connection::ConnectorLoop(name) => format!(
            "{what} が電源を取るコネクタ {} は継続を通して自分自身につながっています",
            shown(name)
        ),
        Connection::NoOutput { block, pin, has } => format!(
            "{what} が {block} の `{}` からつながっていますが、その出力はありません (出力: {has})",
            shown(pin).trim_matches('"')
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use engine::ladder::net::TooLarge;
    use engine::ladder::Pos;

    /// Three lower-case words in a row joined by spaces only: an English
    /// sentence (the page's rule, `app::i18n::errors::english_run`).
    fn english(text: &str) -> bool {
        let mut run = 0;
        for token in text.split_whitespace() {
            let bare = token.trim_end_matches([',', '.', ':', ';', ')']);
            let word = !bare.is_empty() && bare.chars().all(|c| c.is_ascii_lowercase());
            run = if word { run + 1 } else { 0 };
            if run >= 3 {
                return true;
            }
            if bare.len() != token.len() {
                run = 0;
            }
        }
        false
    }

    #[test]
    fn every_import_error_it_says_is_japanese_without_an_english_sentence() {
        let s = || "X".to_string();
        use ImportError as E;
        let mut all = vec![
            E::NotAProject(s()),
            E::Namespace(s()),
            E::NoDrawnBody(s()),
            E::TooManyRungs,
            E::Drawing(TooLarge {
                rows: 1,
                columns: 2,
            }),
            E::NoLocalId(s()),
            E::DuplicateLocalId { id: s(), first: 1 },
            E::DuplicateConnector {
                name: s(),
                first: 1,
            },
            E::NoVariable("contact"),
            E::Variable(NameError::Unmapped {
                declared: s(),
                line: 1,
            }),
            E::Variable(NameError::Refused {
                declared: s(),
                line: 1,
                why: "no such device here".into(),
            }),
            E::NoSuchPou(s(), s()),
            E::NoDrawnInPrograms(s(), s()),
            E::NegatedEdge(s()),
            E::CoilMix(s()),
            E::NotBoolean(s()),
            E::BadEdge(s()),
            E::BadStorage(s()),
            E::WordOutput(s()),
            E::Unsupported(s()),
            E::UnsupportedBlock(s()),
            E::SoftVariableTwice {
                name: s(),
                first: 1,
                types: (s(), s()),
            },
            E::ProjectBlock(s(), s()),
            E::PinNotConnected(s(), "IN"),
            E::PinNotLiteral(s(), "PT"),
            E::BadTimeLiteral(s(), s()),
            E::BadCounterPreset(s(), s()),
            E::CounterQWired(s()),
            E::TimerName(s()),
            E::TimerUnits {
                name: s(),
                ms: 5,
                base: 10,
            },
            E::TimerTooLong(s(), 5),
            E::OnRail(s()),
            E::NoPath(s()),
            E::Net(NetError::NotSeriesParallel(Pos::new(0, 0))),
            E::Net(NetError::TooDeep(Pos::new(0, 0))),
            E::Net(NetError::NoPath),
        ];
        all.extend(nested());
        all.extend(crate::said_soft_ja::tests::every_soft());
        for e in &all {
            let ja = import_ja(e).unwrap_or_else(|| panic!("{e:?} has its Japanese"));
            assert!(ja.chars().any(|c| c > '\u{3000}'), "{e:?}: {ja}");
            assert!(!english(&ja), "{e:?}: {ja}");
        }
    }

    /// One of each XML, lowering and connection problem.
    fn nested() -> Vec<ImportError> {
        use ImportError as E;
        let s = || "X".to_string();
        let mut all = Vec::new();
        let xml = [
            XmlError::TooLarge(9),
            XmlError::NotWellFormed("unexpected end of input".into()),
            XmlError::BadAttribute(s(), "bad quote in value".into()),
            XmlError::BadText("bad entity here".into()),
            XmlError::EndWithoutStart,
            XmlError::NeverClosed(s()),
            XmlError::Empty,
            XmlError::TooDeep,
            XmlError::TooManyAttributes(s()),
            XmlError::DuplicateAttribute(s(), s()),
            XmlError::SecondRoot(s()),
        ];
        all.extend(xml.into_iter().map(E::Xml));
        let lower = [
            LowerError::NoPin("IN"),
            LowerError::XorInputs,
            LowerError::FlipPins,
            LowerError::NoCompare,
            LowerError::NotCounter,
            LowerError::NoRelay,
            LowerError::Contact("cannot be made negated"),
            LowerError::OrNotJoined,
            LowerError::TooMuchWork,
        ];
        all.extend(lower.into_iter().map(|e| E::Lower(s(), e)));
        let connections = [
            Connection::NoRef,
            Connection::Missing(s()),
            Connection::FromVariable(s()),
            Connection::Unconnected,
            Connection::NoConnector(s()),
            Connection::ConnectorLoop(s()),
            Connection::ConnectorChain(s()),
            Connection::NoOutput {
                block: s(),
                pin: s(),
                has: s(),
            },
        ];
        all.extend(connections.into_iter().map(|problem| E::Connection {
            what: "contact X".into(),
            problem,
        }));
        all
    }
}
