//! The five machines' workspaces, listed in this one place: adding a
//! machine means a context here, its view here, and its frame here.

use leptos::prelude::*;

use engine::MachineId;

use std::rc::Rc;

use crate::docks::Tool;
use crate::editor::machine::MachineLink;
use crate::editor::{LadderCtx, LadderEditor, Ladders, Program};
use crate::machines::minasec::board::Board;
use crate::machines::minasec::program::ProgramPane;
use crate::machines::minasec::MinasecCtx;
use crate::machines::{self, arduino, avr, io86a, soft};
use crate::sim::Pace;
use crate::state::{Ctx, MachineKind};
use crate::workbench::docks::{BottomDock, RightDock, Split, Splitter};

/// Every workspace's context; `Copy`.
#[derive(Clone, Copy)]
pub struct Workspaces {
    pub minasec: MinasecCtx,
    pub io86a: io86a::Io86aCtx,
    pub arduino: arduino::ArduinoCtx,
    pub avr: avr::AvrCtx,
    pub soft: soft::SoftCtx,
    /// Each machine's ladder editor.
    pub ladders: Ladders,
    /// The named projects.
    pub projects: crate::editor::projects::Projects,
}

impl Workspaces {
    /// Every workspace on `page`, each restored from its autosave.
    pub fn restore(page: Ctx) -> Workspaces {
        let minasec = MinasecCtx::restore(page);
        let io86a = io86a::Io86aCtx::new();
        let arduino = arduino::ArduinoCtx::restore(page);
        let avr = avr::AvrCtx::restore(page);
        let soft = soft::SoftCtx::restore(page);
        Workspaces::around(page, minasec, io86a, arduino, avr, soft)
    }

    /// The workspaces of these machines, each with its ladder editor
    /// connected to its program pane.
    pub fn around(
        page: Ctx,
        minasec: MinasecCtx,
        io86a: io86a::Io86aCtx,
        arduino: arduino::ArduinoCtx,
        avr: avr::AvrCtx,
        soft: soft::SoftCtx,
    ) -> Workspaces {
        let ladders = Ladders::new(|machine| LadderCtx::restore(page, machine));
        let wire = |machine, link: Rc<dyn MachineLink>, program: Program| {
            let ladder = ladders.of(machine);
            ladder.attach(link);
            ladder.connect(program);
        };
        let minasec_program = Program {
            text: minasec.text,
            load: Callback::new(move |()| {
                minasec.load_text();
                minasec.save();
            }),
            save: Callback::new(move |()| minasec.save()),
            settings: Callback::new(move |()| minasec.project_settings()),
            apply_settings: Callback::new(move |settings| minasec.apply_project_settings(settings)),
        };
        wire(
            MachineId::MinasecU,
            machines::link(minasec.sim, move || minasec.refresh()),
            minasec_program,
        );
        wire(
            MachineId::Io86a,
            machines::link(io86a.sim, move || io86a.refresh()),
            machines::text_program(io86a.texts[0], move || io86a.load(0), move || io86a.save()),
        );
        wire(
            MachineId::ArduinoPlc,
            machines::link(arduino.sim, move || arduino.refresh()),
            machines::text_program(arduino.text, move || arduino.load(), move || arduino.save()),
        );
        // The AVR compiler's scan period before its program pane is read.
        ladders
            .of(MachineId::AvrPlc)
            .text
            .options
            .update(|o| o.avr_scan_ms = avr::scan_ms_default());
        wire(
            MachineId::AvrPlc,
            machines::link(avr.sim, move || avr.refresh()),
            machines::text_program(avr.text, move || avr.load(), move || avr.save()),
        );
        let mut soft_program =
            machines::text_program(soft.text, move || soft.load(), move || soft.save());
        soft_program.settings = Callback::new(move |()| soft.project_settings());
        soft_program.apply_settings =
            Callback::new(move |settings| soft.apply_project_settings(settings));
        wire(
            MachineId::SoftPlc,
            machines::link(soft.sim, move || soft.refresh()),
            soft_program,
        );
        // Every machine powers up in STOP: time stands still until Run.
        for machine in MachineId::ALL {
            ladders.of(machine).stop_at_power_up();
        }
        Workspaces {
            minasec,
            io86a,
            arduino,
            avr,
            soft,
            ladders,
            projects: crate::editor::projects::Projects::restore(page),
        }
    }

    /// Provides every workspace's context to the components below.
    pub fn provide(&self) {
        provide_context(self.minasec);
        provide_context(self.io86a);
        provide_context(self.arduino);
        provide_context(self.avr);
        provide_context(self.soft);
        provide_context(self.ladders);
        provide_context(self.projects);
        provide_context(*self);
    }

    /// One animation frame for the workspace of `kind`: `wall_ms` of wall
    /// time at `pace`, then its signals refreshed. The others rest.
    pub fn frame(&self, kind: MachineKind, pace: Pace, wall_ms: f64, now_ms: fn() -> f64) {
        self.ladders.of(kind).frame(pace, wall_ms, now_ms);
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
            MachineKind::Io86a => view! { <io86a::view::Io86aPanel io=self.io86a /> }.into_any(),
            MachineKind::ArduinoPlc => {
                view! { <arduino::ArduinoPanel ard=self.arduino /> }.into_any()
            }
            MachineKind::AvrPlc => view! { <avr::AvrPanel avr=self.avr /> }.into_any(),
            MachineKind::SoftPlc => view! { <soft::SoftPanel soft=self.soft /> }.into_any(),
        }
    }

    /// The machine's program text, in the tools dock.
    fn program_view(&self, kind: MachineKind) -> AnyView {
        match kind {
            MachineKind::MinasecU => view! { <ProgramPane /> }.into_any(),
            MachineKind::Io86a => view! { <io86a::view::Io86aProgram io=self.io86a /> }.into_any(),
            MachineKind::ArduinoPlc => {
                view! { <arduino::ArduinoProgram ard=self.arduino /> }.into_any()
            }
            MachineKind::AvrPlc => view! { <avr::AvrProgram avr=self.avr /> }.into_any(),
            MachineKind::SoftPlc => view! { <soft::SoftProgram soft=self.soft /> }.into_any(),
        }
    }
}
