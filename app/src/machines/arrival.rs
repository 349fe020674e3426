//! The machines other than the first screen's arrive with their parts
//! (issue #53, docs/performance.md "Parts"): a machine's engine, its
//! compiler and its panel are fetched the first time it is shown (or a
//! share link, an example or a file opens on it). Until then its ladder is
//! kept and edited as any other, compiled once the machine is there.

use engine::MachineId;

pub use super::workspace::{Arrival, MachineWorkspace, Shared};
use crate::editor::LadderCtx;
use crate::parts::PartMissing;
use crate::state::Ctx;

/// Fetches machine `kind`'s part and makes its workspace (registering
/// its engine kit first). The first screen's machine has no part.
pub async fn fetch(kind: MachineId, page: Ctx, ladder: LadderCtx) -> Result<Shared, PartMissing> {
    use crate::machines::{arduino, avr, io86a, soft};
    match kind {
        MachineId::MinasecU => Err(PartMissing),
        MachineId::Io86a => io86a::arrive(page, ladder).await,
        MachineId::AvrPlc => avr::arrive(page, ladder).await,
        MachineId::ArduinoPlc => arduino::arrive(page, ladder).await,
        MachineId::SoftPlc => soft::arrive(page, ladder).await,
    }
}
