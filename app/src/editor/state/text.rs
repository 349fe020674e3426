//! The machine's program text kept in step with the ladder: the pane
//! follows the ladder while it holds the ladder's listing; Load as ladder,
//! Write to PLC.

use super::*;

impl LadderCtx {
    /// Connects the machine's text pane. The pane follows the ladder while
    /// it holds the ladder's listing or nothing; a fresh editor with no
    /// saved ladder starts from the pane's program when it decompiles.
    pub fn connect(&self, program: Program) {
        self.text.pane.set_value(Some(program));
        let queued = self
            .text
            .queued
            .try_update_value(std::mem::take)
            .unwrap_or_default();
        if !queued.is_empty() {
            let refused = program.apply_settings.run(queued);
            if !refused.is_empty() {
                self.panes.message.set(Some(refused.join("\n")));
            }
        }
        if let Some(source) = self
            .text
            .queued_source
            .try_update_value(Option::take)
            .flatten()
        {
            program.apply_source.run(source);
        }
        let text = program.text.get_untracked();
        let empty = self
            .drawing
            .editor
            .with_value(|e| e.ladder().rungs.is_empty());
        if empty && self.text.fresh.get_value() && !text.trim().is_empty() {
            let scan = self.text.options.get_untracked().avr_scan_ms;
            if let Ok(ladder) = engine::ladder::decompile::decompile_text(self.machine, &text, scan)
            {
                self.drawing
                    .editor
                    .update_value(|e| *e = Editor::new(ladder));
                self.refresh(false);
            }
        }
        let listing = self
            .drawing
            .listing
            .with_untracked(|l| l.as_ref().map(|l| l.text.clone()));
        if text.trim().is_empty() || listing.as_deref() == Some(text.as_str()) || empty {
            self.text.synced.set_value(Some(text));
        }
    }

    /// The ladder of a program in the machine's text, drawn with its
    /// outputs in the output column; the engine's located error if not.
    pub fn ladder_of_text(&self, text: &str) -> Result<Ladder, String> {
        let scan = self.text.options.get_untracked().avr_scan_ms;
        let ladder = engine::ladder::decompile::decompile_text(self.machine, text, scan)
            .map_err(|e| crate::i18n::errors::text_error(self.page.lang.get_untracked(), &e))?;
        Ok(align_outputs(&ladder, COLUMNS - 1))
    }

    /// "Load as ladder": the text pane's program becomes the ladder
    /// (one undo brings the old one back); the engine's located error
    /// otherwise, with nothing changed.
    pub fn load_text_as_ladder(&self) -> Result<(), String> {
        let Some(program) = self.text.pane.get_value() else {
            return Err("no program pane".into());
        };
        let text = program.text.get_untracked();
        let ladder = self.ladder_of_text(&text)?;
        // The pane holds the same program: it follows the ladder again.
        self.text.synced.set_value(Some(text));
        if self.ladder() != ladder {
            self.apply(Edit::Replace { ladder });
        }
        Ok(())
    }

    /// The text pane's program is the ladder's (it was opened from the
    /// same example): the pane follows the ladder from now on.
    pub fn adopt_text(&self) {
        if let Some(program) = self.text.pane.get_value() {
            self.text
                .synced
                .set_value(Some(program.text.get_untracked()));
        }
    }

    /// The drawing written to the machine with its source map for the
    /// live colours ([`LadderCtx::start_live`], then
    /// [`LadderCtx::write_to_machine`]): what Run, Write to PLC and an edit
    /// while running do. False while it does not compile.
    pub fn write_drawing(&self) -> bool {
        self.start_live() && self.write_to_machine()
    }

    /// The listing goes into the text pane and is loaded into the machine.
    /// False while the ladder does not compile.
    pub(super) fn write_to_machine(&self) -> bool {
        let Some(listing) = self.drawing.listing.get_untracked() else {
            return false;
        };
        let Some(program) = self.text.pane.get_value() else {
            return false;
        };
        program.text.set(listing.text.clone());
        self.text.synced.set_value(Some(listing.text));
        program.load.run(());
        self.forget_handles();
        true
    }

    /// The text pane takes the new listing while it still holds the last.
    pub(super) fn follow(&self, listing: Option<&Listing>) {
        let (Some(program), Some(listing)) = (self.text.pane.get_value(), listing) else {
            return;
        };
        let text = program.text.get_untracked();
        let follows = self
            .text
            .synced
            .with_value(|s| s.as_deref() == Some(text.as_str()));
        if follows && text != listing.text {
            program.text.set(listing.text.clone());
            self.text.synced.set_value(Some(listing.text.clone()));
            program.save.run(());
        }
    }
}
