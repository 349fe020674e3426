//! The soft PLC behind the [`Plc`] interface: `--set scan=`, devices by
//! variable name or `%` address, block outputs as `TON0.Q`, `TON0.ET`,
//! `CTU0.v`, and events that set a value of any type.

use std::collections::HashMap;
use std::fmt;
use std::sync::{Arc, Mutex, PoisonError};

use super::machine::Machine;
use super::program::Program;
use crate::events::InputValue;
use crate::iec::data::{Data, DataType};
use crate::iec::literal::in_range;
use crate::iec::pins::outputs;
use crate::plc::SettingInfo;
use crate::plc::{self, Device, DeviceError, Plc, PlcError, SettingError, Value};
use crate::time::SimTime;
use crate::MachineId;

const SETTINGS: &[SettingInfo] = &[SettingInfo {
    name: "scan",
    range: "above 0, at most 10s",
    default: "10ms",
}];

// Handles: a value slot below BLOCK; a block output at BLOCK + block ×
// PINS + pin.
const BLOCK: u32 = 0x4000_0000;
const PINS: u32 = 4;
// Bytes of one value in an image.
const WIDTH: usize = 8;

/// A device name or value the soft PLC does not take.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SoftDeviceError {
    /// No declared name, used address or block instance of that name.
    Unknown(String),
    /// A block output that its kind does not have.
    NoOutput { block: String, pin: String },
    /// A block's output given an event.
    BlockOutput(String),
    /// A value the device's type does not hold.
    Value {
        device: String,
        data_type: DataType,
        value: String,
    },
}

impl fmt::Display for SoftDeviceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SoftDeviceError::Unknown(d) => write!(
                f,
                "unknown device {}: name a variable, an address the program uses (%IX0.0) or a block's output (TON0.Q)",
                crate::error::shown(d)
            ),
            SoftDeviceError::NoOutput { block, pin } => {
                write!(f, "{block} has no output {pin}")
            }
            SoftDeviceError::BlockOutput(d) => {
                write!(f, "{d} is a block's output: events set variables and inputs")
            }
            SoftDeviceError::Value {
                device,
                data_type,
                value,
            } => write!(
                f,
                "{device} is {}: {value} is not one ({})",
                data_type.name(),
                takes(*data_type)
            ),
        }
    }
}

impl std::error::Error for SoftDeviceError {}

/// What an event for a variable of type `t` is written as.
fn takes(t: DataType) -> &'static str {
    match t {
        DataType::Bool => "0 or 1",
        DataType::Real | DataType::Lreal => "a number such as 2.5",
        DataType::Time => "milliseconds",
        DataType::String => "nothing: the program writes its STRINGs",
        _ => "an integer in its range",
    }
}

/// The value an event gives a variable of type `t`, if it holds it.
fn data_for(t: DataType, value: InputValue) -> Option<Data> {
    match (t, value) {
        (DataType::Bool, InputValue::Int(n @ (0 | 1))) => Some(Data::Bool(n == 1)),
        (DataType::Real, InputValue::Int(n)) => Some(Data::Real(n as f32)),
        (DataType::Real, InputValue::Real(x)) => {
            let r = x.get() as f32;
            r.is_finite().then_some(Data::Real(r))
        }
        (DataType::Lreal, InputValue::Int(n)) => Some(Data::Lreal(n as f64)),
        (DataType::Lreal, InputValue::Real(x)) => {
            let r = x.get();
            r.is_finite().then_some(Data::Lreal(r))
        }
        (DataType::Time, InputValue::Int(ms)) => ms.checked_mul(1_000_000).map(Data::Time),
        (t, InputValue::Int(n)) if t.bits().is_some() => in_range(t, i128::from(n)),
        _ => None,
    }
}

/// The soft PLC as a [`Plc`].
#[derive(Clone, Debug)]
pub struct SoftPlc {
    machine: Machine,
    /// Every STRING value an image has held, numbered: an image keeps a
    /// text's number in its eight bytes (a recording keeps a text that
    /// stays the same once, however many scans it spans).
    texts: TextBook,
}

/// The texts of [`SoftPlc::texts`], behind a lock as `image_into` reads
/// the machine through `&self`.
#[derive(Default)]
struct TextBook(Mutex<Texts>);

impl TextBook {
    fn lock(&self) -> std::sync::MutexGuard<'_, Texts> {
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Clone for TextBook {
    fn clone(&self) -> Self {
        TextBook(Mutex::new(self.lock().clone()))
    }
}

impl fmt::Debug for TextBook {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "TextBook({} texts)", self.lock().list.len())
    }
}

/// Texts numbered in the order first seen.
#[derive(Clone, Default)]
struct Texts {
    list: Vec<Arc<String>>,
    numbers: HashMap<Arc<String>, u32>,
}

impl Texts {
    fn number(&mut self, text: &Arc<String>) -> u32 {
        if let Some(&n) = self.numbers.get(text) {
            return n;
        }
        let n = u32::try_from(self.list.len()).unwrap_or(u32::MAX);
        self.list.push(Arc::clone(text));
        self.numbers.insert(Arc::clone(text), n);
        n
    }
}

impl Default for SoftPlc {
    fn default() -> Self {
        SoftPlc::new()
    }
}

impl SoftPlc {
    /// A soft PLC with no program, its task every 10 ms, at RUN.
    pub fn new() -> SoftPlc {
        let empty = Program::load("").unwrap_or_else(|_| unreachable!("an empty program loads"));
        SoftPlc {
            machine: Machine::new(empty),
            texts: TextBook::default(),
        }
    }

    /// The machine.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    fn slot(&self, device: Device) -> Result<usize, PlcError> {
        if device.0 >= BLOCK {
            let block = ((device.0 - BLOCK) / PINS) as usize;
            let name = self
                .machine
                .program()
                .block_names
                .get(block)
                .map_or(String::new(), |(n, _)| n.clone());
            return Err(DeviceError::own(SoftDeviceError::BlockOutput(name)).into());
        }
        Ok(device.0 as usize)
    }

    fn name(&self, slot: usize) -> String {
        let program = self.machine.program();
        program
            .devices()
            .into_iter()
            .find(|(_, s)| *s == slot)
            .map_or_else(|| format!("slot {slot}"), |(n, _)| n)
    }

    /// What `value` gives the variable at `slot`, or why not (naming its
    /// type).
    fn data(&self, slot: usize, value: InputValue) -> Result<Data, PlcError> {
        let t = self
            .machine
            .program()
            .slot_type(slot)
            .unwrap_or(DataType::Bool);
        data_for(t, value).ok_or_else(|| {
            DeviceError::own(SoftDeviceError::Value {
                device: self.name(slot),
                data_type: t,
                value: value.to_string(),
            })
            .into()
        })
    }

    /// A block's output by instance and pin name (`TON0`, `ET`); `v` is
    /// its current value (ET, CV), no pin its first output.
    fn block_device(&self, block: &str, pin: Option<&str>) -> Option<Result<Device, PlcError>> {
        let (index, kind) = self.machine.program().block_of(block)?;
        let pins = outputs(kind);
        let at = match pin {
            None => Some(0),
            Some(p) if p.eq_ignore_ascii_case("v") => {
                pins.iter().position(|(n, _)| *n == "ET" || *n == "CV")
            }
            Some(p) => pins.iter().position(|(n, _)| n.eq_ignore_ascii_case(p)),
        };
        Some(match at {
            Some(pin) => Ok(Device(BLOCK + index as u32 * PINS + pin as u32)),
            None => Err(DeviceError::own(SoftDeviceError::NoOutput {
                block: block.to_string(),
                pin: pin.unwrap_or_default().to_string(),
            })
            .into()),
        })
    }
}

/// A value's eight bytes in an image (a text's number in `texts`).
fn encode(d: &Data, texts: &mut Texts) -> [u8; WIDTH] {
    let bits = match *d {
        Data::Bool(b) => i64::from(b),
        Data::Int(_, v) | Data::Time(v) => v,
        Data::Real(r) => i64::from(r.to_bits()),
        Data::Lreal(r) => r.to_bits() as i64,
        Data::Text(ref t) => i64::from(texts.number(t)),
    };
    bits.to_le_bytes()
}

/// A value of type `t` from its eight bytes.
fn decode(t: DataType, bytes: [u8; WIDTH], texts: &Texts) -> Data {
    let bits = i64::from_le_bytes(bytes);
    match t {
        DataType::Bool => Data::Bool(bits != 0),
        DataType::Real => Data::Real(f32::from_bits(bits as u32)),
        DataType::Lreal => Data::Lreal(f64::from_bits(bits as u64)),
        DataType::Time => Data::Time(bits),
        DataType::String => usize::try_from(bits)
            .ok()
            .and_then(|n| texts.list.get(n))
            .map_or_else(|| t.zero(), |text| Data::Text(Arc::clone(text))),
        t => Data::integer(t, i128::from(bits)),
    }
}

impl Plc for SoftPlc {
    fn id(&self) -> MachineId {
        MachineId::SoftPlc
    }

    /// IEC 61131-3 Instruction List with its `VAR … END_VAR` header.
    fn load_text(&mut self, text: &str) -> Result<(), PlcError> {
        let program =
            Program::load(text).map_err(|errors| PlcError::Program(plc::problems(errors)))?;
        self.machine.load(program);
        Ok(())
    }

    fn listing(&self) -> String {
        self.machine.program().listing()
    }

    fn apply(&mut self, command: plc::Command) -> Result<(), PlcError> {
        match command {
            plc::Command::SetInput(device, value) => {
                let slot = self.slot(device)?;
                let data = self.data(slot, value)?;
                if !self.machine.program_mut().set_terminal(slot, data.clone()) {
                    self.machine.write(slot, data);
                }
                Ok(())
            }
            plc::Command::ReleaseInput(device) => {
                let slot = self.slot(device)?;
                let program = self.machine.program_mut();
                if let Some(t) = program.slot_type(slot) {
                    program.set_terminal(slot, t.zero());
                }
                Ok(())
            }
            plc::Command::Setting { name, value } => {
                match name.trim().to_ascii_lowercase().as_str() {
                    "scan" => Ok(self.machine.set_scan_period(
                        SimTime::parse(value.trim()).map_err(SettingError::from)?,
                    )?),
                    _ => Err(SettingError::Unknown {
                        machine: MachineId::SoftPlc,
                        name,
                        takes: "scan",
                    }
                    .into()),
                }
            }
            plc::Command::PowerCycle => {
                self.machine.power_cycle();
                Ok(())
            }
            plc::Command::Run(on) => {
                self.machine.set_running(on);
                Ok(())
            }
            plc::Command::Own(command) => Err(PlcError::NotItsOwn {
                machine: MachineId::SoftPlc,
                command,
            }),
        }
    }

    fn device(&self, name: &str) -> Result<Device, PlcError> {
        let name = name.trim();
        let program = self.machine.program();
        if let Some(slot) = program.slot_of(name) {
            return Ok(Device(slot as u32));
        }
        if let Some(found) = self.block_device(name, None) {
            return found;
        }
        if let Some((base, pin)) = name.rsplit_once('.') {
            if let Some(found) = self.block_device(base, Some(pin)) {
                return found;
            }
            if pin.eq_ignore_ascii_case("v") {
                if let Some(slot) = program.slot_of(base) {
                    return Ok(Device(slot as u32));
                }
            }
        }
        Err(DeviceError::own(SoftDeviceError::Unknown(name.to_string())).into())
    }

    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError> {
        self.data(self.slot(device)?, value).map(|_| ())
    }

    fn read(&self, device: Device) -> Value {
        let program = self.machine.program();
        let data = if device.0 >= BLOCK {
            let at = device.0 - BLOCK;
            program.block_output((at / PINS) as usize, (at % PINS) as usize)
        } else {
            self.machine.last_scan().get(device.0 as usize).cloned()
        };
        data.map_or(Value::Bit(false), |d| d.to_value())
    }

    fn read_image(&self, image: &[u8], device: Device) -> Option<Value> {
        let program = self.machine.program();
        let (at, t) = if device.0 >= BLOCK {
            let at = (device.0 - BLOCK) as usize;
            let (block, pin) = (at / PINS as usize, at % PINS as usize);
            let kind = &program.block_names.get(block)?.1;
            (program.slots() + at, outputs(kind).get(pin)?.1)
        } else {
            let slot = device.0 as usize;
            (slot, program.slot_type(slot)?)
        };
        let bytes = plc::image_bytes::<WIDTH>(image, at * WIDTH)?;
        let texts = self.texts.lock();
        Some(decode(t, bytes, &texts).to_value())
    }

    fn next_scan_end(&self) -> Option<SimTime> {
        self.machine.next_scan_end()
    }

    plc::forward_time!(machine);

    plc::forward_scans!(machine);

    // Step `n` is the program's `n`-th IL instruction (from 0): the bit
    // is its operand's (on when TRUE or not zero), the result the
    // current result's.
    plc::forward_tracing!(machine.tracer);

    /// Each value slot as the last scan left it (8 bytes, little-endian:
    /// the integer, the REAL's bits, the nanoseconds), then each block's
    /// outputs (four 8-byte places a block).
    fn image_into(&self, image: &mut Vec<u8>) {
        image.clear();
        let mut texts = self.texts.lock();
        for d in self.machine.last_scan() {
            image.extend_from_slice(&encode(d, &mut texts));
        }
        let program = self.machine.program();
        for block in 0..program.block_count() {
            for pin in 0..PINS as usize {
                let d = program
                    .block_output(block, pin)
                    .unwrap_or(Data::Bool(false));
                image.extend_from_slice(&encode(&d, &mut texts));
            }
        }
    }

    fn running(&self) -> bool {
        self.machine.running()
    }

    fn settings(&self) -> &'static [SettingInfo] {
        SETTINGS
    }

    /// Plants wire to the board's `%IX0.0-%IX0.7` and `%QX0.0-%QX0.7`,
    /// and an analog level to `%IW0-%IW7` as 0..1000 (tenths of a percent,
    /// inside the board's 10-bit slider).
    fn terminals(&self) -> crate::plc::Terminals {
        use crate::plc::{AnalogScale, Terminals};
        Terminals {
            inputs: Terminals::numbered(8, |i| format!("%IX0.{i}")),
            outputs: Terminals::numbered(8, |i| format!("%QX0.{i}")),
            analog: Terminals::numbered(8, |i| format!("%IW{i}"))
                .into_iter()
                .map(|n| (n, AnalogScale::Word(1000)))
                .collect(),
            by_name: false,
        }
    }

    /// The serial port's terminal: nothing is shown on opening it.
    fn serial_open(&mut self) -> Result<String, PlcError> {
        Ok(String::new())
    }

    /// Types `line`'s characters at the serial port (an empty line: the
    /// Enter key, a CR); the program receives them byte by byte as it
    /// runs, and what it sends comes through [`Plc::serial_sent`].
    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        self.machine
            .uart_mut()
            .type_line(line)
            .map_err(PlcError::own)?;
        Ok(String::new())
    }

    /// Bytes as characters U+0000–U+00FF (Latin-1), as a terminal of
    /// LDmicro's time shows them.
    fn serial_sent(&self, seen: u64, out: &mut String) -> u64 {
        let uart = self.machine.uart();
        out.extend(uart.sent_after(seen).map(char::from));
        uart.sent_total()
    }

    /// Whole scans of every instruction (a program's jumps are not
    /// counted: the figure assumes each scan runs every line once).
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)> {
        plc::whole_scans(
            steps,
            self.machine.program().len() as u64,
            self.machine.scan_period(),
        )
    }
}
