//! LDmicro's `.ld` files (issue #32).

mod blocks;
mod read;
mod run;
