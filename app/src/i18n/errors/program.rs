//! The soft PLC's program text errors in Japanese: written once in the
//! files worker's crate (it says a PLCopen project's generated program
//! the same way), and MINASEC-U's program text's here.

pub use files_worker::said_program_ja::load_ja;

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
