//! PLC-IO86A: the PIC-based embedded PLC with FX-style mnemonics
//! (machines.md §2).
//!
//! - [`isa`]: devices and instructions;
//! - [`asm`]: the mnemonic listing (parser with located errors, `L` listing);
//! - [`machine`]: the scan, timers, counters, data instructions and the
//!   system relays.
//!
//! - [`peripherals`]: analog inputs, the IR receiver, PWM/servo outputs and
//!   the input filter;
//! - [`terminal`]: the serial terminal's commands.

pub mod asm;
pub mod decompile;
pub mod examples;
pub mod front;
pub mod isa;
pub mod link;
pub mod machine;
pub mod peripherals;
pub mod plc;
mod scan;
pub mod target;
pub mod terminal;

pub use asm::{AsmError, Program};
pub use front::{Fronts, Io86aFront};
pub use isa::{Bit, Instruction, Word};
pub use link::{LinkedPair, LoadLinked};
pub use machine::{Devices, Machine};
pub use plc::Io86aPlc;
pub use scan::ScanState;
pub use terminal::Terminal;
