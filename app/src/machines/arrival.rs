//! The machines other than the first screen's arrive with their parts
//! (issue #53, docs/performance.md "Parts"): a machine's engine, its
//! compiler and its panel are fetched the first time it is shown (or a
//! share link, an example or a file opens on it). Until then its ladder is
//! kept and edited as any other, compiled once the machine is there.

use std::rc::Rc;

use engine::MachineId;
use leptos::prelude::*;

use crate::editor::machine::MachineLink;
use crate::editor::{LadderCtx, Program};
use crate::parts::PartMissing;
use crate::state::Ctx;

/// A machine's workspace as its part hands it over: what the page shows of
/// it. Built inside the part, so its code stays there.
pub trait MachineWorkspace {
    /// The machine's own panel: its board, lamps and switches, consoles.
    fn panel(&self) -> AnyView;
    /// The machine's program text, in the tools dock.
    fn program(&self) -> AnyView;
    /// Its own context (the component tests reach a machine's state so).
    fn as_any(&self) -> &dyn std::any::Any;
}

/// A machine's workspace, shared by the views that show it.
pub type Shared = Rc<dyn MachineWorkspace>;

/// Where a machine's part stands.
#[derive(Clone)]
pub enum Arrival {
    /// Not asked for yet.
    NotAsked,
    /// Being fetched.
    Loading,
    /// Could not be fetched (offline on a first visit): retried on asking.
    Missing,
    /// There, with its workspace.
    Ready(Shared),
}

/// Connects an arrived machine to its ladder editor: compiles the ladder
/// now that the machine's compiler is there, then links the simulator and
/// the program pane, as the first screen's machine is at start.
/// What waited for it (Run pressed, an example or an answer to check)
/// runs now.
pub fn wire(ladder: LadderCtx, link: Rc<dyn MachineLink>, program: Program) {
    ladder.refresh(false);
    ladder.attach(link);
    ladder.connect(program);
    // It powers up in STOP, as every machine does, until Run.
    ladder.stop_at_power_up();
    ladder.arrived();
}

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

/// The machine's part's place in a dock while it is not there:
/// "Loading…", or that it could not be fetched with a retry button.
pub fn waiting(
    testid: &'static str,
    lang: Signal<crate::i18n::Lang>,
    arrival: Arrival,
    retry: impl Fn() + Copy + Send + Sync + 'static,
) -> AnyView {
    let texts = lang.get_untracked().parts();
    match arrival {
        Arrival::Missing => view! {
            <div class="part-state" role="alert" data-testid=format!("{testid}-missing")>
                <p>{texts.missing}</p>
                <button type="button" data-testid=format!("{testid}-retry") on:click=move |_| retry()>
                    {texts.retry}
                </button>
            </div>
        }
        .into_any(),
        _ => view! {
            <p class="part-state" role="status" data-testid=format!("{testid}-loading")>
                {texts.loading}
            </p>
        }
        .into_any(),
    }
}
