//! The soft PLC's variables as the variables pane edits them (issue #31):
//! declare (or change) one, remove one, rename one everywhere. A change
//! that leaves a use that no longer fits (a retyped word an ADD adds to a
//! BOOL, a removed word a box reads) is refused at that use's cell, with
//! the compiler's reason; nothing changes.

use crate::iec::is_identifier;
use crate::ladder::compile::{compile, Options};
use crate::ladder::element::Element;
use crate::ladder::grid::{Ladder, LadderError};
use crate::ladder::variables::Variable;
use crate::MachineId;

/// Why the variables pane's edit was refused; nothing changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VariableEditError {
    /// A declaration the soft PLC does not take.
    Declaration(crate::ladder::variables::VariableError),
    /// No variable of that name.
    NoSuchVariable(String),
    /// Another variable has that name.
    NameTaken(String),
    /// A use of the variable that the change would no longer fit, with
    /// the compiler's reason at its cell.
    UseNoLongerFits(LadderError),
}

impl std::fmt::Display for VariableEditError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            VariableEditError::Declaration(e) => e.fmt(f),
            VariableEditError::NoSuchVariable(n) => write!(f, "there is no variable {n}"),
            VariableEditError::NameTaken(n) => write!(f, "{n} is already declared"),
            VariableEditError::UseNoLongerFits(e) => {
                write!(f, "a use would no longer fit: {e}")
            }
        }
    }
}

impl std::error::Error for VariableEditError {}

/// What the variables pane asks for ([`super::Edit::Variable`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VariableEdit {
    /// Declares a variable, or changes the one of its name (any case):
    /// type, address, start value, comment.
    Declare(Variable),
    /// Removes the declaration of this name (any case) no use needs.
    Remove(String),
    /// Renames variable `.0` (any case) to `.1` in its declaration and in
    /// every cell that uses it.
    Rename(String, String),
}

/// The ladder after `edit`, or why not.
pub(super) fn planned(ladder: &Ladder, edit: VariableEdit) -> Result<Ladder, VariableEditError> {
    match edit {
        VariableEdit::Declare(v) => declare(ladder, v),
        VariableEdit::Remove(name) => remove(ladder, &name),
        VariableEdit::Rename(from, to) => rename(ladder, &from, &to),
    }
}

/// The ladder with `variable` declared: added, or in place of the one of
/// its name (any case).
fn declare(ladder: &Ladder, variable: Variable) -> Result<Ladder, VariableEditError> {
    variable.check().map_err(VariableEditError::Declaration)?;
    let mut after = ladder.clone();
    match position(ladder, &variable.name) {
        Some(i) => after.variables[i] = variable,
        None => after.variables.push(variable),
    }
    fits(ladder, &after)?;
    Ok(after)
}

/// The ladder without variable `name`.
fn remove(ladder: &Ladder, name: &str) -> Result<Ladder, VariableEditError> {
    let i = position(ladder, name)
        .ok_or_else(|| VariableEditError::NoSuchVariable(name.to_string()))?;
    let mut after = ladder.clone();
    after.variables.remove(i);
    fits(ladder, &after)?;
    Ok(after)
}

/// The ladder with variable `from` called `to` in its declaration, in
/// every cell that names it (contacts, coils, box operands and results, a
/// block's instance and its outputs `from.Q`) and in its comment's key.
fn rename(ladder: &Ladder, from: &str, to: &str) -> Result<Ladder, VariableEditError> {
    let to = to.trim();
    let i = position(ladder, from)
        .ok_or_else(|| VariableEditError::NoSuchVariable(from.to_string()))?;
    if !is_identifier(to) {
        let bad = crate::ladder::variables::VariableError::BadName(to.to_string());
        return Err(VariableEditError::Declaration(bad));
    }
    if position(ladder, to).is_some_and(|j| j != i) {
        return Err(VariableEditError::NameTaken(to.to_string()));
    }
    let mut after = ladder.clone();
    let old = after.variables[i].name.clone();
    after.variables[i].name = to.to_string();
    for element in after
        .rungs
        .iter_mut()
        .flat_map(|r| r.cells.iter_mut().flatten().flatten())
    {
        rename_in(element, &old, to);
    }
    if let Some(comment) = after.device_comments.remove(&old) {
        after.device_comments.insert(to.to_string(), comment);
    }
    Ok(after)
}

fn position(ladder: &Ladder, name: &str) -> Option<usize> {
    let name = name.trim();
    ladder
        .variables
        .iter()
        .position(|v| v.name.eq_ignore_ascii_case(name))
}

/// `name` renamed, if it is `old` or one of its outputs (`old.Q`).
fn renamed(name: &str, old: &str, new: &str) -> Option<String> {
    let trimmed = name.trim();
    if trimmed.eq_ignore_ascii_case(old) {
        return Some(new.to_string());
    }
    let (base, pin) = trimmed.split_once('.')?;
    base.eq_ignore_ascii_case(old)
        .then(|| format!("{new}.{pin}"))
}

/// Renames `old` (and its outputs `old.Q`) in `element`: its devices and
/// operands, and a box's instance.
fn rename_in(element: &mut Element, old: &str, new: &str) {
    let swap = |name: &mut String| {
        if let Some(n) = renamed(name, old, new) {
            *name = n;
        }
    };
    element.names_mut(swap);
    if let Element::Block(b) | Element::OutputBlock(b) = element {
        swap(&mut b.instance);
    }
}

/// Refuses `after` where it has a problem at a cell that `before` did
/// not: a use the change no longer fits.
fn fits(before: &Ladder, after: &Ladder) -> Result<(), VariableEditError> {
    // Variables are declared on the machines with word boxes (the soft
    // PLC): a change must still fit there.
    let problems = |l: &Ladder| -> Vec<LadderError> {
        MachineId::ALL
            .into_iter()
            .filter(|m| m.target().capabilities().word_boxes)
            .flat_map(|m| compile(l, m, Options::default()).err().unwrap_or_default())
            .collect()
    };
    let old = problems(before);
    match problems(after)
        .into_iter()
        .find(|p| p.pos.is_some() && !old.contains(p))
    {
        Some(p) => Err(VariableEditError::UseNoLongerFits(p)),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Cursor, Edit, Editor};
    use super::VariableEdit;
    use crate::ladder::compile::{compile, Options};
    use crate::ladder::edit::{parse_entry, EntryKind};
    use crate::ladder::{Element, Ladder, Variable};
    use crate::MachineId;

    fn entry(text: &str) -> Element {
        parse_entry(MachineId::SoftPlc, EntryKind::Instruction, text).expect(text)
    }

    /// `%IX0.0 → [ADD count 1 count]`, `[GT count 3] → %QX0.0`, drawn
    /// as the page draws them.
    fn counting() -> Ladder {
        let mut editor = Editor::new(Ladder::default());
        let cells = [
            (0, 0, Element::no("%IX0.0")),
            (0, 1, entry("ADD count 1 count")),
            (1, 0, entry("GT count 3")),
            (1, 1, Element::coil("%QX0.0")),
        ];
        for (rung, col, element) in cells {
            let at = Cursor::new(rung, 0, col);
            editor.apply(Edit::Place { at, element }).expect("places");
        }
        let mut ladder = editor.ladder().clone();
        ladder.variables.push(Variable::new("count", "INT"));
        assert!(compile(&ladder, MachineId::SoftPlc, Options::default()).is_ok());
        ladder
    }

    #[test]
    fn renaming_a_variable_renames_every_use_and_undo_brings_it_back() {
        let mut editor = Editor::new(counting());
        editor
            .apply(Edit::Variable(VariableEdit::Rename(
                "COUNT".into(),
                "parts".into(),
            )))
            .expect("renames");
        let l = editor.ladder();
        assert_eq!(l.variables[0].name, "parts");
        let text = format!("{:?}", l.rungs);
        assert!(
            !text.contains("count") && text.matches("parts").count() == 3,
            "{text}"
        );
        assert!(editor.undo());
        assert_eq!(editor.ladder(), &counting());
    }

    #[test]
    fn a_retype_a_use_no_longer_fits_is_refused_at_its_cell() {
        let mut editor = Editor::new(counting());
        let err = editor
            .apply(Edit::Variable(VariableEdit::Declare(Variable::new(
                "count", "BOOL",
            ))))
            .expect_err("ADD on a BOOL");
        let text = err.to_string();
        assert!(
            text.contains("rung 1") && text.contains("column 10"),
            "{text}"
        );
        assert_eq!(editor.ladder(), &counting(), "nothing changed");
        // A wider integer fits every use.
        editor
            .apply(Edit::Variable(VariableEdit::Declare(Variable::new(
                "count", "DINT",
            ))))
            .expect("DINT fits");
        assert_eq!(editor.ladder().variables[0].data_type, "DINT");
    }

    #[test]
    fn bad_names_taken_names_and_used_words_are_refused() {
        let mut editor = Editor::new(counting());
        let mut bad = Variable::new("2x", "INT");
        assert!(editor
            .apply(Edit::Variable(VariableEdit::Declare(bad.clone())))
            .is_err());
        bad.name = "level".into();
        editor
            .apply(Edit::Variable(VariableEdit::Declare(bad)))
            .expect("declares");
        let taken = editor.apply(Edit::Variable(VariableEdit::Rename(
            "level".into(),
            "Count".into(),
        )));
        assert!(taken.is_err_and(|e| e.to_string().contains("Count")));
        let used = editor.apply(Edit::Variable(VariableEdit::Remove("count".into())));
        assert!(used.is_err(), "a box reads it");
        editor
            .apply(Edit::Variable(VariableEdit::Remove("level".into())))
            .expect("unused");
        assert_eq!(editor.ladder(), &counting());
    }
}
