//! The AVR simplified PLC workspace: the bits the source names (`NAME_R` /
//! `NAME_B`) as switches and lamps, and the program pane in assembler.

use engine::avr::machine::DEFAULT_SCAN;
use engine::avr::{scan_ms, BitRef, Program};
use engine::events::InputValue;
use engine::machines::AvrPlc;
use engine::plc::{Command, Device, Plc, Warning};
use leptos::prelude::*;

use crate::chrome::controls::Led;
use crate::chrome::text_program::TextProgramPane;
use crate::editor::on_screen::{self, Due};
use crate::sim::Simulator;
use crate::state::Ctx;
use crate::storage;

/// The seed's self-holding rungs (with End_PLC), the text a fresh
/// workspace opens with.
pub const SELF_HOLD: &str = include_str!("../../../engine/programs/avr-plc/self-hold.asm");

/// Where the workspace is saved (`SavedText`), and where an earlier
/// version kept the plain text.
const KEY: &str = "hashigo.avr-plc.v2";
const LEGACY_KEY: &str = "hashigo.avr-plc.v1";

/// A named bit and its signals.
#[derive(Clone)]
pub struct NamedBit {
    pub name: String,
    pub bit: BitRef,
    /// The bit's handle in the machine.
    pub device: Device,
    pub value: RwSignal<bool>,
    pub driven: RwSignal<Option<bool>>,
}

/// What the AVR workspace's components share.
#[derive(Clone, Copy)]
pub struct AvrCtx {
    pub sim: StoredValue<Simulator<AvrPlc>, LocalStorage>,
    pub bits: RwSignal<Vec<NamedBit>>,
    pub text: RwSignal<String>,
    /// The lamps' rows, for [`Self::refresh`] to bring those on screen up
    /// to date every frame and the others in turn.
    rows: NodeRef<leptos::html::Tbody>,
}

impl AvrCtx {
    /// A workspace on `page` with its saved text loaded (or the seed's
    /// example); a saved value that does not read is kept aside and
    /// reported in the page's notice.
    pub fn restore(page: Ctx) -> AvrCtx {
        let text = crate::machines::restored_text(page, KEY, LEGACY_KEY, SELF_HOLD);
        let ctx = AvrCtx {
            sim: StoredValue::new_local(Simulator::new(AvrPlc::new())),
            bits: RwSignal::new(Vec::new()),
            text: RwSignal::new(text),
            rows: NodeRef::new(),
        };
        ctx.load();
        ctx
    }

    /// Copies the named bits into their signals (only those that changed).
    /// In a running frame of `turn`, the lamps on screen, the others in
    /// turn (`crate::editor::on_screen`): a program naming 248 bits that
    /// all change each frame cost the frame its display rate (issue #52).
    pub fn refresh(&self, turn: Option<u64>) {
        let due = Due::of(turn, || self.rows_shown());
        self.sim.with_value(|s| {
            self.bits.with_untracked(|bits| {
                for (i, b) in bits.iter().enumerate() {
                    if !due.covers(i) {
                        continue;
                    }
                    let v = s.machine().read(b.device).is_on();
                    if b.value.get_untracked() != v {
                        b.value.set(v);
                    }
                }
            });
        });
    }

    /// The rows the panel's scrolling dock shows now (none when it
    /// cannot be measured).
    fn rows_shown(&self) -> Option<std::ops::Range<usize>> {
        let rows = self.rows.get_untracked()?;
        let view = rows.closest(".dock-right").ok().flatten();
        let all = rows.query_selector_all(":scope > tr").ok()?;
        on_screen::shown_in(view.as_ref().unwrap_or(&rows), &all)
    }

    /// Saves the program text.
    pub fn save(&self) {
        let program = self.text.get_untracked();
        storage::save_to(KEY, &storage::SavedText { program });
    }

    /// Assembles the pane's text (with `Scan` = the machine's scan
    /// period) and, if good, runs it from power-up (timer words cleared);
    /// false if it has errors.
    ///
    /// A bit the new program names again keeps its row, its signals and
    /// the level it is driven to: the keyed `<For>` keeps such a row, so
    /// giving it new signals would leave its lamp and switch bound to the
    /// old ones. A bit no longer named stops being driven.
    pub fn load(&self) -> bool {
        let text = self.text.get_untracked();
        let Ok(program) = Program::parse(&text, scan()) else {
            return false;
        };
        let old = self.bits.get_untracked();
        let loaded = self
            .sim
            .try_update_value(|s| {
                let machine = s.machine_mut();
                machine.load_text(&text)?;
                for gone in old
                    .iter()
                    .filter(|o| !program.names().iter().any(|(_, b)| *b == o.bit))
                {
                    machine.apply(Command::ReleaseInput(gone.device))?;
                }
                Ok::<_, engine::plc::PlcError>(rows_for(&old, &program.bits_in_use(), machine))
            })
            .and_then(Result::ok);
        let Some(rows) = loaded else {
            return false;
        };
        self.bits.set(rows);
        self.refresh(None);
        true
    }

    /// Drives (or releases) a named bit.
    pub fn drive(&self, device: Device, on: Option<bool>) {
        self.sim.update_value(|s| {
            let command = match on {
                Some(on) => Command::SetInput(device, InputValue::Int(i64::from(on))),
                None => Command::ReleaseInput(device),
            };
            // A named bit takes 0 and 1: the command cannot be refused.
            let _ = s.machine_mut().apply(command);
        });
        self.refresh(None);
    }
}

/// The `Scan` symbol the page's AVR runs with (its default scan period).
fn scan() -> i64 {
    i64::from(scan_ms_default())
}

/// The page's AVR scan period in ms (what the ladder compiles for).
pub fn scan_ms_default() -> u32 {
    scan_ms(DEFAULT_SCAN).unwrap_or(10)
}

/// The rows for a program's bits (named, or used by a ladder compiled
/// without names: `R0.0`): an old row whose name and bit
/// are named again is kept as it is (same signals), the others are new;
/// each row's device is resolved by `plc` once.
fn rows_for(old: &[NamedBit], names: &[(String, BitRef)], plc: &dyn Plc) -> Vec<NamedBit> {
    names
        .iter()
        .filter_map(|(name, bit)| {
            if let Some(row) = old.iter().find(|o| &o.name == name && o.bit == *bit) {
                return Some(row.clone());
            }
            Some(NamedBit {
                name: name.clone(),
                bit: *bit,
                device: plc.device(name).ok()?,
                value: RwSignal::new(false),
                driven: RwSignal::new(None),
            })
        })
        .collect()
}

/// The AVR PLC's panel: every named bit as a lamp and a switch.
#[component]
pub fn AvrPanel(avr: AvrCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    view! {
        <div class="workspace avr">
            <section class="device avr-bits">
                <h2>"AVR · " {move || t().bits}</h2>
                <table class="bits">
                    <tbody node_ref=avr.rows>
                        <For
                            each=move || avr.bits.get()
                            key=|b| (b.name.clone(), b.bit.register, b.bit.bit)
                            children=move |b: NamedBit| view! { <BitRow avr b /> }
                        />
                    </tbody>
                </table>
            </section>
        </div>
    }
}

/// The AVR PLC's program text (the tools dock's Program tab).
#[component]
pub fn AvrProgram(avr: AvrCtx) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    // Errors by line, or whether the program has a TOF (on after power-up).
    let parsed = Memo::new(move |_| {
        Program::parse(&avr.text.get(), scan())
            .map(|p| engine::avr::warnings(&p).contains(&Warning::TofOnAtPowerUp))
            .map_err(|e| {
                // In the page's language, again when it changes (issue #49).
                let lang = ctx.lang.get();
                e.iter()
                    .map(|e| (e.line, crate::i18n::errors::avr_program(lang, &e.error)))
                    .collect::<Vec<_>>()
            })
    });
    // The pane's Load starts the program loaded (the ladder's machine).
    let ladder = use_context::<crate::editor::LadderCtx>();
    view! {
        <TextProgramPane
            as_ladder=true
            prefix="avr-"
            text=avr.text
            errors=Signal::derive(move || parsed.get().err().unwrap_or_default())
            on_edit=Callback::new(|program: String| {
                storage::save_to(KEY, &storage::SavedText { program });
            })
            on_load=Callback::new(move |()| {
                if avr.load() {
                            if let Some(ladder) = ladder {
                                ladder.run_loaded();
                            }
                        }
            })
            warning=Signal::derive(move || {
                (parsed.get() == Ok(true)).then(|| t().warn_tof.to_string())
            })
            tall=true
        />
    }
}

/// One named bit: its lamp and the switch that drives it.
#[component]
fn BitRow(avr: AvrCtx, b: NamedBit) -> impl IntoView {
    let ctx = Ctx::get();
    let t = move || ctx.lang.get().texts();
    let NamedBit {
        name,
        bit,
        device,
        value,
        driven,
    } = b;
    let drive = move |on: Option<bool>| {
        driven.set(on);
        avr.drive(device, on);
    };
    view! {
        <tr>
            <td class="bit-name">{name.clone()}</td>
            <td class="bit-ref">{bit.to_string()}</td>
            <td>
                <Led on=value testid=format!("avr-lamp-{name}") colour="amber" label=name.clone() />
            </td>
            <td>
                <button
                    type="button"
                    class="input-switch small"
                    class:on=move || driven.get() == Some(true)
                    data-testid=format!("avr-input-{name}")
                    aria-pressed=move || (driven.get() == Some(true)).to_string()
                    title=move || t().drive
                    on:click=move |_| drive(Some(driven.get_untracked() != Some(true)))
                >
                    {move || t().drive}
                </button>
            </td>
        </tr>
    }
}

crate::parts::part_fn!(
    avr_plc,
    /// The AVR PLC arrives as a part of its own (issue #53): its engine,
    /// its compiler and its panel, fetched when it is first shown.
    pub(crate) fn arrive(
        page: Ctx,
        ladder: crate::editor::LadderCtx,
    ) -> Result<crate::machines::workspace::Shared, crate::parts::PartMissing> {
        engine::machines::register(engine::machines::MachineKit::AVR);
        let avr = AvrCtx::restore(page);
        // The compiler's scan period before the program pane is read.
        ladder
            .text
            .options
            .update(|o| o.avr_scan_ms = scan_ms_default());
        crate::machines::workspace::wire(
            ladder,
            crate::machines::link(avr.sim, move |turn| avr.refresh(turn)),
            crate::machines::text_program(avr.text, move || avr.load(), move || avr.save()),
        );
        Ok(std::rc::Rc::new(avr))
    }
);

impl crate::machines::workspace::MachineWorkspace for AvrCtx {
    fn panel(&self) -> AnyView {
        view! { <AvrPanel avr=*self /> }.into_any()
    }

    fn program(&self) -> AnyView {
        view! { <AvrProgram avr=*self /> }.into_any()
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
