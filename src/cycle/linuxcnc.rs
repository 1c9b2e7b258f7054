//! LinuxCNC's G76 threading cycle, planned pass by pass: a pure function of
//! what the block gave (read by `controller::linuxcnc`) and the pass limit.
//!
//! The semantics are those of LinuxCNC's interpreter (`threading_pass` and
//! `convert_threading_cycle`), checked against `rs274` (tests/linuxcnc.rs).
//! Radius values below; `s` = sign(I) (−1 external, +1 internal), `σ` the
//! cutting direction along Z, `t` = tan Q (Q's sign flipped when cutting
//! towards +Z), `d` the depth of a pass below the peak X0 + I:
//!
//! - depths: `d_n = J·n^(1/R)` while `|I| + d_n < |I| + K` (in f64, as
//!   LinuxCNC compares), then K once, then H more passes at K;
//! - cut at `Xc = X0 + s(|I| + d)`, retract to `Xr = Xc − s(|I| + K)` (beyond
//!   the drive line by K − d), from `Zs = Z0 − d·t` to `Ze = Z1 + (K − d)·t`:
//!   every pass is the full-depth pass moved back along the cut;
//! - tapers (E > 0; L bit 1 entry, bit 2 exit) are synchronised moves of
//!   their own: the entry one starts with an X move in from the retract.
//!
//! One pass: a rapid from where the tool is to `(Xr, Zs)`, a rapid in to
//! `(Xc, Zs)` (without an entry taper), the synchronised moves, a rapid out
//! to `(Xr, Ze)`. After the last pass the tool goes to the block's end point.

use super::PassPath;
use crate::args;
use crate::diagnostic::Finding;
use crate::message::{self as msg, Message};
use crate::motion::{Move, MoveKind, Point};
use crate::span::Span;
use crate::thread::{Axis, CrestSource, Infeed, Pass, PassMoves, Role, Source, Spindle, Thread, ThreadKind};

/// A G76 block as LinuxCNC reads it; lengths in program units, X values radii.
#[derive(Clone, Debug, PartialEq)]
pub struct G76 {
    /// Source line.
    pub line: u32,
    /// Span of the block's G76 word.
    pub span: Span,
    /// Drive point (X0 radius, Z0): the tool position when the cycle starts.
    pub x0: f64,
    /// Z of the drive point: the thread starts there.
    pub z0: f64,
    /// Z1, the end of the thread.
    pub z1: f64,
    /// Where the final traverse goes in X (radius): the drive line, or the block's X word.
    pub x_end: f64,
    /// P: distance along the move per revolution, as written.
    pub pitch: f64,
    /// I: peak offset from the drive line (negative external, positive internal).
    pub i: f64,
    /// J: first pass depth below the peak (> 0).
    pub j: f64,
    /// K: full depth below the peak (> J).
    pub k: f64,
    /// R: depth degression (≥ 1).
    pub r: f64,
    /// Q: compound slide angle, degrees.
    pub q: f64,
    /// H: spring passes (negative: no full-depth pass).
    pub h: i64,
    /// E: taper length along Z (≥ 0).
    pub e: f64,
    /// L: taper ends, bit 1 entry, bit 2 exit.
    pub l: u32,
    /// Tool angle for chip areas (the cycle does not know it).
    pub tool_angle: f64,
    /// The spindle in force.
    pub spindle: Spindle,
}

/// The planned cycle: the thread (its passes' `moves` still empty), each
/// pass's motions, the final traverse and the notes on the plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Planned {
    /// The thread, or `None` when P is 0 (no thread is cut).
    pub thread: Option<Thread>,
    /// The motions of each pass, in cutting order.
    pub paths: Vec<PassPath>,
    /// The move to the block's end point after the last pass, when it moves.
    pub end: Option<Move>,
    /// Warnings and notes.
    pub notes: Vec<Finding>,
}

impl G76 {
    /// Cutting direction along Z: +1 towards +Z, −1 otherwise (as LinuxCNC: Z1 > Z0).
    fn sense(&self) -> f64 {
        if self.z1 > self.z0 { 1.0 } else { -1.0 }
    }

    /// tan of the compound angle as the passes use it.
    fn tan_q(&self) -> f64 {
        let a = if self.sense() > 0.0 { -self.q } else { self.q };
        a.to_radians().tan()
    }

    /// Side of the cut: −1 external (I < 0), +1 internal.
    fn side(&self) -> f64 {
        if self.i > 0.0 { 1.0 } else { -1.0 }
    }

    /// The pass depths below the peak with their roles; `Err(n)` when more
    /// than `limit` passes (n: how many at least).
    pub fn depths(&self, limit: usize) -> Result<Vec<(f64, Role)>, u64> {
        let (i, j, k) = (self.i.abs(), self.j.abs(), self.k.abs());
        let end = k + i;
        let mut out = Vec::new();
        let mut depth = i + j;
        let mut n = 1u64;
        while depth < end {
            if out.len() >= limit {
                return Err(out.len() as u64 + 1);
            }
            out.push((depth - i, Role::Rough));
            n += 1;
            depth = i + j * (n as f64).powf(1.0 / self.r);
        }
        let full = self.h.saturating_add(1).max(0) as u64;
        if out.len() as u64 + full > limit as u64 {
            return Err(out.len() as u64 + full);
        }
        for f in 0..full {
            out.push((k, if f == 0 { Role::Finish } else { Role::Spring }));
        }
        Ok(out)
    }

    /// Taper pitch: P·√(E² + K²)/E, so that Z advances P per revolution on the tapers.
    pub fn taper_pitch(&self) -> f64 {
        self.pitch * self.e.hypot(self.k.abs()) / self.e
    }

    /// The moves of the pass at depth `d` from `from` (radius, Z), with its
    /// points: (approach, synchronised, back, cut start, cut end, screw-in start, taper end).
    fn pass_moves(&self, d: f64, from: (f64, f64)) -> PassGeometry {
        let (s, t, sigma) = (self.side(), self.tan_q(), self.sense());
        let (i, k) = (self.i.abs(), self.k.abs());
        let xc = self.x0 + s * (i + d);
        let xr = xc - s * (i + k);
        let xt = xc - s * k;
        let zs = self.z0 - d * t;
        let ze = self.z1 + k * t - d * t;
        let e = if self.e > 0.0 { sigma * self.e } else { 0.0 };
        let (entry, exit) = (e != 0.0 && self.l & 1 != 0, e != 0.0 && self.l & 2 != 0);
        let mut g = PassGeometry::default();
        let mut at = from;
        let mut go = |v: &mut Vec<Step>, kind, to: (f64, f64), always: bool| {
            if always || to != at {
                v.push((kind, at, to));
            }
            at = to;
        };
        go(&mut g.approach, MoveKind::Rapid, (xr, zs), false);
        let start = if entry {
            go(&mut g.cut, MoveKind::ScrewIn, (xt, zs), true);
            go(&mut g.cut, MoveKind::ScrewIn, (xc, zs + e), true);
            g.screw_in_from = Some((xr, zs));
            (xc, zs + e)
        } else {
            go(&mut g.approach, MoveKind::Rapid, (xc, zs), false);
            (xc, zs)
        };
        let end = if exit { (xc, ze - e) } else { (xc, ze) };
        go(&mut g.cut, MoveKind::Thread, end, true);
        if exit {
            go(&mut g.cut, MoveKind::Runout, (xt, ze), true);
            g.runout_to = Some((xt, ze));
        }
        go(&mut g.back, MoveKind::Rapid, (xr, ze), false);
        g.from = start;
        g.to = end;
        g.at = at;
        g
    }
}

/// A motion as (kind, from, to), points as (radius, Z).
type Step = (MoveKind, (f64, f64), (f64, f64));

/// One pass's motions, and its points.
#[derive(Clone, Debug, Default)]
struct PassGeometry {
    approach: Vec<Step>,
    cut: Vec<Step>,
    back: Vec<Step>,
    from: (f64, f64),
    to: (f64, f64),
    screw_in_from: Option<(f64, f64)>,
    runout_to: Option<(f64, f64)>,
    /// Where the tool is after the pass.
    at: (f64, f64),
}

/// A program point (X as a diameter) from a radius and a Z.
fn pt((r, z): (f64, f64)) -> Point {
    Point::new(2.0 * r, z)
}

/// Plans the cycle: an alarm when it needs more than `limit` passes;
/// `warn_passes` is the count above which a note says the cycle is long.
pub fn plan(g: &G76, limit: usize, warn_passes: usize) -> Result<Planned, Finding> {
    let depths = g
        .depths(limit)
        .map_err(|n| Message::new(&msg::LCNC_PASS_LIMIT, args![n, j = g.j, k = g.k, r = g.r, h = g.h, limit]))?;
    let mv = |(kind, a, b): Step| Move { kind, from: pt(a), to: pt(b), line: g.line, span: g.span, arc: None };
    let mut at = (g.x0, g.z0);
    let mut passes = Vec::with_capacity(depths.len());
    let mut paths = Vec::with_capacity(depths.len());
    let k = g.k.abs();
    let t = g.tan_q();
    let shifts: Vec<(f64, f64)> = depths.iter().map(|&(d, _)| (d, (k - d) * t)).collect();
    let areas = crate::chip::pass_areas(g.tool_angle, &shifts);
    let mut geometry: Vec<PassGeometry> = Vec::with_capacity(depths.len());
    for &(d, _) in &depths {
        let mut p = g.pass_moves(d, at);
        at = p.at;
        // A return straight back along the axis is the pass's before it, as a
        // block-by-block pass owns its return (one back and across starts the next's approach).
        if let Some(last) = geometry.last_mut()
            && p.approach.first().is_some_and(|m| m.1.0 == m.2.0)
        {
            last.back.push(p.approach.remove(0));
        }
        geometry.push(p);
    }
    let mut prev = 0.0;
    for (n, (&(d, role), p)) in depths.iter().zip(&geometry).enumerate() {
        let conv = |v: &[Step]| v.iter().map(|m| mv(*m)).collect::<Vec<_>>();
        paths.push(PassPath::of(&conv(&p.approach), &conv(&p.cut), &conv(&p.back)));
        passes.push(Pass {
            start: 1,
            index: n as u32 + 1,
            from: pt(p.from),
            to: pt(p.to),
            depth: d,
            infeed: d - prev,
            role,
            lines: vec![g.line],
            via: Vec::new(),
            segments: Vec::new(),
            runout_to: p.runout_to.map(pt),
            screw_in_from: p.screw_in_from.map(pt),
            shift: shifts[n].1,
            angle: 0.0,
            area: areas[n],
            moves: PassMoves::default(),
            spindle: g.spindle,
        });
        prev = d;
    }
    let end = (at != (g.x_end, g.z1)).then(|| mv((MoveKind::Rapid, at, (g.x_end, g.z1))));
    let notes = notes(g, &depths, warn_passes);
    let thread = (g.pitch != 0.0 && !passes.is_empty()).then(|| thread(g, passes));
    Ok(Planned { thread, paths, end, notes })
}

/// The thread of the planned passes.
fn thread(g: &G76, passes: Vec<Pass>) -> Thread {
    let s = g.side();
    let t = g.tan_q();
    let infeed = if t == 0.0 {
        Infeed::Radial
    } else if t > 0.0 {
        Infeed::Right
    } else {
        Infeed::Left
    };
    let lead = g.pitch.abs();
    Thread {
        line: g.line,
        end_line: g.line,
        source: Source::LinuxG76,
        units: Default::default(),
        kind: ThreadKind::Straight,
        long_axis: Axis::Z,
        lead,
        pitch: lead,
        starts: 1,
        internal: s > 0.0,
        infeed,
        tool_angle: g.tool_angle,
        crest: 2.0 * (g.x0 + s * g.i.abs()),
        crest_source: CrestSource::Cycle,
        turned: None,
        height: g.k.abs(),
        taper: 0.0,
        passes,
        depth_dir: s,
        first_move: 0,
        shop: Default::default(),
    }
}

/// Notes on a planned cycle: the floating-point extra pass, a backward cut
/// between the tapers, a long cycle.
fn notes(g: &G76, depths: &[(f64, Role)], warn_passes: usize) -> Vec<Finding> {
    let mut out = Vec::new();
    let (i, k) = (g.i.abs(), g.k.abs());
    if let Some(n) = depths.iter().position(|&(d, role)| role == Role::Rough && (k + i) - (i + d) <= 1e-9 * (k + i)) {
        let a = args![n = n + 1, sum = i + depths[n].0, full = k + i, k];
        out.push(Message::new(&msg::LCNC_FLOAT_EXTRA_PASS, a));
    }
    let full = g.pass_moves(k, (g.x0, g.z0));
    if (full.to.1 - full.from.1) * g.sense() < -1e-9 {
        let a = args![e = g.e, len = (g.z1 - g.z0).abs(), from = full.from.1, to = full.to.1];
        out.push(Message::new(&msg::LCNC_BACKWARD_CUT, a));
    }
    if depths.len() > warn_passes {
        let a = args![n = depths.len(), j = g.j, k = g.k, r = g.r, h = g.h, limit = warn_passes];
        out.push(Message::new(&msg::LCNC_MANY_PASSES, a));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn straight() -> G76 {
        G76 {
            line: 4,
            span: Span::default(),
            x0: 10.0,
            z0: 5.0,
            z1: -20.0,
            x_end: 10.0,
            pitch: 1.5,
            i: -1.0,
            j: 0.2,
            k: 1.0,
            r: 1.0,
            q: 0.0,
            h: 0,
            e: 0.0,
            l: 0,
            tool_angle: 60.0,
            spindle: Spindle::default(),
        }
    }

    /// linuxcnc.md §4.1, g76-straight: cuts 8.8 … 8.0, retracts 10.8 … 10.0 (radii).
    #[test]
    fn straight_passes_and_retracts() {
        let p = plan(&straight(), 999, 50).unwrap();
        let t = p.thread.unwrap();
        let x: Vec<f64> = t.passes.iter().map(|p| (p.from.x * 5e3).round() / 1e4).collect();
        assert_eq!(x, [8.8, 8.6, 8.4, 8.2, 8.0]);
        let first = &p.paths[0].moves()[0];
        assert_eq!((first.to.x, first.to.z), (21.6, 5.0));
        assert_eq!(t.passes[4].role, Role::Finish);
        assert_eq!(t.crest, 18.0);
        assert!(p.end.is_none());
    }

    /// `I-0.7 J0.3 K0.9`: 0.7 + 0.3·3 < 1.6 in f64, so four passes, two at K.
    #[test]
    fn float_extra_pass() {
        let g = G76 { i: -0.7, j: 0.3, k: 0.9, ..straight() };
        let d = g.depths(999).unwrap();
        assert_eq!(d.len(), 4);
        assert!((d[2].0 - 0.9).abs() < 1e-12 && d[2].1 == Role::Rough);
        let p = plan(&g, 999, 50).unwrap();
        assert_eq!(p.notes[0].code(), crate::Code::FloatExtraPass);
    }

    /// E2 L3: in-move, entry taper, cut, exit taper (g76-taper-l3).
    #[test]
    fn tapers_at_both_ends() {
        let g = G76 { e: 2.0, l: 3, ..straight() };
        let p = plan(&g, 999, 50).unwrap();
        let cut: Vec<(f64, f64)> = p.paths[0].moves().iter().map(|m| (m.to.x / 2.0, m.to.z)).collect();
        assert_eq!(cut, [(10.8, 5.0), (9.8, 5.0), (8.8, 3.0), (8.8, -18.0), (9.8, -20.0), (10.8, -20.0)]);
        assert_eq!(p.paths[0].counts, [1, 4, 1]);
        assert!((g.taper_pitch() - 1.677051).abs() < 1e-6);
    }

    #[test]
    fn pass_limit_and_negative_h() {
        let g = G76 { j: 1e-6, ..straight() };
        assert_eq!(plan(&g, 999, 50).unwrap_err().code(), crate::Code::PassLimit);
        let g = G76 { h: i64::MAX, ..straight() };
        assert_eq!(plan(&g, 999, 50).unwrap_err().code(), crate::Code::PassLimit);
        let g = G76 { h: -1, ..straight() };
        assert_eq!(g.depths(999).unwrap().len(), 4);
    }
}
