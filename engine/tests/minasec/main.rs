//! MINASEC-U behaviour tests: the seed's examples and every rule of
//! machines.md §1, driven through the engine's public API and the CLI.

#[path = "../common/mod.rs"]
mod common;

mod cli;
mod counter;
mod cpu_view;
mod fast_path;
mod harness;
mod programming;
mod reset_power;
mod robustness;
mod scan_io;
mod seed_program;
mod timers;
