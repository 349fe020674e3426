//! The PLC-IO86A workspace: two linked devices (B is shown on request),
//! the serial terminal of device A, and a program pane per device.

pub mod saved;
pub mod view;

use engine::events::InputValue;
use engine::io86a::peripherals::OutputSignal;
use engine::io86a::{Fronts, Io86aFront, LoadLinked, Program};
use engine::machines::Io86aPlc;
use engine::plc::{Command, Front, Own, Plc};
use leptos::prelude::*;

use crate::sim::Simulator;
use crate::state::put;
use crate::storage::{self, Restored};
use saved::{SavedIo86a, IO86A_KEY};

/// The manual's LED blink, the text a fresh workspace opens with.
pub const BLINK: &str = "; PLC-IO86A manual: LED blink (0.2 s on, 0.2 s off)\n\
1 LDI T01\n2 OUT T00\n3 K2\n4 LD T00\n5 OUT T01\n6 K2\n7 LDI T00\n8 OUT Y00\n9 END\n";

/// One signal per pin and value of a device.
#[derive(Clone, Copy)]
pub struct DeviceSignals {
    /// Input pins X00..X07 as driven.
    pub inputs: [RwSignal<bool>; 8],
    /// Output pins Y00..Y05.
    pub lamps: [RwSignal<bool>; 6],
    /// D00..D07 after the last scan.
    pub d: [RwSignal<i16>; 8],
    /// X04/X05 volts (mV) and whether they are analog inputs.
    pub analog_mv: [RwSignal<i64>; 2],
    pub analog: [RwSignal<bool>; 2],
    /// X07 is the IR receiver.
    pub ir: RwSignal<bool>,
    /// Y03 / Y04 signals.
    pub outputs: [RwSignal<OutputSignal>; 2],
    pub running: RwSignal<bool>,
}

impl DeviceSignals {
    fn new() -> DeviceSignals {
        DeviceSignals {
            inputs: std::array::from_fn(|_| RwSignal::new(false)),
            lamps: std::array::from_fn(|_| RwSignal::new(false)),
            d: std::array::from_fn(|_| RwSignal::new(0)),
            analog_mv: [RwSignal::new(0), RwSignal::new(0)],
            analog: [RwSignal::new(false), RwSignal::new(false)],
            ir: RwSignal::new(false),
            outputs: [
                RwSignal::new(OutputSignal::Level(false)),
                RwSignal::new(OutputSignal::Level(false)),
            ],
            running: RwSignal::new(true),
        }
    }

    fn sync(&self, m: &Io86aFront) {
        for n in 0..8 {
            put(self.inputs[n], m.inputs >> n & 1 != 0);
            put(self.d[n], m.d[n]);
        }
        for n in 0..6 {
            put(self.lamps[n], m.outputs >> n & 1 != 0);
        }
        for i in 0..2 {
            put(self.analog_mv[i], m.analog_mv[i]);
            put(self.analog[i], m.analog[i]);
            put(self.outputs[i], m.signals[i]);
        }
        put(self.ir, m.ir);
        put(self.running, m.running);
    }
}

/// Everything the IO86A workspace's components share.
#[derive(Clone, Copy)]
pub struct Io86aCtx {
    /// Device A, and device B linked to it, with A's serial terminal.
    pub sim: StoredValue<Simulator<Io86aPlc>, LocalStorage>,
    pub devices: [DeviceSignals; 2],
    /// What device A's terminal has sent (CR LF as LF).
    pub console: RwSignal<String>,
    /// The program panes' texts and their errors (line, message).
    pub texts: [RwSignal<String>; 2],
    pub errors: [RwSignal<Vec<(usize, String)>>; 2],
    /// Whether device B is shown.
    pub two: RwSignal<bool>,
    pub notice: RwSignal<Option<String>>,
}

impl Io86aCtx {
    /// A workspace restored from autosave: each text that parses is loaded.
    pub fn new() -> Io86aCtx {
        let ctx = Io86aCtx {
            sim: StoredValue::new_local(Simulator::new(Io86aPlc::new())),
            devices: [DeviceSignals::new(), DeviceSignals::new()],
            console: RwSignal::new(String::new()),
            texts: [
                RwSignal::new(BLINK.to_string()),
                RwSignal::new(String::new()),
            ],
            errors: [RwSignal::new(Vec::new()), RwSignal::new(Vec::new())],
            two: RwSignal::new(false),
            notice: RwSignal::new(None),
        };
        match storage::restore_from::<SavedIo86a>(IO86A_KEY) {
            Restored::Saved(saved) => {
                for (signal, text) in ctx.texts.iter().zip(saved.programs) {
                    signal.set(text);
                }
            }
            Restored::Corrupt { kept_as } => ctx.notice.set(Some(kept_as)),
            Restored::Nothing | Restored::Unavailable => {}
        }
        for device in 0..2 {
            ctx.load(device);
        }
        let prompt = ctx
            .sim
            .try_update_value(|s| s.machine_mut().serial_open().unwrap_or_default())
            .unwrap_or_default();
        ctx.console.set(prompt);
        ctx
    }

    /// Drives input `pin` (`X00`…) of device `i` (0 = A, 1 = B) to
    /// `value`; false when the device refuses it (a voltage on a digital
    /// input).
    pub fn drive(&self, i: usize, pin: &str, value: InputValue) -> bool {
        let name = if i == 0 {
            pin.to_string()
        } else {
            format!("B.{pin}")
        };
        let ok = self
            .sim
            .try_update_value(|s| {
                let m = s.machine_mut();
                let device = m.device(&name)?;
                m.apply(Command::SetInput(device, value))
            })
            .is_some_and(|r| r.is_ok());
        self.refresh();
        ok
    }

    /// Copies both devices into the signals that changed.
    pub fn refresh(&self) {
        self.sim.with_value(|s| {
            let mut front = Front::none();
            s.machine().front_into(&mut front);
            if let Some([a, b]) = front.get::<Fronts>() {
                self.devices[0].sync(a);
                self.devices[1].sync(b);
            }
        });
    }

    /// Parses device `i`'s pane and, if good, loads it and runs it from
    /// the first scan; the errors (by line) go to the pane either way.
    pub fn load(&self, i: usize) -> bool {
        let text = self.texts[i].get_untracked();
        if let Err(errors) = Program::parse(&text) {
            self.errors[i].set(
                errors
                    .iter()
                    .map(|e| (e.line, e.error.to_string()))
                    .collect(),
            );
            return false;
        }
        self.errors[i].set(Vec::new());
        let loaded = self.sim.try_update_value(|s| {
            let m = s.machine_mut();
            if i == 0 {
                m.apply(Command::Run(false))?;
                m.load_text(&text)?;
                m.apply(Command::Run(true))
            } else {
                m.apply(Command::Own(Own::new(LoadLinked(text))))
            }
        });
        self.refresh();
        loaded.is_some_and(|r| r.is_ok())
    }

    /// Types a line at device A's terminal.
    pub fn type_line(&self, line: &str) {
        let reply = self
            .sim
            .try_update_value(|s| s.machine_mut().serial(line).unwrap_or_default())
            .unwrap_or_default();
        crate::chrome::console::append(self.console, &reply);
        self.refresh();
    }

    /// Saves both program texts.
    pub fn save(&self) {
        let saved = SavedIo86a {
            programs: [self.texts[0].get_untracked(), self.texts[1].get_untracked()],
        };
        storage::save_to(IO86A_KEY, &saved);
    }
}

impl Default for Io86aCtx {
    fn default() -> Self {
        Io86aCtx::new()
    }
}

crate::parts::part_fn!(
    io86a,
    /// PLC-IO86A arrives as a part of its own (issue #53): its engine,
    /// its compiler and its panels, fetched when it is first shown.
    pub(crate) fn arrive(
        _page: crate::state::Ctx,
        ladder: crate::editor::LadderCtx,
    ) -> Result<crate::machines::workspace::Shared, crate::parts::PartMissing> {
        engine::machines::register(engine::machines::MachineKit::IO86A);
        let io = Io86aCtx::new();
        crate::machines::workspace::wire(
            ladder,
            crate::machines::link(io.sim, move |_| io.refresh()),
            crate::machines::text_program(io.texts[0], move || io.load(0), move || io.save()),
        );
        Ok(std::rc::Rc::new(io))
    }
);

impl crate::machines::workspace::MachineWorkspace for Io86aCtx {
    fn panel(&self) -> leptos::prelude::AnyView {
        use leptos::prelude::*;
        // Its views below find it as a context.
        provide_context(*self);
        view! { <view::Io86aPanel io=*self /> }.into_any()
    }

    fn program(&self) -> leptos::prelude::AnyView {
        use leptos::prelude::*;
        provide_context(*self);
        view! { <view::Io86aProgram io=*self /> }.into_any()
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
