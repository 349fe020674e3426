//! Structured Text running on the soft PLC (issue #54): programs read,
//! checked, lowered to IL and scanned; expected values worked out from
//! IEC 61131-3's rules by hand.

mod blocks;
mod call_args;
#[path = "../common/mod.rs"]
mod files;

mod cli;
mod common;
mod composite;
mod control;
mod expressions;
mod globals;
mod inout;
mod later_inputs;
mod lines;
mod lreal;
mod numeric;
mod places;
mod programs;
mod property;
mod refusals;
mod small_types;
mod speed;
