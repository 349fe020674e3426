//! The workbench's areas as the page draws them (issue #45, docs/app.md
//! "The workbench"): the docks around the ladder, their tabs and
//! splitters. Their state is plain data in `crate::docks`; the app bar is
//! `crate::appbar`, the ladder view `crate::editor`.

pub mod docks;
