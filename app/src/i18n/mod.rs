//! The interface's two languages. Every visible string comes from here:
//! one table, [`Texts`], in English ([`en`]) and Japanese ([`ja`]).

pub mod classroom;
mod en;
pub mod engine;
pub mod errors;
mod files;
mod ja;
pub mod keymap;
pub mod parts;
pub mod plant;
pub mod plant_errors;
pub mod plant_faults;
pub mod plant_wiring;
pub mod st;
pub mod start;
pub mod words;

use en::EN;
use ja::JA;

/// A language of the interface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lang {
    /// 日本語.
    Ja,
    /// English.
    En,
}

impl Lang {
    /// The code used in the `lang` select and in storage.
    pub const fn code(self) -> &'static str {
        match self {
            Lang::Ja => "ja",
            Lang::En => "en",
        }
    }

    /// The language for a code; `None` for any other.
    pub fn from_code(code: &str) -> Option<Lang> {
        match code {
            "ja" => Some(Lang::Ja),
            "en" => Some(Lang::En),
            _ => None,
        }
    }

    /// The default for a browser language tag (`ja-JP` → Japanese).
    pub fn from_browser(tag: &str) -> Lang {
        if tag.to_ascii_lowercase().starts_with("ja") {
            Lang::Ja
        } else {
            Lang::En
        }
    }

    /// This language's strings.
    pub const fn texts(self) -> &'static Texts {
        match self {
            Lang::Ja => &JA,
            Lang::En => &EN,
        }
    }

    /// The start screen's, the tour's and the guide's strings (issue #47).
    pub const fn start(self) -> &'static start::StartTexts {
        match self {
            Lang::Ja => &start::JA,
            Lang::En => &start::EN,
        }
    }

    /// The key map's and the menus' key names (issue #49).
    pub const fn keys(self) -> &'static keymap::KeyTexts {
        match self {
            Lang::Ja => &keymap::JA,
            Lang::En => &keymap::EN,
        }
    }

    /// Words the page's code said in English (issue #49).
    pub const fn words(self) -> &'static words::Words {
        match self {
            Lang::Ja => &words::JA,
            Lang::En => &words::EN,
        }
    }

    /// The strings of the parts fetched on first use (issue #53).
    pub const fn parts(self) -> &'static parts::PartsTexts {
        match self {
            Lang::Ja => &parts::JA,
            Lang::En => &parts::EN,
        }
    }

    /// The plant dock's strings (issue #52).
    pub const fn plant(self) -> &'static plant::PlantTexts {
        match self {
            Lang::Ja => &plant::JA,
            Lang::En => &plant::EN,
        }
    }

    /// The plant's faults, fault report and manual mode (issue #52).
    pub const fn plant_faults(self) -> &'static plant_faults::PlantFaults {
        match self {
            Lang::Ja => &plant_faults::JA,
            Lang::En => &plant_faults::EN,
        }
    }

    /// The classroom's strings (exercises, writing tests; issue #49).
    pub const fn classroom(self) -> &'static classroom::Classroom {
        match self {
            Lang::Ja => &classroom::JA,
            Lang::En => &classroom::EN,
        }
    }

    /// The Structured Text pane's strings (issue #55).
    pub const fn st(self) -> &'static st::St {
        match self {
            Lang::Ja => &st::JA,
            Lang::En => &st::EN,
        }
    }
}

/// Every string the interface shows: the page and its machines first,
/// then the ladder editor's.
pub struct Texts {
    pub brand: &'static str,
    pub language: &'static str,
    pub example: &'static str,
    pub example_none: &'static str,
    pub example_seed: &'static str,
    pub undo_open: &'static str,
    pub speed: &'static str,
    pub speed_max: &'static str,
    pub pause: &'static str,
    pub resume: &'static str,
    pub power: &'static str,
    pub run: &'static str,
    pub halt: &'static str,
    pub reset: &'static str,
    pub slow: &'static str,
    pub fast: &'static str,
    pub clock: &'static str,
    pub write: &'static str,
    pub count_clear: &'static str,
    pub pc: &'static str,
    pub instruction: &'static str,
    pub accumulator: &'static str,
    pub inputs: &'static str,
    pub outputs: &'static str,
    pub counter: &'static str,
    pub counter_set: &'static str,
    pub tens: &'static str,
    pub ones: &'static str,
    pub dip: &'static str,
    pub timer: &'static str,
    pub seconds: &'static str,
    pub program: &'static str,
    pub load: &'static str,
    pub loaded: &'static str,
    pub not_loaded: &'static str,
    pub errors_none: &'static str,
    pub line: &'static str,
    pub sheet: &'static str,
    pub sheet_address: &'static str,
    pub sheet_opcode: &'static str,
    pub sheet_operand: &'static str,
    pub sheet_binary: &'static str,
    pub corrupt_saved: &'static str,
    pub storage_unavailable: &'static str,
    pub crashed: &'static str,
    pub sim_time: &'static str,
    pub scans: &'static str,
    /// The machine's state in the header's clock.
    pub state_running: &'static str,
    pub state_paused: &'static str,
    pub state_stopped: &'static str,
    pub machine: &'static str,
    pub terminal: &'static str,
    pub terminal_hint: &'static str,
    pub ctrl_c: &'static str,
    pub two_devices: &'static str,
    pub device_a: &'static str,
    pub device_b: &'static str,
    pub ir_remote: &'static str,
    pub analog_in: &'static str,
    pub servo: &'static str,
    pub pwm: &'static str,
    pub running: &'static str,
    pub stopped: &'static str,
    pub monitor: &'static str,
    pub monitor_hint: &'static str,
    pub enabled: &'static str,
    pub disabled: &'static str,
    pub quirk_sketch: &'static str,
    pub warn_spin: &'static str,
    pub warn_tof: &'static str,
    pub bits: &'static str,
    pub drive: &'static str,
    // The soft PLC's board and variables pane.
    pub soft_board: &'static str,
    /// The soft PLC's serial monitor's input line (LDmicro's UART).
    pub soft_monitor_hint: &'static str,
    /// The soft PLC's scan period field.
    pub soft_scan: &'static str,
    pub soft_push: &'static str,
    pub variables: &'static str,
    pub var_name: &'static str,
    pub var_type: &'static str,
    pub var_address: &'static str,
    pub var_initial: &'static str,
    pub var_comment: &'static str,
    pub var_value: &'static str,
    pub var_add: &'static str,
    pub var_remove: &'static str,
    pub var_force: &'static str,
    pub var_hint: &'static str,
    // The ladder editor.
    pub ladder: &'static str,
    pub new_ladder: &'static str,
    pub undo: &'static str,
    pub redo: &'static str,
    pub write_plc: &'static str,
    /// Said when Write to PLC has written the drawing and started it.
    pub written: &'static str,
    pub keys: &'static str,
    pub find: &'static str,
    pub listing: &'static str,
    pub listing_none: &'static str,
    pub problems: &'static str,
    pub problems_none: &'static str,
    pub palette: &'static str,
    pub rung: &'static str,
    pub step: &'static str,
    pub end: &'static str,
    pub load_as_ladder: &'static str,
    pub entry_open: &'static str,
    pub entry_closed: &'static str,
    pub entry_coil: &'static str,
    pub entry_instruction: &'static str,
    pub entry_branch: &'static str,
    pub cancel: &'static str,
    /// Commits the device entry (for touch, where no Return key shows).
    pub ok: &'static str,
    pub replace: &'static str,
    pub replace_with: &'static str,
    pub replace_apply: &'static str,
    pub xref: &'static str,
    pub copy_to: &'static str,
    pub device_comment: &'static str,
    pub rung_comment: &'static str,
    pub close: &'static str,
    pub share: &'static str,
    pub shared_note: &'static str,
    pub shared_keep: &'static str,
    pub shared_back: &'static str,
    pub shared_broken: &'static str,
    pub shared_kept: &'static str,
    /// Another tab saved newer work over this tab's own.
    pub conflict_note: &'static str,
    pub conflict_theirs: &'static str,
    pub conflict_mine: &'static str,
    /// Said when this tab's work was kept as a project of its own.
    pub conflict_kept: &'static str,
    /// The name of that project, after the one it came from.
    pub conflict_copy: &'static str,
    /// The storage is full or blocked: the work is only in the page.
    pub storage_full: &'static str,
    pub storage_blocked: &'static str,
    pub save_json: &'static str,
    pub open_file: &'static str,
    /// The File menu's heading over the exports (PLCopen, SVG, print …).
    pub export_as: &'static str,
    pub export_text: &'static str,
    pub print: &'static str,
    pub projects: &'static str,
    pub project_default: &'static str,
    pub project_name: &'static str,
    pub project_untitled: &'static str,
    pub project_new: &'static str,
    pub project_save_as: &'static str,
    pub project_open: &'static str,
    pub project_rename: &'static str,
    pub project_duplicate: &'static str,
    pub project_delete: &'static str,
    pub project_undo_delete: &'static str,
    pub project_delete_open: &'static str,
    pub shared_project: &'static str,
    pub tests: &'static str,
    pub run_tests: &'static str,
    pub add_test: &'static str,
    pub record_start: &'static str,
    pub record_stop: &'static str,
    pub exercise: &'static str,
    pub passed: &'static str,
    pub delete_test: &'static str,
    pub timeline: &'static str,
    pub expectations: &'static str,
    pub test_pass: &'static str,
    pub test_fail: &'static str,
    pub tests_need_compile: &'static str,
    /// The drawing has errors, so it is not what the machine runs.
    pub not_written: &'static str,
    pub run_drawing: &'static str,
    /// Stops the machine running the drawing.
    pub stop: &'static str,
    pub step_scan: &'static str,
    pub step_instr: &'static str,
    pub step_clock: &'static str,
    pub import_title: &'static str,
    /// While the files worker reads or writes a PLCopen file.
    pub files_loading: &'static str,
    /// Said when an LDmicro file's cycle is not the soft PLC's scan in
    /// the page (`{cycle}`: the file's, in ms).
    pub ld_cycle: &'static str,
    /// The files worker could not be started.
    pub files_failed: &'static str,
    pub import_pou: &'static str,
    pub import_pou_tasks: &'static str,
    pub import_variable: &'static str,
    pub import_device: &'static str,
    pub import_apply: &'static str,
    pub scan: &'static str,
    pub kept_from: &'static str,
    pub live: &'static str,
    pub step_back: &'static str,
    pub step_forward: &'static str,
    pub resume_here: &'static str,
    pub break_on: &'static str,
    pub break_hit: &'static str,
    pub why: &'static str,
    pub why_off: &'static str,
    pub why_on: &'static str,
    pub why_any: &'static str,
    pub why_all: &'static str,
    pub why_changed: &'static str,
    pub why_unchanged: &'static str,
    pub why_driven_by: &'static str,
    pub why_input: &'static str,
    pub why_none: &'static str,
    pub chart: &'static str,
    pub chart_add: &'static str,
    pub chart_follow: &'static str,
    pub chart_export: &'static str,
    pub zoom_in: &'static str,
    /// The end line's cells: "end of ladder, column" and the column.
    pub end_of_ladder: &'static str,
    /// The skip links at the top of the page.
    pub skip_ladder: &'static str,
    pub skip_panel: &'static str,
    /// A test case's name field.
    pub case_name: &'static str,
    /// The time travel slider's name.
    pub scan_slider: &'static str,
    /// The break field's example condition.
    pub break_example: &'static str,
    /// The ladder's zoom buttons: their group, and fitting a rung's width.
    pub zoom: &'static str,
    pub zoom_fit: &'static str,
    pub zoom_out: &'static str,
    pub pan_left: &'static str,
    pub pan_right: &'static str,
    pub watch: &'static str,
    pub forces: &'static str,
    pub release: &'static str,
    pub not_an_input: &'static str,
    pub menus: &'static str,
    pub menu_file: &'static str,
    pub menu_edit: &'static str,
    pub menu_view: &'static str,
    pub menu_help: &'static str,
    pub panel_dock: &'static str,
    pub tools_dock: &'static str,
    pub reset_docks: &'static str,
    pub colour_by_value: &'static str,
    pub colour_by_value_hint: &'static str,
    pub chart_time_axis: &'static str,
    pub dock_collapse: &'static str,
    pub dock_expand: &'static str,
    pub resize_dock: &'static str,
    pub run_controls: &'static str,
    pub step_scan_short: &'static str,
    pub step_instr_short: &'static str,
    pub step_clock_short: &'static str,
    pub scan_time: &'static str,
    pub toolbar: &'static str,
    pub io_strip: &'static str,
    pub io_strip_empty: &'static str,
    pub on: &'static str,
    pub off: &'static str,
    pub copy: &'static str,
    pub cut: &'static str,
    pub paste: &'static str,
    pub why_tab: &'static str,
    pub listing_problems: &'static str,
    pub program_tab: &'static str,
    pub cpu_tab: &'static str,
    pub panel_tab: &'static str,
    pub palette_search: &'static str,
    pub comments_tab: &'static str,
    pub run_needs_compile: &'static str,
}
