//! The soft PLC's example programs (the page's example menu, the
//! start screen's gallery and tests), in its own text.

use crate::plc::Example;
use crate::MachineId;

/// The soft PLC's examples, in menu order.
pub const EXAMPLES: &[Example] = &[
    Example {
        id: "self-hold",
        machine: MachineId::SoftPlc,
        title_en: "Seed: self-holding rung",
        title_ja: "自己保持回路",
        text: include_str!("../../programs/soft-plc/self-hold.il"),
    },
    Example {
        id: "flicker",
        machine: MachineId::SoftPlc,
        title_en: "Seed: MINASEC-U's test (flicker, count to 10)",
        title_ja: "MINASEC-Uのテスト (フリッカ・10カウント)",
        text: include_str!("../../programs/soft-plc/flicker.il"),
    },
    Example {
        id: "parts",
        machine: MachineId::SoftPlc,
        title_en: "Count parts, scale an analog level, compare",
        title_ja: "部品カウント・アナログ値の換算と比較",
        text: include_str!("../../programs/soft-plc/parts.il"),
    },
    Example {
        id: "serial-count",
        machine: MachineId::SoftPlc,
        title_en: "LDmicro-style: a count said over the serial port",
        title_ja: "LDmicro風: カウントをシリアルで表示",
        text: include_str!("../../programs/soft-plc/serial-count.il"),
    },
];
