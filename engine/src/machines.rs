//! The registry: the one place that names every machine. It sits above
//! both the machine interface (`plc/`, which names none), the ladder
//! (whose [`LadderTarget`] each machine folder implements) and the machine
//! folders, so adding a machine is its folder, its [`MachineKit`] and one
//! arm in [`MachineId::target`] (docs/architecture.md, "Adding a machine").

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
/// (MINASEC-U's switch at RUN, the Arduino PLC enabled). With the
/// feature `registry`, only a machine whose kit is registered can be made:
/// [`try_new_plc`] says whether it was.
pub fn new_plc(id: MachineId) -> Box<dyn Plc> {
    match try_new_plc(id) {
        Some(plc) => plc,
        // Only the page (feature `registry`) can get here, and it
        // registers a machine's kit before it shows the machine.
        None => panic!("{} asked for before its kit was registered", id.name()),
    }
}

/// A new machine of kind `id` as [`new_plc`] makes it; `None` only with
/// the feature `registry` for a machine whose kit is not registered yet.
pub fn try_new_plc(id: MachineId) -> Option<Box<dyn Plc>> {
    kit_of(id).map(|kit| (kit.new_plc)())
}

/// What runs a machine: its compiler and how to make one. Apart from
/// [`LadderTarget`] (what it can draw, which the editor asks of every
/// machine) so that the page can fetch each machine's kit with its part
/// (issue #53) and the first screen links only its own machine's.
#[derive(Clone, Copy)]
pub struct MachineKit {
    /// The machine.
    pub id: MachineId,
    /// Its compiler and decompiler.
    pub compiler: &'static dyn MachineCompiler,
    /// A new machine, powered on, with no program.
    pub new_plc: fn() -> Box<dyn Plc>,
}

impl MachineKit {
    /// MINASEC-U's kit.
    pub const MINASEC: MachineKit = MachineKit {
        id: MachineId::MinasecU,
        compiler: &crate::minasec::target::MinasecTarget,
        new_plc: || Box::new(MinasecPlc::new()),
    };
    /// PLC-IO86A's kit.
    pub const IO86A: MachineKit = MachineKit {
        id: MachineId::Io86a,
        compiler: &crate::io86a::target::Io86aTarget,
        new_plc: || Box::new(Io86aPlc::new()),
    };
    /// The AVR simplified PLC's kit.
    pub const AVR: MachineKit = MachineKit {
        id: MachineId::AvrPlc,
        compiler: &crate::avr::target::AvrTarget,
        new_plc: || Box::new(AvrPlc::new()),
    };
    /// The Arduino PLC's kit.
    pub const ARDUINO: MachineKit = MachineKit {
        id: MachineId::ArduinoPlc,
        compiler: &crate::arduino::target::ArduinoTarget,
        new_plc: || Box::new(ArduinoPlc::new()),
    };
    /// The soft PLC's kit.
    pub const SOFT: MachineKit = MachineKit {
        id: MachineId::SoftPlc,
        compiler: &crate::softplc::target::SoftTarget,
        new_plc: || Box::new(SoftPlc::new()),
    };

    /// Every machine's kit, in [`MachineId::ALL`]'s order.
    #[cfg(not(feature = "registry"))]
    const ALL: [MachineKit; 5] = [
        MachineKit::MINASEC,
        MachineKit::IO86A,
        MachineKit::AVR,
        MachineKit::ARDUINO,
        MachineKit::SOFT,
    ];
}

/// The kit of machine `id`: every machine's, linked in, without the
/// feature `registry`; with it, the kits registered so far.
#[cfg(not(feature = "registry"))]
fn kit_of(id: MachineId) -> Option<MachineKit> {
    MachineKit::ALL.into_iter().find(|k| k.id == id)
}

#[cfg(feature = "registry")]
fn kit_of(id: MachineId) -> Option<MachineKit> {
    registry::kit(id)
}

/// Makes machine `kit.id` runnable (feature `registry`: the page calls it
/// for its first machine and from each machine's part when it arrives;
/// without the feature every machine is, and this does nothing).
pub fn register(kit: MachineKit) {
    #[cfg(feature = "registry")]
    registry::register(kit);
    #[cfg(not(feature = "registry"))]
    let _ = kit;
}

/// Whether machine `id` can be compiled for and run (always, without the
/// feature `registry`).
pub fn registered(id: MachineId) -> bool {
    kit_of(id).is_some()
}

/// The kits registered at run time (the page's parts, issue #53): a
/// `static` each machine's part fills once.
#[cfg(feature = "registry")]
mod registry {
    use super::MachineKit;
    use crate::MachineId;
    use std::sync::OnceLock;

    static KITS: [OnceLock<MachineKit>; 5] = [const { OnceLock::new() }; 5];

    fn slot(id: MachineId) -> &'static OnceLock<MachineKit> {
        &KITS[id.index()]
    }

    pub fn register(kit: MachineKit) {
        // A second registration of the same kit changes nothing.
        let _ = slot(kit.id).set(kit);
    }

    pub fn kit(id: MachineId) -> Option<MachineKit> {
        slot(id).get().copied()
    }
}

/// The compiler of a machine whose kit is not registered yet (the page,
/// before the machine's part arrived): nothing to list or say yet; the
/// page compiles again once the kit is there.
struct Pending;

impl MachineCompiler for Pending {
    fn compile(
        &self,
        _: &[crate::ladder::net::RungLogic],
        _: &[crate::ladder::variables::Variable],
        _: crate::ladder::compile::Options,
    ) -> Result<crate::ladder::compile::Mapped, Vec<crate::ladder::grid::LadderError>> {
        Err(Vec::new())
    }

    fn decompile_text(
        &self,
        _: &str,
        _: crate::ladder::compile::Options,
    ) -> Result<Ladder, crate::ladder::decompile::TextError> {
        Err(crate::ladder::decompile::TextError::Program(Vec::new()))
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
    /// target, apart so that asking a capability links no compiler). With
    /// the feature `registry`, a machine whose kit is not registered yet
    /// compiles nothing and says nothing (see [`register`]).
    pub fn compiler(self) -> &'static dyn MachineCompiler {
        match kit_of(self) {
            Some(kit) => kit.compiler,
            None => &Pending,
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
    fn a_machines_index_is_its_place_in_all() {
        for (i, id) in MachineId::ALL.into_iter().enumerate() {
            assert_eq!(id.index(), i, "{}", id.name());
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
