//! The plant's wiring refusals in the page's language (issue #52), from
//! their kind ([`WireError`]) as the alarms are (`super::plant`): the
//! signal and device names stay as written (what a wiring file says), the
//! machine's own refusal is said as the page says it elsewhere. And the
//! dock's parameters: their strings, their refusals.

use engine::error::shown;
use engine::plant::error::PlantError;
use engine::plant::wiring::WireError;

use super::Lang;
use crate::rig::Refusal;

/// The parameters' strings.
pub struct ParamTexts {
    /// The section's heading.
    pub params: &'static str,
    /// What a value does (and an empty one).
    pub params_note: &'static str,
}

const EN: ParamTexts = ParamTexts {
    params: "Parameters",
    params_note:
        "Each as hashigo --set takes it (empty: its default). A new value starts the plant again.",
};

const JA: ParamTexts = ParamTexts {
    params: "パラメーター",
    params_note:
        "hashigo の --set と同じ書き方です (空欄は既定値)。値を変えるとプラントは最初から動きます。",
};

/// The parameters' strings in `lang`.
pub fn texts(lang: Lang) -> &'static ParamTexts {
    match lang {
        Lang::Ja => &JA,
        Lang::En => &EN,
    }
}

/// Why a parameter's value is refused, in `lang`.
pub fn param_error(lang: Lang, e: &PlantError) -> String {
    super::plant_errors::plant_error(lang, e)
}

/// A refusal of the plant's setup, as the dock says it.
pub fn refusal(lang: Lang, r: &Refusal) -> String {
    match (lang, r) {
        (Lang::Ja, Refusal::Wire(e)) => wire_ja(e),
        (Lang::En, Refusal::Wire(e)) => e.to_string(),
        (lang, Refusal::Plant(e)) => super::plant_errors::plant_error(lang, e),
    }
}

/// A wiring row's refusal in Japanese.
fn wire_ja(e: &WireError) -> String {
    let plc = |e| super::errors::plc_error(Lang::Ja, e);
    match e {
        WireError::Signal(PlantError::UnknownSignal { plant, name, known }) => {
            format!(
                "{plant} に信号 {} はありません (信号: {known})",
                shown(name)
            )
        }
        WireError::Signal(other) => super::plant_errors::plant_error(Lang::Ja, other),
        WireError::NoDevice {
            full,
            device,
            error,
        } => format!("{full} を {} に: {}", shown(device), plc(error)),
        WireError::AnalogRefused {
            full,
            device,
            error,
        } => format!("{full} を {device} に: {}", plc(error)),
        WireError::NotAnalog {
            full,
            device,
            machine,
            analog,
        } => {
            let has = if analog.is_empty() {
                format!("{machine} にはアナログ入力がありません")
            } else {
                format!("{machine} のアナログ入力は {} です", analog.join("、"))
            };
            format!("{full} はアナログ信号ですが、{device} はアナログ入力ではありません ({has})")
        }
        WireError::SensorNeedsInput { full, error } => {
            format!(
                "{full} は PLC が読むセンサーなので、入力につなぎます: {}",
                plc(error)
            )
        }
        WireError::ActuatorOnInput { full, device } => {
            format!("{full} は PLC が動かすアクチュエーターですが、{device} は入力です")
        }
        WireError::Twice { full } => format!("{full} が二度配線されています"),
        WireError::TwoSignals { device, full } => {
            format!("{device} に二つの信号がつながっています ({full} とほかの信号)")
        }
    }
}

#[cfg(test)]
mod tests {
    use engine::machines::MinasecPlc;

    use super::*;

    /// An English word (lowercase, three letters or more) in a Japanese
    /// sentence, once the names it keeps as written are out (plants,
    /// signals and machines; device names are upper case).
    fn english_in(text: &str, names: &[&str]) -> bool {
        text.split(|c: char| !c.is_ascii_lowercase())
            .any(|w| w.len() >= 3 && !names.contains(&w))
    }

    #[test]
    fn every_wiring_refusal_of_a_machine_is_said_in_japanese() {
        let machine = MinasecPlc::new();
        let info = (engine::plant::any::ALL.iter())
            .find(|p| p.name == "tank")
            .expect("the tank");
        let rows = [
            ("level", "X04"),
            ("nothing", "X00"),
            ("low", "Q99"),
            ("fill", "X00"),
            ("low", "Y00"),
            ("low", "X00"),
            ("low", "X01"),
            ("high", "X00"),
        ];
        let entries: Vec<_> = (rows.iter().enumerate())
            .map(|(i, (signal, device))| engine::plant::wiring::WireEntry {
                signal: signal.to_string(),
                device: device.to_string(),
                line: i + 1,
            })
            .collect();
        let errors = engine::plant::wiring::check(info, &machine, &entries).unwrap_err();
        // Each row's own kind: analog, no signal, no device, an actuator
        // on an input, a sensor on an output, wired twice, two signals.
        assert_eq!(errors.len(), 7, "{errors:?}");
        let names = [
            "tank", "level", "nothing", "low", "high", "fill", "drain", "minasec",
        ];
        for e in errors {
            let r = Refusal::Wire(e.error.clone());
            let ja = refusal(Lang::Ja, &r);
            // The machine's own refusal too (MINASEC-U's list of its
            // inputs names its CNTCLR button).
            assert!(!english_in(&ja, &names), "row {}: {ja}", e.line);
            assert_eq!(refusal(Lang::En, &r), e.error.to_string());
        }
    }
}
