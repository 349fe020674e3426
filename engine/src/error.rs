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
