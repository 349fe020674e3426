//! One folder (or file) per machine: its workspace's state and view.

pub mod arduino;
pub mod avr;
pub mod io86a;
pub mod minasec;
