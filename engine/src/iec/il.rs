//! The soft PLC's Instruction List (IEC 61131-3 IL), read line by line
//! after its `VAR … END_VAR` header into [`Line`]s: a label, an operator
//! with its modifiers and an operand. This is its syntax only: names are
//! resolved and types checked when a program is loaded.
//!
//! ```text
//! start:  LD    %IX0.0        (* a comment *)
//!         ANDN  stop
//!         ST    lamp
//!         LD    count
//!         ADD   INT#1
//!         ST    count
//!         GT    100
//!         JMPC  done
//!         CAL   delay(IN := lamp, PT := T#500ms, Q => late)
//!         AND(  a
//!         OR    b
//!         )
//! done:   RET
//! ```

use std::fmt;

use crate::error::Located;
use crate::iec::address::{Address, AddressError};
use crate::iec::data::{Data, DataType};
use crate::iec::is_identifier;
use crate::iec::literal::{parse_literal, untyped_integer, LiteralError};

/// An IL operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operator {
    Ld,
    St,
    S,
    R,
    And,
    Or,
    Xor,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Gt,
    Ge,
    Eq,
    Ne,
    Le,
    Lt,
    Jmp,
    Cal,
    Ret,
    /// `)`: ends a deferred operation.
    Close,
    /// A standard function, the current result its first input.
    Function(Function),
}

/// The standard functions IL calls by name, the current result their
/// first input and the line's operands (comma-separated) the others:
/// `LD x` / `SHL 2`, `LD mn` / `LIMIT in, mx`, `LD g` / `SEL a, b`,
/// `LD i` / `INT_TO_DINT`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Function {
    Neg,
    Move,
    Shl,
    Shr,
    Rol,
    Ror,
    Min,
    Max,
    Limit,
    Sel,
    /// ABS of an integer or a REAL.
    Abs,
    /// SQRT of a REAL.
    Sqrt,
    /// TRUNC: a REAL toward zero, as a DINT.
    Trunc,
    /// EXPT: a REAL to the power of its operand (a REAL or an integer).
    Expt,
    /// MUX: the current result (K) picks one of the operands.
    Mux,
    /// `FROM_TO_TO`.
    Convert {
        from: DataType,
        to: DataType,
    },
}

impl Function {
    /// The function a name calls (any case).
    pub fn named(name: &str) -> Option<Function> {
        let upper = name.to_ascii_uppercase();
        Some(match upper.as_str() {
            "NEG" => Function::Neg,
            "MOVE" => Function::Move,
            "SHL" => Function::Shl,
            "SHR" => Function::Shr,
            "ROL" => Function::Rol,
            "ROR" => Function::Ror,
            "MIN" => Function::Min,
            "MAX" => Function::Max,
            "LIMIT" => Function::Limit,
            "SEL" => Function::Sel,
            "ABS" => Function::Abs,
            "SQRT" => Function::Sqrt,
            "TRUNC" => Function::Trunc,
            "EXPT" => Function::Expt,
            "MUX" => Function::Mux,
            _ => {
                let (from, to) = upper.split_once("_TO_")?;
                Function::Convert {
                    from: DataType::from_name(from)?,
                    to: DataType::from_name(to)?,
                }
            }
        })
    }

    /// How many operands the line gives it (MUX: at least this many).
    pub const fn operands(self) -> usize {
        match self {
            Function::Neg | Function::Move | Function::Convert { .. } => 0,
            Function::Abs | Function::Sqrt | Function::Trunc => 0,
            Function::Shl | Function::Shr | Function::Rol | Function::Ror => 1,
            Function::Min | Function::Max | Function::Expt | Function::Mux => 1,
            Function::Limit | Function::Sel => 2,
        }
    }

    /// Whether a line may give it `n` operands.
    pub const fn takes(self, n: usize) -> bool {
        match self {
            Function::Mux => n >= 1,
            _ => n == self.operands(),
        }
    }
}

impl Operator {
    /// Each operator's mnemonic (without modifiers).
    pub const ALL: [(&'static str, Operator); 22] = [
        ("LD", Operator::Ld),
        ("ST", Operator::St),
        ("S", Operator::S),
        ("R", Operator::R),
        ("AND", Operator::And),
        ("OR", Operator::Or),
        ("XOR", Operator::Xor),
        ("NOT", Operator::Not),
        ("ADD", Operator::Add),
        ("SUB", Operator::Sub),
        ("MUL", Operator::Mul),
        ("DIV", Operator::Div),
        ("MOD", Operator::Mod),
        ("GT", Operator::Gt),
        ("GE", Operator::Ge),
        ("EQ", Operator::Eq),
        ("NE", Operator::Ne),
        ("LE", Operator::Le),
        ("LT", Operator::Lt),
        ("JMP", Operator::Jmp),
        ("CAL", Operator::Cal),
        ("RET", Operator::Ret),
    ];

    /// Whether `N` (negate the operand) may follow it.
    const fn negates(self) -> bool {
        matches!(
            self,
            Operator::Ld | Operator::St | Operator::And | Operator::Or | Operator::Xor
        )
    }

    /// Whether `C` / `CN` (only if the current result is TRUE / FALSE) may
    /// follow it.
    const fn conditional(self) -> bool {
        matches!(self, Operator::Jmp | Operator::Cal | Operator::Ret)
    }

    /// Whether `(` may follow it (the operation waits for `)`).
    const fn defers(self) -> bool {
        matches!(
            self,
            Operator::And
                | Operator::Or
                | Operator::Xor
                | Operator::Add
                | Operator::Sub
                | Operator::Mul
                | Operator::Div
                | Operator::Mod
                | Operator::Gt
                | Operator::Ge
                | Operator::Eq
                | Operator::Ne
                | Operator::Le
                | Operator::Lt
        )
    }
}

/// What an operator works on.
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    /// A declared name (or, for JMP, a label), or a block instance's
    /// output (`t0.Q`, `c0.CV`).
    Name(String),
    Address(Address),
    /// A typed literal (`INT#5`, `T#1s`, `TRUE`, `1.5`): its type is its own.
    Literal(Data),
    /// An untyped integer literal (`42`, `16#FF`): it takes the type its
    /// use needs (a DINT, or a LINT when it needs 64 bits, where no use
    /// gives one).
    Number(i128),
    /// A string literal's text (`'Hello $R$N'` read): only an LDmicro
    /// formatted string's `FMT` takes one.
    Text(String),
}

/// One line of IL.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// `name:` before it.
    pub label: Option<String>,
    pub operator: Operator,
    /// `N`: the operand (or the current result, for ST) negated.
    pub negated: bool,
    /// `C` (`Some(true)`) or `CN` (`Some(false)`).
    pub condition: Option<bool>,
    /// `(`: the operation waits for its `)`.
    pub deferred: bool,
    pub operand: Option<Operand>,
    /// A function's operands after the current result.
    pub args: Vec<Operand>,
    /// A CAL's `input := operand` and `output => name` parameters.
    pub inputs: Vec<(String, Operand)>,
    pub outputs: Vec<(String, String)>,
    /// The 1-based line of the text.
    pub line: usize,
}

/// Why a line is not IL.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IlError {
    UnknownOperator(String),
    /// A modifier the operator does not take (`STC`, `LD(` …).
    BadModifier(String),
    /// A label alone on its line.
    LabelAlone,
    /// An operand given to an operator (as written) that takes none.
    NoOperand(String),
    /// A jump (as written) without a label.
    NeedsLabel(String),
    /// An operator (as written) without its operand.
    NeedsOperand(String),
    /// A function (as written) with another number of operands than it
    /// takes (how many it takes after the current result).
    OperandCount(String, usize),
    BadName(String),
    Address(AddressError),
    Literal(LiteralError),
    /// A CAL's parameters are not `(name := value, name => variable)`.
    BadCall(String),
    /// `(*` with no `*)` after it.
    OpenComment,
    /// A label used twice (first on the line given).
    DuplicateLabel {
        label: String,
        first: usize,
    },
    /// A second `PROGRAM` in one text (the first on the line given).
    SecondProgram(usize),
    /// A call's input named twice.
    TwiceGiven(String),
    /// A call's parameter list with an empty place (`CAL t(IN := a, )`).
    EmptyParameter,
}

impl fmt::Display for IlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IlError::UnknownOperator(o) => write!(f, "unknown operator `{o}`"),
            IlError::BadModifier(o) => write!(f, "`{o}`: this operator takes no such modifier"),
            IlError::LabelAlone => f.write_str("a label needs an instruction on its line"),
            IlError::NoOperand(w) => write!(f, "`{w}` takes no operand"),
            IlError::NeedsLabel(w) => write!(f, "`{w}` needs a label"),
            IlError::NeedsOperand(w) => write!(f, "`{w}` needs an operand"),
            IlError::OperandCount(w, n) => {
                write!(f, "`{w}` takes {n} operand(s) after the current result")
            }
            IlError::BadName(n) => write!(f, "`{n}` is not a name"),
            IlError::Address(e) => e.fmt(f),
            IlError::Literal(e) => e.fmt(f),
            IlError::BadCall(c) => write!(
                f,
                "`{c}`: a call is CAL name(input := value, output => variable)"
            ),
            IlError::OpenComment => f.write_str("a comment `(*` is never closed with `*)`"),
            IlError::DuplicateLabel { label, first } => {
                write!(f, "label `{label}` is used twice (first on line {first})")
            }
            IlError::SecondProgram(first) => write!(
                f,
                "a second PROGRAM: one text holds one program (the first starts on line {first})"
            ),
            IlError::TwiceGiven(p) => write!(f, "the input `{p}` is given twice"),
            IlError::EmptyParameter => {
                f.write_str("an empty parameter: write each as name := value or name => variable")
            }
        }
    }
}

impl std::error::Error for IlError {}

/// Reads the IL lines of `text`: every line outside `VAR … END_VAR`
/// blocks that has code. Every error is given at its line; the lines
/// only when there is none.
pub fn parse_il(text: &str) -> Result<Vec<Line>, Vec<Located<IlError>>> {
    let mut lines: Vec<Line> = Vec::new();
    let mut errors = Vec::new();
    let mut in_vars = false;
    let mut first_program = None;
    let mut labels = labels::Labels::default();
    let text = super::comments::blank_long_comments(text);
    for (i, raw) in text.lines().enumerate() {
        let number = i + 1;
        if raw.contains("(*") && !raw[raw.rfind("(*").unwrap_or(0)..].contains("*)") {
            errors.push(Located::new(number, IlError::OpenComment));
            continue;
        }
        let code = strip_comments(raw);
        let code = code.trim();
        let upper = code.trim_end_matches(';').to_ascii_uppercase();
        if super::vars::header(&upper).is_some() {
            in_vars = true;
            continue;
        }
        if upper == "END_VAR" {
            in_vars = false;
            continue;
        }
        // The optional `PROGRAM name … END_PROGRAM` wrapper: one.
        let program = upper
            .strip_prefix("PROGRAM")
            .is_some_and(|rest| rest.starts_with(char::is_whitespace));
        if program && !in_vars {
            match first_program {
                Some(first) => errors.push(Located::new(number, IlError::SecondProgram(first))),
                None => first_program = Some(number),
            }
            continue;
        }
        if in_vars || code.is_empty() || upper == "END_PROGRAM" {
            continue;
        }
        if let Some(done) = labels.alone(code, number, &mut lines) {
            if let Err(e) = done {
                errors.push(Located::new(number, e));
            }
            continue;
        }
        if let Err(e) = line(code, number).and_then(|l| labels.place(l, &mut lines)) {
            errors.push(Located::new(number, e));
        }
    }
    labels.finish(&mut lines);
    if errors.is_empty() {
        Ok(lines)
    } else {
        Err(errors)
    }
}

/// The line without its `(* … *)` comments.
fn strip_comments(raw: &str) -> String {
    let mut out = String::new();
    let mut rest = raw;
    while let Some(at) = rest.find("(*") {
        out.push_str(&rest[..at]);
        rest = rest[at + 2..]
            .split_once("*)")
            .map_or("", |(_, after)| after);
    }
    out.push_str(rest);
    out
}

/// One line of code (no comment), numbered `number`.
fn line(code: &str, number: usize) -> Result<Line, IlError> {
    let (label, code) = match code.split_once(':') {
        // `name:` (not `:=` of a call's parameters).
        Some((l, rest)) if !rest.starts_with('=') && is_identifier(l.trim()) => {
            (Some(l.trim().to_string()), rest.trim())
        }
        _ => (None, code),
    };
    if code.is_empty() {
        return Err(IlError::LabelAlone);
    }
    let (word, rest) = match code.find(|c: char| c.is_whitespace() || c == '(') {
        Some(at) => (&code[..at], code[at..].trim()),
        None => (code, ""),
    };
    let mut out = Line {
        label,
        operator: Operator::Ret,
        negated: false,
        condition: None,
        deferred: false,
        operand: None,
        args: Vec::new(),
        inputs: Vec::new(),
        outputs: Vec::new(),
        line: number,
    };
    if word == ")" {
        out.operator = Operator::Close;
        return if rest.is_empty() {
            Ok(out)
        } else {
            Err(IlError::NoOperand(")".into()))
        };
    }
    if let Some(function) = Function::named(word) {
        return function_line(function, word, rest, out);
    }
    let upper = word.to_ascii_uppercase();
    let (operator, modifiers) = Operator::ALL
        .iter()
        .filter(|(m, _)| upper.starts_with(m))
        .max_by_key(|(m, _)| m.len())
        .map(|&(m, op)| (op, &upper[m.len()..]))
        .ok_or_else(|| IlError::UnknownOperator(word.to_string()))?;
    out.operator = operator;
    match modifiers {
        "" | "N" | "C" | "CN" => {}
        _ => return Err(IlError::UnknownOperator(word.to_string())),
    }
    match modifiers {
        "" => {}
        "N" if operator.negates() => out.negated = true,
        "C" if operator.conditional() => out.condition = Some(true),
        "CN" if operator.conditional() => out.condition = Some(false),
        _ => return Err(IlError::BadModifier(word.to_string())),
    }
    let rest = match rest.strip_prefix('(') {
        Some(after) if operator.defers() => {
            out.deferred = true;
            after.trim()
        }
        Some(_) if operator == Operator::Cal => rest,
        Some(_) => return Err(IlError::BadModifier(format!("{word}("))),
        None => rest,
    };
    operands(word, rest, &mut out)?;
    Ok(out)
}

/// A function's line: its comma-separated operands, as many as it takes.
fn function_line(
    function: Function,
    word: &str,
    rest: &str,
    mut out: Line,
) -> Result<Line, IlError> {
    out.operator = Operator::Function(function);
    out.args = if rest.is_empty() {
        Vec::new()
    } else {
        rest.split(',')
            .map(|a| operand(a.trim()))
            .collect::<Result<_, _>>()?
    };
    if function.takes(out.args.len()) {
        Ok(out)
    } else {
        Err(IlError::OperandCount(word.into(), function.operands()))
    }
}

/// The operand (or a CAL's parameters) of `out`'s operator, from `rest`
/// (what follows `word` on the line).
fn operands(word: &str, rest: &str, out: &mut Line) -> Result<(), IlError> {
    match out.operator {
        Operator::Not | Operator::Ret => {
            if !rest.is_empty() {
                return Err(IlError::NoOperand(word.into()));
            }
        }
        Operator::Cal => call(rest, out)?,
        Operator::Jmp => {
            if !is_identifier(rest) {
                return Err(IlError::NeedsLabel(word.into()));
            }
            out.operand = Some(Operand::Name(rest.to_string()));
        }
        _ if rest.is_empty() && out.deferred => {}
        _ if rest.is_empty() => {
            return Err(IlError::NeedsOperand(word.into()));
        }
        _ => out.operand = Some(operand(rest)?),
    }
    Ok(())
}

/// A name, an address or a literal.
fn operand(text: &str) -> Result<Operand, IlError> {
    if text.starts_with('\'') {
        return crate::iec::literal::parse_text(text)
            .map(Operand::Text)
            .map_err(IlError::Literal);
    }
    if text.starts_with('%') {
        return Address::parse(text)
            .map(Operand::Address)
            .map_err(IlError::Address);
    }
    let literal_like = text.contains('#')
        || text.starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == '+')
        || text.eq_ignore_ascii_case("TRUE")
        || text.eq_ignore_ascii_case("FALSE");
    if literal_like {
        // Below LINT's least no type holds it: refused as a LINT.
        if let Some(v) = untyped_integer(text).filter(|&v| v >= i128::from(i64::MIN)) {
            return Ok(Operand::Number(v));
        }
        return parse_literal(text, None)
            .map(Operand::Literal)
            .map_err(IlError::Literal);
    }
    let output = text
        .split_once('.')
        .is_some_and(|(instance, pin)| is_identifier(instance) && is_identifier(pin));
    if is_identifier(text) || output || is_element(text) {
        Ok(Operand::Name(text.to_string()))
    } else {
        Err(IlError::BadName(text.to_string()))
    }
}

/// Whether `text` is the soft PLC's element operand, Structured Text's
/// array element at a run-time index (`st_v1[i:1:3:2,j:0:2:1]`: the
/// first element, then each index variable with its low bound, length
/// and stride, as [`crate::softplc`] documents).
pub fn is_element(text: &str) -> bool {
    let Some((name, rest)) = text.split_once('[') else {
        return false;
    };
    let Some(dims) = rest.strip_suffix(']') else {
        return false;
    };
    is_identifier(name)
        && dims.split(',').all(|d| {
            let parts: Vec<&str> = d.split(':').collect();
            matches!(parts.as_slice(), [index, low, len, stride]
                if is_identifier(index)
                    && low.parse::<i64>().is_ok()
                    && len.parse::<u32>().is_ok()
                    && stride.parse::<u32>().is_ok())
        })
}

/// An Instruction List program as it was written: its declarations and
/// lines. The ladder reads a program back through this, whoever loaded
/// and checked it (the soft PLC's loader), so it needs no machine.
pub trait IlSource {
    /// The declarations and the IL lines, in order.
    fn source(&self) -> (&[crate::iec::vars::Variable], &[Line]);
}

mod call;
mod labels;
use call::call;
pub(crate) use call::split_params;

#[cfg(test)]
mod tests;
