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
    /// Signals and quantities in words, by plant and engine name (empty:
    /// the engine's names, which are also what wiring files and tests
    /// write).
    pub words: &'static [(&'static str, &'static str, &'static str)],
    /// An alarm's message (the engine's English) in this language.
    pub alarm: fn(&str) -> String,
}

impl PlantTexts {
    /// A plant's name in words (its engine name if unknown).
    pub fn plant_name(&self, name: &'static str) -> &'static str {
        self.plants
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(name, |(_, said)| said)
    }

    /// Signal or quantity `name` of plant `plant` in words (`alarms` is
    /// every plant's); its engine name if the table has none.
    pub fn said<'a>(&self, plant: &str, name: &'a str) -> &'a str {
        self.words
            .iter()
            .find(|(p, n, _)| (*p == plant || p.is_empty()) && *n == name)
            .map_or(name, |(_, _, said)| said)
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
    words: &[],
    alarm: str::to_string,
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
    words: &WORDS_JA,
    alarm: alarm_ja,
};

/// The plants' signals and quantities in Japanese ("" : every plant's).
static WORDS_JA: [(&str, &str, &str); 45] = [
    ("", "alarms", "警報の数"),
    ("conveyor", "infeed", "入口センサー"),
    ("conveyor", "outfeed", "出口センサー"),
    ("conveyor", "motor", "モーター"),
    ("conveyor", "placed", "載せた数"),
    ("conveyor", "delivered", "搬出した数"),
    ("conveyor", "on_belt", "ベルト上の数"),
    ("tank", "low", "下限スイッチ"),
    ("tank", "high", "上限スイッチ"),
    ("tank", "level", "水位"),
    ("tank", "fill", "給水弁"),
    ("tank", "drain", "排水弁"),
    ("tank", "overflow_ms", "あふれた時間 (ms)"),
    ("traffic", "button", "押しボタン"),
    ("traffic", "car_red", "車用の赤"),
    ("traffic", "car_yellow", "車用の黄"),
    ("traffic", "car_green", "車用の青"),
    ("traffic", "walk", "歩行者用の青"),
    ("traffic", "dont_walk", "歩行者用の赤"),
    ("traffic", "crossed", "渡った人数"),
    ("traffic", "waited_max", "最長の待ち時間 (ms)"),
    ("traffic", "waiting", "待っている人数"),
    ("door", "top", "上限スイッチ"),
    ("door", "bottom", "下限スイッチ"),
    ("door", "eye", "光電センサー"),
    ("door", "remote", "リモコン"),
    ("door", "up", "上げ"),
    ("door", "down", "下げ"),
    ("door", "position", "開き具合 (%)"),
    ("sorter", "part", "部品センサー"),
    ("sorter", "tall", "高さセンサー"),
    ("sorter", "pusher_out", "押し出し端スイッチ"),
    ("sorter", "pusher_in", "戻り端スイッチ"),
    ("sorter", "belt", "ベルト"),
    ("sorter", "push", "押し出し弁"),
    ("sorter", "right", "正しい箱へ"),
    ("sorter", "wrong", "違う箱へ"),
    ("sorter", "on_belt", "ベルト上の数"),
    ("room-light", "dark", "暗さセンサー"),
    ("room-light", "light", "明るさセンサー"),
    ("room-light", "lamp", "照明"),
    ("room-light", "lamp_on_ms", "むだな点灯 (ms)"),
    ("room-light", "unlit_ms", "暗いままの時間 (ms)"),
    ("room-light", "daylight", "日の光 (%)"),
    ("room-light", "hour", "時刻"),
];

/// A plant's alarm in Japanese, from its kind and numbers; words no plant
/// says are kept as written.
fn alarm_ja(message: &str) -> String {
    use engine::plant::alarm::AlarmKind as A;
    let Some(kind) = A::parse(message) else {
        return message.to_string();
    };
    match kind {
        A::BeltTooSoon { since, guard } => format!(
            "部品が入口に来てから {since} ms でベルトが動き出しました ({guard} ms より早く、危険です)"
        ),
        A::Overflow => "あふれ: タンクが満水なのに給水弁が開いています".to_string(),
        A::CarsOnWalk { green } => format!(
            "歩行者用が青なのに車用が{}です: 横断歩道が危険です",
            if green { "青" } else { "黄" }
        ),
        A::BothWays => "モーターを上げと下げに同時に回しています".to_string(),
        A::AgainstLimit { up, grace } => {
            let (limit, way) = if up { ("上限", "上げ") } else { ("下限", "下げ") };
            format!("{limit}スイッチに届いたまま、モーターを {grace} ms より長く{way}方向に回しています")
        }
        A::ClosingOnEye { grace } => {
            format!("光電センサーが遮られているのに、{grace} ms より長くドアを閉めています")
        }
        A::PusherHit { tall } => format!(
            "押し出し機が動く途中で背の{}部品に当たりました (部品が押し出し面の前に収まっていませんでした)",
            if tall { "高い" } else { "低い" }
        ),
    }
}

#[cfg(test)]
mod tests {
    use engine::plant::alarm::AlarmKind;
    use engine::plant::any::ALL;

    /// Latin letters other than the units and device names a Japanese
    /// sentence keeps.
    fn english_in(text: &str) -> bool {
        text.replace("ms", "")
            .chars()
            .any(|c| c.is_ascii_alphabetic())
    }

    #[test]
    fn every_signal_and_quantity_of_every_plant_has_its_japanese_words() {
        for plant in ALL {
            let names = plant.signals.iter().map(|s| s.name);
            let names = names.chain(plant.quantities.iter().map(|q| q.name));
            for name in names.chain(["alarms"]) {
                let said = super::JA.said(plant.name, name);
                assert!(!english_in(said), "{}.{name}: {said}", plant.name);
                assert_eq!(super::EN.said(plant.name, name), name);
            }
        }
    }

    #[test]
    fn every_alarm_is_said_in_japanese_from_its_kind_and_numbers() {
        let mut said = std::collections::HashSet::new();
        for kind in AlarmKind::SAMPLES {
            let english = kind.to_string();
            let ja = (super::JA.alarm)(&english);
            assert!(!english_in(&ja), "{english}: {ja}");
            assert_eq!((super::EN.alarm)(&english), english);
            // Each kind its own words.
            assert!(said.insert(ja.clone()), "{ja}");
        }
        let ja = (super::JA.alarm)(
            &AlarmKind::BeltTooSoon {
                since: 301,
                guard: 1000,
            }
            .to_string(),
        );
        assert!(ja.contains("301 ms") && ja.contains("1000 ms"), "{ja}");
    }
}
