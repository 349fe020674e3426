//! The five machines' workspaces, listed in this one place: MINASEC-U's
//! here, the others' each arriving with its part (`machines::arrival`:
//! adding a machine means its part there and its arm in `fetch`).

use leptos::prelude::*;

use engine::MachineId;

use crate::docks::Tool;
use crate::editor::{LadderCtx, LadderEditor, Ladders, Program};
use crate::machines;
use crate::machines::arrival::{self, Arrival, MachineWorkspace};
use crate::machines::minasec::board::Board;
use crate::machines::minasec::program::ProgramPane;
use crate::machines::minasec::MinasecCtx;
use crate::sim::Pace;
use crate::state::{Ctx, MachineKind};
use crate::workbench::docks::{BottomDock, RightDock, Split, Splitter};

/// Every workspace's context; `Copy`. MINASEC-U, the first screen's
/// machine, is always there; the others arrive with their parts
/// ([`crate::machines::arrival`]).
#[derive(Clone, Copy)]
pub struct Workspaces {
    pub minasec: MinasecCtx,
    /// Each machine's part, in [`MachineId::ALL`]'s order (MINASEC-U's
    /// stays `NotAsked`: it has none).
    arrivals: [RwSignal<Arrival, LocalStorage>; MachineId::ALL.len()],
    /// Each machine's ladder editor.
    pub ladders: Ladders,
    /// The named projects.
    pub projects: crate::editor::projects::Projects,
    /// The plant dock's state (issue #52).
    pub plants: crate::plant::Plants,
    page: Ctx,
}

impl Workspaces {
    /// Every workspace on `page`, each ladder restored from its autosave;
    /// MINASEC-U's workspace too, connected to its ladder editor.
    pub fn restore(page: Ctx) -> Workspaces {
        Workspaces::around(page, MinasecCtx::restore(page))
    }

    /// The workspaces of `page` around this MINASEC-U workspace.
    pub fn around(page: Ctx, minasec: MinasecCtx) -> Workspaces {
        let ladders = Ladders::new(|machine| LadderCtx::restore(page, machine));
        let minasec_program = Program {
            text: minasec.text,
            load: Callback::new(move |()| {
                minasec.load_text();
                minasec.save();
            }),
            save: Callback::new(move |()| minasec.save()),
            settings: Callback::new(move |()| minasec.project_settings()),
            apply_settings: Callback::new(move |settings| minasec.apply_project_settings(settings)),
            source: Callback::new(|()| None),
            apply_source: Callback::new(|_| ()),
            why_st: Callback::new(|_| Vec::new()),
        };
        let ladder = ladders.of(MachineId::MinasecU);
        ladder.attach(machines::link(minasec.sim, move |_| minasec.refresh()));
        ladder.connect(minasec_program);
        // Every machine powers up in STOP: time stands still until Run
        // (the others as they arrive, `workspace::wire`).
        ladder.stop_at_power_up();
        Workspaces {
            minasec,
            arrivals: MachineId::ALL.map(|_| RwSignal::new_local(Arrival::NotAsked)),
            ladders,
            projects: crate::editor::projects::Projects::restore(page),
            plants: crate::plant::Plants::new(),
            page,
        }
    }

    fn arrival(&self, kind: MachineId) -> RwSignal<Arrival, LocalStorage> {
        self.arrivals[kind.index()]
    }

    /// Machine `kind`'s workspace, once its part is there (never
    /// MINASEC-U's, which is [`Workspaces::minasec`]).
    pub fn workspace(&self, kind: MachineId) -> Option<arrival::Shared> {
        match self.arrival(kind).get_untracked() {
            Arrival::Ready(workspace) => Some(workspace),
            _ => None,
        }
    }

    /// Fetches machine `kind`'s part unless it is there or on its way
    /// (again after a failed fetch).
    pub fn arrive(&self, kind: MachineId) {
        let slot = self.arrival(kind);
        let asked = slot.with_untracked(|a| !matches!(a, Arrival::NotAsked | Arrival::Missing));
        if kind == MachineId::MinasecU || asked {
            return;
        }
        slot.set(Arrival::Loading);
        let (page, ladder) = (self.page, self.ladders.of(kind));
        leptos::task::spawn_local(async move {
            let next = match arrival::fetch(kind, page, ladder).await {
                Ok(workspace) => Arrival::Ready(workspace),
                // What waits for it (`when_ready`) waits for a retry.
                Err(_) => Arrival::Missing,
            };
            let _ = slot.try_set(next);
        });
    }

    /// Runs `then` once machine `kind` is there: now, or when its part
    /// has arrived (never, if it cannot be fetched and no retry brings it).
    pub fn when_ready(&self, kind: MachineId, then: impl FnOnce() + 'static) {
        self.ladders.of(kind).when_attached(then);
        self.arrive(kind);
    }

    /// Provides every workspace's context to the components below.
    pub fn provide(&self) {
        provide_context(self.minasec);
        provide_context(self.ladders);
        provide_context(self.projects);
        provide_context(self.plants);
        provide_context(crate::rig::ShownPlant(self.plants.shown));
        provide_context(*self);
        let spaces = *self;
        provide_context(crate::editor::files::OpenSt(Callback::new(
            move |(file, text): (String, String)| spaces.open_st(file, text),
        )));
    }

    /// A Structured Text file opened (issue #55): the page shows the soft
    /// PLC, whose program pane takes the text in ST once its part is there
    /// (the ladder stays as it was).
    fn open_st(&self, file: String, text: String) {
        let kind = engine::machines::IEC_MACHINE;
        let (spaces, page) = (*self, self.page);
        page.machine.set(kind);
        crate::storage::save_string(crate::storage::MACHINE_KEY, kind.name());
        self.when_ready(kind, move || {
            // After the arrival is recorded (what waited runs first).
            set_timeout(
                move || {
                    if let Some(w) = spaces.workspace(kind) {
                        if w.open_text(&file, &text) {
                            page.docks.show(Tool::Program);
                        }
                    }
                },
                std::time::Duration::ZERO,
            );
        });
    }

    /// One animation frame for the workspace of `kind`: `wall_ms` of wall
    /// time at `pace`, then its signals refreshed. The others rest.
    pub fn frame(&self, kind: MachineKind, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
        let ladder = self.ladders.of(kind);
        ladder.frame(pace, wall_ms, now_ms);
        self.plants.publish(ladder);
    }

    /// After a frame is drawn: `Speed::Max`'s simulation on machine
    /// `kind` until `deadline_ms` ([`LadderCtx::after_frame`]).
    pub fn after_frame(
        &self,
        kind: MachineKind,
        pace: Pace,
        deadline_ms: f64,
        now_ms: fn() -> f64,
    ) {
        self.ladders.of(kind).after_frame(pace, deadline_ms, now_ms);
    }

    /// The workbench for `kind`: the ladder editor in the centre with the
    /// tools dock under it, the machine's panel in the dock on the right
    /// (docs/app.md, "The workbench").
    pub fn view(&self, kind: MachineKind) -> AnyView {
        let ladder = self.ladders.of(kind);
        provide_context(ladder);
        let grid = NodeRef::<leptos::html::Div>::new();
        let mut tools = crate::editor::tools(ladder, grid);
        tools.push((Tool::Program, self.program_view(kind)));
        tools.push((
            Tool::Plant,
            view! { <crate::plant::PlantDock ladder /> }.into_any(),
        ));
        if Tool::Cpu.on(kind) {
            tools.push((
                Tool::Cpu,
                view! { <crate::machines::minasec::cpu_view::CpuPanel /> }.into_any(),
            ));
        }
        tools.sort_by_key(|(tool, _)| Tool::ALL.iter().position(|t| t == tool));
        let panel = self.panel_view(kind);
        let docks = ladder.page.docks;
        // The style sheet keeps each dock within its share of the window.
        let sizes = move || {
            docks.sizes.with(|s| {
                format!(
                    "--dock-w: {:.0}px; --dock-h: {:.0}px",
                    s.right_px, s.bottom_px
                )
            })
        };
        view! {
            <div class="bench" data-testid="workbench" data-machine=kind.name() style=sizes
                data-right-open=move || docks.sizes.with(|s| s.right_open).to_string()
                data-bottom-open=move || docks.sizes.with(|s| s.bottom_open).to_string()>
                <main class="bench-centre" id="ladder-area">
                    <crate::plant::PlantAbove ladder />
                    <LadderEditor ctx=ladder grid />
                    <Splitter split=Split::Bottom />
                    <BottomDock machine=kind panels=tools />
                </main>
                <Splitter split=Split::Right />
                <RightDock>{panel}</RightDock>
            </div>
        }
        .into_any()
    }

    /// Opens example `id` on the machine's own panel too, if the panel
    /// takes examples (MINASEC-U's board loads its test program as
    /// before, `machines::minasec::examples`); whether it did.
    pub fn open_example_on_panel(&self, kind: MachineKind, id: &str) -> bool {
        match kind {
            MachineKind::MinasecU => {
                crate::machines::minasec::examples::open(self.minasec, id);
                true
            }
            _ => false,
        }
    }

    /// The machine's own panel: its board, lamps and switches, consoles.
    fn panel_view(&self, kind: MachineKind) -> AnyView {
        match kind {
            MachineKind::MinasecU => view! { <div class="workspace"><Board /></div> }.into_any(),
            _ => self.arrived(kind, "machine-panel", |w| w.panel()),
        }
    }

    /// The machine's program text, in the tools dock.
    fn program_view(&self, kind: MachineKind) -> AnyView {
        match kind {
            MachineKind::MinasecU => view! { <ProgramPane /> }.into_any(),
            _ => self.arrived(kind, "machine-program", |w| w.program()),
        }
    }

    /// What `show` draws of machine `kind` once its part is there; until
    /// then where it stands (loading, or missing with a retry).
    fn arrived(
        &self,
        kind: MachineKind,
        testid: &'static str,
        show: fn(&dyn MachineWorkspace) -> AnyView,
    ) -> AnyView {
        let slot = self.arrival(kind);
        let lang = self.page.lang;
        let me = *self;
        let retry = Callback::new(move |()| me.arrive(kind));
        (move || match slot.get() {
            Arrival::Ready(workspace) => show(&*workspace),
            other => {
                let missing = matches!(other, Arrival::Missing);
                crate::parts::not_there(testid, lang.get(), missing, retry)
            }
        })
        .into_any()
    }
}
