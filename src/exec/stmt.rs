//! A macro line parsed: an assignment, a jump, a loop keyword, an o-word,
//! or NC words whose values are expressions.
//!
//! Only lines the lexer marks as macro lines come here (they hold `#`, `[`,
//! a keyword such as `IF`, `WHILE`, `GOTO`, `END`, `DO`, or a LinuxCNC
//! o-word); every other line is read by the lexer alone.

use super::expr::{Expr, Flavor, Parser, Src, SyntaxError};
use crate::message as msg;
use crate::span::Span;

/// A value written at an address: a number as written or an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A plain number with its digits as written.
    Num(crate::block::Number),
    /// `#1`, `-#1`, `[…]`, `SIN[…]` (LinuxCNC).
    Expr(Expr),
}

/// An address word of a macro line.
#[derive(Clone, Debug, PartialEq)]
pub struct MWord {
    /// Upper-case letter.
    pub letter: u8,
    /// Its value.
    pub value: Value,
    /// The span of the word.
    pub span: Span,
}

/// `#target = value`.
#[derive(Clone, Debug, PartialEq)]
pub struct Assign {
    /// The variable: `#n`, `#[e]` or `#<name>` as an [`Expr::Var`] / [`Expr::Named`].
    pub target: Expr,
    /// The value.
    pub value: Expr,
    /// The span of the assignment.
    pub span: Span,
}

/// What a LinuxCNC o-word line says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OKw {
    /// `sub`
    Sub,
    /// `endsub`
    EndSub,
    /// `call`
    Call,
    /// `return`
    Return,
    /// `if`
    If,
    /// `elseif`
    ElseIf,
    /// `else`
    Else,
    /// `endif`
    EndIf,
    /// `while`
    While,
    /// `endwhile`
    EndWhile,
    /// `do`
    Do,
    /// `repeat`
    Repeat,
    /// `endrepeat`
    EndRepeat,
    /// `break`
    Break,
    /// `continue`
    Continue,
}

/// The o-word keywords, longest first where one begins another.
pub const OKWS: &[(&str, OKw)] = &[
    ("endsub", OKw::EndSub),
    ("endif", OKw::EndIf),
    ("endwhile", OKw::EndWhile),
    ("endrepeat", OKw::EndRepeat),
    ("elseif", OKw::ElseIf),
    ("else", OKw::Else),
    ("sub", OKw::Sub),
    ("call", OKw::Call),
    ("return", OKw::Return),
    ("if", OKw::If),
    ("while", OKw::While),
    ("do", OKw::Do),
    ("repeat", OKw::Repeat),
    ("break", OKw::Break),
    ("continue", OKw::Continue),
];

/// A parsed macro line.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// Address words (some with expressions) and, on LinuxCNC, parameter
    /// settings that take effect when the line has been read.
    Words(Vec<MWord>, Vec<Assign>),
    /// `#i = e` (Fanuc).
    Assign(Assign),
    /// `IF [c] GOTO n`.
    IfGoto(Expr, Expr, Span),
    /// `IF [c] THEN #i = e`.
    IfThen(Expr, Assign),
    /// `WHILE [c] DO m`.
    While(Expr, u8, Span),
    /// `DO m` without a condition: a loop that only a jump leaves.
    Do(u8, Span),
    /// `END m`.
    End(u8, Span),
    /// `GOTO n`, `GOTO #i`.
    Goto(Expr, Span),
    /// A LinuxCNC o-word: label, keyword, arguments or condition.
    O(Box<str>, OKw, Vec<Expr>, Span),
}

/// A parsed line: its `N`, block delete and statement.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// The `N` number as written.
    pub n: Option<crate::block::Word>,
    /// Starts with `/`.
    pub deleted: bool,
    /// What it says.
    pub stmt: Stmt,
}

/// Parses a macro line of `flavor`; `known(letter)` says which addresses the controller has.
pub fn parse(src: &Src, flavor: Flavor, known: &dyn Fn(u8) -> bool) -> Result<Line, SyntaxError> {
    let mut p = Parser::new(src, 0, flavor);
    let mut deleted = false;
    if p.peek() == b'/' {
        p.i += 1;
        deleted = true;
        if p.src.get(p.i).is_ascii_digit() {
            p.i += 1;
        }
    }
    let mut n = None;
    if p.peek().eq_ignore_ascii_case(&b'N') && p.src.get(p.i + 1).is_ascii_digit() {
        let at = p.i;
        p.i += 1;
        let v = p.number()?;
        n = Some(word(b'N', v, p.src.span(at, p.i)));
    }
    let stmt = if flavor == Flavor::LinuxCnc && p.peek().eq_ignore_ascii_case(&b'O') {
        oword(&mut p)?
    } else if flavor == Flavor::Fanuc {
        fanuc(&mut p, known)?
    } else {
        words(&mut p, known)?
    };
    if p.peek() != 0 && p.peek() != b';' {
        return Err(p.fail(&msg::X_END));
    }
    Ok(Line { n, deleted, stmt })
}

/// A word with a plain value, as the lexer would give it.
fn word(letter: u8, v: f64, span: Span) -> crate::block::Word {
    let num = crate::block::Number { value: v, has_point: v.fract() != 0.0, int_digits: 1, frac_digits: 0 };
    crate::block::Word { letter, num, span }
}

/// A keyword at the next character, not followed by another letter
/// (`END1`, `GOTO 10`, `IF[`).
fn kw(p: &mut Parser, name: &str) -> bool {
    p.blank();
    p.src.keyword(p.i, name) && !p.src.get(p.i + name.len()).is_ascii_alphabetic()
}

/// A loop number 1–3 (Fanuc allows 1 to 3 for DO/END).
fn loop_id(p: &mut Parser) -> Result<(u8, Span), SyntaxError> {
    let at = p.i;
    let v = p.number()?;
    let span = p.src.span(at, p.i);
    if v.fract() != 0.0 || !(1.0..=255.0).contains(&v) {
        p.i = at;
        return Err(p.fail(&msg::X_LOOP));
    }
    Ok((v as u8, span))
}

fn fanuc(p: &mut Parser, known: &dyn Fn(u8) -> bool) -> Result<Stmt, SyntaxError> {
    let start = p.i;
    if kw(p, "IF") {
        p.i += 2;
        let cond = p.bracketed()?;
        if kw(p, "GOTO") {
            p.i += 4;
            let at = p.i;
            let target = p.unary()?;
            return Ok(Stmt::IfGoto(cond, target, p.src.span(at, p.i)));
        }
        if kw(p, "THEN") {
            p.i += 4;
            let a = assign(p)?;
            return Ok(Stmt::IfThen(cond, a));
        }
        return Err(p.fail(&msg::X_GOTO_THEN));
    }
    if kw(p, "WHILE") {
        p.i += 5;
        let cond = p.bracketed()?;
        if !kw(p, "DO") {
            return Err(p.fail(&msg::X_DO));
        }
        p.i += 2;
        let (m, span) = loop_id(p)?;
        return Ok(Stmt::While(cond, m, span));
    }
    if kw(p, "GOTO") {
        p.i += 4;
        let target = p.unary()?;
        return Ok(Stmt::Goto(target, p.src.span(start, p.i)));
    }
    if kw(p, "END") {
        p.i += 3;
        let (m, span) = loop_id(p)?;
        return Ok(Stmt::End(m, span));
    }
    if kw(p, "DO") {
        p.i += 2;
        let (m, span) = loop_id(p)?;
        return Ok(Stmt::Do(m, span));
    }
    if p.peek() == b'#' {
        return Ok(Stmt::Assign(assign(p)?));
    }
    words(p, known)
}

/// `#i = e` or `#<name> = e`.
fn assign(p: &mut Parser) -> Result<Assign, SyntaxError> {
    p.blank();
    let at = p.i;
    let target = p.variable()?;
    p.expect(b'=', &msg::X_EQUALS)?;
    let value = p.expr(0)?;
    Ok(Assign { target, value, span: p.src.span(at, p.i) })
}

/// Address words whose values may be expressions; on LinuxCNC, parameter settings too.
fn words(p: &mut Parser, known: &dyn Fn(u8) -> bool) -> Result<Stmt, SyntaxError> {
    let mut out = Vec::new();
    let mut sets = Vec::new();
    loop {
        let c = p.peek();
        if c == 0 || c == b';' {
            break;
        }
        if c == b'#' {
            if p.flavor == Flavor::Fanuc && !out.is_empty() {
                return Err(p.fail(&msg::X_ADDRESS));
            }
            sets.push(assign(p)?);
            continue;
        }
        if !c.is_ascii_alphabetic() {
            return Err(p.fail(&msg::X_ADDRESS));
        }
        let letter = c.to_ascii_uppercase();
        if !known(letter) {
            return Err(p.fail(&msg::X_OWN_ADDRESS));
        }
        let at = p.i;
        p.i += 1;
        let value = match p.peek() {
            b'#' | b'[' => Value::Expr(p.unary()?),
            b'-' | b'+' if matches!(next_after_sign(p), b'#' | b'[') => Value::Expr(p.unary()?),
            c if c.is_ascii_alphabetic() && p.flavor == Flavor::LinuxCnc => Value::Expr(p.unary()?),
            _ => Value::Num(plain(p)?),
        };
        out.push(MWord { letter, value, span: p.src.span(at, p.i) });
    }
    Ok(Stmt::Words(out, sets))
}

fn next_after_sign(p: &mut Parser) -> u8 {
    let mut j = p.i + 1;
    while matches!(p.src.get(j), b' ' | b'\t') {
        j += 1;
    }
    p.src.get(j)
}

/// A signed number with its digits as written.
fn plain(p: &mut Parser) -> Result<crate::block::Number, SyntaxError> {
    let neg = match p.peek() {
        b'-' => {
            p.i += 1;
            true
        }
        b'+' => {
            p.i += 1;
            false
        }
        _ => false,
    };
    p.blank();
    let from = p.i;
    let v = p.number()?;
    let text: Vec<u8> = p.src.b[from..p.i].iter().copied().filter(|c| !c.is_ascii_whitespace()).collect();
    let point = text.iter().position(|&c| c == b'.');
    let (int_digits, frac_digits) = match point {
        Some(k) => (k, text.len() - k - 1),
        None => (text.len(), 0),
    };
    Ok(crate::block::Number {
        value: if neg { -v } else { v },
        has_point: point.is_some(),
        int_digits: int_digits.min(255) as u8,
        frac_digits: frac_digits.min(255) as u8,
    })
}

/// `o100 call [1] [2]`, `o<name> if [c]`, `o100 endsub`.
fn oword(p: &mut Parser) -> Result<Stmt, SyntaxError> {
    let at = p.i;
    p.i += 1;
    let label: Box<str> = if p.peek() == b'<' {
        p.name()?
    } else {
        let from = p.i;
        let v = p.number()?;
        if v.fract() != 0.0 {
            p.i = from;
            return Err(p.fail(&msg::X_OWORD_NUMBER));
        }
        format!("{}", v as i64).into_boxed_str()
    };
    p.blank();
    let Some(&(name, k)) = OKWS.iter().find(|(n, _)| kw(p, n)) else {
        return Err(p.fail(&msg::X_OWORD_KEYWORD));
    };
    p.i += name.len();
    let span = p.src.span(at, p.i);
    let mut args = Vec::new();
    match k {
        OKw::Call => {
            while p.peek() == b'[' {
                args.push(p.bracketed()?);
            }
        }
        OKw::If | OKw::ElseIf | OKw::While | OKw::Repeat => args.push(p.bracketed()?),
        OKw::Return | OKw::EndSub if p.peek() == b'[' => args.push(p.bracketed()?),
        _ => {}
    }
    Ok(Stmt::O(label, k, args, span))
}

/// Folds a line of `text` (`span`) into a [`Src`]; `None` when a character has no ASCII twin.
pub fn source(text: &str, span: Span) -> Src {
    let (start, end) = (span.start as usize, span.end as usize);
    let line = &text[start..end];
    let mut b = Vec::with_capacity(line.len());
    let mut at = Vec::with_capacity(line.len() + 1);
    for (i, c) in line.char_indices() {
        let folded = if c.is_ascii() { c as u8 } else { crate::lexer::fold_char(c).unwrap_or(b'?') };
        b.push(folded);
        at.push((start + i) as u32);
    }
    at.push(end as u32);
    Src { b, at }
}
