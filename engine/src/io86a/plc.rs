//! PLC-IO86A behind the [`Plc`] interface: `--set` settings, devices by
//! handle, inputs (digital, analog, IR) and the serial terminal.

use super::isa::{parse_bit, parse_word, Bit, Word};
use super::machine::Machine;
use super::peripherals::{InputMode, IrMode};
use super::{LinkedPair, Program, Terminal};
use crate::events::InputValue;
use crate::plc::SettingInfo;
use crate::plc::{self, Device, DeviceError, Drives, Plc, PlcError, SettingError, Value};
use crate::time::SimTime;
use crate::MachineId;

const SETTINGS: &[SettingInfo] = &[
    SettingInfo {
        name: "scan",
        range: "above 0, at most 10s",
        default: "1ms",
    },
    SettingInfo {
        name: "filter",
        range: "0..10 (input filter, scans)",
        default: "0",
    },
    SettingInfo {
        name: "X04",
        range: "D, or A:n1:n2 (analog)",
        default: "D",
    },
    SettingInfo {
        name: "X05",
        range: "D, or A:n1:n2 (analog)",
        default: "D",
    },
    SettingInfo {
        name: "X07",
        range: "D, I, or I:code (IR)",
        default: "D",
    },
    SettingInfo {
        name: "Y03",
        range: "D, R (servo), S, M, H (PWM)",
        default: "D",
    },
    SettingInfo {
        name: "Y04",
        range: "D, R (servo), S, M, H (PWM)",
        default: "D",
    },
];

/// What events can drive.
const INPUTS: &str = "X00-X07";

// Handles: a bit (kind × 0x100 + n), a value (0x1000 + kind × 0x100 + n),
// an output signal (0x2000 + index).
const VALUE: u32 = 0x1000;
const SIGNAL: u32 = 0x2000;

fn bit_handle(b: Bit) -> u32 {
    let (kind, n) = match b {
        Bit::X(n) => (0, n),
        Bit::Y(n) => (1, n),
        Bit::M(n) => (2, n),
        Bit::S(n) => (3, n),
        Bit::T(n) => (4, n),
        Bit::C(n) => (5, n),
    };
    kind << 8 | u32::from(n)
}

fn handle_bit(h: u32) -> Bit {
    let n = (h & 0xFF) as u8;
    match h >> 8 {
        0 => Bit::X(n),
        1 => Bit::Y(n),
        2 => Bit::M(n),
        3 => Bit::S(n),
        4 => Bit::T(n),
        _ => Bit::C(n),
    }
}

fn word_handle(w: Word) -> u32 {
    let (kind, n) = match w {
        Word::D(n) => (0, n),
        Word::T(n) => (1, n),
        Word::C(n) => (2, n),
        Word::K(_) => (3, 0),
    };
    VALUE | kind << 8 | u32::from(n)
}

fn handle_word(h: u32) -> Word {
    let n = (h & 0xFF) as u8;
    match (h >> 8) & 0xF {
        0 => Word::D(n),
        1 => Word::T(n),
        _ => Word::C(n),
    }
}

impl Machine {
    /// Applies one `--set NAME=VALUE`: `scan=<time>`, `filter=<0..10>`, or
    /// a pin setting in the terminal's words: `X04=A:401:100`, `X05=D`,
    /// `X07=I:10EF`, `Y03=R` (S, M, H, D).
    pub fn apply_setting(&mut self, name: &str, value: &str) -> Result<(), SettingError> {
        match name.to_ascii_uppercase().as_str() {
            "SCAN" => self.set_scan_period(SimTime::parse(value)?),
            "FILTER" => self
                .settings_mut()
                .apply(&format!("!{value}"))
                .map_err(SettingError::own),
            "X04" | "X05" | "X07" | "Y03" | "Y04" => self
                .settings_mut()
                .apply(&format!("{name}{value}"))
                .map_err(SettingError::own),
            _ => Err(SettingError::Unknown {
                machine: MachineId::Io86a,
                name: name.to_string(),
                takes: "scan, filter, X04, X05, X07, Y03, Y04",
            }),
        }
    }
}

/// A listing parsed, its problems as a [`PlcError`].
fn parse(text: &str) -> Result<Program, PlcError> {
    Program::parse(text).map_err(|errors| PlcError::Program(plc::problems(errors)))
}

/// PLC-IO86A as a [`Plc`]: the device in RUN and its serial terminal,
/// and a second device linked to it by SETS / RSTS once one is loaded
/// ([`plc::Command::LoadLinked`]; its devices are named `B.X00`).
/// Stepping by scan or instruction steps device A; device B follows when
/// time next runs.
#[derive(Clone, Debug)]
pub struct Io86aPlc {
    pair: LinkedPair,
    /// Whether device B is in use (else only A runs).
    linked: bool,
    terminal: Terminal,
}

/// The image's length: 16 bytes of bits, then 48 words.
const IMAGE_BYTES: usize = 16 + 2 * 48;

/// A word's place among the image's words (after its 16 bytes of bits):
/// D00-D07, T00-T31, C00-C07 (`image_into`).
fn image_word_index(word: Word) -> Option<usize> {
    match word {
        Word::D(n) => Some(usize::from(n)),
        Word::T(n) => Some(8 + usize::from(n)),
        Word::C(n) => Some(40 + usize::from(n)),
        Word::K(_) => None,
    }
}

/// The handle bit that names device B.
const DEVICE_B: u32 = 0x8000;

impl Default for Io86aPlc {
    fn default() -> Self {
        Io86aPlc::new()
    }
}

impl Io86aPlc {
    /// A device with no program, powered on and in RUN.
    pub fn new() -> Io86aPlc {
        Io86aPlc::with(Machine::new(Program::default()))
    }

    /// `machine` as a [`Plc`].
    pub fn with(machine: Machine) -> Io86aPlc {
        let terminal = Terminal::new(&machine);
        Io86aPlc {
            pair: LinkedPair::new(machine, Machine::new(Program::default())),
            linked: false,
            terminal,
        }
    }

    /// Device A.
    pub fn machine(&self) -> &Machine {
        &self.pair.a
    }

    /// The device a handle names.
    fn unit(&self, device: Device) -> &Machine {
        if device.0 & DEVICE_B != 0 {
            &self.pair.b
        } else {
            &self.pair.a
        }
    }

    fn unit_mut(&mut self, device: Device) -> &mut Machine {
        if device.0 & DEVICE_B != 0 {
            &mut self.pair.b
        } else {
            &mut self.pair.a
        }
    }

    fn input_number(&self, device: Device) -> Result<u8, PlcError> {
        match device.0 & !DEVICE_B {
            h if h < VALUE => match handle_bit(h) {
                Bit::X(n) => Ok(n),
                other => Err(DeviceError::NotAnInput {
                    device: other.to_string(),
                    drives: Drives::Terminals(INPUTS),
                }
                .into()),
            },
            h => Err(DeviceError::NotAnInput {
                device: self.name(h),
                drives: Drives::Terminals(INPUTS),
            }
            .into()),
        }
    }

    fn name(&self, h: u32) -> String {
        let prefix = if h & DEVICE_B != 0 { "B." } else { "" };
        let h = h & !DEVICE_B;
        let name = match h {
            h if h >= SIGNAL => format!("Y0{}.v", 3 + (h & 1)),
            h if h >= VALUE => match handle_word(h) {
                Word::D(n) => format!("D{n:02}"),
                Word::T(n) => format!("T{n:02}.v"),
                Word::C(n) => format!("C{n:02}.v"),
                Word::K(k) => format!("K{k}"),
            },
            h => handle_bit(h).to_string(),
        };
        format!("{prefix}{name}")
    }
}

impl Plc for Io86aPlc {
    fn id(&self) -> MachineId {
        MachineId::Io86a
    }

    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        let program = parse(text)?;
        self.pair.a.load(program);
        // The terminal edits its own copy of the program: start it anew.
        self.terminal = Terminal::new(&self.pair.a);
        Ok(())
    }

    fn listing(&self) -> String {
        self.pair.a.program().listing()
    }

    fn apply(&mut self, command: plc::Command) -> Result<(), PlcError> {
        match command {
            plc::Command::SetInput(device, value) => {
                self.check_input(device, value)?;
                let n = self.input_number(device)?;
                let m = self.unit_mut(device);
                match value {
                    InputValue::Millivolts(mv) => {
                        m.set_analog(usize::from(n.saturating_sub(4)), mv)
                    }
                    InputValue::Int(frame) if n == 7 && m.settings().ir != IrMode::Digital => {
                        m.set_ir(u32::try_from(frame).ok().filter(|&f| f != 0));
                    }
                    InputValue::Int(v) => m.set_input(n, v == 1),
                    // Refused by check_input above.
                    InputValue::Real(_) => {}
                }
                Ok(())
            }
            plc::Command::ReleaseInput(device) => {
                self.apply(plc::Command::SetInput(device, InputValue::Int(0)))
            }
            plc::Command::Setting { name, value } => {
                let (name, m) = match name.trim().strip_prefix("B.") {
                    Some(rest) => (rest, &mut self.pair.b),
                    None => (name.trim(), &mut self.pair.a),
                };
                Ok(m.apply_setting(name, value.trim())?)
            }
            plc::Command::PowerCycle => {
                self.pair.a.power_cycle();
                self.pair.b.power_cycle();
                Ok(())
            }
            plc::Command::Run(on) => {
                self.pair.a.set_running(on);
                Ok(())
            }
            plc::Command::Own(own) => {
                let Some(super::LoadLinked(text)) = own.get::<super::LoadLinked>() else {
                    return Err(PlcError::NotItsOwn {
                        machine: MachineId::Io86a,
                        command: own,
                    });
                };
                let program = parse(text)?;
                let now = self.pair.a.now();
                let b = &mut self.pair.b;
                b.set_running(false);
                b.load(program);
                // B's clock joins A's: it was idle, not running, until now.
                b.run_until(now);
                b.set_running(true);
                self.linked = !text.trim().is_empty();
                Ok(())
            }
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        // One `B.` names device B; a second is part of an unknown name
        // (never stripped again: `B.B.Y00` is not `B.Y00`).
        match strip_b(name) {
            Some(rest) if strip_b(rest).is_none() => Ok(Device(unit_device(rest)?.0 | DEVICE_B)),
            // Refused by its whole name.
            _ => unit_device(name),
        }
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        let n = self.input_number(device)?;
        let name = self.name(device.0);
        let settings = self.unit(device).settings();
        let analog =
            matches!(n, 4 | 5) && settings.analog[usize::from(n - 4)] != InputMode::Digital;
        let ir = n == 7 && settings.ir != IrMode::Digital;
        let error = match value {
            InputValue::Millivolts(_) if analog => return Ok(()),
            InputValue::Millivolts(_) => DeviceError::NeedsAnalogMode(name),
            InputValue::Int(frame) if ir => match u32::try_from(frame) {
                Ok(_) => return Ok(()),
                Err(_) => DeviceError::IrFrame(name),
            },
            InputValue::Int(_) if analog => DeviceError::NeedsVoltage(name),
            InputValue::Int(0 | 1) => return Ok(()),
            InputValue::Int(_) | InputValue::Real(_) => DeviceError::BitValue(name),
        };
        Err(error.into())
    }

    fn read(&self, device: Device) -> Value {
        let m = self.unit(device);
        let scan = m.last_scan();
        match device.0 & !DEVICE_B {
            h if h >= SIGNAL => Value::Int(m.output_signal((h & 1) as usize).value()),
            h if h >= VALUE => Value::Int(i64::from(scan.word(handle_word(h)))),
            h => match handle_bit(h) {
                Bit::Y(n) => Value::Bit(m.output_terminals() >> n & 1 != 0),
                bit => Value::Bit(scan.bit(bit)),
            },
        }
    }

    fn now(&self) -> SimTime {
        self.pair.a.now()
    }

    fn run_until(&mut self, t: SimTime) {
        if self.linked {
            self.pair.run_until(t);
        } else {
            self.pair.a.run_until(t);
        }
    }

    fn run_before(&mut self, t: SimTime) {
        if self.linked {
            self.pair
                .run_until(crate::clock::PeriodicClock::just_before(t));
            self.pair.b.run_before(t);
        }
        self.pair.a.run_before(t);
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        self.nth_scan_end(1)
    }

    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        let a = &self.pair.a;
        match (n, a.scan_position().is_some()) {
            (0, _) => None,
            (1, true) => Some(a.now()),
            (_, true) => a.nth_scan_at(n - 1),
            (_, false) => a.nth_scan_at(n),
        }
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        if device.0 & DEVICE_B != 0 || device.0 >= SIGNAL {
            return None;
        }
        if device.0 >= VALUE {
            let at = 16 + 2 * image_word_index(handle_word(device.0))?;
            return plc::image_bytes(image, at)
                .map(|b| Value::Int(i64::from(i16::from_le_bytes(b))));
        }
        let (at, n) = match handle_bit(device.0) {
            Bit::X(n) => (0, n),
            Bit::Y(n) => (1, n),
            Bit::M(n) => (2 + usize::from(n / 8), n % 8),
            Bit::S(n) => (10, n),
            Bit::T(n) => (11 + usize::from(n / 8), n % 8),
            Bit::C(n) => (15, n),
        };
        image.get(at).map(|b| Value::Bit(b >> n & 1 != 0))
    }

    fn step_scan(&mut self) {
        self.pair.a.step_scan();
    }

    fn scans(&self) -> u64 {
        self.pair.a.scans()
    }

    fn step_instruction(&mut self) -> Option<usize> {
        self.pair.a.step_instruction()
    }

    // Device A's steps, numbered as its listing numbers them (an
    // instruction's first line).
    plc::forward_tracing!(pair.a.tracer);

    fn running(&self) -> bool {
        self.pair.a.running()
    }

    /// Both devices' pins (device B's stays at rest until one is linked).
    fn front_into(&self, front: &mut plc::Front) {
        front.fill(|fronts: &mut super::Fronts| {
            *fronts = [
                super::Io86aFront::of(&self.pair.a),
                super::Io86aFront::of(&self.pair.b),
            ];
        });
    }

    /// X, Y, M (8 bytes, bit n = device n), S, then T and C contacts (4
    /// bytes, 1 byte), then D00-D07, T00-T31 and C00-C07 values (2 bytes
    /// each, little-endian), as the last scan left them.
    fn image_into(&self, image: &mut Vec<u8>) {
        let m = &self.pair.a;
        let scan = m.last_scan();
        // Filled field by field in one buffer, not device by device:
        // recording takes an image every scan (issue #16).
        let mut buf = [0u8; IMAGE_BYTES];
        let timers = (0..32).fold(0u32, |acc, n| acc | u32::from(scan.timers[n].on) << n);
        let counters = (0..8).fold(0u8, |acc, n| acc | u8::from(scan.counters[n].on) << n);
        buf[0] = scan.x;
        buf[1] = m.output_terminals();
        buf[2..10].copy_from_slice(&scan.m.to_le_bytes());
        buf[10] = scan.s;
        buf[11..15].copy_from_slice(&timers.to_le_bytes());
        buf[15] = counters;
        let mut put = |i: usize, w: i16| {
            let [lo, hi] = w.to_le_bytes();
            buf[16 + 2 * i] = lo;
            buf[17 + 2 * i] = hi;
        };
        for (i, &d) in scan.d.iter().enumerate() {
            put(i, d);
        }
        for (n, t) in (0u8..).zip(&scan.timers) {
            put(8 + usize::from(n), t.current(n));
        }
        for (i, c) in scan.counters.iter().enumerate() {
            put(40 + i, c.count);
        }
        image.clear();
        image.extend_from_slice(&buf);
    }

    fn settings(&self) -> &'static [SettingInfo] {
        SETTINGS
    }

    /// Plants wire to X00-X07 and Y00-Y05; X04/X05 take an analog level
    /// as 0-5 V (once set to analog mode, `X04=A:n1:n2`).
    fn terminals(&self) -> crate::plc::Terminals {
        use crate::plc::{AnalogScale, Terminals};
        Terminals {
            inputs: Terminals::numbered(8, |i| format!("X{i:02}")),
            outputs: Terminals::numbered(6, |i| format!("Y{i:02}")),
            analog: ["X04", "X05"]
                .map(|n| (n.to_string(), AnalogScale::Millivolts(5000)))
                .to_vec(),
            by_name: false,
        }
    }

    /// Whole scans of every instruction (END included).
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        plc::whole_scans(
            steps,
            self.pair.a.steps_per_scan() as u64,
            self.pair.a.scan_period(),
        )
    }

    fn serial_open(&mut self) -> Result<String, PlcError> {
        Ok(self.terminal.prompt(&self.pair.a))
    }

    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        Ok(self.terminal.type_line(&mut self.pair.a, line))
    }
}

/// `name` without its `B.` (or `b.`) prefix, if it has one.
fn strip_b(name: &str) -> Option<&str> {
    name.strip_prefix("B.").or_else(|| name.strip_prefix("b."))
}

/// A device of one unit (no `B.` prefix): `X00`, `D05`, `T01.v`, `Y03.v`.
fn unit_device(name: &str) -> Result<Device, PlcError> {
    let upper = name.to_ascii_uppercase();
    match upper.as_str() {
        "Y03.V" => return Ok(Device(SIGNAL)),
        "Y04.V" => return Ok(Device(SIGNAL | 1)),
        _ => {}
    }
    if let Some(base) = upper.strip_suffix(".V") {
        return match parse_word(base).map_err(DeviceError::own)? {
            Word::K(_) => Err(DeviceError::Constant(name.to_string()).into()),
            word => Ok(Device(word_handle(word))),
        };
    }
    if upper.starts_with('D') {
        let word = parse_word(&upper).map_err(DeviceError::own)?;
        return Ok(Device(word_handle(word)));
    }
    let bit = parse_bit(name).map_err(DeviceError::own)?;
    Ok(Device(bit_handle(bit)))
}
