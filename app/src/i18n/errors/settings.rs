//! MINASEC-U's and IO86A's own refusals of a setting (a test case's
//! `settings`, the boards' knobs), in Japanese (issue #49). Device names
//! and what was written are kept as written.

use engine::io86a::peripherals::SettingError as Io86aSetting;
use engine::minasec::control::{MAX_HZ, MIN_HZ};
use engine::minasec::SettingError as MinasecSetting;
use engine::shown;

/// MINASEC-U's refusal of a setting, in Japanese.
pub fn minasec_setting_ja(e: &MinasecSetting) -> String {
    match e {
        MinasecSetting::DelayOutOfRange { timer, delay } => {
            let (lo, hi) = timer.range();
            format!(
                "{timer:?} の遅延 {}s は範囲外です: ボリュームで {}s..{}s です",
                delay.as_secs_f64(),
                lo.as_secs_f64(),
                hi.as_secs_f64()
            )
        }
        MinasecSetting::PresetOutOfRange(v) => {
            format!("カウンタの設定値 {v} は範囲外です: 0..99 (BCD 2 桁)")
        }
        MinasecSetting::NoSuchInput(n) => format!("入力 X{n:02} はありません: X00..X07 です"),
        MinasecSetting::BadClock(t) => format!(
            "不正なクロック {}: fast, slow か {MIN_HZ} から {MAX_HZ} Hz の周波数を書いてください",
            shown(t)
        ),
    }
}

/// IO86A's refusal of a setting, in Japanese.
pub fn io86a_setting_ja(e: &Io86aSetting) -> String {
    match e {
        Io86aSetting::Unknown(c) => format!("不明な設定 {}", shown(c)),
        Io86aSetting::Analog(c) => format!(
            "不正なアナログ設定 {}: X04A:n1:n2 (n1 は 2..1024) と書きます",
            shown(c)
        ),
        Io86aSetting::CustomCode(c) => format!(
            "不正なカスタムコード {}: 16 進 4 桁です (X07I:10EF など)",
            shown(c)
        ),
        Io86aSetting::Filter(n) => format!("不正な入力フィルタ \"!{n}\": !0..!10 です"),
    }
}
