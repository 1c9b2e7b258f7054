//! Fanuc custom macro B and subprograms: `#i = e`, `IF … GOTO`, `IF …
//! THEN`, `WHILE … DO m`, `END m`, `GOTO n`, `M98 P… L…`, `M99 [P]`, `G65
//! P… L… <arguments>` (argument specification I). GSK980TDc reads the same
//! forms where its manual has them (its rules say which).

use super::eval::{Fail, Val};
use super::index::At;
use super::stmt::{Assign, Line, Stmt};
use super::{CallKind, Ctx, Exec, Flow, Loop, Macros, Vals, eval, fill, truth};
use crate::args;
use crate::block::Block;
use crate::message as msg;
use crate::settings::P;
use crate::span::Span;

/// Runs a parsed macro line.
pub(super) fn statement(
    ex: &mut Exec,
    ctx: &mut Ctx,
    block: &mut Block,
    line: &Line,
    macros: &Macros,
) -> Result<Flow, Fail> {
    match &line.stmt {
        Stmt::Words(words, _) if macros.h_codes && words.iter().any(is_g65) => {
            let ops: Vec<_> = words.iter().map(operand).collect();
            let g = words.iter().find(|w| is_g65(w)).map_or(block.span, |w| w.span);
            Ok(super::gsk::run_or_alarm(ex, ctx, block, &ops, g))
        }
        Stmt::Words(words, _) => {
            if !fill(ex, ctx, block, line, words) {
                block.has_error = true;
                return Ok(Flow::Run);
            }
            Ok(g65(ex, ctx, block, macros))
        }
        Stmt::Assign(a) => assign(ex, ctx, a).map(|()| Flow::Skip),
        Stmt::IfThen(c, a) => {
            if truth(eval(ex, ctx, c)?) {
                assign(ex, ctx, a)?;
            }
            Ok(Flow::Skip)
        }
        Stmt::IfGoto(c, target, span) => {
            if truth(eval(ex, ctx, c)?) {
                goto(ex, ctx, target, *span)?;
            }
            Ok(Flow::Skip)
        }
        Stmt::Goto(target, span) => goto(ex, ctx, target, *span).map(|()| Flow::Skip),
        Stmt::While(c, m, span) => {
            check_loop_id(*m, *span, macros)?;
            if truth(eval(ex, ctx, c)?) {
                open_loop(ex, ctx, *m);
            } else {
                close_loop(ex, ctx, *m, *span)?;
            }
            Ok(Flow::Skip)
        }
        Stmt::Do(m, span) => {
            check_loop_id(*m, *span, macros)?;
            open_loop(ex, ctx, *m);
            Ok(Flow::Skip)
        }
        Stmt::End(m, span) => {
            let id = m.to_string();
            let loops = ex.loops();
            let Some(k) = loops.iter().rposition(|l| *l.id == *id) else {
                return Err(Fail { template: &msg::END_WITHOUT_DO, span: *span, args: args![m = *m] });
            };
            let head = loops[k].head;
            loops.truncate(k + 1);
            ex.go(ctx, head);
            Ok(Flow::Skip)
        }
        Stmt::O(..) => Ok(Flow::Skip),
    }
}

/// Whether a macro line's word is `G65`.
fn is_g65(w: &super::stmt::MWord) -> bool {
    w.letter == b'G' && matches!(&w.value, super::stmt::Value::Num(n) if n.integer() == Some(65))
}

/// A macro line's word as an operand of GSK's `G65 H`.
fn operand(w: &super::stmt::MWord) -> super::gsk::Operand {
    let value = match &w.value {
        super::stmt::Value::Num(n) => super::expr::Expr::Num(n.value),
        super::stmt::Value::Expr(e) => e.clone(),
    };
    super::gsk::Operand { letter: w.letter, value, span: w.span }
}

fn check_loop_id(m: u8, span: Span, macros: &Macros) -> Result<(), Fail> {
    if m == 0 || m > macros.max_loop {
        return Err(Fail { template: &msg::LOOP_NUMBER, span, args: args![m, max = macros.max_loop] });
    }
    Ok(())
}

/// A WHILE whose condition holds, or a DO: the loop is open (once, however often its head runs).
fn open_loop(ex: &mut Exec, ctx: &mut Ctx, m: u8) {
    let head = ctx.here;
    let loops = ex.loops();
    if let Some(k) = loops.iter().rposition(|l| l.head == head) {
        loops.truncate(k + 1);
    } else {
        loops.push(Loop { id: m.to_string().into_boxed_str(), head, left: None });
    }
}

/// A WHILE whose condition fails: on after its END.
fn close_loop(ex: &mut Exec, ctx: &mut Ctx, m: u8, span: Span) -> Result<(), Fail> {
    let head = ctx.here;
    let loops = ex.loops();
    if let Some(k) = loops.iter().rposition(|l| l.head == head) {
        loops.truncate(k);
    }
    let Some(end) = ctx.end_of_loop(m, head.offset) else {
        return Err(Fail { template: &msg::LOOP_WITHOUT_END, span, args: args![m] });
    };
    ex.go(ctx, end.next);
    Ok(())
}

/// Jumps to the sequence number `target` gives, in the program being run.
pub(super) fn goto(ex: &mut Exec, ctx: &mut Ctx, target: &super::expr::Expr, span: Span) -> Result<(), Fail> {
    let v = eval(ex, ctx, target)?.unwrap_or(f64::NAN);
    let n = v.round();
    if !(1.0..=99999.0).contains(&n) || (v - n).abs() > 1e-6 {
        return Err(Fail { template: &msg::BAD_SEQUENCE_NUMBER, span, args: args![value = v] });
    }
    let Some(e) = ctx.sequence(n as u32, ctx.here.offset) else {
        return Err(Fail { template: &msg::SEQUENCE_NOT_FOUND, span, args: args![n = n as i64] });
    };
    ex.go(ctx, e.at);
    Ok(())
}

fn assign(ex: &mut Exec, ctx: &mut Ctx, a: &Assign) -> Result<(), Fail> {
    let v = eval(ex, ctx, &a.value)?;
    let super::expr::Expr::Var(n, span) = &a.target else {
        return Err(Fail {
            template: &msg::MACRO_SYNTAX,
            span: a.span,
            args: args![found = "#<", expected = &msg::X_VAR],
        });
    };
    store(ex, ctx, n, v, *span, a.span)
}

/// Writes `v` to the variable whose number `n` gives (written at `span`,
/// in the statement at `whole`).
pub(super) fn store(
    ex: &mut Exec,
    ctx: &mut Ctx,
    n: &super::expr::Expr,
    v: Val,
    span: Span,
    whole: Span,
) -> Result<(), Fail> {
    // A vacant number is 0 here as in arithmetic: #0, which cannot be written.
    let n = eval(ex, ctx, n)?.unwrap_or(0.0);
    if n.fract() != 0.0 || !n.is_finite() {
        return Err(Fail { template: &msg::BAD_VARIABLE_NUMBER, span, args: args![value = n] });
    }
    let n = n as i64;
    match n {
        1..=33 => ex.vars.set_local(n as usize, v),
        100..=199 | 500..=999 => ex.vars.set_common(n as u32, v),
        3000 => {
            // The program raises its own alarm: the controller stops here.
            let value = v.unwrap_or(0.0);
            return Err(Fail { template: &msg::MACRO_ALARM, span: whole, args: args![value] });
        }
        _ => {
            let title = crate::message::Arg::lit(ctx.rules.title());
            return Err(Fail { template: &msg::VARIABLE_NOT_WRITABLE, span, args: args![n, controller = title] });
        }
    }
    Ok(())
}

/// Reads `#n`: local, common, or the system variables a threading program reads.
pub fn read(env: &mut Vals, n: i64, span: Span) -> Result<Val, Fail> {
    let m = env.modal;
    Ok(match n {
        0 => None,
        1..=33 => env.vars.local(n as usize),
        100..=199 | 500..=999 => env.vars.common(n as u32),
        // Modal information of the block before (group 1 motion, 3 distance, 6 units).
        4001 => m.motion_code.map(|c| c as f64 / 10.0),
        4003 => Some(if m.incremental { 91.0 } else { 90.0 }),
        4006 => Some(if m.inch { 20.0 } else { 21.0 }),
        4109 => m.feed,
        4119 => m.spindle,
        // End point of the block before and current position: X (diameter), Z.
        5001 | 5041 => Some(m.pos.p.x),
        5002 | 5042 => Some(m.pos.p.z),
        1000.. => {
            let supported = "#4001 #4003 #4006 #4109 #4119 #5001 #5002 #5041 #5042";
            return Err(Fail { template: &msg::SYSTEM_VARIABLE, span, args: args![n, supported] });
        }
        _ => {
            let title = crate::message::Arg::lit(env.title);
            return Err(Fail { template: &msg::VARIABLE_OUT_OF_RANGE, span, args: args![n, controller = title] });
        }
    })
}

/// Argument specification I: the address of each local variable #1–#26.
const ARGS_I: &[(u8, usize)] = &[
    (b'A', 1),
    (b'B', 2),
    (b'C', 3),
    (b'I', 4),
    (b'J', 5),
    (b'K', 6),
    (b'D', 7),
    (b'E', 8),
    (b'F', 9),
    (b'H', 11),
    (b'M', 13),
    (b'Q', 17),
    (b'R', 18),
    (b'S', 19),
    (b'T', 20),
    (b'U', 21),
    (b'V', 22),
    (b'W', 23),
    (b'X', 24),
    (b'Y', 25),
    (b'Z', 26),
];

/// `G65 P… L… <arguments>`: a macro call with a new level of locals;
/// `G66 P… L… <arguments>`: the same call made after each later block
/// that moves an axis, until `G67` (which cancels it).
pub fn g65(ex: &mut Exec, ctx: &mut Ctx, block: &mut Block, macros: &Macros) -> Flow {
    if block.has_error || !macros.macro_calls {
        return Flow::Run;
    }
    if block.all(b'G').any(|w| w.num.integer() == Some(67)) {
        ex.modal_call = None;
    }
    let Some(g) = block.all(b'G').find(|w| matches!(w.num.integer(), Some(65 | 66))).copied() else {
        return Flow::Run;
    };
    let Some(p) = block.get(b'P').copied() else {
        ctx.diag(&msg::CALL_NEEDS_P, g.span, args![word = g]);
        return Flow::Skip;
    };
    let count = block.get(b'L').map_or(1.0, |l| l.value());
    let count = if count >= 1.0 && count.fract() == 0.0 { count as u32 } else { 1 };
    let mut locals = [None; 33];
    for &(letter, slot) in ARGS_I {
        if let Some(w) = block.get(letter) {
            locals[slot - 1] = Some(w.value());
        }
    }
    if g.num.integer() == Some(66) {
        let Some(n) = program_number(ctx, p.value(), p.span) else { return Flow::Skip };
        let level = macro_level(ex);
        ex.modal_call =
            Some(Box::new(super::ModalCall { program: n, span: p.span, count, args: Box::new(locals), level }));
        // The block's other G words (G20 …) still run; its other words were the arguments.
        block.retain_words(|w| w.letter == b'G' && w.num.integer() != Some(66));
        return if block.words().is_empty() { Flow::Skip } else { Flow::Run };
    }
    let Some(body) = program(ctx, p.value(), p.span) else { return Flow::Skip };
    enter_macro(ex, ctx, body, count, &locals, g.span, macros);
    Flow::Skip
}

/// Calls a macro at `body` with `locals` as its arguments, `count` times.
fn enter_macro(ex: &mut Exec, ctx: &mut Ctx, body: At, count: u32, locals: &Args, span: Span, macros: &Macros) {
    if ex.call(ctx, CallKind::Macro, body, count - 1, span, macros) {
        ex.vars.top().num = *locals;
        if let Some(f) = ex.frames.last_mut() {
            f.args = Some(Box::new(*locals));
        }
    }
}

/// The arguments of a macro call, #1–#33.
type Args = [Option<f64>; 33];

/// How many macro calls are active.
fn macro_level(ex: &Exec) -> usize {
    ex.frames.iter().filter(|f| f.kind == CallKind::Macro).count()
}

/// After a block ran with a `G66` call in force: when it moved an axis,
/// the macro is called (true). Blocks of the macro itself, and blocks
/// that name an axis without moving it (G04 dwell, G10, G50), do not call.
pub fn g66_call(ex: &mut Exec, ctx: &mut Ctx, block: &Block, macros: &Macros) -> bool {
    let Some(m) = ex.modal_call.as_deref().cloned() else { return false };
    let moves = block.words().iter().any(|w| matches!(w.letter, b'X' | b'Z' | b'U' | b'W' | b'Y' | b'C'));
    let not_a_move = block.all(b'G').any(|w| matches!(w.num.integer(), Some(4 | 10 | 50 | 65 | 66)));
    if block.has_error || !moves || not_a_move || macro_level(ex) != m.level {
        return false;
    }
    let Some(body) = program(ctx, m.program as f64, m.span) else {
        ex.modal_call = None;
        return false;
    };
    enter_macro(ex, ctx, body, m.count, &m.args, m.span, macros);
    true
}

/// A program number `P`; `None` after an alarm.
fn program_number(ctx: &mut Ctx, p: f64, span: Span) -> Option<u32> {
    let n = p.round();
    if !(1.0..=99_999_999.0).contains(&n) || n != p {
        ctx.diag(&msg::BAD_PROGRAM_NUMBER, span, args![value = p]);
        return None;
    }
    Some(n as u32)
}

/// The body of program `O(p)`; `None` after an alarm.
fn program(ctx: &mut Ctx, p: f64, span: Span) -> Option<At> {
    let n = program_number(ctx, p, span)? as f64;
    match ctx.program(n as u32) {
        Some(e) => Some(e.next),
        None => {
            ctx.diag(&msg::PROGRAM_NOT_FOUND, span, args![n = n as i64, setting = ""]);
            None
        }
    }
}

/// `M98` and `M99` after the block's other words ran.
pub fn m98_m99(ex: &mut Exec, ctx: &mut Ctx, block: &Block, macros: &Macros) -> Flow {
    if block.has_error {
        return Flow::Run;
    }
    for m in block.all(b'M') {
        match m.num.integer() {
            Some(98) => {
                let Some(p) = block.get(b'P') else {
                    ctx.diag(&msg::CALL_NEEDS_P, m.span, args![word = *m]);
                    return Flow::Run;
                };
                // M98 P□□□□○○○○: more than four digits pack the count before the program number.
                let v = p.value().round();
                let (count, prog) = if v >= 10_000.0 { ((v / 10_000.0).trunc(), v % 10_000.0) } else { (1.0, v) };
                let count = block.get(b'L').map_or(count, |l| l.value().round());
                if count < 1.0 {
                    return Flow::Run;
                }
                let Some(body) = program(ctx, prog, p.span) else { return Flow::Run };
                ex.call(ctx, CallKind::Sub, body, count as u32 - 1, m.span, macros);
                return Flow::Run;
            }
            Some(99) => return m99(ex, ctx, block, m.span),
            _ => {}
        }
    }
    Flow::Run
}

fn m99(ex: &mut Exec, ctx: &mut Ctx, block: &Block, span: Span) -> Flow {
    let Some(top) = ex.frames.last_mut() else {
        // M99 in the main program: it starts again from its top.
        ex.main_runs += 1;
        let runs = ctx.settings.int(P::MainRepeats).max(1) as u32;
        if ex.main_runs >= runs {
            ctx.diag(&msg::MAIN_REPEATS, span, args![runs, setting = "program.main_repeats"]);
            return Flow::Stop;
        }
        let main = ex.main.unwrap_or(super::index::At { offset: 0, line: 1 });
        ex.loops.clear();
        ex.go(ctx, main);
        return Flow::Run;
    };
    if top.repeats > 0 {
        top.repeats -= 1;
        top.loops.clear();
        let body = top.body;
        if let Some(args) = top.args.clone() {
            ex.vars.top().num = *args;
        }
        ex.go(ctx, body);
        return Flow::Run;
    }
    let Some(f) = ex.return_from(ctx) else { return Flow::Run };
    if let Some(p) = block.get(b'P') {
        // M99 Pn: back to sequence number n of the caller.
        let n = p.value().round();
        match ctx.sequence(n as u32, f.ret.offset) {
            Some(e) => ex.go(ctx, e.at),
            None => ctx.diag(&msg::SEQUENCE_NOT_FOUND, p.span, args![n = n as i64]),
        }
    }
    Flow::Run
}
