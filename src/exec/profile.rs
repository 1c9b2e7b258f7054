//! The profile cycles' flow (Fanuc 0i and GSK980TDc, two-block forms):
//! `G71 P(ns) Q(nf) …`, `G72 P Q …` and `G73 P Q …` read their contour,
//! the blocks N(ns) … N(nf) after them, and the program goes on after
//! N(nf): the contour is not run in line. `G70 P(ns) Q(nf)` runs the
//! contour — the finishing pass, the part's outline — and goes on after
//! itself (Fanuc 0i-TF operator's manual, "Multiple repetitive cycle
//! (G70–G76)": the blocks between the sequence numbers P and Q specify the
//! finishing shape; GSK980TDc user manual §3.20, the same forms).
//!
//! The roughing passes of G71–G73 are not planned (their blocks get a
//! not-simulated note); G70's return to its start point is not drawn.

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
            rough,
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
    if let Some(c) = ex.return_from(ctx).and_then(|f| f.capture) {
        ex.captured = Some(c);
    }
    true
}
