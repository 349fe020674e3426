//! The plant's faults, manual mode and the fault report (issue #52), in a
//! table of their own, reached through [`super::Lang::plant_faults`], so
//! that parallel work does not collide in the other plant strings.

/// The strings of the Faults section, the fault report and manual mode.
pub struct PlantFaults {
    /// The Faults section's heading.
    pub faults: &'static str,
    /// Said when the plant has no fault (that the viewer may see).
    pub no_faults: &'static str,
    /// The columns and fields of a fault: its signal, its kind, from when.
    pub signal: &'static str,
    pub kind: &'static str,
    pub from: &'static str,
    /// The kinds: stuck at 0, stuck at 1, dead.
    pub stuck_0: &'static str,
    pub stuck_1: &'static str,
    pub dead: &'static str,
    /// The hidden mark (not shown to a student in an exercise).
    pub hidden: &'static str,
    /// Adds the fault as given; removes a fault.
    pub add: &'static str,
    pub remove: &'static str,
    /// Said over a fault the engine refuses.
    pub refused: &'static str,
    /// The fault report's heading and its note.
    pub report: &'static str,
    pub report_note: &'static str,
    /// The report's first choice: nothing named yet.
    pub choose: &'static str,
    /// The verdict's line for the fault: its name in the result.
    pub fault_case: &'static str,
    /// Said when the named fault is not the hidden one (or none named).
    pub fault_wrong: &'static str,
    /// Manual mode's switch and its note.
    pub manual: &'static str,
    pub manual_note: &'static str,
}

/// English.
pub const EN: PlantFaults = PlantFaults {
    faults: "Faults",
    no_faults: "No fault: every device works.",
    signal: "Signal",
    kind: "Fault",
    from: "From (s)",
    stuck_0: "stuck off (0)",
    stuck_1: "stuck on (1)",
    dead: "dead (does not act)",
    hidden: "hidden from the student",
    add: "Add fault",
    remove: "Remove",
    refused: "Not added:",
    report: "Which fault?",
    report_note: "A device of this plant is broken. Find it with the live ladder, the chart and Why?, name it here, then Check my answer: the fault you name is repaired for the tests.",
    choose: "(choose)",
    fault_case: "The broken device",
    fault_wrong: "The fault named in the Plant tab (Which fault?) is not the one: watch the signals again.",
    manual: "Manual mode",
    manual_note: "With the machine stopped, drive the plant's actuators by hand; Run gives the plant back to the ladder as it stands.",
};

/// Japanese.
pub const JA: PlantFaults = PlantFaults {
    faults: "故障",
    no_faults: "故障なし: すべての機器が正常です。",
    signal: "信号",
    kind: "故障",
    from: "開始(秒)",
    stuck_0: "OFFのまま(0)",
    stuck_1: "ONのまま(1)",
    dead: "動かない",
    hidden: "生徒には隠す",
    add: "故障を追加",
    remove: "削除",
    refused: "追加できません:",
    report: "どの故障?",
    report_note: "このプラントの機器のどれかが壊れています。動いているラダー、タイムチャート、「なぜ?」で見つけてここで答え、答え合わせをしてください。答えた故障はテストのときに修理されます。",
    choose: "(選ぶ)",
    fault_case: "壊れている機器",
    fault_wrong: "プラントのタブ(どの故障?)で答えた故障は違います。もう一度信号を観察してください。",
    manual: "手動モード",
    manual_note: "機械を止めたまま、プラントのアクチュエーターを手で動かせます。実行すると、プラントはその状態のままラダーに戻ります。",
};
