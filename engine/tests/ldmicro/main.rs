//! LDmicro's `.ld` files (issue #32).

mod blocks;
#[path = "../common/mod.rs"]
mod common;
mod forms;
mod plcopen;
mod read;
mod run;
mod segments;
mod strings;
