//! The page's side of the files worker (`worker/`, issue #29): PLCopen
//! import and export run there, in a wasm of their own that the page
//! fetches the first time they are used, so the first screen does not
//! wait for them. Each request gets its reply through a callback; if the
//! worker cannot start (offline before the service worker kept it, a
//! blocked file) every waiting request is told so.

use std::cell::RefCell;
use std::collections::HashMap;

use files_worker::{Envelope, Reply, Request};
use leptos::prelude::{RwSignal, Set};
use leptos::wasm_bindgen::closure::Closure;
use leptos::wasm_bindgen::JsCast;
use web_sys::{MessageEvent, Worker, WorkerOptions, WorkerType};

use crate::i18n::Texts;

/// The loader Trunk writes for the worker (`index.html`'s worker asset).
const LOADER: &str = "./files_worker_loader.js";

/// What a request is told: the reply, or why there is none.
type Done = Box<dyn FnOnce(Result<Reply, String>)>;

struct Running {
    worker: Worker,
    next_id: u32,
    waiting: HashMap<u32, Done>,
    /// Requests written before the worker said it listens
    /// ([`files_worker::READY`]); `None` once it has.
    held: Option<Vec<String>>,
}

thread_local! {
    static RUNNING: RefCell<Option<Running>> = const { RefCell::new(None) };
}

/// Sends `request` to the worker (started on first use); `done` gets the
/// reply, or a sentence saying why there is none.
pub fn ask(request: Request, done: impl FnOnce(Result<Reply, String>) + 'static) {
    let mut done: Option<Done> = Some(Box::new(done));
    let sent = RUNNING.with(|running| {
        let mut running = running.borrow_mut();
        if running.is_none() {
            *running = Some(start()?);
        }
        let Some(r) = running.as_mut() else {
            return Err("not started".to_string());
        };
        let id = r.next_id;
        r.next_id = r.next_id.wrapping_add(1);
        let text =
            serde_json::to_string(&Envelope { id, body: request }).map_err(|e| e.to_string())?;
        match &mut r.held {
            Some(held) => held.push(text),
            None => r
                .worker
                .post_message(&text.into())
                .map_err(|e| format!("{e:?}"))?,
        }
        if let Some(done) = done.take() {
            r.waiting.insert(id, done);
        }
        Ok(())
    });
    if let (Err(why), Some(done)) = (sent, done) {
        done(Err(why));
    }
}

/// [`ask`], saying so on the page: `message` reads "Reading the
/// file…" while the worker works and says why when it cannot start;
/// `then` gets the reply (the message cleared).
pub fn ask_saying(
    message: RwSignal<Option<String>>,
    texts: &'static Texts,
    request: Request,
    then: impl FnOnce(Reply) + 'static,
) {
    message.set(Some(texts.files_loading.to_string()));
    ask(request, move |reply| match reply {
        Ok(reply) => {
            message.set(None);
            then(reply);
        }
        Err(why) => message.set(Some(format!("{} ({why})", texts.files_failed))),
    });
}

/// Starts the worker and listens to it for the page's life.
fn start() -> Result<Running, String> {
    let options = WorkerOptions::new();
    options.set_type(WorkerType::Module);
    let worker = Worker::new_with_options(LOADER, &options).map_err(|e| format!("{e:?}"))?;
    let on_message = Closure::<dyn Fn(MessageEvent)>::new(|event: MessageEvent| {
        let Some(text) = event.data().as_string() else {
            return;
        };
        if text == files_worker::READY {
            return RUNNING.with(|r| {
                if let Some(r) = r.borrow_mut().as_mut() {
                    for text in r.held.take().unwrap_or_default() {
                        // A refusal leaves its request waiting; none is
                        // expected for a string.
                        let _ = r.worker.post_message(&text.into());
                    }
                }
            });
        }
        let Ok(Envelope { id, body }) = serde_json::from_str::<Envelope<Reply>>(&text) else {
            return;
        };
        // Taken out before it runs: it may ask again.
        let done = RUNNING.with(|r| r.borrow_mut().as_mut()?.waiting.remove(&id));
        if let Some(done) = done {
            done(Ok(body));
        }
    });
    let on_error = Closure::<dyn Fn(web_sys::Event)>::new(|_| {
        // A worker that failed to load is dropped, so the next use tries
        // again (the network may be back).
        let waiting = RUNNING.with(|r| r.borrow_mut().take().map(|r| r.waiting));
        for (_, done) in waiting.into_iter().flatten() {
            done(Err("the worker did not start".to_string()));
        }
    });
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    on_message.forget();
    on_error.forget();
    Ok(Running {
        worker,
        next_id: 0,
        waiting: HashMap::new(),
        held: Some(Vec::new()),
    })
}
