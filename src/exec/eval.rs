//! Evaluating an [`Expr`] against the variables: Fanuc's vacant variable
//! (kept by a lone variable, read as 0 by arithmetic, told from 0 by `EQ`
//! and `NE`), the functions in degrees, division by zero and domains as
//! alarms in each controller's words.

use super::expr::{Expr, Flavor, Func, Op};
use crate::message as msg;
use crate::span::Span;

/// Why an evaluation failed: a template and its arguments at a span.
#[derive(Debug)]
pub struct Fail {
    /// The message.
    pub template: &'static crate::message::Template,
    /// Where.
    pub span: Span,
    /// Its arguments.
    pub args: crate::message::Args,
}

/// A value: `None` is Fanuc's vacant variable.
pub type Val = Option<f64>;

/// What an expression reads: the variables.
pub trait Env {
    /// Variable `n` (already a whole number).
    fn get(&mut self, n: i64, span: Span) -> Result<Val, Fail>;
    /// Named parameter `name` (LinuxCNC).
    fn named(&mut self, name: &str, span: Span) -> Result<Val, Fail>;
    /// Whether `name` is defined (LinuxCNC `EXISTS`).
    fn exists(&mut self, name: &str) -> bool;
    /// The least input increment (for `ADP`).
    fn increment(&self) -> f64;
    /// The language.
    fn flavor(&self) -> Flavor;
}

fn num(v: Val) -> f64 {
    v.unwrap_or(0.0)
}

/// Evaluates `e`. Fanuc's vacant is kept by a lone variable and read as 0
/// by arithmetic; `EQ`/`NE` tell vacant from 0, the other relations do not.
pub fn eval(e: &Expr, env: &mut dyn Env) -> Result<Val, Fail> {
    Ok(match e {
        Expr::Num(v) => Some(*v),
        Expr::Var(n, span) => {
            let v = num(eval(n, env)?);
            let i = v.round();
            if (v - i).abs() > 1e-6 || i.abs() > 1e9 {
                return Err(Fail { template: &msg::BAD_VARIABLE_NUMBER, span: *span, args: crate::args![value = v] });
            }
            env.get(i as i64, *span)?
        }
        Expr::Named(name, span) => env.named(name, *span)?,
        Expr::Exists(name) => Some(if env.exists(name) { 1.0 } else { 0.0 }),
        Expr::Neg(a) => Some(-num(eval(a, env)?)),
        Expr::Call(f, a, span) => Some(call(*f, num(eval(a, env)?), *span, env)?),
        Expr::Atan2(a, b) => {
            let (y, x) = (num(eval(a, env)?), num(eval(b, env)?));
            let d = y.atan2(x).to_degrees();
            // Fanuc's ATAN is 0° to 360°; LinuxCNC's −180° to 180°.
            Some(if env.flavor() == Flavor::Fanuc && d < 0.0 { d + 360.0 } else { d })
        }
        Expr::Bin(op, a, b, span) => {
            let (x, y) = (eval(a, env)?, eval(b, env)?);
            binary(*op, x, y, *span, env.flavor())?
        }
    })
}

fn call(f: Func, x: f64, span: Span, env: &mut dyn Env) -> Result<f64, Fail> {
    let domain = |what: &'static str| Fail { template: &msg::MACRO_DOMAIN, span, args: crate::args![what, value = x] };
    let v = match f {
        Func::Sin => x.to_radians().sin(),
        Func::Cos => x.to_radians().cos(),
        Func::Tan => x.to_radians().tan(),
        Func::Asin if x.abs() <= 1.0 => x.asin().to_degrees(),
        Func::Acos if x.abs() <= 1.0 => x.acos().to_degrees(),
        Func::Asin => return Err(domain("ASIN")),
        Func::Acos => return Err(domain("ACOS")),
        Func::Atan => x.atan().to_degrees(),
        Func::Sqrt if x >= 0.0 => x.sqrt(),
        Func::Sqrt => return Err(domain("SQRT")),
        Func::Abs => x.abs(),
        Func::Round => x.round(),
        Func::Fix => x.trunc(),
        Func::Fup => {
            let t = x.trunc();
            if t == x { t } else { t + x.signum() }
        }
        Func::Ln if x > 0.0 => x.ln(),
        Func::Ln => return Err(domain("LN")),
        Func::Exp => x.exp(),
        Func::Bin => bcd_to_bin(x),
        Func::Bcd => bin_to_bcd(x),
        Func::Adp => x * env.increment(),
    };
    if v.is_finite() { Ok(v) } else { Err(domain("")) }
}

fn bcd_to_bin(x: f64) -> f64 {
    let mut v = x.abs() as u64;
    let (mut out, mut place) = (0u64, 1u64);
    while v > 0 && place < 1_000_000_000_000 {
        out += (v & 0xF) * place;
        v >>= 4;
        place *= 10;
    }
    out as f64
}

fn bin_to_bcd(x: f64) -> f64 {
    let mut v = x.abs() as u64;
    let (mut out, mut shift) = (0u64, 0u32);
    while v > 0 && shift < 60 {
        out |= (v % 10) << shift;
        v /= 10;
        shift += 4;
    }
    out as f64
}

fn binary(op: Op, x: Val, y: Val, span: Span, flavor: Flavor) -> Result<Val, Fail> {
    let (a, b) = (num(x), num(y));
    let truth = |t: bool| Some(if t { 1.0 } else { 0.0 });
    let int = |v: f64| v.round() as i64;
    Ok(match op {
        Op::Add => Some(a + b),
        Op::Sub => Some(a - b),
        Op::Mul => Some(a * b),
        // rs274: x MOD 0 is not a number.
        Op::Mod if b == 0.0 && flavor == Flavor::LinuxCnc => {
            return Err(Fail { template: &msg::LCNC_NOT_A_NUMBER, span, args: crate::args![] });
        }
        // Fanuc's MOD takes the remainder of whole numbers: a divisor that rounds to 0 divides by zero.
        Op::Div | Op::Mod if b == 0.0 || (op == Op::Mod && flavor == Flavor::Fanuc && int(b) == 0) => {
            let t = if flavor == Flavor::LinuxCnc { &msg::LCNC_DIVIDE_BY_ZERO } else { &msg::DIVIDED_BY_ZERO };
            return Err(Fail { template: t, span, args: crate::args![] });
        }
        Op::Div => Some(a / b),
        Op::Mod => Some(match flavor {
            // rs274: fmod, then a negative remainder raised by |b|: never negative.
            Flavor::LinuxCnc => {
                let r = a % b;
                if r < 0.0 { r + b.abs() } else { r }
            }
            Flavor::Fanuc => (int(a) % int(b)) as f64,
        }),
        Op::Pow => {
            let v = a.powf(b);
            if !v.is_finite() {
                return Err(Fail { template: &msg::MACRO_DOMAIN, span, args: crate::args![what = "POW", value = a] });
            }
            Some(v)
        }
        Op::And if flavor == Flavor::LinuxCnc => truth(a != 0.0 && b != 0.0),
        Op::Or if flavor == Flavor::LinuxCnc => truth(a != 0.0 || b != 0.0),
        Op::Xor if flavor == Flavor::LinuxCnc => truth((a != 0.0) != (b != 0.0)),
        Op::And => Some((int(a) & int(b)) as f64),
        Op::Or => Some((int(a) | int(b)) as f64),
        Op::Xor => Some((int(a) ^ int(b)) as f64),
        Op::Eq => truth(same(x, y)),
        Op::Ne => truth(!same(x, y)),
        Op::Gt => truth(a > b),
        Op::Ge => truth(a >= b),
        Op::Lt => truth(a < b),
        Op::Le => truth(a <= b),
    })
}

/// `EQ`: vacant equals only vacant; numbers within a millionth.
fn same(x: Val, y: Val) -> bool {
    match (x, y) {
        (None, None) => true,
        (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0),
        _ => false,
    }
}
