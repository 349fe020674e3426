//! What the blocks do when a program runs, scan by scan: IEC 61131-3's
//! standard function blocks ([`standard`]), LDmicro's elements run as
//! blocks ([`ldmicro`]), one instance's state ([`instance`]) and the
//! serial port LDmicro's UART elements use ([`uart`]). The soft PLC runs
//! them and the ladder's reference evaluator runs the same ones, so each
//! is written once; their signatures are `crate::iec::pins`.

pub mod instance;
pub mod ldmicro;
pub mod standard;
pub mod uart;
