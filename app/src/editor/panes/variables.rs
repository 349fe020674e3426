//! The soft PLC's variables pane `[data-testid=variables]` (issue #31):
//! declare a variable, rename it everywhere, retype it, give it an
//! address, a start value and a comment, each an undoable edit that the
//! engine refuses at the use it would break (`Edit::Variable`: declare,
//! rename, remove); while the machine
//! runs, each variable's value, and a value to set (an input keeps it;
//! another variable takes it until the program writes it again).

use engine::events::{InputValue, Real};
use engine::ladder::edit::{Edit, VariableEdit};
use engine::ladder::Variable;
use engine::plc::Command;
use leptos::prelude::*;

use crate::editor::LadderCtx;

/// The types offered for a new variable (any IEC elementary type or
/// standard block can be typed).
const TYPES: [&str; 13] = [
    "INT", "BOOL", "DINT", "UINT", "WORD", "REAL", "TIME", "STRING", "TON", "TOF", "CTU", "CTD",
    "R_TRIG",
];

/// A value as typed: TRUE/FALSE, an integer, a decimal (for REAL).
pub fn typed_value(text: &str) -> Option<InputValue> {
    let text = text.trim();
    match text.to_ascii_uppercase().as_str() {
        "TRUE" => return Some(InputValue::Int(1)),
        "FALSE" => return Some(InputValue::Int(0)),
        _ => {}
    }
    if let Ok(n) = text.parse::<i64>() {
        return Some(InputValue::Int(n));
    }
    text.parse::<f64>()
        .ok()
        .and_then(Real::new)
        .map(InputValue::Real)
}

/// The pane.
#[component]
pub fn VariablesPane(ctx: LadderCtx) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let error = RwSignal::new(None::<String>);
    // Whether the edit was made; a refusal is said under the table.
    let edit = move |e: Edit| {
        let refused = ctx.try_edit(e).err();
        let done = refused.is_none();
        error.set(refused);
        done
    };
    let name = RwSignal::new(String::new());
    let kind = RwSignal::new("INT".to_string());
    let declare = move || {
        let n = name.get_untracked();
        let declared = Variable::new(n.trim(), &kind.get_untracked());
        if edit(Edit::Variable(VariableEdit::Declare(declared))) {
            name.set(String::new());
        }
    };
    view! {
        <section class="variables" data-testid="variables">
            <h2>{move || t().variables}</h2>
            <p class="hint">{move || t().var_hint}</p>
            <div class="var-table-wrap">
            <table class="var-table">
                <thead><tr>
                    <th>{move || t().var_name}</th><th>{move || t().var_type}</th>
                    <th>{move || t().var_address}</th><th>{move || t().var_value}</th>
                </tr></thead>
                <For each=move || ctx.drawing.variables.get() key=|v| v.clone()
                    children=move |v| view! { <VariableRow ctx v edit /> } />
            </table>
            </div>
            <form class="var-new" on:submit=move |e| { e.prevent_default(); declare(); }>
                <input data-testid="var-new-name" placeholder=move || t().var_name
                    aria-label=move || t().var_name spellcheck="false" autocomplete="off"
                    prop:value=move || name.get() on:input=move |e| name.set(event_target_value(&e)) />
                <input data-testid="var-new-type" list="var-types" aria-label=move || t().var_type
                    spellcheck="false" prop:value=move || kind.get()
                    on:input=move |e| kind.set(event_target_value(&e)) />
                <datalist id="var-types">
                    {TYPES.map(|k| view! { <option value=k></option> }).collect_view()}
                </datalist>
                <button type="submit" data-testid="var-add">{move || t().var_add}</button>
            </form>
            <div class="entry-error" role="alert" data-testid="variables-error">{move || error.get()}</div>
        </section>
    }
}

/// One variable: each field edits it when it changes (Enter or leaving
/// the field).
#[component]
fn VariableRow(
    ctx: LadderCtx,
    v: Variable,
    edit: impl Fn(Edit) -> bool + Copy + Send + Sync + 'static,
) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let old = v.name.clone();
    let field = move |get: fn(&Variable) -> String, set: fn(&mut Variable, String)| {
        let v = v.clone();
        (get(&v), move |e: leptos::ev::Event| {
            let mut changed = v.clone();
            set(&mut changed, event_target_value(&e).trim().to_string());
            if changed != v && !edit(Edit::Variable(VariableEdit::Declare(changed))) {
                shown_back(&e, &get(&v));
            }
        })
    };
    let (kind, on_kind) = field(|v| v.data_type.clone(), |v, s| v.data_type = s);
    let (address, on_address) = field(|v| v.address.clone(), |v, s| v.address = s);
    let (initial, on_initial) = field(|v| v.initial.clone(), |v, s| v.initial = s);
    let (comment, on_comment) = field(|v| v.comment.clone(), |v, s| v.comment = s);
    let from = old.clone();
    let rename = move |e: leptos::ev::Event| {
        let to = event_target_value(&e);
        let rename = VariableEdit::Rename(from.clone(), to.trim().to_string());
        if to.trim() != from && !edit(Edit::Variable(rename)) {
            shown_back(&e, &from);
        }
    };
    let gone = old.clone();
    let v_is_text = kind.trim().eq_ignore_ascii_case("STRING");
    view! {
        <tbody data-testid=format!("var-{old}")>
            <tr>
                <td><input data-testid="var-name" value=old.clone() aria-label=move || t().var_name
                    spellcheck="false" on:change=rename /></td>
                <td><input data-testid="var-type" value=kind list="var-types" class="narrow"
                    aria-label=move || t().var_type on:change=on_kind /></td>
                <td><input data-testid="var-address" value=address class="narrow"
                    aria-label=move || t().var_address on:change=on_address /></td>
                <ValueCell ctx name=old.clone() text=v_is_text />
            </tr>
            <tr class="var-more">
                <td colspan="4">
                    <label>{move || t().var_initial} " "
                        <input data-testid="var-initial" value=initial class="narrow" on:change=on_initial />
                    </label>
                    <label>{move || t().var_comment} " "
                        <input data-testid="var-comment" value=comment class="wide" on:change=on_comment />
                    </label>
                    <button type="button" data-testid="var-remove" aria-label=move || t().var_remove
                        title=move || t().var_remove
                        on:click=move |_| {
                            edit(Edit::Variable(VariableEdit::Remove(gone.clone())));
                        }>"×"</button>
                </td>
            </tr>
        </tbody>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typed_values_read_as_the_soft_plc_takes_them() {
        assert_eq!(typed_value(" 42 "), Some(InputValue::Int(42)));
        assert_eq!(typed_value("true"), Some(InputValue::Int(1)));
        assert_eq!(typed_value("-3"), Some(InputValue::Int(-3)));
        assert!(matches!(typed_value("2.5"), Some(InputValue::Real(r)) if r.get() == 2.5));
        assert_eq!(typed_value("x"), None);
        assert_eq!(typed_value("inf"), None);
    }
}

/// The field of event `e` shows `text` again: what the declaration still
/// holds after a refused change (the row is not drawn anew, since the
/// variable did not change).
fn shown_back(e: &leptos::ev::Event, text: &str) {
    event_target::<web_sys::HtmlInputElement>(e).set_value(text);
}

/// A variable's value on the machine, and a value to set: an input
/// keeps it; another variable takes it until the program writes it. A
/// STRING (`text`) has no value to set (the program writes its STRINGs):
/// its text takes the room.
#[component]
fn ValueCell(ctx: LadderCtx, name: String, text: bool) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    let watched = name.clone();
    let value = Memo::new(move |_| {
        ctx.live.variable_values.with(|vs| {
            vs.iter()
                .find(|(n, _)| *n == watched)
                .map_or(String::new(), |(_, v)| v.clone())
        })
    });
    let to_set = RwSignal::new(String::new());
    let refused = RwSignal::new(None::<String>);
    let set_value = move || {
        let text = to_set.get_untracked();
        let Some(value) = typed_value(&text) else {
            let lang = ctx.page.lang.get_untracked();
            refused.set(Some(format!(
                "{text:?}: {}",
                lang.words().true_false_number
            )));
            return;
        };
        let mut said = None;
        ctx.operate(|plc| {
            let done = plc
                .device(&name)
                .and_then(|d| plc.apply(Command::SetInput(d, value)));
            let lang = ctx.page.lang.get_untracked();
            said = done.err().map(|e| crate::i18n::errors::plc_error(lang, &e));
        });
        refused.set(said);
    };
    view! {
        <td class="var-value" class:text=text>
            <output data-testid="var-value" title=move || value.get()>{move || value.get()}</output>
            {(!text).then(|| view! {
                <form on:submit=move |e| { e.prevent_default(); set_value(); }>
                    <input data-testid="var-set" class="narrow" aria-label=move || t().var_force
                        prop:value=move || to_set.get() on:input=move |e| to_set.set(event_target_value(&e)) />
                    <button type="submit" data-testid="var-set-ok">{move || t().var_force}</button>
                </form>
            })}
            <span class="soft-refused" role="alert" data-testid="var-set-error">{move || refused.get()}</span>
        </td>
    }
}
