//! IO86A's program text errors (its Program tab) in Japanese. Mnemonics
//! and devices are kept as written.

use engine::io86a::asm::{AsmError, MAX_STEPS};
use engine::ladder::target::ElementError;

/// Why a line of IO86A's program text is refused, in Japanese.
pub fn io86a_asm_ja(e: &AsmError) -> String {
    use AsmError as A;
    match e {
        A::TooManyLines(n) => format!(
            "プログラムが {n} 行あり、上限 {} 行を超えています",
            engine::limits::MAX_PROGRAM_LINES
        ),
        A::StepNumber { found, expected } => {
            format!("ステップ番号 {found} が合いません: ここはステップ {expected} です")
        }
        A::MissingInstruction => "ステップ番号だけで命令がありません".into(),
        A::UnknownMnemonic(m) => format!(
            "不明な命令 {}: PLC-IO86A の命令は LD LDI AND ANI OR ORI ORB ANB OUT PLS PLF SET RST SETS RSTS CMP MOV INC DEC END です",
            engine::shown(m)
        ),
        A::MissingOperand("OUT", _) => {
            "OUT T/C には次のステップに設定値 (K10 など) が必要です".into()
        }
        A::MissingOperand(m, n) => format!("{m} にはオペランドが {n} 個必要です"),
        A::Unexpected(w) => format!("余分な {} があります", engine::shown(w)),
        A::StrayOperand(w) => format!(
            "オペランド {w} を待つ命令がありません (OUT T/C, MOV, CMP, INC, DEC)"
        ),
        A::Operand(e) => crate::i18n::engine::element_ja(&ElementError::Io86a(e.clone())),
        A::OutputToInput(m, b) => format!("{m} {b}: {b} は入力なので駆動できません"),
        A::SystemRelay(m, b) => {
            format!("{m} {b}: {b} は PLC 自身が駆動するシステムリレーです")
        }
        A::NotAllowed(m, b) => format!("{m} は {b} を駆動できません"),
        A::BadPreset(w) => {
            format!("設定値 {w}: タイマとカウンタがとるのは K か D です")
        }
        A::NotARegister(m, w) => format!("{m}: 行き先 {w} は D レジスタにしてください"),
        A::NoBlockToJoin(m) => {
            format!("{m} には LD か LDI で始まるブロックが 2 つ必要です")
        }
        A::NoRung => "この回路を始める LD か LDI がありません".into(),
        A::TooManySteps(n) => {
            format!("ステップが多すぎます: {n} (PLC-IO86A は {MAX_STEPS} まで)")
        }
    }
}
