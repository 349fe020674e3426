//! Component tests in a real browser (`wasm-pack test --headless --chrome`):
//! mount the workspace, drive it with DOM events, assert the DOM and the
//! machine behind it.

use engine::minasec::{Command, Mode, TimerId};
use engine::SimTime;
use leptos::prelude::*;
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{Element, HtmlElement};

use app::i18n::Lang;
use app::machines::minasec::MinasecCtx;
use app::sim::Simulator;
use app::state::Ctx;
use app::workspaces::Workspaces;
use app::App;
use engine::plc::Plc;

wasm_bindgen_test_configure!(run_in_browser);

fn document() -> web_sys::Document {
    web_sys::window().unwrap().document().unwrap()
}

/// Mounts a fresh workspace (no frame loop: tests advance time themselves)
/// into its own container and returns the context and the container.
fn mount() -> (Ctx, MinasecCtx, Element) {
    let (ctx, workspaces, container) = mount_workspaces();
    (ctx, workspaces.minasec, container)
}

/// Mounts every workspace; returns them all.
fn mount_workspaces() -> (Ctx, Workspaces, Element) {
    if let Some(store) = web_sys::window().unwrap().local_storage().unwrap() {
        store.clear().unwrap();
    }
    let container = document().create_element("div").unwrap();
    document().body().unwrap().append_child(&container).unwrap();
    let ctx = Ctx::new(Lang::En);
    let workspaces = Workspaces::around(
        ctx,
        MinasecCtx::new(
            ctx,
            Simulator::new(engine::machines::MinasecPlc::with(
                engine::minasec::Machine::new(),
            )),
        ),
    );
    let html: HtmlElement = container.clone().unchecked_into();
    let handle = leptos::mount::mount_to(
        html,
        move || view! { <App ctx=ctx workspaces=workspaces start=app::start::Start::new() /> },
    );
    handle.forget();
    (ctx, workspaces, container)
}

fn find(container: &Element, testid: &str) -> HtmlElement {
    container
        .query_selector(&format!("[data-testid=\"{testid}\"]"))
        .unwrap()
        .unwrap_or_else(|| panic!("no element {testid}"))
        .unchecked_into()
}

/// The element with `testid` in the menu `menu`, whose controls are drawn
/// at its first opening (a part, issue #53): the menu opened (and closed
/// again) first.
async fn in_menu(container: &Element, menu: &str, testid: &str) -> HtmlElement {
    let button = find(container, &format!("menu-{menu}"));
    button.click();
    button.click();
    for _ in 0..10 {
        settle().await;
    }
    find(container, testid)
}

fn attr(container: &Element, testid: &str, name: &str) -> String {
    find(container, testid)
        .get_attribute(name)
        .unwrap_or_default()
}

/// Lets scheduled reactive work run.
async fn settle() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        web_sys::window()
            .unwrap()
            .set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, 0)
            .unwrap();
    });
    wasm_bindgen_futures::JsFuture::from(promise).await.unwrap();
}

fn pointer(target: &HtmlElement, kind: &str) {
    let init = web_sys::PointerEventInit::new();
    init.set_bubbles(true);
    let event = web_sys::PointerEvent::new_with_event_init_dict(kind, &init).unwrap();
    target.dispatch_event(&event).unwrap();
}

fn key(target: &HtmlElement, kind: &str, key: &str) {
    let init = web_sys::KeyboardEventInit::new();
    init.set_bubbles(true);
    init.set_key(key);
    let event = web_sys::KeyboardEvent::new_with_keyboard_event_init_dict(kind, &init).unwrap();
    target.dispatch_event(&event).unwrap();
}

fn change(target: &HtmlElement, kind: &str) {
    let init = web_sys::EventInit::new();
    init.set_bubbles(true);
    let event = web_sys::Event::new_with_event_init_dict(kind, &init).unwrap();
    target.dispatch_event(&event).unwrap();
}

#[wasm_bindgen_test]
async fn a_click_on_an_input_switch_toggles_it_and_the_terminal() {
    let (_ctx, board, c) = mount();
    let x02 = find(&c, "input-X02");
    pointer(&x02, "pointerdown");
    pointer(&x02, "pointerup");
    settle().await;
    assert_eq!(attr(&c, "input-X02", "aria-pressed"), "true");
    assert_eq!(
        board
            .sim
            .with_value(|s| s.machine().shown_machine().machine().input_terminals()),
        0b100
    );
    pointer(&x02, "pointerdown");
    pointer(&x02, "pointerup");
    settle().await;
    assert_eq!(attr(&c, "input-X02", "aria-pressed"), "false");
    assert_eq!(
        board
            .sim
            .with_value(|s| s.machine().shown_machine().machine().input_terminals()),
        0
    );
}

#[wasm_bindgen_test]
async fn lamps_and_leds_follow_the_machine_without_being_replaced() {
    let (_ctx, board, c) = mount();
    board.text.set("LD X00\nST Y03\n".to_string());
    assert!(board.load_text());
    board.send(Command::SetInput(0, true));
    board.send(Command::SetMode(Mode::Run));
    let lamp_before = find(&c, "lamp-Y03");
    assert_eq!(attr(&c, "lamp-Y03", "data-on"), "0");
    board
        .sim
        .update_value(|s| s.machine_mut().tick(SimTime::from_millis(20)));
    board.refresh();
    settle().await;
    assert_eq!(attr(&c, "lamp-Y03", "data-on"), "1");
    assert!(
        lamp_before.is_same_node(Some(&find(&c, "lamp-Y03"))),
        "updated in place"
    );
    assert_eq!(attr(&c, "lamp-Y00", "data-on"), "0");
}

#[wasm_bindgen_test]
async fn knobs_are_sliders_driven_by_the_keyboard() {
    let (_ctx, board, c) = mount();
    let rv1 = find(&c, "rv1");
    assert_eq!(attr(&c, "rv1", "role"), "slider");
    assert_eq!(attr(&c, "rv1", "aria-valuemin"), "0.10");
    assert_eq!(attr(&c, "rv1", "aria-valuemax"), "1.10");
    key(&rv1, "keydown", "End");
    settle().await;
    assert_eq!(attr(&c, "rv1", "aria-valuenow"), "1.10");
    let delay = board.sim.with_value(|s| {
        s.machine()
            .shown_machine()
            .machine()
            .timer(TimerId::T0)
            .delay()
    });
    assert_eq!(delay, SimTime::from_millis(1100));
    key(&rv1, "keydown", "ArrowDown");
    settle().await;
    assert_eq!(attr(&c, "rv1", "aria-valuenow"), "1.09");
    key(&rv1, "keydown", "Home");
    settle().await;
    assert_eq!(attr(&c, "rv1", "aria-valuenow"), "0.10");

    let ones = find(&c, "counter-set-ones");
    key(&ones, "keydown", "ArrowUp");
    key(&ones, "keydown", "ArrowUp");
    settle().await;
    assert_eq!(attr(&c, "counter-set-ones", "aria-valuenow"), "2");
    assert_eq!(
        board
            .sim
            .with_value(|s| s.machine().shown_machine().machine().counter().set_value()),
        2
    );
}

#[wasm_bindgen_test]
async fn the_clock_button_steps_one_instruction_per_press() {
    let (_ctx, board, c) = mount();
    assert_eq!(
        board
            .sim
            .with_value(|s| s.machine().shown_machine().machine().mode()),
        Mode::Halt
    );
    let button = find(&c, "clock-button");
    pointer(&button, "pointerdown");
    settle().await;
    assert_eq!(
        attr(&c, "pc-led-0", "data-on"),
        "0",
        "the PC moves on release"
    );
    pointer(&button, "pointerup");
    settle().await;
    assert_eq!(attr(&c, "pc-led-0", "data-on"), "1");
    key(&button, "keydown", " ");
    key(&button, "keyup", " ");
    settle().await;
    assert_eq!(attr(&c, "pc-led-0", "data-on"), "0");
    assert_eq!(attr(&c, "pc-led-1", "data-on"), "1");
}

#[wasm_bindgen_test]
async fn program_errors_appear_as_you_type_and_block_loading() {
    let (_ctx, _board, c) = mount();
    let text: web_sys::HtmlTextAreaElement = find(&c, "program-text").unchecked_into();
    text.set_value("LD X00\nST Q1\n");
    change(&text.clone().unchecked_into(), "input");
    settle().await;
    let errors = find(&c, "program-error").text_content().unwrap_or_default();
    assert!(
        errors.contains("line 2") && errors.contains("Q1"),
        "{errors}"
    );
    let load: web_sys::HtmlButtonElement = find(&c, "program-load").unchecked_into();
    assert!(load.disabled());
    text.set_value("LD X00\nST Y01\n");
    change(&text.clone().unchecked_into(), "input");
    settle().await;
    assert!(!load.disabled());
    assert_eq!(
        find(&c, "program-error").text_content().unwrap_or_default(),
        "no errors"
    );
}

#[wasm_bindgen_test]
async fn opening_the_seed_example_sets_the_panel_and_can_be_undone() {
    let (_ctx, board, c) = mount();
    board.text.set("; my own work\nLD X07\n".to_string());
    let select: web_sys::HtmlSelectElement = in_menu(&c, "file", "example").await.unchecked_into();
    select.set_value("seed-test");
    change(&select.clone().unchecked_into(), "change");
    settle().await;
    assert_eq!(
        board.text.get_untracked(),
        engine::minasec::SEED_TEST_PROGRAM
    );
    assert_eq!(attr(&c, "rv1", "aria-valuenow"), "1.10");
    assert_eq!(attr(&c, "rv2", "aria-valuenow"), "1.0");
    assert_eq!(attr(&c, "counter-set-tens", "aria-valuenow"), "1");
    assert_eq!(select.value(), "", "the select returns to its prompt");
    let memory = board
        .sim
        .with_value(|s| *s.machine().shown_machine().machine().memory());
    assert_eq!(memory[1], 0b100_01000, "loaded into the board");
    find(&c, "example-undo").click();
    settle().await;
    assert_eq!(board.text.get_untracked(), "; my own work\nLD X07\n");
}

#[wasm_bindgen_test]
async fn the_language_select_switches_every_label() {
    let (_ctx, _board, c) = mount();
    assert_eq!(
        find(&c, "program-load").text_content().unwrap(),
        "Load into the board"
    );
    let select: web_sys::HtmlSelectElement = in_menu(&c, "view", "lang").await.unchecked_into();
    select.set_value("ja");
    change(&select.clone().unchecked_into(), "change");
    settle().await;
    assert_eq!(find(&c, "program-load").text_content().unwrap(), "書き込む");
}

#[wasm_bindgen_test]
async fn the_seven_segment_display_shows_the_count() {
    let (_ctx, board, c) = mount();
    board.text.set("LD X00\nST C0\n".to_string());
    assert!(board.load_text());
    board.send(Command::SetCounterPreset(5, 0));
    board.send(Command::SetMode(Mode::Run));
    for _ in 0..3 {
        board.send(Command::SetInput(0, true));
        board
            .sim
            .update_value(|s| s.machine_mut().tick(SimTime::from_millis(20)));
        board.send(Command::SetInput(0, false));
        board
            .sim
            .update_value(|s| s.machine_mut().tick(SimTime::from_millis(20)));
    }
    board.refresh();
    settle().await;
    assert_eq!(find(&c, "seg7").text_content().unwrap(), "03");
    board.send(Command::Power(false));
    settle().await;
    assert_eq!(
        find(&c, "seg7").text_content().unwrap(),
        "",
        "dark without power"
    );
}

#[wasm_bindgen_test]
async fn the_io86a_workspace_runs_its_terminal() {
    let (ctx, workspaces, c) = mount_workspaces();
    ctx.machine.set(app::state::MachineKind::Io86a);
    settle().await;
    // Its workspace arrived when it was shown (issue #53).
    let shown = workspaces
        .workspace(engine::MachineId::Io86a)
        .expect("the IO86A workspace is there once shown");
    let io = *shown
        .as_any()
        .downcast_ref::<app::machines::io86a::Io86aCtx>()
        .expect("the IO86A workspace's context");
    io.type_line("^C");
    io.type_line("NA");
    for line in ["LD M57", "OUT Y05", "END", "Q", "R"] {
        io.type_line(line);
    }
    io.sim
        .update_value(|s| s.machine_mut().tick(SimTime::from_millis(5)));
    io.refresh();
    settle().await;
    assert_eq!(attr(&c, "io86a-lamp-Y05", "data-on"), "1");
    let screen = find(&c, "io86a-terminal")
        .text_content()
        .unwrap_or_default();
    assert!(screen.contains("LD M57"), "{screen}");
    assert!(screen.ends_with("R>"), "{screen}");
}

/// Every drawn cell of the ladder in `container`, by its test id.
fn ladder_cells(container: &Element) -> Vec<(String, Element)> {
    let list = container
        .query_selector_all("[data-testid=ladder] [data-testid^=cell-]")
        .unwrap();
    (0..list.length())
        .filter_map(|i| list.item(i))
        .map(|n| {
            let e: Element = n.unchecked_into();
            (e.get_attribute("data-testid").unwrap(), e)
        })
        .collect()
}

#[wasm_bindgen_test]
async fn an_edit_redraws_only_the_cells_it_changed() {
    use engine::ladder::edit::{Cursor, Edit};
    use engine::ladder::Element as Part;
    let (_ctx, workspaces, c) = mount_workspaces();
    let ladder = workspaces.ladders.of(engine::MachineId::MinasecU);
    for (rung, input, output) in [(0, "X00", "Y00"), (1, "X01", "Y01")] {
        assert!(ladder.apply(Edit::Place {
            at: Cursor::new(rung, 0, 0),
            element: Part::no(input),
        }));
        assert!(ladder.apply(Edit::Place {
            at: Cursor::new(rung, 0, 1),
            element: Part::coil(output),
        }));
    }
    settle().await;
    let before = ladder_cells(&c);
    assert!(
        before.len() > 40,
        "two rungs of two rows and ten columns, and the end line"
    );
    assert_eq!(attr(&c, "cell-1-0-0", "data-device"), "X01");

    // One cell changes: only its node is new.
    assert!(ladder.apply(Edit::Place {
        at: Cursor::new(1, 0, 0),
        element: Part::nc("X02"),
    }));
    settle().await;
    assert_eq!(attr(&c, "cell-1-0-0", "data-kind"), "nc");
    let mut redrawn = Vec::new();
    for (id, node) in &before {
        let now = find(&c, id);
        if !node.is_same_node(Some(&now)) {
            redrawn.push(id.clone());
        }
    }
    assert_eq!(redrawn, vec!["cell-1-0-0".to_string()]);

    // A rung inserted above: every cell keeps its node, renumbered.
    let coil = find(&c, "cell-0-0-9");
    assert!(ladder.apply(Edit::InsertRung { index: 0 }));
    settle().await;
    let moved = find(&c, "cell-1-0-9");
    assert!(
        coil.is_same_node(Some(&moved)),
        "the rung moved down, not redrawn"
    );
    assert_eq!(attr(&c, "cell-1-0-9", "data-device"), "Y00");
    assert_eq!(
        attr(&c, "cell-1-0-9", "aria-label"),
        "rung 2, row 1, column 10: coil Y00"
    );
    // The cursor is one cell: aria-selected on it alone.
    let selected = c
        .query_selector_all("[data-testid=ladder] [aria-selected=true]")
        .unwrap();
    assert_eq!(selected.length(), 1);
}

/// The timing chart's rows, top to bottom, by test id.
fn chart_rows(container: &Element) -> Vec<String> {
    let list = find(container, "timing-chart")
        .query_selector_all("[data-testid^=chart-row-]")
        .unwrap();
    (0..list.length())
        .filter_map(|i| list.item(i))
        .map(|n| {
            n.unchecked_into::<Element>()
                .get_attribute("data-testid")
                .unwrap()
        })
        .collect()
}

#[wasm_bindgen_test]
async fn the_timing_chart_follows_an_edit_without_waiting_for_a_frame() {
    use engine::ladder::edit::{Cursor, Edit};
    use engine::ladder::Element as Part;
    // No frame loop here: only the edit itself can redraw the chart.
    let (ctx, workspaces, c) = mount_workspaces();
    let ladder = workspaces.ladders.of(engine::MachineId::MinasecU);
    // The chart is drawn when its tab is first shown (a part, issue #53).
    ctx.docks.show(app::docks::Tool::Chart);
    for _ in 0..10 {
        settle().await;
    }
    assert!(chart_rows(&c).is_empty(), "an empty ladder has no devices");
    assert!(ladder.apply(Edit::Place {
        at: Cursor::new(0, 0, 0),
        element: Part::no("X00"),
    }));
    assert!(ladder.apply(Edit::Place {
        at: Cursor::new(0, 0, 1),
        element: Part::coil("Y00"),
    }));
    settle().await;
    assert_eq!(
        chart_rows(&c),
        ["chart-row-Y00", "chart-row-X00"],
        "outputs first"
    );
    // Undone, the coil's row goes with it.
    ladder.undo();
    settle().await;
    assert_eq!(chart_rows(&c), ["chart-row-X00"]);
}
