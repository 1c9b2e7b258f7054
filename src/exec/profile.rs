//! The profile cycles' flow (Fanuc 0i and GSK980TDc, two-block forms):
//! `G71 P(ns) Q(nf) …`, `G72 P Q …` and `G73 P Q …` read their contour,
//! the blocks N(ns) … N(nf) after them, and the program goes on after
//! N(nf): the contour is not run in line. `G70 P(ns) Q(nf)` runs the
//! contour — the finishing pass, the part's outline — and goes on after
//! itself (Fanuc 0i-TF operator's manual, "Multiple repetitive cycle
//! (G70–G76)": the blocks between the sequence numbers P and Q specify the
//! finishing shape; GSK980TDc user manual §3.20, the same forms).
//!
//! G71 and G72 rough over the contour (`cycle::rough`), G73 cuts it d
//! times (`cycle::pattern`); after G70's contour the tool returns to the
//! start point in rapid (Fanuc 0i-TF: "the tool returns to the start point
//! A"; GSK980TDc the same), drawn as a rapid of the G70 block.
//! LinuxCNC's G70–G72 read their profile from a subroutine, o(Q), the same
//! way (`linux_profile`; its roughing is `cycle::g7x`).

use super::{CallKind, Ctx, Exec, Flow, Macros};
use crate::args;
use crate::block::Block;
use crate::cycle::g7x::finish::Passes;
use crate::cycle::g7x::{Fail, Job, Step, Words};
use crate::cycle::pattern::Pattern;
use crate::cycle::rough::{MAX_CUTS, Rough};
use crate::message as msg;
use crate::motion::{Move, MoveKind, Point};
use crate::span::Span;

/// What a contour is read for.
#[derive(Clone, Debug, PartialEq)]
pub enum Cycle {
    /// Fanuc's and GSK's G71/G72: roughing over it.
    Rough(Rough),
    /// Fanuc's and GSK's G73: the contour cut d times, shifted.
    Pattern(Pattern),
    /// LinuxCNC's G70: finishing passes over the moves as read, arcs kept.
    LinuxFinish {
        /// D, E and P.
        passes: Passes,
        /// The profile's subroutine, o(q).
        q: u32,
    },
    /// LinuxCNC's G71/G72 (and .1/.2): roughing over the moves as read, arcs kept.
    LinuxRough {
        /// The cycle's words.
        words: Words,
        /// The profile's subroutine, o(q).
        q: u32,
    },
}

/// A stock-removal cycle reading its contour: the cycle, where the tool
/// was, the modal state to go back to, the contour as read, and the cycle
/// block's line and span.
#[derive(Clone, Debug, PartialEq)]
pub struct Capture {
    /// What the contour is read for.
    pub cycle: Cycle,
    /// The start point A (the tool at the cycle block).
    pub start: Point,
    /// The modal state at the cycle block, restored when the contour is read.
    pub modal: Box<crate::state::Modal>,
    /// The end points of the contour's motions, in order (arcs as chords).
    pub points: Vec<Point>,
    /// Whether the contour's first block N(ns) has an X (or U) word and a Z (or W) word:
    /// G71/G72 type II when both (Fanuc 0i); `None` until it is read.
    pub first: Option<(bool, bool)>,
    /// The contour's moves as rs274 reads them, for LinuxCNC's roughing (instead of `points`).
    pub steps: Vec<Step>,
    /// A profile move rs274 refuses (LinuxCNC's roughing), where it is: the profile ends there.
    pub refused: Option<(Fail, Span)>,
    /// The cycle block's line.
    pub line: u32,
    /// The cycle block's span.
    pub span: Span,
}

impl Capture {
    /// A capture for `cycle` from the block being run, the tool where `ctx` has it.
    fn new(cycle: Cycle, ctx: &Ctx, span: Span) -> Capture {
        Capture {
            cycle,
            start: ctx.modal.pos.p,
            modal: Box::new(ctx.modal.clone()),
            points: Vec::new(),
            first: None,
            steps: Vec::new(),
            refused: None,
            line: ctx.here.line,
            span,
        }
    }
}

impl Exec {
    /// Whether the blocks read now are a stock-removal cycle's contour (read, not run).
    pub fn capturing(&self) -> bool {
        self.frames.last().is_some_and(|f| f.capture.is_some())
    }

    /// Whether the contour being read is a LinuxCNC profile read as rs274
    /// reads it, block by block ([`Exec::capture_block`]).
    pub fn capturing_words(&self) -> bool {
        let c = self.frames.last().and_then(|f| f.capture.as_ref());
        c.is_some_and(|c| matches!(c.cycle, Cycle::LinuxRough { .. } | Cycle::LinuxFinish { .. }))
    }

    /// Adds the move of profile block `b` to a LinuxCNC profile being read,
    /// `modal` the state after it (its motion mode, G7 or G8); at most
    /// [`MAX_CUTS`] moves. A move rs274 refuses ends the profile.
    pub fn capture_block(&mut self, b: &Block, modal: &crate::state::Modal) {
        let Some(c) = self.frames.last_mut().and_then(|f| f.capture.as_mut()) else { return };
        if c.refused.is_some() || c.steps.len() >= MAX_CUTS {
            return;
        }
        let at = c.steps.last().map_or(c.start, |s| s.to);
        match crate::cycle::g7x::read::step(b, modal.motion, modal.radius, at) {
            Ok(Some(s)) => c.steps.push(s),
            Ok(None) => {}
            Err(f) => c.refused = Some((f, b.span)),
        }
    }

    /// Notes the axis words of block `b` when it is the contour's first (see [`Capture::first`]).
    pub fn capture_first(&mut self, b: &Block) {
        let Some(c) = self.frames.last_mut().and_then(|f| f.capture.as_mut()) else { return };
        if c.first.is_none() {
            c.first = Some((b.has(b'X') || b.has(b'U'), b.has(b'Z') || b.has(b'W')));
        }
    }

    /// Adds motion `m` to the contour being read; at most [`MAX_CUTS`] points.
    pub fn capture_move(&mut self, m: &Move) {
        let Some(c) = self.frames.last_mut().and_then(|f| f.capture.as_mut()) else { return };
        let points = if m.kind == MoveKind::Arc {
            crate::motion::arc_points(m).into_iter().skip(1).map(|p| Point { x: 2.0 * p[1], z: p[0] }).collect()
        } else {
            vec![m.to]
        };
        for p in points {
            if c.points.len() < MAX_CUTS {
                c.points.push(p);
            }
        }
    }
}

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
        let cycle = match g {
            73 => ctx.modal.pattern_call.map(Cycle::Pattern),
            _ => ctx.modal.rough_call.map(Cycle::Rough),
        };
        let Some(cycle) = cycle.filter(|_| known) else {
            // Not roughed: on after N(nf).
            ex.go(ctx, end.next);
            return Some(Flow::Run);
        };
        // G71–G73: read the contour (its blocks move the tool, not drawn), rough over it, on after N(nf).
        let Some(start) = ctx.sequence(ns, ctx.here.offset) else {
            ctx.diag(&msg::SEQUENCE_NOT_FOUND, p.span, args![n = ns as i64]);
            ex.go(ctx, end.next);
            return Some(Flow::Run);
        };
        let capture = Capture::new(cycle, ctx, block.span);
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
    // After the contour the tool returns to the start point in rapid (when it is known).
    let known = ctx.modal.pos.kx && ctx.modal.pos.kz;
    let back_to = known.then_some((ctx.modal.pos.p, block.span));
    if ex.call(ctx, CallKind::Sub, start.at, 0, block.span, macros) {
        if let Some(f) = ex.frames.last_mut() {
            f.until = Some(nf);
            f.back_to = back_to;
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

/// After a LinuxCNC G70–G72 the interpreter took (`Modal::profile_call`):
/// its profile, subroutine o(Q), is read as a contour (not run in line),
/// and the planner makes it the finishing pass or the roughing; the
/// program goes on after the block. rs274 reads the profile the same way
/// (`convert_g7x` calls `O<q> CALL` and reads the subroutine's moves
/// without running them). `None` when the block is no such cycle.
pub fn linux_profile(ex: &mut Exec, ctx: &mut Ctx, block: &Block, macros: &Macros) -> Option<Flow> {
    let call = ctx.modal.profile_call?;
    let cycle_code = |c: i64| matches!(c, 700 | 710..=712 | 720..=722);
    block.all(b'G').find(|w| cycle_code((w.value() * 10.0).round() as i64))?;
    let label = call.q.to_string();
    let known = ex.defined.iter().any(|d| **d == *label);
    let sub = if known {
        ctx.sub(&label)
    } else {
        ctx.next_oword(&label, ctx.here.offset, &[super::stmt::OKw::Sub]).map(|(_, e)| e)
    };
    let span = block.get(b'Q').map_or(block.span, |w| w.span);
    let Some(sub) = sub else {
        // rs274 seeks the subroutine to the end of the file, and stops there.
        let line = ctx.here.line;
        ctx.diag(&msg::LCNC_SUB_SOUGHT, span, args![label = format!("o<{label}>"), line]);
        return Some(Flow::Abort);
    };
    if !known {
        // Found after the call, as for `call`: met again in the flow it is refused.
        ex.defined.push(label.into());
    }
    let cycle = match call.job {
        Job::Rough(words) => Cycle::LinuxRough { words, q: call.q },
        Job::Finish(passes) => Cycle::LinuxFinish { passes, q: call.q },
    };
    let capture = Capture::new(cycle, ctx, block.span);
    if ex.call(ctx, CallKind::Macro, sub.next, 0, span, macros) {
        if let Some(f) = ex.frames.last_mut() {
            f.capture = Some(Box::new(capture));
        }
    }
    Some(Flow::Run)
}
