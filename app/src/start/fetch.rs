//! Static files the page fetches on first use (the start screen, the
//! guide): each is fetched once per page and kept; the service worker
//! keeps a copy for offline use (web/sw.js).

use std::collections::HashMap;

use leptos::prelude::*;

use crate::state::Ctx;
use leptos::wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

/// Why a file could not be had.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FetchError {
    /// No network and no copy kept (the browser's fetch failed).
    Network,
    /// The server answered with this HTTP status.
    Status(u16),
}

/// What a fetch has given so far.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Fetched {
    /// Under way.
    Loading,
    /// The file's text.
    Text(String),
    /// It failed: the place shows the error and offers to retry.
    Failed(FetchError),
}

/// Files fetched, by URL, kept for the page's life.
#[derive(Clone, Copy)]
pub struct Files {
    kept: StoredValue<HashMap<String, String>>,
}

impl Files {
    /// Nothing fetched yet.
    pub fn new() -> Files {
        Files {
            kept: StoredValue::new(HashMap::new()),
        }
    }

    /// Sets `into` to the text of `url`: at once if kept, else after the
    /// fetch (a failed one is not kept, so a retry fetches again).
    pub fn load(&self, url: &str, into: RwSignal<Fetched>) {
        if let Some(text) = self.kept.with_value(|k| k.get(url).cloned()) {
            into.set(Fetched::Text(text));
            return;
        }
        into.set(Fetched::Loading);
        let kept = self.kept;
        let url = url.to_string();
        leptos::task::spawn_local(async move {
            match text(&url).await {
                Ok(body) => {
                    kept.update_value(|k| {
                        k.insert(url, body.clone());
                    });
                    // The screen that asked may be closed by now.
                    let _ = into.try_set(Fetched::Text(body));
                }
                Err(e) => {
                    let _ = into.try_set(Fetched::Failed(e));
                }
            }
        });
    }
}

impl Default for Files {
    fn default() -> Files {
        Files::new()
    }
}

/// The text of `url` (a path on the page's own origin).
async fn text(url: &str) -> Result<String, FetchError> {
    let window = web_sys::window().ok_or(FetchError::Network)?;
    let response = JsFuture::from(window.fetch_with_str(url))
        .await
        .map_err(|_| FetchError::Network)?;
    let response: web_sys::Response = response.dyn_into().map_err(|_| FetchError::Network)?;
    if !response.ok() {
        return Err(FetchError::Status(response.status()));
    }
    let body = response.text().map_err(|_| FetchError::Network)?;
    let body = JsFuture::from(body)
        .await
        .map_err(|_| FetchError::Network)?;
    body.as_string().ok_or(FetchError::Network)
}

/// The start screen's, the tour's and the guide's style sheet: linked in
/// the page when one of them first shows, so the first screen's styles
/// do not carry it.
pub fn ensure_style() {
    const ID: &str = "start-css";
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if document.get_element_by_id(ID).is_some() {
        return;
    }
    let (Ok(link), Some(head)) = (document.create_element("link"), document.head()) else {
        return;
    };
    link.set_id(ID);
    let _ = link.set_attribute("rel", "stylesheet");
    let _ = link.set_attribute("href", "start/start.css");
    let _ = head.append_child(&link);
}

/// "Loading…", or the failure with a retry, for a fetched file.
#[component]
pub fn FetchState(
    fetched: RwSignal<Fetched>,
    retry: impl Fn() + Copy + Send + Sync + 'static,
) -> impl IntoView {
    let ctx = Ctx::get();
    let s = move || ctx.lang.get().start();
    move || {
        match fetched.get() {
        Fetched::Loading => view! { <p class="muted" role="status">{s().loading}</p> }.into_any(),
        Fetched::Failed(_) => view! {
            <p class="fetch-failed" role="alert" data-testid="fetch-failed">
                {s().fetch_failed} " "
                <button type="button" data-testid="fetch-retry" on:click=move |_| retry()>{s().retry}</button>
            </p>
        }
        .into_any(),
        Fetched::Text(_) => ().into_any(),
    }
    }
}
