//! The Arduino PLC workspace: the board's PD2-PD7 inputs and PB0-PB5
//! outputs, the serial monitor, and the program pane in the sketch's
//! mnemonic text.

use engine::arduino::{Chip, Program};
use engine::events::InputValue;
use engine::machines::ArduinoPlc;
use engine::plc::Warning;
use engine::plc::{Command, Device, Plc};
use leptos::prelude::*;

use crate::chrome::console::ConsolePane;
use crate::chrome::controls::Led;
use crate::chrome::text_program::TextProgramPane;
use crate::sim::Simulator;
use crate::state::put;
use crate::state::Ctx;
use crate::storage;

/// The seed's self-holding example, the text a fresh workspace opens with.
pub const SELF_HOLD: &str = include_str!("../../../engine/programs/arduino-plc/self-hold.txt");

/// Where the workspace is saved (`SavedText`), and where an earlier
/// version kept the plain text.
const KEY: &str = "hashigo.arduino-plc.v2";
const LEGACY_KEY: &str = "hashigo.arduino-plc.v1";

/// What the Arduino workspace's components share.
#[derive(Clone, Copy)]
pub struct ArduinoCtx {
    pub sim: StoredValue<Simulator<ArduinoPlc>, LocalStorage>,
    /// X000-X005 and Y000-Y005, resolved once.
    pins: [[Device; 6]; 2],
    pub inputs: [RwSignal<bool>; 6],
    pub outputs: [RwSignal<bool>; 6],
    pub enabled: RwSignal<bool>,
    pub sketch_quirk: RwSignal<bool>,
    pub console: RwSignal<String>,
    pub text: RwSignal<String>,
}

impl ArduinoCtx {
    /// A workspace on `page` with its saved text loaded (or the seed's
    /// example); a saved value that does not read is kept aside and
    /// reported in the page's notice.
    pub fn restore(page: Ctx) -> ArduinoCtx {
        let text = crate::machines::restored_text(page, KEY, LEGACY_KEY, SELF_HOLD);
        let plc = ArduinoPlc::new();
        // The pin names are the machine's own: they always resolve.
        let pin = |name: String| plc.device(&name).unwrap_or_else(|_| unreachable!("{name}"));
        let pins = [
            std::array::from_fn(|n| pin(format!("X{n:03}"))),
            std::array::from_fn(|n| pin(format!("Y{n:03}"))),
        ];
        let ctx = ArduinoCtx {
            sim: StoredValue::new_local(Simulator::new(plc)),
            pins,
            inputs: std::array::from_fn(|_| RwSignal::new(false)),
            outputs: std::array::from_fn(|_| RwSignal::new(false)),
            enabled: RwSignal::new(false),
            sketch_quirk: RwSignal::new(false),
            console: RwSignal::new(String::new()),
            text: RwSignal::new(text),
        };
        ctx.load();
        ctx
    }

    /// Copies the pins into the signals that changed.
    pub fn refresh(&self) {
        self.sim.with_value(|s| {
            let m = s.machine();
            for n in 0..6 {
                put(self.inputs[n], m.read(self.pins[0][n]).is_on());
                put(self.outputs[n], m.read(self.pins[1][n]).is_on());
            }
            put(self.enabled, m.running());
        });
    }

    /// Saves the program text.
    pub fn save(&self) {
        let program = self.text.get_untracked();
        storage::save_to(KEY, &storage::SavedText { program });
    }

    /// Writes the pane's program into EEPROM (as keying it in with `s`)
    /// and enables the PLC; false if it has errors.
    pub fn load(&self) -> bool {
        let text = self.text.get_untracked();
        let quirk = if self.sketch_quirk.get_untracked() {
            "sketch"
        } else {
            "none"
        };
        // Written into EEPROM, then started afresh (the pins as driven stay).
        let loaded = self
            .sim
            .try_update_value(|s| {
                let m = s.machine_mut();
                m.load_text(&text)?;
                m.apply(Command::Setting {
                    name: "quirk".into(),
                    value: quirk.into(),
                })?;
                m.apply(Command::PowerCycle)?;
                m.apply(Command::Run(true))?;
                s.power_cycled();
                Ok::<(), engine::plc::PlcError>(())
            })
            .is_some_and(|r| r.is_ok());
        self.refresh();
        loaded
    }

    /// Drives input X00n.
    pub fn drive(&self, n: usize, on: bool) {
        let input = self.pins[0][n];
        self.sim.update_value(|s| {
            // X000-X005 take 0 and 1: the command cannot be refused.
            let _ = s
                .machine_mut()
                .apply(Command::SetInput(input, InputValue::Int(i64::from(on))));
        });
        self.refresh();
    }

    /// Types a line at the serial monitor.
    pub fn type_line(&self, line: &str) {
        let reply = self
            .sim
            .try_update_value(|s| s.machine_mut().serial(line).unwrap_or_default())
            .unwrap_or_default();
        crate::chrome::console::append(self.console, &reply);
        self.refresh();
    }
}

/// The Arduino's panel: its pins, the sketch's quirk and its serial
/// monitor (the panel dock).
#[component]
pub fn ArduinoPanel(ard: ArduinoCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <div class="workspace arduino">
            <section class="device arduino-board">
                <h2>
                    "Arduino (ATmega328) · "
                    <span data-testid="arduino-state">
                        {move || if ard.enabled.get() { t().enabled } else { t().disabled }}
                    </span>
                </h2>
                <Pins ard=ard />
                <label class="quirk">
                    <input
                        type="checkbox"
                        data-testid="arduino-quirk"
                        prop:checked=move || ard.sketch_quirk.get()
                        on:change=move |_| {
                            ard.sketch_quirk.update(|q| *q = !*q);
                            ard.load();
                        }
                    />
                    {move || t().quirk_sketch}
                </label>
            </section>
            <ConsolePane
                title=Signal::derive(move || t().monitor.to_string())
                hint=Signal::derive(move || t().monitor_hint.to_string())
                testid="arduino-monitor"
                console=ard.console
                on_line=Callback::new(move |line: String| ard.type_line(&line))
            />
        </div>
    }
}

/// The Arduino's program text (the tools dock's Program tab).
#[component]
pub fn ArduinoProgram(ard: ArduinoCtx) -> impl IntoView {
    view! { <ProgramPane ard=ard /> }
}

/// PD2-PD7 as input switches, PB0-PB5 as lamps.
#[component]
fn Pins(ard: ArduinoCtx) -> impl IntoView {
    let inputs = (0..6u8)
        .map(|n| {
            let on = ard.inputs[usize::from(n)];
            view! {
                <div class="pin">
                    <span class="pin-name">{format!("PD{}", n + 2)}</span>
                    <button
                        type="button"
                        class="input-switch small"
                        class:on=move || on.get()
                        data-testid=format!("arduino-input-X{n:03}")
                        aria-pressed=move || on.get().to_string()
                        on:click=move |_| {
                            let v = !on.get_untracked();
                            ard.drive(usize::from(n), v);
                        }
                    >
                        {format!("X{n:03}")}
                    </button>
                </div>
            }
        })
        .collect_view();
    let outputs = (0..6usize)
        .map(|n| {
            view! {
                <div class="pin">
                    <span class="pin-name">{format!("PB{n}")}</span>
                    <span class="pin-lamp">
                        <Led
                            on=ard.outputs[n]
                            testid=format!("arduino-lamp-Y{n:03}")
                            colour="amber"
                            label=format!("Y{n:03}")
                        />
                        {format!("Y{n:03}")}
                    </span>
                </div>
            }
        })
        .collect_view();
    view! {
        <div class="arduino-pins">
            <div class="pins">{inputs}</div>
            <div class="pins">{outputs}</div>
        </div>
    }
}

/// The program pane in the sketch's mnemonic text.
#[component]
fn ProgramPane(ard: ArduinoCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    // Errors by line, or whether the program can run into erased EEPROM
    // (no END and no JUMP: it spins at step 255).
    let parsed = Memo::new(move |_| {
        Program::parse(&ard.text.get(), Chip::Atmega328.capacity())
            .map(|p| engine::arduino::warnings(p.words()).contains(&Warning::RunsIntoErasedEeprom))
            .map_err(|e| {
                // In the page's language, again when it changes (issue #49).
                let lang = ctx.lang.get();
                e.iter()
                    .map(|e| (e.line, crate::i18n::errors::arduino_asm(lang, &e.error)))
                    .collect::<Vec<_>>()
            })
    });
    view! {
                <TextProgramPane
                    as_ladder=true
                    prefix="arduino-"
                    text=ard.text
                    errors=Signal::derive(move || parsed.get().err().unwrap_or_default())
                    on_edit=Callback::new(|program: String| {
                        storage::save_to(KEY, &storage::SavedText { program });
                    })
                    on_load=Callback::new(move |()| {
                        ard.load();
                    })
                    warning=Signal::derive(move || {
                        (parsed.get() == Ok(true)).then(|| t().warn_spin.to_string())
                    })
                />
    }
}

crate::parts::part_fn!(
    arduino_plc,
    /// The Arduino PLC arrives as a part of its own (issue #53): its
    /// engine, its compiler and its panel, fetched when it is first shown.
    pub(crate) fn arrive(
        page: Ctx,
        ladder: crate::editor::LadderCtx,
    ) -> Result<crate::machines::workspace::Shared, crate::parts::PartMissing> {
        engine::machines::register(engine::machines::MachineKit::ARDUINO);
        let ard = ArduinoCtx::restore(page);
        crate::machines::workspace::wire(
            ladder,
            crate::machines::link(ard.sim, move |_| ard.refresh()),
            crate::machines::text_program(ard.text, move || ard.load(), move || ard.save()),
        );
        Ok(std::rc::Rc::new(ard))
    }
);

impl crate::machines::workspace::MachineWorkspace for ArduinoCtx {
    fn panel(&self) -> AnyView {
        view! { <ArduinoPanel ard=*self /> }.into_any()
    }

    fn program(&self) -> AnyView {
        view! { <ArduinoProgram ard=*self /> }.into_any()
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
