//! The AVR PLC's program text errors (its Program tab) in Japanese.
//! Directives, labels and expressions are kept as written.

use engine::avr::asm::AsmError;
use engine::avr::ProgramError;
use engine::limits::{MAX_EXPRESSION_DEPTH, MAX_PROGRAM_LINES};

/// Why a line of the AVR PLC's program text is refused, in Japanese.
pub fn avr_program_ja(e: &ProgramError) -> String {
    use ProgramError as P;
    match e {
        P::Asm(e) => asm_ja(e),
        P::UnknownCode(c) => format!("命令コード {c} は 1-16 か $FF のどれでもありません"),
        P::Register(r) => format!("レジスタ {r} はありません: R0-R31 です"),
        P::Pattern(p) => format!(
            "ビットパターン ${p:02X} は 1 ビットではありません: $01, $02, $04 … $80 (Bit0..Bit7) にしてください"
        ),
        P::TimerAddress(a) => format!(
            "タイマの RAM アドレス ${a:02X} が PLC_Timer_Top の後の 2 バイトのワードではありません"
        ),
        P::NoTimerTop => {
            "タイマには .dseg の PLC_Timer_Top ラベルの後の RAM が必要です".into()
        }
        P::NotOperand => "Not はオペランドをとりません: 残りのバイトは 0 です".into(),
        P::ShortRecord(n) => format!("レコードが {n} バイトです: どれも 4 バイトです"),
        P::NoEnd => "プログラムに End_PLC レコードがありません".into(),
    }
}

fn asm_ja(e: &AsmError) -> String {
    use AsmError as A;
    match e {
        A::TooManyLines(n) => {
            format!("プログラムが {n} 行あり、上限 {MAX_PROGRAM_LINES} 行を超えています")
        }
        A::UnknownDirective(d) => format!(
            "不明な指示 {d}: このアセンブラがとるのは .equ .db .cseg .csg .dseg .byte とラベルです"
        ),
        A::EquSyntax => ".equ には NAME=式 が必要です".into(),
        A::Redefined(n, first) => {
            format!("{} は {first} 行目で定義済みです", engine::shown(n))
        }
        A::UnknownSymbol(n) => format!("不明な記号 {n}"),
        A::Expression(e) => format!("式 {e} が正しくありません"),
        A::DivisionByZero(e) => format!("{e} に 0 での割り算があります"),
        A::Overflow(e) => format!("{e} があふれます: 値は 64 ビット整数です"),
        A::TooDeep(e) => format!(
            "{e} は括弧・LOW/HIGH・マイナス記号の入れ子が {MAX_EXPRESSION_DEPTH} 段を超えています"
        ),
        A::Range(e, v) => format!("{e} は {v} です: バイトは -128..255 です"),
        A::ByteOutsideDseg => ".byte は RAM を確保します: .dseg の後で使ってください".into(),
        A::DbInDseg => {
            ".db はプログラムメモリにバイトを置きます: .cseg の後で使ってください".into()
        }
    }
}
