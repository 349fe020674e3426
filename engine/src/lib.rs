//! Hashigo's simulator core: the PLC machines, their program formats and
//! the simulated clock. Pure Rust with no web or OS dependencies, so the
//! same code runs natively (the `hashigo` command, tests, benchmarks) and
//! in the browser (wasm32).

pub mod arduino;
pub mod avr;
pub mod cases;
pub mod clock;
pub mod error;
pub mod events;
pub mod examples;
pub mod formats;
pub mod headless;
pub mod iec;
pub mod io86a;
pub mod ladder;
pub mod limits;
pub mod machine_id;
pub mod machines;
pub mod minasec;
pub mod operand;
pub mod plant;
pub mod plc;
pub mod record;
pub mod runtime;
pub mod scan_timer;
pub mod softplc;
pub mod sort;
pub mod time;

pub use error::{shown, Located};
pub use machine_id::{MachineId, UnknownMachine};
pub use time::SimTime;
