//! Break conditions: `Y01 rises`, `Y01 falls`, `T00 on`, `X00 off`,
//! `C0.v = 5` (also `!=`, `<`, `<=`, `>`, `>=`), `D00 changes`. Checked
//! at the end of every scan; the machine stops at the first scan where
//! one holds.

use std::fmt;

use crate::plc::{Device, Plc, Value};

/// A condition on one device, resolved for one machine.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition {
    /// The device's name as written.
    pub name: String,
    /// The whole condition as written.
    text: String,
    device: Device,
    test: Test,
    /// The device's value at the last check (for rises, falls, changes).
    last: Value,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Test {
    Rises,
    Falls,
    Changes,
    Compare(Cmp, i64),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

/// Why a condition was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ConditionError {
    /// Not `DEVICE rises|falls|on|off|changes` or `DEVICE OP NUMBER`.
    Form(String),
    /// The machine has no such device (its refusal).
    Device(crate::plc::PlcError),
}

impl fmt::Display for ConditionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConditionError::Form(text) => write!(
                f,
                "`{text}`: write DEVICE rises|falls|on|off|changes, or DEVICE = N \
                 (also !=, <, <=, >, >=), e.g. `Y01 rises`, `C0.v = 5`"
            ),
            ConditionError::Device(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for ConditionError {}

impl Condition {
    /// Reads `text` for `machine`, whose present values are the starting
    /// point for rises, falls and changes.
    pub fn parse(text: &str, machine: &dyn Plc) -> Result<Condition, ConditionError> {
        let form = || ConditionError::Form(text.trim().to_string());
        let words: Vec<&str> = split(text);
        let (name, test) = match words.as_slice() {
            [name, word] => {
                let test = match word.to_ascii_lowercase().as_str() {
                    "rises" | "rise" | "↑" => Test::Rises,
                    "falls" | "fall" | "↓" => Test::Falls,
                    "changes" | "change" => Test::Changes,
                    "on" => Test::Compare(Cmp::Ne, 0),
                    "off" => Test::Compare(Cmp::Eq, 0),
                    _ => return Err(form()),
                };
                (*name, test)
            }
            [name, op, number] => {
                let cmp = match *op {
                    "=" | "==" => Cmp::Eq,
                    "!=" | "<>" => Cmp::Ne,
                    "<" => Cmp::Lt,
                    "<=" => Cmp::Le,
                    ">" => Cmp::Gt,
                    ">=" => Cmp::Ge,
                    _ => return Err(form()),
                };
                let n = number.parse::<i64>().map_err(|_| form())?;
                (*name, Test::Compare(cmp, n))
            }
            _ => return Err(form()),
        };
        let device = machine.device(name).map_err(ConditionError::Device)?;
        Ok(Condition {
            name: name.to_string(),
            text: text.trim().to_string(),
            device,
            test,
            last: machine.read(device),
        })
    }

    /// The condition as written.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Whether it holds after the scan `machine` just completed.
    pub fn holds(&mut self, machine: &dyn Plc) -> bool {
        let now = machine.read(self.device);
        let before = std::mem::replace(&mut self.last, now.clone());
        match self.test {
            Test::Rises => !before.is_on() && now.is_on(),
            Test::Falls => before.is_on() && !now.is_on(),
            Test::Changes => before != now,
            Test::Compare(cmp, n) => match cmp {
                Cmp::Eq => now == n,
                Cmp::Ne => now != n,
                Cmp::Lt => now < n,
                Cmp::Le => now <= n,
                Cmp::Gt => now > n,
                Cmp::Ge => now >= n,
            },
        }
    }
}

/// Splits `C0.v=5` as `C0.v = 5`: operators need no spaces around them.
fn split(text: &str) -> Vec<&str> {
    let text = text.trim();
    for op in ["==", "!=", "<>", "<=", ">=", "=", "<", ">"] {
        if let Some(at) = text.find(op) {
            let (name, number) = (text[..at].trim(), text[at + op.len()..].trim());
            return vec![name, op, number];
        }
    }
    text.split_whitespace().collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::machines::{AvrPlc, Io86aPlc};

    #[test]
    fn conditions_read_with_or_without_spaces_and_refuse_what_they_cannot() {
        let m = Io86aPlc::new();
        for text in [
            "Y01 rises",
            "C00.v = 5",
            "C00.v=5",
            "T00 on",
            "X00 off",
            "D00 >= -3",
        ] {
            assert!(Condition::parse(text, &m).is_ok(), "{text}");
        }
        assert!(matches!(
            Condition::parse("Y01 jumps", &m),
            Err(ConditionError::Form(_))
        ));
        assert!(matches!(
            Condition::parse("C00.v = five", &m),
            Err(ConditionError::Form(_))
        ));
        assert!(matches!(
            Condition::parse("Q9 rises", &m),
            Err(ConditionError::Device(_))
        ));
        assert!(Condition::parse("", &m).is_err());
    }

    #[test]
    fn rises_holds_once_per_rise_and_values_compare() {
        let mut m = AvrPlc::new();
        m.load_text(include_str!("../../programs/avr-plc/self-hold.asm"))
            .expect("example");
        let inputs = [m.device("INPUT1"), m.device("INPUT2")].map(|d| d.expect("input"));
        let mut rises = Condition::parse("COIL1 rises", &m).expect("cond");
        let mut on = Condition::parse("COIL2 = 1", &m).expect("cond");
        let mut seen = Vec::new();
        for scan in 0..6u64 {
            if scan == 2 {
                for d in inputs {
                    let press = crate::plc::Command::SetInput(d, crate::events::InputValue::Int(1));
                    m.apply(press).expect("press");
                }
            }
            m.step_scan();
            seen.push((rises.holds(&m), on.holds(&m)));
        }
        assert_eq!(seen[..2], [(false, false), (false, false)]);
        assert_eq!(seen[2], (true, true), "the scan that latches");
        assert_eq!(seen[3..], [(false, true), (false, true), (false, true)]);
    }
}
