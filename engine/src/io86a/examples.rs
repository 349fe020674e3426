//! PLC-IO86A's example programs (the page's example menu, the
//! start screen's gallery and tests), in its own text.

use crate::plc::Example;
use crate::MachineId;

/// PLC-IO86A's examples, in menu order.
pub const EXAMPLES: &[Example] = &[
    Example {
        id: "timer",
        machine: MachineId::Io86a,
        title_en: "Manual: timer OUT T00 K19",
        title_ja: "マニュアル: タイマ OUT T00 K19",
        text: include_str!("../../programs/io86a/timer.il"),
    },
    Example {
        id: "orb",
        machine: MachineId::Io86a,
        title_en: "Manual: ORB",
        title_ja: "マニュアル: ORB命令",
        text: include_str!("../../programs/io86a/orb.il"),
    },
    Example {
        id: "anb",
        machine: MachineId::Io86a,
        title_en: "Manual: ANB",
        title_ja: "マニュアル: ANB命令",
        text: include_str!("../../programs/io86a/anb.il"),
    },
    Example {
        id: "push-on-off",
        machine: MachineId::Io86a,
        title_en: "Manual: push-on / push-off (PLS)",
        title_ja: "マニュアル: プッシュオン・プッシュオフ (PLS)",
        text: include_str!("../../programs/io86a/push-on-off.il"),
    },
];
