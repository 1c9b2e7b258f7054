//! The walk's moves as the plan's: back in the program's coordinates (X a
//! diameter), of the cycle block, roughing or the part's outline; and the
//! checks rs274 makes of each as it makes it (`motion_machine` in
//! `interp_g7x.cc` hands each to the interpreter's `convert_straight` and
//! `convert_arc`, whose arc check is `arc_data_ijk` in `interp_arc.cc`):
//! an arc to where the tool is is no move; an arc whose radius from where
//! the tool is and at its end differ by more than the interpreter allows,
//! or one of them nothing, is its alarm.

use super::cx::{self, C};
use super::walk::Out;
use super::{Fail, Frame};
use crate::motion::{ArcData, Move, MoveKind, Point};
use crate::span::Span;

/// How the walk's moves become the plan's: the frame, whether the moves
/// along the profile turn the part's outline, the units, the cycle block.
pub struct Emit {
    /// The walk's frame.
    pub frame: Frame,
    /// The moves along the profile are the part's outline (D 0), not roughing.
    pub finished: bool,
    /// Inches (rs274's arc tolerances are in the program's units).
    pub inch: bool,
    /// The cycle block's line.
    pub line: u32,
    /// The cycle block's span.
    pub span: Span,
}

impl Emit {
    /// The walk's moves `out` in the program's coordinates from `at` (where
    /// the tool then is), onto `into`; the arc rs274 refuses, if any (the
    /// moves before it made).
    pub fn moves(&self, out: &[Out], at: &mut Point, into: &mut Vec<Move>) -> Option<Fail> {
        let point = |q: C| self.frame.point(q);
        let contour = if self.finished { MoveKind::Feed } else { MoveKind::Rough };
        for o in out {
            let (kind, to, arc) = match *o {
                Out::Rapid(q) => (MoveKind::Rapid, point(q), None),
                Out::Feed(q, along) => (if along { contour } else { MoveKind::Rough }, point(q), None),
                Out::Arc { ccw, c, to } => {
                    let to = point(to);
                    if (to.z - at.z).abs() < 1e-4 && (to.x - at.x).abs() / 2.0 < 1e-4 {
                        continue;
                    }
                    let center = point(c);
                    if let Some(f) = self.refused(*at, center, to) {
                        return Some(f);
                    }
                    let arc = ArcData { center, cw: ccw == self.frame.mirrored() };
                    let kind = if self.finished { MoveKind::Arc } else { MoveKind::Rough };
                    (kind, to, Some(arc).filter(|a| a.center.is_finite()))
                }
            };
            if !to.is_finite() {
                continue;
            }
            if at.dist(to) > 1e-9 {
                into.push(Move { kind, from: *at, to, line: self.line, span: self.span, arc });
            }
            *at = to;
        }
        None
    }

    /// rs274's check of an arc from `from` about `c` to `to`: the radii at
    /// both ends within 0.0283 mm (0.00283 in) of each other, or 100 times
    /// that when they differ by less than 0.1 %, and neither below 0.00127
    /// mm (0.00005 in).
    fn refused(&self, from: Point, c: Point, to: Point) -> Option<Fail> {
        let (spiral, least) =
            if self.inch { (2.0 * 0.001 * 2f64.sqrt(), 0.00005) } else { (2.0 * 0.01 * 2f64.sqrt(), 0.00005 * 25.4) };
        let zr = |p: Point| (p.z, p.x / 2.0);
        let (r1, r2) = radii(zr(from), zr(c), zr(to));
        let zero = r1 < least || r2 < least;
        let err = (r1 - r2).abs();
        let rel = err / r1.max(r2);
        (zero || err > spiral * 100.0 || (rel > 0.001 && err > spiral)).then_some(Fail::Arc {
            zero,
            from: zr(from),
            c: zr(c),
            to: zr(to),
        })
    }
}

/// The radii from centre `c` to `from` and to `to`, points (Z, radius).
fn radii(from: (f64, f64), c: (f64, f64), to: (f64, f64)) -> (f64, f64) {
    ((c.1 - from.1).hypot(c.0 - from.0), (c.1 - to.1).hypot(c.0 - to.0))
}

/// rs274's message for an arc it refuses (points as (Z, radius)).
pub fn arc_message(zero: bool, from: (f64, f64), c: (f64, f64), to: (f64, f64)) -> String {
    let (r1, r2) = radii(from, c, to);
    let p = |q: (f64, f64)| format!("(Z{:.4},X{:.4})", q.0, q.1);
    let ends = format!("start={} center={} end={} r1={r1:.4} r2={r2:.4}", p(from), p(c), p(to));
    if zero {
        return format!("Zero-radius arc: {ends}");
    }
    let err = (r1 - r2).abs();
    let rel = err / r1.max(r2) * 100.0;
    format!(
        "Radius to end of arc differs from radius to start: {ends} abs_err={} rel_err={rel:.4}%",
        cx::g_prec(err, 4)
    )
}
