//! Macro expressions: `[#1 * 2 + SIN[30]]`, parsed from a folded line
//! ([`Src`]) into an [`Expr`] and evaluated against the variables.
//!
//! Precedence is the controller's (a [`Flavor`]): Fanuc custom macro B
//! binds functions, then `* / AND MOD`, then `+ - OR XOR`, then the
//! relations; LinuxCNC (rs274ngc) binds `**`, then `* / MOD`, then `+ -`,
//! then the relations, then `AND OR XOR`. Operators of one level associate
//! to the left on both.

use crate::message::{self as msg, Phrase};
use crate::span::Span;

pub use crate::controller::macros::Flavor;

/// A line of code as the macro parser reads it: one folded ASCII byte per
/// character, with each character's byte offset in the program.
pub struct Src {
    /// Folded characters (full-width forms as their ASCII twins).
    pub b: Vec<u8>,
    /// Byte offset of each character, plus one past the last.
    pub at: Vec<u32>,
}

impl Src {
    /// The character at `i` (0 past the end).
    pub fn get(&self, i: usize) -> u8 {
        self.b.get(i).copied().unwrap_or(0)
    }

    /// The span of characters `from..to`.
    pub fn span(&self, from: usize, to: usize) -> Span {
        let n = self.b.len();
        Span::new(self.at[from.min(n)] as usize, self.at[to.min(n)] as usize)
    }

    /// Whether the letters at `i` spell `kw` (case-insensitive).
    pub fn keyword(&self, i: usize, kw: &str) -> bool {
        kw.bytes().enumerate().all(|(k, c)| self.get(i + k).eq_ignore_ascii_case(&c))
    }
}

/// A function of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    /// Sine of degrees.
    Sin,
    /// Cosine of degrees.
    Cos,
    /// Tangent of degrees.
    Tan,
    /// Arc sine, degrees.
    Asin,
    /// Arc cosine, degrees.
    Acos,
    /// Arc tangent of one argument, degrees.
    Atan,
    /// Square root.
    Sqrt,
    /// Absolute value.
    Abs,
    /// Rounded to the nearest whole number, halves away from zero.
    Round,
    /// Fraction dropped (towards zero).
    Fix,
    /// Fraction raised (away from zero).
    Fup,
    /// Natural logarithm.
    Ln,
    /// e to the power.
    Exp,
    /// BCD to binary.
    Bin,
    /// Binary to BCD.
    Bcd,
    /// Adds the decimal point: the value read in least input increments.
    Adp,
}

const FUNCS: &[(&str, Func)] = &[
    ("SIN", Func::Sin),
    ("COS", Func::Cos),
    ("TAN", Func::Tan),
    ("ASIN", Func::Asin),
    ("ACOS", Func::Acos),
    ("ATAN", Func::Atan),
    ("SQRT", Func::Sqrt),
    ("SQR", Func::Sqrt),
    ("ABS", Func::Abs),
    ("ROUND", Func::Round),
    ("FIX", Func::Fix),
    ("FUP", Func::Fup),
    ("LN", Func::Ln),
    ("EXP", Func::Exp),
    ("BIN", Func::Bin),
    ("BCD", Func::Bcd),
    ("ADP", Func::Adp),
];

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `MOD`
    Mod,
    /// `**` (LinuxCNC), `POW[a,b]` (Fanuc)
    Pow,
    /// `AND`
    And,
    /// `OR`
    Or,
    /// `XOR`
    Xor,
    /// `EQ`
    Eq,
    /// `NE`
    Ne,
    /// `GT`
    Gt,
    /// `GE`
    Ge,
    /// `LT`
    Lt,
    /// `LE`
    Le,
}

const OPS: &[(&str, Op)] = &[
    ("**", Op::Pow),
    ("+", Op::Add),
    ("-", Op::Sub),
    ("*", Op::Mul),
    ("/", Op::Div),
    ("MOD", Op::Mod),
    ("AND", Op::And),
    ("XOR", Op::Xor),
    ("OR", Op::Or),
    ("EQ", Op::Eq),
    ("NE", Op::Ne),
    ("GT", Op::Gt),
    ("GE", Op::Ge),
    ("LT", Op::Lt),
    ("LE", Op::Le),
];

impl Op {
    /// Binding strength (higher binds tighter) in `flavor`.
    fn level(self, flavor: Flavor) -> u8 {
        use Op::*;
        match (flavor, self) {
            (_, Pow) => 5,
            (Flavor::Fanuc, Mul | Div | Mod | And) => 4,
            (Flavor::Fanuc, Add | Sub | Or | Xor) => 3,
            (Flavor::LinuxCnc, Mul | Div | Mod) => 4,
            (Flavor::LinuxCnc, Add | Sub) => 3,
            (_, Eq | Ne | Gt | Ge | Lt | Le) => 2,
            (_, And | Or | Xor) => 1,
        }
    }
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A number.
    Num(f64),
    /// `#n`: the variable whose number the expression gives.
    Var(Box<Expr>, Span),
    /// `#<name>` (LinuxCNC), the name lower-cased without spaces.
    Named(Box<str>, Span),
    /// `EXISTS[#<name>]` (LinuxCNC).
    Exists(Box<str>),
    /// `-e`.
    Neg(Box<Expr>),
    /// `FUNC[e]`.
    Call(Func, Box<Expr>, Span),
    /// `ATAN[y]/[x]`, `ATAN[y,x]`.
    Atan2(Box<Expr>, Box<Expr>),
    /// `a op b`.
    Bin(Op, Box<Expr>, Box<Expr>, Span),
}

/// A parse failure: what was expected and where.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntaxError {
    /// Where.
    pub span: Span,
    /// What the parser found there, as written (`None`: the end of the block).
    pub found: Option<String>,
    /// What it expected.
    pub expected: &'static Phrase,
}

impl SyntaxError {
    /// The message arguments: `found` and `expected`.
    pub fn args(&self) -> crate::message::Args {
        let found = match &self.found {
            Some(s) => crate::message::Arg::from(s.as_str()),
            None => crate::message::Arg::Phrase(&crate::message::X_END),
        };
        crate::args![found, expected = self.expected]
    }
}

/// Most nested brackets in one expression (beyond it, an alarm; also keeps
/// the recursion bounded).
pub const MAX_DEPTH: usize = 32;

/// Parses expressions from a [`Src`].
pub struct Parser<'s> {
    /// The line.
    pub src: &'s Src,
    /// The next character.
    pub i: usize,
    /// The language.
    pub flavor: Flavor,
    depth: usize,
}

impl<'s> Parser<'s> {
    /// A parser at character `i` of `src`.
    pub fn new(src: &'s Src, i: usize, flavor: Flavor) -> Parser<'s> {
        Parser { src, i, flavor, depth: 0 }
    }

    /// Skips blanks and comments.
    pub fn blank(&mut self) {
        loop {
            match self.src.get(self.i) {
                b' ' | b'\t' => self.i += 1,
                b'(' => {
                    while !matches!(self.src.get(self.i), 0 | b')') {
                        self.i += 1;
                    }
                    if self.src.get(self.i) == b')' {
                        self.i += 1;
                    }
                }
                _ => return,
            }
        }
    }

    /// The next character after blanks (not consumed).
    pub fn peek(&mut self) -> u8 {
        self.blank();
        self.src.get(self.i)
    }

    /// A failure at the next character.
    pub fn fail(&mut self, expected: &'static Phrase) -> SyntaxError {
        self.blank();
        let end = (self.i + 1).min(self.src.b.len());
        let found = if self.i >= self.src.b.len() {
            None
        } else {
            Some(String::from_utf8_lossy(&self.src.b[self.i..end]).into_owned())
        };
        SyntaxError { span: self.src.span(self.i, end.max(self.i + 1)), found, expected }
    }

    /// Consumes `c` or fails.
    pub fn expect(&mut self, c: u8, expected: &'static Phrase) -> Result<(), SyntaxError> {
        if self.peek() == c {
            self.i += 1;
            Ok(())
        } else {
            Err(self.fail(expected))
        }
    }

    /// `[ expr ]`.
    pub fn bracketed(&mut self) -> Result<Expr, SyntaxError> {
        let open = self.i;
        self.expect(b'[', &msg::X_OPEN)?;
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            self.i = open;
            return Err(self.fail(&msg::X_FEWER_BRACKETS));
        }
        let e = self.expr(0)?;
        self.expect(b']', &msg::X_CLOSE)?;
        self.depth -= 1;
        Ok(e)
    }

    /// An expression whose operators bind tighter than `min`.
    pub fn expr(&mut self, min: u8) -> Result<Expr, SyntaxError> {
        let start = self.i;
        let mut lhs = self.unary()?;
        loop {
            self.blank();
            let Some((len, op)) = self.operator() else { break };
            let level = op.level(self.flavor);
            if level <= min {
                break;
            }
            self.i += len;
            let rhs = self.expr(level)?;
            let span = self.src.span(start, self.i);
            lhs = Expr::Bin(op, Box::new(lhs), Box::new(rhs), span);
        }
        Ok(lhs)
    }

    fn operator(&self) -> Option<(usize, Op)> {
        for &(name, op) in OPS {
            if op == Op::Pow && self.flavor == Flavor::Fanuc {
                continue;
            }
            if self.src.keyword(self.i, name) {
                // A word operator is not the start of a longer name.
                let alpha = name.as_bytes()[0].is_ascii_alphabetic();
                if alpha && self.src.get(self.i + name.len()).is_ascii_alphabetic() {
                    continue;
                }
                return Some((name.len(), op));
            }
        }
        None
    }

    /// A value: a number, a variable, a bracketed expression, a function, a sign.
    pub fn unary(&mut self) -> Result<Expr, SyntaxError> {
        match self.peek() {
            b'-' => {
                self.i += 1;
                Ok(Expr::Neg(Box::new(self.unary()?)))
            }
            b'+' => {
                self.i += 1;
                self.unary()
            }
            b'[' => self.bracketed(),
            b'#' => self.variable(),
            b'0'..=b'9' | b'.' => self.number().map(Expr::Num),
            c if c.is_ascii_alphabetic() => self.function(),
            _ => Err(self.fail(&msg::X_VALUE)),
        }
    }

    /// `#n`, `#[e]`, `##n`, `#<name>`.
    pub fn variable(&mut self) -> Result<Expr, SyntaxError> {
        let at = self.i;
        self.expect(b'#', &msg::X_HASH)?;
        if self.flavor == Flavor::LinuxCnc && self.peek() == b'<' {
            let name = self.name()?;
            return Ok(Expr::Named(name, self.src.span(at, self.i)));
        }
        let inner = match self.peek() {
            b'[' => self.bracketed()?,
            b'#' => self.variable()?,
            b'0'..=b'9' => Expr::Num(self.number()?),
            _ => return Err(self.fail(&msg::X_VARIABLE_NUMBER)),
        };
        Ok(Expr::Var(Box::new(inner), self.src.span(at, self.i)))
    }

    /// `<name>`: lower-cased, blanks dropped (as rs274 reads it).
    pub fn name(&mut self) -> Result<Box<str>, SyntaxError> {
        self.expect(b'<', &msg::X_LT)?;
        let mut s = String::new();
        loop {
            match self.src.get(self.i) {
                b'>' => {
                    self.i += 1;
                    break;
                }
                0 => return Err(self.fail(&msg::X_GT)),
                b' ' | b'\t' => self.i += 1,
                c => {
                    s.push(c.to_ascii_lowercase() as char);
                    self.i += 1;
                }
            }
        }
        if s.is_empty() {
            return Err(self.fail(&msg::X_NAME));
        }
        Ok(s.into_boxed_str())
    }

    /// An unsigned decimal number.
    pub fn number(&mut self) -> Result<f64, SyntaxError> {
        self.blank();
        let from = self.i;
        let mut seen_digit = false;
        let mut seen_point = false;
        loop {
            match self.src.get(self.i) {
                b'0'..=b'9' => seen_digit = true,
                b'.' if !seen_point => seen_point = true,
                b' ' | b'\t' if self.flavor == Flavor::LinuxCnc => {}
                _ => break,
            }
            self.i += 1;
        }
        let text: String =
            self.src.b[from..self.i].iter().filter(|c| !c.is_ascii_whitespace()).map(|&c| c as char).collect();
        match text.parse::<f64>() {
            Ok(v) if seen_digit && v.is_finite() => Ok(v),
            _ => {
                self.i = from;
                Err(self.fail(&msg::X_NUMBER))
            }
        }
    }

    fn function(&mut self) -> Result<Expr, SyntaxError> {
        let at = self.i;
        if self.flavor == Flavor::LinuxCnc && self.src.keyword(self.i, "EXISTS") {
            self.i += 6;
            self.expect(b'[', &msg::X_OPEN)?;
            self.expect(b'#', &msg::X_HASH)?;
            let name = self.name()?;
            self.expect(b']', &msg::X_CLOSE)?;
            return Ok(Expr::Exists(name));
        }
        if self.flavor == Flavor::Fanuc && self.src.keyword(self.i, "POW") {
            self.i += 3;
            self.expect(b'[', &msg::X_OPEN)?;
            let a = self.expr(0)?;
            self.expect(b',', &msg::X_COMMA)?;
            let b = self.expr(0)?;
            self.expect(b']', &msg::X_CLOSE)?;
            return Ok(Expr::Bin(Op::Pow, Box::new(a), Box::new(b), self.src.span(at, self.i)));
        }
        // The longest name that matches (ASIN before SIN is not an issue: names start differently).
        let found = FUNCS
            .iter()
            .filter(|(n, _)| self.src.keyword(self.i, n) && !self.src.get(self.i + n.len()).is_ascii_alphabetic())
            .max_by_key(|(n, _)| n.len());
        let Some(&(name, f)) = found else { return Err(self.fail(&msg::X_FUNCTION)) };
        self.i += name.len();
        if self.peek() != b'[' {
            return Err(self.fail(&msg::X_OPEN));
        }
        self.depth += 1;
        self.i += 1;
        let a = self.expr(0)?;
        if f == Func::Atan && self.flavor == Flavor::Fanuc && self.peek() == b',' {
            self.i += 1;
            let b = self.expr(0)?;
            self.expect(b']', &msg::X_CLOSE)?;
            self.depth -= 1;
            return Ok(Expr::Atan2(Box::new(a), Box::new(b)));
        }
        self.expect(b']', &msg::X_CLOSE)?;
        self.depth -= 1;
        if f == Func::Atan && self.peek() == b'/' {
            let save = self.i;
            self.i += 1;
            if self.peek() == b'[' {
                let b = self.bracketed()?;
                return Ok(Expr::Atan2(Box::new(a), Box::new(b)));
            }
            self.i = save;
            if self.flavor == Flavor::LinuxCnc {
                return Err(self.fail(&msg::X_ATAN_DIVISOR));
            }
        } else if f == Func::Atan && self.flavor == Flavor::LinuxCnc {
            return Err(self.fail(&msg::X_ATAN_SLASH));
        }
        Ok(Expr::Call(f, Box::new(a), self.src.span(at, self.i)))
    }
}
