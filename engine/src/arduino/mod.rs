//! The Arduino PLC sketch (machines.md §4): 16-bit words in EEPROM run with
//! a bit stack, and its serial monitor.
//!
//! - [`isa`]: words, mnemonics, the listing;
//! - [`machine`]: stepping, the stack (intended or the sketch's pop order),
//!   erased EEPROM as `JUMP 255`;
//! - [`monitor`]: the serial monitor's commands.

pub mod decompile;
pub mod examples;
pub mod isa;
pub mod machine;
pub mod monitor;
pub mod plc;
pub mod target;

pub use isa::Program;
pub use machine::{Chip, Machine, PopOrder};
pub use plc::{warnings, ArduinoPlc};
