//! The palette: only the elements the machine has (the engine's
//! capability table); what it lacks is shown disabled with the reason.
//! A click acts at the cursor; an item dragged onto a cell acts there.

use engine::ladder::edit::EntryKind;
use engine::ladder::target::capabilities;
use engine::ladder::{CoilKind, ContactKind, Element};
use engine::MachineId;
use leptos::prelude::*;

use super::cell_kind::CellKind;
use super::keys::Action;
use super::state::LadderCtx;
use super::texts;

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

/// The palette of `machine`.
pub fn items(machine: MachineId) -> Vec<Item> {
    let caps = capabilities(machine);
    let entry = |kind, branch, prefill| {
        Does::Key(Action::Entry {
            kind,
            branch,
            prefill,
        })
    };
    let contact = |k| caps.contacts.contains(&k);
    let coil = |k| caps.coils.contains(&k);
    let why = |ok: bool, what: &str| (!ok).then(|| format!("{machine} has no {what}"));
    let edges = contact(ContactKind::Rising);
    vec![
        item(
            CellKind::No.hook(),
            CellKind::No.look().symbol,
            "normally open contact (F5)",
            entry(EntryKind::Open, false, ""),
            None,
        ),
        item(
            CellKind::Nc.hook(),
            CellKind::Nc.look().symbol,
            "normally closed contact (F6)",
            entry(EntryKind::Closed, false, ""),
            None,
        ),
        item(
            "or-no",
            "└┤ ├┘",
            "OR branch, normally open (Shift+F5)",
            entry(EntryKind::Open, true, ""),
            None,
        ),
        item(
            "or-nc",
            "└┤/├┘",
            "OR branch, normally closed (Shift+F6)",
            entry(EntryKind::Closed, true, ""),
            None,
        ),
        item(
            CellKind::Rise.hook(),
            CellKind::Rise.look().symbol,
            "rising edge contact (LDP)",
            entry(EntryKind::Instruction, false, "LDP "),
            why(edges, "edge contacts"),
        ),
        item(
            CellKind::Fall.hook(),
            CellKind::Fall.look().symbol,
            "falling edge contact (LDF)",
            entry(EntryKind::Instruction, false, "LDF "),
            why(edges, "edge contacts"),
        ),
        item(
            "wire",
            "──",
            "horizontal wire (F9)",
            Does::Key(Action::Wire),
            None,
        ),
        item(
            "link",
            "│",
            "vertical link (Shift+F9)",
            Does::Key(Action::ToggleLink),
            None,
        ),
        item(
            CellKind::Coil.hook(),
            CellKind::Coil.look().symbol,
            "coil (F7)",
            entry(EntryKind::Coil, false, ""),
            why(coil(CoilKind::Normal), "coils"),
        ),
        item(
            CellKind::CoilNot.hook(),
            CellKind::CoilNot.look().symbol,
            "inverted coil",
            entry(EntryKind::Instruction, false, "STI "),
            why(coil(CoilKind::Inverted), "inverted coils"),
        ),
        item(
            CellKind::Set.hook(),
            CellKind::Set.look().symbol,
            "set coil",
            entry(EntryKind::Instruction, false, "SET "),
            why(coil(CoilKind::Set), "set coils"),
        ),
        item(
            CellKind::Reset.hook(),
            CellKind::Reset.look().symbol,
            "reset coil",
            entry(EntryKind::Instruction, false, "RST "),
            why(coil(CoilKind::Reset), "reset coils"),
        ),
        item(
            "timer",
            "(T K)",
            "timer coil: OUT T00 K10",
            entry(EntryKind::Instruction, false, "OUT T00 K"),
            why(
                caps.timer_counter_coils,
                "timer coils with set values (MINASEC-U: coil T0/T1)",
            ),
        ),
        item(
            "counter",
            "(C K)",
            "counter coil: OUT C00 K10",
            entry(EntryKind::Instruction, false, "OUT C00 K"),
            why(
                caps.timer_counter_coils,
                "counter coils with set values (MINASEC-U: coil C0)",
            ),
        ),
        item(
            "pls",
            "[PLS]",
            "one-scan pulse output",
            entry(EntryKind::Instruction, false, "PLS "),
            why(caps.pulse_outputs, "PLS/PLF outputs"),
        ),
        item(
            "plf",
            "[PLF]",
            "one-scan pulse on falling power",
            entry(EntryKind::Instruction, false, "PLF "),
            why(caps.pulse_outputs, "PLS/PLF outputs"),
        ),
        item(
            "mov",
            "[MOV]",
            "MOV K50 D00",
            entry(EntryKind::Instruction, false, "MOV "),
            why(caps.data_boxes, "data boxes"),
        ),
        item(
            "cmp",
            "[CMP]",
            "CMP D00 K10",
            entry(EntryKind::Instruction, false, "CMP "),
            why(caps.data_boxes, "data boxes"),
        ),
        item(
            "inc",
            "[INC]",
            "INC D00",
            entry(EntryKind::Instruction, false, "INC "),
            why(caps.data_boxes, "data boxes"),
        ),
        item(
            "dec",
            "[DEC]",
            "DEC D00",
            entry(EntryKind::Instruction, false, "DEC "),
            why(caps.data_boxes, "data boxes"),
        ),
        item(
            "not",
            "[NOT]",
            "invert the power flow",
            Does::Place(Element::Not),
            why(caps.inline_boxes, "in-line boxes"),
        ),
        item(
            "r-trig",
            "[R_TRIG]",
            "one scan on rising power",
            Does::Place(Element::Edge { falling: false }),
            why(caps.inline_boxes, "in-line boxes"),
        ),
        item(
            "f-trig",
            "[F_TRIG]",
            "one scan on falling power",
            Does::Place(Element::Edge { falling: true }),
            why(caps.inline_boxes, "in-line boxes"),
        ),
        item(
            "ton",
            "[TON]",
            "on-delay timer: TON t1 500ms",
            entry(EntryKind::Instruction, false, "TON "),
            why(caps.inline_boxes, "in-line timers"),
        ),
        item(
            "tof",
            "[TOF]",
            "off-delay timer: TOF t1 500ms",
            entry(EntryKind::Instruction, false, "TOF "),
            why(caps.inline_boxes, "in-line timers"),
        ),
        item(
            "tp",
            "[TP]",
            "pulse timer: TP t1 500ms",
            entry(EntryKind::Instruction, false, "TP "),
            why(caps.inline_boxes, "in-line timers"),
        ),
    ]
}

fn item(
    id: &'static str,
    symbol: &'static str,
    name: &'static str,
    does: Does,
    lacks: Option<String>,
) -> Item {
    Item {
        id,
        symbol,
        name,
        does,
        lacks,
    }
}

/// Does what palette item `id` does, at the cursor.
pub fn activate(ctx: LadderCtx, id: &str) {
    let Some(item) = items(ctx.machine).into_iter().find(|i| i.id == id) else {
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

/// The palette beside the ladder.
#[component]
pub fn Palette(ctx: LadderCtx, on_done: Callback<()>) -> impl IntoView {
    let t = move || texts::texts(ctx.page.lang.get());
    let buttons = items(ctx.machine)
        .into_iter()
        .map(|i| {
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
                    title=title.clone()
                    aria-label=title
                    aria-disabled=if disabled { "true" } else { "false" }
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
        })
        .collect_view();
    view! {
        <div class="palette" data-testid="palette" role="toolbar" aria-label=move || t().palette>
            {buttons}
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lacks(machine: MachineId, id: &str) -> Option<String> {
        items(machine)
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
    }
}
