//! The soft PLC: a general IEC 61131-3 machine with word data, for
//! ladders from other tools (PLCopen XML, LDmicro `.ld` files) and its
//! own Instruction List. Its vocabulary (types, values, literals,
//! addresses, block signatures) is `crate::iec`, its blocks' runtime
//! `crate::runtime`; here are its program text (declarations [`vars`],
//! IL [`il`], POUs [`pou`]), the loader that resolves and type-checks it
//! ([`program`]), the scan that runs it ([`scan`], [`machine`]) and its
//! place behind `Plc` ([`plc`]); docs/soft-plc.md states its semantics.

pub mod examples;
pub mod machine;
pub mod plc;
pub mod pou;
pub mod program;
pub mod scan;
pub mod st;
pub mod st_online;
pub mod st_why;
pub mod target;

pub use plc::SoftPlc;
pub use program::{LoadError, Program};
