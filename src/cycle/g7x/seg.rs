//! One piece of the profile — a line or an arc — in the cycle's frame
//! (`cx`), with what the roughing asks of it: where it crosses a depth,
//! whether it runs one way along the cut, how it moves when the profile is
//! offset, and where it meets the next piece (rs274's `segment`,
//! `straight_segment` and `round_segment` in `interp_g7x.cc`).

use super::Fail;
use super::cx::{C, I};

/// How close two values must be to count as equal (rs274's `tolerance`).
pub const TOL: f64 = 1e-6;

/// The shape of a piece.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A straight line.
    Line,
    /// An arc about `c`, counter-clockwise in the frame when `ccw` (G3 in G18).
    Arc {
        /// Counter-clockwise.
        ccw: bool,
        /// Centre.
        c: C,
    },
}

/// A piece of the profile from `s` to `e`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    /// Start.
    pub s: C,
    /// End.
    pub e: C,
    /// Line or arc.
    pub shape: Shape,
    /// A corner still to be made between the pieces either side (`A`/`C` on
    /// a profile move): of this size, a fillet when an arc, a chamfer when a
    /// line; `None` once made, and for every other piece.
    pub corner: Option<f64>,
}

/// Where a piece crosses a depth: at most two cut coordinates, in the piece's order.
#[derive(Clone, Copy, Debug, Default)]
pub struct Hits {
    v: [f64; 2],
    n: usize,
}

impl Hits {
    fn push(&mut self, x: f64) {
        if self.n < 2 {
            self.v[self.n] = x;
            self.n += 1;
        }
    }

    /// No crossing.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The first crossing.
    pub fn front(&self) -> Option<f64> {
        (self.n > 0).then(|| self.v[0])
    }

    /// The last crossing.
    pub fn back(&self) -> Option<f64> {
        (self.n > 0).then(|| self.v[self.n - 1])
    }
}

impl Seg {
    /// A line from `s` to `e`.
    pub fn line(s: C, e: C) -> Seg {
        Seg { s, e, shape: Shape::Line, corner: None }
    }

    /// An arc from `s` to `e` about `c`.
    pub fn arc(ccw: bool, s: C, c: C, e: C) -> Seg {
        Seg { s, e, shape: Shape::Arc { ccw, c }, corner: None }
    }

    /// Its size: a line's length, an arc's chord or radius, the smaller.
    pub fn size(&self) -> f64 {
        match self.shape {
            Shape::Line => (self.s - self.e).abs(),
            Shape::Arc { c, .. } => (self.s - self.e).abs().min((self.s - c).abs()),
        }
    }

    /// Whether rs274 drops it: smaller than 0.001 (one of no number for a size stays).
    pub fn tiny(&self) -> bool {
        self.size() < 1e-3
    }

    /// Whether it never goes back along the cut (`re` does not grow; an arc
    /// stays on the far side of its centre).
    pub fn monotone(&self) -> bool {
        let dz = (self.e - self.s).re;
        match self.shape {
            Shape::Line => dz <= 1e-3,
            Shape::Arc { .. } if self.corner.is_some_and(|d| d != 0.0) => true,
            Shape::Arc { ccw, c } => {
                let (entry, exit) = ((self.s - c).im, (self.e - c).im);
                if ccw {
                    entry >= -1e-3 && exit >= -1e-3 && dz <= -1e-3
                } else {
                    entry <= 1e-3 && exit <= 1e-3 && dz <= -1e-3
                }
            }
        }
    }

    /// Moves it `d` to its left (a line), or grows a counter-clockwise arc's radius by `d`.
    pub fn offset(&mut self, d: f64) {
        match self.shape {
            Shape::Line => {
                let v = (I.scale(d) * (self.s - self.e)).over((self.s - self.e).abs());
                self.s += v;
                self.e += v;
            }
            Shape::Arc { ccw, c } => {
                let r = (self.s - c).abs();
                let k = (r + if ccw { d } else { -d }) / r;
                self.s = (self.s - c).scale(k) + c;
                self.e = (self.e - c).scale(k) + c;
            }
        }
    }

    /// Applies `f` to its points (and centre); `mirror`: `f` reverses turning.
    pub fn map(&mut self, f: impl Fn(C) -> C, mirror: bool) {
        self.s = f(self.s);
        self.e = f(self.e);
        if let Shape::Arc { ccw, c } = self.shape {
            self.shape = Shape::Arc { ccw: ccw != mirror, c: f(c) };
        }
    }

    /// Whether point `p` (on its circle) lies on the arc from `s` to `e` about `c`.
    fn on_arc(&self, ccw: bool, c: C, p: C) -> bool {
        let (a, b) = ((self.s - c).cross(p - c), (self.e - c).cross(p - c));
        if ccw { a >= -TOL && b <= TOL } else { a <= TOL && b >= -TOL }
    }

    /// Where it crosses depth `x`: a level line gives both its ends.
    pub fn crossings(&self, x: f64) -> Hits {
        let mut h = Hits::default();
        match self.shape {
            Shape::Line => {
                let (lo, hi) = (self.s.im.min(self.e.im), self.s.im.max(self.e.im));
                if lo > x + TOL || hi < x - TOL {
                    return h;
                }
                if (self.s - self.e).im.abs() < TOL {
                    h.push(self.s.re);
                    h.push(self.e.re);
                } else {
                    h.push((x - self.s.im) / (self.e.im - self.s.im) * (self.e.re - self.s.re) + self.s.re);
                }
            }
            Shape::Arc { ccw, c } => {
                let r = (self.s - c).abs();
                let q = -(x - r - c.im) * (x + r - c.im);
                if q < -TOL {
                    return h;
                }
                let q = if q < 0.0 { 0.0 } else { q.sqrt() };
                for p in [C::new(c.re + q, x), C::new(c.re - q, x)] {
                    if self.on_arc(ccw, c, p) {
                        h.push(p.re);
                    }
                }
            }
        }
        h
    }
}

/// Makes `p` end and `n` start where the two meet (after an offset moved them apart).
pub fn join(p: &mut Seg, n: &mut Seg) -> Result<(), Fail> {
    let at = match (p.shape, n.shape) {
        (Shape::Line, Shape::Line) => {
            // In a frame where n runs along the real axis from its end.
            let rot = (n.s - n.e).conj().over((n.s - n.e).abs());
            let (ps, pe) = ((p.s - n.e) * rot, (p.e - n.e) * rot);
            if (ps - pe).im == 0.0 {
                return Err(Fail::Parallel);
            }
            let f = ps.im / (ps - pe).im;
            (ps + (pe - ps).scale(f)) / rot + n.e
        }
        (Shape::Arc { c, .. }, Shape::Line) => {
            if (n.s - p.e).abs() < TOL {
                return Ok(());
            }
            line_meets_circle(n.s, n.e, p.e, c, n.s)
        }
        (Shape::Line, Shape::Arc { c, .. }) => {
            if (n.s - p.e).abs() < TOL {
                return Ok(());
            }
            line_meets_circle(p.s, p.e, n.e, c, n.s)
        }
        (Shape::Arc { c: pc, .. }, Shape::Arc { c: nc, .. }) => {
            // The triangle of the two centres and the meeting point.
            let a = (n.s - nc).abs();
            let b = (p.s - pc).abs();
            let d = (nc - pc).abs();
            let cos = (d * d + a * a - b * b) / 2.0 / a / d;
            let cos2 = if cos * cos > 1.0 { 1.0 } else { cos * cos };
            let rot = C::new(cos, (1.0 - cos2).sqrt());
            (rot * (pc - nc)).over(d).scale(a) + nc
        }
    };
    if !at.is_finite() {
        return Err(Fail::Parallel);
    }
    p.e = at;
    n.s = at;
    Ok(())
}

/// Where the line through `a` → `b` meets the circle about `c` through
/// `on`: of the two points, the one nearer `near`.
fn line_meets_circle(a: C, b: C, on: C, c: C, near: C) -> C {
    let rot = (a - b).conj().over((a - b).abs());
    let (pe, pc) = ((on - b) * rot, (c - b) * rot);
    let q = (pc - pe).norm() - pc.im * pc.im;
    let q = if q < 0.0 { 0.0 } else { q.sqrt() };
    let s1 = C::new(pc.re + q, 0.0) / rot + b;
    let s2 = C::new(pc.re - q, 0.0) / rot + b;
    if (near - s1).abs() < (near - s2).abs() { s1 } else { s2 }
}
