//! What a machine's part hands the page (issue #53): its workspace, and
//! how it connects to its ladder editor. A leaf the machines' folders
//! import; `arrival.rs` fetches them.

use std::rc::Rc;

use leptos::prelude::*;

use crate::editor::machine::MachineLink;
use crate::editor::{LadderCtx, Program};

/// A machine's workspace as its part hands it over: what the page shows of
/// it. Built inside the part, so its code stays there.
pub trait MachineWorkspace {
    /// The machine's own panel: its board, lamps and switches, consoles.
    fn panel(&self) -> AnyView;
    /// The machine's program text, in the tools dock.
    fn program(&self) -> AnyView;
    /// Its own context (the component tests reach a machine's state so).
    fn as_any(&self) -> &dyn std::any::Any;
    /// Opens a program text of the machine's own language (a `.st` file
    /// on the soft PLC, issue #55) in its program pane; false where the
    /// machine takes none. The code stays in the machine's part.
    fn open_text(&self, _file: &str, _text: &str) -> bool {
        false
    }
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
