//! PLC-IO86A: the PIC-based embedded PLC with FX-style mnemonics
//! (machines.md §2).
//!
//! - [`isa`]: devices and instructions;
//! - [`asm`]: the mnemonic listing (parser with located errors, `L` listing);
//! - [`machine`]: the scan, timers, counters, data instructions and the
//!   system relays.
//!
//! Not yet here: the serial terminal, the peripherals (analog, PWM/servo,
//! IR, input filter) and the link between two devices beyond SETS/RSTS
//! writes being collected.

pub mod asm;
pub mod headless;
pub mod isa;
pub mod machine;

pub use asm::{AsmError, Program};
pub use isa::{Bit, Instruction, Word};
pub use machine::{Devices, Machine};
