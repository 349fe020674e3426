//! A POU's IL body (`<body><IL>`, issue #44) on the soft PLC: its text
//! is already the soft PLC's language, so it goes to the IL loader line
//! for line, each at its line of the file (an error there is said
//! there). What changes on the way:
//!
//! - a program's names that clash with another program's are written
//!   as renamed (`prog2_count`), as its declarations are;
//! - a program's labels are made unique in the program's section (the
//!   programs the tasks run share one), `prog2_loop` when taken;
//! - `RET`, `RETC`, `RETCN` in a program end that program, not the scan:
//!   they jump to a label at the body's end;
//! - a `CAL` whose parameters go on over several lines (as IEC's
//!   examples write it) is joined into one line.
//!
//! Labels on their own line and a label whose instruction uses the
//! current result are the loader's own (`iec::il`).

use std::collections::{HashMap, HashSet};

use super::declare::{Declarations, Interface};
use super::emit::Output;
use super::SoftError;
use crate::error::Located;
use crate::formats::plcopen::dom::Node;

/// The text of `pou`'s IL body, if it has one, and the node it is in.
pub(super) fn il_body(pou: &Node) -> Option<&Node> {
    let il = pou.child("body")?.child("IL")?;
    Some(il.child("p").unwrap_or(il))
}

/// Where the body's lines go, and what they are written in.
pub(super) struct Place<'a> {
    pub decl: &'a Declarations,
    pub out: &'a mut Output,
    /// A program's: its labels unique among `labels` (upper-case), its
    /// RETs ending it alone. `None`: a function block's own section.
    pub labels: Option<&'a mut HashSet<String>>,
    /// The project's own blocks and functions (upper-case), so that an
    /// IL line calling one of its functions calls it (`il_call`).
    pub user: Option<&'a HashMap<String, Interface>>,
    /// What runs when the body ends, its RETs too: a function block's
    /// externals copied back out (`Declarations::copy_out`).
    pub copy_out: Vec<String>,
}

/// Writes the IL body `text_node` of `pou` (from file `source`); a line
/// that is not an instruction (a `VAR` block, `END_PROGRAM`), refused
/// at its line.
pub(super) fn write(
    pou: &Node,
    text_node: &Node,
    source: &str,
    place: Place,
) -> Vec<Located<SoftError>> {
    let text = text_node.text.as_str();
    let first = first_line(text, text_node.line, source);
    let lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (l.to_string(), first + i));
    write_lines(pou.attr("name").unwrap_or_default(), lines.collect(), place)
}

/// Writes IL `lines` of POU `name`'s body, each with its file line, as
/// [`write`] does.
pub(super) fn write_lines(
    name: &str,
    lines: Vec<(String, usize)>,
    place: Place,
) -> Vec<Located<SoftError>> {
    let mut errors = Vec::new();
    let first = lines.first().map_or(0, |&(_, at)| at);
    let written = place.out.lines.len();
    let mut renamed_labels = HashMap::new();
    let copy_out = !place.copy_out.is_empty();
    let end = end_label(name, &lines, (place.labels, copy_out), &mut renamed_labels);
    let mut words = Words {
        pou: name,
        decl: place.decl,
        labels: &renamed_labels,
        end: end.as_deref(),
        returned: false,
    };
    let mut comment = false;
    let mut call: Option<(String, usize, i64)> = None;
    let mut last = first;
    for (raw, at) in &lines {
        let at = *at;
        last = at;
        let (line, code) = words.rewrite(raw, &mut comment);
        if let Some(word) = section_word(&code) {
            errors.push(Located::new(at, SoftError::BodySection(word.to_string())));
            continue;
        }
        if call.is_none() {
            let own = (place.user, place.decl, &mut *place.out);
            if let Some(lines) = own_function(&line, &code, name, own, at) {
                match lines {
                    Ok(lines) => place.out.lines.extend(lines.into_iter().map(|l| (l, at))),
                    Err(e) => errors.push(Located::new(at, e)),
                }
                continue;
            }
        }
        let depth = paren_depth(&code);
        if let Some((mut joined, from, open)) = call.take() {
            joined.push(' ');
            joined.push_str(line.trim());
            match open + depth {
                d if d > 0 => call = Some((joined, from, d)),
                _ => place.out.lines.push((joined, from)),
            }
            continue;
        }
        if depth > 0 && is_call(&code) {
            call = Some((line, at, depth));
            continue;
        }
        place.out.lines.push((line, at));
    }
    if let Some((joined, from, _)) = call {
        // Never closed: the loader says so at the CAL's line.
        place.out.lines.push((joined, from));
    }
    if let (Some(end), true) = (words.end, words.returned) {
        place.out.lines.push((format!("{end}:"), last));
    }
    if let Some(user) = place.user {
        let lines = &mut place.out.lines[written..];
        errors.extend(pass_externals(lines, name, place.decl, user));
    }
    let copy_out = place.copy_out.iter().map(|l| (l.clone(), last));
    place.out.lines.extend(copy_out);
    errors
}

/// The label a body's RETs jump to: a program's (its labels, renamed
/// into `renamed`, and its end unique among `labels`, the programs'
/// section's), or a block's that copies its externals out (`copy_out`:
/// its end a label none of its own); `None` for another block, whose
/// RETs return.
fn end_label(
    name: &str,
    lines: &[(String, usize)],
    (labels, copy_out): (Option<&mut HashSet<String>>, bool),
    renamed: &mut HashMap<String, String>,
) -> Option<String> {
    let own = lines.iter().filter_map(|(l, _)| label_of(l));
    match labels {
        Some(used) => {
            for label in own {
                renamed.insert(label.to_ascii_uppercase(), unique(label, name, used));
            }
            Some(unique(&format!("{name}_end"), name, used))
        }
        None if copy_out => {
            let mut used = own.map(str::to_ascii_uppercase).collect();
            Some(unique(&format!("{name}_end"), name, &mut used))
        }
        None => None,
    }
}

/// Each `CAL` of `lines` (POU `pou`'s, written) of an instance of the
/// project's own block that has externals given them
/// ([`super::il_call::with_externals`]); a call whose POU has no
/// variable for one, refused at its line.
fn pass_externals(
    lines: &mut [(String, usize)],
    pou: &str,
    decl: &Declarations,
    user: &HashMap<String, Interface>,
) -> Vec<Located<SoftError>> {
    let mut errors = Vec::new();
    for (line, at) in lines {
        let code = super::il_call::without_comments(line);
        let (label, rest) = match code.split_once(':') {
            Some((head, rest)) if label_of(&code) == Some(head.trim()) => {
                (format!("{}: ", head.trim()), rest)
            }
            _ => (String::new(), code.as_str()),
        };
        match super::il_call::with_externals(rest, pou, decl, user) {
            Some(Ok(call)) => *line = format!("{label}{call}"),
            Some(Err(e)) => errors.push(Located::new(*at, e)),
            None => {}
        }
    }
    errors
}

/// The lines calling the project's own function when `code` (of body
/// line `line`) calls one ([`super::il_call`]), its label first.
fn own_function(
    line: &str,
    code: &str,
    pou: &str,
    (user, decl, out): (
        Option<&HashMap<String, Interface>>,
        &Declarations,
        &mut Output,
    ),
    at: usize,
) -> Option<Result<Vec<String>, SoftError>> {
    let user = user?;
    let (label, code) = match code.split_once(':') {
        Some((head, rest)) if label_of(code) == Some(head.trim()) => {
            (Some(label_of(line.trim())?), rest)
        }
        _ => (None, code),
    };
    let call = super::il_call::own_function_call(code, (user, decl), pou, out, at)?;
    Some(call.map(|lines| {
        let label = label.map(|l| format!("{l}:"));
        label.into_iter().chain(lines).collect()
    }))
}

/// The first word of `code` when it opens or closes a section of an IL
/// text (`VAR_INPUT`, `END_PROGRAM`, `FUNCTION_BLOCK` …), which a body
/// does not hold (the loader would read it as one).
fn section_word(code: &str) -> Option<String> {
    let word = code.split(|c: char| c.is_whitespace() || c == ';').next()?;
    let upper = word.to_ascii_uppercase();
    let sections = [
        "VAR",
        "END_VAR",
        "PROGRAM",
        "END_PROGRAM",
        "FUNCTION_BLOCK",
        "END_FUNCTION_BLOCK",
        "FUNCTION",
        "END_FUNCTION",
    ];
    (sections.contains(&upper.as_str()) || upper.starts_with("VAR_")).then_some(upper)
}

/// `label`, or `pou_label` (then `pou_label3` …) when `used` has it;
/// used from now on.
fn unique(label: &str, pou: &str, used: &mut HashSet<String>) -> String {
    let mut out = label.to_string();
    let mut n = 2;
    while used.contains(&out.to_ascii_uppercase()) {
        out = match n {
            2 => format!("{pou}_{label}"),
            _ => format!("{pou}_{label}{n}"),
        };
        n += 1;
    }
    used.insert(out.to_ascii_uppercase());
    out
}

/// The file line of the text's first line: the text is trimmed, so the
/// line of the file from `from` on that holds its first line.
pub(super) fn first_line(text: &str, from: usize, source: &str) -> usize {
    let Some(head) = text.lines().next().map(str::trim).filter(|h| !h.is_empty()) else {
        return from;
    };
    source
        .lines()
        .enumerate()
        .skip(from.saturating_sub(1))
        .take(200)
        .find(|(_, l)| l.contains(head))
        .map_or(from, |(i, _)| i + 1)
}

/// The label a line defines (`name:` first on it), if any.
fn label_of(line: &str) -> Option<&str> {
    let (head, rest) = line.split_once(':')?;
    let head = head.trim();
    let ok = !rest.starts_with('=') && crate::iec::is_identifier(head);
    ok.then_some(head)
}

/// A `CAL` line (after its label, if it has one).
fn is_call(code: &str) -> bool {
    let code = match code.split_once(':') {
        Some((head, rest)) if label_of(code) == Some(head.trim()) => rest,
        _ => code,
    };
    let word = code.split_whitespace().next().unwrap_or_default();
    word.get(..3).is_some_and(|w| w.eq_ignore_ascii_case("CAL"))
}

/// `(` less `)` in code with no comments.
fn paren_depth(code: &str) -> i64 {
    code.chars().fold(0, |d, c| match c {
        '(' => d + 1,
        ')' => d - 1,
        _ => d,
    })
}

/// How the body's words are written in the soft PLC's text.
struct Words<'a> {
    pou: &'a str,
    decl: &'a Declarations,
    labels: &'a HashMap<String, String>,
    /// A program's end label, that its RETs jump to.
    end: Option<&'a str>,
    returned: bool,
}

impl Words<'_> {
    /// `raw` rewritten (comments and texts as they are), and its code
    /// alone; `comment`: inside a `(* … *)` that goes on.
    fn rewrite(&mut self, raw: &str, comment: &mut bool) -> (String, String) {
        let chars: Vec<char> = raw.chars().collect();
        let (mut out, mut code) = (String::new(), String::new());
        let mut i = 0;
        // Which word of the line's code this is: label, operator, operand.
        let mut nth = 0;
        let mut operator = String::new();
        while i < chars.len() {
            let c = chars[i];
            if *comment {
                out.push(c);
                if c == '*' && chars.get(i + 1) == Some(&')') {
                    out.push(')');
                    i += 1;
                    *comment = false;
                }
                i += 1;
                continue;
            }
            if c == '(' && chars.get(i + 1) == Some(&'*') {
                *comment = true;
                out.push_str("(*");
                i += 2;
                continue;
            }
            if c == '\'' {
                let start = i;
                i += 1;
                while i < chars.len() && chars[i] != '\'' {
                    i += if chars[i] == '$' { 2 } else { 1 };
                }
                i = (i + 1).min(chars.len());
                let text: String = chars[start..i].iter().collect();
                out.push_str(&text);
                code.push_str(&text);
                continue;
            }
            if c.is_ascii_alphanumeric() || c == '_' {
                let start = i;
                while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let word: String = chars[start..i].iter().collect();
                let before = code.trim_end().chars().last();
                // The two characters after the word and its spaces (not
                // the rest of the line: a long line stays linear).
                let after: String = chars[i..]
                    .iter()
                    .skip_while(|c| c.is_whitespace())
                    .take(2)
                    .collect();
                let after = after.as_str();
                let written = self.word(&word, before, after, &mut nth, &mut operator);
                out.push_str(&written);
                code.push_str(&written);
                continue;
            }
            out.push(c);
            code.push(c);
            i += 1;
        }
        (out, code)
    }

    /// One word of the code: `before` the character before it, `after`
    /// the line after it.
    fn word(
        &mut self,
        word: &str,
        before: Option<char>,
        after: &str,
        nth: &mut usize,
        operator: &mut String,
    ) -> String {
        let literal = word.starts_with(|c: char| c.is_ascii_digit());
        if literal || matches!(before, Some('.' | '#')) || after.starts_with('#') {
            return word.to_string();
        }
        if after.starts_with(":=") || after.starts_with("=>") {
            return word.to_string(); // a CAL's parameter name
        }
        let first = *nth == 0;
        *nth += 1;
        if first && after.starts_with(':') {
            *nth = 0; // the label: the operator comes next
            return self.label(word);
        }
        if operator.is_empty() {
            *operator = word.to_ascii_uppercase();
            let ret = ["RET", "RETC", "RETCN"].contains(&operator.as_str());
            return match (self.end, ret) {
                (Some(end), true) => {
                    self.returned = true;
                    format!("{} {end}", operator.replacen("RET", "JMP", 1))
                }
                _ => word.to_string(),
            };
        }
        if operator.starts_with("JMP") {
            return self.label(word);
        }
        self.decl.name_in(self.pou, word)
    }

    fn label(&self, word: &str) -> String {
        self.labels
            .get(&word.to_ascii_uppercase())
            .cloned()
            .unwrap_or_else(|| word.to_string())
    }
}
