//! Parts of the page fetched on first use (issue #53): each function
//! marked `#[wasm_split(<part>, …, fallible)]` lands in the wasm of
//! `<part>`, which the build cuts off the page's wasm
//! (scripts/split-wasm.py, docs/performance.md "Parts"); calling it
//! fetches that part first. A view part answers with the function that
//! draws it ([`Draw`]), which [`part`] calls once the part is there.

use std::future::Future;

use leptos::prelude::*;
use leptos::wasm_split::SplitLoaderError;

use crate::i18n::Lang;

/// Declares `fn $name` as held in part `$part`: with the feature `split`
/// (the page's Trunk build, which splits the wasm) a
/// `#[wasm_split($part, …, fallible)]` function, fetched at its first
/// call; without it (native tests, the wasm-bindgen tests, which run one
/// unsplit wasm that has no parts' loader to import) a plain `async fn`.
/// Either way an `async fn` returning `Result<_, PartMissing>`.
macro_rules! part_fn {
    ($part:ident, $(#[$meta:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty $body:block) => {
        $(#[$meta])*
        #[cfg(feature = "split")]
        #[::leptos::wasm_split::wasm_split($part, wasm_split_path = ::leptos::wasm_split, fallible)]
        $vis fn $name($($arg: $ty),*) -> $ret $body

        $(#[$meta])*
        #[cfg(not(feature = "split"))]
        $vis async fn $name($($arg: $ty),*) -> $ret $body
    };
}
pub(crate) use part_fn;

/// A part that could not be fetched (offline on a first visit, a server
/// gone): the caller says so where it was asked for and offers to retry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PartMissing;

impl From<SplitLoaderError> for PartMissing {
    fn from(_: SplitLoaderError) -> Self {
        PartMissing
    }
}

/// Draws a view held in a part; a plain function pointer, so that it
/// crosses from the part to the page as a table index.
pub type Draw = fn() -> AnyView;

/// Draws a view held in a part from what the page gives it (a dock
/// pane's context): a plain function pointer, as [`Draw`].
pub type DrawFor<A> = fn(A) -> AnyView;

/// Where a part's view stands.
#[derive(Debug, Clone, Copy)]
enum Stage<D> {
    Loading,
    Missing,
    Ready(D),
}

/// The place of a view held in a part: "Loading…" while it is fetched,
/// then the view; if it cannot be fetched, says so with a retry button
/// (nothing else on the page changes, so nothing the user made is lost).
/// `testid` names the place for the end-to-end tests; `lang` is the
/// page's language.
pub fn part<F, Fut>(testid: &'static str, lang: Signal<Lang>, load: F) -> impl IntoView
where
    F: Fn() -> Fut + Copy + Send + Sync + 'static,
    Fut: Future<Output = Result<Draw, PartMissing>> + 'static,
{
    place(testid, lang, load, |draw: Draw| draw())
}

/// [`part`] for a view drawn from `arg` (a pane's context and callbacks).
pub fn part_for<A, F, Fut>(
    testid: &'static str,
    lang: Signal<Lang>,
    arg: A,
    load: F,
) -> impl IntoView
where
    A: Copy + Send + Sync + 'static,
    F: Fn() -> Fut + Copy + Send + Sync + 'static,
    Fut: Future<Output = Result<DrawFor<A>, PartMissing>> + 'static,
{
    place(testid, lang, load, move |draw: DrawFor<A>| draw(arg))
}

/// What [`part`] and [`part_for`] share: fetches with `load`, then shows
/// what it gave with `show`.
fn place<D, F, Fut>(
    testid: &'static str,
    lang: Signal<Lang>,
    load: F,
    show: impl Fn(D) -> AnyView + Send + Sync + 'static,
) -> impl IntoView
where
    D: Copy + Send + Sync + 'static,
    F: Fn() -> Fut + Copy + Send + Sync + 'static,
    Fut: Future<Output = Result<D, PartMissing>> + 'static,
{
    let stage = RwSignal::new(Stage::Loading);
    let fetch = move || {
        stage.set(Stage::Loading);
        leptos::task::spawn_local(async move {
            let next = match load().await {
                Ok(draw) => Stage::Ready(draw),
                Err(PartMissing) => Stage::Missing,
            };
            // The place may be gone by now (its tab closed): nothing to show.
            let _ = stage.try_set(next);
        });
    };
    fetch();
    let retry = Callback::new(move |()| fetch());
    move || match stage.get() {
        Stage::Ready(draw) => show(draw),
        Stage::Loading => not_there(testid, lang.get(), false, retry),
        Stage::Missing => not_there(testid, lang.get(), true, retry),
    }
}

/// The place of something a part brings while the part is not there, in
/// `lang`: "Loading…" (`<testid>-loading`), or when it could not be
/// fetched (`missing`) says so with a button that calls `retry`
/// (`<testid>-missing`, `<testid>-retry`).
pub fn not_there(testid: &'static str, lang: Lang, missing: bool, retry: Callback<()>) -> AnyView {
    let texts = lang.parts();
    if missing {
        view! {
            <div class="part-state" role="alert" data-testid=format!("{testid}-missing")>
                <p>{texts.missing}</p>
                <button type="button" data-testid=format!("{testid}-retry") on:click=move |_| retry.run(())>
                    {texts.retry}
                </button>
            </div>
        }
        .into_any()
    } else {
        view! {
            <p class="part-state" role="status" data-testid=format!("{testid}-loading")>
                {texts.loading}
            </p>
        }
        .into_any()
    }
}
