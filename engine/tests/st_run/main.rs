//! Structured Text running on the soft PLC (issue #54): programs read,
//! checked, lowered to IL and scanned; expected values worked out from
//! IEC 61131-3's rules by hand.

mod blocks;
#[path = "../common/mod.rs"]
mod files;

mod cli;
mod common;
mod control;
mod expressions;
mod inout;
mod lines;
mod numeric;
mod property;
mod refusals;
mod small_types;
mod speed;
