//! The plant dock's words (issue #52): the plants' names, their signals
//! and quantities, alarms and the wiring table. A table of its own,
//! reached through [`super::Lang::plant`], so that parallel work does not
//! collide in the big [`super::Texts`] table.

/// The plant dock's strings.
pub struct PlantTexts {
    /// The dock's tab.
    pub tab: &'static str,
    /// The select's label.
    pub choose: &'static str,
    /// The select's first choice: no plant.
    pub none: &'static str,
    /// Each plant's name in words, by its engine name.
    pub plants: [(&'static str, &'static str); 6],
    /// Said while no plant is chosen.
    pub idle: &'static str,
    /// Said while the machine does not run (the plant stands still).
    pub standing: &'static str,
    /// The conveyor's count: "{n} delivered".
    pub delivered: &'static str,
    /// The tank's level: "level {n} %".
    pub level: &'static str,
    /// A signal not wired to any device.
    pub unwired: &'static str,
    /// No alarm so far.
    pub no_alarm: &'static str,
    /// Before an alarm's time: "Alarm at".
    pub alarm_at: &'static str,
    /// The wiring table's heading and columns.
    pub wiring: &'static str,
    pub signal: &'static str,
    pub device: &'static str,
    pub direction_in: &'static str,
    pub direction_out: &'static str,
    /// Applies the wiring as edited.
    pub apply: &'static str,
    /// Puts the machine's default wiring back.
    pub default_wiring: &'static str,
    /// Said over refusals: the plant is not attached until they are fixed.
    pub refused: &'static str,
    /// The signals' and quantities' heading.
    pub signals: &'static str,
}

impl PlantTexts {
    /// A plant's name in words (its engine name if unknown).
    pub fn plant_name(&self, name: &'static str) -> &'static str {
        self.plants
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(name, |(_, said)| said)
    }
}

/// English.
pub static EN: PlantTexts = PlantTexts {
    tab: "Plant",
    choose: "Plant",
    none: "None",
    plants: [
        ("conveyor", "Conveyor belt"),
        ("tank", "Tank"),
        ("traffic", "Pedestrian crossing"),
        ("door", "Garage door"),
        ("sorter", "Sorter"),
        ("room-light", "Room light"),
    ],
    idle: "Choose a plant: a machine for the ladder to control. Its sensors drive the inputs, the outputs drive it.",
    standing: "The machine is not running: the plant stands still.",
    delivered: "delivered",
    level: "level",
    unwired: "not wired",
    no_alarm: "No alarm.",
    alarm_at: "Alarm at",
    wiring: "Wiring",
    signal: "Signal",
    device: "Device",
    direction_in: "sensor",
    direction_out: "actuator",
    apply: "Apply wiring",
    default_wiring: "Machine's default",
    refused: "The plant is not attached until these are fixed:",
    signals: "Signals",
};

/// Japanese.
pub static JA: PlantTexts = PlantTexts {
    tab: "プラント",
    choose: "プラント",
    none: "なし",
    plants: [
        ("conveyor", "ベルトコンベヤ"),
        ("tank", "タンク"),
        ("traffic", "押しボタン式信号"),
        ("door", "ガレージのドア"),
        ("sorter", "仕分け機"),
        ("room-light", "部屋の照明"),
    ],
    idle: "プラント（ラダーで制御する機械）を選んでください。センサーが入力を動かし、出力がプラントを動かします。",
    standing: "PLC が運転していないので、プラントは止まっています。",
    delivered: "個 搬出",
    level: "水位",
    unwired: "未配線",
    no_alarm: "警報はありません。",
    alarm_at: "警報",
    wiring: "配線",
    signal: "信号",
    device: "デバイス",
    direction_in: "センサー",
    direction_out: "アクチュエータ",
    apply: "配線を適用",
    default_wiring: "機種の標準配線",
    refused: "次の問題を直すまでプラントはつながりません：",
    signals: "信号",
};
