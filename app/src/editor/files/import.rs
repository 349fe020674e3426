//! Importing another tool's PLCopen project (issue #18): when a file
//! names variables the machine has no device for, runs more than one
//! program, or gives warnings, the import dialog
//! (`[data-testid=import-dialog]`) shows a mapping table with the devices
//! the files worker proposes (each editable), a POU picker, the warnings
//! and the errors at their lines; Import replaces the ladder (one undo
//! away) only when the file imports whole. The reading itself runs in the
//! files worker (`crate::worker`, fetched on first use: issue #29).

use engine::ladder::edit::Edit;
use files_worker::{Reply, Request};
use leptos::prelude::*;

use engine::MachineId;

use crate::editor::{LadderCtx, Ladders};

/// A file waiting in the dialog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pending {
    /// The file's name and text.
    pub file: String,
    pub text: String,
    /// The POUs with an LD or FBD body, and the one chosen (`None`: what the
    /// tasks run).
    pub pous: Vec<String>,
    pub pou: Option<String>,
    /// Each name and the device it is to take, as the user edits them.
    pub rows: Vec<(String, String)>,
    /// The last attempt's warnings and errors, each with its line.
    pub warnings: Vec<String>,
    pub errors: Vec<String>,
    /// The errors typed (one for each), said in the page's language.
    pub said: Vec<files_worker::Said>,
    /// The machine that imports the file when this one refuses it: the
    /// dialog offers the switch (`import-switch-machine`, issue #49).
    pub runs_on: Option<MachineId>,
}

/// Tries `pending` as it stands (`first`: the file just opened, its
/// devices to be proposed). On success the ladder is replaced, the dialog
/// closes and `closed` runs; otherwise the dialog shows what was said. A
/// file that imports whole with nothing proposed and nothing to say is
/// imported without the dialog.
pub fn attempt(
    ctx: LadderCtx,
    shown: RwSignal<Option<Pending>>,
    mut pending: Pending,
    first: bool,
    closed: impl FnOnce(&[String]) + 'static,
) {
    let texts = ctx.page.lang.get_untracked().texts();
    let request = Request::Import {
        file: pending.file.clone(),
        text: pending.text.clone(),
        machine: ctx.machine,
        rows: (!first).then(|| pending.rows.clone()),
        pou: pending.pou.clone(),
    };
    crate::worker::ask_saying(ctx.panes.message, texts, request, move |reply| {
        let reply = match reply {
            Reply::Import(reply) => reply,
            other => return leptos::logging::warn!("an import got {other:?}"),
        };
        pending.pous = reply.pous;
        pending.rows = reply.rows;
        // Said in the page's language of the moment they came (issue #49).
        let lang = ctx.page.lang.get_untracked();
        let said = |(i, w): (usize, &String)| {
            crate::i18n::engine::import_error(lang, reply.warnings_said.get(i), w)
        };
        pending.warnings = reply.warnings.iter().enumerate().map(said).collect();
        pending.errors = reply.errors;
        pending.runs_on = reply.runs_on;
        pending.said = reply.said;
        let clean = pending.warnings.is_empty() && pending.rows.is_empty();
        match reply.ladder {
            // Shown first, so the user sees what was proposed.
            Some(_) if first && !clean => shown.set(Some(pending)),
            Some(ladder) => {
                // Its ST POUs in the soft PLC's ST pane (issue #55), first:
                // its blocks are then declared when the ladder's boxes of
                // their types are checked.
                if let Some(text) = &reply.st {
                    ctx.apply_source(Some(engine::formats::project::ProgramText::st(text)));
                    ctx.page.docks.show(crate::docks::Tool::Program);
                }
                if ctx.ladder() != ladder {
                    ctx.apply(Edit::Replace { ladder });
                }
                // Another program: nothing said of the last one stays.
                ctx.clean_slate();
                ctx.titled(&pending.file, &pending.file);
                shown.set(None);
                closed(&pending.warnings);
            }
            None => shown.set(Some(pending)),
        }
    });
}

/// A PLCopen file opened: imported at once when nothing needs saying,
/// else offered in the dialog with proposed devices.
pub fn open(ctx: LadderCtx, shown: RwSignal<Option<Pending>>, file: &str, text: &str) {
    let pending = Pending {
        file: file.to_string(),
        text: text.to_string(),
        pous: Vec::new(),
        pou: None,
        rows: Vec::new(),
        warnings: Vec::new(),
        errors: Vec::new(),
        said: Vec::new(),
        runs_on: None,
    };
    attempt(ctx, shown, pending, true, |_| {});
}

/// The offered switch: the page shows `machine`'s editor and the file is
/// imported there at once (the user chose to), its warnings said in that
/// editor's message line. Closes this dialog first: its errors were this
/// machine's.
fn switch_and_import(
    ctx: LadderCtx,
    shown: RwSignal<Option<Pending>>,
    machine: MachineId,
    ladders: Option<Ladders>,
) {
    let Some(p) = shown.get_untracked() else {
        return;
    };
    shown.set(None);
    let target = ladders.map_or(ctx, |l| l.of(machine));
    ctx.page.machine.set(machine);
    crate::storage::save_string(crate::storage::MACHINE_KEY, machine.name());
    // Imported at once (the user chose to): what the soft PLC warns of is
    // said in its message line, not in a second dialog.
    let pending = Pending {
        rows: Vec::new(),
        warnings: Vec::new(),
        errors: Vec::new(),
        said: Vec::new(),
        runs_on: None,
        ..p
    };
    // Not the dialog's `on_close`: it gives the focus back to this
    // machine's ladder, whose view (and the callback with it) the switch
    // has disposed of by the time the worker answers.
    attempt(
        target,
        target.panes.import,
        pending,
        false,
        move |warnings| {
            if !warnings.is_empty() {
                target.panes.message.set(Some(warnings.join("\n")));
            }
        },
    );
}

/// The dialog.
#[component]
pub fn ImportDialog(
    ctx: LadderCtx,
    shown: RwSignal<Option<Pending>>,
    /// Gives the focus back to the ladder when the dialog closes.
    on_close: Callback<()>,
) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let ladders = use_context::<Ladders>();
    let apply = move |_| {
        if let Some(p) = shown.get_untracked() {
            attempt(ctx, shown, p, false, move |_| on_close.run(()));
        }
    };
    let node = NodeRef::<leptos::html::Div>::new();
    focus_when_shown(shown, node);
    view! {
        {move || shown.get().map(|p| {
            let rows = p.rows.clone();
            view! {
                <div class="import-dialog" data-testid="import-dialog" role="dialog" aria-label=t().import_title
                    tabindex="-1" node_ref=node
                    on:keydown=move |e: web_sys::KeyboardEvent| if e.key() == "Escape" {
                        e.prevent_default();
                        shown.set(None);
                        on_close.run(());
                    }>
                    <h3>{t().import_title} " · " {p.file.clone()}</h3>
                    {(p.pous.len() > 1).then(|| view! {
                        <label>{t().import_pou} " "
                            <select data-testid="import-pou" on:change=move |e| {
                                let v = event_target_value(&e);
                                // What was said was the old Program's (issue #49).
                                shown.update(|s| if let Some(s) = s {
                                    s.pou = (!v.is_empty()).then_some(v);
                                    s.errors.clear();
                                    s.said.clear();
                                    s.warnings.clear();
                                    s.runs_on = None;
                                });
                            }>
                                <option value="">{t().import_pou_tasks}</option>
                                {p.pous.iter().map(|n| view! { <option value=n.clone()>{n.clone()}</option> }).collect_view()}
                            </select>
                        </label>
                    })}
                    {(!rows.is_empty()).then(|| view! {
                    <table class="import-map">
                        <thead><tr><th>{t().import_variable}</th><th>{t().import_device}</th></tr></thead>
                        <tbody>
                            {rows.into_iter().enumerate().map(|(i, (name, device))| view! {
                                <tr>
                                    <th>{name.clone()}</th>
                                    <td><input data-testid=format!("import-map-{name}") spellcheck="false"
                                        prop:value=device
                                        on:input=move |e| {
                                            let v = event_target_value(&e);
                                            shown.update(|s| if let Some(s) = s { if let Some(r) = s.rows.get_mut(i) { r.1 = v } });
                                        } /></td>
                                </tr>
                            }).collect_view()}
                        </tbody>
                    </table>
                    })}
                    {said(ctx, &p)}
                    {p.runs_on.map(|m| switch_offer(ctx, shown, m, ladders))}
                    <button type="button" data-testid="import-apply" on:click=apply>{t().import_apply}</button>
                    <button type="button" data-testid="import-cancel" on:click=move |_| { shown.set(None); on_close.run(()); }>{t().cancel}</button>
                </div>
            }
        })}
    }
}

/// The dialog takes the focus when it opens (not when its table is
/// edited).
fn focus_when_shown(shown: RwSignal<Option<Pending>>, node: NodeRef<leptos::html::Div>) {
    Effect::new(move |was: Option<bool>| {
        let now = shown.with(Option::is_some);
        if now && was != Some(true) {
            if let Some(n) = node.get() {
                let _ = n.focus();
            }
        }
        now
    });
}

/// The offer to open the file on machine `m`, which runs it.
fn switch_offer(
    ctx: LadderCtx,
    shown: RwSignal<Option<Pending>>,
    m: MachineId,
    ladders: Option<Ladders>,
) -> impl IntoView {
    let f = move || ctx.page.lang.get().files();
    let named = move |s: &str| s.replace("{machine}", crate::state::product_name(m));
    view! {
        <p class="import-switch" data-testid="import-switch">
            <span>{move || named(f().switch_offer)}</span> " "
            <button type="button" class="primary" data-testid="import-switch-machine"
                on:click=move |_| switch_and_import(ctx, shown, m, ladders)>
                {move || named(f().switch_button)}
            </button>
        </p>
    }
}

/// The errors, in the page's language where they are typed, and the
/// warnings.
fn said(ctx: LadderCtx, p: &Pending) -> impl IntoView {
    let errors = p.errors.iter().enumerate().map(|(i, e)| {
        let (said, e) = (p.said.get(i).cloned(), e.clone());
        let text =
            move || crate::i18n::engine::import_error(ctx.page.lang.get(), said.as_ref(), &e);
        view! { <li class="error" data-testid="import-error">{text}</li> }
    });
    let warnings = p.warnings.iter().map(|w| {
        view! { <li class="warning" data-testid="import-warning">{w.clone()}</li> }
    });
    view! {
        <ul class="import-said">
            {errors.collect_view()}
            {warnings.collect_view()}
        </ul>
    }
}

/// What the dialog is drawn from: the editor, the file shown, and what
/// gives the focus back when it closes.
type DialogArgs = (LadderCtx, RwSignal<Option<Pending>>, Callback<()>);

crate::parts::part_fn!(
    pane_import,
    /// The import dialog is a part of its own (issue #53): fetched when a
    /// file first opens, not by the first screen.
    pub(crate) fn dialog() -> Result<crate::parts::DrawFor<DialogArgs>, crate::parts::PartMissing> {
        Ok(|(ctx, shown, on_close)| view! { <ImportDialog ctx shown on_close /> }.into_any())
    }
);
