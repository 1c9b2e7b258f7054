//! Grouping of block-by-block thread cuts (G32, Renhe G32/G33) into threads.
//!
//! The textbook pattern cuts each pass with four blocks — infeed (G00 X),
//! cut (G32), retract (G00 X), return (G00 Z) — and repeats it deeper. Each
//! run of G32 blocks (a continuous thread) is one [`Chain`]; consecutive
//! chains that cut the same helix become one [`Thread`] whose passes carry
//! the lines of their four blocks.

use crate::diagnostic::Code;
use crate::interp::{Interp, Target};
use crate::motion::MoveKind;
use crate::motion::Point;
use crate::num::{EPS, close as near};
use crate::settings::P;
use crate::span::Span;
use crate::thread::{Axis, CrestSource, Infeed, Pass, Role, Source, Thread, ThreadKind};

/// One straight piece of a continuous thread.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    /// Start of the synchronised cut.
    pub from: Point,
    /// End of the synchronised cut (run-out excluded).
    pub to: Point,
    /// End of the run-out, when the block has one.
    pub runout_to: Option<Point>,
    /// Shape of this piece.
    pub kind: ThreadKind,
    /// Long axis of this piece.
    pub long: Axis,
}

impl Seg {
    /// Travel along the long axis (radial for X).
    pub fn long_travel(&self) -> f64 {
        match self.long {
            Axis::Z => self.to.z - self.from.z,
            Axis::X => (self.to.x - self.from.x) / 2.0,
        }
    }

    /// Long-axis coordinate of a point (radius for X).
    pub fn long_of(&self, p: Point) -> f64 {
        match self.long {
            Axis::Z => p.z,
            Axis::X => p.r(),
        }
    }

    /// Short-axis coordinate of a point (radius for X).
    pub fn short_of(&self, p: Point) -> f64 {
        match self.long {
            Axis::Z => p.r(),
            Axis::X => p.z,
        }
    }
}

/// A continuous thread cut: consecutive thread blocks without a wait for the one-rev signal.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// Command family.
    pub source: Source,
    /// Lead of the first block.
    pub lead: f64,
    /// The pieces.
    pub segs: Vec<Seg>,
    /// Start angle in degrees (the first block's Q).
    pub angle: f64,
    /// Lines of the blocks (the infeed, retract and return are added by the grouper).
    pub lines: Vec<u32>,
    /// Direction of the last X motion before the cut (−1 inward, +1 outward, 0 unknown).
    pub approach: f64,
    /// Span of the first block.
    pub span: Span,
    /// Index in the plan's moves of the chain's first motion.
    pub first_move: usize,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum After {
    #[default]
    Nothing,
    Retract,
    Return,
}

/// Grouping state kept by the interpreter.
#[derive(Clone, Debug, Default)]
pub struct Grouper {
    /// The continuous cut in progress.
    pub chain: Option<Chain>,
    cuts: Vec<Chain>,
    after: After,
    /// Line of the last rapid that moved X (the infeed of a Z thread) and that moved Z (of a face thread).
    infeed_line: [Option<u32>; 2],
}

/// Notes a rapid: after a cut the first rapid on its short axis is its
/// retract and the next rapid on its long axis its return; otherwise the
/// last rapid on a short axis is the next cut's infeed (X for a thread along
/// Z, Z for a face thread).
pub fn after_rapid(it: &mut Interp, t: &Target, line: u32) {
    let g = &mut it.grouper;
    let mut consumed = false;
    let long_z = g.cuts.last().is_none_or(|c| c.segs[0].long == Axis::Z);
    let (on_short, on_long) = if long_z { (t.has_x, t.has_z) } else { (t.has_z, t.has_x) };
    match g.after {
        After::Retract if on_short || on_long => {
            if let Some(last) = g.cuts.last_mut() {
                last.lines.push(line);
            }
            g.after = if on_short && !on_long { After::Return } else { After::Nothing };
            consumed = true;
        }
        After::Return if on_long && !on_short => {
            if let Some(last) = g.cuts.last_mut() {
                last.lines.push(line);
            }
            g.after = After::Nothing;
            consumed = true;
        }
        After::Return => g.after = After::Nothing,
        _ => {}
    }
    if !consumed {
        if t.has_x {
            g.infeed_line[0] = Some(line);
        }
        if t.has_z {
            g.infeed_line[1] = Some(line);
        }
    }
}

/// Adds a finished chain: it joins the current thread or starts a new one.
pub fn add_chain(it: &mut Interp, mut chain: Chain) {
    // Block-by-block passes own their infeed, retract and return; a G92 block is all of its pass.
    let blockwise = chain.source != Source::G92;
    let short = if chain.segs[0].long == Axis::Z { 0 } else { 1 };
    let infeed = it.grouper.infeed_line[short];
    it.grouper.infeed_line = [None, None];
    if let (Some(l), true) = (infeed, blockwise) {
        chain.lines.insert(0, l);
    }
    let max_infeed = it.s.get(P::GroupMaxInfeed);
    if let Some(last) = it.grouper.cuts.last() {
        if !same_thread(last, &chain, max_infeed) {
            close(it);
        }
    }
    it.grouper.cuts.push(chain);
    it.grouper.after = if blockwise { After::Retract } else { After::Nothing };
}

/// Emits one block-by-block thread piece — the synchronised cut from
/// `from` to `to`, then the run-out to `runout_to` — moves the tool there,
/// and adds the piece to the continuous thread being cut (or starts one).
#[allow(clippy::too_many_arguments)]
pub fn cut_piece(it: &mut Interp, source: Source, lead: f64, angle: f64, seg: Seg, end: Point, line: u32, span: Span) {
    let first_move = it.moves.len();
    it.emit(MoveKind::Thread, seg.from, seg.to, line, None, span);
    if let Some(o) = seg.runout_to {
        it.emit(MoveKind::Runout, seg.to, o, line, None, span);
    }
    let approach = it.last_x.0;
    it.arrive(seg.runout_to.unwrap_or(end), true, true, line);
    match &mut it.grouper.chain {
        Some(c) => {
            c.segs.push(seg);
            c.lines.push(line);
        }
        None => {
            it.grouper.chain =
                Some(Chain { source, lead, segs: vec![seg], angle, lines: vec![line], approach, span, first_move });
        }
    }
}

/// Whether `b` cuts the same helix as `a` (one more pass of it).
fn same_thread(a: &Chain, b: &Chain, max_infeed: f64) -> bool {
    if a.source != b.source || !near(a.lead, b.lead) || a.segs.len() != b.segs.len() {
        return false;
    }
    for (x, y) in a.segs.iter().zip(&b.segs) {
        if x.kind != y.kind || x.long != y.long || x.long_travel().signum() != y.long_travel().signum() {
            return false;
        }
    }
    let (x, y) = (&a.segs[0], &b.segs[0]);
    let (a0, a1) = minmax(x.long_of(x.from), x.long_of(x.to));
    let (b0, b1) = minmax(y.long_of(y.from), y.long_of(y.to));
    let overlap = a1.min(b1) - a0.max(b0);
    let shorter = (a1 - a0).min(b1 - b0);
    if overlap < 0.5 * shorter - EPS {
        return false;
    }
    (x.short_of(x.from) - y.short_of(y.from)).abs() <= max_infeed * a.lead + EPS
}

fn minmax(a: f64, b: f64) -> (f64, f64) {
    if a <= b { (a, b) } else { (b, a) }
}

/// Closes the thread being grouped, if any, and adds it to the plan.
pub fn close(it: &mut Interp) {
    let cuts = std::mem::take(&mut it.grouper.cuts);
    it.grouper.after = After::Nothing;
    if cuts.is_empty() {
        return;
    }
    let angle = match it.dialect {
        crate::dialect::Dialect::Gsk980tdc => it.s.get(P::No058),
        crate::dialect::Dialect::Fanuc0i => it.s.get(P::Fanuc5143),
        crate::dialect::Dialect::Renhe => 60.0,
    };
    let limit = it.s.int(P::LimitStarts).max(1) as usize;
    let thread = build(&cuts, angle);
    if thread.starts as usize > limit {
        // The chain that brought the first start over the limit.
        let mut seen: Vec<f64> = Vec::new();
        for c in &cuts {
            if !seen.iter().any(|a| (a - c.angle).abs() < 1e-6) {
                seen.push(c.angle);
                if seen.len() > limit {
                    it.diag(
                        Code::TooManyStarts,
                        c.span,
                        format!(
                            "{} starts (distinct start angles Q): at most {limit} (setting limits.starts)",
                            thread.starts
                        ),
                    );
                    break;
                }
            }
        }
    }
    it.threads.push(thread);
}

/// Builds a thread from its chains: starts from distinct start angles, passes in order.
fn build(cuts: &[Chain], tool_angle: f64) -> Thread {
    let mut angles: Vec<f64> = Vec::new();
    for c in cuts {
        if !angles.iter().any(|a| (a - c.angle).abs() < 1e-6) {
            angles.push(c.angle);
        }
    }
    angles.sort_by(f64::total_cmp);
    let mut counts = vec![0u32; angles.len()];
    let mut passes = Vec::with_capacity(cuts.len());
    for c in cuts {
        let si = angles.iter().position(|a| (a - c.angle).abs() < 1e-6).unwrap_or(0);
        counts[si] += 1;
        let first = c.segs[0];
        let last = *c.segs.last().unwrap_or(&first);
        let mut segments = Vec::new();
        if c.segs.len() > 1 {
            segments.push(first.from);
            for (i, s) in c.segs.iter().enumerate() {
                segments.push(s.to);
                if let (Some(r), true) = (s.runout_to, i + 1 < c.segs.len()) {
                    segments.push(r);
                }
            }
        }
        let mut lines = c.lines.clone();
        lines.sort_unstable();
        lines.dedup();
        passes.push(Pass {
            start: si as u32 + 1,
            index: counts[si],
            from: first.from,
            to: last.to,
            depth: 0.0,
            infeed: 0.0,
            role: Role::Rough,
            lines,
            segments,
            runout_to: last.runout_to,
            screw_in_from: None,
            shift: 0.0,
            angle: c.angle,
            area: None,
        });
    }
    let c0 = &cuts[0];
    let main =
        *c0.segs.iter().max_by(|a, b| a.long_travel().abs().total_cmp(&b.long_travel().abs())).unwrap_or(&c0.segs[0]);
    let depth_dir = depth_direction(cuts, &main);
    let lead = c0.lead;
    let starts = angles.len() as u32;
    let line = cuts.iter().flat_map(|c| c.lines.iter().copied()).min().unwrap_or(0);
    let end_line = cuts.iter().flat_map(|c| c.lines.iter().copied()).max().unwrap_or(0);
    let p0 = &passes[0];
    Thread {
        line,
        end_line,
        source: c0.source,
        kind: main.kind,
        long_axis: main.long,
        lead,
        pitch: lead / starts as f64,
        starts,
        internal: main.long == Axis::Z && depth_dir > 0.0,
        infeed: Infeed::Programmed,
        tool_angle,
        crest: 0.0,
        crest_source: CrestSource::Assumed,
        height: 0.0,
        taper: match main.long {
            Axis::Z => p0.from.r() - p0.to.r(),
            Axis::X => 0.0,
        },
        passes,
        depth_dir,
        first_move: cuts.iter().map(|c| c.first_move).min().unwrap_or(0),
    }
}

/// Which way the depth grows along the short axis: from the passes'
/// progression, else from the approach of the first cut, else from its
/// run-out (which leaves the work), else outward-in (external thread).
fn depth_direction(cuts: &[Chain], main: &Seg) -> f64 {
    let s0 = main.short_of(cuts[0].segs[0].from);
    for c in &cuts[1..] {
        let d = main.short_of(c.segs[0].from) - s0;
        if d.abs() > EPS {
            return d.signum();
        }
    }
    if main.long == Axis::Z && cuts[0].approach != 0.0 {
        return cuts[0].approach;
    }
    if let Some(r) = cuts[0].segs.last().and_then(|s| s.runout_to.map(|r| (s, r))) {
        let d = main.short_of(r.1) - main.short_of(r.0.to);
        if d.abs() > EPS {
            return -d.signum();
        }
    }
    -1.0
}
