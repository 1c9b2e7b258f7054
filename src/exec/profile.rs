//! The profile cycles' flow (Fanuc 0i and GSK980TDc, two-block forms):
//! `G71 P(ns) Q(nf) …`, `G72 P Q …` and `G73 P Q …` read their contour,
//! the blocks N(ns) … N(nf) after them, and the program goes on after
//! N(nf): the contour is not run in line. `G70 P(ns) Q(nf)` runs the
//! contour — the finishing pass, the part's outline — and goes on after
//! itself (Fanuc 0i-TF operator's manual, "Multiple repetitive cycle
//! (G70–G76)": the blocks between the sequence numbers P and Q specify the
//! finishing shape; GSK980TDc user manual §3.20, the same forms).
//!
//! G71 and G72 rough over the contour (`cycle::rough`); G73 is not planned
//! (a not-simulated note); G70's return to its start point is not drawn.
//! LinuxCNC's G70 reads its profile from a subroutine, o(Q), the same way.

use super::{CallKind, Capture, Ctx, Exec, Flow, Macros};
use crate::args;
use crate::block::Block;
use crate::message as msg;

/// After a block ran: a G71–G73 with P and Q goes on after N(Q); a G70
/// with P and Q runs N(P) … N(Q) and comes back. `None` when the block is
/// neither.
pub fn after(ex: &mut Exec, ctx: &mut Ctx, block: &Block, macros: &Macros) -> Option<Flow> {
    let g = block.all(b'G').find_map(|w| w.num.integer().filter(|c| (70..=73).contains(c)))?;
    let (p, q) = (block.get(b'P').copied()?, block.get(b'Q').copied()?);
    let number = |v: f64| (v >= 1.0 && v.fract() == 0.0 && v <= 99_999.0).then_some(v as u32);
    let (Some(ns), Some(nf)) = (number(p.value()), number(q.value())) else {
        ctx.diag(&msg::BAD_SEQUENCE_NUMBER, p.span.cover(q.span), args![value = p.value()]);
        return Some(Flow::Run);
    };
    let Some(end) = ctx.sequence(nf, ctx.here.offset) else {
        ctx.diag(&msg::SEQUENCE_NOT_FOUND, q.span, args![n = nf as i64]);
        return Some(Flow::Run);
    };
    if g != 70 {
        let known = ctx.modal.pos.kx && ctx.modal.pos.kz;
        let Some(rough) = ctx.modal.rough_call.filter(|_| g != 73 && known) else {
            // Not roughed: on after N(nf).
            ex.go(ctx, end.next);
            return Some(Flow::Run);
        };
        // G71/G72: read the contour (its blocks move the tool, not drawn), rough over it, on after N(nf).
        let Some(start) = ctx.sequence(ns, ctx.here.offset) else {
            ctx.diag(&msg::SEQUENCE_NOT_FOUND, p.span, args![n = ns as i64]);
            ex.go(ctx, end.next);
            return Some(Flow::Run);
        };
        let capture = Capture {
            rough: Some(rough),
            start: ctx.modal.pos.p,
            modal: Box::new(ctx.modal.clone()),
            points: Vec::new(),
            line: ctx.here.line,
            span: block.span,
        };
        if ex.call(ctx, CallKind::Sub, start.at, 0, block.span, macros) {
            if let Some(f) = ex.frames.last_mut() {
                f.until = Some(nf);
                f.ret = end.next;
                f.capture = Some(Box::new(capture));
            }
        }
        return Some(Flow::Run);
    }
    let Some(start) = ctx.sequence(ns, ctx.here.offset) else {
        ctx.diag(&msg::SEQUENCE_NOT_FOUND, p.span, args![n = ns as i64]);
        return Some(Flow::Run);
    };
    if ex.call(ctx, CallKind::Sub, start.at, 0, block.span, macros) {
        if let Some(f) = ex.frames.last_mut() {
            f.until = Some(nf);
        }
    }
    Some(Flow::Run)
}

/// After a block of a contour G70 runs: its last block returns.
pub fn contour_end(ex: &mut Exec, ctx: &mut Ctx, block: &Block) -> bool {
    let last = ex.frames.last().and_then(|f| f.until);
    let n = block.n.and_then(|w| w.num.integer());
    if last.is_none() || n.map(|n| n as u32) != last {
        return false;
    }
    // The frame's capture, if any, goes to the planner (`Exec::captured`).
    ex.return_from(ctx);
    true
}

/// After a LinuxCNC G70 the interpreter took (`Modal::finish_q`): its
/// profile, subroutine o(Q), is read as a contour (not run in line) and the
/// planner makes it one finishing pass; the program goes on after the G70.
/// rs274 reads the profile the same way: its moves are G70's, the first a
/// traverse. `None` when the block is no such G70.
pub fn linux_finish(ex: &mut Exec, ctx: &mut Ctx, block: &Block, macros: &Macros) -> Option<Flow> {
    let q = ctx.modal.finish_q?;
    block.all(b'G').find(|w| w.num.integer() == Some(70))?;
    let label = q.to_string();
    let known = ex.defined.iter().any(|d| **d == *label);
    let sub = if known {
        ctx.sub(&label)
    } else {
        ctx.next_oword(&label, ctx.here.offset, &[super::stmt::OKw::Sub]).map(|(_, e)| e)
    };
    let span = block.get(b'Q').map_or(block.span, |w| w.span);
    let Some(sub) = sub else {
        ctx.diag(&msg::SUB_NOT_FOUND, span, args![label = format!("o{label}")]);
        return Some(Flow::Run);
    };
    if !known {
        // Found after the call, as for `call`: met again in the flow it is refused.
        ex.defined.push(label.into());
    }
    let capture = Capture {
        rough: None,
        start: ctx.modal.pos.p,
        modal: Box::new(ctx.modal.clone()),
        points: Vec::new(),
        line: ctx.here.line,
        span: block.span,
    };
    if ex.call(ctx, CallKind::Macro, sub.next, 0, span, macros) {
        if let Some(f) = ex.frames.last_mut() {
            f.capture = Some(Box::new(capture));
        }
    }
    Some(Flow::Run)
}
