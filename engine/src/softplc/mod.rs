//! The soft PLC (issue #30, in progress): a general IEC 61131-3 machine
//! with word data, for ladders from other tools. Built so far: its data
//! (the elementary types, typed values, IEC literals and the arithmetic
//! that blocks will run, with the semantics docs/soft-plc.md states:
//! OpenPLC's runtime where it defines them), located variables' addresses
//! and the `VAR … END_VAR` declarations. The machine, its Instruction List
//! and its place behind `Plc` come next.

pub mod address;
pub mod blocks;
mod comments;
pub mod data;
pub mod il;
pub mod ld_blocks;
pub mod ld_format;
mod ld_pins;
pub mod ld_printf;
mod ld_words;
pub mod listing;
pub mod literal;
pub mod machine;
pub(crate) mod pins;
pub mod plc;
pub mod pou;
pub mod program;
pub mod scan;
pub mod segments;
pub mod uart;
pub mod vars;

pub use address::{Address, AddressError, Area, Size};
pub use data::{Data, DataType};
pub use literal::{literal_type, parse_literal, LiteralError};
pub use plc::SoftPlc;
pub use program::{LoadError, Program};
pub use vars::{parse_vars, Kind, VarError, Variable};

/// The tests' view of a refusal: each error's line and message.
#[cfg(test)]
fn said<T: std::fmt::Debug, E: std::fmt::Display>(
    result: Result<T, Vec<crate::error::Located<E>>>,
) -> Vec<(usize, String)> {
    result
        .expect_err("refused")
        .into_iter()
        .map(|e| (e.line, e.error.to_string()))
        .collect()
}
