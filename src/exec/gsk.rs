//! GSK's macro A: `G65 Hm P#i Q#j R#k`, an operation whose result goes to
//! `#i`, or a jump to sequence number `P` when `#j` and `#k` compare as the
//! H code says (the GSK980TD family's "macro command list", GSK980TDi user
//! manual ch. 3). Q and R are variables or constants; a vacant variable
//! reads as 0.
//!
//! Each operation is written as the macro B expression it stands for and
//! evaluated by [`super::eval`], so division by zero, the square root of a
//! negative number and the degrees of the trigonometric functions are the
//! same as in `#i = […]`.

use super::eval::Fail;
use super::expr::{Expr, Func, Op};
use super::{Ctx, Exec, Flow, eval, fanuc};
use crate::args;
use crate::block::Block;
use crate::message as msg;
use crate::span::Span;

/// One address of a `G65 H` block: its letter, value as an expression and span.
pub struct Operand {
    /// The address letter.
    pub letter: u8,
    /// `#j` as [`Expr::Var`], a constant as [`Expr::Num`].
    pub value: Expr,
    /// Where it was written.
    pub span: Span,
}

/// Whether a block's words hold `G65`.
pub fn is_g65(block: &Block) -> bool {
    block.all(b'G').any(|w| w.num.integer() == Some(65))
}

/// A plain `G65 H… P… Q… R…` block (no `#` in it): constants only.
pub fn plain(ex: &mut Exec, ctx: &mut Ctx, block: &mut Block) -> Flow {
    let ops: Vec<Operand> =
        block.words().iter().map(|w| Operand { letter: w.letter, value: Expr::Num(w.value()), span: w.span }).collect();
    let g = block.all(b'G').find(|w| w.num.integer() == Some(65)).map_or(block.span, |w| w.span);
    run_or_alarm(ex, ctx, block, &ops, g)
}

/// Runs a `G65 H` block; an alarm marks the block and stops nothing else.
pub fn run_or_alarm(ex: &mut Exec, ctx: &mut Ctx, block: &mut Block, ops: &[Operand], g65: Span) -> Flow {
    match run(ex, ctx, ops, g65) {
        Ok(flow) => flow,
        Err(f) => {
            ctx.fail(f);
            block.has_error = true;
            Flow::Skip
        }
    }
}

/// Runs `G65 Hm …` given as `ops`.
fn run(ex: &mut Exec, ctx: &mut Ctx, ops: &[Operand], g65: Span) -> Result<Flow, Fail> {
    let get = |c: u8| ops.iter().find(|o| o.letter == c);
    let Some(h) = get(b'H') else { return needs(0, &msg::X_H_RESULT, g65) };
    let code = eval(ex, ctx, &h.value)?.unwrap_or(0.0);
    let hn = code as i64;
    let listed = matches!(hn, 1..=5 | 11..=13 | 21..=27 | 31..=34 | 80..=86 | 99);
    if code.fract() != 0.0 || !listed {
        return Err(unknown(ctx, code, h.span));
    }
    let (q, r) = (get(b'Q').map(|o| o.value.clone()), get(b'R').map(|o| o.value.clone()));
    let bin = |op: Op, a: Expr, b: Expr| Expr::Bin(op, Box::new(a), Box::new(b), h.span);
    let call = |f: Func, a: Expr| Expr::Call(f, Box::new(a), h.span);
    match hn {
        80..=86 => {
            let Some(p) = get(b'P') else { return needs(hn, &msg::X_H_SEQUENCE, h.span) };
            if hn > 80 {
                let (Some(a), Some(b)) = (q, r) else { return needs(hn, &msg::X_H_OPERANDS, h.span) };
                let rel = [Op::Eq, Op::Ne, Op::Gt, Op::Lt, Op::Ge, Op::Le][hn as usize - 81];
                // A vacant operand compares as 0.
                let zero = |e: Expr| bin(Op::Add, e, Expr::Num(0.0));
                if !super::truth(eval(ex, ctx, &bin(rel, zero(a), zero(b)))?) {
                    return Ok(Flow::Skip);
                }
            }
            fanuc::goto(ex, ctx, &p.value, p.span)?;
            Ok(Flow::Skip)
        }
        99 => {
            let Some(p) = get(b'P') else { return needs(hn, &msg::X_H_ALARM, h.span) };
            let n = eval(ex, ctx, &p.value)?.unwrap_or(0.0);
            Err(Fail { template: &msg::H_ALARM, span: h.span, args: args![n, value = 500.0 + n] })
        }
        _ => {
            let Some(p) = get(b'P') else { return needs(hn, &msg::X_H_RESULT, h.span) };
            let Expr::Var(target, _) = &p.value else { return needs(hn, &msg::X_H_RESULT, p.span) };
            let two = hn != 1 && !matches!(hn, 21 | 22 | 24 | 25);
            let (Some(a), b) = (q, r) else { return needs(hn, &msg::X_H_OPERANDS, h.span) };
            let Some(b) = b.or(if two { None } else { Some(Expr::Num(0.0)) }) else {
                return needs(hn, &msg::X_H_OPERANDS, h.span);
            };
            let e = match hn {
                1 => a,
                2 => bin(Op::Add, a, b),
                3 => bin(Op::Sub, a, b),
                4 => bin(Op::Mul, a, b),
                5 => bin(Op::Div, a, b),
                11 => bin(Op::Or, a, b),
                12 => bin(Op::And, a, b),
                13 => bin(Op::Xor, a, b),
                21 => call(Func::Sqrt, a),
                22 => call(Func::Abs, a),
                23 => bin(Op::Mod, a, b),
                24 => call(Func::Bin, a),
                25 => call(Func::Bcd, a),
                26 => bin(Op::Div, bin(Op::Mul, p.value.clone(), a), b),
                27 => call(Func::Sqrt, bin(Op::Add, bin(Op::Mul, a.clone(), a), bin(Op::Mul, b.clone(), b))),
                31 => bin(Op::Mul, a, call(Func::Sin, b)),
                32 => bin(Op::Mul, a, call(Func::Cos, b)),
                33 => bin(Op::Mul, a, call(Func::Tan, b)),
                34 => Expr::Atan2(Box::new(a), Box::new(b)),
                _ => return Err(unknown(ctx, code, h.span)),
            };
            let v = eval(ex, ctx, &e)?;
            fanuc::store(ex, ctx, target, Some(v.unwrap_or(0.0)), p.span, h.span)?;
            Ok(Flow::Skip)
        }
    }
}

fn needs<T>(h: i64, what: &'static msg::Phrase, span: Span) -> Result<T, Fail> {
    Err(Fail { template: &msg::H_NEEDS, span, args: args![h = format!("{h:02}"), what] })
}

fn unknown(ctx: &Ctx, code: f64, span: Span) -> Fail {
    let controller = crate::message::Arg::lit(ctx.rules.title());
    let h = if code.fract() == 0.0 { format!("{:02}", code as i64) } else { code.to_string() };
    Fail { template: &msg::H_UNKNOWN, span, args: args![h, controller] }
}
