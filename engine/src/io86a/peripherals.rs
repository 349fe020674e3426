//! PLC-IO86A's pin modes: X04/X05 analog input, X07 IR receiver, Y03/Y04
//! PWM or RC-servo output, and the input filter. Set with the terminal's
//! setting commands (`X04A:401:100`, `X07I:10EF`, `Y03R`, `!2`).

use std::fmt;

use crate::time::SimTime;

/// X04 or X05: digital, or analog with 0-5 V mapped to 0..n1-1, plus n2.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum InputMode {
    /// A digital input (default).
    #[default]
    Digital,
    /// `X0nA:n1:n2`.
    Analog {
        /// Steps of the full scale plus one (2..=1024).
        n1: u16,
        /// Offset added (0..).
        n2: u16,
    },
}

impl InputMode {
    /// The value the AD conversion gives for `millivolts` (0-5 V).
    pub fn convert(self, millivolts: i64) -> Option<i16> {
        match self {
            InputMode::Digital => None,
            InputMode::Analog { n1, n2 } => {
                let mv = millivolts.clamp(0, FULL_SCALE_MV);
                let steps = i64::from(n1) - 1;
                // Round to the nearest step.
                let value = (mv * steps + FULL_SCALE_MV / 2) / FULL_SCALE_MV + i64::from(n2);
                Some(value as i16)
            }
        }
    }
}

/// The analog full scale: the 5 V supply.
pub const FULL_SCALE_MV: i64 = 5000;

/// X07: digital, or the IR receiver (NEC format) with an optional custom
/// code to accept.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum IrMode {
    /// A digital input (default).
    #[default]
    Digital,
    /// `X07I` or `X07I:nnnn`.
    Ir {
        /// Only frames with this custom code reach D03.
        custom: Option<u16>,
    },
}

/// Y03 or Y04: digital, RC servo, or PWM at one of three frequencies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum OutputMode {
    /// A digital output (default), `Y0nD`.
    #[default]
    Digital,
    /// `Y0nR`: 20 ms period, pulse = D × 5 µs (D 0..=500).
    Servo,
    /// `Y0nS` / `Y0nM` / `Y0nH`: 200 Hz / 400 Hz / 32 kHz, duty = D % (0..=100).
    Pwm(u32),
}

/// What an output pin does, for panels and watches (off until told).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputSignal {
    /// A level.
    Level(bool),
    /// Servo pulses every 20 ms of this width; `None` while the Y bit is off.
    Servo(Option<SimTime>),
    /// PWM at `hz` with `duty` percent; 0 % while the Y bit is off.
    Pwm { hz: u32, duty: u8 },
}

impl Default for OutputSignal {
    fn default() -> Self {
        OutputSignal::Level(false)
    }
}

impl OutputMode {
    /// The pin's signal for the Y bit and its D register (D04 / D05).
    pub fn signal(self, on: bool, command: i16) -> OutputSignal {
        match self {
            OutputMode::Digital => OutputSignal::Level(on),
            OutputMode::Servo => {
                let units = u64::try_from(command.clamp(0, 500)).unwrap_or(0);
                OutputSignal::Servo(on.then(|| SimTime::from_micros(units * 5)))
            }
            OutputMode::Pwm(hz) => OutputSignal::Pwm {
                hz,
                duty: if on { command.clamp(0, 100) as u8 } else { 0 },
            },
        }
    }
}

impl OutputSignal {
    /// The number a watch shows: the level, the pulse in µs, or the duty %.
    pub fn value(self) -> i64 {
        match self {
            OutputSignal::Level(on) => i64::from(on),
            OutputSignal::Servo(pulse) => pulse.map_or(0, |p| (p.as_nanos() / 1000) as i64),
            OutputSignal::Pwm { duty, .. } => i64::from(duty),
        }
    }
}

/// The device's settings (the `V` command shows them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// X04, X05.
    pub analog: [InputMode; 2],
    /// X07.
    pub ir: IrMode,
    /// Y03, Y04.
    pub outputs: [OutputMode; 2],
    /// The input filter `!n` (0..=10): an input change counts once it has
    /// held for n × 10 ms.
    pub filter: u8,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            analog: [InputMode::Digital; 2],
            ir: IrMode::Digital,
            outputs: [OutputMode::Digital; 2],
            filter: DEFAULT_FILTER,
        }
    }
}

/// The input filter after power-on (`!2`, about 20-30 ms).
pub const DEFAULT_FILTER: u8 = 2;

impl Settings {
    /// How long an input must hold before the image takes it.
    pub fn filter_time(&self) -> SimTime {
        SimTime::from_millis(u64::from(self.filter) * 10)
    }

    /// Applies one setting command (`X04A:401:100`, `X05D`, `X07I`,
    /// `X07I:10EF`, `X07D`, `Y03R|S|M|H|D`, `Y04…`, `!n`). Nothing changes
    /// on error.
    pub fn apply(&mut self, command: &str) -> Result<(), SettingError> {
        let upper = command.trim().to_ascii_uppercase();
        let bad = || SettingError::Unknown(command.trim().to_string());
        if let Some(n) = upper.strip_prefix('!') {
            let n: u8 = n.parse().map_err(|_| SettingError::Filter(n.to_string()))?;
            if n > 10 {
                return Err(SettingError::Filter(n.to_string()));
            }
            self.filter = n;
            return Ok(());
        }
        let (pin, rest) = (upper.get(..3).unwrap_or(""), upper.get(3..).unwrap_or(""));
        match (pin, rest) {
            ("X04" | "X05", _) => {
                let index = usize::from(pin == "X05");
                self.analog[index] = parse_input_mode(rest)
                    .ok_or_else(|| SettingError::Analog(command.trim().to_string()))?;
            }
            ("X07", "D") => self.ir = IrMode::Digital,
            ("X07", "I") => self.ir = IrMode::Ir { custom: None },
            ("X07", code) => {
                let hex = code.strip_prefix("I:").ok_or_else(bad)?;
                let custom = u16::from_str_radix(hex, 16)
                    .ok()
                    .filter(|_| hex.len() == 4)
                    .ok_or_else(|| SettingError::CustomCode(hex.to_string()))?;
                self.ir = IrMode::Ir {
                    custom: Some(custom),
                };
            }
            ("Y03" | "Y04", mode) => {
                let index = usize::from(pin == "Y04");
                self.outputs[index] = match mode {
                    "D" => OutputMode::Digital,
                    "R" => OutputMode::Servo,
                    "S" => OutputMode::Pwm(200),
                    "M" => OutputMode::Pwm(400),
                    "H" => OutputMode::Pwm(32_000),
                    _ => return Err(bad()),
                };
            }
            _ => return Err(bad()),
        }
        Ok(())
    }
}

fn parse_input_mode(rest: &str) -> Option<InputMode> {
    if rest == "D" {
        return Some(InputMode::Digital);
    }
    let mut parts = rest.strip_prefix("A:")?.split(':');
    let n1: u16 = parts.next()?.parse().ok()?;
    let n2: u16 = parts.next()?.parse().ok()?;
    if parts.next().is_some()
        || !(2..=1024).contains(&n1)
        || u32::from(n1) - 1 + u32::from(n2) > 32767
    {
        return None;
    }
    Some(InputMode::Analog { n1, n2 })
}

impl fmt::Display for Settings {
    /// The `V` command's settings lines.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, mode) in self.analog.iter().enumerate() {
            match mode {
                InputMode::Digital => write!(f, "X0{}D ", 4 + i)?,
                InputMode::Analog { n1, n2 } => write!(f, "X0{}A:{n1}:{n2} ", 4 + i)?,
            }
        }
        match self.ir {
            IrMode::Digital => f.write_str("X07D ")?,
            IrMode::Ir { custom: None } => f.write_str("X07I ")?,
            IrMode::Ir { custom: Some(c) } => write!(f, "X07I:{c:04X} ")?,
        }
        for (i, mode) in self.outputs.iter().enumerate() {
            let letter = match mode {
                OutputMode::Digital => 'D',
                OutputMode::Servo => 'R',
                OutputMode::Pwm(200) => 'S',
                OutputMode::Pwm(400) => 'M',
                OutputMode::Pwm(_) => 'H',
            };
            write!(f, "Y0{}{letter} ", 3 + i)?;
        }
        write!(f, "!{}", self.filter)
    }
}

/// A setting command the device does not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SettingError {
    /// Not a setting command.
    Unknown(String),
    /// `X0nA:n1:n2` with n1 outside 2..=1024 or malformed.
    Analog(String),
    /// `X07I:nnnn` with a code that is not four hex digits.
    CustomCode(String),
    /// `!n` with n outside 0..=10.
    Filter(String),
}

impl fmt::Display for SettingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingError::Unknown(c) => write!(f, "unknown setting {}", crate::error::shown(c)),
            SettingError::Analog(c) => {
                write!(
                    f,
                    "bad analog setting {}: X04A:n1:n2 with n1 2..1024",
                    crate::error::shown(c)
                )
            }
            SettingError::CustomCode(c) => write!(
                f,
                "bad custom code {}: four hex digits, e.g. X07I:10EF",
                crate::error::shown(c)
            ),
            SettingError::Filter(n) => write!(f, "bad input filter \"!{n}\": !0..!10"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_manuals_servo_scaling() {
        let mut s = Settings::default();
        s.apply("X04A:401:100").unwrap();
        assert_eq!(s.analog[0].convert(0), Some(100), "0 V → 100 (500 µs)");
        assert_eq!(s.analog[0].convert(5000), Some(500), "5 V → 500 (2500 µs)");
        assert_eq!(s.analog[0].convert(2500), Some(300));
        s.apply("X05A:1024:0").unwrap();
        assert_eq!(s.analog[1].convert(5000), Some(1023));
    }

    #[test]
    fn settings_commands_and_their_errors() {
        let mut s = Settings::default();
        for ok in ["Y03R", "Y04H", "X07I:10EF", "!5", "x05a:101:0"] {
            s.apply(ok).unwrap_or_else(|e| panic!("{ok}: {e}"));
        }
        assert_eq!(s.to_string(), "X04D X05A:101:0 X07I:10EF Y03R Y04H !5");
        let before = s;
        for bad in ["X04A:1:0", "X04A:2000:0", "X07I:XYZ", "Y03Q", "!11", "Z99"] {
            assert!(s.apply(bad).is_err(), "{bad}");
        }
        assert_eq!(s, before, "a rejected command changes nothing");
    }

    #[test]
    fn output_signals() {
        assert_eq!(OutputMode::Servo.signal(true, 100).value(), 500);
        assert_eq!(
            OutputMode::Servo.signal(false, 100),
            OutputSignal::Servo(None)
        );
        assert_eq!(
            OutputMode::Pwm(400).signal(true, 150),
            OutputSignal::Pwm { hz: 400, duty: 100 }
        );
    }
}
