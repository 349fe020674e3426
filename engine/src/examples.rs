//! The seeds' example programs, in each machine's own text, for the
//! page's example menu (each opens as a ladder) and for tests. Each
//! machine folder owns its examples (`examples.rs` there); the registry
//! joins them in the order the docs list the machines.

pub use crate::machines::EXAMPLES;
pub use crate::plc::Example;
use crate::MachineId;

/// The examples of `machine`.
pub fn examples_of(machine: MachineId) -> impl Iterator<Item = &'static Example> {
    EXAMPLES.iter().filter(move |e| e.machine == machine)
}
