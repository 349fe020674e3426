//! The variables a soft PLC ladder declares (issue #30): what a name
//! holds (an elementary type or a standard block), where it is located,
//! its start value, whether it is kept over a power cycle, a comment.
//! Names a contact or coil uses undeclared are BOOLs; words must be
//! declared, since `count` could be any of the integer types.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::iec::data::DataType;
use crate::iec::is_identifier;
use crate::iec::{parse_literal, Address, AddressError, LiteralError};
use crate::ladder::user_blocks::is_block_type;

/// One declared variable.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Variable {
    /// An IEC name (compared without regard to case).
    pub name: String,
    /// `INT`, `BOOL`, `REAL`, `TIME` … or a block (`TON`, `CTU`).
    #[serde(rename = "type")]
    pub data_type: String,
    /// `%IX0.0`, `%QW2` … or empty.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub address: String,
    /// Its value at power-on, as an IEC literal, or empty for the
    /// type's zero.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub initial: String,
    /// Kept over a power cycle (`VAR_RETAIN`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub retain: bool,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

impl Variable {
    /// A variable of `data_type` with nothing else.
    pub fn new(name: &str, data_type: &str) -> Variable {
        Variable {
            name: name.to_string(),
            data_type: data_type.to_string(),
            address: String::new(),
            initial: String::new(),
            retain: false,
            comment: String::new(),
        }
    }

    /// Its elementary type, if it has one.
    pub fn elementary(&self) -> Option<DataType> {
        DataType::from_name(self.data_type.trim())
    }

    /// Why it is not a declaration the soft PLC takes.
    pub fn check(&self) -> Result<(), VariableError> {
        let name = self.name.clone();
        if !is_identifier(&name) {
            return Err(VariableError::BadName(name));
        }
        let ty = self.data_type.trim().to_ascii_uppercase();
        match self.elementary() {
            Some(t) => {
                if !self.address.is_empty() {
                    Address::parse(&self.address)
                        .and_then(|a| a.for_type(t))
                        .map_err(|e| VariableError::Address(name.clone(), e))?;
                }
                if !self.initial.is_empty() {
                    parse_literal(&self.initial, Some(t))
                        .map_err(|e| VariableError::Initial(name.clone(), e))?;
                }
            }
            None if is_block_type(&ty) => {
                if !self.address.is_empty() || !self.initial.is_empty() {
                    return Err(VariableError::BlockWithValue(name, ty));
                }
            }
            None => return Err(VariableError::UnknownType(name, self.data_type.clone())),
        }
        Ok(())
    }

    /// Its declaration line: `name [AT %address] : TYPE [:= value];
    /// [(* comment *)]`.
    pub fn declaration(&self) -> String {
        let mut line = self.name.clone();
        if !self.address.is_empty() {
            line.push_str(&format!(" AT {}", self.address.trim()));
        }
        line.push_str(&format!(
            " : {}",
            self.data_type.trim().to_ascii_uppercase()
        ));
        if !self.initial.is_empty() {
            line.push_str(&format!(" := {}", self.initial.trim()));
        }
        line.push(';');
        if !self.comment.is_empty() {
            let one = self.comment.replace(['\n', '\r'], " ").replace("*)", "* )");
            line.push_str(&format!(" (* {one} *)"));
        }
        line
    }
}

/// Why a declaration is not one the soft PLC takes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VariableError {
    /// Not an IEC name.
    BadName(String),
    /// An address that does not parse or does not hold the type.
    Address(String, AddressError),
    /// An initial value that is no literal of the type.
    Initial(String, LiteralError),
    /// A block instance given an address or a value (name, type).
    BlockWithValue(String, String),
    /// No type or block of that name (name, type).
    UnknownType(String, String),
}

impl fmt::Display for VariableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VariableError::BadName(n) => {
                write!(
                    f,
                    "`{n}` is not a name (a letter or _, then letters, digits, _)"
                )
            }
            VariableError::Address(n, e) => write!(f, "{n}: {e}"),
            VariableError::Initial(n, e) => write!(f, "{n}: {e}"),
            VariableError::BlockWithValue(n, t) => {
                write!(f, "{n} is a {t}: it has no address or value")
            }
            VariableError::UnknownType(n, t) => write!(f, "{n}: unknown type `{t}`"),
        }
    }
}

impl std::error::Error for VariableError {}
