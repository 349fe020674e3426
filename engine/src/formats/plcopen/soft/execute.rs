//! CODESYS's EXECUTE block (issue #54): a box of a drawn body holding
//! ST (`STCode` in its `addData`), run where the box stands while its EN
//! is on, through the ST lowering (`st_body::lower`).

use super::emit::Emitter;
use super::il_body::{write_lines, Place};
use super::st_body::{lower, Lines, Scope};
use super::SoftError;
use crate::formats::plcopen::dom::Node;
use crate::formats::plcopen::graph::{Element, Graph};

/// The ST code of a CODESYS EXECUTE block's element (`STCode` in its
/// `addData`), if it has one.
fn execute_code(block: &Node) -> Option<&Node> {
    let mut found = Vec::new();
    block.descendants("STCode", &mut found);
    found.first().copied()
}

impl Emitter<'_> {
    /// CODESYS's EXECUTE block: its ST runs where the block stands, while
    /// EN is on (jumped over while off, as any block's EN is); ENO is EN.
    /// A `RETURN` in it ends the block's code. Its ST problems go to
    /// `out.errors`, each at its line of the file.
    pub(super) fn execute(&mut self, g: &Graph, e: &Element) -> Result<(), SoftError> {
        let Some(code) = execute_code(e.node) else {
            return Err(SoftError::Block("EXECUTE".into()));
        };
        let tag = format!("_{}_x{}_", self.index, e.id);
        let scope = Scope {
            pou: &self.pou,
            decl: self.decl,
            user: self.user,
        };
        // CODESYS writes the code right after the tag, on its line.
        let (vars, lines) = match lower(&scope, &code.text, code.line, &tag) {
            Ok(lowered) => lowered,
            Err(mut errors) => {
                self.out.errors.append(&mut errors);
                return Err(SoftError::Follows);
            }
        };
        let en = self.enable(g, e)?;
        self.out.vars.extend(vars);
        let end = format!("{tag}end");
        let lines: Lines = lines
            .into_iter()
            .map(|(l, at)| match l.as_str() {
                "RET" => (format!("JMP {end}"), at),
                _ => (l, at),
            })
            .collect();
        let place = Place {
            decl: self.decl,
            out: self.out,
            labels: None,
            user: None,
            copy_out: Vec::new(),
        };
        let errors = write_lines(&self.pou, lines, place);
        self.out.errors.extend(errors);
        self.out.lines.push((format!("{end}:"), e.line));
        self.enabled(e, en);
        Ok(())
    }
}
