//! LDmicro's `.ld` files (issue #32).

mod read;
