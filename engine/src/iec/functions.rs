//! The standard functions (ADD, SEL, MUX, …) a drawn body or a ladder's
//! box calls, as IL: the first data input loaded, the others applied in
//! turn (`LD IN1`, `ADD IN2`, `ADD IN3`), the result left for the caller
//! to store. Their type is their
//! first typed input's (an untyped literal takes it), or, when every
//! input is an untyped literal, the type the output feeds.

use crate::iec::data::DataType;

/// An operand and its type (`None`: an untyped literal).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Operand {
    pub text: String,
    pub ty: Option<DataType>,
    pub literal: bool,
}

impl Operand {
    /// A variable of type `ty`.
    pub fn temp(text: String, ty: DataType) -> Operand {
        Operand {
            text,
            ty: Some(ty),
            literal: false,
        }
    }

    /// Whether it is the literal TRUE (the left rail's power).
    pub fn is_true(&self) -> bool {
        self.literal && self.text.eq_ignore_ascii_case("TRUE")
    }

    /// An untyped number written at type `t` (0 and 1 are IEC's BOOL
    /// literals too).
    pub fn at(mut self, t: Option<DataType>) -> Operand {
        if let (true, None, Some(t)) = (self.literal, self.ty, t) {
            if t == DataType::Bool && matches!(self.text.as_str(), "0" | "1") {
                self.text = if self.text == "1" { "TRUE" } else { "FALSE" }.into();
                self.ty = Some(t);
            } else if t != DataType::Bool && t != DataType::Time {
                self.text = format!("{}#{}", t.name(), self.text);
                self.ty = Some(t);
            }
        }
        self
    }
}

/// A standard function the soft PLC's IL has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Function {
    /// ADD, SUB, MUL, DIV, MOD, AND, OR, XOR, MAX, MIN: the IL operator
    /// applied to each input after the first (`n` ≥ 2; SUB, DIV, MOD 2).
    Fold(&'static str, bool),
    /// GT … LT of two inputs.
    Compare(&'static str),
    /// NOT, NEG, MOVE, `*_TO_*`: one input, an IL operator (none: MOVE).
    Unary(&'static str),
    /// A conversion `FROM_TO_TO`.
    Convert(DataType, DataType),
    /// SEL (G, IN0, IN1).
    Sel,
    /// LIMIT (MN, IN, MX).
    Limit,
    /// SHL, SHR, ROL, ROR (IN, N).
    Shift(&'static str),
}

impl Function {
    /// The function a block's type names (any case).
    pub fn named(upper: &str) -> Option<Function> {
        Some(match upper {
            "ADD" => Function::Fold("ADD", true),
            "MUL" => Function::Fold("MUL", true),
            "SUB" => Function::Fold("SUB", false),
            "DIV" => Function::Fold("DIV", false),
            "MOD" => Function::Fold("MOD", false),
            "AND" => Function::Fold("AND", true),
            "OR" => Function::Fold("OR", true),
            "XOR" => Function::Fold("XOR", true),
            "MAX" => Function::Fold("MAX", true),
            "MIN" => Function::Fold("MIN", true),
            "GT" => Function::Compare("GT"),
            "GE" => Function::Compare("GE"),
            "EQ" => Function::Compare("EQ"),
            "NE" => Function::Compare("NE"),
            "LE" => Function::Compare("LE"),
            "LT" => Function::Compare("LT"),
            "NOT" => Function::Unary("NOT"),
            "NEG" => Function::Unary("NEG"),
            "MOVE" => Function::Unary(""),
            "SEL" => Function::Sel,
            "LIMIT" => Function::Limit,
            "SHL" => Function::Shift("SHL"),
            "SHR" => Function::Shift("SHR"),
            "ROL" => Function::Shift("ROL"),
            "ROR" => Function::Shift("ROR"),
            _ => {
                let (from, to) = upper.split_once("_TO_")?;
                Function::Convert(DataType::from_name(from)?, DataType::from_name(to)?)
            }
        })
    }

    /// The IL computing it from `args` (pin, value) in the order the file
    /// gives them, and the result's type; `wanted` is what the output
    /// feeds.
    pub fn code(
        self,
        args: &[(String, Operand)],
        wanted: Option<DataType>,
    ) -> Result<(Vec<String>, DataType), FunctionError> {
        // The inputs that share the function's type.
        let data: Vec<&Operand> = match self {
            Function::Sel => args.iter().skip(1).map(|(_, o)| o).collect(),
            Function::Shift(_) => args.iter().take(1).map(|(_, o)| o).collect(),
            _ => args.iter().map(|(_, o)| o).collect(),
        };
        let ty = data
            .iter()
            .find_map(|o| o.ty)
            .or(match self {
                Function::Compare(_) => None,
                _ => wanted,
            })
            .unwrap_or(DataType::Dint);
        let mut code = Vec::new();
        let result = self.lines(args, ty, &mut code)?;
        Ok((code, result))
    }

    /// Appends the IL to `code` with its inputs at type `ty`; the result's
    /// type.
    fn lines(
        self,
        args: &[(String, Operand)],
        ty: DataType,
        code: &mut Vec<String>,
    ) -> Result<DataType, FunctionError> {
        let at = |o: &Operand| o.clone().at(Some(ty)).text;
        let pin = |name: &'static str| {
            args.iter()
                .find(|(p, _)| p.eq_ignore_ascii_case(name))
                .map(|(_, o)| o.clone())
                .ok_or(FunctionError::Missing(name))
        };
        let count = |least: usize, most: usize| {
            if (least..=most).contains(&args.len()) {
                Ok(())
            } else {
                Err(FunctionError::Inputs(args.len()))
            }
        };
        Ok(match self {
            Function::Fold(op, many) => {
                count(2, if many { usize::MAX } else { 2 })?;
                code.push(format!("LD {}", at(&args[0].1)));
                code.extend(args[1..].iter().map(|(_, o)| format!("{op} {}", at(o))));
                ty
            }
            // IEC's comparisons of more than two inputs hold for each
            // neighbouring pair: (IN1 > IN2) AND (IN2 > IN3) ….
            Function::Compare(op) => {
                count(2, usize::MAX)?;
                code.push(format!("LD {}", at(&args[0].1)));
                code.push(format!("{op} {}", at(&args[1].1)));
                for pair in args[1..].windows(2) {
                    code.push(format!("AND( {}", at(&pair[0].1)));
                    code.push(format!("{op} {}", at(&pair[1].1)));
                    code.push(")".into());
                }
                DataType::Bool
            }
            Function::Unary(op) => {
                count(1, 1)?;
                code.push(format!("LD {}", at(&args[0].1)));
                code.extend((!op.is_empty()).then(|| op.to_string()));
                ty
            }
            Function::Convert(from, to) => {
                count(1, 1)?;
                code.push(format!("LD {}", args[0].1.clone().at(Some(from)).text));
                code.push(format!("{}_TO_{}", from.name(), to.name()));
                to
            }
            Function::Sel => {
                count(3, 3)?;
                code.push(format!("LD {}", pin("G")?.text));
                code.push(format!("SEL {}, {}", at(&pin("IN0")?), at(&pin("IN1")?)));
                ty
            }
            Function::Limit => {
                count(3, 3)?;
                code.push(format!("LD {}", at(&pin("MN")?)));
                code.push(format!("LIMIT {}, {}", at(&pin("IN")?), at(&pin("MX")?)));
                ty
            }
            Function::Shift(op) => {
                count(2, 2)?;
                code.push(format!("LD {}", at(&pin("IN")?)));
                code.push(format!("{op} {}", pin("N")?.text));
                ty
            }
        })
    }
}

/// Why a function call cannot be written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FunctionError {
    /// It does not take that many inputs.
    Inputs(usize),
    /// An input it needs is not connected.
    Missing(&'static str),
}

impl std::fmt::Display for FunctionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FunctionError::Inputs(n) => write!(f, "it does not take {n} inputs"),
            FunctionError::Missing(pin) => write!(f, "no {pin} connected"),
        }
    }
}

impl std::error::Error for FunctionError {}
