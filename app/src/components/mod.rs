//! The page's components: thin views over [`crate::state::Ctx`].

pub mod board;
pub mod console;
pub mod controls;
pub mod header;
pub mod program;
pub mod text_program;
