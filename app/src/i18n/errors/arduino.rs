//! The Arduino PLC's program text errors (its Program tab) in Japanese.
//! Mnemonics and devices are kept as written.

use engine::arduino::isa::AsmError;
use engine::shown;

/// Why a line of the Arduino PLC's listing is refused, in Japanese.
pub fn arduino_asm_ja(e: &AsmError) -> String {
    use AsmError as A;
    match e {
        A::TooManyLines(n) => format!(
            "プログラムが {n} 行あり、上限 {} 行を超えています",
            engine::limits::MAX_PROGRAM_LINES
        ),
        A::UnknownMnemonic(m) => format!(
            "不明な命令 {}: スケッチの命令は END OUT LD LDN AND ANDN OR ORN ANDB ORB JUMP です",
            shown(m)
        ),
        A::MissingOperand(m) => format!("{m} にはオペランドが必要です"),
        A::BadOperand(o) => format!(
            "オペランド {} が正しくありません: X000-X005 か Y000-Y005 です",
            shown(o)
        ),
        A::OutToInput(o) => format!("OUT {o}: 出力は Y000-Y005 です"),
        A::BadStep(s) => format!(
            "ステップ {} が正しくありません: JUMP がとるのは 0..255 です",
            shown(s)
        ),
        A::Unexpected(w) => format!("余分な {} があります", shown(w)),
        A::MissingMnemonic => "ステップ番号だけで命令がありません".into(),
        A::StepOrder { found, next } => {
            format!("ステップ {found} の順番が違います: 次のステップは {next} 以降です")
        }
        A::TooManySteps { step, capacity } => {
            format!("ステップ {step} は EEPROM の外です: このチップは {capacity} ステップまでです")
        }
    }
}
