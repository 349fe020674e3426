//! The box entry's field per operand (issue #49): once the entry's first
//! word names a soft PLC box (`CTU `, from F8 or the palette), a labelled
//! field for each operand it takes in order (CTU: instance, R, PV), so the
//! whole call is there to fill in, on a phone too. The fields write the
//! entry's text (operands in order, `-` for one left empty): the text
//! stays what is committed.

use engine::ladder::edit::{box_operands, BoxOperand, OperandRole};
use leptos::prelude::*;

use super::state::LadderCtx;

/// The operands of the box `text` asks for in the operand form, each
/// with what is typed for it so far (`""`: nothing, or `-`). `None` when
/// the text is no box, is in the call form, or gives more operands than
/// the fields (a function taking more: `ADD a b 2 total`).
pub fn operand_fields(text: &str) -> Option<Vec<(BoxOperand, String)>> {
    if text.contains('(') || text.contains(":=") {
        return None;
    }
    let mut words = text.split_whitespace();
    let operands = box_operands(words.next()?)?;
    let given: Vec<&str> = words.collect();
    if given.len() > operands.len() {
        return None;
    }
    Some(
        operands
            .into_iter()
            .enumerate()
            .map(|(i, o)| {
                let typed = given.get(i).copied().unwrap_or("");
                let shown = if typed == "-" || typed == "·" {
                    ""
                } else {
                    typed
                };
                (o, shown.to_string())
            })
            .collect(),
    )
}

/// `text` with operand `index` set to `value` (empty: `-`, left off at
/// the end); the kind's word is kept, followed by a space while no
/// operand is given, so the fields stay.
pub fn with_operand(text: &str, index: usize, value: &str) -> String {
    let mut words: Vec<String> = text.split_whitespace().map(str::to_string).collect();
    if words.is_empty() {
        return text.to_string();
    }
    while words.len() <= index + 1 {
        words.push("-".into());
    }
    let value: String = value.split_whitespace().collect();
    words[index + 1] = if value.is_empty() { "-".into() } else { value };
    while words.len() > 1 && words.last().is_some_and(|w| w == "-") {
        words.pop();
    }
    let mut out = words.join(" ");
    if words.len() == 1 {
        out.push(' ');
    }
    out
}

/// The fields, under the entry's text while it names a box.
#[component]
pub fn BoxFields(
    ctx: LadderCtx,
    set_text: Callback<String>,
    commit: Callback<()>,
    close: Callback<()>,
) -> impl IntoView {
    let f = move || ctx.page.lang.get().files();
    let text = move || {
        ctx.panes
            .entry
            .with(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default())
    };
    // Rebuilt only when the box's kind changes, so a field keeps its focus
    // while it is typed in.
    let operands = Memo::new(move |_| {
        operand_fields(&text()).map(|all| all.into_iter().map(|(o, _)| o).collect::<Vec<_>>())
    });
    let value = move |i: usize| {
        operand_fields(&text())
            .and_then(|all| all.get(i).map(|(_, v)| v.clone()))
            .unwrap_or_default()
    };
    move || {
        operands.get().map(|all| {
            let fields = all
                .into_iter()
                .enumerate()
                .map(|(i, o)| {
                    let pin = o.pin.clone();
                    let label = move || match o.role {
                        OperandRole::Instance => f().box_instance.to_string(),
                        OperandRole::Result => format!("{} ({})", f().box_result, o.pin),
                        OperandRole::Input => o.pin.clone(),
                    };
                    let hint = o.needs.map_or("", |t| t.name());
                    view! {
                        <label class="box-field">
                            <span>{label}</span>
                            <input data-testid=format!("box-operand-{i}") data-pin=pin
                                autocomplete="off" spellcheck="false" placeholder=hint
                                prop:value=move || value(i)
                                on:input=move |e| {
                                    let now = ctx.panes.entry.with_untracked(|e| e.as_ref().map(|e| e.text.clone()).unwrap_or_default());
                                    set_text.run(with_operand(&now, i, &event_target_value(&e)));
                                }
                                on:keydown=move |e: web_sys::KeyboardEvent| match e.key().as_str() {
                                    "Enter" => { e.prevent_default(); commit.run(()); }
                                    "Escape" => { e.prevent_default(); close.run(()); }
                                    _ => {}
                                } />
                        </label>
                    }
                })
                .collect_view();
            view! { <div class="box-fields" data-testid="box-fields">{fields}</div> }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_counter_gets_a_field_per_operand_filled_from_the_text() {
        let fields = operand_fields("CTU ").expect("a box");
        let pins: Vec<_> = fields
            .iter()
            .map(|(o, v)| (o.pin.as_str(), v.as_str()))
            .collect();
        assert_eq!(pins, [("", ""), ("R", ""), ("PV", "")]);
        let fields = operand_fields("CTU c0 - 10").expect("a box");
        let values: Vec<_> = fields.iter().map(|(_, v)| v.as_str()).collect();
        assert_eq!(values, ["c0", "", "10"]);
        assert!(operand_fields("X00").is_none(), "no box");
        assert!(
            operand_fields("c0: CTU(PV := 10)").is_none(),
            "the call form"
        );
        assert!(
            operand_fields("ADD a b 2 total").is_none(),
            "more than the fields"
        );
    }

    #[test]
    fn a_field_writes_its_operand_into_the_text() {
        assert_eq!(with_operand("CTU ", 0, "c1"), "CTU c1");
        assert_eq!(with_operand("CTU c1", 2, "10"), "CTU c1 - 10");
        assert_eq!(with_operand("CTU c1 - 10", 1, "reset"), "CTU c1 reset 10");
        assert_eq!(with_operand("CTU c1 - 10", 2, ""), "CTU c1");
        assert_eq!(with_operand("CTU c1", 0, ""), "CTU ");
        assert_eq!(with_operand("MOVE 42", 1, "my count"), "MOVE 42 mycount");
        // And the entry reads it back as the box the fields show.
        let e = engine::ladder::edit::parse_entry(
            engine::MachineId::SoftPlc,
            engine::ladder::edit::EntryKind::Instruction,
            &with_operand("CTU c1 - 10", 1, "reset"),
        );
        assert!(e.is_ok(), "{e:?}");
    }
}
