//! The soft PLC workspace (issue #31): a board built from the I/O its
//! program names — a switch and a push button for each `%IX` input, a
//! lamp for each `%QX` output, a slider for each word input, a gauge for
//! each word output, a segment digit for each variable an LDmicro
//! `7SEGMENTS` … `16SEGMENTS` writes — beside the variables pane and the program pane in
//! Instruction List. The bits `%IX0.0–%IX0.7` and `%QX0.0–%QX0.7` are
//! always on the board (a small PLC's 8 in / 8 out), so a new ladder has
//! something to wire to; a program's other I/O is added after them.

use engine::events::InputValue;
use engine::iec::{Address, Area, Size};
use engine::machines::SoftPlc;
use engine::plc::{Command, Device, Plc};
use leptos::prelude::*;

use crate::chrome::console::ConsolePane;
use crate::sim::Simulator;
use crate::state::{put, Ctx};
use crate::storage;

mod rows;
pub mod st;
mod st_complete;
mod st_lex;
mod st_online;
mod st_pane;
use rows::{Digits, GaugeRow, LampRow, ScanSetting, SliderRow, SwitchRow};
use st_pane::SoftProgram;

/// Where the workspace's program is saved (`SavedText`); nothing was
/// ever saved under the legacy key.
pub(super) const KEY: &str = "hashigo.soft-plc.v1";
const LEGACY_KEY: &str = "hashigo.soft-plc.v0";
/// Where the scan period is saved (as the engine's setting reads it,
/// `5000us`); absent for the default 10 ms.
const SCAN_KEY: &str = "hashigo.soft-plc.scan.v1";

/// The cyclic task's period on a fresh workspace, in µs.
pub const DEFAULT_SCAN_US: u64 = 10_000;

/// The most a slider reaches: a 10-bit converter's top (any value of the
/// input's type can be typed in its box).
pub const SLIDER_MAX: i64 = 1023;

/// What a terminal on the board is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TerminalKind {
    /// A `%IX` input: a switch and a push button.
    Switch,
    /// A `%QX` output: a lamp.
    Lamp,
    /// A word input (`%IW`, `%IB`, `%ID`, `%IL`): a slider.
    Slider,
    /// A word output: a gauge.
    Gauge,
}

impl TerminalKind {
    /// The kind of terminal `a` is; `None` for memory.
    pub fn of(a: Address) -> Option<TerminalKind> {
        match (a.area, a.size == Size::Bit) {
            (Area::Input, true) => Some(TerminalKind::Switch),
            (Area::Output, true) => Some(TerminalKind::Lamp),
            (Area::Input, false) => Some(TerminalKind::Slider),
            (Area::Output, false) => Some(TerminalKind::Gauge),
            (Area::Memory, _) => None,
        }
    }
}

/// The test hook's form of an address: `%IX0.0` → `IX0-0`.
pub fn hook(address: &str) -> String {
    address.trim_start_matches('%').replace('.', "-")
}

/// The board's addresses: the default 8 in / 8 out, then the program's
/// other inputs and outputs in their order of first use.
pub fn board_addresses(program_io: impl Iterator<Item = Address>) -> Vec<Address> {
    let bit = |area, n| Address {
        area,
        size: Size::Bit,
        index: 0,
        bit: Some(n),
    };
    let mut out: Vec<Address> = (0..8)
        .map(|n| bit(Area::Input, n))
        .chain((0..8).map(|n| bit(Area::Output, n)))
        .collect();
    for a in program_io {
        if TerminalKind::of(a).is_some() && !out.contains(&a) {
            out.push(a);
        }
    }
    out
}

/// One terminal and its signals.
#[derive(Clone)]
pub struct Terminal {
    /// As IEC writes it (`%IX0.0`).
    pub address: String,
    /// The variable declared at it, if any.
    pub name: String,
    pub kind: TerminalKind,
    /// Its handle on the machine (`None` while the program does not use it).
    pub device: Option<Device>,
    /// Its value on the machine (1/0 for bits).
    pub value: RwSignal<i64>,
    /// What the board drives an input to (kept over a new program).
    pub driven: RwSignal<i64>,
    /// A push button held.
    pub held: RwSignal<bool>,
}

/// A segment digit on the board, wired to a variable an LDmicro
/// `7SEGMENTS` … `16SEGMENTS` writes.
#[derive(Clone)]
pub struct DigitRow {
    /// The variable.
    pub name: String,
    /// 7, 9, 14 or 16.
    pub segments: u8,
    /// Common anode: a segment lights when its bit is 0.
    pub anode: bool,
    pub device: Option<Device>,
    /// The variable's value on the machine.
    pub value: RwSignal<i64>,
}

/// What the soft PLC workspace's components share.
#[derive(Clone, Copy)]
pub struct SoftCtx {
    pub sim: StoredValue<Simulator<SoftPlc>, LocalStorage>,
    pub terminals: RwSignal<Vec<Terminal>>,
    /// The digits the program's `7SEGMENTS` blocks drive.
    pub digits: RwSignal<Vec<DigitRow>>,
    pub text: RwSignal<String>,
    /// The serial monitor, shown while the program uses the UART.
    pub serial: RwSignal<bool>,
    pub console: RwSignal<String>,
    /// Bytes of the port's output the console shows.
    console_seen: StoredValue<u64>,
    /// The cyclic task's period in µs (an LDmicro file's `CYCLE=`).
    pub scan_us: RwSignal<u64>,
    /// The Structured Text pane and program (issue #55).
    pub st: st::StState,
}

impl SoftCtx {
    /// A workspace on `page` with its saved program loaded (a fresh one
    /// has none: the default board and an empty ladder).
    pub fn restore(page: Ctx) -> SoftCtx {
        let text = crate::machines::restored_text(page, KEY, LEGACY_KEY, "");
        let ctx = SoftCtx {
            sim: StoredValue::new_local(Simulator::new(SoftPlc::new())),
            terminals: RwSignal::new(Vec::new()),
            digits: RwSignal::new(Vec::new()),
            text: RwSignal::new(text),
            serial: RwSignal::new(false),
            console: RwSignal::new(String::new()),
            console_seen: StoredValue::new(0),
            scan_us: RwSignal::new(DEFAULT_SCAN_US),
            st: st::StState::restore(page),
        };
        if let Some(saved) = storage::saved_string(SCAN_KEY) {
            if let Err(e) = ctx.set_scan(&saved) {
                page.notice.set(Some(format!("{SCAN_KEY}: {e}")));
            }
        }
        if !ctx.load() {
            ctx.rebuild();
        }
        ctx
    }

    /// Sets the cyclic task's period (`5ms`, `5000us`: as the engine's
    /// `scan` setting reads it) and saves it; the machine's refusal
    /// leaves it as it was.
    pub fn set_scan(&self, value: &str) -> Result<(), String> {
        self.sim
            .try_update_value(|s| {
                s.machine_mut().apply(Command::Setting {
                    name: "scan".into(),
                    value: value.into(),
                })
            })
            .unwrap_or(Ok(()))
            .map_err(|e| e.to_string())?;
        let us = self.sim.with_value(|s| {
            let period = s.machine().shown_machine().machine().scan_period();
            period.as_nanos() / 1000
        });
        self.scan_us.set(us);
        if us == DEFAULT_SCAN_US {
            storage::remove(SCAN_KEY);
        } else {
            storage::save_string(SCAN_KEY, &format!("{us}us"));
        }
        Ok(())
    }

    /// The settings a project keeps: the scan period when it is not
    /// the default.
    pub fn project_settings(&self) -> Vec<(String, String)> {
        let us = self.scan_us.get_untracked();
        if us == DEFAULT_SCAN_US {
            Vec::new()
        } else {
            vec![("scan".into(), format!("{us}us"))]
        }
    }

    /// Applies a project's settings; returns the refusals, each named.
    pub fn apply_project_settings(&self, settings: Vec<(String, String)>) -> Vec<String> {
        settings
            .into_iter()
            .filter_map(|(name, value)| {
                let done = if name.trim().eq_ignore_ascii_case("scan") {
                    self.set_scan(&value)
                } else {
                    Err("the soft PLC's only setting is scan".into())
                };
                done.err().map(|e| format!("{name}={value}: {e}"))
            })
            .collect()
    }

    /// Copies the terminals' values into the signals that changed, and
    /// what the serial port sent since into the console.
    pub fn refresh(&self) {
        self.sim.with_value(|s| {
            self.terminals.with_untracked(|ts| {
                for t in ts {
                    if let Some(d) = t.device {
                        put(t.value, s.machine().read(d).as_i64());
                    }
                }
            });
            self.digits.with_untracked(|ds| {
                for d in ds {
                    if let Some(device) = d.device {
                        put(d.value, s.machine().read(device).as_i64());
                    }
                }
            });
            let seen = self.console_seen.get_value();
            let mut sent = String::new();
            let total = s.machine().serial_sent(seen, &mut sent);
            if total < seen {
                // Travelled back, or powered up anew: the port's own copy.
                sent.clear();
                s.machine().serial_sent(0, &mut sent);
                self.console.set(String::new());
            }
            if !sent.is_empty() {
                crate::chrome::console::append(self.console, &sent);
            }
            self.console_seen.set_value(total);
        });
        self.st.refresh(self.sim);
    }

    /// Types `line` at the serial port (an empty line: the Enter key); a
    /// refusal (a character that is no byte) is shown in the console.
    pub fn type_line(&self, line: &str) {
        let typed = self
            .sim
            .try_update_value(|s| s.machine_mut().serial(line))
            .unwrap_or(Ok(String::new()));
        if let Err(e) = typed {
            crate::chrome::console::append(self.console, &format!("\n[{e}]\n"));
        }
        self.refresh();
    }

    /// Saves the program text.
    pub fn save(&self) {
        let program = self.text.get_untracked();
        storage::save_to(KEY, &storage::SavedText { program });
    }

    /// Loads the pane's program (from power-up), in the pane's language;
    /// false if it has errors. The board follows its I/O; what the board
    /// drives stays driven.
    pub fn load(&self) -> bool {
        let loaded = if self.st.runs() {
            self.st.load(self.sim)
        } else {
            let text = self.text.get_untracked();
            self.st.forget(self.sim);
            let loaded = self
                .sim
                .try_update_value(|s| s.machine_mut().load_text(&text))
                .is_some_and(|r| r.is_ok());
            if loaded {
                // The ST blocks it calls, followed in the ST pane.
                self.st.load_ladder(self.sim, &text);
            }
            loaded
        };
        if loaded {
            self.rebuild();
        }
        loaded
    }

    /// The board for the program loaded: a terminal named again keeps
    /// its row and signals (the `<For>` is keyed by address and name), its
    /// driven level applied to the new program.
    fn rebuild(&self) {
        let old = self.terminals.get_untracked();
        let rows = self.sim.with_value(|s| {
            let plc = s.machine();
            let program = plc.shown_machine().machine().program();
            let named = |a: Address| {
                program
                    .source()
                    .0
                    .iter()
                    .find(|v| v.address == Some(a))
                    .map_or(String::new(), |v| v.name.clone())
            };
            put(self.serial, program.uses_serial());
            let digits: Vec<DigitRow> = program
                .segment_displays()
                .into_iter()
                .map(|d| DigitRow {
                    device: plc.device(&d.name).ok(),
                    name: d.name,
                    segments: d.segments,
                    anode: d.anode,
                    value: RwSignal::new(0),
                })
                .collect();
            self.digits.set(digits);
            board_addresses(program.io())
                .into_iter()
                .filter_map(|a| {
                    let kind = TerminalKind::of(a)?;
                    let address = a.to_string();
                    let device = plc.device(&address).ok();
                    let name = named(a);
                    let before = old.iter().find(|t| t.address == address);
                    Some(match before {
                        Some(t) if t.name == name => Terminal {
                            device,
                            ..t.clone()
                        },
                        // Named anew: a new row (its label changes), at
                        // the level the board drove it to.
                        _ => Terminal {
                            address,
                            name,
                            kind,
                            device,
                            value: RwSignal::new(0),
                            driven: RwSignal::new(before.map_or(0, |t| t.driven.get_untracked())),
                            held: RwSignal::new(false),
                        },
                    })
                })
                .collect::<Vec<_>>()
        });
        for t in &rows {
            let level = t.driven.get_untracked();
            if level != 0 {
                // Taken before by an input of this address and type; a
                // new type that refuses it leaves the input at zero.
                let _ = self.drive_device(t.device, level);
            }
        }
        self.terminals.set(rows);
        self.refresh();
    }

    /// Sets `device` to `level`; the machine's refusal (a value its type
    /// does not hold) if it refuses.
    fn drive_device(&self, device: Option<Device>, level: i64) -> Result<(), String> {
        let Some(device) = device else {
            return Ok(());
        };
        self.sim
            .try_update_value(|s| {
                s.machine_mut()
                    .apply(Command::SetInput(device, InputValue::Int(level)))
            })
            .unwrap_or(Ok(()))
            .map_err(|e| e.to_string())
    }

    /// The machine's handle of the terminal at `address` now (a row's
    /// copy keeps the handle of the program it was made for).
    fn device_of(&self, address: &str) -> Option<Device> {
        self.terminals.with_untracked(|ts| {
            ts.iter()
                .find(|t| t.address == address)
                .and_then(|t| t.device)
        })
    }

    /// Drives input `t` to `level` (the switch, a slider); a value the
    /// input's type does not hold is refused, the input left as it was.
    pub fn drive(&self, t: &Terminal, level: i64) -> Result<(), String> {
        let held = i64::from(t.held.get_untracked());
        let done = self.drive_device(self.device_of(&t.address), level | held);
        if done.is_ok() {
            t.driven.set(level);
        }
        self.refresh();
        done
    }

    /// A push button pressed or released: the input is on while it is
    /// held or while its switch is on.
    pub fn push(&self, t: &Terminal, held: bool) {
        t.held.set(held);
        let level = i64::from(held) | t.driven.get_untracked();
        // A bit takes 0 and 1: never refused.
        let _ = self.drive_device(self.device_of(&t.address), level);
        self.refresh();
    }
}

/// The soft PLC's panel: its board, built from the program's I/O, and
/// the serial monitor while the program uses a UART.
#[component]
pub fn SoftPanel(soft: SoftCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let of = move |kind: TerminalKind| {
        move || {
            soft.terminals
                .get()
                .into_iter()
                .filter(|t| t.kind == kind)
                .collect::<Vec<_>>()
        }
    };
    view! {
        <div class="workspace soft">
            <section class="device soft-board" data-testid="soft-board">
                <h2>{move || t().soft_board}</h2>
                <ScanSetting soft />
                <div class="soft-io">
                    <ul class="soft-inputs">
                        <For each=of(TerminalKind::Switch) key=|t| (t.address.clone(), t.name.clone())
                            children=move |term| view! { <SwitchRow soft term /> } />
                    </ul>
                    <ul class="soft-outputs">
                        <For each=of(TerminalKind::Lamp) key=|t| (t.address.clone(), t.name.clone())
                            children=move |term| view! { <LampRow term /> } />
                    </ul>
                </div>
                <ul class="soft-analog">
                    <For each=of(TerminalKind::Slider) key=|t| (t.address.clone(), t.name.clone())
                        children=move |term| view! { <SliderRow soft term /> } />
                    <For each=of(TerminalKind::Gauge) key=|t| (t.address.clone(), t.name.clone())
                        children=move |term| view! { <GaugeRow term /> } />
                </ul>
                <Digits soft />
            </section>
            <Show when=move || soft.serial.get()>
                <ConsolePane
                    title=Signal::derive(move || t().monitor.to_string())
                    hint=Signal::derive(move || t().soft_monitor_hint.to_string())
                    testid="soft-monitor"
                    console=soft.console
                    on_line=Callback::new(move |line: String| soft.type_line(&line))
                />
            </Show>
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn addr(text: &str) -> Address {
        Address::parse(text).expect(text)
    }

    #[test]
    fn the_board_is_the_default_eight_and_eight_then_the_programs_own() {
        let board = board_addresses(
            ["%IX0.3", "%MW0", "%IW0", "%IX2.1", "%QW1", "%QX0.0"]
                .into_iter()
                .map(addr),
        );
        let names: Vec<String> = board.iter().map(|a| a.to_string()).collect();
        assert_eq!(names.len(), 19, "{names:?}");
        assert_eq!(names[0], "%IX0.0");
        assert_eq!(names[15], "%QX0.7");
        assert_eq!(names[16..], ["%IW0", "%IX2.1", "%QW1"], "memory left out");
        let kinds: Vec<_> = board[16..]
            .iter()
            .filter_map(|a| TerminalKind::of(*a))
            .collect();
        assert_eq!(
            kinds,
            [
                TerminalKind::Slider,
                TerminalKind::Switch,
                TerminalKind::Gauge
            ]
        );
        assert_eq!(hook("%IX0.0"), "IX0-0");
        assert_eq!(hook("%IW0"), "IW0");
    }
}

crate::parts::part_fn!(
    soft_plc,
    /// The soft PLC arrives as a part of its own (issue #53): its engine
    /// (IEC, IL, LDmicro's blocks), its compiler and its panel, fetched
    /// when it is first shown.
    pub(crate) fn arrive(
        page: Ctx,
        ladder: crate::editor::LadderCtx,
    ) -> Result<crate::machines::workspace::Shared, crate::parts::PartMissing> {
        engine::machines::register(engine::machines::MachineKit::SOFT);
        let soft = SoftCtx::restore(page);
        // Before the ladder is checked (`wire`): its boxes of ST blocks.
        soft.st.attach(ladder);
        let mut program =
            crate::machines::text_program(soft.text, move || soft.load(), move || soft.save());
        program.settings = Callback::new(move |()| soft.project_settings());
        program.apply_settings =
            Callback::new(move |settings| soft.apply_project_settings(settings));
        program.source = Callback::new(move |()| soft.st.source());
        program.apply_source = Callback::new(move |source| soft.st.take_source(source, soft.sim));
        program.why_st = Callback::new(move |(kind, instance): (String, String)| {
            soft.st.why_box(&kind, &instance, soft.sim)
        });
        crate::machines::workspace::wire(
            ladder,
            crate::machines::link(soft.sim, move |_| soft.refresh()),
            program,
        );
        Ok(std::rc::Rc::new(soft))
    }
);

impl crate::machines::workspace::MachineWorkspace for SoftCtx {
    fn panel(&self) -> AnyView {
        view! { <SoftPanel soft=*self /> }.into_any()
    }

    fn program(&self) -> AnyView {
        view! { <SoftProgram soft=*self /> }.into_any()
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }

    /// A `.st` file: its text in the program pane, in ST, not loaded
    /// until Load or Run (as a text typed there).
    fn open_text(&self, _file: &str, text: &str) -> bool {
        self.st.open(text, self.sim);
        true
    }
}
