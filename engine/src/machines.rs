//! The registry: the one place that names every machine. It sits above
//! both the machine interface (`plc/`, which names none), the ladder
//! (whose [`LadderTarget`] each machine folder implements) and the machine
//! folders, so adding a machine is its folder, one arm in [`new_plc`] and
//! one in [`MachineId::target`] (docs/architecture.md, "Adding a machine").

pub use crate::arduino::ArduinoPlc;
pub use crate::avr::AvrPlc;
pub use crate::io86a::Io86aPlc;
pub use crate::minasec::MinasecPlc;
pub use crate::softplc::SoftPlc;

use crate::ladder::decompile::DecompileError;
use crate::ladder::grid::Ladder;
pub use crate::ladder::machine_target::{LadderTarget, MachineCompiler};
use crate::plc::example::{joined, total};
use crate::plc::{Example, Plc};
use crate::MachineId;

/// Every machine's example programs, machine by machine (each folder's
/// `examples.rs`, in [`MachineId::ALL`]'s order).
pub const EXAMPLES: &[Example] =
    &joined::<{ total(EXAMPLE_LISTS) }>(EXAMPLE_LISTS, crate::minasec::examples::EXAMPLES[0]);

const EXAMPLE_LISTS: &[&[Example]] = &[
    crate::minasec::examples::EXAMPLES,
    crate::io86a::examples::EXAMPLES,
    crate::avr::examples::EXAMPLES,
    crate::arduino::examples::EXAMPLES,
    crate::softplc::examples::EXAMPLES,
];

/// The machine that runs other tools' IEC projects as written (a PLCopen
/// project's own program, an LDmicro file): the soft PLC.
pub const IEC_MACHINE: MachineId = MachineId::SoftPlc;

/// A new machine of kind `id`, powered on, with no program, ready to run
/// (MINASEC-U's switch at RUN, the Arduino PLC enabled).
pub fn new_plc(id: MachineId) -> Box<dyn Plc> {
    match id {
        MachineId::MinasecU => Box::new(MinasecPlc::new()),
        MachineId::Io86a => Box::new(Io86aPlc::new()),
        MachineId::AvrPlc => Box::new(AvrPlc::new()),
        MachineId::ArduinoPlc => Box::new(ArduinoPlc::new()),
        MachineId::SoftPlc => Box::new(SoftPlc::new()),
    }
}

impl MachineId {
    /// The machine's ladder target, from its folder: what it can draw,
    /// its device rules, its compiler and decompiler, how it runs.
    pub fn target(self) -> &'static dyn LadderTarget {
        match self {
            MachineId::MinasecU => &crate::minasec::target::MinasecTarget,
            MachineId::Io86a => &crate::io86a::target::Io86aTarget,
            MachineId::AvrPlc => &crate::avr::target::AvrTarget,
            MachineId::ArduinoPlc => &crate::arduino::target::ArduinoTarget,
            MachineId::SoftPlc => &crate::softplc::target::SoftTarget,
        }
    }

    /// The machine's compiler and decompiler (the other half of its
    /// target, apart so that asking a capability links no compiler).
    pub fn compiler(self) -> &'static dyn MachineCompiler {
        match self {
            MachineId::MinasecU => &crate::minasec::target::MinasecTarget,
            MachineId::Io86a => &crate::io86a::target::Io86aTarget,
            MachineId::AvrPlc => &crate::avr::target::AvrTarget,
            MachineId::ArduinoPlc => &crate::arduino::target::ArduinoTarget,
            MachineId::SoftPlc => &crate::softplc::target::SoftTarget,
        }
    }
}

/// A program parsed for its machine.
pub enum Source<'a> {
    /// A MINASEC-U listing.
    Minasec(&'a crate::minasec::Program),
    /// An AVR PLC program and its scan period in ms (for timer presets).
    Avr(&'a crate::avr::Program, u32),
    /// An IO86A listing.
    Io86a(&'a crate::io86a::Program),
    /// An Arduino sketch program.
    Arduino(&'a crate::arduino::Program),
    /// A soft PLC program.
    Soft(&'a dyn crate::iec::il::IlSource),
}

/// The program as a ladder, by its machine's decompiler.
pub fn decompile(source: Source<'_>) -> Result<Ladder, DecompileError> {
    match source {
        Source::Minasec(p) => crate::minasec::decompile::decompile(p),
        Source::Avr(p, scan_ms) => crate::avr::decompile::decompile(p, scan_ms),
        Source::Io86a(p) => crate::io86a::decompile::decompile(p),
        Source::Arduino(p) => crate::arduino::decompile::decompile(p),
        Source::Soft(p) => crate::ladder::decompile::il_ladder(p),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_machine_hands_out_its_own_target() {
        for id in MachineId::ALL {
            assert_eq!(id.target().id(), id);
        }
    }

    #[test]
    fn share_codes_are_the_machines_own_and_distinct() {
        let codes: Vec<u8> = MachineId::ALL
            .into_iter()
            .map(|m| m.target().share_code())
            .collect();
        // Links given out before the targets name the machines so.
        assert_eq!(codes, [0, 1, 2, 3, 4]);
    }

    #[test]
    fn the_examples_come_machine_by_machine_each_for_its_own() {
        let order: Vec<MachineId> = EXAMPLES.iter().map(|e| e.machine).collect();
        let mut sorted = order.clone();
        sorted.sort_by_key(|m| MachineId::ALL.iter().position(|a| a == m));
        assert_eq!(order, sorted);
        assert_eq!(EXAMPLES.len(), 12);
        assert!(crate::io86a::examples::EXAMPLES
            .iter()
            .all(|e| e.machine == MachineId::Io86a));
    }

    #[test]
    fn only_the_avr_plc_runs_without_a_run_switch() {
        let fixed: Vec<MachineId> = MachineId::ALL
            .into_iter()
            .filter(|m| !m.target().stoppable())
            .collect();
        assert_eq!(fixed, [MachineId::AvrPlc]);
    }
}
