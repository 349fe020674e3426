//! PLCopen TC6 XML.
use super::grid::Ladder;
use crate::error::Located;

/// Imports.
pub fn import(_text: &str) -> Result<Ladder, Vec<Located<String>>> {
    Err(vec![Located::new(1, "todo".to_string())])
}
