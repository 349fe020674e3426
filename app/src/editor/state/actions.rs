//! What keys, clicks and the device entry do to the ladder, and the
//! clipboard.

use super::*;
use crate::i18n::errors;

impl LadderCtx {
    /// Puts the cursor on a cell (a click, a problem, a find result).
    pub fn move_to(&self, to: Cursor) {
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing.anchor.set(None);
        self.drawing
            .cursor
            .set(self.drawing.editor.with_value(Editor::cursor));
    }

    /// Grows the selection to `to` (Shift+click).
    pub fn extend_to(&self, to: Cursor) {
        if self.drawing.anchor.get_untracked().is_none() {
            self.drawing
                .anchor
                .set(Some(self.drawing.cursor.get_untracked()));
        }
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing
            .cursor
            .set(self.drawing.editor.with_value(Editor::cursor));
    }

    /// The selection's corners, when there is one.
    pub fn selection(&self) -> Option<(Cursor, Cursor)> {
        let anchor = self.drawing.anchor.get_untracked()?;
        Some((anchor, self.drawing.cursor.get_untracked()))
    }

    /// A key on the ladder; false when the ladder leaves it alone.
    pub fn key(&self, key: &str, shift: bool, ctrl: bool, alt: bool) -> bool {
        match keys::action(key, shift, ctrl, alt) {
            Some(action) => {
                self.dispatch(action);
                true
            }
            None => false,
        }
    }

    /// Does what an action asks.
    pub fn dispatch(&self, action: Action) {
        let at = self.drawing.cursor.get_untracked();
        match action {
            Action::Move(mv, extend) => self.step(mv, extend),
            Action::Why => self.why.request.update(|n| *n += 1),
            Action::Entry {
                kind,
                branch,
                prefill,
            } => self.open_entry(kind, branch, prefill.to_string()),
            Action::EditCell => {
                let (kind, text) = self
                    .drawing
                    .editor
                    .with_value(|e| e.ladder().rungs.get(at.rung)?.get(at.pos()).map(entry_for))
                    .unwrap_or((EntryKind::Open, String::new()));
                self.open_entry(kind, false, text);
            }
            Action::Wire => {
                self.apply(Edit::Wire { at });
            }
            Action::ToggleLink => {
                self.apply(Edit::ToggleLink { at });
            }
            Action::DeleteWire => {
                self.apply(Edit::DeleteWire { at });
            }
            Action::DeleteLink => {
                self.apply(Edit::DeleteLink { at });
            }
            Action::Clear => {
                let edit = match self.selection() {
                    Some((a, b)) if a.rung == b.rung => Edit::ClearBlock { from: a, to: b },
                    Some((a, b)) => Edit::DeleteRungs {
                        first: a.rung.min(b.rung),
                        last: a.rung.max(b.rung).min(self.rung_count().saturating_sub(1)),
                    },
                    None => Edit::Clear { at },
                };
                self.apply(edit);
            }
            Action::InsertAbove => {
                self.apply(Edit::InsertRung { index: at.rung });
            }
            Action::InsertBelow => {
                let index = (at.rung + 1).min(self.rung_count());
                self.apply(Edit::InsertRung { index });
            }
            Action::DeleteRungs => {
                let (first, last) = match self.selection() {
                    Some((a, b)) => (a.rung.min(b.rung), a.rung.max(b.rung)),
                    None => (at.rung, at.rung),
                };
                let last = last.min(self.rung_count().saturating_sub(1));
                self.apply(Edit::DeleteRungs { first, last });
            }
            Action::RungUp | Action::RungDown => {
                self.apply(Edit::MoveRung {
                    index: at.rung,
                    up: action == Action::RungUp,
                });
            }
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            // The clipboard events carry these; the keys only make sure a
            // copy works where the browser sends no event.
            Action::Copy => {
                self.copy_text();
            }
            Action::Cut | Action::Paste => {}
            Action::Find => self.panes.show(self.panes.find_open),
            Action::Help => self.panes.help.update(|h| *h = !*h),
            Action::Cancel => {
                self.drawing.anchor.set(None);
                self.panes.help.set(false);
                self.panes.message.set(None);
            }
        }
    }

    pub(super) fn rung_count(&self) -> usize {
        self.drawing.editor.with_value(|e| e.ladder().rungs.len())
    }

    pub(super) fn step(&self, mv: Move, extend: bool) {
        let from = self.drawing.cursor.get_untracked();
        let to = self
            .drawing
            .editor
            .with_value(|e| keys::moved(e.ladder(), e.output_column(), from, mv));
        if extend {
            if self.drawing.anchor.get_untracked().is_none() {
                self.drawing.anchor.set(Some(from));
            }
        } else {
            self.drawing.anchor.set(None);
        }
        self.drawing.editor.update_value(|e| e.move_to(to));
        self.drawing.cursor.set(to);
    }

    /// Opens the device entry at the cursor.
    pub fn open_entry(&self, kind: EntryKind, branch: bool, text: String) {
        self.panes.entry.set(Some(EntryState {
            kind,
            branch,
            at: self.drawing.cursor.get_untracked(),
            text,
            error: None,
        }));
    }

    /// Enter in the device entry: the element goes in when the machine
    /// has it; otherwise the entry stays open with the engine's message.
    pub fn commit_entry(&self) -> bool {
        let Some(state) = self.panes.entry.get_untracked() else {
            return false;
        };
        let refuse = |message: String| {
            self.panes.entry.update(|e| {
                if let Some(e) = e {
                    e.error = Some(message);
                }
            });
            false
        };
        let element = match parse_entry(self.machine, state.kind, &state.text) {
            Ok(e) => e,
            // In the page's language (issue #49).
            Err(e) => {
                return refuse(crate::i18n::engine::entry_error(
                    self.page.lang.get_untracked(),
                    &e,
                ))
            }
        };
        let edit = if state.branch {
            Edit::PlaceBranch {
                at: state.at,
                element,
            }
        } else {
            Edit::Place {
                at: state.at,
                element,
            }
        };
        match self.try_apply(edit) {
            Ok(()) => {
                self.panes.entry.set(None);
                true
            }
            Err(e) => refuse(errors::edit_error(self.page.lang.get_untracked(), &e)),
        }
    }

    /// Places `element` at the cursor without the entry (the palette's
    /// wire, NOT, R_TRIG).
    pub fn place(&self, element: Element) -> bool {
        let at = self.drawing.cursor.get_untracked();
        self.apply(Edit::Place { at, element })
    }

    /// The selection (or the cursor's cell) as clipboard text, also kept
    /// as this page's clipboard.
    pub fn copy_text(&self) -> Option<String> {
        let at = self.drawing.cursor.get_untracked();
        let clip = self.drawing.editor.with_value(|e| match self.selection() {
            Some((a, b)) if a.rung == b.rung => Clip::cells(e.ladder(), a, b),
            Some((a, b)) => {
                let last = a
                    .rung
                    .max(b.rung)
                    .min(e.ladder().rungs.len().saturating_sub(1));
                Clip::rungs(e.ladder(), a.rung.min(b.rung), last)
            }
            None => Clip::cells(e.ladder(), at, at),
        });
        match clip {
            Ok(clip) => {
                let text = clip.to_text();
                self.clip.text.set_value(Some(text.clone()));
                Some(text)
            }
            Err(e) => {
                let said = errors::edit_error(self.page.lang.get_untracked(), &e);
                self.panes.message.set(Some(said));
                None
            }
        }
    }

    /// Cut: copies, then clears what was copied.
    pub fn cut_text(&self) -> Option<String> {
        let text = self.copy_text()?;
        self.dispatch(Action::Clear);
        Some(text)
    }

    /// Pastes clipboard text at the cursor (this page's clipboard when
    /// `text` is `None`); what the machine lacks is refused, all of it.
    pub fn paste_text(&self, text: Option<String>) {
        let Some(text) = text.or_else(|| self.clip.text.get_value()) else {
            return;
        };
        // Read by a part (issue #53), then pasted where the cursor is.
        let ctx = *self;
        wasm_bindgen_futures::spawn_local(async move {
            let lang = ctx.page.lang.get_untracked();
            match crate::editor::files::reading::clip(text).await {
                Ok(Ok(clip)) => ctx.paste_clip(clip),
                Ok(Err(e)) => ctx.panes.message.set(Some(errors::clip_error(lang, &e))),
                Err(_) => ctx
                    .panes
                    .message
                    .set(Some(lang.parts().missing.to_string())),
            }
        });
    }

    /// Pastes cells read from the clipboard at the cursor; what the
    /// machine lacks is refused, all of it.
    fn paste_clip(&self, clip: Clip) {
        match clip.for_machine(self.machine) {
            Ok(clip) => {
                let at = self.drawing.cursor.get_untracked();
                self.apply(Edit::Paste { at, clip });
            }
            Err(errors) => {
                let lang = self.page.lang.get_untracked();
                let all: Vec<String> = errors.iter().map(|e| errors::clip_error(lang, e)).collect();
                self.panes.message.set(Some(all.join("; ")));
            }
        }
    }
}
