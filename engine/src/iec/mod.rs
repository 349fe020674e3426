//! The IEC 61131-3 vocabulary every layer above shares: the elementary
//! types and typed values with their arithmetic ([`data`]), literals
//! ([`literal`], the one IEC TIME literal parser among them),
//! identifiers ([`identifier`]), located variables' addresses
//! ([`address`]), the blocks' signatures ([`pins`]), the standard
//! functions' typing and IL ([`functions`]), and the texts'
//! syntax: `VAR … END_VAR` declarations ([`vars`]), Instruction List
//! lines ([`il`]) and both written back ([`listing`]). It names no
//! machine and no file format: the ladder, the soft PLC, the file formats
//! and Structured Text ([`st`], its front end so far) all build on it.

pub mod address;
pub(crate) mod comments;
pub mod comparison;
pub mod data;
pub mod functions;
pub mod identifier;
pub mod il;
pub mod listing;
pub mod literal;
pub mod pins;
pub mod st;
pub mod vars;

pub use address::{Address, AddressError, Area, Size};
pub use comparison::Comparison;
pub use data::{Data, DataType};
pub use identifier::is_identifier;
pub use literal::{literal_type, parse_literal, LiteralError};
pub use vars::{parse_vars, Kind, VarError, Variable};

/// The tests' view of a refusal: each error's line and message.
#[cfg(test)]
pub(crate) fn said<T: std::fmt::Debug, E: std::fmt::Display>(
    result: Result<T, Vec<crate::error::Located<E>>>,
) -> Vec<(usize, String)> {
    result
        .expect_err("refused")
        .into_iter()
        .map(|e| (e.line, e.error.to_string()))
        .collect()
}
