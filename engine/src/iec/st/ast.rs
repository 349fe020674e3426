//! The syntax tree of a Structured Text source: what the parser builds
//! and the printer writes back. Every statement and expression carries
//! the [`Span`] (line, column) it starts at, so that later layers name
//! the place of what they refuse.

/// Where something starts in the source: 1-based line and column (the
/// column counts characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Span {
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub column: u32,
}

/// A name as written (its case kept; names compare without case later).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ident {
    /// The name's text.
    pub name: String,
    /// Where it is written.
    pub span: Span,
}

/// A whole source: its POUs, type and global declarations in file order.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Source {
    /// The items in the order they are written.
    pub items: Vec<Item>,
}

/// One top-level item of a source.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A `PROGRAM`, `FUNCTION` or `FUNCTION_BLOCK`.
    Pou(Pou),
    /// A `TYPE … END_TYPE` block.
    Types(Vec<TypeDecl>),
    /// A `VAR_GLOBAL … END_VAR` block outside any POU.
    Globals(VarBlock),
}

/// Which kind of program organisation unit.
#[derive(Clone, Debug, PartialEq)]
pub enum PouKind {
    /// `PROGRAM`.
    Program,
    /// `FUNCTION name : TYPE`, with its result's type.
    Function(TypeRef),
    /// `FUNCTION_BLOCK`.
    FunctionBlock,
}

/// A program organisation unit: its declarations and its body.
#[derive(Clone, Debug, PartialEq)]
pub struct Pou {
    /// Program, function (with its type) or function block.
    pub kind: PouKind,
    /// Its name.
    pub name: Ident,
    /// Its `VAR…` blocks in order.
    pub vars: Vec<VarBlock>,
    /// Its statements.
    pub body: Vec<Stmt>,
    /// Where its keyword is.
    pub span: Span,
}

/// The section a `VAR…` block declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarKind {
    /// `VAR_INPUT`.
    Input,
    /// `VAR_OUTPUT`.
    Output,
    /// `VAR_IN_OUT`.
    InOut,
    /// `VAR`.
    Local,
    /// `VAR_TEMP`.
    Temp,
    /// `VAR_GLOBAL`.
    Global,
    /// `VAR_EXTERNAL`.
    External,
}

impl VarKind {
    /// The keyword that opens the block.
    pub const fn keyword(self) -> &'static str {
        match self {
            VarKind::Input => "VAR_INPUT",
            VarKind::Output => "VAR_OUTPUT",
            VarKind::InOut => "VAR_IN_OUT",
            VarKind::Local => "VAR",
            VarKind::Temp => "VAR_TEMP",
            VarKind::Global => "VAR_GLOBAL",
            VarKind::External => "VAR_EXTERNAL",
        }
    }
}

/// A `VAR… END_VAR` block.
#[derive(Clone, Debug, PartialEq)]
pub struct VarBlock {
    /// Which section.
    pub kind: VarKind,
    /// `CONSTANT` written after the keyword.
    pub constant: bool,
    /// `RETAIN` written after the keyword.
    pub retain: bool,
    /// Its declarations.
    pub decls: Vec<VarDecl>,
    /// Where its keyword is.
    pub span: Span,
}

/// One declaration: `a, b AT %IX0.0 : INT := 5;`.
#[derive(Clone, Debug, PartialEq)]
pub struct VarDecl {
    /// The names declared (several share the type and initial value).
    pub names: Vec<Ident>,
    /// `AT %…`: the located variable's address as written.
    pub location: Option<String>,
    /// The declared type.
    pub ty: TypeRef,
    /// The initial value, when one is given.
    pub init: Option<Init>,
    /// Where the first name is.
    pub span: Span,
}

/// The elementary types Structured Text names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Elementary {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Ulint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    Lreal,
    Time,
}

impl Elementary {
    /// Every elementary type, with the name the standard gives it.
    pub const ALL: [(Elementary, &'static str); 16] = [
        (Elementary::Bool, "BOOL"),
        (Elementary::Sint, "SINT"),
        (Elementary::Int, "INT"),
        (Elementary::Dint, "DINT"),
        (Elementary::Lint, "LINT"),
        (Elementary::Usint, "USINT"),
        (Elementary::Uint, "UINT"),
        (Elementary::Udint, "UDINT"),
        (Elementary::Ulint, "ULINT"),
        (Elementary::Byte, "BYTE"),
        (Elementary::Word, "WORD"),
        (Elementary::Dword, "DWORD"),
        (Elementary::Lword, "LWORD"),
        (Elementary::Real, "REAL"),
        (Elementary::Lreal, "LREAL"),
        (Elementary::Time, "TIME"),
    ];

    /// The type a name (any case) gives, if it is elementary.
    pub fn from_name(name: &str) -> Option<Elementary> {
        Self::ALL
            .iter()
            .find(|(_, n)| n.eq_ignore_ascii_case(name))
            .map(|(t, _)| *t)
    }

    /// The standard's name.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(t, _)| *t == self)
            .map_or("?", |(_, n)| n)
    }

    /// Whether the type is an integer or bit string (its literals are
    /// whole numbers).
    pub fn is_integer(self) -> bool {
        !matches!(
            self,
            Elementary::Bool | Elementary::Real | Elementary::Lreal | Elementary::Time
        )
    }
}

/// A type as a declaration names it.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeRef {
    /// An elementary type.
    Elementary(Elementary),
    /// `STRING`, with its length when one is written (`STRING[20]`).
    String(Option<u32>),
    /// A type declared by name (a `TYPE`, a block's type, a standard
    /// block such as `TON`).
    Named(Ident),
    /// `ARRAY [l..h, …] OF T`.
    Array {
        /// Each dimension's lower and upper bound.
        dims: Vec<(i128, i128)>,
        /// The element type.
        of: Box<TypeRef>,
    },
}

/// An initial value.
#[derive(Clone, Debug, PartialEq)]
pub enum Init {
    /// A constant expression.
    Expr(Expr),
    /// `[a, b, n(c), …]` for an array.
    Array(Vec<ArrayInit>),
    /// `(m := v, …)` for a structure.
    Struct(Vec<(Ident, Init)>),
}

/// One element of an array's initial value.
#[derive(Clone, Debug, PartialEq)]
pub enum ArrayInit {
    /// One value.
    One(Init),
    /// `n(v)`: `v` n times; `n()` n default values.
    Repeat(u32, Option<Init>),
}

/// One `name : …;` inside `TYPE … END_TYPE`.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeDecl {
    /// The new type's name.
    pub name: Ident,
    /// What it is.
    pub def: TypeDef,
}

/// What a declared type is.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeDef {
    /// `STRUCT … END_STRUCT`: its members.
    Struct(Vec<VarDecl>),
    /// Another type (an array, an elementary type), with a default value.
    Alias(TypeRef, Option<Init>),
}

/// A statement and where it starts.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    /// What it does.
    pub kind: StmtKind,
    /// Where it starts.
    pub span: Span,
}

/// The statements of Structured Text.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// `target := value;`
    Assign {
        /// The variable written.
        target: Variable,
        /// The value.
        value: Expr,
    },
    /// `name(args);`: a function or block instance called.
    Call(Call),
    /// `IF c THEN … ELSIF c THEN … ELSE … END_IF`.
    If {
        /// Each condition with its statements, `IF` first.
        branches: Vec<(Expr, Vec<Stmt>)>,
        /// The `ELSE` part, when written.
        otherwise: Option<Vec<Stmt>>,
    },
    /// `CASE e OF … ELSE … END_CASE`.
    Case {
        /// The value chosen on.
        selector: Expr,
        /// The labelled arms in order.
        arms: Vec<CaseArm>,
        /// The `ELSE` part, when written.
        otherwise: Option<Vec<Stmt>>,
    },
    /// `FOR v := a TO b BY c DO … END_FOR`.
    For {
        /// The control variable.
        var: Ident,
        /// Its first value.
        from: Expr,
        /// Its last value.
        to: Expr,
        /// The step, when written (1 otherwise).
        by: Option<Expr>,
        /// The loop's statements.
        body: Vec<Stmt>,
    },
    /// `WHILE c DO … END_WHILE`.
    While {
        /// Checked before each pass.
        cond: Expr,
        /// The loop's statements.
        body: Vec<Stmt>,
    },
    /// `REPEAT … UNTIL c END_REPEAT`.
    Repeat {
        /// The loop's statements.
        body: Vec<Stmt>,
        /// Checked after each pass; the loop ends when true.
        until: Expr,
    },
    /// `EXIT;` (inside a loop).
    Exit,
    /// `RETURN;`
    Return,
    /// A lone `;`.
    Empty,
}

/// One arm of a `CASE`: its labels and statements.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseArm {
    /// The values and ranges that choose it.
    pub labels: Vec<CaseLabel>,
    /// Its statements.
    pub body: Vec<Stmt>,
}

/// A `CASE` label.
#[derive(Clone, Debug, PartialEq)]
pub enum CaseLabel {
    /// One value.
    Value(Expr),
    /// `low..high`, both included.
    Range(Expr, Expr),
}

/// A variable read or written: a name and what is selected in it.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// The name, or a direct address (`%IX0.0`).
    pub base: Ident,
    /// `[i, j]` and `.member` in order.
    pub path: Vec<Selector>,
}

/// A step into a variable.
#[derive(Clone, Debug, PartialEq)]
pub enum Selector {
    /// `[i, j]`: an array element.
    Index(Vec<Expr>),
    /// `.m`: a structure member or a block's input or output.
    Member(Ident),
}

/// A call: a function or a function block instance.
#[derive(Clone, Debug, PartialEq)]
pub struct Call {
    /// What is called.
    pub callee: Ident,
    /// The arguments in order.
    pub args: Vec<Arg>,
}

impl Call {
    /// The input values in their order (formal or positional), the
    /// outputs left out: what a standard function takes.
    pub fn input_values(&self) -> Vec<&Expr> {
        self.args
            .iter()
            .filter_map(|a| match a {
                Arg::Positional(e) | Arg::Input(_, e) => Some(e),
                Arg::Output { .. } => None,
            })
            .collect()
    }
}

/// A call's argument.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// `x` by position.
    Positional(Expr),
    /// `IN := x`.
    Input(Ident, Expr),
    /// `Q => y` (`NOT Q => y` when negated).
    Output {
        /// The output.
        name: Ident,
        /// Whether `NOT` inverts it.
        negated: bool,
        /// Where it goes.
        target: Variable,
    },
}

/// An expression and where it starts.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it computes.
    pub kind: ExprKind,
    /// Where it starts.
    pub span: Span,
}

/// The expressions of Structured Text.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A literal.
    Literal(Literal),
    /// A variable read.
    Variable(Variable),
    /// A function called (or a block instance named with arguments).
    Call(Call),
    /// `-x`, `+x`, `NOT x`.
    Unary(UnaryOp, Box<Expr>),
    /// `a op b`.
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
}

/// A literal's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Literal {
    /// `TRUE`, `FALSE`, `BOOL#1`.
    Bool(bool),
    /// `42`, `16#FF`, `INT#-5`: the value, with the type when written.
    Integer(i128, Option<Elementary>),
    /// `1.5`, `1.0E3`, `LREAL#2.5`: the value, with the type when written.
    Real(f64, Option<Elementary>),
    /// `T#1s200ms`: nanoseconds.
    Time(i64),
    /// `'text'` with its `$` escapes read.
    String(String),
}

/// The unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-`.
    Neg,
    /// `+`.
    Plus,
    /// `NOT`.
    Not,
}

/// The binary operators, from the tightest binding (`**`) to the loosest
/// (`OR`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum BinaryOp {
    Pow,
    Mul,
    Div,
    Mod,
    Add,
    Sub,
    Lt,
    Gt,
    Le,
    Ge,
    Eq,
    Ne,
    And,
    Xor,
    Or,
}

impl BinaryOp {
    /// How tightly it binds: `OR` 1 … `**` 8 (the unary operators bind
    /// tighter still, 9, as the standard's grammar has it).
    pub const fn precedence(self) -> u8 {
        match self {
            BinaryOp::Or => 1,
            BinaryOp::Xor => 2,
            BinaryOp::And => 3,
            BinaryOp::Eq | BinaryOp::Ne => 4,
            BinaryOp::Lt | BinaryOp::Gt | BinaryOp::Le | BinaryOp::Ge => 5,
            BinaryOp::Add | BinaryOp::Sub => 6,
            BinaryOp::Mul | BinaryOp::Div | BinaryOp::Mod => 7,
            BinaryOp::Pow => 8,
        }
    }

    /// The operator as the printer writes it.
    pub const fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Pow => "**",
            BinaryOp::Mul => "*",
            BinaryOp::Div => "/",
            BinaryOp::Mod => "MOD",
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Lt => "<",
            BinaryOp::Gt => ">",
            BinaryOp::Le => "<=",
            BinaryOp::Ge => ">=",
            BinaryOp::Eq => "=",
            BinaryOp::Ne => "<>",
            BinaryOp::And => "AND",
            BinaryOp::Xor => "XOR",
            BinaryOp::Or => "OR",
        }
    }
}

impl Elementary {
    /// The values an integer or bit-string type holds; `None` for the
    /// others.
    pub const fn range(self) -> Option<(i128, i128)> {
        Some(match self {
            Elementary::Sint => (-128, 127),
            Elementary::Int => (-32_768, 32_767),
            Elementary::Dint => (i32::MIN as i128, i32::MAX as i128),
            Elementary::Lint => (i64::MIN as i128, i64::MAX as i128),
            Elementary::Usint | Elementary::Byte => (0, 255),
            Elementary::Uint | Elementary::Word => (0, 65_535),
            Elementary::Udint | Elementary::Dword => (0, u32::MAX as i128),
            Elementary::Ulint | Elementary::Lword => (0, u64::MAX as i128),
            _ => return None,
        })
    }
}
