//! Errors from the engine in the page's language (issue #49): rendered
//! from their kind and arguments, so the command line keeps the engine's
//! English (`Display`) while the page says them in Japanese. Every
//! variant is matched by name (no `_`): a new kind fails to compile here
//! until it has its Japanese. Device names, mnemonics and what a file
//! says are kept as written.

use engine::ladder::edit::EntryError;
use engine::ladder::target::{capabilities, Drivable, ElementError, LackReason, Latch};
use engine::ladder::LadderError;
use engine::{io86a, minasec, MachineId};

use super::Lang;

/// A machine's refusal of an element, in `lang`.
pub fn element_error(lang: Lang, e: &ElementError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => element_ja(e),
    }
}

/// A ladder problem, in `lang`: its place, then the typed reason in
/// Japanese, else the engine's words (a problem not yet typed).
pub fn ladder_error(lang: Lang, e: &LadderError) -> String {
    if lang == Lang::En {
        return e.to_string();
    }
    let at = match e.pos {
        Some(p) => format!(
            "回路 {}、行 {}、列 {}",
            e.rung,
            p.row as u128 + 1,
            p.col as u128 + 1
        ),
        None => format!("回路 {}", e.rung),
    };
    let why = match (&e.cause, &e.problem) {
        (Some(c), _) => element_ja(c),
        (None, Some(p)) => super::errors::rung_problem_ja(p),
        (None, None) => e.message.clone(),
    };
    format!("{at}: {why}")
}

/// An import error of the files worker in `lang`: at its place, the typed
/// reason in Japanese when it has one, else `english` as said.
pub fn import_error(lang: Lang, said: Option<&files_worker::Said>, english: &str) -> String {
    match (lang, said) {
        (
            Lang::Ja,
            Some(files_worker::Said {
                at,
                cause: Some(why),
                ..
            }),
        ) => {
            format!("{at}: {}", element_ja(why))
        }
        (
            Lang::Ja,
            Some(files_worker::Said {
                at, ja: Some(ja), ..
            }),
        ) => format!("{at}: {ja}"),
        _ => english.to_string(),
    }
}

/// A machine as the page names it in Japanese (its maker's product name;
/// kept here so the strings do not depend on the page's state).
pub(super) fn machine_ja(m: MachineId) -> &'static str {
    match m {
        MachineId::MinasecU => "MINASEC-U",
        MachineId::Io86a => "PLC-IO86A",
        MachineId::ArduinoPlc => "Arduino PLC",
        MachineId::AvrPlc => "AVR PLC",
        MachineId::SoftPlc => "ソフトPLC",
    }
}

pub(super) fn element_ja(e: &ElementError) -> String {
    use ElementError as E;
    match e {
        E::Lacks { machine, what, why } => format!(
            "{} には {} がありません{}",
            machine_ja(*machine),
            what_ja(what),
            lack_ja(*why)
        ),
        E::ZeroTimer => "タイマの設定時間は 0 ms より大きくしてください".into(),
        E::PresetTooLarge(k) => format!("設定値 K{k} が K32767 を超えています"),
        E::Minasec(e) => match e {
            minasec::isa::OperandError::UnknownDevice(d) => format!(
                "不明なデバイス {d}: MINASEC-U のデバイスは {} です",
                capabilities(MachineId::MinasecU).devices
            ),
            minasec::isa::OperandError::BadRawAddress(d) => {
                format!("不正な直接アドレス {d}: %00000..%11111 または $00..$1F と書きます")
            }
        },
        E::Io86a(e) => match e {
            io86a::isa::OperandError::UnknownDevice(d) => format!(
                "不明なデバイス {d}: PLC-IO86A のデバイスは X00-X07, Y00-Y05, M00-M63, S00-S07, T00-T31, C00-C07, D00-D07 です"
            ),
            io86a::isa::OperandError::BadConstant(k) => {
                format!("不正な定数 {k}: K0..K32767 で書きます")
            }
            io86a::isa::OperandError::NotAWord(d) => {
                format!("{d} はビットです: このオペランドはワード (K, D, T, C) です")
            }
        },
        E::UnknownDevice { machine, device } => {
            let has = match machine {
                MachineId::SoftPlc => "%IX0.0, %QX0.0, %MX0.0 または変数名".to_string(),
                m => capabilities(*m).devices.to_string(),
            };
            format!("不明なデバイス {device}: {} のデバイスは {has} です", machine_ja(*machine))
        }
        E::InputAsCoil(d) => format!("{d} は入力です: コイルでは駆動できません"),
        E::NotADataRegister(d) => {
            format!("{d}: 値を入れられるのはデータレジスタ D00-D07 だけです")
        }
        E::CannotDrive { device, want } => {
            let want = match want {
                Drivable::Timer => "タイマ T00-T31",
                Drivable::Counter => "カウンタ C00-C07",
                Drivable::Output => "Y・M・S のデバイス (C はセット/リセットのみ)",
            };
            format!("{device} はここでは駆動できません: {want} を使ってください")
        }
        E::MinasecLatch { kind, device } => {
            let kind = match kind {
                Latch::Set => "セット",
                Latch::Reset => "リセット",
            };
            format!(
                "MINASEC-U では {device} の{kind}コイルに意味がありません: 通常のコイルで駆動してください (C0 のリセットコイルはカウントをクリアします)"
            )
        }
        E::Io86aCounterCoil(d) => format!(
            "通常のコイルではカウンタ {d} を駆動できません: 設定値付きのカウンタコイル (OUT {d} K10) かセット/リセットコイルを使ってください"
        ),
        E::Block(why) => files_worker::box_error_ja(why),
    }
}

/// The element a machine lacks, as [`ElementError::Lacks`] names it
/// (`in-line TON T1 box`, `PLS/PLF output`, `MOV box`, `box input R`):
/// the engine's words for the kind, the element's own as written.
fn what_ja(what: &str) -> String {
    if let Some(inner) = what
        .strip_prefix("in-line ")
        .and_then(|w| w.strip_suffix(" box"))
    {
        return format!("インラインの {inner} ボックス");
    }
    if what == "PLS/PLF output" {
        return "PLS/PLF 出力".into();
    }
    if let Some(pin) = what.strip_prefix("box input ") {
        return format!("ボックス入力 {pin}");
    }
    if let Some(kind) = what.strip_suffix(" box") {
        return format!("{kind} ボックス");
    }
    // An element as `Element`'s Display names it: its kind in Japanese,
    // its devices as written.
    const KINDS: [(&str, &str); 10] = [
        ("rising contact ", "立上り接点 "),
        ("falling contact ", "立下り接点 "),
        ("NC contact ", "b接点 "),
        ("contact ", "a接点 "),
        ("inverted coil ", "反転コイル "),
        ("set coil ", "セットコイル "),
        ("reset coil ", "リセットコイル "),
        ("coil ", "コイル "),
        ("timer ", "タイマコイル "),
        ("counter ", "カウンタコイル "),
    ];
    KINDS
        .iter()
        .find_map(|(en, ja)| what.strip_prefix(en).map(|rest| format!("{ja}{rest}")))
        .unwrap_or_else(|| what.to_string())
}

/// The device entry's refusal, in `lang`.
pub fn entry_error(lang: Lang, e: &EntryError) -> String {
    if lang == Lang::En {
        return e.to_string();
    }
    match e {
        EntryError::Empty => "デバイスか命令を入力してください".into(),
        EntryError::UnknownWord(w) => format!(
            "不明な命令 {w}: LD, LDI, LDP, LDF, OUT, SET, RST, PLS, PLF, MOV, CMP, INC, DEC, NOT, R_TRIG, F_TRIG, TON, TOF, TP のどれかです"
        ),
        EntryError::Usage(u) => format!("{u} の形で書いてください"),
        EntryError::BadNumber(n) => format!("{n} は数ではありません"),
        EntryError::Element(why) => element_ja(why),
    }
}

fn lack_ja(why: LackReason) -> &'static str {
    match why {
        LackReason::Plain => "",
        LackReason::NoEdgeContacts => " (エッジ接点がありません)",
        LackReason::BoxInputsAreSoft => ": ブロックの入力を回路でつなげるのはソフトPLCです",
        LackReason::WordBoxesAreSoft => ": ワードの関数とブロックはソフトPLCのものです",
        LackReason::ArduinoNoTimers => " (Arduino スケッチにはタイマがありません)",
        LackReason::MinasecPanelTimers => {
            ": T0/T1・C0 はコイルで駆動します。遅延と設定値はパネルで設定します"
        }
        LackReason::UseInlineTimer => ": インラインの TON/TOF/TP ボックスを使ってください",
        LackReason::ArduinoNoTimersOrCounters => {
            " (Arduino スケッチにはタイマもカウンタもありません)"
        }
        LackReason::NoDataRegisters => " (データレジスタがありません)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One of each kind (the match above has no `_`: a new kind must be
    /// added there, and here).
    fn every_kind() -> Vec<ElementError> {
        use engine::ladder::block::BoxError;
        use ElementError as E;
        let s = || "X".to_string();
        let mut all = vec![
            E::ZeroTimer,
            E::PresetTooLarge(40000),
            E::Minasec(minasec::isa::OperandError::UnknownDevice(s())),
            E::Minasec(minasec::isa::OperandError::BadRawAddress(s())),
            E::Io86a(io86a::isa::OperandError::UnknownDevice(s())),
            E::Io86a(io86a::isa::OperandError::BadConstant(s())),
            E::Io86a(io86a::isa::OperandError::NotAWord(s())),
            E::InputAsCoil(s()),
            E::NotADataRegister(s()),
            E::Io86aCounterCoil(s()),
            E::Block(BoxError::UnknownKind(s())),
            E::Block(BoxError::NoInstance(s())),
            E::Block(BoxError::FunctionInstance(s())),
            E::Block(BoxError::NoSuchInput(s(), s(), s())),
            E::Block(BoxError::BadOperand(s())),
            E::Block(BoxError::NotWired(s(), s())),
            E::Block(BoxError::NoSuchOutput(s(), s())),
            E::Block(BoxError::NotAVariable(s(), s(), s())),
        ];
        for want in [Drivable::Timer, Drivable::Counter, Drivable::Output] {
            all.push(E::CannotDrive { device: s(), want });
        }
        for kind in [Latch::Set, Latch::Reset] {
            all.push(E::MinasecLatch { kind, device: s() });
        }
        for machine in MachineId::ALL {
            all.push(E::UnknownDevice {
                machine,
                device: s(),
            });
        }
        for why in [
            LackReason::Plain,
            LackReason::NoEdgeContacts,
            LackReason::BoxInputsAreSoft,
            LackReason::WordBoxesAreSoft,
            LackReason::ArduinoNoTimers,
            LackReason::MinasecPanelTimers,
            LackReason::UseInlineTimer,
            LackReason::ArduinoNoTimersOrCounters,
            LackReason::NoDataRegisters,
        ] {
            all.push(E::Lacks {
                machine: MachineId::MinasecU,
                what: "in-line TON T1 box".into(),
                why,
            });
        }
        all
    }

    /// Words of English prose (not device names or mnemonics).
    const ENGLISH: [&str; 12] = [
        " has ", " no ", " is ", " the ", " a ", " use ", " not ", " an ", "only", "cannot",
        "needs", "wired",
    ];

    #[test]
    fn every_machine_refusal_has_a_japanese_rendering_without_english_prose() {
        for e in every_kind() {
            let ja = element_error(Lang::Ja, &e);
            assert!(ja.chars().any(|c| c > '\u{3000}'), "{e:?}: {ja}");
            for word in ENGLISH {
                assert!(!ja.contains(word), "{e:?}: {ja} says {word:?}");
            }
            assert_eq!(
                element_error(Lang::En, &e),
                e.to_string(),
                "English is the engine's"
            );
        }
    }

    #[test]
    fn a_ladder_problem_says_its_place_and_its_typed_reason_in_japanese() {
        use engine::ladder::{element::Element, Ladder, Pos, Rung};
        let mut rung = Rung::default();
        rung.set(Pos { row: 0, col: 0 }, Some(Element::no("X00")));
        let pulse = Element::Pulse {
            falling: false,
            device: "Y00".into(),
        };
        rung.set(Pos { row: 0, col: 1 }, Some(pulse));
        let ladder = Ladder {
            rungs: vec![rung],
            ..Ladder::default()
        };
        let errors = ladder
            .logic(MachineId::MinasecU)
            .expect_err("no PLS on MINASEC-U");
        let ja = ladder_error(Lang::Ja, &errors[0]);
        assert!(ja.starts_with("回路 1、行 1、列 "), "{ja}");
        assert!(
            ja.contains("MINASEC-U には PLS/PLF 出力 がありません"),
            "{ja}"
        );
        assert_eq!(ladder_error(Lang::En, &errors[0]), errors[0].to_string());
    }

    #[test]
    fn an_entry_refusal_and_an_elements_kind_are_said_in_japanese() {
        for e in [
            EntryError::Empty,
            EntryError::UnknownWord("FOO".into()),
            EntryError::Usage("MOV K50 D00"),
            EntryError::BadNumber("K1x".into()),
            EntryError::Element(ElementError::ZeroTimer),
        ] {
            let ja = entry_error(Lang::Ja, &e);
            assert!(ja.chars().any(|c| c > '\u{3000}'), "{e:?}: {ja}");
            for word in ENGLISH {
                assert!(!ja.contains(word), "{e:?}: {ja} says {word:?}");
            }
            assert_eq!(entry_error(Lang::En, &e), e.to_string());
        }
        assert_eq!(what_ja("timer T01 K2"), "タイマコイル T01 K2");
        assert_eq!(what_ja("NC contact X01"), "b接点 X01");
        assert_eq!(what_ja("CTU"), "CTU", "a name as written");
    }

    #[test]
    fn an_import_error_with_its_cause_is_said_in_japanese() {
        let said = files_worker::Said {
            ja: None,
            at: "lab4.xml:67".into(),
            cause: Some(ElementError::Lacks {
                machine: MachineId::MinasecU,
                what: "in-line TON T1 box".into(),
                why: LackReason::Plain,
            }),
        };
        let english = "lab4.xml:67: minasec-u has no in-line TON T1 box";
        assert_eq!(
            import_error(Lang::Ja, Some(&said), english),
            "lab4.xml:67: MINASEC-U には インラインの TON T1 ボックス がありません"
        );
        assert_eq!(import_error(Lang::En, Some(&said), english), english);
        assert_eq!(
            import_error(Lang::Ja, None, english),
            english,
            "untyped: as said"
        );
    }
}
