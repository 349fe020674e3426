//! Errors that name the place in the user's input they come from.

use std::fmt;

/// An error at a 1-based line of a text input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Located<E> {
    /// The 1-based line number.
    pub line: usize,
    /// What is wrong there.
    pub error: E,
}

impl<E> Located<E> {
    /// `error` at `line`.
    pub const fn new(line: usize, error: E) -> Self {
        Located { line, error }
    }

    /// The error as the command line prints it: `error: FILE:LINE: message`.
    pub fn report(&self, file: &str) -> String
    where
        E: fmt::Display,
    {
        format!("error: {file}:{}: {}", self.line, self.error)
    }
}

impl<E: fmt::Display> fmt::Display for Located<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.error)
    }
}

impl<E: fmt::Debug + fmt::Display> std::error::Error for Located<E> {}

/// Writes `items` separated by `; `: several problems as one message.
pub fn write_joined<T: fmt::Display>(
    f: &mut fmt::Formatter<'_>,
    items: impl IntoIterator<Item = T>,
) -> fmt::Result {
    for (i, item) in items.into_iter().enumerate() {
        if i > 0 {
            f.write_str("; ")?;
        }
        write!(f, "{item}")?;
    }
    Ok(())
}

/// `text` as an error message repeats it: in quotes, control characters
/// and quotes escaped, cut to [`crate::limits::MAX_ECHO_CHARS`] characters
/// with `…` so that one problem stays one short line whatever the input.
pub fn shown(text: &str) -> String {
    let mut out = String::from("\"");
    for (i, c) in text.chars().enumerate() {
        if i == crate::limits::MAX_ECHO_CHARS {
            out.push('…');
            break;
        }
        if c.is_control() || c == '"' || c == '\\' {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::shown;

    #[test]
    fn shown_quotes_escapes_and_shortens() {
        assert_eq!(shown("X00"), "\"X00\"");
        assert_eq!(shown("a\u{0}b\u{1b}\n"), "\"a\\u{0}b\\u{1b}\\n\"");
        let long = "x".repeat(50_000_000 / 1000);
        let s = shown(&long);
        assert!(s.chars().count() < 50 && s.ends_with("…\""), "{s}");
    }
}
