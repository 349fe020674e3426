//! Hostile and extreme input (docs/limits.md): every input that once made
//! the engine panic, overflow its stack, run out of memory, hang or give a
//! silently wrong result, kept as a regression test.

#[path = "../common/mod.rs"]
mod common;
mod gen;

mod avr_source;
mod cli;
mod ladders;
mod messages;
mod plcopen;
mod properties;
mod round2;
mod round3;
