//! Importing another tool's PLCopen project (issue #18): when a file
//! names variables the machine has no device for, runs more than one
//! program, or gives warnings, the import dialog
//! (`[data-testid=import-dialog]`) shows a mapping table with the devices
//! `engine::ladder::plcopen::declare::propose` suggests (each editable),
//! a POU picker, the warnings and the errors at their lines; Import
//! replaces the ladder (one undo away) only when the file imports whole.

use engine::ladder::edit::{align_outputs, Edit, COLUMNS};
use engine::ladder::plcopen::{declare, dom, drawn_body, import_pou, VarMap};
use leptos::prelude::*;

use super::LadderCtx;

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
}

impl Pending {
    /// The map the rows make.
    fn map(&self) -> VarMap {
        VarMap::from_pairs(
            self.rows
                .iter()
                .filter(|(_, d)| !d.trim().is_empty())
                .map(|(n, d)| (n.clone(), d.trim().to_string())),
        )
    }
}

/// Tries `pending` as it stands: the ladder replaced on success (and
/// `None` returned), else the pending import with what was said.
pub fn attempt(ctx: LadderCtx, mut pending: Pending, quiet_if_clean: bool) -> Option<Pending> {
    let map = pending.map();
    if let Err(errors) = map.check(ctx.machine) {
        // Said at the table's row (the map's lines number its filled rows).
        pending.errors = errors
            .iter()
            .filter_map(|e| {
                let (name, device, _) = map.entries.iter().find(|(_, _, l)| *l == e.line)?;
                Some(format!("{name} → {device}: {}", e.error))
            })
            .collect();
        return Some(pending);
    }
    match import_pou(
        &pending.text,
        Some(ctx.machine),
        Some(&map),
        pending.pou.as_deref(),
    ) {
        Ok(imported) => {
            pending.warnings = imported
                .warnings
                .iter()
                .map(|w| format!("{}:{}: {}", pending.file, w.line, w.error))
                .collect();
            pending.errors.clear();
            let clean = pending.warnings.is_empty() && pending.rows.is_empty();
            if quiet_if_clean && !clean {
                // Shown first, so the user sees what was proposed.
                return Some(pending);
            }
            let ladder = align_outputs(&imported.ladder, COLUMNS - 1);
            if ctx.ladder() != ladder {
                ctx.apply(Edit::Replace { ladder });
            }
            None
        }
        Err(errors) => {
            pending.errors = errors
                .iter()
                .map(|e| format!("{}:{}: {}", pending.file, e.line, e.error))
                .collect();
            Some(pending)
        }
    }
}

/// A PLCopen file opened: imported at once when nothing needs saying,
/// else offered in the dialog with proposed devices.
pub fn open(ctx: LadderCtx, shown: RwSignal<Option<Pending>>, file: &str, text: &str) {
    let (pous, rows) = match dom::parse(text) {
        Ok(root) => {
            let mut found = Vec::new();
            root.descendants("pou", &mut found);
            let pous = found
                .iter()
                .filter(|p| drawn_body(p).is_some())
                .filter_map(|p| p.attr("name").map(str::to_string))
                .collect();
            (pous, declare::propose(&root, ctx.machine, None))
        }
        Err(_) => (Vec::new(), Vec::new()),
    };
    let pending = Pending {
        file: file.to_string(),
        text: text.to_string(),
        pous,
        pou: None,
        rows,
        warnings: Vec::new(),
        errors: Vec::new(),
    };
    shown.set(attempt(ctx, pending, true));
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
    let apply = move |_| {
        if let Some(p) = shown.get_untracked() {
            shown.set(attempt(ctx, p, false));
            if shown.with_untracked(Option::is_none) {
                on_close.run(());
            }
        }
    };
    // It takes the focus when it opens (not when its table is edited).
    let node = NodeRef::<leptos::html::Div>::new();
    Effect::new(move |was: Option<bool>| {
        let now = shown.with(Option::is_some);
        if now && was != Some(true) {
            if let Some(n) = node.get() {
                let _ = n.focus();
            }
        }
        now
    });
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
                                shown.update(|s| if let Some(s) = s { s.pou = (!v.is_empty()).then_some(v) });
                            }>
                                <option value="">{t().import_pou_tasks}</option>
                                {p.pous.iter().map(|n| view! { <option value=n.clone()>{n.clone()}</option> }).collect_view()}
                            </select>
                        </label>
                    })}
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
                    <ul class="import-said">
                        {p.errors.iter().map(|e| view! { <li class="error" data-testid="import-error">{e.clone()}</li> }).collect_view()}
                        {p.warnings.iter().map(|w| view! { <li class="warning" data-testid="import-warning">{w.clone()}</li> }).collect_view()}
                    </ul>
                    <button type="button" data-testid="import-apply" on:click=apply>{t().import_apply}</button>
                    <button type="button" data-testid="import-cancel" on:click=move |_| { shown.set(None); on_close.run(()); }>{t().cancel}</button>
                </div>
            }
        })}
    }
}
