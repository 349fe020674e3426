//! Load as ladder's refusal of a program with no ladder form, in
//! Japanese (issue #49): the step and why, from the engine's kind.
//! Mnemonics and what the program wrote are kept as written.

use engine::ladder::decompile::{DecompileError, StepWhy};
use engine::limits::{MAX_NESTING, MAX_RUNG_CELLS};

/// A program with no ladder form, in Japanese.
pub fn decompile_ja(e: &DecompileError) -> String {
    match e {
        DecompileError::Step(e) => format!("ステップ {}: {}", e.step, step_ja(&e.why)),
        DecompileError::Drawing { rung, size } => format!(
            "回路 {rung}: この回路はラダーにすると {} 行 {} 列になり、上限 {MAX_RUNG_CELLS} セルを超えます",
            size.rows, size.columns
        ),
    }
}

/// Why a step has no ladder form, in Japanese.
fn step_ja(why: &StepWhy) -> String {
    use StepWhy as S;
    match why {
        S::AfterOutputs => {
            "出力の後に回路が続きますが、どの出力もその結果を持っていません".into()
        }
        S::UsedAgain => {
            "出力の後に結果をまた使いますが、どの出力もそれを持っていません: 先に内部リレーに格納してください".into()
        }
        S::NoLoad => "このステップの前に LD がありません".into(),
        S::TwoBlocks => "ORB / ANB には 2 つのブロックが必要です".into(),
        S::TooDeep => format!(
            "ここでブロックの入れ子が {MAX_NESTING} 段を超えます: ラダーには描けません"
        ),
        S::OutputFirst => "前に LD のない出力です".into(),
        S::Labels => "ラベルと条件付きの命令はラダーにできません".into(),
        S::NoOpen => "`(` のない `)` です".into(),
        S::Line(line) => format!("`{line}` はまだラダーにできません"),
        S::BoxWithoutOutput => {
            "このステップの前の回路がボックスで終わり、出力がありません: ラダーにはそう描けません (コンパイラが出力ボックスを書くように電源の LD で終えるか、コイルで終えてください)".into()
        }
        S::ParallelBox => "並列の枝にあるボックスは、ここではラダーにできません".into(),
        S::NoPowerOut => "電源の出力 (Q =>) のない呼び出しはラダーにできません".into(),
        S::EdgeOnLiteral => "リテラルのエッジはラダーにできません".into(),
        S::TimerPreset => "PT が T# リテラルでないタイマは、ここではラダーにできません".into(),
        S::Call(block) => format!("CAL {block} はまだラダーにできません"),
        S::NoLabel => "ジャンプ先のラベルがありません".into(),
        S::NoBoxReads => "それを読むボックスがありません".into(),
        S::Jump(operand) => format!(
            "JUMP {operand} はラダーにできません: できるのは最後の JUMP 0 (か END) だけです"
        ),
        S::Word(w) => format!("ワード {w:04X} は命令ではありません"),
        S::RegisterValue => {
            "データレジスタからの設定値は、ここではラダーにできません: K 定数を使ってください".into()
        }
        S::SecondDevice => {
            "SETS / RSTS は 2 つ目のデバイスを駆動します: ここではラダーにできません".into()
        }
    }
}
