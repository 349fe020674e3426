//! The page's shared chrome: header, controls, the serial console and the
//! text program pane; thin views over [`crate::state::Ctx`].

pub mod console;
pub mod controls;
pub mod header;
pub mod text_program;
