//! One rung's view: a stable id (the `<For>` key), its signals, and its
//! cells' live slots and device probes.

use super::*;

/// One rung's view: a stable id (the `<For>` key) and its signals.
#[derive(Clone)]
pub struct RungView {
    /// Stays with the rung while it is moved or edited.
    pub id: u64,
    /// Its index (0-based) in the ladder now.
    pub number: ArcRwSignal<usize>,
    /// Its first step in the listing, when it compiled to steps.
    pub first_step: ArcRwSignal<Option<usize>>,
    /// What it shows.
    pub data: ArcRwSignal<RungData>,
    /// One live slot per cell (by the cell's place in `data.cells`): a
    /// frame sets only the signals whose value changed, so only those
    /// cells repaint.
    pub slots: std::sync::Arc<std::sync::Mutex<Vec<CellSlot>>>,
    /// Each cell's devices on the machine, resolved once for this drawing
    /// and program (tagged with [`LadderCtx`]'s probe generation), so a
    /// frame reads the machine without a name lookup.
    pub(super) probes: std::sync::Arc<std::sync::Mutex<Probes>>,
}

/// The machine's handles for a rung's cells.
#[derive(Default)]
pub(super) struct Probes {
    /// The generation they were resolved in (`None`: not yet).
    pub(super) generation: Option<u64>,
    cells: Vec<Probe>,
}

/// A cell's handles: its device's state, a timer's or counter's
/// current value, and a soft PLC box's operands (label, handle).
#[derive(Clone, Default)]
pub(super) struct Probe {
    pub(super) state: Option<engine::plc::Device>,
    pub(super) value: Option<engine::plc::Device>,
    pub(super) words: Vec<(String, engine::plc::Device)>,
}

/// A cell's live signals.
#[derive(Clone, Default)]
pub struct CellSlot {
    /// Its device's state on the running machine (`None`: no device).
    pub on: ArcRwSignal<Option<bool>>,
    /// Its power in the machine's last scan, while it runs the ladder as
    /// drawn.
    pub powered: ArcRwSignal<Option<bool>>,
    /// Its power changed in a scan since the last frame: how often its
    /// contact's device rose.
    pub pulsed: ArcRwSignal<Option<u32>>,
    /// Whether its contact is closed (`crate::editor::conduct`).
    pub conducts: ArcRwSignal<Option<bool>>,
    /// A timer's or counter's current value, on its coil.
    pub value: ArcRwSignal<Option<i64>>,
    /// A soft PLC box's operands' values (`a=5 c=6`).
    pub words: ArcRwSignal<Option<String>>,
}

fn bit(b: bool) -> &'static str {
    if b {
        "1"
    } else {
        "0"
    }
}

impl CellSlot {
    /// `data-on`: its device's state.
    pub fn on_attr(&self) -> impl Fn() -> Option<&'static str> + Clone + Send + Sync + 'static {
        let on = self.on.clone();
        move || on.get().map(bit)
    }

    /// `data-conducts`: whether its contact is closed.
    pub fn conducts_attr(
        &self,
    ) -> impl Fn() -> Option<&'static str> + Clone + Send + Sync + 'static {
        let conducts = self.conducts.clone();
        move || conducts.get().map(bit)
    }

    /// `data-powered`: its power in the last scan.
    pub fn power_attr(&self) -> impl Fn() -> Option<&'static str> + Clone + Send + Sync + 'static {
        let powered = self.powered.clone();
        move || powered.get().map(bit)
    }

    /// `data-pulsed`: its power changed since the last frame.
    pub fn pulse_attr(&self) -> impl Fn() -> Option<&'static str> + Clone + Send + Sync + 'static {
        let pulsed = self.pulsed.clone();
        move || pulsed.get().map(|_| "1")
    }

    /// `data-rises`: how often its device rose since the last frame.
    pub fn rises(&self) -> impl Fn() -> Option<String> + Clone + Send + Sync + 'static {
        let pulsed = self.pulsed.clone();
        move || pulsed.get().filter(|n| *n > 0).map(|n| n.to_string())
    }

    /// A box's operands' values, as text.
    pub fn words_attr(&self) -> impl Fn() -> Option<String> + Clone + Send + Sync + 'static {
        let words = self.words.clone();
        move || words.get()
    }

    /// A timer's or counter's current value, as text.
    pub fn value_attr(&self) -> impl Fn() -> Option<String> + Clone + Send + Sync + 'static {
        let value = self.value.clone();
        move || value.get().map(|v| v.to_string())
    }
}

impl RungView {
    /// A new rung's view, with id `id`, at `number`.
    pub(super) fn new(
        id: u64,
        number: usize,
        first_step: Option<usize>,
        data: RungData,
    ) -> RungView {
        RungView {
            id,
            number: ArcRwSignal::new(number),
            first_step: ArcRwSignal::new(first_step),
            data: ArcRwSignal::new(data),
            slots: Default::default(),
            probes: Default::default(),
        }
    }

    /// The live slot of cell `index` (made when first asked for).
    pub fn slot(&self, index: usize) -> CellSlot {
        let Ok(mut slots) = self.slots.lock() else {
            return CellSlot::default();
        };
        if slots.len() <= index {
            slots.resize_with(index + 1, CellSlot::default);
        }
        slots[index].clone()
    }

    /// Sets each cell's value to `value_of(its place)`, touching only the
    /// signals whose value changes; nothing is allocated.
    pub(super) fn update_each<T: PartialEq + Send + Sync + 'static>(
        &self,
        value_of: impl Fn(usize) -> Option<T>,
        field: impl Fn(&CellSlot) -> &ArcRwSignal<Option<T>>,
    ) {
        self.update_each_from(|i, _| value_of(i), field);
    }

    /// [`Self::update_each`] with each cell's value computed from its place
    /// and its slot as it is (a value made from the cell's other signals).
    pub(super) fn update_each_from<T: PartialEq + Send + Sync + 'static>(
        &self,
        value_of: impl Fn(usize, &CellSlot) -> Option<T>,
        field: impl Fn(&CellSlot) -> &ArcRwSignal<Option<T>>,
    ) {
        let Ok(slots) = self.slots.lock() else {
            return;
        };
        for (i, slot) in slots.iter().enumerate() {
            let new = value_of(i, slot);
            let signal = field(slot);
            if signal.with_untracked(|old| *old != new) {
                signal.set(new);
            }
        }
    }

    /// This rung's probes, resolved on `plc` when they are not of
    /// `generation` (the drawing or the program changed since).
    pub(super) fn probe<R>(
        &self,
        generation: u64,
        resolve: impl Fn(&crate::editor::model::CellData) -> Probe,
        f: impl FnOnce(&[Probe]) -> R,
    ) -> Option<R> {
        let mut probes = self.probes.lock().ok()?;
        if probes.generation != Some(generation) {
            let cells = self
                .data
                .with_untracked(|d| d.cells.iter().map(&resolve).collect());
            *probes = Probes {
                generation: Some(generation),
                cells,
            };
        }
        Some(f(&probes.cells))
    }
}

/// One problem of the ladder, where it is.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Problem {
    /// The rung (0-based).
    pub rung: usize,
    /// The cell, when it has one.
    pub pos: Option<Pos>,
    /// `rung 2, row 1, column 3: …` (1-based, the engine's words).
    pub text: String,
    /// The same in Japanese, from its typed reason when it has one
    /// (`crate::i18n::engine`).
    pub ja: String,
}

/// The device entry while it is open.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EntryState {
    /// What it places.
    pub kind: EntryKind,
    /// As an OR branch (Shift+F5 / Shift+F6).
    pub branch: bool,
    /// The cell it places at.
    pub at: Cursor,
    /// What is typed.
    pub text: String,
    /// Why the last commit was refused.
    pub error: Option<String>,
}
