//! The roughing passes of the stock-removal cycles G71 (turning) and G72
//! (facing), type I, as the Fanuc manual describes them (Series 21i-TB
//! operator's manual B-63604EN, §13.2.1 "Stock removal in turning" and
//! §13.2.2 "Stock removal in facing"; the 0i-TF's G71/G72 are the same;
//! GSK980TDc reads the same two-block forms, its user manual §3.20):
//!
//! - the finishing shape A′ … B (the contour N(ns) … N(nf)) shifted by the
//!   finishing allowances Δu (on the diameter) and Δw;
//! - cuts at depths Δd (radius; W for G72) from the start point A towards
//!   A′, each along Z (along X for G72) from A's Z (X) until the shifted
//!   shape; at the end of each cut the tool escapes by e at 45° and returns
//!   in rapid to the start's Z (X);
//! - after the last cut a cut along the shifted shape, and a rapid back to A.
//!
//! Pure: points in, motions out. A shape that is not monotone across (type
//! II, with pockets) is roughed by `cycle::pockets`; [`check`] says which
//! shapes a type refuses.

use crate::motion::{Move, MoveKind, Point};
use crate::span::Span;

/// Which cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Along {
    /// G71: cuts along Z, depths in X.
    Z,
    /// G72: cuts along X, depths in Z.
    X,
}

/// A roughing cycle's words.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rough {
    /// G71 or G72.
    pub along: Along,
    /// Depth of cut Δd (radius for G71, Z for G72), positive.
    pub depth: f64,
    /// Escape e, positive.
    pub escape: f64,
    /// Finishing allowance Δu, on the diameter (signed).
    pub du: f64,
    /// Finishing allowance Δw (signed).
    pub dw: f64,
    /// The controller roughs pockets (type II, `cycle::pockets`) when the
    /// contour's first block moves both axes (Fanuc 0i); `false`: it has
    /// type I only (GSK980TDc).
    pub pockets: bool,
}

/// How a contour breaks a roughing cycle's rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unfit {
    /// It goes back along the cut (Z for G71, X for G72): no type allows it.
    Back,
    /// It is not monotone across (it has pockets) and is roughed as type I.
    Pockets,
}

/// Whether `shape` (A′ first) fits cycle `r`: monotone along the cut
/// always, and across too unless it is roughed as type II (`type2`).
pub fn check(r: &Rough, shape: &[Point], type2: bool) -> Result<(), Unfit> {
    let pts: Vec<(f64, f64)> = shape.iter().map(|p| cl(*p, r.along)).collect();
    let monotone = |v: &dyn Fn(&(f64, f64)) -> f64| {
        let (mut up, mut down) = (false, false);
        for w in pts.windows(2) {
            let d = v(&w[1]) - v(&w[0]);
            up |= d > 1e-9;
            down |= d < -1e-9;
        }
        !(up && down)
    };
    if !monotone(&|p| p.0) {
        return Err(Unfit::Back);
    }
    if !type2 && !monotone(&|p| p.1) {
        return Err(Unfit::Pockets);
    }
    Ok(())
}

/// Most cuts drawn of one cycle (a tiny Δd on a large part).
pub const MAX_CUTS: usize = 10_000;

/// (cut, level) coordinates of a point: G71 cuts along Z at radius levels, G72 the other way.
pub(super) fn cl(p: Point, along: Along) -> (f64, f64) {
    match along {
        Along::Z => (p.z, p.x / 2.0),
        Along::X => (p.x / 2.0, p.z),
    }
}

/// The point of (cut, level) coordinates.
pub(super) fn pt(c: f64, l: f64, along: Along) -> Point {
    match along {
        Along::Z => Point { x: 2.0 * l, z: c },
        Along::X => Point { x: 2.0 * c, z: l },
    }
}

/// Where the shifted shape first reaches level `l`, walking from its start (its cut coordinate).
fn crossing(shape: &[(f64, f64)], l: f64) -> Option<f64> {
    for w in shape.windows(2) {
        let ((c0, l0), (c1, l1)) = (w[0], w[1]);
        if (l0 - l) * (l1 - l) <= 0.0 && (l1 - l0).abs() > 1e-12 {
            return Some(c0 + (c1 - c0) * (l - l0) / (l1 - l0));
        }
    }
    None
}

/// The roughing motions of cycle `r` from start point `a` over the finishing
/// shape `shape` (A′ first, B last), made by the block at `line`/`span`;
/// none when the shape is degenerate or lies on the wrong side of A.
pub fn passes(r: &Rough, a: Point, shape: &[Point], line: u32, span: Span) -> Vec<Move> {
    let along = r.along;
    if shape.len() < 2 || !(r.depth > 0.0 && r.depth.is_finite()) || !(r.escape >= 0.0 && r.escape.is_finite()) {
        return Vec::new();
    }
    let shifted: Vec<(f64, f64)> = shape.iter().map(|p| cl(Point { x: p.x + r.du, z: p.z + r.dw }, along)).collect();
    let (ac, al) = cl(a, along);
    let (q0, qn) = (shifted[0], shifted[shifted.len() - 1]);
    // Depths go from A towards A′; cuts from A's cut coordinate towards B.
    let down = (q0.1 - al).signum();
    let forward = (qn.0 - q0.0).signum();
    if down == 0.0 || forward == 0.0 {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut at = a;
    let mut go = |to: Point, kind: MoveKind, out: &mut Vec<Move>| {
        if (to.x - at.x).abs() > 1e-12 || (to.z - at.z).abs() > 1e-12 {
            out.push(Move { kind, from: at, to, line, span, arc: None });
            at = to;
        }
    };
    let total = (q0.1 - al).abs();
    let cuts = ((total / r.depth).ceil() as usize).min(MAX_CUTS);
    for k in 1..=cuts {
        let l = if k == cuts { q0.1 } else { al + down * r.depth * k as f64 };
        // The cut ends where the shifted shape reaches this depth (past B's: at B).
        let end = crossing(&shifted, l).unwrap_or(qn.0);
        if (end - ac) * forward <= 1e-9 {
            continue;
        }
        go(pt(ac, l, along), MoveKind::Rapid, &mut out);
        go(pt(end, l, along), MoveKind::Rough, &mut out);
        let (ec, el) = (end - forward * r.escape, l - down * r.escape);
        go(pt(ec, el, along), MoveKind::Rapid, &mut out);
        go(pt(ac, el, along), MoveKind::Rapid, &mut out);
    }
    // The cut along the shifted shape, then back to A.
    go(pt(ac, q0.1, along), MoveKind::Rapid, &mut out);
    go(pt(q0.0, q0.1, along), MoveKind::Rapid, &mut out);
    for &(c, l) in &shifted[1..] {
        go(pt(c, l, along), MoveKind::Rough, &mut out);
    }
    go(a, MoveKind::Rapid, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, z: f64) -> Point {
        Point { x, z }
    }

    #[test]
    fn g71_cuts_at_each_depth_to_the_shifted_shape() {
        // A X52 Z2; Δd 1.5, e 0.5; Δu 0.4, Δw 0.1; shape X26 Z2 → X30 Z-2 → Z-40 → X44 → Z-60 → X52.
        let r = Rough { along: Along::Z, depth: 1.5, escape: 0.5, du: 0.4, dw: 0.1, pockets: false };
        let shape = [p(26.0, 2.0), p(30.0, -2.0), p(30.0, -40.0), p(44.0, -40.0), p(44.0, -60.0), p(52.0, -60.0)];
        let m = passes(&r, p(52.0, 2.0), &shape, 5, Span::default());
        let cuts: Vec<&Move> = m.iter().filter(|m| m.kind == MoveKind::Rough).collect();
        // Radius 26 down to the shifted A′ at 13.2 in steps of 1.5: 24.5 … 14 and 13.2 (9 depths);
        // at 13.2 the shifted shape starts at Z2.1, behind A's Z2: no cut there.
        let levels: Vec<f64> = cuts.iter().take_while(|c| c.from.z == 2.0).map(|c| c.from.x / 2.0).collect();
        assert_eq!(levels, [24.5, 23.0, 21.5, 20.0, 18.5, 17.0, 15.5, 14.0]);
        // 24.5 and 23 end at the shifted shoulder face Z-59.9; 21.5 … 15.5 at Z-39.9; 14 on the chamfer at Z0.5.
        let ends: Vec<f64> = cuts.iter().take(8).map(|c| (c.to.z * 1e9).round() / 1e9).collect();
        assert_eq!(ends, [-59.9, -59.9, -39.9, -39.9, -39.9, -39.9, -39.9, 0.5]);
        // Each cut escapes 0.5 at 45° (out and back along Z) and returns to Z2 in rapid.
        let after_first = &m[2];
        assert_eq!((after_first.kind, after_first.to), (MoveKind::Rapid, p(50.0, -59.4)));
        assert_eq!(m[3].to, p(50.0, 2.0));
        // Then the shifted shape, from X26.4 Z2.1 to X52.4 Z-59.9, and back to A.
        assert_eq!(cuts[8].from, p(26.4, 2.1));
        let last_cut: Vec<Point> = cuts[8..].iter().map(|c| c.to).collect();
        assert_eq!(last_cut.len(), 5);
        assert_eq!(last_cut.last(), Some(&p(52.4, -59.9)));
        assert_eq!(m.last().map(|m| (m.kind, m.to)), Some((MoveKind::Rapid, p(52.0, 2.0))));
    }

    #[test]
    fn g72_faces_at_each_depth() {
        // A X82 Z1; Δd (W) 2, e 0.5; Δu 0.2, Δw 0.1.
        let r = Rough { along: Along::X, depth: 2.0, escape: 0.5, du: 0.2, dw: 0.1, pockets: false };
        // A′ X82 Z-6 (type I: Z only), face to X40, turn to Z0, face to X20.
        let shape = [p(82.0, -6.0), p(40.0, -6.0), p(40.0, 0.0), p(20.0, 0.0)];
        let m = passes(&r, p(82.0, 1.0), &shape, 3, Span::default());
        let cuts: Vec<&Move> = m.iter().filter(|m| m.kind == MoveKind::Rough).collect();
        // Z from 1 towards the shifted A′ at Z-5.9: -1, -3, -5, -5.9; each faced from X82 (radius 41) inwards
        // to the shifted shape: at Z-1 to the step at X40.2 (radius 20.1); at -3 and -5 also 20.1; at -5.9 (the shifted face) to X40.2.
        let levels: Vec<f64> = cuts.iter().take(4).map(|c| (c.from.z * 1e9).round() / 1e9).collect();
        assert_eq!(levels, [-1.0, -3.0, -5.0, -5.9]);
        assert!(cuts.iter().take(4).all(|c| (c.to.x - 40.2).abs() < 1e-9), "{cuts:?}");
        assert!(cuts[0].from.x == 82.0);
    }

    #[test]
    fn nothing_to_rough_gives_nothing() {
        let r = Rough { along: Along::Z, depth: 0.0, escape: 0.5, du: 0.4, dw: 0.1, pockets: false };
        assert!(passes(&r, p(52.0, 2.0), &[p(26.0, 2.0), p(30.0, -2.0)], 1, Span::default()).is_empty());
        let r = Rough { depth: 1.0, ..r };
        assert!(passes(&r, p(52.0, 2.0), &[p(26.0, 2.0)], 1, Span::default()).is_empty());
    }
}
