//! G71/G72 type II (Fanuc 0i): a finishing shape with pockets. The shape
//! must be monotone along the cut (Z for G71, X for G72) but may go up and
//! down across it; the type is chosen by the contour's first block, which
//! moves both axes (W0 when Z does not move).
//!
//! The roughing, as this preview plans it from the manual's words (no
//! citable page gives the path move by move; the choices are the README's):
//!
//! - the depths are type I's, Δd apart from the start point A towards A′,
//!   and go on past A′ to the deepest point of the shifted shape;
//! - at each depth the stock to cut is where the shifted shape lies deeper
//!   than it: from A's cut coordinate to the first crossing (the cut type I
//!   makes), and, past a rise of the shape, each pocket from the wall it
//!   goes down to the wall it comes up again;
//! - after each cut the tool follows the shifted shape up its wall to the
//!   depth before (or to the top of a rise lower than that): type II leaves
//!   no steps; it then escapes by e straight out and returns in rapid;
//! - the cuts from A go first, down to their last depth; then each pocket
//!   in turn along the cut, depth by depth (a pocket within a pocket after
//!   it). A pocket is entered from above the top of the rise before it:
//!   a rapid out to A's level, along it, down to the depth cut there, a
//!   feed onto the shape and along it down the wall to the cut; the next
//!   depth of the same pocket follows the wall down from where the last
//!   one started;
//! - last, as in type I, the cut along the whole shifted shape and a rapid
//!   back to A.
//!
//! Pure: points in, motions out.

use super::rough::{MAX_CUTS, Rough, cl, pt};
use crate::motion::{Move, MoveKind, Point};
use crate::span::Span;

/// Most motions planned for the cuts of one cycle (the last cut along the shape comes after them).
const MAX_MOVES: usize = 8 * MAX_CUTS;

/// One cut: along depth `y` from `u0` to `u1`; `s0`, `s1` where it meets the
/// shape (segment index plus fraction); `yp` the depth before.
#[derive(Clone, Copy, Debug)]
struct Cut {
    y: f64,
    yp: f64,
    u0: f64,
    u1: f64,
    s0: f64,
    s1: f64,
    main: bool,
    parent: Option<usize>,
}

/// The shape in (u, y): u grows along the cut from A′ to B, y grows away
/// from the part (from A′ towards A).
struct Frame {
    pts: Vec<(f64, f64)>,
    along: super::rough::Along,
    forward: f64,
    down: f64,
}

impl Frame {
    fn point(&self, u: f64, y: f64) -> Point {
        pt(self.forward * u, -self.down * y, self.along)
    }

    /// The shape's point at `s`.
    fn at(&self, s: f64) -> (f64, f64) {
        let j = (s.floor() as usize).min(self.pts.len() - 1);
        let t = s - j as f64;
        if j + 1 >= self.pts.len() || t <= 0.0 {
            return self.pts[j];
        }
        let (a, b) = (self.pts[j], self.pts[j + 1]);
        (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t)
    }

    /// Where a segment from `a` to `b` is at depth `y` (its fraction).
    fn frac(a: (f64, f64), b: (f64, f64), y: f64) -> f64 {
        if (b.1 - a.1).abs() < 1e-12 { 1.0 } else { ((y - a.1) / (b.1 - a.1)).clamp(0.0, 1.0) }
    }

    /// Where the shape first reaches depth `y` walking from its start, as type I's cut ends (`None`: past B).
    fn first_crossing(&self, y: f64) -> Option<f64> {
        self.pts.windows(2).enumerate().find_map(|(j, w)| {
            let (a, b) = (w[0], w[1]);
            ((a.1 - y) * (b.1 - y) <= 0.0 && (b.1 - a.1).abs() > 1e-12).then(|| j as f64 + Self::frac(a, b, y))
        })
    }

    /// The stretches where the shape lies deeper than `y`, as (s0, s1).
    fn below(&self, y: f64) -> Vec<(f64, f64)> {
        let deep = |p: (f64, f64)| p.1 < y - 1e-9;
        let mut out = Vec::new();
        let mut start = deep(self.pts[0]).then_some(0.0);
        for (j, w) in self.pts.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            match (start, deep(b)) {
                (None, true) => start = Some(j as f64 + Self::frac(a, b, y)),
                (Some(s0), false) => {
                    out.push((s0, j as f64 + Self::frac(a, b, y)));
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(s0) = start {
            out.push((s0, (self.pts.len() - 1) as f64));
        }
        out
    }

    /// Walking on from `s`, where the shape reaches depth `yp` or stops rising (the end at last).
    fn climb(&self, s: f64, yp: f64) -> f64 {
        let mut j = s.floor() as usize;
        while j + 1 < self.pts.len() {
            let (a, b) = (self.pts[j], self.pts[j + 1]);
            if b.1 >= yp - 1e-9 && a.1 < yp {
                return (j as f64 + Self::frac(a, b, yp)).max(s);
            }
            if b.1 < a.1 - 1e-9 {
                return (j as f64).max(s);
            }
            j += 1;
        }
        (self.pts.len() - 1) as f64
    }

    /// Walking back from `s`, the top of the rise before it (a vertex, or the start).
    fn hill(&self, s: f64) -> f64 {
        let mut j = (s.ceil() as usize).min(self.pts.len() - 1);
        if j as f64 > s {
            j -= 1;
        }
        while j > 0 && self.pts[j - 1].1 >= self.pts[j].1 - 1e-9 {
            j -= 1;
        }
        j as f64
    }
}

/// The depths: Δd apart from A's, A′'s among them (type I's last), on to the deepest point.
fn depths(ya: f64, y0: f64, ymin: f64, step: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut k = 1.0;
    loop {
        let y = ya - step * k;
        if y <= ymin + 1e-9 || out.len() >= MAX_CUTS {
            break;
        }
        out.push(y);
        k += 1.0;
    }
    out.push(y0);
    out.push(ymin);
    crate::order::sort_by(&mut out, |a, b| b.total_cmp(a));
    out.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    out.retain(|y| *y < ya - 1e-9);
    out
}

/// The cuts at every depth, each with the cut at the depth before that holds it.
fn cuts(f: &Frame, ua: f64, ya: f64, levels: &[f64]) -> Vec<Cut> {
    let y0 = f.pts[0].1;
    let mut out: Vec<Cut> = Vec::new();
    let mut before = 0..0;
    for (i, &y) in levels.iter().enumerate() {
        let yp = if i == 0 { ya } else { levels[i - 1] };
        let first = out.len();
        let mut main_end = f64::NEG_INFINITY;
        if y >= y0 - 1e-9 {
            let s1 = f.first_crossing(y).unwrap_or((f.pts.len() - 1) as f64);
            let u1 = f.at(s1).0;
            if u1 > ua + 1e-9 {
                out.push(Cut { y, yp, u0: ua, u1, s0: 0.0, s1, main: true, parent: None });
                main_end = u1;
            }
        }
        for (s0, s1) in f.below(y) {
            let (u0, u1) = (f.at(s0).0, f.at(s1).0);
            // The stretch from the start, where a cut from A is made, is not a pocket.
            if u0 >= main_end - 1e-9 && u1 > u0 + 1e-9 {
                out.push(Cut { y, yp, u0, u1, s0, s1, main: false, parent: None });
            }
        }
        for k in first..out.len() {
            let mid = 0.5 * (out[k].u0 + out[k].u1);
            let parent = before.clone().find(|&p| out[p].u0 - 1e-9 <= mid && mid <= out[p].u1 + 1e-9);
            out[k].parent = parent;
        }
        before = first..out.len();
        if out.len() >= MAX_CUTS {
            break;
        }
    }
    out
}

/// The cuts in the order they are made: each one, then those it holds, in order along the cut.
fn order(cuts: &[Cut]) -> Vec<usize> {
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); cuts.len()];
    let mut stack = Vec::new();
    for (k, c) in cuts.iter().enumerate().rev() {
        match c.parent {
            Some(p) => children[p].insert(0, k),
            None => stack.push(k),
        }
    }
    let mut out = Vec::with_capacity(cuts.len());
    while let Some(k) = stack.pop() {
        out.push(k);
        stack.extend(children[k].iter().rev());
    }
    out
}

/// Motions in (u, y), kept with where the tool is.
struct Path<'f> {
    f: &'f Frame,
    at: (f64, f64),
    out: Vec<Move>,
    line: u32,
    span: Span,
}

impl Path<'_> {
    fn go(&mut self, to: (f64, f64), kind: MoveKind) {
        if (to.0 - self.at.0).abs() > 1e-12 || (to.1 - self.at.1).abs() > 1e-12 {
            let (from, p) = (self.f.point(self.at.0, self.at.1), self.f.point(to.0, to.1));
            self.out.push(Move { kind, from, to: p, line: self.line, span: self.span, arc: None });
            self.at = to;
        }
    }

    /// Feeds along the shape from `s0` on to `s1`.
    fn along(&mut self, s0: f64, s1: f64) {
        let mut j = s0.floor() as usize + 1;
        while (j as f64) < s1 {
            self.go(self.f.pts[j], MoveKind::Rough);
            j += 1;
        }
        self.go(self.f.at(s1), MoveKind::Rough);
    }
}

/// The roughing motions of type II over the finishing shape `shape` (A′
/// first, B last) from start point `a`, made by the block at
/// `line`/`span`; none when the shape is degenerate or lies on the wrong
/// side of A.
pub fn passes(r: &Rough, a: Point, shape: &[Point], line: u32, span: Span) -> Vec<Move> {
    if shape.len() < 2 || !(r.depth > 0.0 && r.depth.is_finite()) || !(r.escape >= 0.0 && r.escape.is_finite()) {
        return Vec::new();
    }
    let along = r.along;
    let shifted: Vec<(f64, f64)> = shape.iter().map(|p| cl(Point { x: p.x + r.du, z: p.z + r.dw }, along)).collect();
    let (ac, al) = cl(a, along);
    let (q0, qn) = (shifted[0], shifted[shifted.len() - 1]);
    let (down, forward) = ((q0.1 - al).signum(), (qn.0 - q0.0).signum());
    if down == 0.0 || forward == 0.0 {
        return Vec::new();
    }
    let pts = shifted.iter().map(|&(c, l)| (forward * c, -down * l)).collect();
    let f = Frame { pts, along, forward, down };
    let (ua, ya) = (forward * ac, -down * al);
    let ymin = f.pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let levels = depths(ya, f.pts[0].1, ymin, r.depth);
    let cuts = cuts(&f, ua, ya, &levels);
    let mut path = Path { f: &f, at: (ua, ya), out: Vec::new(), line, span };
    let mut prev: Option<usize> = None;
    for k in order(&cuts) {
        if path.out.len() > MAX_MOVES {
            break;
        }
        cut(&mut path, &cuts, k, prev, (ua, ya), r.escape);
        prev = Some(k);
    }
    // Out to A's depth, to A, then the cut along the shifted shape and back to A.
    path.go((path.at.0, ya.max(path.at.1)), MoveKind::Rapid);
    path.go((ua, path.at.1), MoveKind::Rapid);
    path.go((ua, f.pts[0].1), MoveKind::Rapid);
    path.go(f.pts[0], MoveKind::Rapid);
    for k in 1..f.pts.len() {
        path.go(f.pts[k], MoveKind::Rough);
    }
    path.go((ua, ya), MoveKind::Rapid);
    path.out
}

/// Cut `k` of `cuts`, the one made before it `prev`, A at `a` in (u, y), escape `e`.
fn cut(path: &mut Path, cuts: &[Cut], k: usize, prev: Option<usize>, a: (f64, f64), e: f64) {
    let c = cuts[k];
    let (ua, ya) = a;
    if c.main {
        if prev.is_some_and(|p| !cuts[p].main) {
            path.go((path.at.0, ya.max(path.at.1)), MoveKind::Rapid);
        }
        path.go((ua, path.at.1), MoveKind::Rapid);
        path.go((ua, c.y), MoveKind::Rapid);
    } else if c.parent.is_some() && c.parent == prev && !cuts[prev.unwrap_or(k)].main {
        // The next depth of the same pocket: down its wall from where the last one started.
        let from = cuts[prev.unwrap_or(k)].s0;
        path.along(from, c.s0);
    } else {
        let h = path.f.hill(c.s0);
        let top = path.f.at(h);
        path.go((path.at.0, ya.max(path.at.1)), MoveKind::Rapid);
        path.go((top.0, path.at.1), MoveKind::Rapid);
        path.go((top.0, c.yp.max(top.1)), MoveKind::Rapid);
        path.go(top, MoveKind::Rough);
        path.along(h, c.s0);
    }
    path.go((c.u1, c.y), MoveKind::Rough);
    let up = path.f.climb(c.s1, c.yp);
    path.along(c.s1, up);
    let out = path.at.1 + e;
    path.go((path.at.0, out), MoveKind::Rapid);
    if c.main {
        path.go((ua, out), MoveKind::Rapid);
    } else {
        path.go((c.u0, out), MoveKind::Rapid);
        path.go((c.u0, c.y), MoveKind::Rapid);
    }
}

#[cfg(test)]
mod tests;
