//! The seeds' example programs, in each machine's own text, for the
//! page's example menu (each opens as a ladder) and for tests.

use crate::MachineId;

/// One example program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Example {
    /// Its id in the menu (unique per machine).
    pub id: &'static str,
    /// The machine it is for.
    pub machine: MachineId,
    /// Its title in English.
    pub title_en: &'static str,
    /// Its title in Japanese.
    pub title_ja: &'static str,
    /// The program text.
    pub text: &'static str,
}

/// Every example, machine by machine.
pub const EXAMPLES: &[Example] = &[
    Example {
        id: "seed-test",
        machine: MachineId::MinasecU,
        title_en: "Test program (start, flicker, count to 10)",
        title_ja: "テストプログラム (起動・フリッカ・10カウント)",
        text: crate::minasec::SEED_TEST_PROGRAM,
    },
    Example {
        id: "timer",
        machine: MachineId::Io86a,
        title_en: "Manual: timer OUT T00 K19",
        title_ja: "マニュアル: タイマ OUT T00 K19",
        text: include_str!("../programs/io86a/timer.il"),
    },
    Example {
        id: "orb",
        machine: MachineId::Io86a,
        title_en: "Manual: ORB",
        title_ja: "マニュアル: ORB命令",
        text: include_str!("../programs/io86a/orb.il"),
    },
    Example {
        id: "anb",
        machine: MachineId::Io86a,
        title_en: "Manual: ANB",
        title_ja: "マニュアル: ANB命令",
        text: include_str!("../programs/io86a/anb.il"),
    },
    Example {
        id: "push-on-off",
        machine: MachineId::Io86a,
        title_en: "Manual: push-on / push-off (PLS)",
        title_ja: "マニュアル: プッシュオン・プッシュオフ (PLS)",
        text: include_str!("../programs/io86a/push-on-off.il"),
    },
    Example {
        id: "self-hold",
        machine: MachineId::AvrPlc,
        title_en: "Seed: self-holding rungs",
        title_ja: "自己保持回路",
        text: include_str!("../programs/avr-plc/self-hold.asm"),
    },
    Example {
        id: "e-stop-timer",
        machine: MachineId::AvrPlc,
        title_en: "Seed: TOF timer (E_Stop)",
        title_ja: "TOFタイマ (E_Stop)",
        text: include_str!("../programs/avr-plc/e-stop-timer.asm"),
    },
    Example {
        id: "self-hold",
        machine: MachineId::ArduinoPlc,
        title_en: "Seed: self-hold",
        title_ja: "自己保持回路",
        text: include_str!("../programs/arduino-plc/self-hold.txt"),
    },
    Example {
        id: "self-hold",
        machine: MachineId::SoftPlc,
        title_en: "Seed: self-holding rung",
        title_ja: "自己保持回路",
        text: include_str!("../programs/soft-plc/self-hold.il"),
    },
    Example {
        id: "flicker",
        machine: MachineId::SoftPlc,
        title_en: "Seed: MINASEC-U's test (flicker, count to 10)",
        title_ja: "MINASEC-Uのテスト (フリッカ・10カウント)",
        text: include_str!("../programs/soft-plc/flicker.il"),
    },
    Example {
        id: "parts",
        machine: MachineId::SoftPlc,
        title_en: "Count parts, scale an analog level, compare",
        title_ja: "部品カウント・アナログ値の換算と比較",
        text: include_str!("../programs/soft-plc/parts.il"),
    },
    Example {
        id: "serial-count",
        machine: MachineId::SoftPlc,
        title_en: "LDmicro-style: a count said over the serial port",
        title_ja: "LDmicro風: カウントをシリアルで表示",
        text: include_str!("../programs/soft-plc/serial-count.il"),
    },
];

/// The examples of `machine`.
pub fn examples_of(machine: MachineId) -> impl Iterator<Item = &'static Example> {
    EXAMPLES.iter().filter(move |e| e.machine == machine)
}
