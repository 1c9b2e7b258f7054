//! The passes of the pattern repeating cycle G73 (Fanuc 0i, GSK980TDc):
//! `G73 U(Δi) W(Δk) R(d)` then `G73 P(ns) Q(nf) U(Δu) W(Δw) F`.
//!
//! The finishing shape A′ … B (the contour N(ns) … N(nf)) is cut d times,
//! each time shifted from the finished shape by the relief still left:
//! pass k (1 … d) by Δi·(d−k)/(d−1) + Δu/2 across (a radius) and
//! Δk·(d−k)/(d−1) + Δw along Z, so the first pass is Δi + Δu/2 and Δk + Δw
//! off the shape and the last is at the finishing allowance; with d = 1 the
//! one pass is at the allowance. Each pass is a rapid from the start point
//! A to the shifted A′, the shifted shape fed, and a rapid back to A
//! (Yaskawa YASNAC LX3 manual §2.8.2.5.4 "Pattern repeating (G73)": the
//! tool path A → A′ → B, D the number of cuttings, "when D is 1 … a single
//! cycle remaining finishing allowance"; the Fanuc concise guide's "profile
//! repetition": the profile repeated R times, moved each time by a certain
//! distance, U the radial stock to remove).
//!
//! Pure: points in, motions out.

use super::rough::MAX_CUTS;
use crate::motion::{Move, MoveKind, Point};
use crate::span::Span;

/// A pattern repeating cycle's words.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pattern {
    /// Relief across Δi, a radius (signed): the first pass's distance from the allowance.
    pub di: f64,
    /// Relief along Z Δk (signed).
    pub dk: f64,
    /// The number of divisions d: passes, 1 or more.
    pub d: u32,
    /// Finishing allowance Δu, on the diameter (signed).
    pub du: f64,
    /// Finishing allowance Δw (signed).
    pub dw: f64,
}

/// Most motions one G73 plans (d passes of the contour's moves, with their rapids).
pub const MAX_MOVES: usize = 8 * MAX_CUTS;

impl Pattern {
    /// The shift of pass `k` (1 … d) from the finished shape: (on the diameter, along Z).
    pub fn shift(&self, k: u32) -> (f64, f64) {
        let f = if self.d <= 1 { 0.0 } else { f64::from(self.d.saturating_sub(k)) / f64::from(self.d - 1) };
        (2.0 * self.di * f + self.du, self.dk * f + self.dw)
    }

    /// The motions the cycle would plan over a shape of `points` points (rapids included).
    pub fn moves_needed(&self, points: usize) -> usize {
        (self.d as usize).saturating_mul(points + 1)
    }
}

/// The passes of cycle `p` from start point `a` over the finishing shape
/// `shape` (A′ first, B last), made by the block at `line`/`span`. `Err`
/// with the number of motions when they would be more than [`MAX_MOVES`];
/// none when the shape is empty.
pub fn passes(p: &Pattern, a: Point, shape: &[Point], line: u32, span: Span) -> Result<Vec<Move>, usize> {
    let needed = p.moves_needed(shape.len());
    if needed > MAX_MOVES {
        return Err(needed);
    }
    let mut out = Vec::with_capacity(needed);
    if shape.is_empty() || p.d == 0 {
        return Ok(out);
    }
    let mut at = a;
    let mut go = |to: Point, kind: MoveKind, out: &mut Vec<Move>| {
        if (to.x - at.x).abs() > 1e-12 || (to.z - at.z).abs() > 1e-12 {
            out.push(Move { kind, from: at, to, line, span, arc: None });
            at = to;
        }
    };
    for k in 1..=p.d {
        let (sx, sz) = p.shift(k);
        let moved = |q: &Point| Point { x: q.x + sx, z: q.z + sz };
        go(moved(&shape[0]), MoveKind::Rapid, &mut out);
        for q in &shape[1..] {
            go(moved(q), MoveKind::Rough, &mut out);
        }
        go(a, MoveKind::Rapid, &mut out);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, z: f64) -> Point {
        Point { x, z }
    }

    /// A point rounded to 1e-9 (sums of decimals).
    fn r(q: Point) -> Point {
        p((q.x * 1e9).round() / 1e9, (q.z * 1e9).round() / 1e9)
    }

    #[test]
    fn passes_step_from_the_relief_to_the_allowance() {
        // Δi 3 (radius), Δk 1, d 3, Δu 0.4, Δw 0.1: across 3 + 0.2, 1.5 + 0.2, 0.2 (diameters 6.4, 3.4,
        // 0.4); along 1 + 0.1, 0.5 + 0.1, 0.1.
        let g = Pattern { di: 3.0, dk: 1.0, d: 3, du: 0.4, dw: 0.1 };
        let s: Vec<Point> = (1..=3).map(|k| g.shift(k)).map(|(x, z)| r(p(x, z))).collect();
        assert_eq!(s, [p(6.4, 1.1), p(3.4, 0.6), p(0.4, 0.1)]);
        let shape = [p(20.0, 0.0), p(20.0, -10.0), p(30.0, -15.0)];
        let m = passes(&g, p(50.0, 5.0), &shape, 4, Span::default()).unwrap();
        // Each pass: a rapid to the shifted A′, two feeds, a rapid back: 12 motions.
        assert_eq!(m.len(), 12);
        assert_eq!((m[0].kind, r(m[0].to)), (MoveKind::Rapid, p(26.4, 1.1)));
        assert_eq!((m[2].kind, r(m[2].to)), (MoveKind::Rough, p(36.4, -13.9)));
        assert_eq!((m[3].kind, m[3].to), (MoveKind::Rapid, p(50.0, 5.0)));
        assert_eq!(r(m[4].to), p(23.4, 0.6));
        assert_eq!(r(m[8].to), p(20.4, 0.1));
        assert_eq!(r(m[10].to), p(30.4, -14.9));
    }

    #[test]
    fn one_division_is_one_pass_at_the_allowance() {
        let g = Pattern { di: 5.0, dk: 2.0, d: 1, du: 0.5, dw: 0.0 };
        assert_eq!(g.shift(1), (0.5, 0.0));
        let m = passes(&g, p(40.0, 2.0), &[p(10.0, 0.0), p(30.0, -20.0)], 1, Span::default()).unwrap();
        let ends: Vec<Point> = m.iter().map(|m| m.to).collect();
        assert_eq!(ends, [p(10.5, 0.0), p(30.5, -20.0), p(40.0, 2.0)]);
    }

    #[test]
    fn too_many_motions_are_refused() {
        let g = Pattern { di: 1.0, dk: 0.0, d: 999, du: 0.0, dw: 0.0 };
        let shape = vec![p(10.0, 0.0); 100];
        assert_eq!(passes(&g, p(20.0, 1.0), &shape, 1, Span::default()), Err(999 * 101));
        assert!(passes(&g, p(20.0, 1.0), &[], 1, Span::default()).unwrap().is_empty());
    }
}
