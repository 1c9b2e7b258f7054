//! Chip areas: what each pass of a thread removes from the thread space.
//!
//! Thread-space profiles as piecewise-linear functions of the axial offset
//! `u`: the surface left after some passes, `w(u)` ≤ 0 below the crest
//! (external orientation: depth downward). A tool at depth `d` and shift `s`
//! cuts everything above `-d + max(0, |u − s| − flat) / tan(a/2)`; the
//! surface after several passes is the lower envelope of their cuts, and
//! the area a pass removes lies between the surfaces before and after it.

/// A piecewise-linear function given by its vertices, sorted by `u`.
/// Outside its vertices it is 0 (the uncut crest).
#[derive(Clone, Debug, PartialEq)]
pub struct Pl {
    /// Vertices `(u, w)`.
    pub pts: Vec<(f64, f64)>,
}

/// The cutting edge of a tool: V of half-angle `atan(t)` with a flat tip of
/// half-width `flat` (0 for a sharp V).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tool {
    /// `tan(a/2)`: axial run per unit of depth along a flank.
    pub t: f64,
    /// Half-width of the flat tip.
    pub flat: f64,
}

impl Tool {
    /// The surface this tool leaves with its tip at depth `d` (> 0 cuts)
    /// and axial shift `s`, over `[u0, u1]`.
    pub fn cut(&self, d: f64, s: f64, u0: f64, u1: f64) -> Pl {
        let mut us = vec![u0, u1];
        if d > 0.0 {
            let half = self.flat + d * self.t;
            us.extend([s - half, s - self.flat, s + self.flat, s + half]);
        }
        Pl::sample(us, u0, u1, |u| self.depth_at(d, s, u))
    }

    fn depth_at(&self, d: f64, s: f64, u: f64) -> f64 {
        if d <= 0.0 {
            return 0.0;
        }
        let off = ((u - s).abs() - self.flat).max(0.0);
        (-d + off / self.t).min(0.0)
    }
}

impl Pl {
    /// The uncut crest over `[u0, u1]`.
    pub fn flat(u0: f64, u1: f64) -> Pl {
        Pl { pts: vec![(u0, 0.0), (u1, 0.0)] }
    }

    fn sample(mut us: Vec<f64>, u0: f64, u1: f64, f: impl Fn(f64) -> f64) -> Pl {
        us.retain(|u| u.is_finite() && *u >= u0 && *u <= u1);
        crate::order::sort_floats(&mut us);
        us.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (1.0 + a.abs()));
        Pl { pts: us.into_iter().map(|u| (u, f(u))).collect() }.simplified()
    }

    /// Value at `u` (0 outside the vertices).
    pub fn at(&self, u: f64) -> f64 {
        let p = &self.pts;
        if p.is_empty() || u < p[0].0 || u > p[p.len() - 1].0 {
            return 0.0;
        }
        let i = p.partition_point(|q| q.0 < u);
        if i == 0 {
            return p[0].1;
        }
        if i >= p.len() {
            return p[p.len() - 1].1;
        }
        let (a, b) = (p[i - 1], p[i]);
        if b.0 - a.0 <= 0.0 { b.1 } else { a.1 + (b.1 - a.1) * (u - a.0) / (b.0 - a.0) }
    }

    /// This function shifted right by `du`, over `[u0, u1]`.
    pub fn shifted(&self, du: f64, u0: f64, u1: f64) -> Pl {
        let us: Vec<f64> = self.pts.iter().map(|p| p.0 + du).chain([u0, u1]).collect();
        Pl::sample(us, u0, u1, |u| self.at(u - du))
    }

    /// The lower envelope `min(self, o)`, with the crossings as vertices.
    pub fn min(&self, o: &Pl) -> Pl {
        let mut us: Vec<f64> = self.pts.iter().chain(&o.pts).map(|p| p.0).collect();
        crate::order::sort_floats(&mut us);
        us.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (1.0 + a.abs()));
        let mut out: Vec<(f64, f64)> = Vec::with_capacity(us.len() * 2);
        for (k, &u) in us.iter().enumerate() {
            let (a, b) = (self.at(u), o.at(u));
            if k > 0 {
                let up = us[k - 1];
                let (pa, pb) = (self.at(up), o.at(up));
                let (d0, d1) = (pa - pb, a - b);
                if (d0 > 0.0 && d1 < 0.0) || (d0 < 0.0 && d1 > 0.0) {
                    let x = up + (u - up) * d0 / (d0 - d1);
                    out.push((x, self.at(x).min(o.at(x))));
                }
            }
            out.push((u, a.min(b)));
        }
        Pl { pts: out }.simplified()
    }

    /// Drops vertices on a straight line between their neighbours.
    pub fn simplified(mut self) -> Pl {
        if self.pts.len() < 3 {
            return self;
        }
        let mut out: Vec<(f64, f64)> = Vec::with_capacity(self.pts.len());
        for p in self.pts.drain(..) {
            while out.len() >= 2 {
                let (a, b) = (out[out.len() - 2], out[out.len() - 1]);
                let cross = (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0);
                let scale = (p.0 - a.0).abs().max((p.1 - a.1).abs()).max(1e-12);
                if cross.abs() <= 1e-12 * scale * scale {
                    out.pop();
                } else {
                    break;
                }
            }
            out.push(p);
        }
        Pl { pts: out }
    }

    /// The regions where `lower` is below `self` (the area a cut removes),
    /// each as a polygon: the lower edge left to right, then the upper edge back.
    pub fn regions_above(&self, lower: &Pl) -> Vec<Vec<(f64, f64)>> {
        let mut us: Vec<f64> = self.pts.iter().chain(&lower.pts).map(|p| p.0).collect();
        crate::order::sort_floats(&mut us);
        us.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (1.0 + a.abs()));
        let eps = 1e-12;
        let gap = |u: f64| self.at(u) - lower.at(u);
        let mut out = Vec::new();
        let mut k = 0;
        while k + 1 < us.len() {
            // A region starts on an interval where the gap is open.
            let mid = (us[k] + us[k + 1]) / 2.0;
            if gap(mid) <= eps {
                k += 1;
                continue;
            }
            let first = k;
            while k + 1 < us.len() && gap((us[k] + us[k + 1]) / 2.0) > eps {
                k += 1;
            }
            let span = &us[first..=k];
            let mut poly: Vec<(f64, f64)> = span.iter().map(|&u| (u, lower.at(u))).collect();
            poly.extend(span.iter().rev().map(|&u| (u, self.at(u))));
            poly.dedup_by(|a, b| (a.0 - b.0).abs() <= eps && (a.1 - b.1).abs() <= eps);
            out.push(poly);
        }
        out
    }
}

/// The area each pass removes from one thread space, in cutting order, for
/// passes given as (depth, axial shift) with a V tool of `angle_deg`: the
/// material between the surface before the pass and the lower envelope of
/// the surface and the pass's cut. Radial and single-flank passes give
/// tan(a/2)·(h₁² − h₀²); alternating flanks leave slivers and remove more.
/// `None` for a 0° (square) tool, whose width the program does not give.
pub fn pass_areas(angle_deg: f64, passes: &[(f64, f64)]) -> Vec<Option<f64>> {
    if !(angle_deg > 0.0 && angle_deg < 180.0) {
        return vec![None; passes.len()];
    }
    let tool = Tool { t: (angle_deg.to_radians() / 2.0).tan(), flat: 0.0 };
    // When each cut contains the one before (the tip moves no further
    // sideways than the V widens: radial and single-flank infeed), the
    // space after pass n is the V of pass n and the areas have a closed form.
    let nested = passes.windows(2).all(|w| (w[1].1 - w[0].1).abs() <= (w[1].0 - w[0].0) * tool.t + 1e-12);
    if nested {
        let mut prev = 0.0f64;
        return passes
            .iter()
            .map(|&(d, _)| {
                let d = d.max(prev);
                let a = crate::thread::v_area(angle_deg, prev, d);
                prev = d;
                a
            })
            .collect();
    }
    let reach = passes.iter().map(|(d, s)| d.max(0.0) * tool.t + s.abs()).fold(0.0, f64::max);
    let (u0, u1) = (-reach - 1.0, reach + 1.0);
    let mut surface = Pl::flat(u0, u1);
    passes
        .iter()
        .map(|&(d, s)| {
            let next = surface.min(&tool.cut(d, s, u0, u1));
            let a: f64 = surface.regions_above(&next).iter().map(|r| area(r)).sum();
            surface = next;
            Some(a)
        })
        .collect()
}

/// Area of a simple polygon (absolute, shoelace).
pub fn area(poly: &[(f64, f64)]) -> f64 {
    let n = poly.len();
    if n < 3 {
        return 0.0;
    }
    let mut s = 0.0;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        s += a.0 * b.1 - b.0 * a.1;
    }
    s.abs() / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    const T60: f64 = 0.5773502691896257; // tan 30°

    #[test]
    fn a_v_cut_is_a_triangle() {
        let tool = Tool { t: T60, flat: 0.0 };
        let c = tool.cut(1.0, 0.0, -2.0, 2.0);
        assert_eq!(c.pts.len(), 5);
        assert!((c.at(0.0) + 1.0).abs() < 1e-12);
        assert!((c.at(T60 / 2.0) + 0.5).abs() < 1e-12);
        assert_eq!(c.at(1.5), 0.0);
        let regions = Pl::flat(-2.0, 2.0).regions_above(&c);
        assert_eq!(regions.len(), 1);
        assert!((area(&regions[0]) - T60).abs() < 1e-12);
    }

    #[test]
    fn radial_passes_remove_chevrons_of_the_v_area() {
        let tool = Tool { t: T60, flat: 0.0 };
        let first = Pl::flat(-2.0, 2.0).min(&tool.cut(0.45, 0.0, -2.0, 2.0));
        let second = first.min(&tool.cut(0.75, 0.0, -2.0, 2.0));
        let removed: f64 = first.regions_above(&second).iter().map(|r| area(r)).sum();
        assert!((removed - T60 * (0.75f64.powi(2) - 0.45f64.powi(2))).abs() < 1e-12, "{removed}");
    }

    #[test]
    fn flank_passes_cross_and_leave_a_sliver() {
        let tool = Tool { t: T60, flat: 0.0 };
        // Second pass deeper and shifted right: the envelope has a crossing vertex.
        let a = tool.cut(0.5, 0.0, -2.0, 2.0);
        let b = tool.cut(0.8, 0.1, -2.0, 2.0);
        let env = a.min(&b);
        // The envelope is never above either cut and equals one of them everywhere.
        for i in 0..=400 {
            let u = -2.0 + 4.0 * i as f64 / 400.0;
            let e = env.at(u);
            assert!((e - a.at(u).min(b.at(u))).abs() < 1e-9, "u={u}");
        }
        let removed: f64 = a.regions_above(&env).iter().map(|r| area(r)).sum();
        let total = area(&Pl::flat(-2.0, 2.0).regions_above(&env)[0]);
        assert!((removed + T60 * 0.25 - total).abs() < 1e-9, "{removed} {total}");
    }

    /// Radial passes: tan 30°·(h₁² − h₀²); flank passes the same; alternating more.
    #[test]
    fn pass_areas_by_infeed() {
        let radial = pass_areas(60.0, &[(0.45, 0.0), (0.75, 0.0)]);
        assert!((radial[0].unwrap() - T60 * 0.45 * 0.45).abs() < 1e-12);
        assert!((radial[1].unwrap() - T60 * (0.75f64.powi(2) - 0.45f64.powi(2))).abs() < 1e-12);
        // Left flank: the tip runs on the −Z flank, (k − h)·tan 30° left of the middle (k = 1.3).
        let k = 1.3;
        let flank: Vec<(f64, f64)> = [0.4, 0.8, 1.2, 1.3].iter().map(|&h| (h, -(k - h) * T60)).collect();
        let a = pass_areas(60.0, &flank);
        let mut prev = 0.0f64;
        for (h, got) in [0.4, 0.8, 1.2, 1.3].iter().zip(&a) {
            assert!((got.unwrap() - T60 * (h * h - prev * prev)).abs() < 1e-9, "{h}: {got:?}");
            prev = *h;
        }
        // Alternating: the second pass, on the other flank, removes more than the radial formula.
        let alt = pass_areas(60.0, &[(0.4, -0.9 * T60), (0.8, 0.5 * T60)]);
        assert!(alt[1].unwrap() > T60 * (0.64 - 0.16) + 1e-6, "{alt:?}");
        assert_eq!(pass_areas(0.0, &[(1.0, 0.0)]), vec![None]);
    }

    /// The closed form for nested cuts agrees with the envelope.
    #[test]
    fn closed_form_matches_the_envelope() {
        let k = 1.3;
        let flank: Vec<(f64, f64)> = [0.4, 0.6, 0.9, 1.2, 1.3].iter().map(|&h| (h, (k - h) * T60)).collect();
        let fast = pass_areas(60.0, &flank);
        // The envelope, step by step as in `pass_areas`' general path.
        let tool = Tool { t: T60, flat: 0.0 };
        let mut surface = Pl::flat(-3.0, 3.0);
        for (&(d, s), got) in flank.iter().zip(&fast) {
            let next = surface.min(&tool.cut(d, s, -3.0, 3.0));
            let a: f64 = surface.regions_above(&next).iter().map(|r| area(r)).sum();
            assert!((a - got.unwrap()).abs() < 1e-9, "{a} vs {got:?}");
            surface = next;
        }
    }

    #[test]
    fn shifting_moves_the_notch() {
        let tool = Tool { t: T60, flat: 0.0 };
        let c = tool.cut(1.0, 0.0, -3.0, 3.0).shifted(2.0, -3.0, 3.0);
        assert!((c.at(2.0) + 1.0).abs() < 1e-12);
        assert_eq!(c.at(0.0), 0.0);
    }
}
