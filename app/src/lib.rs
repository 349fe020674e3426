//! Hashigo's web app: the workbench (app bar, the ladder editor in the
//! centre, the machine's panel and the tools in docks) and the simulation
//! loop. It renders and dispatches; the machine is the engine's.

pub mod appbar;
pub mod bench;
pub mod chrome;
pub mod docks;
pub mod editor;
pub mod examples;
pub mod i18n;
pub mod machines;
pub mod parts;
pub mod plant;
pub mod rig;
pub mod sim;
pub mod start;
pub mod state;
pub mod storage;
pub mod workbench;
pub mod worker;
pub mod workspaces;

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use leptos::prelude::*;
use leptos::wasm_bindgen::closure::Closure;
use leptos::wasm_bindgen::JsCast;

use appbar::{set_document_lang, AppBar};
use i18n::Lang;
use state::Ctx;
use workspaces::Workspaces;

/// Starts the page: the benchmark when the URL asks for `?bench`, else the
/// workspace with its simulation loop.
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        show_crash();
    }));
    // The first screen's machine; the others register with their parts.
    engine::machines::register(engine::machines::MachineKit::MINASEC);
    let search = web_sys::window()
        .and_then(|w| w.location().search().ok())
        .unwrap_or_default();
    if search.contains("bench") {
        leptos::mount::mount_to_body(bench::BenchPage);
        remove_loading_screen();
        return;
    }
    let ctx = page();
    let start = start::Start::new();
    // Asked before anything is restored or opened (which may save).
    start.open.set(start::first_visit(
        editor::shared::location_fragment().is_none(),
        nothing_saved(),
    ));
    // A returning visit's saved ladders are read first (their reader is
    // a part, issue #53); a first visit has none and starts at once.
    let saved = editor::files::store::saved_texts();
    if saved.is_empty() {
        begin(ctx, start);
    } else {
        // Not Leptos's executor: it is set up when the app mounts.
        wasm_bindgen_futures::spawn_local(read_then_begin(ctx, start, saved));
    }
}

/// Reads the saved ladders `saved`, then starts the page. While their
/// reader cannot be fetched the loading screen stays (it says what to
/// do after a while) and it is asked again: starting without them would
/// let the autosave write over them.
async fn read_then_begin(ctx: Ctx, start: start::Start, saved: Vec<(String, String)>) {
    while editor::files::reading::read_saved(saved.clone())
        .await
        .is_err()
    {
        sleep_ms(2_000).await;
    }
    begin(ctx, start);
}

/// Resolves after `ms` milliseconds.
async fn sleep_ms(ms: i32) {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Some(window) = web_sys::window() {
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms);
        }
    });
    // A promise that only resolves.
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}

/// Starts the page once what it restores is read: the workspaces, the
/// app mounted, the simulation loop.
fn begin(ctx: Ctx, start: start::Start) {
    let workspaces = Workspaces::restore(ctx);
    editor::shared::open_from_location(ctx, workspaces.ladders);
    // A link pasted into the address bar of the open page.
    let ladders = workspaces.ladders;
    let listener = window_event_listener(leptos::ev::hashchange, move |_| {
        editor::shared::open_from_location(ctx, ladders);
    });
    // It listens for the page's life.
    std::mem::forget(listener);
    listen_to_other_tabs(workspaces);
    leptos::mount::mount_to_body(
        move || view! { <App ctx=ctx workspaces=workspaces start=start /> },
    );
    remove_loading_screen();
    // After the first screen: its install fetches every file of the
    // release, which must not compete with the first screen's own.
    register_service_worker();
    start_loop(ctx, workspaces);
}

/// No machine's ladder and no project is saved in this profile.
fn nothing_saved() -> bool {
    engine::MachineId::ALL
        .iter()
        .all(|&m| storage::saved_string(&editor::files::store::key(m)).is_none())
        && storage::saved_string(editor::projects::INDEX_KEY).is_none()
}

/// Another tab of the page saved (the `storage` event, which only other
/// tabs get): each editor follows it or shows a conflict, and the project
/// list is read again.
fn listen_to_other_tabs(workspaces: Workspaces) {
    let listener = window_event_listener(leptos::ev::storage, move |e| {
        // `None`: the other tab cleared storage; nothing to follow.
        let Some(key) = e.key() else {
            return;
        };
        for machine in engine::MachineId::ALL {
            workspaces.ladders.of(machine).on_storage(&key);
        }
        if key == editor::projects::INDEX_KEY {
            workspaces.projects.reload();
        }
    });
    std::mem::forget(listener);
}

/// The loading screen of index.html gives way to the app.
/// The moment is marked `hashigo-ready` on the page's performance
/// timeline (the first-visit figures of docs/performance.md read it).
fn remove_loading_screen() {
    if let Some(el) = element_by_id("loading") {
        el.remove();
    }
    if let Some(performance) = web_sys::window().and_then(|w| w.performance()) {
        // Only a measurement: a browser without marks still runs the page.
        let _ = performance.mark("hashigo-ready");
    }
}

/// The page's element with `id`.
pub(crate) fn element_by_id(id: &str) -> Option<web_sys::Element> {
    web_sys::window()?.document()?.get_element_by_id(id)
}

/// Registers the service worker that keeps the page working offline
/// (`web/sw.js`); where the browser offers none (an insecure origin) the
/// page works online only.
fn register_service_worker() {
    let Some(window) = web_sys::window() else {
        return;
    };
    let navigator = window.navigator();
    let offered = js_sys::Reflect::get(&navigator, &"serviceWorker".into())
        .is_ok_and(|v| !v.is_undefined() && !v.is_null());
    if offered {
        // A refusal (private mode, a policy) leaves the page as it is.
        let _ = navigator.service_worker().register("sw.js");
    }
}

/// A panic must not leave a dead page: say so, in both languages.
fn show_crash() {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    let Some(body) = document.body() else {
        return;
    };
    if let Ok(div) = document.create_element("div") {
        div.set_class_name("fatal");
        let _ = div.set_attribute("role", "alert");
        let _ = div.set_attribute("data-testid", "fatal");
        div.set_text_content(Some(&format!(
            "{} / {}",
            Lang::Ja.texts().crashed,
            Lang::En.texts().crashed
        )));
        let _ = body.prepend_with_node_1(&div);
    }
}

/// The language: remembered, else the browser's.
fn initial_lang() -> Lang {
    storage::saved_lang()
        .as_deref()
        .and_then(Lang::from_code)
        .unwrap_or_else(|| {
            let tag = web_sys::window()
                .and_then(|w| w.navigator().language())
                .unwrap_or_default();
            Lang::from_browser(&tag)
        })
}

/// The page's state: the language and the machine shown, remembered.
pub fn page() -> Ctx {
    let lang = initial_lang();
    set_document_lang(lang);
    let ctx = Ctx::new(lang);
    if let Some(kind) = storage::saved_string(storage::MACHINE_KEY)
        .as_deref()
        .and_then(|code| state::MachineKind::parse(code).ok())
        .filter(|kind| engine::MachineId::ALL.contains(kind))
    {
        ctx.machine.set(kind);
    }
    ctx
}

/// The page: header, notices, and the chosen machine's workspace.
#[component]
pub fn App(ctx: Ctx, workspaces: Workspaces, start: start::Start) -> impl IntoView {
    provide_context(ctx);
    provide_context(start);
    workspaces.provide();
    // The machine shown arrives with its part (issue #53) if not there.
    Effect::new(move |_| workspaces.arrive(ctx.machine.get()));
    // An example chosen on the start screen opens in its workspace.
    Effect::new(move |_| {
        if let Some((machine, id)) = start.example.get() {
            untrack(|| examples::open(machine, &id, workspaces));
            start.example.set(None);
        }
    });
    view! {
        <ErrorBoundary fallback=move |_| {
            view! { <div class="fatal" role="alert">{move || ctx.lang.get().texts().crashed}</div> }
        }>
            <a class="skip" href="#ladder" on:click=move |e| skip_to(&e, "ladder")>
                {move || ctx.lang.get().texts().skip_ladder}
            </a>
            <a class="skip" href="#panel" on:click=move |e| skip_to(&e, "panel")>
                {move || ctx.lang.get().texts().skip_panel}
            </a>
            <AppBar />
            <Show when=move || ctx.notice.with(Option::is_some)>
                <div class="notice" role="alert" data-testid="notice">
                    {move || ctx.notice.get().unwrap_or_default()}
                </div>
            </Show>
            // On a phone the tour's card stands in the page's flow, above
            // the ladder; elsewhere it floats beside it.
            // The start screen, the tour and the guide are parts, fetched
            // when they first show (issue #53); each fetches its words too.
            <Show when=move || start.tour.with(Option::is_some)>
                {parts::part("tour-part", ctx.lang.into(), start::tour::part)}
            </Show>
            {move || workspaces.view(ctx.machine.get())}
            <Show when=move || start.open.get()>
                {parts::part("start-part", ctx.lang.into(), start::screen::part)}
            </Show>
            <Show when=move || start.guide.with(Option::is_some)>
                {parts::part("guide-part", ctx.lang.into(), start::guide::part)}
            </Show>
        </ErrorBoundary>
    }
}

/// A skip link: the focus goes to element `id`, and the address keeps its
/// fragment (which is where share links live).
fn skip_to(e: &web_sys::MouseEvent, id: &str) {
    e.prevent_default();
    let target = element_by_id(id).and_then(|el| el.dyn_into::<web_sys::HtmlElement>().ok());
    if let Some(el) = target {
        let _ = el.focus();
    }
}

/// Wall-clock milliseconds (`performance.now()`).
pub fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

/// The simulation loop: each animation frame advances the simulator by the
/// frame's wall time (at the chosen speed, capped) and copies the panel into
/// the signals that changed. At `Speed::Max` the simulation runs after the
/// frame is drawn instead, in a task of its own until shortly before the
/// next frame is due (`sim::Display`). Runs for the page's life.
pub fn start_loop(ctx: Ctx, workspaces: Workspaces) {
    type FrameFn = Closure<dyn FnMut(f64)>;
    let slot: Rc<RefCell<Option<FrameFn>>> = Rc::new(RefCell::new(None));
    let again = Rc::clone(&slot);
    let last = Cell::new(None::<f64>);
    let display = Cell::new(sim::Display::default());
    let deadline = Rc::new(Cell::new(0.0));
    let run_max = {
        let deadline = Rc::clone(&deadline);
        move || {
            let kind = ctx.machine.get_untracked();
            workspaces.after_frame(kind, ctx.pace(), deadline.get(), now_ms);
        }
    };
    let after_frame = AfterFrame::new(run_max.clone());
    *slot.borrow_mut() = Some(Closure::new(move |timestamp: f64| {
        let wall_ms = last.replace(Some(timestamp)).map_or(0.0, |l| timestamp - l);
        let mut d = display.get();
        d.learn(wall_ms);
        display.set(d);
        let pace = ctx.pace();
        workspaces.frame(ctx.machine.get_untracked(), pace, wall_ms, now_ms);
        if pace.speed == sim::Speed::Max && !pace.paused {
            deadline.set(d.deadline(timestamp));
            match after_frame.as_ref() {
                Some(after) => after.post(),
                None => run_max(),
            }
        }
        if let Some(f) = again.borrow().as_ref() {
            request_frame(f);
        }
    }));
    let first = slot.borrow();
    if let Some(f) = first.as_ref() {
        request_frame(f);
    }
}

/// A task posted from an animation frame, which the browser runs once the
/// frame is drawn (a message to the page itself: a timer could be held
/// back, an idle callback skipped while the page is busy).
struct AfterFrame {
    port: web_sys::MessagePort,
    /// The channel's other end and what it calls, kept for the page's life.
    _receiver: (web_sys::MessagePort, Closure<dyn FnMut()>),
}

impl AfterFrame {
    /// `run` as the task; `None` where the browser has no message channel.
    fn new(run: impl FnMut() + 'static) -> Option<AfterFrame> {
        let channel = web_sys::MessageChannel::new().ok()?;
        let run = Closure::<dyn FnMut()>::new(run);
        let receiver = channel.port1();
        receiver.set_onmessage(Some(run.as_ref().unchecked_ref()));
        Some(AfterFrame {
            port: channel.port2(),
            _receiver: (receiver, run),
        })
    }

    /// Asks for the task to run once.
    fn post(&self) {
        let _ = self.port.post_message(&wasm_bindgen::JsValue::NULL);
    }
}

fn request_frame(f: &Closure<dyn FnMut(f64)>) {
    if let Some(window) = web_sys::window() {
        let _ = window.request_animation_frame(f.as_ref().unchecked_ref());
    }
}
