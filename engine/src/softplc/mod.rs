//! The soft PLC (issue #30, in progress): a general IEC 61131-3 machine
//! with word data, for ladders from other tools. This first part is its
//! data: the elementary types, typed values, IEC literals and the
//! arithmetic that blocks will run, with the semantics docs/soft-plc.md
//! states (OpenPLC's runtime where it defines them). The machine, its
//! Instruction List and its place behind `Plc` come next.

pub mod data;
pub mod literal;

pub use data::{Data, DataType};
pub use literal::{parse_literal, LiteralError};
