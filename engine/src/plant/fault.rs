//! Faults (`--fault`): a signal stuck at 0 or 1, or an actuator dead,
//! each from a given time, so a teacher can hand out a faulty machine.
//! A fault may end in `hidden`: it acts the same, and the page does not
//! show it to a student in an exercise, whose task is to find it.

use super::{Direction, Kind, PlantError, PlantInfo};
use crate::time::SimTime;

/// What is wrong with a signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultKind {
    /// A sensor that reads this value, or an actuator that acts as if so
    /// driven, whatever the PLC writes (a leaking valve: stuck 1).
    Stuck(bool),
    /// An actuator that no longer acts.
    Dead,
}

/// One fault on one signal, from a time on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fault {
    /// The signal, by index in the plant's signals.
    pub signal: usize,
    /// What is wrong.
    pub kind: FaultKind,
    /// From when (0: from power-on).
    pub from: SimTime,
    /// Not shown to a student in an exercise (the text ends in `hidden`).
    pub hidden: bool,
}

impl Fault {
    /// Parses `SIGNAL stuck 0|1 [from TIME] [hidden]` or `SIGNAL dead
    /// [from TIME] [hidden]` for the plant `plant`.
    pub fn parse(text: &str, plant: &PlantInfo) -> Result<Fault, PlantError> {
        let mut words: Vec<&str> = text.split_whitespace().collect();
        let hidden = words.last() == Some(&"hidden");
        if hidden {
            words.pop();
        }
        let Some((&name, rest)) = words.split_first() else {
            return Err(PlantError::FaultUsage);
        };
        let signal = plant.signal_named(name)?;
        let info = &plant.signals[signal];
        let (kind, rest) = match rest {
            ["stuck", "0", rest @ ..] => (FaultKind::Stuck(false), rest),
            ["stuck", "1", rest @ ..] => (FaultKind::Stuck(true), rest),
            ["dead", rest @ ..] => (FaultKind::Dead, rest),
            _ => return Err(PlantError::FaultUsage),
        };
        let from = match rest {
            [] => SimTime::ZERO,
            ["from", time] => {
                SimTime::parse(time).map_err(|e| PlantError::FaultTime(time.to_string(), e))?
            }
            _ => return Err(PlantError::FaultUsage),
        };
        let full = format!("{}.{}", plant.name, info.name);
        if info.kind == Kind::Analog {
            return Err(PlantError::AnalogFault(full));
        }
        if kind == FaultKind::Dead && info.direction == Direction::In {
            return Err(PlantError::DeadSensor(full));
        }
        Ok(Fault {
            signal,
            kind,
            from,
            hidden,
        })
    }

    /// Whether `named` (a fault as [`Fault::parse`] reads it, its time
    /// and `hidden` aside) names this fault: the same signal, the same
    /// kind. A student's answer in an exercise names a hidden fault so.
    pub fn is_named(&self, named: &Fault) -> bool {
        self.signal == named.signal && self.kind == named.kind
    }
}

/// Whether a fault's text ends in `hidden` (checked without the plant,
/// so the page's first screen knows an exercise hides a fault).
pub fn is_hidden(text: &str) -> bool {
    text.split_whitespace().last() == Some("hidden")
}

/// The fault acting on `signal` at `now`: of those begun, the one that
/// began last (the later of two at the same time: the one given later).
pub fn acting(faults: &[Fault], signal: usize, now: SimTime) -> Option<FaultKind> {
    faults
        .iter()
        .filter(|f| f.signal == signal && f.from <= now)
        .max_by_key(|f| f.from)
        .map(|f| f.kind)
}

/// `value` as a fault leaves it.
pub fn apply(kind: Option<FaultKind>, value: i64) -> i64 {
    match kind {
        None => value,
        Some(FaultKind::Stuck(v)) => i64::from(v),
        Some(FaultKind::Dead) => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::conveyor::INFO;

    #[test]
    fn faults_parse_with_their_time_and_refuse_what_cannot_be() {
        let f = Fault::parse("motor stuck 1 from 2s", &INFO).unwrap();
        assert_eq!(f.signal, 2);
        assert_eq!(f.kind, FaultKind::Stuck(true));
        assert_eq!(f.from, SimTime::from_secs(2));
        let f = Fault::parse("conveyor.infeed stuck 0", &INFO).unwrap();
        assert_eq!((f.signal, f.from), (0, SimTime::ZERO));
        assert!(Fault::parse("motor dead", &INFO).is_ok());
        let e = Fault::parse("infeed dead", &INFO).unwrap_err().to_string();
        assert!(e.contains("sensor"), "{e}");
        let e = Fault::parse("belt stuck 1", &INFO).unwrap_err().to_string();
        assert!(
            e.contains("\"belt\"") && e.contains("infeed, outfeed, motor"),
            "{e}"
        );
        assert!(Fault::parse("motor stuck 2", &INFO).is_err());
        assert!(Fault::parse("motor stuck 1 from", &INFO).is_err());
        assert!(Fault::parse("motor stuck 1 from soon", &INFO).is_err());
        assert!(Fault::parse("", &INFO).is_err());
        let tank = &crate::plant::tank::INFO;
        let e = Fault::parse("level stuck 1", tank).unwrap_err();
        assert_eq!(e, PlantError::AnalogFault("tank.level".into()));
        assert_eq!(
            Fault::parse("motor stuck 1 from soon", &INFO)
                .unwrap_err()
                .to_string(),
            "from \"soon\": ".to_string() + &SimTime::parse("soon").unwrap_err().to_string()
        );
    }

    #[test]
    fn a_fault_ending_in_hidden_acts_the_same_and_is_marked() {
        let f = Fault::parse("infeed stuck 0 from 5s hidden", &INFO).unwrap();
        assert_eq!(
            (f.signal, f.kind, f.from, f.hidden),
            (0, FaultKind::Stuck(false), SimTime::from_secs(5), true)
        );
        assert!(!Fault::parse("infeed stuck 0", &INFO).unwrap().hidden);
        assert!(Fault::parse("motor dead hidden", &INFO).unwrap().hidden);
        assert!(Fault::parse("hidden", &INFO).is_err());
        assert!(Fault::parse("motor hidden dead", &INFO).is_err());
        assert!(is_hidden("motor dead hidden") && !is_hidden("motor dead"));
    }

    #[test]
    fn the_latest_begun_fault_acts() {
        let faults = [
            Fault {
                signal: 2,
                kind: FaultKind::Stuck(true),
                from: SimTime::ZERO,
                hidden: false,
            },
            Fault {
                signal: 2,
                kind: FaultKind::Dead,
                from: SimTime::from_secs(5),
                hidden: false,
            },
        ];
        assert_eq!(
            acting(&faults, 2, SimTime::from_secs(1)),
            Some(FaultKind::Stuck(true))
        );
        assert_eq!(
            acting(&faults, 2, SimTime::from_secs(5)),
            Some(FaultKind::Dead)
        );
        assert_eq!(acting(&faults, 0, SimTime::from_secs(5)), None);
        assert!(faults[1].is_named(&Fault::parse("motor dead", &INFO).unwrap()));
        assert!(!faults[1].is_named(&Fault::parse("motor stuck 1", &INFO).unwrap()));
        assert_eq!(apply(Some(FaultKind::Dead), 1), 0);
        assert_eq!(apply(None, 1), 1);
    }
}
