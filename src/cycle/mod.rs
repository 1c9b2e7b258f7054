//! Canned cycles: the turning cycles G90/G94 and the threading cycles
//! G92, G76 and G78, planned pass by pass.
//!
//! The threading cycles share one planner: a [`Geometry`] (start point A,
//! the root line of the finished thread, which side is outside, run-out and
//! screw-in), a depth [`schedule`], the axial [`infeed`] shift and the
//! [`runout`] rules. Each cycle module only reads its words and parameters.

pub mod g76;
pub mod g78;
pub mod g92;
pub mod infeed;
pub mod runout;
pub mod schedule;

use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::dialect::Dialect;
use crate::g32::{classify, read_lead, split_runout};
use crate::gcode::G;
use crate::interp::Interp;
use crate::motion::{MoveKind, Point};
use crate::num::{EPS, fmt};
use crate::settings::P;
use crate::span::Span;
use crate::thread::{Axis, CrestSource, Infeed, Pass, Source, Thread, ThreadKind};

/// State the cycles keep between blocks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CycleState {
    /// The last G78 first block.
    pub g78: Option<g78::First>,
    /// The last G76 first block.
    pub g76: Option<g76::First>,
    /// G92 modal values for continuation blocks.
    pub g92: Option<g92::Modal>,
}

/// G76/G78: the first block (no X/Z/U/W) stores its words, the second plans the thread.
pub fn two_block(it: &mut Interp, b: &Block, g: G, w: Word) {
    let second = b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W');
    match (g, second) {
        (G::G78, false) => g78::first(it, b),
        (G::G78, true) => g78::second(it, b, w),
        (G::G76, false) => g76::first(it, b),
        (G::G76, true) => g76::second(it, b, w),
        _ => {}
    }
}

/// Reads a cycle depth word (P(k), Q(Δd), Q(Δdmin)) by the dialect's unit
/// rule: Fanuc integers in least input increments; GSK per NO182.7 (0:
/// increments, a decimal point changes nothing; 1: mm).
pub fn depth_word(it: &mut Interp, w: &Word, what: &str) -> Option<f64> {
    let inc = it.s.length_increment(it.inch);
    match it.dialect {
        Dialect::Fanuc0i => {
            if w.num.has_point {
                it.diag(
                    Code::DecimalPointNotAllowed,
                    w.span,
                    format!(
                        "{}: {what} is an integer in least input increments ({} per unit)",
                        w.display(),
                        fmt(1.0 / inc)
                    ),
                );
                return None;
            }
            Some(w.value() * inc)
        }
        _ => {
            if it.s.flag(P::No182_7) {
                Some(w.value())
            } else {
                if w.num.has_point {
                    it.diag(
                        Code::DecimalPointIgnored,
                        w.span,
                        format!(
                            "{}: with NO182.7 = 0 {what} is in least input increments whatever the decimal point, so this is {} {}",
                            w.display(),
                            fmt(w.value() * inc),
                            if it.inch { "in" } else { "mm" }
                        ),
                    );
                }
                Some(w.value() * inc)
            }
        }
    }
}

/// What the second block of G76 and G78 always gives: the lead, the thread
/// height P(k) and the first depth Q(Δd), each checked; `None` after an
/// alarm. `what` names the cycle in messages.
pub fn height_and_first_depth(it: &mut Interp, b: &Block, g: &Word, what: &str) -> Option<(f64, f64, f64)> {
    let lead = read_lead(it, b, what)?;
    let Some(pk) = b.get(b'P').copied() else {
        it.diag(Code::MissingThreadHeight, g.span, format!("{what} needs the thread height P(k)"));
        return None;
    };
    let Some(qd) = b.get(b'Q').copied() else {
        it.diag(Code::MissingFirstDepth, g.span, format!("{what} needs the first cut depth Q(Δd)"));
        return None;
    };
    let k = depth_word(it, &pk, "P(k)")?;
    let dd = depth_word(it, &qd, "Q(Δd)")?;
    let inc = it.s.length_increment(it.inch);
    let ok = in_range(it, &pk, k, inc, 99999.999, "thread height k")
        && in_range(it, &qd, dd, inc, 99999.999, "first depth Δd");
    ok.then_some((lead, k, dd))
}

/// Reads the first block's Q(Δdmin) and R(d) (G76, G78) into `dmin` and
/// `d` when written (they keep their value otherwise); false after an alarm.
pub fn min_cut_and_allowance(it: &mut Interp, b: &Block, dmin: &mut Option<f64>, d: &mut Option<f64>) -> bool {
    if let Some(w) = b.get(b'Q').copied() {
        let Some(v) = depth_word(it, &w, "Q(Δdmin)") else { return false };
        if !in_range(it, &w, v, 0.0, 99.9999, "Δdmin") {
            return false;
        }
        *dmin = Some(v);
    }
    if let Some(w) = b.get(b'R').copied() {
        let v = it.length(&w);
        if !in_range(it, &w, v, 0.0, 99.9999, "finishing allowance d") {
            return false;
        }
        *d = Some(v);
    }
    true
}

/// Checks `lo ≤ v ≤ hi`, reporting at `w` otherwise.
pub fn in_range(it: &mut Interp, w: &Word, v: f64, lo: f64, hi: f64, what: &str) -> bool {
    if v >= lo - EPS && v <= hi + EPS {
        return true;
    }
    it.diag(
        Code::ValueOutOfRange,
        w.span,
        format!("{}: {what} {} is outside {}..{}", w.display(), fmt(v), fmt(lo), fmt(hi)),
    );
    false
}

/// The shape of a cycle's thread: start point A, the root line of the
/// finished thread from A's Z to the programmed end, and which side is out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    /// Start and return point A.
    pub a: Point,
    /// Root of the finished thread at A's Z (end X plus the taper R(i)).
    pub root_start: Point,
    /// Root at the programmed end point.
    pub root_end: Point,
    /// +1 when A is outside the root (external thread), −1 inside (internal).
    pub out: f64,
    /// Straight or taper.
    pub kind: ThreadKind,
    /// Run-out: radial amount J and axial length K.
    pub runout: Option<(f64, f64)>,
    /// Screw-in: radial amount E and axial length.
    pub screw_in: Option<(f64, f64)>,
}

/// The points of one pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PassPoints {
    /// Where the screw-in starts.
    pub screw_in_from: Option<Point>,
    /// Start of the synchronised cut.
    pub from: Point,
    /// End of the synchronised cut.
    pub to: Point,
    /// End of the run-out.
    pub runout_to: Option<Point>,
}

impl Geometry {
    /// Builds the geometry of a cycle whose thread ends at `end` with taper
    /// `i` (radius, start minus end); alarms at `span` for a thread that
    /// does not run along Z or does not move.
    pub fn new(it: &mut Interp, a: Point, end: Point, i: f64, span: Span, what: &str) -> Option<Geometry> {
        let root_start = Point::new(end.x + 2.0 * i, a.z);
        if (end.z - a.z).abs() < EPS {
            it.diag(
                Code::FaceThreadNotAllowed,
                span,
                format!("{what} cuts straight and taper threads along Z only: the end Z is the start Z, which would be a face thread (use G32)"),
            );
            return None;
        }
        match classify(root_start, end) {
            None => {
                it.diag(
                    Code::ZeroLengthThread,
                    span,
                    format!("{what}: the thread has no length (end Z is the start Z)"),
                );
                None
            }
            Some((ThreadKind::Face, _)) | Some((_, Axis::X)) => {
                it.diag(
                    Code::FaceThreadNotAllowed,
                    span,
                    format!("{what} cuts straight and taper threads along Z only: this thread runs along X (a face or steep thread needs G32)"),
                );
                None
            }
            Some((kind, Axis::Z)) => {
                let out = if a.r() >= root_start.r() { 1.0 } else { -1.0 };
                Some(Geometry { a, root_start, root_end: end, out, kind, runout: None, screw_in: None })
            }
        }
    }

    /// Thread length along Z.
    pub fn length(&self) -> f64 {
        (self.root_end.z - self.root_start.z).abs()
    }

    /// The pass at depth `h` of a thread of height `k`, shifted axially by `shift`.
    pub fn pass(&self, h: f64, k: f64, shift: f64) -> PassPoints {
        let off = self.out * (k - h);
        let p0 = self.root_start.offset_r(off, shift);
        let p1 = self.root_end.offset_r(off, shift);
        let len = (p1.z - p0.z).abs();
        let (screw_in_from, from) = match self.screw_in {
            Some((e, ls)) if len > 0.0 => (Some(p0.offset_r(self.out * e, 0.0)), p0.lerp(p1, (ls / len).min(1.0))),
            _ => (None, p0),
        };
        let (to, runout_to) = match self.runout {
            Some((j, kk)) => {
                let (c, o) = split_runout(p0, p1, Axis::Z, self.out * j, kk);
                (c, Some(o))
            }
            None => (p1, None),
        };
        PassPoints { screw_in_from, from, to, runout_to }
    }

    /// Alarms when screw-in and run-out together are longer than the thread.
    pub fn check_ends(&self, it: &mut Interp, span: Span) -> bool {
        let si = self.screw_in.map_or(0.0, |s| s.1);
        let ro = self.runout.map_or(0.0, |r| r.1);
        if si + ro > self.length() + EPS {
            it.diag(
                Code::RunoutTooLong,
                span,
                format!(
                    "run-out {} and screw-in {} together are longer than the thread's {} of Z",
                    fmt(ro),
                    fmt(si),
                    fmt(self.length())
                ),
            );
            return false;
        }
        true
    }

    /// Emits the motions of one pass: approach from A, screw-in, cut,
    /// run-out, retract in X to A's diameter, return in Z to A.
    pub fn emit(&self, it: &mut Interp, p: &PassPoints, line: u32, span: Span) {
        let first = p.screw_in_from.unwrap_or(p.from);
        it.emit(MoveKind::Rapid, self.a, first, line, None, span);
        if let Some(s) = p.screw_in_from {
            it.emit(MoveKind::ScrewIn, s, p.from, line, None, span);
        }
        it.emit(MoveKind::Thread, p.from, p.to, line, None, span);
        let last = match p.runout_to {
            Some(r) => {
                it.emit(MoveKind::Runout, p.to, r, line, None, span);
                r
            }
            None => p.to,
        };
        let up = Point::new(self.a.x, last.z);
        it.emit(MoveKind::Rapid, last, up, line, None, span);
        it.emit(MoveKind::Rapid, up, self.a, line, None, span);
    }
}

/// A multi-pass cycle (G76, G78) ready to plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Multi {
    /// Which cycle.
    pub source: Source,
    /// Lines of its blocks.
    pub lines: Vec<u32>,
    /// Span of the second block's G word.
    pub span: Span,
    /// Geometry.
    pub geom: Geometry,
    /// Lead.
    pub lead: f64,
    /// Starts (L).
    pub starts: u32,
    /// Depth schedule inputs.
    pub schedule: schedule::Spec,
    /// Infeed mode.
    pub infeed: Infeed,
    /// Tool angle a.
    pub angle: f64,
}

/// Plans every pass of a multi-pass cycle for every start, emits its motions
/// and adds the thread. The pass limit is checked before anything is emitted.
pub fn plan_multi(it: &mut Interp, m: Multi) {
    let limit = it.s.int(P::LimitPasses).max(1) as usize;
    let sched = match schedule::plan(&m.schedule, limit) {
        Ok(s) => s,
        Err(needed) => {
            let s = &m.schedule;
            it.diag(
                Code::PassLimit,
                m.span,
                format!(
                    "the depth schedule needs {} passes per start (k {}, Δd {}, Δdmin {}, d {}): more than {limit} (setting limits.passes_per_start)",
                    if needed == u64::MAX { "too many".to_string() } else { needed.to_string() },
                    fmt(s.k),
                    fmt(s.first),
                    fmt(s.min),
                    fmt(s.allowance)
                ),
            );
            return;
        }
    };
    let max_starts = it.s.int(P::LimitStarts).max(1) as u32;
    if m.starts > max_starts {
        it.diag(
            Code::TooManyStarts,
            m.span,
            format!("{} starts: at most {max_starts} (setting limits.starts)", m.starts),
        );
        return;
    }
    if !m.geom.check_ends(it, m.span) {
        return;
    }
    // `flank.r1_side` places G78's "left" flank; G76 picks its flank from the cutting direction.
    let left_side = if m.source == Source::G78 && it.s.int(P::FlankR1Side) == 1 { 1.0 } else { -1.0 };
    let crest_r = m.geom.root_start.r() + m.geom.out * m.schedule.k;
    if (m.geom.a.r() - crest_r) * m.geom.out < -EPS {
        it.diag(
            Code::StartInsideThread,
            m.span,
            format!(
                "the start point X{} is inside the thread's crest X{}: the approach rapids through the work",
                fmt(m.geom.a.x),
                fmt(2.0 * crest_r)
            ),
        );
    }
    let k = m.schedule.k;
    let line = *m.lines.last().unwrap_or(&0);
    let first_move = it.moves.len();
    // Every start has the same passes: the chip areas are computed once.
    let shifts: Vec<(f64, f64)> = sched
        .iter()
        .enumerate()
        .map(|(n, &(h, _))| (h, infeed::shift(m.infeed, n as u32 + 1, h, k, m.angle, left_side)))
        .collect();
    let areas = crate::chip::pass_areas(m.angle, &shifts);
    let mut passes = Vec::with_capacity(sched.len() * m.starts as usize);
    'starts: for s in 0..m.starts {
        let angle = 360.0 * s as f64 / m.starts as f64;
        let mut prev = 0.0;
        for (n, &(h, role)) in sched.iter().enumerate() {
            let shift = shifts[n].1;
            let pts = m.geom.pass(h, k, shift);
            m.geom.emit(it, &pts, line, m.span);
            if it.stopped() {
                break 'starts;
            }
            passes.push(Pass {
                start: s + 1,
                index: n as u32 + 1,
                from: pts.from,
                to: pts.to,
                depth: h,
                infeed: h - prev,
                role,
                lines: m.lines.clone(),
                segments: Vec::new(),
                runout_to: pts.runout_to,
                screw_in_from: pts.screw_in_from,
                shift,
                angle,
                area: areas[n],
            });
            prev = h;
        }
    }
    it.arrive(m.geom.a, true, true, line);
    if passes.is_empty() {
        return;
    }
    let g = &m.geom;
    it.threads.push(Thread {
        line: m.lines[0],
        end_line: line,
        source: m.source,
        kind: g.kind,
        long_axis: Axis::Z,
        lead: m.lead,
        pitch: m.lead / m.starts as f64,
        starts: m.starts,
        internal: g.out < 0.0,
        infeed: m.infeed,
        tool_angle: m.angle,
        crest: 2.0 * (g.root_start.r() + g.out * k),
        crest_source: CrestSource::Cycle,
        height: k,
        taper: g.root_start.r() - g.root_end.r(),
        passes,
        depth_dir: -g.out,
        first_move,
    });
}

/// G90 (turning) and G94 (facing) single cycles: from the start point A,
/// rapid to the cut's start, feed along the cut (taper R), feed back out,
/// rapid home. Modal: a following block with axis words repeats it.
pub fn turning(it: &mut Interp, b: &Block, facing: bool) {
    let name = if facing { "G94" } else { "G90" };
    if !it.check_words(b, b"XZUWR", name) {
        return;
    }
    let a = it.current(b.span);
    let t = it.target(b);
    let r = b.get(b'R').copied().map_or(0.0, |w| it.length(&w));
    let end = t.p;
    let line = b.line;
    let pts: [(MoveKind, Point); 4] = if facing {
        // R: taper along Z, start minus end.
        let p1 = Point::new(a.x, end.z + r);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(end.x, a.z)), (MoveKind::Rapid, a)]
    } else {
        // R: taper as a radius difference, start minus end.
        let p1 = Point::new(end.x + 2.0 * r, a.z);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(a.x, end.z)), (MoveKind::Rapid, a)]
    };
    let mut from = a;
    for (kind, to) in pts {
        if from != to {
            it.emit(kind, from, to, line, None, b.span);
        }
        from = to;
    }
    it.arrive(a, true, true, line);
}
