//! Widgets the machines' panels share: controls (switches, lamps, knobs),
//! the serial console and the text program pane; thin views over
//! [`crate::state::Ctx`]. The page's header is [`crate::header`].

pub mod console;
pub mod controls;
pub mod digit;
pub mod text_program;
