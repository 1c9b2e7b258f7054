//! LinuxCNC's o-words as rs274ngc runs them: `sub`/`endsub`/`call` with
//! positional arguments into #1–#30, `return`, `if`/`elseif`/`else`/`endif`,
//! `while`/`endwhile`, `do`/`while`, `repeat`/`endrepeat`, `break`,
//! `continue`; numbered parameters (unset ones read 0), `#<local>` and
//! `#<_global>` named parameters; the parameters set on a line take their
//! values when the whole line has been read.

use super::eval::{Fail, Val};
use super::expr::Expr;
use super::index::{At, Entry};
use super::stmt::{Line, OKw, Stmt};
use super::{CallKind, Ctx, Exec, Flow, Loop, Macros, Vals, eval, fill, truth};
use crate::args;
use crate::block::Block;
use crate::message as msg;
use crate::span::Span;

/// Highest numbered parameter (rs274ngc's RS274NGC_MAX_PARAMETERS − 1).
const MAX_PARAMETER: i64 = 5601;

/// Runs a parsed LinuxCNC macro line.
pub(super) fn statement(
    ex: &mut Exec,
    ctx: &mut Ctx,
    block: &mut Block,
    line: &Line,
    macros: &Macros,
) -> Result<Flow, Fail> {
    match &line.stmt {
        Stmt::Words(words, sets) => {
            // A named parameter set on the line exists, at 0, while the line
            // is read; every value is read before any parameter is set.
            for a in sets {
                if let Expr::Named(name, _) = &a.target {
                    if ex.vars.named(name).is_none() {
                        ex.vars.set_named(name, 0.0);
                    }
                }
            }
            let mut values = Vec::with_capacity(sets.len());
            for a in sets {
                values.push(eval(ex, ctx, &a.value)?.unwrap_or(0.0));
            }
            if !fill(ex, ctx, block, line, words) {
                block.has_error = true;
                return Ok(Flow::Run);
            }
            for (a, v) in sets.iter().zip(values) {
                set(ex, ctx, &a.target, v)?;
            }
            Ok(if block.words().is_empty() && block.n.is_none() { Flow::Skip } else { Flow::Run })
        }
        Stmt::O(label, kw, args, span) => oword(ex, ctx, label, *kw, args, *span, macros).map(|()| Flow::Skip),
        _ => Ok(Flow::Skip),
    }
}

fn set(ex: &mut Exec, ctx: &mut Ctx, target: &Expr, v: f64) -> Result<(), Fail> {
    match target {
        Expr::Named(name, _) => {
            ex.vars.set_named(name, v);
            Ok(())
        }
        Expr::Var(n, span) => {
            let n = eval(ex, ctx, n)?.unwrap_or(0.0);
            let k = n.round() as i64;
            if (n - k as f64).abs() > 1e-6 || !(1..=MAX_PARAMETER).contains(&k) {
                return Err(Fail { template: &msg::PARAMETER_RANGE, span: *span, args: args![] });
            }
            if k <= 30 {
                ex.vars.set_local(k as usize, Some(v));
            } else {
                ex.vars.set_common(k as u32, Some(v));
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Reads numbered parameter `#n`: unset ones are 0.
pub fn read(env: &mut Vals, n: i64, span: Span) -> Result<Val, Fail> {
    if !(1..=MAX_PARAMETER).contains(&n) {
        return Err(Fail { template: &msg::PARAMETER_RANGE, span, args: args![] });
    }
    Ok(Some(if n <= 30 { env.vars.local(n as usize) } else { env.vars.common(n as u32) }.unwrap_or(0.0)))
}

/// Reads `#<name>`: a value set by the program, or one of the predefined
/// names that tell the modal state and the position.
pub fn named(env: &mut Vals, name: &str, span: Span) -> Result<Val, Fail> {
    if let Some(v) = env.vars.named(name) {
        return Ok(Some(v));
    }
    let m = env.modal;
    let flag = |b: bool| Some(if b { 1.0 } else { 0.0 });
    Ok(match name {
        "_metric" => flag(!m.inch),
        "_imperial" => flag(m.inch),
        "_absolute" => flag(!m.incremental),
        "_incremental" => flag(m.incremental),
        "_value" | "_value_returned" => Some(0.0),
        // The current position: X as a radius even in diameter mode (rs274 keeps the radius;
        // tests/linuxcnc/oword-quirk-position), Y 0 on a lathe.
        "_x" => Some(if m.pos.kx { m.pos.p.r() } else { 0.0 }),
        "_z" => Some(if m.pos.kz { m.pos.p.z } else { 0.0 }),
        "_y" => Some(0.0),
        _ => return Err(Fail { template: &msg::NAMED_NOT_DEFINED, span, args: args![name] }),
    })
}

/// What an o-word line does.
fn oword(
    ex: &mut Exec,
    ctx: &mut Ctx,
    label: &str,
    kw: OKw,
    args: &[Expr],
    span: Span,
    macros: &Macros,
) -> Result<(), Fail> {
    let here = ctx.here;
    let missing =
        |what: &'static str| Fail { template: &msg::OWORD_UNMATCHED, span, args: args![label = shown(label), what] };
    match kw {
        OKw::Sub => {
            // Met in the flow: the definition is skipped and known from now on;
            // met again after a call found it: rs274 refuses it.
            if ex.defined.iter().any(|d| &**d == label) {
                // rs274 writes the name between bars here.
                let label =
                    if label.bytes().all(|c| c.is_ascii_digit()) { format!("o{label}") } else { format!("o|{label}|") };
                return Err(Fail { template: &msg::LCNC_SUB_ILLEGAL, span, args: args![line = here.line, label] });
            }
            let end = next(ctx, label, here, &[OKw::EndSub]).ok_or_else(|| missing("endsub"))?;
            ex.defined.push(label.into());
            // Passing over the endsub, rs274 sets #<_value> as a return without a value does.
            ex.vars.set_named("_value", 0.0);
            ex.vars.set_named("_value_returned", 0.0);
            ex.go(ctx, end.next);
        }
        OKw::EndSub | OKw::Return => {
            let value = match args.first() {
                Some(e) => Some(eval(ex, ctx, e)?.unwrap_or(0.0)),
                None => None,
            };
            if ex.frames.is_empty() {
                return Err(Fail { template: &msg::RETURN_OUTSIDE_SUB, span, args: args![label = shown(label)] });
            }
            ex.return_from(ctx);
            ex.vars.set_named("_value", value.unwrap_or(0.0));
            ex.vars.set_named("_value_returned", if value.is_some() { 1.0 } else { 0.0 });
        }
        OKw::Call => {
            let mut values = [None; 33];
            for (k, e) in args.iter().enumerate().take(30) {
                values[k] = Some(eval(ex, ctx, e)?.unwrap_or(0.0));
            }
            // A subroutine not yet defined is sought after the call.
            let known = ex.defined.iter().any(|d| &**d == label);
            let sub = if known { ctx.sub(label) } else { next(ctx, label, here, &[OKw::Sub]) };
            let Some(sub) = sub else {
                let t = if known { &msg::SUB_NOT_FOUND } else { &msg::LCNC_SUB_SOUGHT };
                return Err(Fail { template: t, span, args: args![label = shown(label), line = here.line] });
            };
            if !known {
                ex.defined.push(label.into());
            }
            if ex.call(ctx, CallKind::Macro, sub.next, 0, span, macros) {
                ex.vars.top().num = values;
            }
        }
        OKw::If => {
            if !truth(eval(ex, ctx, &args[0])?) {
                branch(ex, ctx, label, here, span)?;
            }
        }
        OKw::ElseIf | OKw::Else => {
            // A branch was taken: on after the endif.
            let end = next(ctx, label, here, &[OKw::EndIf]).ok_or_else(|| missing("endif"))?;
            ex.go(ctx, end.next);
        }
        OKw::EndIf | OKw::Do => {}
        OKw::While => {
            let before = ctx.prev_oword(label, here.offset, &[OKw::Do, OKw::While, OKw::EndWhile]);
            if let Some((OKw::Do, d)) = before {
                // The end of a do … while: again from the do while the condition
                // holds, unless a break's flag is set (it is cleared here).
                let again = truth(eval(ex, ctx, &args[0])?) && !ex.broke;
                ex.broke = false;
                if again {
                    ex.go(ctx, d.next);
                }
            } else if !truth(eval(ex, ctx, &args[0])?) {
                let end = next(ctx, label, here, &[OKw::EndWhile]).ok_or_else(|| missing("endwhile"))?;
                ex.go(ctx, end.next);
            }
        }
        OKw::EndWhile => {
            let head = ctx.prev_oword(label, here.offset, &[OKw::While]).ok_or_else(|| missing("while"))?;
            ex.go(ctx, head.1.at);
        }
        OKw::Repeat => {
            // A count left by a return from inside the loop goes on (rs274 keeps it).
            // Each run of the body takes one from the count as it starts.
            if let Some(k) = ex.repeats.iter().rposition(|l| &*l.id == label) {
                let left = ex.repeats[k].left.unwrap_or(0);
                if left == 0 {
                    ex.repeats.remove(k);
                    let end = next(ctx, label, here, &[OKw::EndRepeat]).ok_or_else(|| missing("endrepeat"))?;
                    ex.go(ctx, end.next);
                } else {
                    ex.repeats[k].left = Some(left - 1);
                }
                return Ok(());
            }
            let n = eval(ex, ctx, &args[0])?.unwrap_or(0.0);
            let times = if n >= 1.0 { n.round().min(1e15) as u64 } else { 0 };
            if times == 0 {
                let end = next(ctx, label, here, &[OKw::EndRepeat]).ok_or_else(|| missing("endrepeat"))?;
                ex.go(ctx, end.next);
            } else {
                let body = ctx.next;
                ex.repeats.push(Loop { id: label.into(), head: body, left: Some(times - 1) });
            }
        }
        OKw::EndRepeat => end_repeat(ex, ctx, label, span)?,
        OKw::Break => {
            let head = ctx.prev_oword(label, here.offset, &[OKw::Repeat, OKw::While, OKw::Do]);
            if let Some((OKw::Repeat, r)) = head {
                let block = line_text(ctx.text, here);
                let a = args![line = here.line, block, found = r.at.line];
                return Err(Fail { template: &msg::LCNC_BREAK_NOT_LOOP, span, args: a });
            }
            if ex.continued.as_deref().is_some_and(|c| c != label) {
                // A continue's flag of another loop still set: rs274 does nothing here.
                ex.continued = None;
                return Ok(());
            }
            let end = next(ctx, label, here, &[OKw::EndWhile, OKw::While]).ok_or_else(|| missing("endwhile"))?;
            ex.broke = true;
            ex.go(ctx, end.next);
        }
        OKw::Continue => {
            let end = next(ctx, label, here, &[OKw::EndWhile, OKw::EndRepeat, OKw::While])
                .ok_or_else(|| missing("loop end"))?;
            // Continue is the loop's end reached early.
            ex.continued = Some(label.into());
            ex.go(ctx, end.at);
        }
    }
    Ok(())
}

/// The next o-word line of `label` after `here` with one of `kws`.
fn next(ctx: &mut Ctx, label: &str, here: At, kws: &[OKw]) -> Option<Entry> {
    ctx.next_oword(label, here.offset, kws).map(|(_, e)| e)
}

/// An `if` or `elseif` whose condition failed: on at the next branch whose condition holds, or after the endif.
fn branch(ex: &mut Exec, ctx: &mut Ctx, label: &str, mut from: At, span: Span) -> Result<(), Fail> {
    loop {
        let found = ctx.next_oword(label, from.offset, &[OKw::ElseIf, OKw::Else, OKw::EndIf]);
        let Some((kw, e)) = found else {
            return Err(Fail {
                template: &msg::OWORD_UNMATCHED,
                span,
                args: args![label = shown(label), what = "endif"],
            });
        };
        if kw != OKw::ElseIf {
            ex.go(ctx, e.next);
            return Ok(());
        }
        // Read the elseif's condition where it stands.
        let line_span = line_span(ctx.text, e);
        let src = super::stmt::source(ctx.text, line_span);
        let rules = ctx.rules;
        let parsed = super::stmt::parse(&src, super::expr::Flavor::LinuxCnc, &|c| rules.has_address(c));
        let cond = match parsed {
            Ok(Line { stmt: Stmt::O(_, OKw::ElseIf, args, _), .. }) if !args.is_empty() => args[0].clone(),
            Ok(_) => {
                return Err(Fail {
                    template: &msg::OWORD_UNMATCHED,
                    span,
                    args: args![label = shown(label), what = "elseif"],
                });
            }
            Err(err) => return Err(Fail { template: &msg::MACRO_SYNTAX, span: err.span, args: err.args() }),
        };
        if truth(eval(ex, ctx, &cond)?) {
            ex.go(ctx, e.next);
            return Ok(());
        }
        from = e.at;
    }
}

/// The span of an indexed line (without its line ending).
fn line_span(text: &str, e: Entry) -> Span {
    let line = &text.as_bytes()[e.at.offset..e.next.offset.min(text.len())];
    let len = memchr::memchr2(b'\n', b'\r', line).unwrap_or(line.len());
    Span::new(e.at.offset, e.at.offset + len)
}

fn end_repeat(ex: &mut Exec, ctx: &mut Ctx, label: &str, span: Span) -> Result<(), Fail> {
    let loops = &mut ex.repeats;
    let Some(k) = loops.iter().rposition(|l| &*l.id == label) else {
        return Err(Fail { template: &msg::OWORD_UNMATCHED, span, args: args![label = shown(label), what = "repeat"] });
    };
    loops.truncate(k + 1);
    let l = &mut loops[k];
    let left = l.left.unwrap_or(0);
    if left > 0 {
        l.left = Some(left - 1);
        let body = l.head;
        ex.go(ctx, body);
    } else {
        loops.pop();
    }
    Ok(())
}

/// The text of the line at `at`, as written.
fn line_text(text: &str, at: At) -> String {
    let rest = &text[at.offset.min(text.len())..];
    rest[..rest.find(['\n', '\r']).unwrap_or(rest.len())].to_string()
}

/// An o-word label as written: `o100`, `o<name>`.
fn shown(label: &str) -> String {
    if label.bytes().all(|c| c.is_ascii_digit()) { format!("o{label}") } else { format!("o<{label}>") }
}
