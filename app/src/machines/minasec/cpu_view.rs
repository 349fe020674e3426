//! Inside MINASEC-U (issue #33): the book's block diagram of its 1-bit
//! CPU, drawn from the machine's own snapshot (`engine::minasec::cpu`),
//! one signal per block and bus, set only when it changes; a button
//! steps one clock edge (at HALT, as the panel's CLOCK button); a strip
//! draws CLK, WE and the scan signal over the last 32 edges.

use engine::minasec::cpu::{Block, CpuView, EdgeLevels, Phase};
use engine::minasec::{Command, Machine, Mode};
use leptos::prelude::*;

use super::MinasecCtx;
use crate::i18n::Lang;
use crate::state::{put, Ctx};

/// A text in English and Japanese.
type Words = (&'static str, &'static str);

fn said(w: Words, lang: Lang) -> &'static str {
    match lang {
        Lang::En => w.0,
        Lang::Ja => w.1,
    }
}

/// Each block: its name, its chips and the book's section.
fn about(block: Block) -> (Words, &'static str, Words) {
    match block {
        Block::Pc => (
            ("Program counter", "プログラムカウンター"),
            "74HC590",
            (
                "1bit CPU · Program counter",
                "1bit CPU・プログラムカウンター",
            ),
        ),
        Block::Memory => (
            ("Program memory", "プログラムメモリ"),
            "HM6116",
            ("Program memory", "プログラムメモリ"),
        ),
        Block::Decoder => (
            (
                "Instruction decoder · logic unit",
                "命令デコーダー・Logic Unit",
            ),
            "74HC NAND",
            ("Instruction set and decoder", "命令セットと命令デコーダー"),
        ),
        Block::AddressDecoder => (
            ("Address decoder", "アドレスデコーダー"),
            "74HC138",
            ("Address decoder", "アドレスデコーダー"),
        ),
        Block::Accumulator => (
            ("Accumulator", "アキュムレーター"),
            "74HC74",
            ("Load and store", "ロードとストア"),
        ),
        Block::Inputs => (
            ("Digital inputs X", "デジタル入力 X"),
            "74HC273 · 74HC251",
            ("Digital inputs", "デジタル入力"),
        ),
        Block::Outputs => (
            ("Digital outputs Y", "デジタル出力 Y"),
            "74HC259 · 74HC273",
            ("Digital outputs", "デジタル出力"),
        ),
        Block::Relays => (
            ("Internal relays M", "内部リレー M"),
            "74HC259 · 74HC251",
            ("Internal relays", "内部リレー"),
        ),
        Block::Timers => (
            ("Timers T0 T1", "タイマー T0 T1"),
            "74HC132",
            ("Timers", "タイマー"),
        ),
        Block::Counter => (
            ("Counter C0", "カウンター C0"),
            "74HC390 · 74HC4511 · 74HC688",
            ("Counter", "カウンター"),
        ),
    }
}

/// How a block's value reads.
fn shown(block: Block, value: u32) -> String {
    match block {
        Block::Pc => format!("{value} ({value:08b})"),
        Block::Memory => format!("{value:08b}"),
        Block::Decoder => format!("OP {value:03b}"),
        Block::AddressDecoder => format!("Y{value}"),
        Block::Accumulator => format!("Q = {value}"),
        Block::Inputs | Block::Outputs => format!("{value:08b}"),
        Block::Relays => format!("{:04b} {:08b}", value >> 8, value & 0xFF),
        Block::Timers => format!("T1 {} T0 {}", value >> 1 & 1, value & 1),
        Block::Counter => format!("{value:02}"),
    }
}

/// One signal per block, bus and line of the view; the strip's edges.
#[derive(Clone, Copy)]
pub struct CpuSignals {
    pub open: RwSignal<bool>,
    blocks: [(RwSignal<u32>, RwSignal<bool>); 10],
    instruction: RwSignal<u8>,
    address: RwSignal<u8>,
    data_in: RwSignal<bool>,
    data_out: RwSignal<bool>,
    we: RwSignal<bool>,
    scan: RwSignal<bool>,
    clear: RwSignal<bool>,
    clk: RwSignal<bool>,
    phase: RwSignal<Phase>,
    halted: RwSignal<bool>,
    edges: RwSignal<Vec<EdgeLevels>>,
}

impl CpuSignals {
    /// Closed, everything low.
    pub fn new() -> CpuSignals {
        CpuSignals {
            open: RwSignal::new(false),
            blocks: std::array::from_fn(|_| (RwSignal::new(0), RwSignal::new(false))),
            instruction: RwSignal::new(0),
            address: RwSignal::new(0),
            data_in: RwSignal::new(false),
            data_out: RwSignal::new(false),
            we: RwSignal::new(true),
            scan: RwSignal::new(false),
            clear: RwSignal::new(false),
            clk: RwSignal::new(false),
            phase: RwSignal::new(Phase::Low),
            halted: RwSignal::new(true),
            edges: RwSignal::new(Vec::new()),
        }
    }

    /// Copies the machine's CPU into the signals that changed (only
    /// while the view is open: closed, it costs nothing a frame).
    pub fn sync(&self, machine: &Machine) {
        if !self.open.get_untracked() {
            return;
        }
        let mut v = CpuView::default();
        machine.cpu_view_into(&mut v);
        for ((value, active), state) in self.blocks.iter().zip(v.blocks) {
            put(*value, state.value);
            put(*active, state.active);
        }
        put(self.instruction, v.instruction);
        put(self.address, v.address);
        put(self.data_in, v.data_in);
        put(self.data_out, v.data_out);
        put(self.we, v.we);
        put(self.scan, v.scan);
        put(self.clear, v.clear);
        put(self.clk, v.clk);
        put(self.phase, v.phase);
        put(
            self.halted,
            machine.mode() == Mode::Halt && machine.powered(),
        );
        let mut edges = Vec::new();
        machine.recent_edges_into(&mut edges);
        put(self.edges, edges);
    }
}

impl Default for CpuSignals {
    fn default() -> Self {
        CpuSignals::new()
    }
}

impl MinasecCtx {
    /// One clock edge at HALT: a rise when the clock is low, a fall when
    /// it is high, as pressing and releasing the panel's CLOCK button.
    pub fn step_edge(&self) {
        let high = self.cpu.clk.get_untracked();
        self.send(Command::ClockButton(!high));
    }
}

/// The CPU view with its open button.
#[component]
pub fn CpuPanel() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let lang = move || ctx.lang.get();
    let cpu = board.cpu;
    let toggle = move |_| {
        cpu.open.update(|o| *o = !*o);
        board.refresh();
    };
    view! {
        <section class="cpu-section">
            <button
                type="button"
                data-testid="cpu-view-open"
                aria-expanded=move || cpu.open.get().to_string()
                on:click=toggle
            >
                {move || said(("Inside the CPU", "CPU の中"), lang())}
            </button>
            <Show when=move || cpu.open.get()>
                {crate::parts::part("cpu-part", ctx.lang.into(), cpu_diagram)}
            </Show>
        </section>
    }
}

crate::parts::part_fn!(
    cpu_view,
    /// The diagram is a part of its own (issue #53): most visits never open it.
    fn cpu_diagram() -> Result<crate::parts::Draw, crate::parts::PartMissing> {
        Ok(|| view! { <CpuDiagram /> }.into_any())
    }
);

#[component]
fn CpuDiagram() -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let lang = move || ctx.lang.get();
    let cpu = board.cpu;
    let block = move |b: Block| view! { <CpuBlock block=b /> };
    let bit = |s: RwSignal<bool>| move || u8::from(s.get()).to_string();
    view! {
        <div class="cpu-view" data-testid="cpu-view" role="region"
            aria-label=move || said(("MINASEC-U's CPU, clock edge by clock edge", "MINASEC-U の CPU (クロックエッジごと)"), lang())>
            <div class="cpu-controls">
                <button
                    type="button"
                    data-testid="cpu-step-edge"
                    prop:disabled=move || !cpu.halted.get()
                    title=move || said(("One clock edge (switch at HALT)", "クロックエッジを1つ進める (HALT 時)"), lang())
                    on:click=move |_| board.step_edge()
                >
                    {move || said(("Step one edge", "エッジを1つ進める"), lang())}
                </button>
                <span data-testid="cpu-phase" data-value=move || cpu.phase.get().name()>
                    {move || format!("CLK {} · {}", u8::from(cpu.clk.get()), phase_said(cpu.phase.get(), lang()))}
                </span>
                <span class="cpu-chips">
                    {move || said(("Clock: 74HC4060 · 74HC74 (§ Clock)", "クロック: 74HC4060・74HC74 (§ クロック)"), lang())}
                </span>
                <span class="cpu-hint">
                    {move || if cpu.halted.get() { "" } else { said(("Set the switch to HALT to step edges.", "エッジを進めるにはスイッチを HALT に。"), lang()) }}
                </span>
            </div>
            <div class="cpu-grid">
                <div class="cpu-row">
                    {block(Block::Pc)}
                    <Bus testid="cpu-bus-instruction" name=("instruction bus", "命令バス") value=Signal::derive(move || u32::from(cpu.instruction.get())) bits=8 />
                    {block(Block::Memory)}
                </div>
                <div class="cpu-row">
                    {block(Block::Decoder)}
                    {block(Block::Accumulator)}
                    {block(Block::AddressDecoder)}
                </div>
                <div class="cpu-row cpu-buses">
                    <Bus testid="cpu-bus-address" name=("address bus", "アドレスバス") value=Signal::derive(move || u32::from(cpu.address.get())) bits=5 />
                    <Bus testid="cpu-bus-data-in" name=("input data bus (Din)", "入力データバス (Din)") value=Signal::derive(move || u32::from(cpu.data_in.get())) bits=1 />
                    <Bus testid="cpu-bus-data-out" name=("output data bus (Dout)", "出力データバス (Dout)") value=Signal::derive(move || u32::from(cpu.data_out.get())) bits=1 />
                    <span class="cpu-line" data-testid="cpu-line-we" data-value=bit(cpu.we)>{move || format!("WE {}", u8::from(cpu.we.get()))}</span>
                    <span class="cpu-line" data-testid="cpu-line-scan" data-value=bit(cpu.scan)>{move || format!("SCAN {}", u8::from(cpu.scan.get()))}</span>
                    <span class="cpu-line" data-testid="cpu-line-clear" data-value=bit(cpu.clear)>{move || format!("CLR {}", u8::from(cpu.clear.get()))}</span>
                </div>
                <div class="cpu-row cpu-devices">
                    {block(Block::Inputs)}
                    {block(Block::Outputs)}
                    {block(Block::Relays)}
                    {block(Block::Timers)}
                    {block(Block::Counter)}
                </div>
            </div>
            <Strip />
        </div>
    }
}

fn phase_said(phase: Phase, lang: Lang) -> &'static str {
    said(
        match phase {
            Phase::Rising => ("rising edge: the step executes", "立ち上がり: 命令を実行"),
            Phase::High => ("high", "H"),
            Phase::Falling => ("falling edge: the PC advances", "立ち下がり: PC が進む"),
            Phase::Low => ("low", "L"),
        },
        lang,
    )
}

#[component]
fn CpuBlock(block: Block) -> impl IntoView {
    let ctx = Ctx::get();
    let board = MinasecCtx::get();
    let lang = move || ctx.lang.get();
    let index = Block::ALL.iter().position(|b| *b == block).unwrap_or(0);
    let (value, active) = board.cpu.blocks[index];
    let (name, chips, section) = about(block);
    view! {
        <div
            class="cpu-block"
            class:active=move || active.get()
            data-testid=format!("cpu-block-{}", block.name())
            data-value=move || value.get().to_string()
            data-active=move || if active.get() { "1" } else { "0" }
        >
            <strong>{move || said(name, lang())}</strong>
            <span class="cpu-chips">{chips}</span>
            <output>{move || shown(block, value.get())}</output>
            <span class="cpu-section-ref">{move || format!("§ {}", said(section, lang()))}</span>
        </div>
    }
}

#[component]
fn Bus(testid: &'static str, name: Words, value: Signal<u32>, bits: usize) -> impl IntoView {
    let ctx = Ctx::get();
    let lang = move || ctx.lang.get();
    view! {
        <span class="cpu-bus" data-testid=testid data-value=move || value.get().to_string()>
            <span class="cpu-bus-name">{move || said(name, lang())}</span>
            <code>{move || format!("{:0width$b}", value.get(), width = bits)}</code>
        </span>
    }
}

/// CLK, WE and SCAN over the last edges, as a timing chart (the book's
/// 動作タイミング).
#[component]
fn Strip() -> impl IntoView {
    let board = MinasecCtx::get();
    let edges = board.cpu.edges;
    const STEP: usize = 12;
    let trace = move |pick: fn(&EdgeLevels) -> bool, row: usize| {
        edges.with(|e| {
            let mut d = String::new();
            let y = |on: bool| row * 20 + if on { 4 } else { 16 };
            for (k, edge) in e.iter().enumerate() {
                let x = k * STEP;
                let yy = y(pick(edge));
                if k == 0 {
                    d.push_str(&format!("M{x},{yy}"));
                } else {
                    d.push_str(&format!(" L{x},{yy}"));
                }
                d.push_str(&format!(" L{},{yy}", x + STEP));
            }
            d
        })
    };
    let width = 32 * STEP + 40;
    view! {
        <svg class="cpu-strip" data-testid="cpu-strip" viewBox=format!("-40 0 {width} 62") role="img"
            aria-label="CLK, WE, SCAN">
            <text x="-38" y="14">"CLK"</text>
            <text x="-38" y="34">"WE"</text>
            <text x="-38" y="54">"SCAN"</text>
            <path d=move || trace(|e| e.clk, 0) />
            <path d=move || trace(|e| e.we, 1) />
            <path d=move || trace(|e| e.scan, 2) />
        </svg>
    }
}
