//! Each POU's body as its source writes it (comments and layout kept),
//! for writers that hold a body apart from its declarations (a PLCopen
//! project's `<ST>` body, issue #54).

use super::ast::{Item, Source};
use super::lexer::{tokenize, Tok, Token};
use super::print_body;

/// The body of each POU of `source` (parsed from `text`), in the order
/// of its items: the text between the POU's last `END_VAR` (or its
/// header's line) and its `END_…` keyword, its common indent taken off.
/// A slice that does not parse to the very statements parsed (a header
/// and a statement on one line) is replaced by the statements printed,
/// so what is given always reads back to the same body.
pub fn body_texts(text: &str, source: &Source) -> Vec<String> {
    let tokens = tokenize(text).unwrap_or_default();
    let starts = line_starts(text);
    let mut out = Vec::new();
    for item in &source.items {
        let Item::Pou(pou) = item else { continue };
        let printed = print_body(&pou.body);
        let sliced = slice(text, &tokens, &starts, pou.span.line, pou.span.column);
        let same = sliced
            .as_deref()
            .and_then(|s| super::parse_body(s).ok())
            .is_some_and(|stmts| print_body(&stmts) == printed);
        out.push(match sliced {
            Some(s) if same => s,
            _ => dedent(&printed),
        });
    }
    out
}

/// The byte offset each line starts at.
fn line_starts(text: &str) -> Vec<usize> {
    std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .collect()
}

/// The byte offset of (line, column in characters), both 1-based.
fn offset(text: &str, starts: &[usize], line: u32, column: u32) -> Option<usize> {
    let start = *starts.get((line as usize).checked_sub(1)?)?;
    let rest = text.get(start..)?;
    let skip = (column as usize).saturating_sub(1);
    Some(
        rest.char_indices()
            .nth(skip)
            .map_or(text.len(), |(i, _)| start + i),
    )
}

/// The body text of the POU whose keyword is at (line, column).
fn slice(text: &str, tokens: &[Token], starts: &[usize], line: u32, column: u32) -> Option<String> {
    let first = tokens
        .iter()
        .position(|t| t.span.line == line && t.span.column == column)?;
    let is_end = |t: &Token| matches!(t.tok, Tok::Keyword(k) if matches!(k, "END_PROGRAM" | "END_FUNCTION" | "END_FUNCTION_BLOCK"));
    let last = first + tokens[first..].iter().position(is_end)?;
    let end_var = tokens[first..last]
        .iter()
        .rev()
        .find(|t| matches!(t.tok, Tok::Keyword("END_VAR")));
    let from = match end_var {
        Some(t) => offset(text, starts, t.span.line, t.span.column)? + t.text.len(),
        // No declarations: the body starts on the line after the header.
        None => *starts.get(line as usize)?,
    };
    let end = &tokens[last];
    let to = offset(text, starts, end.span.line, end.span.column)?;
    Some(dedent(text.get(from..to)?))
}

/// `s` without its leading blank lines, trailing blanks and the indent
/// every non-blank line shares.
fn dedent(s: &str) -> String {
    let lines: Vec<&str> = s.lines().collect();
    let Some(first) = lines.iter().position(|l| !l.trim().is_empty()) else {
        return String::new();
    };
    let indent = lines[first..]
        .iter()
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    let kept: Vec<&str> = lines[first..]
        .iter()
        .map(|l| l.get(indent..).unwrap_or_else(|| l.trim_start()))
        .collect();
    kept.join("\n").trim_end().to_string() + "\n"
}
