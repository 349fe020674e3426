//! The AVR assembler subset the simplified PLC is written in: `.equ`,
//! `.db`, `.cseg`/`.csg`/`.dseg`, labels with `.byte`, `LOW()`/`HIGH()`,
//! arithmetic, `$` hex, `;` comments (machines.md §3).

use std::collections::HashMap;
use std::fmt;

use crate::error::Located;

/// Where `.dseg` starts: SRAM of the ATmega328P and its kin.
pub const DSEG_START: i64 = 0x0100;

/// The instruction codes and bit patterns every program may use without
/// defining them (the seed keeps them in `PLC_Bit_Def.asm`).
pub const PREDEFINED: [(&str, i64); 25] = [
    ("Load_A", 1),
    ("Load_B", 2),
    ("And_A", 3),
    ("And_B", 4),
    ("Or_A", 5),
    ("Or_B", 6),
    ("Coil_A", 7),
    ("Coil_B", 8),
    ("Set_Coil", 9),
    ("Reset_Coil", 10),
    ("TON", 11),
    ("TOF", 12),
    ("TP", 13),
    ("Not", 14),
    ("Pulse_A", 15),
    ("Pulse_B", 16),
    ("End_PLC", 0xFF),
    ("Bit0", 0x01),
    ("Bit1", 0x02),
    ("Bit2", 0x04),
    ("Bit3", 0x08),
    ("Bit4", 0x10),
    ("Bit5", 0x20),
    ("Bit6", 0x40),
    ("Bit7", 0x80),
];

/// The assembled source: code bytes with their lines, and the symbols.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Assembly {
    /// The `.cseg` bytes, each with the 1-based line of its `.db`.
    pub code: Vec<(u8, usize)>,
    /// `.equ` names (as written) and their values, in order.
    pub equs: Vec<(String, i64)>,
    /// Labels (as written) and their addresses.
    pub labels: Vec<(String, i64)>,
}

impl Assembly {
    /// A symbol's value, ignoring letter case as the AVR assembler does.
    pub fn symbol(&self, name: &str) -> Option<i64> {
        self.labels
            .iter()
            .chain(&self.equs)
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, v)| v)
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Segment {
    Code,
    Data,
}

/// Assembles `text`. `scan_ms` is the value of the predefined symbol
/// `Scan` (so `1000/Scan` is one second of scans).
pub fn assemble(text: &str, scan_ms: i64) -> Result<Assembly, Vec<Located<AsmError>>> {
    crate::limits::check_program_lines(text)
        .map_err(|(line, n)| vec![Located::new(line, AsmError::TooManyLines(n))])?;
    let mut a = Assembler::new(scan_ms);
    for (index, raw) in text.lines().enumerate() {
        a.line(index + 1, raw);
    }
    a.finish()
}

/// The assembler's state between lines.
struct Assembler {
    symbols: HashMap<String, i64>,
    /// Names this source defines, with their line.
    defined_here: HashMap<String, usize>,
    out: Assembly,
    errors: Vec<Located<AsmError>>,
    segment: Segment,
    /// The next free `.dseg` address.
    dseg: i64,
    /// `.db` lines are evaluated at the end, so they may use later labels.
    pending_db: Vec<(usize, String)>,
}

impl Assembler {
    fn new(scan_ms: i64) -> Assembler {
        let mut symbols: HashMap<String, i64> = PREDEFINED
            .iter()
            .map(|&(n, v)| (n.to_ascii_uppercase(), v))
            .collect();
        symbols.insert("SCAN".to_string(), scan_ms);
        Assembler {
            symbols,
            defined_here: HashMap::new(),
            out: Assembly::default(),
            errors: Vec::new(),
            segment: Segment::Code,
            dseg: DSEG_START,
            pending_db: Vec::new(),
        }
    }

    /// One source line: an optional label, then a directive.
    fn line(&mut self, line: usize, raw: &str) {
        let code = self.label(line, raw.split(';').next().unwrap_or("").trim());
        if code.is_empty() {
            return;
        }
        let (directive, args) = match code.split_once(char::is_whitespace) {
            Some((d, a)) => (d, a.trim()),
            None => (code, ""),
        };
        if let Err(e) = self.directive(line, directive, args) {
            self.errors.push(Located::new(line, e));
        }
    }

    /// Defines a label `Name:` at the start of `code`; the rest of it.
    fn label<'c>(&mut self, line: usize, code: &'c str) -> &'c str {
        let Some((name, rest)) = code.split_once(':') else {
            return code;
        };
        let name = name.trim();
        if !is_identifier(name) || name.starts_with('.') {
            return code;
        }
        let key = name.to_ascii_uppercase();
        if let Some(first) = self.defined_here.insert(key.clone(), line) {
            self.errors.push(Located::new(
                line,
                AsmError::Redefined(name.to_string(), first),
            ));
        } else {
            let address = if self.segment == Segment::Data {
                self.dseg
            } else {
                0
            };
            self.symbols.insert(key, address);
            self.out.labels.push((name.to_string(), address));
        }
        rest.trim()
    }

    fn directive(&mut self, line: usize, directive: &str, args: &str) -> Result<(), AsmError> {
        match directive.to_ascii_lowercase().as_str() {
            ".cseg" | ".csg" => self.segment = Segment::Code,
            ".dseg" => self.segment = Segment::Data,
            // The seed splits its source over files; their definitions are
            // predefined here, so an include has nothing left to bring.
            ".include" | ".list" | ".nolist" | ".device" => {}
            ".equ" | ".set" => define(
                args,
                &mut self.symbols,
                &mut self.defined_here,
                line,
                &mut self.out.equs,
            )?,
            ".byte" => {
                if self.segment != Segment::Data {
                    return Err(AsmError::ByteOutsideDseg);
                }
                let n = eval(args, &self.symbols)?;
                if n < 0 {
                    return Err(AsmError::Range(crate::error::shown(args), n));
                }
                self.dseg += n;
            }
            ".db" => {
                if self.segment == Segment::Data {
                    return Err(AsmError::DbInDseg);
                }
                self.pending_db.push((line, args.to_string()));
            }
            other => return Err(AsmError::UnknownDirective(crate::error::shown(other))),
        }
        Ok(())
    }

    /// Evaluates the `.db` lines, now that every label is known.
    fn finish(mut self) -> Result<Assembly, Vec<Located<AsmError>>> {
        for (line, args) in std::mem::take(&mut self.pending_db) {
            for item in split_args(&args) {
                match eval(item, &self.symbols) {
                    Ok(v) if (-128..=255).contains(&v) => {
                        self.out.code.push(((v & 0xFF) as u8, line))
                    }
                    Ok(v) => self.errors.push(Located::new(
                        line,
                        AsmError::Range(crate::error::shown(item), v),
                    )),
                    Err(e) => self.errors.push(Located::new(line, e)),
                }
            }
        }
        if self.errors.is_empty() {
            Ok(self.out)
        } else {
            crate::sort::by_key(&mut self.errors, |e| e.line);
            Err(self.errors)
        }
    }
}

fn define(
    args: &str,
    symbols: &mut HashMap<String, i64>,
    defined_here: &mut HashMap<String, usize>,
    line: usize,
    equs: &mut Vec<(String, i64)>,
) -> Result<(), AsmError> {
    let (name, expr) = args.split_once('=').ok_or(AsmError::EquSyntax)?;
    let name = name.trim();
    if !is_identifier(name) {
        return Err(AsmError::EquSyntax);
    }
    let value = eval(expr, symbols)?;
    let key = name.to_ascii_uppercase();
    if let Some(&first) = defined_here.get(&key) {
        return Err(AsmError::Redefined(name.to_string(), first));
    }
    defined_here.insert(key.clone(), line);
    symbols.insert(key, value);
    equs.push((name.to_string(), value));
    Ok(())
}

fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Splits `.db` arguments at top-level commas.
fn split_args(args: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in args.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(args[start..i].trim());
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(args[start..].trim());
    parts.into_iter().filter(|p| !p.is_empty()).collect()
}

/// Evaluates an expression: integers (`12`, `$1F`, `0x1F`, `0b101`),
/// symbols, `+ - * /`, unary minus, parentheses, `LOW()` and `HIGH()`.
pub fn eval(expr: &str, symbols: &HashMap<String, i64>) -> Result<i64, AsmError> {
    let tokens = tokenize(expr)?;
    let mut p = ExprParser {
        tokens: &tokens,
        pos: 0,
        symbols,
        text: expr,
        depth: 0,
    };
    let v = p.sum()?;
    if p.pos != tokens.len() {
        return Err(AsmError::Expression(crate::error::shown(expr.trim())));
    }
    Ok(v)
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Num(i64),
    Name(String),
    Op(char),
}

fn tokenize(expr: &str) -> Result<Vec<Token>, AsmError> {
    let bad = || AsmError::Expression(crate::error::shown(expr.trim()));
    let bytes = expr.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i] as char;
        if c.is_ascii_whitespace() {
            i += 1;
        } else if "+-*/()".contains(c) {
            tokens.push(Token::Op(c));
            i += 1;
        } else if c == '$' || c.is_ascii_digit() {
            let start = i;
            i += 1;
            while i < bytes.len() && (bytes[i] as char).is_ascii_alphanumeric() {
                i += 1;
            }
            let lit = &expr[start..i];
            let lower = lit.to_ascii_lowercase();
            let parsed =
                if let Some(h) = lower.strip_prefix('$').or_else(|| lower.strip_prefix("0x")) {
                    i64::from_str_radix(h, 16)
                } else if let Some(b) = lower.strip_prefix("0b") {
                    i64::from_str_radix(b, 2)
                } else {
                    lower.parse::<i64>()
                };
            tokens.push(Token::Num(parsed.map_err(|_| bad())?));
        } else if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < bytes.len()
                && ((bytes[i] as char).is_ascii_alphanumeric() || bytes[i] == b'_')
            {
                i += 1;
            }
            tokens.push(Token::Name(expr[start..i].to_string()));
        } else {
            return Err(bad());
        }
    }
    Ok(tokens)
}

struct ExprParser<'a> {
    tokens: &'a [Token],
    pos: usize,
    symbols: &'a HashMap<String, i64>,
    text: &'a str,
    /// Parentheses, `LOW(`/`HIGH(` and unary minus open now.
    depth: usize,
}

impl ExprParser<'_> {
    fn bad(&self) -> AsmError {
        AsmError::Expression(crate::error::shown(self.text.trim()))
    }

    fn overflow(&self) -> AsmError {
        AsmError::Overflow(crate::error::shown(self.text.trim()))
    }

    /// Enters one nesting level; the parser recurses once per level, so
    /// the depth is capped before the stack is at risk.
    fn deeper(&mut self) -> Result<(), AsmError> {
        self.depth += 1;
        if self.depth > crate::limits::MAX_EXPRESSION_DEPTH {
            return Err(AsmError::TooDeep(crate::error::shown(self.text.trim())));
        }
        Ok(())
    }

    fn next_op(&self, ops: &str) -> Option<char> {
        match self.tokens.get(self.pos) {
            Some(Token::Op(c)) if ops.contains(*c) => Some(*c),
            _ => None,
        }
    }

    fn sum(&mut self) -> Result<i64, AsmError> {
        let mut v = self.product()?;
        while let Some(op) = self.next_op("+-") {
            self.pos += 1;
            let rhs = self.product()?;
            v = if op == '+' {
                v.checked_add(rhs)
            } else {
                v.checked_sub(rhs)
            }
            .ok_or_else(|| self.overflow())?;
        }
        Ok(v)
    }

    fn product(&mut self) -> Result<i64, AsmError> {
        let mut v = self.unary()?;
        while let Some(op) = self.next_op("*/") {
            self.pos += 1;
            let rhs = self.unary()?;
            v = if op == '*' {
                v.checked_mul(rhs).ok_or_else(|| self.overflow())?
            } else if rhs == 0 {
                return Err(AsmError::DivisionByZero(crate::error::shown(
                    self.text.trim(),
                )));
            } else {
                // i64::MIN / -1 is the one quotient that does not fit.
                v.checked_div(rhs).ok_or_else(|| self.overflow())?
            };
        }
        Ok(v)
    }

    fn unary(&mut self) -> Result<i64, AsmError> {
        if self.next_op("-").is_some() {
            self.pos += 1;
            self.deeper()?;
            let v = self.unary()?;
            self.depth -= 1;
            return v.checked_neg().ok_or_else(|| self.overflow());
        }
        self.atom()
    }

    fn atom(&mut self) -> Result<i64, AsmError> {
        let token = self
            .tokens
            .get(self.pos)
            .cloned()
            .ok_or_else(|| self.bad())?;
        self.pos += 1;
        match token {
            Token::Num(n) => Ok(n),
            Token::Op('(') => {
                self.deeper()?;
                let v = self.sum()?;
                if self.next_op(")").is_none() {
                    return Err(self.bad());
                }
                self.pos += 1;
                self.depth -= 1;
                Ok(v)
            }
            Token::Name(name) => {
                let upper = name.to_ascii_uppercase();
                if (upper == "LOW" || upper == "HIGH") && self.next_op("(").is_some() {
                    self.deeper()?;
                    let v = self.atom()?;
                    self.depth -= 1;
                    return Ok(if upper == "LOW" {
                        v & 0xFF
                    } else {
                        (v >> 8) & 0xFF
                    });
                }
                self.symbols
                    .get(&upper)
                    .copied()
                    .ok_or(AsmError::UnknownSymbol(crate::error::shown(&name)))
            }
            Token::Op(_) => Err(self.bad()),
        }
    }
}

/// A problem with one line of AVR PLC source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AsmError {
    /// More lines than [`crate::limits::MAX_PROGRAM_LINES`] (how many).
    TooManyLines(usize),
    /// Not a directive this subset knows.
    UnknownDirective(String),
    /// `.equ` without `NAME=expr`.
    EquSyntax,
    /// A name defined twice (the line of the first).
    Redefined(String, usize),
    /// A name that is not defined.
    UnknownSymbol(String),
    /// A malformed expression.
    Expression(String),
    /// Division by zero.
    DivisionByZero(String),
    /// A result outside -2^63..2^63.
    Overflow(String),
    /// Nested past [`crate::limits::MAX_EXPRESSION_DEPTH`].
    TooDeep(String),
    /// A value out of range for its place (the value).
    Range(String, i64),
    /// `.byte` outside `.dseg`.
    ByteOutsideDseg,
    /// `.db` in `.dseg`.
    DbInDseg,
}

impl fmt::Display for AsmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AsmError::TooManyLines(n) => write!(
                f,
                "the program has {n} lines, more than the {} a program may have (docs/limits.md)",
                crate::limits::MAX_PROGRAM_LINES
            ),
            AsmError::UnknownDirective(d) => write!(
                f,
                "unknown directive {d}: this assembler takes .equ .db .cseg .csg .dseg .byte and labels"
            ),
            AsmError::EquSyntax => f.write_str(".equ needs NAME=expression"),
            AsmError::Redefined(n, first) => write!(
                f,
                "{} is already defined on line {first}",
                crate::error::shown(n)
            ),
            AsmError::UnknownSymbol(n) => write!(f, "unknown symbol {n}"),
            AsmError::Expression(e) => write!(f, "bad expression {e}"),
            AsmError::DivisionByZero(e) => write!(f, "division by zero in {e}"),
            AsmError::Overflow(e) => write!(f, "{e} overflows: values are 64-bit integers"),
            AsmError::TooDeep(e) => write!(
                f,
                "{e} nests more than {} levels of parentheses, LOW/HIGH or minus signs (docs/limits.md)",
                crate::limits::MAX_EXPRESSION_DEPTH
            ),
            AsmError::Range(e, v) => write!(f, "{e} is {v}: a byte is -128..255"),
            AsmError::ByteOutsideDseg => f.write_str(".byte reserves RAM: use it after .dseg"),
            AsmError::DbInDseg => f.write_str(".db puts bytes in program memory: use it after .cseg"),
        }
    }
}

impl std::error::Error for AsmError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn expressions() {
        let mut s = HashMap::new();
        s.insert("SCAN".to_string(), 10);
        s.insert("T".to_string(), 0x1234);
        assert_eq!(eval("1000/Scan", &s), Ok(100));
        assert_eq!(eval("LOW(1000/Scan)", &s), Ok(100));
        assert_eq!(eval("HIGH(t)", &s), Ok(0x12));
        assert_eq!(eval("low(T)+$10*2", &s), Ok(0x34 + 32));
        assert_eq!(eval("-(2+3)*4", &s), Ok(-20));
        assert!(matches!(eval("1/0", &s), Err(AsmError::DivisionByZero(_))));
        assert!(matches!(eval("FOO+1", &s), Err(AsmError::UnknownSymbol(_))));
        assert!(matches!(eval("1 +", &s), Err(AsmError::Expression(_))));
    }

    #[test]
    fn labels_segments_and_records() {
        let src = ".equ A_R=4\n.equ A_B=Bit2\n.dseg\nPLC_Timer_Top:\nT1: .byte 2\nT2: .byte 2\n.cseg\n.db Load_A,A_R,A_B,0\n.db TON,LOW(T2),LOW(1000/Scan),HIGH(1000/Scan)\n.db End_PLC,0,0,0\n";
        let a = assemble(src, 10).unwrap();
        assert_eq!(a.symbol("t2"), Some(DSEG_START + 2));
        let bytes: Vec<u8> = a.code.iter().map(|b| b.0).collect();
        assert_eq!(bytes, [1, 4, 4, 0, 11, 2, 100, 0, 0xFF, 0, 0, 0]);
    }

    #[test]
    fn errors_are_located() {
        let errors = assemble(
            ".equ X=1\n.equ X=2\n.db Load_A,Nope,1,0\n.frob\n.byte 2\n.dseg\n.db 1\n",
            10,
        )
        .unwrap_err();
        let lines: Vec<usize> = errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, [2, 3, 4, 5, 7]);
        assert_eq!(errors[0].error, AsmError::Redefined("X".to_string(), 1));
    }
}
