//! The one object-safe trait a machine implements to be a ladder target:
//! what it can draw, its device rules, compile and decompile, how its
//! listing counts steps and how it runs. Each machine folder implements
//! it in its own `target.rs`; the registry (`machines.rs`) hands a
//! machine's out as a machine id's `target()`. This file names no machine.

use super::compile::{Mapped, Options};
use super::decompile::TextError;
use super::element::CoilKind;
use super::grid::{Ladder, LadderError};
use super::net::RungLogic;
use super::target::{Capabilities, ElementError, LackReason, Role};
use super::variables::Variable;
use crate::MachineId;

/// A machine's devices by kind, in the order a PLCopen import proposes
/// them for the names a project leaves unlocated.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DevicePools {
    /// Inputs.
    pub inputs: Vec<String>,
    /// Outputs.
    pub outputs: Vec<String>,
    /// Internal relays.
    pub relays: Vec<String>,
    /// Timers.
    pub timers: Vec<String>,
    /// Counters.
    pub counters: Vec<String>,
}

impl DevicePools {
    /// `prefix` and each of `ns` in `width` digits: `X00` … `X07`.
    pub fn range(prefix: &str, width: usize, ns: std::ops::Range<u32>) -> Vec<String> {
        ns.map(|n| format!("{prefix}{n:0width$}")).collect()
    }
}

/// Why a located bit (`%IX0.3`) has no device on a machine, before its
/// device rules are asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LocatedError {
    /// The machine has no such area.
    NotThere,
    /// The machine has no internal relays (`%MX`).
    NoRelays,
    /// Past the registers the machine gives the area.
    Past {
        /// inputs, outputs or relays.
        what: &'static str,
        /// The first register.
        first: u8,
        /// The last register.
        last: u8,
    },
}

/// One machine as a ladder target: everything the ladder, the editor and
/// the file formats need to know of it. Object-safe: the registry hands
/// each machine's out as a `&'static dyn LadderTarget`.
pub trait LadderTarget: Sync {
    /// The machine.
    fn id(&self) -> MachineId;
    /// Its product name, as its maker writes it (the page's labels).
    fn product_name(&self) -> &'static str;
    /// Its byte in a share link (never reused: links already given out
    /// name the machine by it).
    fn share_code(&self) -> u8;
    /// What it can draw.
    fn capabilities(&self) -> Capabilities;
    /// `device` used as `role` in the machine's canonical spelling, or why
    /// the machine has no such device.
    fn canonical(&self, device: &str, role: Role) -> Result<String, ElementError>;
    /// The machine's own rule for a coil of `kind` on a (canonical)
    /// `device`, beyond the device being writable.
    fn check_coil(&self, _kind: CoilKind, _device: &str) -> Result<(), ElementError> {
        Ok(())
    }
    /// Why it has no in-line boxes (when it has none).
    fn lacks_inline_boxes(&self) -> LackReason {
        LackReason::Plain
    }
    /// Why it has no timer or counter coils (when it has none).
    fn lacks_timer_counter_coils(&self) -> LackReason {
        LackReason::UseInlineTimer
    }
    /// The largest timer or counter coil set value.
    fn max_preset(&self) -> u16 {
        u16::MAX
    }
    /// What follows "unknown device X: " in an error.
    fn devices_help(&self) -> &'static str {
        self.capabilities().devices
    }
    /// Whether its compiled text depends on the scan period
    /// ([`Options::avr_scan_ms`]): a timer preset counted in scans.
    fn scan_in_program(&self) -> bool {
        false
    }
    /// The device a located bit stands for (`area` `I`, `Q` or `M`; bit
    /// `n` = byte × 8 + bit), before its device rules check it.
    fn located_bit(&self, _area: char, _n: u32) -> Result<String, LocatedError> {
        Err(LocatedError::NotThere)
    }
    /// The device a located word stands for (`area` then the rest:
    /// `I`, `W0`), if the machine reads one.
    fn located_word(&self, _area: char, _rest: &str) -> Option<String> {
        None
    }
    /// Its devices by kind, for an import's proposals (none: its
    /// variables keep their names).
    fn pools(&self) -> DevicePools {
        DevicePools::default()
    }
    /// The bits an import may take to hold a network's power, highest
    /// first (as `Vec::pop` gives them): its relays.
    fn spare_bits(&self) -> Vec<String> {
        self.pools().relays
    }
    /// Its always-on relay, if it has one (IO86A's M57): what a PLCopen
    /// import wires to the left rail where a gate or box needs power.
    fn always_on(&self) -> Option<&'static str> {
        None
    }
    /// Whether the page can stop and start it (a RUN switch or command).
    fn stoppable(&self) -> bool {
        true
    }
    /// Whether it steps clock by clock (MINASEC-U's logic ICs): the page
    /// offers a clock step and the view inside its CPU.
    fn steps_clocks(&self) -> bool {
        false
    }
}

/// The half of a machine's ladder target that turns a ladder into its
/// program and back: kept apart from [`LadderTarget`] because a trait
/// object links every method of every machine, and the files worker and
/// the page's capability questions need none of the compilers (issue
/// #48: the worker grew 78 KB of gzip when they were one trait).
pub trait MachineCompiler: Sync {
    /// Compiles checked rung logic (with the ladder's declared
    /// `variables`) to the machine's own text, with where each rung and
    /// leaf went.
    fn compile(
        &self,
        rungs: &[RungLogic],
        variables: &[Variable],
        options: Options,
    ) -> Result<Mapped, Vec<LadderError>>;
    /// A program in the machine's own text (compiled for `options`' scan
    /// period where that matters) as a ladder.
    fn decompile_text(&self, text: &str, options: Options) -> Result<Ladder, TextError>;
    /// The 0-based line of its compiled `text` where steps begin.
    fn code_start(&self, _text: &str) -> usize {
        0
    }
    /// Whether a line of its compiled text is a step of the program.
    fn is_step(&self, line: &str) -> bool {
        let line = line.trim();
        !line.is_empty() && !line.starts_with(';')
    }
    /// How many steps end every compiled program (an END marker).
    fn end_steps(&self) -> usize {
        1
    }
}
