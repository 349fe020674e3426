//! MINASEC-U: the logic-IC PLC of the seed book (machines.md §1).
//!
//! - [`isa`]: opcodes, addresses, encode/decode, the logic unit;
//! - [`asm`]: the mnemonic listing and the programming sheet;
//! - [`machine`]: the board stepping clock by clock, and [`control`] for
//!   operating it;
//! - [`panel`]: the front panel as plain data;
//! - [`cpu`]: the CPU's signals and blocks for the view inside it.

pub mod asm;
pub mod control;
pub mod counter;
pub mod cpu;
pub mod decompile;
pub mod examples;
mod fast;
pub mod isa;
pub mod machine;
pub mod panel;
pub mod plc;
pub mod target;
pub mod timer;

pub use asm::{AsmError, Program, ProgrammingSheet};
pub use control::{ClockSpeed, Command, Mode, SettingError, TimerId};
pub use isa::{Address, Instruction, Opcode};
pub use machine::{Machine, ScanSnapshot};
pub use panel::{CpuSignals, Panel};
pub use plc::MinasecPlc;

/// The seed book's test program (machines.md §1): X00 start, X01 stop,
/// self-holding Y00; T0/T1 flicker while running; each T0 rise counts C0;
/// C0 match lights Y01; X02 clears the count.
///
/// The book prints the listing as a picture; this is its text, rebuilt
/// from the book's ladder description and its step 1 (`OR Y00` =
/// `100 01000`).
pub const SEED_TEST_PROGRAM: &str = include_str!("../../programs/minasec-u/seed-test.il");
