//! IEC 61131-3 identifiers: the names of variables, blocks and
//! programs, as every text Hashigo reads them (IL, PLCopen, LDmicro's
//! names once mapped, the ladder's variables).

/// Whether `name` is an IEC identifier.
pub fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.contains("__")
}

#[cfg(test)]
mod tests {
    use super::is_identifier;

    #[test]
    fn identifiers() {
        for ok in ["a", "_x", "Motor_1", "T0"] {
            assert!(is_identifier(ok), "{ok}");
        }
        for bad in ["", "1a", "a b", "a__b", "é", "a-b"] {
            assert!(!is_identifier(bad), "{bad}");
        }
    }
}
