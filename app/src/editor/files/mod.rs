//! Files and sharing (issue #45): the File menu's buttons and downloads
//! ([`buttons`], re-exported here), the import dialog, pictures (SVG,
//! PNG), share links, the autosave and the projects' storage slots.

pub mod autosave;
pub mod buttons;
pub mod import;
pub mod picture;
pub mod reading;
pub mod shared;
pub mod store;

pub use buttons::*;
