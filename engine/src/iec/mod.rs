//! The IEC 61131-3 vocabulary every layer above shares: the elementary
//! types and typed values with their arithmetic ([`data`]), literals
//! ([`literal`], the one IEC TIME literal parser among them),
//! identifiers ([`identifier`]), located variables' addresses
//! ([`address`]) and the blocks' signatures ([`pins`]). It names no
//! machine and no file format: the ladder, the soft PLC, the file formats
//! and the coming Structured Text all build on it.

pub mod address;
pub mod data;
pub mod identifier;
pub mod literal;
pub mod pins;

pub use address::{Address, AddressError, Area, Size};
pub use data::{Data, DataType};
pub use identifier::is_identifier;
pub use literal::{literal_type, parse_literal, LiteralError};
