//! A light reading of Structured Text for the page (issue #55): each
//! line's pieces for colouring (keywords, literals, comments), the names
//! each line uses (for the live values beside it), and the names a POU
//! declares (for completion). The engine's parser decides what loads;
//! this only colours and lists, so it never refuses anything.

use engine::iec::st::KEYWORDS;

/// What a piece of a line is, for its colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Keyword,
    /// An elementary type's name (`INT`, `BOOL`).
    Type,
    Name,
    /// A number, `TRUE`/`FALSE`, a typed or time literal.
    Number,
    Text,
    Comment,
    Other,
}

impl Kind {
    /// Its CSS class.
    pub fn class(self) -> &'static str {
        match self {
            Kind::Keyword => "st-kw",
            Kind::Type => "st-type",
            Kind::Name => "st-name",
            Kind::Number => "st-num",
            Kind::Text => "st-str",
            Kind::Comment => "st-comment",
            Kind::Other => "st-other",
        }
    }
}

/// The elementary types coloured as types.
const TYPES: [&str; 22] = [
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "BYTE", "WORD",
    "DWORD", "LWORD", "REAL", "LREAL", "TIME", "STRING", "TON", "TOF", "TP", "CTU", "R_TRIG",
];

fn word_kind(word: &str) -> Kind {
    let upper = word.to_ascii_uppercase();
    if upper == "TRUE" || upper == "FALSE" {
        Kind::Number
    } else if KEYWORDS.contains(&upper.as_str()) {
        Kind::Keyword
    } else if TYPES.contains(&upper.as_str()) {
        Kind::Type
    } else {
        Kind::Name
    }
}

/// Each line's pieces: (kind, text), the text of all of them the line.
/// A `(* … *)` comment may run over lines (nested, as the 3rd edition
/// allows).
pub fn pieces(text: &str) -> Vec<Vec<(Kind, String)>> {
    let mut depth = 0usize;
    text.split('\n')
        .map(|line| line_pieces(line, &mut depth))
        .collect()
}

fn line_pieces(line: &str, depth: &mut usize) -> Vec<(Kind, String)> {
    let chars: Vec<char> = line.chars().collect();
    let mut out: Vec<(Kind, String)> = Vec::new();
    let mut push = |kind: Kind, s: &[char]| {
        if let Some((k, last)) = out.last_mut() {
            if *k == kind && kind != Kind::Name && kind != Kind::Keyword {
                last.extend(s);
                return;
            }
        }
        out.push((kind, s.iter().collect()));
    };
    let mut i = 0;
    while i < chars.len() {
        let rest = &chars[i..];
        let two = |a: char, b: char| rest.len() > 1 && rest[0] == a && rest[1] == b;
        let end = if *depth > 0 || two('(', '*') {
            let mut j = i;
            while j < chars.len() {
                if j + 1 < chars.len() && chars[j] == '(' && chars[j + 1] == '*' {
                    *depth += 1;
                    j += 2;
                } else if j + 1 < chars.len() && chars[j] == '*' && chars[j + 1] == ')' {
                    *depth = depth.saturating_sub(1);
                    j += 2;
                    if *depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            push(Kind::Comment, &chars[i..j]);
            j
        } else if two('/', '/') {
            push(Kind::Comment, rest);
            chars.len()
        } else if rest[0] == '\'' || rest[0] == '"' {
            let q = rest[0];
            let j = (i + 1..chars.len())
                .find(|&j| chars[j] == q && chars[j - 1] != '$')
                .map_or(chars.len(), |j| j + 1);
            push(Kind::Text, &chars[i..j]);
            j
        } else if rest[0].is_ascii_digit() {
            let j = (i..chars.len())
                .find(|&j| !(chars[j].is_ascii_alphanumeric() || "_#.".contains(chars[j])))
                .unwrap_or(chars.len());
            push(Kind::Number, &chars[i..j]);
            j
        } else if rest[0].is_alphabetic() || rest[0] == '_' {
            let j = (i..chars.len())
                .find(|&j| !(chars[j].is_alphanumeric() || chars[j] == '_'))
                .unwrap_or(chars.len());
            let word: String = chars[i..j].iter().collect();
            // A typed or time literal: `T#1s`, `INT#5`.
            if j < chars.len() && chars[j] == '#' {
                let k = (j + 1..chars.len())
                    .find(|&k| !(chars[k].is_alphanumeric() || "_.-+#".contains(chars[k])))
                    .unwrap_or(chars.len());
                push(Kind::Number, &chars[i..k]);
                k
            } else {
                push(word_kind(&word), &chars[i..j]);
                j
            }
        } else {
            push(Kind::Other, &chars[i..=i]);
            i + 1
        };
        i = end.max(i + 1);
    }
    out
}

/// The names each line uses (1-based line, names in order of first use;
/// `a.b` as one name), keywords, types and literals left out.
pub fn names_by_line(text: &str) -> Vec<(usize, Vec<String>)> {
    pieces(text)
        .into_iter()
        .enumerate()
        .filter_map(|(n, line)| {
            let mut names: Vec<String> = Vec::new();
            let mut i = 0;
            while i < line.len() {
                if line[i].0 == Kind::Name {
                    let mut name = line[i].1.clone();
                    // `t.q`: a block instance's output.
                    while i + 2 < line.len()
                        && line[i + 1] == (Kind::Other, ".".to_string())
                        && line[i + 2].0 == Kind::Name
                    {
                        name.push('.');
                        name.push_str(&line[i + 2].1);
                        i += 2;
                    }
                    if !names.iter().any(|n| n.eq_ignore_ascii_case(&name)) {
                        names.push(name);
                    }
                }
                i += 1;
            }
            (!names.is_empty()).then_some((n + 1, names))
        })
        .collect()
}

/// The names the text declares (`name : TYPE` in its `VAR` blocks, a
/// `FUNCTION_BLOCK`'s name), each with whether it is a block.
pub fn declared(text: &str) -> Vec<(String, bool)> {
    let mut out: Vec<(String, bool)> = Vec::new();
    let words: Vec<(Kind, String)> = pieces(text)
        .into_iter()
        .flatten()
        .filter(|(k, s)| *k != Kind::Comment && !s.trim().is_empty())
        .collect();
    // In a VAR block, before a declaration's `:` (names are listed).
    let (mut in_var, mut naming) = (false, false);
    let mut block_next = false;
    for (kind, word) in &words {
        let upper = word.to_ascii_uppercase();
        if upper.starts_with("VAR") && *kind == Kind::Keyword {
            (in_var, naming) = (true, true);
        } else if upper == "END_VAR" {
            (in_var, naming) = (false, false);
        } else if upper == "FUNCTION_BLOCK" {
            block_next = true;
            continue;
        } else if block_next && *kind == Kind::Name {
            out.push((word.clone(), true));
        } else if in_var && word.trim() == ":" {
            naming = false;
        } else if in_var && word.contains(';') {
            naming = true;
        } else if naming
            && *kind == Kind::Name
            && !out.iter().any(|(n, _)| n.eq_ignore_ascii_case(word))
        {
            out.push((word.clone(), false));
        }
        block_next = false;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_is_coloured_by_what_each_piece_is() {
        let lines = pieces("IF a > 16#FF THEN (* a\nb *) s := 'x'; // c\nEND_IF");
        let kinds = |n: usize| -> Vec<Kind> {
            lines[n]
                .iter()
                .filter(|(_, s)| !s.trim().is_empty())
                .map(|(k, _)| *k)
                .collect()
        };
        assert_eq!(
            kinds(0),
            [
                Kind::Keyword,
                Kind::Name,
                Kind::Other,
                Kind::Number,
                Kind::Keyword,
                Kind::Comment
            ]
        );
        assert_eq!(
            kinds(1),
            [
                Kind::Comment,
                Kind::Name,
                Kind::Other,
                Kind::Text,
                Kind::Other,
                Kind::Comment
            ]
        );
        assert_eq!(kinds(2), [Kind::Keyword]);
        // Every character is kept, in order.
        let back: Vec<String> = lines
            .iter()
            .map(|l| l.iter().map(|(_, s)| s.as_str()).collect())
            .collect();
        assert_eq!(
            back.join("\n"),
            "IF a > 16#FF THEN (* a\nb *) s := 'x'; // c\nEND_IF"
        );
    }

    #[test]
    fn each_line_names_the_variables_it_uses() {
        let text = "x := T#1s; (* y *)\nb := t.q AND NOT a;\n\nIF TRUE THEN x := x; END_IF";
        let names = names_by_line(text);
        assert_eq!(
            names,
            [
                (1, vec!["x".to_string()]),
                (2, vec!["b".to_string(), "t.q".to_string(), "a".to_string()]),
                (4, vec!["x".to_string()]),
            ]
        );
    }

    #[test]
    fn the_declared_names_and_blocks() {
        let text = "FUNCTION_BLOCK Twice\nVAR_INPUT x : INT; END_VAR\nEND_FUNCTION_BLOCK\nPROGRAM p\nVAR\n  a, b : INT; (* c : INT *)\n  t : Twice;\nEND_VAR\na := 1;\nEND_PROGRAM";
        let names: Vec<(String, bool)> = declared(text);
        let want = [
            ("Twice", true),
            ("x", false),
            ("a", false),
            ("b", false),
            ("t", false),
        ];
        let want: Vec<(String, bool)> = want.iter().map(|(n, b)| (n.to_string(), *b)).collect();
        assert_eq!(names, want);
    }
}
