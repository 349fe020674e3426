//! One interface to the five machines (docs/architecture.md).
//!
//! The command line, the page and the tests drive every machine through
//! [`Plc`]: load a program, apply [`Command`]s, advance simulated time (by
//! a span, a scan, an instruction or a clock edge), resolve device names
//! once to [`Device`] handles and read them cheaply. Each machine's folder
//! holds its implementation (`minasec/plc.rs`, …);
//! `crate::machines::new_plc` makes one for a [`MachineId`]. This module
//! names no machine: what only one machine has travels as [`Own`] values.
//! Errors are typed ([`PlcError`]); wall-clock time never enters: the
//! caller says how far to go.

pub mod error;
pub mod example;
pub mod front;
pub mod own;
pub mod terminals;
pub mod trace;
pub mod value;

pub use error::{problems, DeviceError, Drives, PlcError, ProgramProblem, SettingError};
pub use example::Example;
pub use front::Front;
pub use own::Own;
pub use terminals::{AnalogScale, Terminals};
pub use trace::{ScanTrace, TraceHistory, Tracer};
pub use value::Value;

use crate::events::InputValue;
use crate::time::SimTime;
use crate::time::MAX_SIM_TIME;
use crate::MachineId;

/// A device resolved once by [`Plc::device`]; reading it is a match and a
/// shift, no name look-up. Only meaningful to the machine that made it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Device(pub(crate) u32);

/// A command into a machine: everything that changes it other than time.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// Drives an input device (resolved by [`Plc::device`]) to a value:
    /// `0`/`1` for bits, a word, or millivolts for an analog input.
    SetInput(Device, InputValue),
    /// A setting as `--set NAME=VALUE` writes it (`scan=10ms`, `T0=1.1s`).
    Setting {
        /// The setting's name.
        name: String,
        /// Its value, in the setting's own words.
        value: String,
    },
    /// Stops driving an input: the AVR PLC's bit is left to the program;
    /// a terminal input (the other machines) goes off.
    ReleaseInput(Device),
    /// Power off, then on: volatile state cleared; the program, the
    /// settings and the inputs as they are stay. Simulated time goes on.
    PowerCycle,
    /// Runs (`true`) or stops the program: MINASEC-U's RUN / HALT switch,
    /// IO86A's `R` / `S`, the Arduino sketch's `e` / `d`. The AVR PLC has
    /// no such switch.
    Run(bool),
    /// A command only one machine takes, as that machine's own type:
    /// MINASEC-U's front panel (`minasec::Command`: switches, buttons,
    /// knobs), IO86A's second device (`io86a::LoadLinked`). Another
    /// machine refuses it with [`PlcError::NotThisMachine`].
    Own(Own),
}

/// A warning about the loaded program: what it does is legal but
/// probably not what its author meant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Warning {
    /// Arduino: neither END nor JUMP, so the PLC runs on through erased
    /// EEPROM and spins at its last step (docs/arduino-plc.md).
    RunsIntoErasedEeprom,
    /// AVR: a TOF's output is on for its set time after power-up, as the
    /// seed warns (docs/avr-plc.md).
    TofOnAtPowerUp,
}

/// A setting a machine takes, for the page's controls and for messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SettingInfo {
    /// Its name for `--set` and in project files.
    pub name: &'static str,
    /// The values it takes, in words (`0.1s..1.1s`).
    pub range: &'static str,
    /// Its value on a new machine.
    pub default: &'static str,
}

/// The longest span one [`Plc::tick`] simulates: a frame that comes late
/// (a hidden tab, a breakpoint in the debugger) resumes instead of racing
/// through the gap.
pub const MAX_TICK: SimTime = SimTime::from_secs(10);

/// One simulated PLC.
pub trait Plc {
    /// Which machine this is.
    fn id(&self) -> MachineId;

    /// Parses `text` in the machine's own program format (mnemonic
    /// listing, AVR `.db` source) and loads it. On error nothing changes.
    fn load_text(&mut self, text: &str) -> Result<(), PlcError>;

    /// The loaded program as the machine stores it (what `hashigo asm`
    /// prints: MINASEC-U's programming sheet, IO86A's `L` listing,
    /// the Arduino EEPROM dump, AVR `.db` records).
    fn listing(&self) -> String;

    /// Applies a command. On error nothing changes.
    fn apply(&mut self, command: Command) -> Result<(), PlcError>;

    /// Resolves a device name (`X00`, `C0.v`, `R4.2`, a named AVR bit).
    fn device(&self, name: &str) -> Result<Device, PlcError>;

    /// Checks that `value` can drive the input `device` without driving it.
    fn check_input(&self, device: Device, value: InputValue) -> Result<(), PlcError>;

    /// A device's value after the last completed scan (for the Arduino
    /// sketch, which has no scan, now), typed as the machine holds it.
    fn read(&self, device: Device) -> Value;

    /// The simulated time.
    fn now(&self) -> SimTime;

    /// Scans completed (Arduino: program passes back to step 0).
    fn scans(&self) -> u64;

    /// Runs every clock edge, step or scan due at or before `t`; the time
    /// becomes `t`.
    fn run_until(&mut self, t: SimTime);

    /// Runs everything due strictly before `t` (so that an event at `t`
    /// comes first); the time becomes `t`.
    fn run_before(&mut self, t: SimTime);

    /// Advances by `dt` (at most [`MAX_TICK`], never past the clock's
    /// limit) in whole scans or steps.
    fn tick(&mut self, dt: SimTime) {
        self.run_until(tick_end(self.now(), dt));
    }

    /// Runs the rest of the scan under way, or one whole scan.
    fn step_scan(&mut self);

    /// The earliest time at which the scan under way (or the next one)
    /// can complete, if nothing is applied meanwhile: `run_until` of it
    /// completes at most one scan. `None` while no scan runs (HALT,
    /// stopped). A machine that cannot tell in advance (the Arduino
    /// sketch, whose scan ends wherever its program jumps) gives its next
    /// step's time. Recording uses it to stop at every scan's end.
    fn next_scan_end(&self) -> Option<SimTime>;

    /// When the `n`-th scan from now ends (`n` = 1: [`Plc::next_scan_end`]),
    /// if nothing is applied meanwhile; `None` where the machine cannot
    /// tell. Recording runs to just before a keyframe's scan in one go.
    fn nth_scan_end(&self, n: u64) -> Option<SimTime> {
        if n == 1 {
            self.next_scan_end()
        } else {
            None
        }
    }

    /// Runs one instruction (the next scan's first when none is under
    /// way); returns its step number, or `None` when the machine is not
    /// running a program.
    fn step_instruction(&mut self) -> Option<usize>;

    /// Runs one clock edge where the machine has a visible clock
    /// (MINASEC-U); false where it has none or is not clocked.
    fn step_clock(&mut self) -> bool {
        false
    }

    /// Starts or stops per-step tracing ([`ScanTrace`]); a machine that
    /// cannot trace ignores it.
    fn set_tracing(&mut self, _on: bool) {}

    /// While tracing: what each step of the last completed scan read and
    /// left, by step number (the listing's numbering).
    fn trace(&self) -> Option<&ScanTrace> {
        None
    }

    /// While tracing: what each step did in every scan since the last
    /// call ([`TraceHistory`]), then forgotten.
    fn take_trace_history(&mut self) -> TraceHistory {
        TraceHistory::default()
    }

    /// Copies the device memory as the last scan left it into `image`
    /// (replacing its contents; the caller keeps the buffer between
    /// frames), in the machine's own layout (docs/architecture.md).
    fn image_into(&self, image: &mut Vec<u8>);

    /// A device's value in an image [`Plc::image_into`] made (on this
    /// machine or a copy of it); `None` for a device the image does not
    /// hold (IO86A's device B, a MINASEC-U button).
    fn read_image(&self, image: &[u8], device: Device) -> Option<Value>;

    /// Whether the program runs: RUN, enabled (the AVR PLC always runs).
    fn running(&self) -> bool;

    /// Copies what the machine's front shows beyond its devices into
    /// `front` (replacing it; the caller keeps it between frames).
    fn front_into(&self, front: &mut Front) {
        front.clear();
    }

    /// Warnings about the loaded program (none, unless the machine has
    /// some to give).
    fn warnings(&self) -> Vec<Warning> {
        Vec::new()
    }

    /// The settings this machine takes.
    fn settings(&self) -> &'static [SettingInfo];

    /// The terminals a plant wires to by default (none, unless the
    /// machine says).
    fn terminals(&self) -> Terminals {
        Terminals::default()
    }

    /// For `hashigo bench`: the time by which at least `steps` steps have
    /// run from power-on when running flat out, and how many that is
    /// (scan machines run whole scans); `None` past the clock's range.
    fn time_for_steps(&self, steps: u64) -> Option<(SimTime, u64)>;

    /// Opens the device's serial terminal: what it shows first (IO86A's
    /// prompt; the Arduino sketch shows nothing).
    fn serial_open(&mut self) -> Result<String, PlcError> {
        Err(PlcError::NotThisMachine {
            machine: self.id(),
            lacks: "serial terminal: console is for io86a and arduino-plc",
        })
    }

    /// What the device sent at its serial port on its own, while running
    /// (the soft PLC's UART; IO86A and the Arduino answer typed lines
    /// instead): appends to `out` the bytes sent after the first `seen`
    /// since power-on, as far as the device keeps them, and returns how
    /// many it has sent in all. A total below `seen` means the device's
    /// port started over (time travel to before them).
    fn serial_sent(&self, seen: u64, out: &mut String) -> u64 {
        let _ = (seen, out);
        0
    }

    /// Types one line at the device's serial port and returns what it
    /// sends back (`hashigo console`).
    fn serial(&mut self, line: &str) -> Result<String, PlcError> {
        let _ = line;
        Err(PlcError::NotThisMachine {
            machine: self.id(),
            lacks: "serial terminal: console is for io86a and arduino-plc",
        })
    }
}

/// The time methods every [`Plc`] implementation forwards unchanged to
/// the machine in its field `$field` (`now`, `run_until`, `run_before`,
/// `step_scan`).
macro_rules! forward_time {
    ($field:ident) => {
        fn now(&self) -> $crate::time::SimTime {
            self.$field.now()
        }

        fn run_until(&mut self, t: $crate::time::SimTime) {
            self.$field.run_until(t);
        }

        fn run_before(&mut self, t: $crate::time::SimTime) {
            self.$field.run_before(t);
        }

        fn step_scan(&mut self) {
            self.$field.step_scan();
        }
    };
}
pub(crate) use forward_time;

/// The scan methods a [`Plc`] implementation forwards unchanged to the
/// machine in its field `$field` (`nth_scan_end`, `scans`,
/// `step_instruction`): the AVR PLC and the soft PLC.
macro_rules! forward_scans {
    ($field:ident) => {
        fn nth_scan_end(&self, n: u64) -> Option<$crate::time::SimTime> {
            self.$field.nth_scan_end(n)
        }

        fn scans(&self) -> u64 {
            self.$field.scans()
        }

        fn step_instruction(&mut self) -> Option<usize> {
            self.$field.step_instruction()
        }
    };
}
pub(crate) use forward_scans;

/// The tracing methods every [`Plc`] implementation forwards to the
/// [`Tracer`] at `$($path).+` (`machine.tracer`, `pair.a.tracer`); each
/// machine says next to the call how its steps are numbered.
macro_rules! forward_tracing {
    ($($path:ident).+) => {
        fn set_tracing(&mut self, on: bool) {
            self.$($path).+.set(on);
        }

        fn trace(&self) -> Option<&$crate::plc::ScanTrace> {
            self.$($path).+.last()
        }

        fn take_trace_history(&mut self) -> $crate::plc::TraceHistory {
            self.$($path).+.take_history()
        }
    };
}
pub(crate) use forward_tracing;

/// Where a [`Plc::tick`] of `dt` from `now` ends: at most [`MAX_TICK`]
/// on, never past the clock's limit.
pub fn tick_end(now: SimTime, dt: SimTime) -> SimTime {
    now.saturating_add(dt.min(MAX_TICK)).min(MAX_SIM_TIME)
}

/// Reads `N` little-endian bytes of `image` at `at`.
pub(crate) fn image_bytes<const N: usize>(image: &[u8], at: usize) -> Option<[u8; N]> {
    image.get(at..at + N)?.try_into().ok()
}

/// Steps in whole scans: the time `scans` periods from power-on for at
/// least `steps` steps of `per_scan` each.
pub(crate) fn whole_scans(steps: u64, per_scan: u64, period: SimTime) -> Option<(SimTime, u64)> {
    if per_scan == 0 {
        return None;
    }
    let scans = steps.div_ceil(per_scan);
    let t = scans.checked_mul(period.as_nanos())?;
    Some((SimTime::from_nanos(t), scans.checked_mul(per_scan)?))
}
