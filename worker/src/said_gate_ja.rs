//! Why a block is not lowered for a bit machine, in Japanese (issue #49),
//! made from its kind as the other import errors are (`said_ja`). The
//! command line's advice (`--map`) is said as what to map, which the
//! page's table does.

use engine::formats::plcopen::gate_why::{GateWhy, OperandWhy, COMPARED};

/// The block `what` refused for `why`, in Japanese.
pub fn gate_ja(what: &str, why: &GateWhy) -> String {
    use GateWhy as G;
    let why = match why {
        G::NeedsRelay(w) => {
            format!("状態を持つリレーが必要です: {w} をリレー (M10 など) に割り当ててください")
        }
        G::Negated(pin) => {
            format!("ピン {pin} が反転されています: 代わりに NOT ブロックを置いてください")
        }
        G::Edge(pin, e) => {
            let e = if *e == "rising" { "立ち上がり" } else { "立ち下がり" };
            format!("ピン {pin} に{e}の印があります: 代わりに R_TRIG か F_TRIG ブロックを置いてください")
        }
        G::NoInput(pin, has) => format!("入力 `{pin}` はありません (入力: {has})"),
        G::EnableWired => "EN がつながっています: Hashigo のブロックは常に実行します: EN は左の母線につなぐか、開けておいてください".into(),
        G::NeedsTwo => "入力が 2 つ必要です".into(),
        G::CounterWired(pin) => format!(
            "{pin} がつながっています: このマシンのカウンタは加算だけでプリセットできません: Hashigo が読むのは CD と LD を使わない CTUD です"
        ),
        G::Inputs(n, ty, two) => {
            let takes = if *two { "2 つ" } else { "2 つ以上" };
            format!("入力が {n} 個あります: {ty} が比べるのは {takes}です")
        }
        G::InputsOrder(pins) => format!(
            "入力が {pins} です: Hashigo は IN1, IN2, … IN{} を順に読みます",
            COMPARED.len()
        ),
        G::Operand(pin, expr, why) => {
            let expr = engine::shown(expr);
            match why {
                OperandWhy::NotNumber => format!(
                    "{pin} {expr}: 0..32767 の整数でも変数でもありません"
                ),
                OperandWhy::Declared(ty) => format!(
                    "{pin} {expr}: {ty} と宣言されています: 比較は数をとります (IEC は同じ型の値を比べます)"
                ),
                OperandWhy::NoWord(name) => format!(
                    "{pin} {expr}: ワードではありません: {} をデータレジスタ (D00 など) に割り当ててください",
                    name.trim()
                ),
            }
        }
    };
    format!("{what}: {why}")
}
