//! The Tests pane's texts in Japanese: why a case could not run and what
//! a failed expectation saw.

use engine::cases::{CaseError, EdgeSeen, ExpectError, Observed, MAX_TEST_WORK};
use engine::events::EventError;
use engine::plc::{DeviceError, Drives, Own, PlcError, SettingError};
use engine::shown;
use engine::softplc::plc::SoftDeviceError;
use engine::time::TimeError;
use engine::{io86a, minasec};

use super::super::engine::machine_ja;
use super::program::load_ja;

/// What a failed expectation saw, in Japanese.
pub fn observed_ja(o: &Observed) -> String {
    match o {
        Observed::Was { device, value, at } => format!("{device} は {at}ms に {value} でした"),
        Observed::NumberNotText { device, value } => {
            format!("{device} は数 ({value}) で文字列ではありません: 数と比べてください")
        }
        Observed::TextNotNumber { device, value } => {
            format!("{device} は文字列 ({value}) です: 引用符で囲んだ文字列 ('…') と比べてください")
        }
        Observed::NoEdge {
            device,
            falling,
            seen,
        } => {
            let verb = if *falling {
                "立ち下がりません"
            } else {
                "立ち上がりません"
            };
            let seen = match seen {
                EdgeSeen::Stayed(v) => format!("{v} のままでした"),
                EdgeSeen::Went {
                    first,
                    last,
                    opposite: Some(t),
                } => {
                    let other = if *falling {
                        "立ち上がり"
                    } else {
                        "立ち下がり"
                    };
                    format!("{first} から {last} になり、{t}ms に{other}ました")
                }
                EdgeSeen::Went { first, last, .. } => format!("{first} から {last} になりました"),
            };
            format!("{device} が{verb}でした ({seen})")
        }
    }
}

/// Why a case could not run, in Japanese.
pub fn case_error_ja(e: &CaseError) -> String {
    match e {
        CaseError::Events(errors) => errors
            .iter()
            .map(|e| format!("入力の {} 行目: {}", e.line, event_ja(&e.error)))
            .collect::<Vec<_>>()
            .join("\n"),
        CaseError::Event(e) => format!("入力の {} 行目: {}", e.line, plc_ja(&e.error)),
        CaseError::Expect(i, e) => format!("期待 {}: {}", i + 1, expect_ja(e)),
        CaseError::Device(i, e) => format!("期待 {}: {}", i + 1, plc_ja(e)),
        CaseError::TooLong => format!(
            "テストが {MAX_TEST_WORK} サンプル (見る時点と期待) を超えます: 期間を短くしてください"
        ),
    }
}

fn expect_ja(e: &ExpectError) -> String {
    match e {
        ExpectError::Form(line) => format!(
            "{line} は期待の形ではありません: \"Y00 = 1 at 2s\"、\"Y00 stays 0 from 1s to 2s\"、\"Y00 rises within 0s..3s\" のように書きます"
        ),
        ExpectError::Value(v) => format!("{v} は整数ではありません"),
        ExpectError::OutOfRange(v) => format!(
            "{v} は範囲外です: 値は {} から {} の整数です",
            i64::MIN,
            i64::MAX
        ),
        ExpectError::Time(e) => time_ja(e),
        ExpectError::Window => "期間の終わりが始まりより前です".into(),
        ExpectError::Text(t) => format!(
            "{t} は文字列ではありません: ' で囲み、' は $'、$ は $$ と書きます"
        ),
        ExpectError::TextOrder(op) => {
            format!("文字列は = か <> で比べます ({op} は使えません)")
        }
    }
}

/// What a machine's input events drive, in Japanese (MINASEC-U's list
/// of its inputs names its CNTCLR button).
fn drives_ja(drives: &Drives) -> String {
    match drives {
        Drives::Terminals(range) => range.to_string(),
        Drives::TerminalsAndButton(range, button) => format!("{range} と {button} ボタン"),
        Drives::Bits => "ビット".to_string(),
    }
}

/// A time refused, in Japanese.
pub fn time_ja(e: &TimeError) -> String {
    match e {
        TimeError::BadNumber(t) => {
            format!("不正な時間 {t}: 10us, 250ms, 1.5s, 20 のような 0 以上の数を書きます")
        }
        TimeError::BadUnit(t) => format!("不正な時間 {t}: 単位は ns, us, ms, s のどれかです"),
        TimeError::Negative(t) => {
            format!("不正な時間 {t}: 時間は負になりません (シミュレーションは 0 から始まります)")
        }
        TimeError::Exponent(t) => {
            format!("不正な時間 {t}: 指数ではなく 1.5s のような小数で書きます")
        }
        TimeError::TooLong(t) => {
            format!("時間 {t} がシミュレーション時計の上限 10000000s を超えています")
        }
    }
}

fn event_ja(e: &EventError) -> String {
    match e {
        EventError::FieldCount(n) => {
            format!("時間,デバイス,値 の 3 つを書きます ({n} 個ありました)")
        }
        EventError::Time(e) => time_ja(e),
        EventError::MissingDevice => "デバイスが空です".into(),
        EventError::BadValue(v) => format!(
            "不正な値 {}: ビットは 0 か 1、ワードは整数、電圧は 2.5V、REAL は 2.5 のように書きます",
            shown(v)
        ),
        EventError::TooMany(n) => format!(
            "{n} 行あり、入力の上限 {} 行を超えています",
            engine::limits::MAX_EVENTS
        ),
    }
}

/// A machine's refusal of a command, in Japanese (a machine's own
/// refusal of a kind not known here keeps the engine's words).
pub fn plc_ja(e: &PlcError) -> String {
    match e {
        PlcError::Program(problems) => problems
            .iter()
            .map(|p| format!("{} 行目: {}", p.line, own_ja(&p.error)))
            .collect::<Vec<_>>()
            .join("\n"),
        PlcError::Device(e) => device_ja(e),
        PlcError::Setting(e) => setting_ja(e),
        PlcError::Own(e) => own_ja(e),
        PlcError::NotThisMachine { machine, lacks } => {
            format!("{} には {lacks} がありません", machine_ja(*machine))
        }
        PlcError::NotItsOwn { machine, command } => {
            format!("{} には {command} がありません", machine_ja(*machine))
        }
    }
}

/// A machine's own refusal, in Japanese when its kind is one the page
/// knows.
fn own_ja(e: &Own) -> String {
    if let Some(e) = e.get::<SoftDeviceError>() {
        return soft_device_ja(e);
    }
    if let Some(e) = e.get::<engine::softplc::LoadError>() {
        return load_ja(e);
    }
    if let Some(said) = asm_ja(e) {
        return said;
    }
    if let Some(e) = e.get::<minasec::SettingError>() {
        return super::settings::minasec_setting_ja(e);
    }
    if let Some(e) = e.get::<io86a::peripherals::SettingError>() {
        return super::settings::io86a_setting_ja(e);
    }
    let element = if let Some(e) = e.get::<minasec::isa::OperandError>() {
        engine::ladder::target::ElementError::Minasec(e.clone())
    } else if let Some(e) = e.get::<io86a::isa::OperandError>() {
        engine::ladder::target::ElementError::Io86a(e.clone())
    } else {
        return e.to_string();
    };
    super::super::engine::element_ja(&element)
}

/// A machine's program text error (its assembler's), in Japanese.
fn asm_ja(e: &Own) -> Option<String> {
    if let Some(e) = e.get::<minasec::AsmError>() {
        return Some(super::program::minasec_asm_ja(e));
    }
    if let Some(e) = e.get::<io86a::asm::AsmError>() {
        return Some(super::io86a::io86a_asm_ja(e));
    }
    if let Some(e) = e.get::<engine::arduino::isa::AsmError>() {
        return Some(super::arduino::arduino_asm_ja(e));
    }
    let e = e.get::<engine::avr::ProgramError>()?;
    Some(super::avr::avr_program_ja(e))
}

fn soft_device_ja(e: &SoftDeviceError) -> String {
    match e {
        SoftDeviceError::Unknown(d) => format!(
            "不明なデバイス {}: 変数名、プログラムが使うアドレス (%IX0.0)、ブロックの出力 (TON0.Q) のどれかです",
            shown(d)
        ),
        SoftDeviceError::NoOutput { block, pin } => format!("{block} に出力 {pin} はありません"),
        SoftDeviceError::BlockOutput(d) => {
            format!("{d} はブロックの出力です: 入力で変えられるのは変数と入力です")
        }
        SoftDeviceError::Value {
            device,
            data_type,
            value,
        } => format!("{device} は {} 型です: {value} はその値ではありません", data_type.name()),
    }
}

fn device_ja(e: &DeviceError) -> String {
    match e {
        DeviceError::Own(e) => own_ja(e),
        DeviceError::ArduinoPin(d) => format!(
            "不明なデバイス {}: Arduino PLC のデバイスは X000-X005, Y000-Y005 です",
            shown(d)
        ),
        DeviceError::AvrBit(d) => format!(
            "不明なビット {}: NAME_R と NAME_B で定義したビット名か R4.2 の形で書きます",
            shown(d)
        ),
        DeviceError::AvrTimer(d) => format!(
            "不明なタイマ {}: PLC_Timer_Top の後のラベル名を書きます",
            shown(d)
        ),
        DeviceError::Constant(d) => format!("{d} は定数でデバイスではありません"),
        DeviceError::NotAnInput { device, drives } => {
            let drives = drives_ja(drives);
            format!("{device} は入力ではありません: 入力で変えられるのは {drives} です")
        }
        DeviceError::IsAnOutput { device, drives } => {
            let drives = drives_ja(drives);
            format!("{device} は出力です: 入力で変えられるのは {drives} です")
        }
        DeviceError::BitValue(d) => format!("{d} はビットです: 値は 0 か 1 です"),
        DeviceError::NeedsAnalogMode(d) => {
            format!("{d} はデジタル入力です: 電圧はアナログモードで与えます")
        }
        DeviceError::NeedsVoltage(d) => {
            format!("{d} はアナログモードです: 2.5V のような電圧を与えてください")
        }
        DeviceError::IrFrame(d) => {
            format!("{d} は IR フレームを受けます: 0 (なし) か 32 ビットの NEC フレームです")
        }
    }
}

fn setting_ja(e: &SettingError) -> String {
    match e {
        SettingError::Unknown {
            machine,
            name,
            takes,
        } => format!("不明な設定 {}: {} の設定は {takes} です", shown(name), machine_ja(*machine)),
        SettingError::Time(e) => time_ja(e),
        SettingError::Own(e) => own_ja(e),
        SettingError::CounterPreset(v) => {
            format!("C0={v}: カウンタの設定値は 0..99 の数です")
        }
        SettingError::PeriodOutOfRange { what, period, max } => format!(
            "{what} {period}ms は範囲外です: 0 より大きく {}s 以下です",
            max.as_secs_f64()
        ),
        SettingError::AvrScan(period) => format!(
            "AVR PLC のスキャン周期は 1ms から 10s の整数ミリ秒です ({period}ms は使えません)"
        ),
        SettingError::Choice {
            setting,
            value,
            choices,
        } => format!("不明な {setting} {}: {choices} のどれかです", shown(value)),
        SettingError::ChipTooSmall { step, capacity } => format!(
            "チップが小さすぎます: プログラムはステップ {step} まであり、チップは {capacity} ステップです"
        ),
    }
}
