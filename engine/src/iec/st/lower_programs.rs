//! Several ST programs lowered as one IL program, one after the other
//! (their declarations renamed apart by `super::rename`).

use super::ast::Pou;
use super::lower::Lower;

impl Lower {
    /// Several programs as one IL program, one after the other, each
    /// with its own declarations (renamed apart by [`super::rename::programs`]); a
    /// `RETURN` ends its own program, not the scan. The globals are
    /// declared with the first.
    pub(super) fn programs(&mut self, programs: &[Pou]) {
        let Some(first) = programs.first() else {
            return;
        };
        self.emit(format!("PROGRAM {}", first.name.name), first.span);
        let last = programs.len().saturating_sub(1);
        for (i, p) in programs.iter().enumerate() {
            let end = (i < last).then(|| self.label());
            self.ret = end.clone();
            self.pou_inside(p);
            self.ret = None;
            if let Some(end) = end {
                self.place(&end, p.span);
            }
        }
        self.emit("END_PROGRAM", first.span);
    }
}
