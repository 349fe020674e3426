//! Files: the project as JSON (the engine's versioned format), PLCopen
//! XML out and in, the machine's program text, the ladder as SVG and PNG,
//! and printing. Downloads are made in the page (a Blob and a link); an
//! opened file is read by the engine, which names the line of a problem,
//! and becomes the ladder (one undo away) only when it reads.

use engine::formats::Project;
use engine::ladder::edit::{align_outputs, Edit, COLUMNS};
use engine::machines::IEC_MACHINE;
use files_worker::{Reply, Request};
use leptos::prelude::*;
use leptos::wasm_bindgen::closure::Closure;
use leptos::wasm_bindgen::{JsCast, JsValue};

use crate::editor::model::RungData;
use crate::editor::{picture, LadderCtx, Ladders};
use crate::parts::PartMissing;

/// Offers `content` as a download named `name`.
pub fn download(name: &str, mime: &str, content: &str) {
    let parts = js_sys::Array::of1(&JsValue::from_str(content));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let Ok(blob) = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options) else {
        return;
    };
    if let Ok(url) = web_sys::Url::create_object_url_with_blob(&blob) {
        click_link(name, &url);
    }
}

fn click_link(name: &str, href: &str) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if let Ok(a) = document.create_element("a") {
        let a: web_sys::HtmlAnchorElement = a.unchecked_into();
        a.set_href(href);
        a.set_download(name);
        a.click();
    }
}

/// The rung drawings as the screen has them, with numbers and steps.
fn drawings(ctx: LadderCtx) -> Vec<(usize, Option<usize>, RungData)> {
    ctx.drawing
        .rungs
        .get_untracked()
        .iter()
        .map(|r| {
            (
                r.number.get_untracked(),
                r.first_step.get_untracked(),
                r.data.get_untracked(),
            )
        })
        .collect()
}

crate::parts::part_fn!(
    pictures,
    /// The ladder's picture is a part of its own (issue #53): drawn only
    /// when a picture is first exported.
    fn svg_part(rungs: Vec<(usize, Option<usize>, RungData)>) -> Result<String, PartMissing> {
        let refs: Vec<(usize, Option<usize>, &RungData)> =
            rungs.iter().map(|(n, s, d)| (*n, *s, d)).collect();
        Ok(picture::svg(&refs))
    }
);

/// Calls `then` with the ladder as SVG text once its part is there; if
/// the part cannot be fetched, says so in the message line (pressing the
/// export again retries).
fn with_svg(ctx: LadderCtx, then: impl FnOnce(String) + 'static) {
    let rungs = drawings(ctx);
    wasm_bindgen_futures::spawn_local(async move {
        match svg_part(rungs).await {
            Ok(svg) => then(svg),
            Err(PartMissing) => {
                let said = ctx.page.lang.get_untracked().parts().missing;
                ctx.panes.message.set(Some(said.to_string()));
            }
        }
    });
}

/// Downloads the ladder as PLCopen XML, written by the files worker
/// (fetched on first use, issue #29).
fn export_plcopen(ctx: LadderCtx) {
    let texts = ctx.page.lang.get_untracked().texts();
    let request = Request::Export {
        ladder: ctx.ladder(),
        name: "Main".to_string(),
    };
    crate::worker::ask_saying(ctx.panes.message, texts, request, move |reply| {
        ctx.panes.message.set(match reply {
            Reply::Export(Ok(xml)) => {
                download(&name(ctx, "xml"), "application/xml", &xml);
                None
            }
            Reply::Export(Err(errors)) => Some(errors.join("; ")),
            other => Some(format!("{other:?}")),
        });
    });
}

/// Downloads a soft PLC ladder of LDmicro's elements as an `.ld` file,
/// its `CYCLE=` the soft PLC's scan period (docs/ldmicro.md, "Writing it
/// back").
fn export_ld(ctx: LadderCtx) {
    let texts = ctx.page.lang.get_untracked().texts();
    let request = Request::ExportLd {
        ladder: ctx.ladder(),
        cycle_us: scan_us(&ctx.settings()),
    };
    crate::worker::ask_saying(ctx.panes.message, texts, request, move |reply| {
        ctx.panes.message.set(match reply {
            Reply::ExportLd(Ok(text)) => {
                download(&name(ctx, "ld"), "text/plain", &text);
                None
            }
            Reply::ExportLd(Err(errors)) => Some(errors.join("; ")),
            other => Some(format!("{other:?}")),
        });
    });
}

/// The soft PLC's scan period in µs from its project settings (10 ms
/// when they name none).
fn scan_us(settings: &[(String, String)]) -> u64 {
    settings
        .iter()
        .find(|(name, _)| name == "scan")
        .and_then(|(_, v)| engine::SimTime::parse(v).ok())
        .map_or(10_000, |t| t.as_nanos() / 1000)
}

/// A file name for this machine's ladder.
fn name(ctx: LadderCtx, ext: &str) -> String {
    format!("{}-ladder.{ext}", ctx.machine.name())
}

/// The ladder as PNG: the SVG drawn on a canvas by the browser.
fn export_png(ctx: LadderCtx, svg: String) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    let Ok(image) = web_sys::HtmlImageElement::new() else {
        return;
    };
    let file = name(ctx, "png");
    let img = image.clone();
    let onload = Closure::once_into_js(move || {
        let Ok(canvas) = document.create_element("canvas") else {
            return;
        };
        let canvas: web_sys::HtmlCanvasElement = canvas.unchecked_into();
        canvas.set_width(img.natural_width());
        canvas.set_height(img.natural_height());
        let context = canvas
            .get_context("2d")
            .ok()
            .flatten()
            .and_then(|c| c.dyn_into::<web_sys::CanvasRenderingContext2d>().ok());
        if let Some(context) = context {
            let _ = context.draw_image_with_html_image_element(&img, 0.0, 0.0);
            if let Ok(url) = canvas.to_data_url() {
                click_link(&file, &url);
            }
        }
    });
    image.set_onload(Some(onload.unchecked_ref()));
    let encoded: String = js_sys::encode_uri_component(&svg).into();
    image.set_src(&format!("data:image/svg+xml;charset=utf-8,{encoded}"));
}

/// An LDmicro file opened (docs/ldmicro.md): read in the files worker,
/// drawn on the soft PLC (the page switches to it), one undo away; the
/// soft PLC then scans at the file's cycle, which a notice says when it
/// is not 10 ms.
fn open_ld(ctx: LadderCtx, ladders: Option<Ladders>, file: &str, text: &str) {
    let texts = ctx.page.lang.get_untracked().texts();
    let request = Request::OpenLd {
        file: file.to_string(),
        text: text.to_string(),
    };
    let message = ctx.panes.message;
    let file = file.to_string();
    crate::worker::ask_saying(message, texts, request, move |reply| match reply {
        Reply::OpenLd(Ok(opened)) => {
            let target = ladders.map_or(ctx, |l| l.of(IEC_MACHINE));
            ctx.page.machine.set(IEC_MACHINE);
            if target.ladder() != opened.ladder {
                target.apply(Edit::Replace {
                    ladder: opened.ladder,
                });
            }
            target.clean_slate();
            target.titled(&file, &file);
            let scan = vec![("scan".to_string(), format!("{}us", opened.cycle_us))];
            let refused = target.apply_settings(scan);
            // Said in the soft PLC's editor, which the page now shows.
            if !refused.is_empty() {
                target.panes.message.set(Some(refused.join("\n")));
            } else if opened.cycle_us != 10_000 {
                let ms = format!("{}", opened.cycle_us as f64 / 1000.0);
                target
                    .panes
                    .message
                    .set(Some(texts.ld_cycle.replace("{cycle}", &ms)));
            }
        }
        Reply::OpenLd(Err(errors)) => message.set(Some(errors.join("\n"))),
        other => leptos::logging::warn!("an LDmicro file got {other:?}"),
    });
}

/// Opens a Structured Text file (issue #55) on the soft PLC: given by the
/// workspaces, which reach its part (`Workspaces::open_st`): (file, text).
#[derive(Clone, Copy)]
pub struct OpenSt(pub Callback<(String, String)>);

/// Reads an opened file: a project (`.json`), PLCopen XML or an LDmicro
/// `.ld` file (a `.st` file is [`OpenSt`]'s). A project for another machine opens on that machine.
fn open_text(
    ctx: LadderCtx,
    ladders: Option<Ladders>,
    pending: RwSignal<Option<crate::editor::import::Pending>>,
    file: &str,
    text: &str,
) {
    let start = text.trim_start_matches('\u{feff}').trim_start();
    if file.to_ascii_lowercase().ends_with(".ld") || start.starts_with("LDmicro") {
        open_ld(ctx, ladders, file, text);
        return;
    }
    if start.starts_with('<') {
        // Another tool's project may need devices for its variables: the
        // import dialog (docs/ladder.md, "Declarations").
        crate::editor::import::open(ctx, pending, file, text);
        return;
    }
    let (file, text) = (file.to_string(), text.to_string());
    wasm_bindgen_futures::spawn_local(async move {
        let said = |e: String| ctx.panes.message.set(Some(e));
        match super::reading::project(text).await {
            Ok(Ok(p)) => open_project(ctx, ladders, p),
            Ok(Err(e)) => said(format!("{file}:{}: {}", e.line, e.error)),
            Err(PartMissing) => said(ctx.page.lang.get_untracked().parts().missing.to_string()),
        }
    });
}

/// Opens a project file's `p` in its machine's editor: its ladder as an
/// edit (one undo brings back what was there), its tests (and
/// exercise, plant) on a clean slate.
fn open_project(ctx: LadderCtx, ladders: Option<Ladders>, p: Project) {
    let target = ladders.map_or(ctx, |l| l.of(p.machine));
    ctx.page.machine.set(p.machine);
    let ladder = align_outputs(&p.ladder, COLUMNS - 1);
    if target.ladder() != ladder {
        target.apply(Edit::Replace { ladder });
    }
    target.show_cases(p.tests, p.exercise, p.plant);
    // Its Structured Text into the soft PLC's pane (issue #55).
    target.apply_source(p.program);
    target.save();
}

/// Offers the project (ladder, settings, tests) as a JSON file.
pub fn save_project_file(ctx: LadderCtx) {
    let project = crate::editor::shared::project_of(ctx);
    download(&name(ctx, "json"), "application/json", &project.to_json());
}

/// The file buttons.
#[component]
pub fn FileButtons(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let ladders = use_context::<Ladders>();
    let open_st = use_context::<OpenSt>();
    let pending = ctx.panes.import;
    let on_file = move |e: web_sys::Event| {
        let Some(input) = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok())
        else {
            return;
        };
        let Some(file) = input.files().and_then(|f| f.get(0)) else {
            return;
        };
        let name = file.name();
        input.set_value("");
        let Ok(reader) = web_sys::FileReader::new() else {
            return;
        };
        let r = reader.clone();
        let onload = Closure::once_into_js(move || {
            let text = r
                .result()
                .ok()
                .and_then(|v| v.as_string())
                .unwrap_or_default();
            match open_st {
                Some(OpenSt(open)) if name.to_ascii_lowercase().ends_with(".st") => {
                    open.run((name, text));
                }
                _ => open_text(ctx, ladders, pending, &name, &text),
            }
        });
        reader.set_onload(Some(onload.unchecked_ref()));
        let _ = reader.read_as_text(&file);
    };
    view! {
        <span class="files">
            <button type="button" data-testid="save-json" on:click=move |_| save_project_file(ctx)>
                {move || t().save_json}
            </button>
            <label class="file-open">
                {move || t().open_file}
                <input type="file" data-testid="open-file" accept=".json,.xml,.ld,.st,application/json,text/xml" on:change=on_file />
            </label>
            <span class="menu-heading" data-testid="export-heading">{move || t().export_as}</span>
            <button type="button" data-testid="export-plcopen" on:click=move |_| export_plcopen(ctx)>"PLCopen"</button>
            <Show when=move || ctx.machine == IEC_MACHINE>
                <button type="button" data-testid="export-ld" on:click=move |_| export_ld(ctx)>"LDmicro"</button>
            </Show>
            <button type="button" data-testid="export-text" disabled=move || ctx.drawing.listing.with(Option::is_none) on:click=move |_| {
                if let Some(listing) = ctx.drawing.listing.get_untracked() {
                    download(&name(ctx, "txt"), "text/plain", &listing.text);
                }
            }>{move || t().export_text}</button>
            <button type="button" data-testid="export-svg" on:click=move |_| {
                with_svg(ctx, move |svg| download(&name(ctx, "svg"), "image/svg+xml", &svg));
            }>"SVG"</button>
            <button type="button" data-testid="export-png" on:click=move |_| with_svg(ctx, move |svg| export_png(ctx, svg))>"PNG"</button>
            <button type="button" data-testid="print" on:click=|_| {
                if let Some(w) = web_sys::window() {
                    let _ = w.print();
                }
            }>{move || t().print}</button>
        </span>
    }
}
