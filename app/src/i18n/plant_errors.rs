//! The plant's refusals that are no wiring row's (issue #52), in the
//! page's language from their kind: a fault the engine does not take, a
//! parameter, the plant's own check of its parameters together
//! ([`Misfit`]), a plant that is none. The names stay as written (what a
//! project and `--fault` say); English is the engine's `Display`.

use engine::error::shown;
use engine::plant::{Misfit, PlantError};

use super::Lang;

/// Why the plant refuses a fault, a parameter or a name, in `lang`.
pub fn plant_error(lang: Lang, e: &PlantError) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Ja => plant_ja(e),
    }
}

fn plant_ja(e: &PlantError) -> String {
    match e {
        PlantError::UnknownSignal { plant, name, known } => {
            format!("{plant} に信号 {} はありません (信号: {known})", shown(name))
        }
        PlantError::FaultUsage => "故障は「信号 stuck 0|1 [from 時間] [hidden]」か「信号 dead [from 時間] [hidden]」と書きます".to_string(),
        PlantError::FaultTime(time, e) => {
            format!("from {}: {}", shown(time), super::errors::time_ja(e))
        }
        PlantError::AnalogFault(s) => {
            format!("{s} はアナログ信号です: 故障にできるのはビット信号だけです")
        }
        PlantError::DeadSensor(s) => format!(
            "{s} はセンサーです: dead はアクチュエーター用です (何も読まないセンサーは stuck 0)"
        ),
        PlantError::UnknownParam { plant, key, known } => format!(
            "{plant} にパラメーター {} はありません (パラメーター: {known})",
            shown(key)
        ),
        PlantError::NotANumber { key, text, range } => format!(
            "{key} には整数を入れます ({range})。{} は使えません",
            shown(text)
        ),
        PlantError::OutOfRange { key, value, range } => {
            format!("{key} = {value} は範囲外です ({range})")
        }
        PlantError::Together(m) => format!("ほかのパラメーターと合いません: {}", misfit_ja(m)),
        PlantError::NoPlant { name, known } => {
            format!("プラント {} はありません (プラント: {known})", shown(name))
        }
    }
}

/// A plant's own check of its parameters, in Japanese.
fn misfit_ja(m: &Misfit) -> String {
    match m {
        Misfit::PartOverHalfBelt { part, length } => {
            format!("part = {part} mm がベルトの半分より長くなっています (length = {length} mm)")
        }
        Misfit::LowAboveHigh { low, high } => {
            format!("下限スイッチ ({low} %) が上限スイッチ ({high} %) より上にあります")
        }
        Misfit::PartOverFace { part, face } => {
            format!("part = {part} mm がプッシャーの面より長くなっています (face = {face} mm)")
        }
        Misfit::BeltTooShort {
            length,
            part,
            from,
            to,
        } => format!(
            "ベルト (length = {length} mm) が、{part} mm の部品二つにも、{from}..{to} mm のプッシャーにも足りません"
        ),
    }
}

#[cfg(test)]
mod tests {
    use engine::time::SimTime;

    use super::*;

    fn s() -> String {
        "X".to_string()
    }

    /// Each kind of [`Misfit`], one by one.
    fn misfits() -> Vec<Misfit> {
        vec![
            Misfit::PartOverHalfBelt {
                part: 200,
                length: 300,
            },
            Misfit::LowAboveHigh { low: 90, high: 80 },
            Misfit::PartOverFace {
                part: 100,
                face: 80,
            },
            Misfit::BeltTooShort {
                length: 1000,
                part: 50,
                from: 990,
                to: 1070,
            },
        ]
    }

    /// Each kind of [`PlantError`], one by one.
    fn kinds() -> Vec<PlantError> {
        let time = SimTime::parse("soon").unwrap_err();
        let mut all = vec![
            PlantError::UnknownSignal {
                plant: "conveyor",
                name: s(),
                known: "infeed, outfeed, motor".into(),
            },
            PlantError::FaultUsage,
            PlantError::FaultTime("soon".into(), time),
            PlantError::AnalogFault("tank.level".into()),
            PlantError::DeadSensor("conveyor.infeed".into()),
            PlantError::UnknownParam {
                plant: "conveyor",
                key: s(),
                known: "speed, length".into(),
            },
            PlantError::NotANumber {
                key: "speed",
                text: s(),
                range: "1..10000 mm/s".into(),
            },
            PlantError::OutOfRange {
                key: "speed",
                value: 20_000,
                range: "1..10000 mm/s".into(),
            },
            PlantError::NoPlant {
                name: s(),
                known: "conveyor, tank".into(),
            },
        ];
        all.extend(misfits().into_iter().map(PlantError::Together));
        all
    }

    #[test]
    fn every_refusal_of_a_plant_is_said_in_japanese_and_in_the_engines_english() {
        let kinds = kinds();
        assert_eq!(kinds.len(), 13);
        for e in &kinds {
            let ja = plant_error(Lang::Ja, e);
            assert!(ja.chars().any(|c| c > '\u{3000}'), "{e:?}: {ja}");
            assert_eq!(super::super::errors::english_run(&ja), None, "{e:?}: {ja}");
            assert_eq!(plant_error(Lang::En, e), e.to_string());
        }
    }

    #[test]
    fn a_misfit_keeps_its_numbers_in_japanese() {
        for m in misfits() {
            let ja = plant_error(Lang::Ja, &PlantError::Together(m.clone()));
            let en = m.to_string();
            // Every number the engine says is said in Japanese too.
            let numbers = |t: &str| -> Vec<String> {
                t.split(|c: char| !c.is_ascii_digit())
                    .filter(|n| !n.is_empty())
                    .map(str::to_string)
                    .collect()
            };
            let mut a = numbers(&en);
            let mut b = numbers(&ja);
            a.sort();
            b.sort();
            assert_eq!(a, b, "{en} / {ja}");
        }
    }

    #[test]
    fn a_fault_the_engine_refuses_is_said_in_japanese() {
        let info = &engine::plant::conveyor::INFO;
        for text in ["infeed dead", "belt stuck 1", "motor stuck 1 from soon", ""] {
            let e = engine::plant::Fault::parse(text, info).unwrap_err();
            let ja = plant_error(Lang::Ja, &e);
            assert_eq!(super::super::errors::english_run(&ja), None, "{text}: {ja}");
        }
    }
}
