//! LDmicro's escapes in the texts it saves (comments, strings, quoted
//! characters).

/// LDmicro's escapes in a saved string (`\n`, `\r`, `\t`, `\\`, `\x20`
/// for a space, `\'`, `\"`, `\?`, `\a`, `\b`, `\e`, `\f`, `\v`); an
/// unknown one keeps its backslash, as LDmicro does.
pub fn unescape(text: &str) -> String {
    if text == "(none)" {
        return String::new();
    }
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        let rest: String = chars.clone().take(4).collect();
        if rest.starts_with("x20") {
            out.push(' ');
            chars.nth(2);
            continue;
        }
        if rest.starts_with("\\x20") {
            out.push(' ');
            chars.nth(3);
            continue;
        }
        let mapped = match chars.peek() {
            Some('\'') => Some('\''),
            Some('"') => Some('"'),
            Some('?') => Some('?'),
            Some('\\') => Some('\\'),
            Some('a') => Some('\u{7}'),
            Some('b') => Some('\u{8}'),
            Some('e') => Some('\u{1b}'),
            Some('f') => Some('\u{c}'),
            Some('n') => Some('\n'),
            Some('r') => Some('\r'),
            Some('t') => Some('\t'),
            Some('v') => Some('\u{b}'),
            _ => None,
        };
        match mapped {
            Some(m) => {
                out.push(m);
                chars.next();
            }
            None => out.push('\\'),
        }
    }
    out
}
