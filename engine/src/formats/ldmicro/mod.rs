//! LDmicro's `.ld` ladder files (issue #32; docs/ldmicro.md): read in
//! every form LDmicro 2.x and 4.x write, in phases: text → document
//! ([`parse`](mod@parse) into an [`LdFile`]), document → model
//! ([`to_ladder`]), model → text ([`export`](fn@export)).
//!
//! - [`file`](mod@file): the file as read — settings, the variable, I/O and pull-up
//!   lists, rungs of nested series and parallel groups;
//! - [`element`]: one variant per kind of element line;
//! - [`parse`](mod@parse): the reader, every problem at its line;
//! - [`to_ladder`]: the file as a soft PLC ladder, LDmicro's timers and
//!   counters as its blocks ([`crate::runtime::ldmicro`]).

pub mod element;
mod elements;
pub mod error;
mod escape;
mod export;
pub mod file;
mod ladder;
mod leaf;
mod lower;
mod numbers;
pub mod parse;
mod parts;
mod roles;
mod texts;

pub use element::Element;
pub use error::LdError;
pub use export::export;
pub use file::{LdFile, LdRung, Node, Version};
pub use ladder::{locate, to_ladder};
pub use parse::{decode, parse};
