//! MINASEC-U's example programs (the page's example menu, the
//! start screen's gallery and tests), in its own text.

use crate::plc::Example;
use crate::MachineId;

/// MINASEC-U's examples, in menu order.
pub const EXAMPLES: &[Example] = &[Example {
    id: "seed-test",
    machine: MachineId::MinasecU,
    title_en: "Test program (start, flicker, count to 10)",
    title_ja: "テストプログラム (起動・フリッカ・10カウント)",
    text: super::SEED_TEST_PROGRAM,
}];
