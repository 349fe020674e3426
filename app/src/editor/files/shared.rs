//! Share links: the Share button puts a URL whose fragment holds the
//! whole project (ladder, comments, machine, settings) in
//! `[data-testid=share-url]` and on the clipboard; a page opened with such
//! a fragment shows the project as unsaved work under a banner, to keep or
//! to leave. The fragment never reaches a server (browsers do not send
//! it), and opening a link never overwrites the autosaved ladder: saving
//! waits for "Keep", which first sets the old ladder aside.

use engine::formats::share::ShareError;
use engine::formats::Project;
use leptos::prelude::*;

use crate::editor::{LadderCtx, Ladders};
use crate::parts::PartMissing;
use crate::state::Ctx;

crate::parts::part_fn!(
    share_codec,
    /// A share link read: the codec (its deflate and base64 too) is a
    /// part of its own (issue #53), fetched when a link is first opened
    /// or made.
    fn decode(fragment: String) -> Result<Result<Project, ShareError>, PartMissing> {
        Ok(engine::formats::share::decode(&fragment))
    }
);

crate::parts::part_fn!(
    share_codec,
    /// A share link made (see [`decode`]).
    pub(crate) fn encode(project: Project) -> Result<Result<String, ShareError>, PartMissing> {
        Ok(engine::formats::share::encode(&project))
    }
);

/// What a share link's codec said, or that it could not be fetched, in
/// the page's language.
pub(crate) fn codec_failed(lang: crate::i18n::Lang, e: Result<ShareError, PartMissing>) -> String {
    match e {
        Ok(e) => crate::i18n::errors::share_error(lang, &e),
        Err(PartMissing) => lang.parts().missing.to_string(),
    }
}

/// The fragment of the page's URL, without `#`, when it has one.
pub fn location_fragment() -> Option<String> {
    let hash = web_sys::window()?.location().hash().ok()?;
    let fragment = hash.strip_prefix('#').unwrap_or(&hash).to_string();
    (!fragment.is_empty()).then_some(fragment)
}

/// Removes the fragment from the address bar (the page stays).
fn clear_fragment() {
    let Some(window) = web_sys::window() else {
        return;
    };
    let Ok(history) = window.history() else {
        return;
    };
    let location = window.location();
    let path = format!(
        "{}{}",
        location.pathname().unwrap_or_default(),
        location.search().unwrap_or_default()
    );
    let _ = history.replace_state_with_url(&leptos::wasm_bindgen::JsValue::NULL, "", Some(&path));
}

/// Opens the project in the page's fragment, if there is one: its machine
/// is shown with the project's ladder, unsaved, under the banner. A
/// fragment that does not read is reported and changes nothing.
pub fn open_from_location(page: Ctx, ladders: Ladders) {
    let Some(fragment) = location_fragment() else {
        return;
    };
    // A student's answer (`?answer`): checked at once for the teacher,
    // from the ladder itself (the link carries no verdict to forge).
    let answer = web_sys::window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|q| q.trim_start_matches('?').split('&').any(|p| p == "answer"));
    open_then(page, ladders, fragment, move |ctx| {
        if answer && ctx.cases.exercise.get_untracked().is_some() {
            // Its machine may still be on its way (its part).
            ctx.when_attached(move || crate::editor::panes::cases::run_all(ctx));
            let c = page.lang.get_untracked().classroom();
            page.notice.set(Some(c.answer_of.to_string()));
        }
    });
}

/// The link a student sends back: the page with `?answer` and `fragment`
/// (their ladder, the exercise and its tests), checked when opened.
pub fn answer_url(fragment: &str) -> String {
    let Some(window) = web_sys::window() else {
        return format!("?answer#{fragment}");
    };
    let l = window.location();
    format!(
        "{}{}?answer#{fragment}",
        l.origin().unwrap_or_default(),
        l.pathname().unwrap_or_default()
    )
}

/// Opens share text `fragment` (see [`open_from_location`]).
pub fn open_fragment(page: Ctx, ladders: Ladders, fragment: &str) {
    open_then(page, ladders, fragment.to_string(), |_| ());
}

/// Opens share text `fragment` once its codec is there, then calls
/// `then` with the editor that shows it. A link that does not read, or
/// whose codec cannot be fetched, is reported and changes nothing.
fn open_then(
    page: Ctx,
    ladders: Ladders,
    fragment: String,
    then: impl FnOnce(LadderCtx) + 'static,
) {
    // wasm-bindgen's own spawner: a link opens while the page starts,
    // before Leptos' executor is set up.
    wasm_bindgen_futures::spawn_local(async move {
        let failed = match decode(fragment).await {
            Ok(Ok(project)) => {
                // Every machine has its editor in the page.
                page.machine.set(project.machine);
                let ctx = ladders.of(project.machine);
                ctx.show_shared(project);
                if !ctx.work.shared.get_untracked() {
                    // Taken as this machine's work (an exercise in a fresh
                    // profile): a reload must not open the link again.
                    clear_fragment();
                }
                then(ctx);
                return;
            }
            Ok(Err(e)) => Ok(e),
            Err(missing) => Err(missing),
        };
        let lang = page.lang.get_untracked();
        let why = codec_failed(lang, failed);
        page.notice
            .set(Some(format!("{} {why}", lang.texts().shared_broken)));
    });
}

/// The URL of the page with `fragment`.
fn url_with(fragment: &str) -> String {
    let Some(window) = web_sys::window() else {
        return format!("#{fragment}");
    };
    let l = window.location();
    format!(
        "{}{}{}#{fragment}",
        l.origin().unwrap_or_default(),
        l.pathname().unwrap_or_default(),
        l.search().unwrap_or_default()
    )
}

/// The project as shared: the ladder, its comments, the machine's settings.
pub fn project_of(ctx: LadderCtx) -> Project {
    let mut project = ctx.project_now();
    project.settings = ctx.settings().into_iter().collect();
    project
}

/// The Share button and the link it made.
#[component]
pub fn ShareButton(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let c = move || ctx.page.lang.get().classroom();
    let url = RwSignal::new(None::<String>);
    // Whether the clipboard took the link: `None` while it is asked.
    let copied = RwSignal::new(None::<bool>);
    let share = move |_| {
        let project = project_of(ctx);
        let said = move |e| {
            let lang = ctx.page.lang.get_untracked();
            ctx.panes.message.set(Some(codec_failed(lang, e)));
        };
        wasm_bindgen_futures::spawn_local(async move {
            match encode(project).await {
                Ok(Ok(fragment)) => {
                    let link = url_with(&fragment);
                    copied.set(None);
                    copy_to_clipboard(&link, copied);
                    url.set(Some(link));
                    ctx.panes.message.set(None);
                }
                Ok(Err(e)) => said(Ok(e)),
                Err(missing) => said(Err(missing)),
            }
        });
    };
    view! {
        <button type="button" data-testid="share" on:click=share>{move || t().share}</button>
        <Show when=move || url.with(Option::is_some)>
            <input
                class="share-url"
                data-testid="share-url"
                readonly
                aria-label=move || t().share
                prop:value=move || url.get().unwrap_or_default()
                on:focus=|e| {
                    use leptos::wasm_bindgen::JsCast;
                    if let Some(i) = e.target().and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok()) {
                        i.select();
                    }
                }
            />
            <span class="share-copied" role="status" data-testid="share-copied" data-copied=move || copied.get().map(|c| c.to_string())>
                {move || match copied.get() {
                    Some(true) => c().copied,
                    Some(false) => c().copy_by_hand,
                    None => "",
                }}
            </span>
        </Show>
    }
}

/// Puts `link` on the clipboard; `copied` says whether it took it (it
/// may be refused: the link stays in its field to copy by hand, and the
/// page says so).
fn copy_to_clipboard(link: &str, copied: RwSignal<Option<bool>>) {
    use leptos::wasm_bindgen::{closure::Closure, JsValue};
    let Some(window) = web_sys::window() else {
        return;
    };
    let promise = window.navigator().clipboard().write_text(link);
    let ok = Closure::once(move |_: JsValue| copied.set(Some(true)));
    let refused = Closure::once(move |_: JsValue| copied.set(Some(false)));
    let _ = promise.then2(&ok, &refused);
    // Owned by the promise from here (two small closures a click).
    ok.forget();
    refused.forget();
}

/// The banner over a shared project: keep it, or go back to your own.
#[component]
pub fn SharedBanner(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    view! {
        <Show when=move || ctx.work.shared.get()>
            <div class="shared-banner" role="status" data-testid="shared-banner">
                <span>{move || t().shared_note}</span>
                <button type="button" data-testid="shared-keep" on:click=move |_| {
                    ctx.keep_shared(use_context::<crate::editor::projects::Projects>());
                    clear_fragment();
                }>{move || t().shared_keep}</button>
                <button type="button" data-testid="shared-back" on:click=move |_| {
                    ctx.leave_shared();
                    clear_fragment();
                }>{move || t().shared_back}</button>
            </div>
        </Show>
    }
}
