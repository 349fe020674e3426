//! The palette: only the elements the machine has (the engine's
//! capability table); what it lacks is shown disabled with the reason.
//! A click acts at the cursor; an item dragged onto a cell acts there.

use engine::ladder::edit::EntryKind;
use engine::ladder::target::{capabilities, Capabilities};
use engine::ladder::{CoilKind, ContactKind, Element};
use engine::MachineId;
use leptos::prelude::*;

use super::cell_kind::CellKind;
use super::keys::Action;
use super::state::LadderCtx;
use crate::i18n::Lang;

/// What a palette item does.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Does {
    /// Opens the device entry (like its key).
    Key(Action),
    /// Places an element that names no device.
    Place(Element),
}

/// One palette item.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Item {
    /// Its hook: `palette-{id}`, and what a drag carries.
    pub id: &'static str,
    /// The symbol shown.
    pub symbol: &'static str,
    /// What it is, in words (its tooltip).
    pub name: &'static str,
    /// What it does.
    pub does: Does,
    /// Why the machine cannot take it, when it cannot.
    pub lacks: Option<String>,
}

/// What a palette item asks of the machine.
#[derive(Clone, Copy)]
enum Needs {
    Nothing,
    /// Rising and falling edge contacts.
    Edges,
    /// A coil of this kind (what it is called, in English and Japanese).
    Coil(CoilKind, Words),
    /// Timer and counter coils with set values (what they are called).
    CountCoils(Words),
    /// PLS / PLF.
    Pulses,
    /// MOV, CMP, INC, DEC.
    DataBoxes,
    /// NOT, R_TRIG, F_TRIG, TON … on the rung (what they are called).
    InlineBoxes(Words),
    /// The soft PLC's functions and blocks on words: only its palette
    /// shows them (no other machine has words to give them).
    WordBoxes,
}

/// Words in English and Japanese.
type Words = (&'static str, &'static str);

/// The words of `w` in `lang`.
fn said(w: Words, lang: Lang) -> &'static str {
    match lang {
        Lang::En => w.0,
        Lang::Ja => w.1,
    }
}

impl Needs {
    /// Why `machine` cannot take it, when it cannot, in `lang`.
    fn lacking(self, machine: MachineId, caps: &Capabilities, lang: Lang) -> Option<String> {
        let (has, what) = match self {
            Needs::Nothing => return None,
            Needs::Edges => (
                caps.contacts.contains(&ContactKind::Rising),
                ("edge contacts", "エッジ接点"),
            ),
            Needs::Coil(kind, what) => (caps.coils.contains(&kind), what),
            Needs::CountCoils(what) => (caps.timer_counter_coils, what),
            Needs::Pulses => (caps.pulse_outputs, ("PLS/PLF outputs", "PLS/PLF 出力")),
            Needs::DataBoxes => (caps.data_boxes, ("data boxes", "データ命令")),
            Needs::InlineBoxes(what) => (caps.inline_boxes, what),
            Needs::WordBoxes => (caps.word_boxes, ("functions on words", "ワード命令")),
        };
        let what = said(what, lang);
        (!has).then(|| match lang {
            Lang::En => format!("{machine} has no {what}"),
            Lang::Ja => format!(
                "{}には{what}がありません",
                crate::state::product_name(machine)
            ),
        })
    }
}

/// What an item does, as data: the device entry of a kind (as a branch,
/// prefilled), a key's action, or an element placed as it is.
enum Act {
    Entry(EntryKind, bool, &'static str),
    Key(Action),
    Place(Element),
}

/// One row of the palette's table.
struct Spec {
    id: &'static str,
    symbol: &'static str,
    name: Words,
    act: Act,
    needs: Needs,
}

const fn spec(id: &'static str, symbol: &'static str, name: Words, act: Act, needs: Needs) -> Spec {
    Spec {
        id,
        symbol,
        name,
        act,
        needs,
    }
}

/// A kind from the cells' table, by its hook and symbol.
const fn kind(k: CellKind, name: Words, act: Act, needs: Needs) -> Spec {
    spec(k.hook(), k.look().symbol, name, act, needs)
}

use Act::{Entry, Key, Place};
use EntryKind::{Closed, Coil as CoilEntry, Instruction, Open};

/// The palette, in the order shown.
#[rustfmt::skip]
const SPECS: &[Spec] = &[
    kind(CellKind::No, ("normally open contact (F5)", "a接点 (F5)"), Entry(Open, false, ""), Needs::Nothing),
    kind(CellKind::Nc, ("normally closed contact (F6)", "b接点 (F6)"), Entry(Closed, false, ""), Needs::Nothing),
    spec("or-no", "└┤ ├┘", ("OR branch, normally open (Shift+F5)", "並列 a接点 (Shift+F5)"), Entry(Open, true, ""), Needs::Nothing),
    spec("or-nc", "└┤/├┘", ("OR branch, normally closed (Shift+F6)", "並列 b接点 (Shift+F6)"), Entry(Closed, true, ""), Needs::Nothing),
    kind(CellKind::Rise, ("rising edge contact (LDP)", "立上りエッジ接点 (LDP)"), Entry(Instruction, false, "LDP "), Needs::Edges),
    kind(CellKind::Fall, ("falling edge contact (LDF)", "立下りエッジ接点 (LDF)"), Entry(Instruction, false, "LDF "), Needs::Edges),
    spec("wire", "──", ("horizontal wire (F9)", "横線 (F9)"), Key(Action::Wire), Needs::Nothing),
    spec("link", "│", ("vertical link (Shift+F9)", "縦線 (Shift+F9)"), Key(Action::ToggleLink), Needs::Nothing),
    kind(CellKind::Coil, ("coil (F7)", "コイル (F7)"), Entry(CoilEntry, false, ""), Needs::Coil(CoilKind::Normal, ("coils", "コイル"))),
    kind(CellKind::CoilNot, ("inverted coil", "反転コイル"), Entry(Instruction, false, "STI "), Needs::Coil(CoilKind::Inverted, ("inverted coils", "反転コイル"))),
    kind(CellKind::Set, ("set coil", "セットコイル"), Entry(Instruction, false, "SET "), Needs::Coil(CoilKind::Set, ("set coils", "セットコイル"))),
    kind(CellKind::Reset, ("reset coil", "リセットコイル"), Entry(Instruction, false, "RST "), Needs::Coil(CoilKind::Reset, ("reset coils", "リセットコイル"))),
    spec("timer", "(T K)", ("timer coil: OUT T00 K10", "タイマコイル: OUT T00 K10"), Entry(Instruction, false, "OUT T00 K"), Needs::CountCoils(("timer coils with set values (MINASEC-U: coil T0/T1)", "設定値付きタイマコイル (MINASEC-U: コイル T0/T1)"))),
    spec("counter", "(C K)", ("counter coil: OUT C00 K10", "カウンタコイル: OUT C00 K10"), Entry(Instruction, false, "OUT C00 K"), Needs::CountCoils(("counter coils with set values (MINASEC-U: coil C0)", "設定値付きカウンタコイル (MINASEC-U: コイル C0)"))),
    spec("pls", "[PLS]", ("one-scan pulse output", "1スキャンパルス出力"), Entry(Instruction, false, "PLS "), Needs::Pulses),
    spec("plf", "[PLF]", ("one-scan pulse on falling power", "立下りで1スキャンパルス"), Entry(Instruction, false, "PLF "), Needs::Pulses),
    spec("mov", "[MOV]", ("MOV K50 D00", "転送: MOV K50 D00"), Entry(Instruction, false, "MOV "), Needs::DataBoxes),
    spec("cmp", "[CMP]", ("CMP D00 K10", "比較: CMP D00 K10"), Entry(Instruction, false, "CMP "), Needs::DataBoxes),
    spec("inc", "[INC]", ("INC D00", "インクリメント: INC D00"), Entry(Instruction, false, "INC "), Needs::DataBoxes),
    spec("dec", "[DEC]", ("DEC D00", "デクリメント: DEC D00"), Entry(Instruction, false, "DEC "), Needs::DataBoxes),
    spec("not", "[NOT]", ("invert the power flow", "導通の反転"), Place(Element::Not), Needs::InlineBoxes(("in-line boxes", "インライン命令"))),
    spec("r-trig", "[R_TRIG]", ("one scan on rising power", "導通の立上りで1スキャン"), Place(Element::Edge { falling: false }), Needs::InlineBoxes(("in-line boxes", "インライン命令"))),
    spec("f-trig", "[F_TRIG]", ("one scan on falling power", "導通の立下りで1スキャン"), Place(Element::Edge { falling: true }), Needs::InlineBoxes(("in-line boxes", "インライン命令"))),
    spec("ton", "[TON]", ("on-delay timer: TON t1 500ms", "オンディレイタイマ: TON t1 500ms"), Entry(Instruction, false, "TON "), Needs::InlineBoxes(("in-line timers", "インラインタイマ"))),
    spec("tof", "[TOF]", ("off-delay timer: TOF t1 500ms", "オフディレイタイマ: TOF t1 500ms"), Entry(Instruction, false, "TOF "), Needs::InlineBoxes(("in-line timers", "インラインタイマ"))),
    spec("tp", "[TP]", ("pulse timer: TP t1 500ms", "パルスタイマ: TP t1 500ms"), Entry(Instruction, false, "TP "), Needs::InlineBoxes(("in-line timers", "インラインタイマ"))),
    spec("add", "[ADD]", ("ADD a 1 c: c := a + 1", "加算: ADD a 1 c (c := a + 1)"), Entry(Instruction, false, "ADD "), Needs::WordBoxes),
    spec("sub", "[SUB]", ("SUB a 1 c: c := a − 1", "減算: SUB a 1 c (c := a − 1)"), Entry(Instruction, false, "SUB "), Needs::WordBoxes),
    spec("mul", "[MUL]", ("MUL a 2 c: c := a × 2", "乗算: MUL a 2 c (c := a × 2)"), Entry(Instruction, false, "MUL "), Needs::WordBoxes),
    spec("div", "[DIV]", ("DIV a 10 c: c := a ÷ 10", "除算: DIV a 10 c (c := a ÷ 10)"), Entry(Instruction, false, "DIV "), Needs::WordBoxes),
    spec("move", "[MOVE]", ("MOVE 42 d: d := 42", "転送: MOVE 42 d (d := 42)"), Entry(Instruction, false, "MOVE "), Needs::WordBoxes),
    spec("gt", "[>]", ("GT a 10: power while a > 10", "比較: GT a 10 (a > 10 の間導通)"), Entry(Instruction, false, "GT "), Needs::WordBoxes),
    spec("eq", "[=]", ("EQ a 10: power while a = 10", "比較: EQ a 10 (a = 10 の間導通)"), Entry(Instruction, false, "EQ "), Needs::WordBoxes),
    spec("lt", "[<]", ("LT a 10: power while a < 10", "比較: LT a 10 (a < 10 の間導通)"), Entry(Instruction, false, "LT "), Needs::WordBoxes),
    spec("ctu", "[CTU]", ("up counter: CTU c0 reset 10", "加算カウンタ: CTU c0 reset 10"), Entry(Instruction, false, "CTU "), Needs::WordBoxes),
    spec("pin", "[▸R]", ("a block's input wired from the network to its left, below the block: PIN R", "ブロックの入力 (下の行の回路から): PIN R"), Entry(Instruction, false, "PIN "), Needs::WordBoxes),
    spec("ctd", "[CTD]", ("down counter: CTD c1 load 10", "減算カウンタ: CTD c1 load 10"), Entry(Instruction, false, "CTD "), Needs::WordBoxes),
    spec("ld-ton", "[LD_TON]", ("LDmicro's on-delay timer, counting scans: LD_TON Tw_ld 49 Tw", "LDmicro のオンディレイタイマ (スキャン数): LD_TON Tw_ld 49 Tw"), Entry(Instruction, false, "LD_TON "), Needs::WordBoxes),
    spec("ld-tof", "[LD_TOF]", ("LDmicro's off-delay timer, counting scans: LD_TOF Tw_ld 49 Tw", "LDmicro のオフディレイタイマ (スキャン数): LD_TOF Tw_ld 49 Tw"), Entry(Instruction, false, "LD_TOF "), Needs::WordBoxes),
    spec("ld-ctu", "[LD_CTU]", ("LDmicro's up counter: LD_CTU Cn_ld 10 0 Cn", "LDmicro の加算カウンタ: LD_CTU Cn_ld 10 0 Cn"), Entry(Instruction, false, "LD_CTU "), Needs::WordBoxes),
    spec("ld-ctc", "[LD_CTC]", ("LDmicro's circular counter: LD_CTC Cn_ld 9 0 Cn", "LDmicro の循環カウンタ: LD_CTC Cn_ld 9 0 Cn"), Entry(Instruction, false, "LD_CTC "), Needs::WordBoxes),
    spec("ld-rto", "[LD_RTO]", ("LDmicro's retentive on-delay timer, counting scans: LD_RTO Tr_ld 49 Tr", "LDmicro の積算タイマ (スキャン数): LD_RTO Tr_ld 49 Tr"), Entry(Instruction, false, "LD_RTO "), Needs::WordBoxes),
    spec("ld-tcy", "[LD_TCY]", ("LDmicro's cyclic timer, turning over each period: LD_TCY Tc_ld 49 Tc", "LDmicro のサイクリックタイマ: LD_TCY Tc_ld 49 Tc"), Entry(Instruction, false, "LD_TCY "), Needs::WordBoxes),
    spec("ld-ctd", "[LD_CTD]", ("LDmicro's down counter: LD_CTD Cd_ld 0 10 Cd", "LDmicro の減算カウンタ: LD_CTD Cd_ld 0 10 Cd"), Entry(Instruction, false, "LD_CTD "), Needs::WordBoxes),
    spec("ld-ctr", "[LD_CTR]", ("LDmicro's circular down counter: LD_CTR Cr_ld 0 9 Cr", "LDmicro の循環減算カウンタ: LD_CTR Cr_ld 0 9 Cr"), Entry(Instruction, false, "LD_CTR "), Needs::WordBoxes),
    spec("ld-uart-send", "[UART SEND]", ("LDmicro's serial send of a byte: LD_UART_SEND send_ld ch", "LDmicro のシリアル送信 (1バイト): LD_UART_SEND send_ld ch"), Entry(Instruction, false, "LD_UART_SEND "), Needs::WordBoxes),
    spec("ld-rtl", "[LD_RTL]", ("LDmicro's retentive timer counting while off: LD_RTL Tl_ld 49 Tl", "LDmicro のオフ積算タイマ: LD_RTL Tl_ld 49 Tl"), Entry(Instruction, false, "LD_RTL "), Needs::WordBoxes),
    spec("ld-thi", "[LD_THI]", ("LDmicro's pulse, high for its period after a rise: LD_THI Th_ld 49 Th", "LDmicro のパルス (立上りから期間中オン): LD_THI Th_ld 49 Th"), Entry(Instruction, false, "LD_THI "), Needs::WordBoxes),
    spec("ld-tlo", "[LD_TLO]", ("LDmicro's pulse, low for its period after a fall: LD_TLO Tf_ld 49 Tf", "LDmicro のパルス (立下りから期間中オフ): LD_TLO Tf_ld 49 Tf"), Entry(Instruction, false, "LD_TLO "), Needs::WordBoxes),
    spec("ld-osl", "[LD_OSL]", ("LDmicro's one scan low at a fall: LD_OSL osl_ld", "LDmicro の立下り1スキャンオフ: LD_OSL osl_ld"), Entry(Instruction, false, "LD_OSL "), Needs::WordBoxes),
    spec("ld-osc", "[LD_OSC]", ("LDmicro's oscillator, on every other scan: LD_OSC osc_ld", "LDmicro の発振 (1スキャンおき): LD_OSC osc_ld"), Entry(Instruction, false, "LD_OSC "), Needs::WordBoxes),
    spec("ld-seg7", "[7SEG]", ("LDmicro's 7-segment digit, drawn on the board: LD_SEG7 seg_ld n 0 seg 8 (source, 0 common cathode or 1 anode, digit variable, its bits)", "LDmicro の7セグメント変換 (ボードに表示): LD_SEG7 seg_ld n 0 seg 8 (元の値, 0 カソードコモン / 1 アノードコモン, 表示変数, ビット数)"), Entry(Instruction, false, "LD_SEG7 "), Needs::WordBoxes),
    spec("ld-uart-recv", "[UART RECV]", ("LDmicro's serial receive of a byte: LD_UART_RECV recv_ld ch", "LDmicro のシリアル受信 (1バイト): LD_UART_RECV recv_ld ch"), Entry(Instruction, false, "LD_UART_RECV "), Needs::WordBoxes),
    spec("ld-uart-avail", "[UART AVAIL]", ("power while the serial port holds a byte: LD_UART_AVAIL avail_ld", "シリアル受信データありの間導通: LD_UART_AVAIL avail_ld"), Entry(Instruction, false, "LD_UART_AVAIL "), Needs::WordBoxes),
    spec("ld-uart-ready", "[UART READY]", ("power while the serial port can send: LD_UART_READY ready_ld", "シリアル送信可能の間導通: LD_UART_READY ready_ld"), Entry(Instruction, false, "LD_UART_READY "), Needs::WordBoxes),
    spec("ld-string", "[STRING]", ("LDmicro's STRING, a C format printed into a STRING variable while powered: str_ld: LD_STRING(V := n, D := msg, FMT := 'n=%d', D => msg)", "LDmicro の STRING (通電中、C の書式で STRING 変数へ書き込み): str_ld: LD_STRING(V := n, D := msg, FMT := 'n=%d', D => msg)"), Entry(Instruction, false, "str_ld: LD_STRING(V := n, D := msg, FMT := 'n=%d', D => msg)"), Needs::WordBoxes),
    spec("ld-fmtstr", "[FMT STR]", ("LDmicro's formatted string sent over the serial port: fmt_ld: LD_FMTSTR(V := n, FMT := 'n = \\3$R$N')", "LDmicro の書式付き文字列のシリアル送信: fmt_ld: LD_FMTSTR(V := n, FMT := 'n = \\3$R$N')"), Entry(Instruction, false, "fmt_ld: LD_FMTSTR(V := n, FMT := 'n = \\3$R$N')"), Needs::WordBoxes),
];

/// The palette of `machine` in `lang`: every item, with what the machine
/// lacks.
pub fn items(machine: MachineId, lang: Lang) -> Vec<Item> {
    let caps = capabilities(machine);
    SPECS
        .iter()
        .filter(|s| !matches!(s.needs, Needs::WordBoxes) || caps.word_boxes)
        .map(|s| Item {
            id: s.id,
            symbol: s.symbol,
            name: said(s.name, lang),
            does: match &s.act {
                Entry(kind, branch, prefill) => Does::Key(Action::Entry {
                    kind: *kind,
                    branch: *branch,
                    prefill,
                }),
                Key(action) => Does::Key(*action),
                Place(element) => Does::Place(element.clone()),
            },
            lacks: s.needs.lacking(machine, &caps, lang),
        })
        .chain(own_blocks(machine, lang))
        .collect()
}

/// The project's own Structured Text function blocks (issue #55), each a
/// box typed by its instance and inputs: `SCALE scale0 x`.
fn own_blocks(machine: MachineId, lang: Lang) -> Vec<Item> {
    use engine::ladder::user_blocks::{declared, intern};
    if machine != MachineId::SoftPlc {
        return Vec::new();
    }
    declared()
        .into_iter()
        .filter(|b| engine::ladder::user_blocks::is_user_block(&b.name))
        .map(|b| {
            let pins = |l: &[(String, engine::iec::data::DataType)]| {
                l.iter()
                    .map(|(p, _)| p.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let (ins, outs) = (pins(&b.inputs), pins(&b.outputs));
            let what = said(("ST function block", "ST ファンクションブロック"), lang);
            let name = format!("{what} {}({ins}) → {outs}", b.name);
            Item {
                id: intern(&format!("st-{}", b.name.to_ascii_lowercase())),
                symbol: intern(&format!("[{}]", b.name)),
                name: intern(&name),
                does: Does::Key(Action::Entry {
                    kind: Instruction,
                    branch: false,
                    prefill: intern(&format!("{} ", b.name)),
                }),
                lacks: None,
            }
        })
        .collect()
}

/// Does what palette item `id` does, at the cursor.
pub fn activate(ctx: LadderCtx, id: &str) {
    let Some(item) = items(ctx.machine, ctx.page.lang.get_untracked())
        .into_iter()
        .find(|i| i.id == id)
    else {
        return;
    };
    if let Some(why) = item.lacks {
        ctx.panes.message.set(Some(why));
        return;
    }
    match item.does {
        Does::Key(action) => ctx.dispatch(action),
        Does::Place(element) => {
            ctx.place(element);
        }
    }
}

/// The palette's groups, in the order shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    Contacts,
    Coils,
    TimersCounters,
    Compare,
    Math,
    MoveConvert,
    Ldmicro,
    /// The project's own ST blocks.
    Own,
}

impl Group {
    /// Every group, in the order shown.
    pub const ALL: [Group; 8] = [
        Group::Contacts,
        Group::Coils,
        Group::TimersCounters,
        Group::Compare,
        Group::Math,
        Group::MoveConvert,
        Group::Ldmicro,
        Group::Own,
    ];

    /// The group of the item with hook `id`.
    pub fn of(id: &str) -> Group {
        match id {
            _ if id.starts_with("ld-") => Group::Ldmicro,
            _ if id.starts_with("st-") => Group::Own,
            "coil" | "coil-not" | "set" | "reset" | "pls" | "plf" => Group::Coils,
            "timer" | "counter" | "ton" | "tof" | "tp" | "ctu" | "ctd" | "pin" => {
                Group::TimersCounters
            }
            "cmp" | "gt" | "eq" | "lt" => Group::Compare,
            "add" | "sub" | "mul" | "div" | "inc" | "dec" => Group::Math,
            "mov" | "move" => Group::MoveConvert,
            _ => Group::Contacts,
        }
    }

    /// Its name in `lang`.
    pub fn name(self, lang: Lang) -> &'static str {
        said(
            match self {
                Group::Contacts => ("Contacts", "接点"),
                Group::Coils => ("Coils", "コイル"),
                Group::TimersCounters => ("Timers, counters", "タイマ・カウンタ"),
                Group::Compare => ("Compare", "比較"),
                Group::Math => ("Math", "演算"),
                Group::MoveConvert => ("Move", "転送"),
                Group::Ldmicro => ("LDmicro", "LDmicro"),
                Group::Own => ("ST blocks", "ST ブロック"),
            },
            lang,
        )
    }
}

/// Whether `item` answers the palette's search `query` (its hook, symbol
/// or name holds it, letter case aside); an empty query takes all. The
/// items are named in English and Japanese, so ASCII's case is all the
/// case there is: folding Unicode's put its case tables on the first
/// screen (7 KB gzip) for nothing.
pub fn matches(item: &Item, query: &str) -> bool {
    let q = query.trim().to_ascii_lowercase();
    q.is_empty()
        || [item.id, item.symbol, item.name]
            .iter()
            .any(|s| s.to_ascii_lowercase().contains(&q))
}

/// The palette beside the ladder: its items in groups, a search field
/// over them; it scrolls inside, never taller than the ladder.
#[component]
pub fn Palette(ctx: LadderCtx, on_done: Callback<()>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let query = RwSignal::new(String::new());
    let button = move |i: Item| {
        let id = i.id;
        let disabled = i.lacks.is_some();
        let title = match &i.lacks {
            Some(why) => format!("{}: {why}", i.name),
            None => i.name.to_string(),
        };
        view! {
            <button
                type="button"
                class="palette-item"
                data-testid=format!("palette-{id}")
                aria-label=format!("{} {title}", i.symbol)
                title=title
                aria-disabled=if disabled { "true" } else { "false" }
                // What the machine lacks is said, not reached by Tab.
                tabindex=if disabled { "-1" } else { "0" }
                data-reason=i.lacks.clone()
                draggable=if disabled { "false" } else { "true" }
                on:dragstart=move |e: web_sys::DragEvent| {
                    if let Some(dt) = e.data_transfer() {
                        let _ = dt.set_data("text/plain", &format!("palette:{id}"));
                    }
                }
                on:click=move |_| {
                    activate(ctx, id);
                    on_done.run(());
                }
            >
                {i.symbol}
            </button>
        }
    };
    // The project's own ST blocks: looked at again after each refresh,
    // drawn again only when they change.
    let own = Memo::new(move |_| {
        ctx.drawing.revision.track();
        engine::ladder::user_blocks::declared()
    });
    // Made again when the language, the search or the own blocks change.
    let groups = move || {
        // Read, not only tracked: a memo recomputes when it is read.
        own.with(|_| ());
        let lang = ctx.page.lang.get();
        let q = query.get();
        let all = items(ctx.machine, lang);
        Group::ALL
            .into_iter()
            .filter_map(|g| {
                let inside: Vec<Item> = all
                    .iter()
                    .filter(|i| Group::of(i.id) == g && matches(i, &q))
                    .cloned()
                    .collect();
                (!inside.is_empty()).then(|| {
                    view! {
                        <div class="palette-group" role="group" aria-label=g.name(lang)>
                            <h3 aria-hidden="true">{g.name(lang)}</h3>
                            {inside.into_iter().map(button).collect_view()}
                        </div>
                    }
                })
            })
            .collect_view()
    };
    view! {
        <div class="palette" data-testid="palette" role="toolbar" aria-label=move || t().palette>
            <input type="search" class="palette-search" data-testid="palette-search"
                placeholder=move || t().palette_search aria-label=move || t().palette_search
                prop:value=move || query.get()
                on:input=move |e| query.set(event_target_value(&e)) />
            {groups}
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lacks(machine: MachineId, id: &str) -> Option<String> {
        items(machine, Lang::En)
            .into_iter()
            .find(|i| i.id == id)
            .and_then(|i| i.lacks)
    }

    #[test]
    fn the_palette_follows_the_capability_table() {
        assert_eq!(lacks(MachineId::Io86a, "mov"), None);
        assert_eq!(
            lacks(MachineId::MinasecU, "mov").as_deref(),
            Some("minasec-u has no data boxes")
        );
        assert!(lacks(MachineId::ArduinoPlc, "rise").is_some());
        assert_eq!(lacks(MachineId::AvrPlc, "ton"), None);
        assert!(lacks(MachineId::Io86a, "ton").is_some());
        assert_eq!(lacks(MachineId::Io86a, "or-no"), None);
        assert_eq!(lacks(MachineId::SoftPlc, "add"), None);
        let ids = |m| {
            items(m, Lang::En)
                .into_iter()
                .map(|i| i.id)
                .collect::<Vec<_>>()
        };
        assert!(ids(MachineId::SoftPlc).contains(&"ctu"));
        assert!(
            !ids(MachineId::Io86a).contains(&"add"),
            "words only on the soft PLC"
        );
    }

    #[test]
    fn every_ldmicro_entrys_example_is_a_box_the_soft_plc_takes() {
        use engine::ladder::edit::{parse_entry, EntryKind};
        let ld: Vec<Item> = items(MachineId::SoftPlc, Lang::En)
            .into_iter()
            .filter(|i| i.id.starts_with("ld-"))
            .collect();
        assert!(ld.len() >= 18, "{}", ld.len());
        for item in ld {
            // The example follows the name's colon; a note in brackets ends it.
            let (_, example) = item.name.split_once(": ").expect(item.id);
            let example = example.split(" (").next().unwrap_or(example);
            let made = parse_entry(MachineId::SoftPlc, EntryKind::Instruction, example);
            assert!(made.is_ok(), "{}: {example}: {made:?}", item.id);
        }
    }

    #[test]
    fn every_item_has_a_group_and_the_search_finds_by_name() {
        let soft = items(MachineId::SoftPlc, Lang::En);
        let group = |id: &str| Group::of(id);
        assert_eq!(group("no"), Group::Contacts);
        assert_eq!(group("coil"), Group::Coils);
        assert_eq!(group("ctu"), Group::TimersCounters);
        assert_eq!(group("gt"), Group::Compare);
        assert_eq!(group("add"), Group::Math);
        assert_eq!(group("move"), Group::MoveConvert);
        assert_eq!(group("ld-seg7"), Group::Ldmicro);
        let found: Vec<&str> = soft
            .iter()
            .filter(|i| matches(i, "COUNTER"))
            .map(|i| i.id)
            .collect();
        assert!(
            found.contains(&"ctu") && found.contains(&"ctd"),
            "{found:?}"
        );
        assert!(!found.contains(&"no"));
        assert_eq!(soft.iter().filter(|i| matches(i, "  ")).count(), soft.len());
        // No group is empty on the soft PLC, the one machine with all.
        // The project's own blocks' group is empty until ST declares some.
        for g in Group::ALL.into_iter().filter(|g| *g != Group::Own) {
            assert!(soft.iter().any(|i| Group::of(i.id) == g), "{g:?}");
        }
    }

    #[test]
    fn the_projects_st_blocks_are_boxes_on_the_soft_plc_only() {
        use engine::iec::data::DataType;
        use engine::ladder::user_blocks::{set, UserBlock};
        set(
            vec![UserBlock {
                name: "SCALE".into(),
                inputs: vec![("go".into(), DataType::Bool), ("x".into(), DataType::Int)],
                outputs: vec![("y".into(), DataType::Int)],
            }],
            String::new(),
        );
        let soft = items(MachineId::SoftPlc, Lang::En);
        let own = soft.iter().find(|i| i.id == "st-scale").expect("offered");
        assert_eq!(Group::of(own.id), Group::Own);
        assert_eq!(own.symbol, "[SCALE]");
        assert!(own.name.contains("SCALE(go, x) → y"), "{}", own.name);
        assert!(matches!(
            own.does,
            Does::Key(Action::Entry {
                prefill: "SCALE ",
                ..
            })
        ));
        let ja = items(MachineId::SoftPlc, Lang::Ja);
        assert!(ja
            .iter()
            .any(|i| i.id == "st-scale" && i.name.contains("ファンクションブロック")));
        assert!(!items(MachineId::Io86a, Lang::En)
            .iter()
            .any(|i| i.id == "st-scale"));
        set(Vec::new(), String::new());
        assert!(!items(MachineId::SoftPlc, Lang::En)
            .iter()
            .any(|i| i.id == "st-scale"));
    }

    #[test]
    fn the_palette_speaks_japanese_too() {
        let ja = items(MachineId::MinasecU, Lang::Ja);
        let en = items(MachineId::MinasecU, Lang::En);
        assert_eq!(ja.len(), en.len());
        for (j, e) in ja.iter().zip(&en) {
            assert_eq!((j.id, j.symbol), (e.id, e.symbol));
            assert_ne!(j.name, e.name, "{} has a Japanese name", j.id);
        }
        let mov = ja
            .iter()
            .find(|i| i.id == "mov")
            .and_then(|i| i.lacks.clone());
        assert_eq!(mov.as_deref(), Some("MINASEC-Uにはデータ命令がありません"));
    }
}
