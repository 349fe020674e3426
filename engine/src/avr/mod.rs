//! The AVR simplified PLC (machines.md §3): ladder records written as `.db`
//! lines in AVR assembler, run by an accumulator interpreter.
//!
//! - [`asm`]: the assembler subset;
//! - [`program`]: records decoded into instructions, bit names;
//! - [`machine`]: the scan and the TON/TOF/TP timers.

pub mod asm;
pub mod decompile;
pub mod examples;
pub mod machine;
pub mod plc;
pub mod program;
pub mod target;

pub use machine::{scan_ms, Machine, TimerWord};
pub use plc::{warnings, AvrPlc};
pub use program::{parse_register_bit, BitRef, Instruction, Program, ProgramError, TimerKind};
