//! The worker's entry: each message from the page is a request envelope
//! (JSON text, `files_worker::answer`); the reply goes back the same way.

#[cfg(target_arch = "wasm32")]
fn main() {
    use wasm_bindgen::closure::Closure;
    use wasm_bindgen::JsCast;
    use web_sys::{DedicatedWorkerGlobalScope, MessageEvent};

    let scope: DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
    let replier = scope.clone();
    let on_message = Closure::<dyn Fn(MessageEvent)>::new(move |event: MessageEvent| {
        let Some(text) = event.data().as_string() else {
            return;
        };
        if let Some(reply) = files_worker::answer(&text) {
            // The page is gone if this fails; nothing is waiting then.
            let _ = replier.post_message(&reply.into());
        }
    });
    scope.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    // It answers for the worker's life.
    on_message.forget();
    // The page holds its requests until this.
    let _ = scope.post_message(&files_worker::READY.into());
}

/// Natively there is no page to answer: the library is tested instead.
#[cfg(not(target_arch = "wasm32"))]
fn main() {
    eprintln!("files_worker runs in the browser, as the page's Web Worker");
}
