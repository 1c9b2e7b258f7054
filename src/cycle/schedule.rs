//! Depth schedules of the multi-pass cycles (G76, G78).
//!
//! Roughing passes go down to k − d: equal depth (every pass cuts Δd) or
//! degressive (the first pass at Δd, pass n at Δd·√n, a cut below Δdmin
//! raised to Δdmin from the second pass on), the last one clamped at k − d.
//! The first finishing pass removes the allowance d at full depth k and
//! further finishing passes are spring passes (GSK980TDc §3.21.7 steps
//! ①–⑩); or, by the setting `cycle.finish_rule`, each removes d/m.

use crate::thread::Role;

/// How roughing depths progress.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthMode {
    /// Every roughing pass cuts Δd (G78 m = 0).
    Equal,
    /// Pass n reaches Δd·√n (G76; G78 m = 1).
    Degressive,
}

/// How a degressive cut below Δdmin is raised (setting `cycle.dmin_rule`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DminRule {
    /// The pass cuts Δdmin below the previous pass.
    #[default]
    Previous,
    /// The depth is √(n−1)·Δd + Δdmin, the formula as the manual prints it.
    Printed,
}

/// How the finishing passes share the allowance (setting `cycle.finish_rule`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FinishRule {
    /// The first removes d at depth k, the others are spring passes at k.
    #[default]
    Steps,
    /// Each of the m passes removes d/m.
    Split,
}

/// The inputs of a schedule, radial lengths in program units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    /// Thread height k (total depth).
    pub k: f64,
    /// First depth Δd.
    pub first: f64,
    /// Minimum roughing cut Δdmin.
    pub min: f64,
    /// Finishing allowance d.
    pub allowance: f64,
    /// Equal or degressive.
    pub mode: DepthMode,
    /// Finishing passes (the first removes d, the rest are spring passes).
    pub finish: u32,
    /// How a cut below Δdmin is raised.
    pub dmin_rule: DminRule,
    /// How the finishing passes share d.
    pub finish_rule: FinishRule,
}

/// The schedule: cumulative depth and role of every pass of one start.
pub type Schedule = Vec<(f64, Role)>;

/// Plans the passes of one start, or returns an estimate of how many passes
/// it would need when that is more than `limit`.
pub fn plan(spec: &Spec, limit: usize) -> Result<Schedule, u64> {
    let target = spec.k - spec.allowance;
    let step = |n: u64, prev: f64| -> f64 {
        match spec.mode {
            DepthMode::Equal => n as f64 * spec.first.max(spec.min),
            // Step ①: the first pass is at Δd whatever Δdmin is.
            DepthMode::Degressive if n == 1 => spec.first,
            DepthMode::Degressive => {
                let raised = match spec.dmin_rule {
                    DminRule::Previous => prev + spec.min,
                    DminRule::Printed => spec.first * ((n - 1) as f64).sqrt() + spec.min,
                };
                (spec.first * (n as f64).sqrt()).max(raised)
            }
        }
    };
    let tol = 1e-9 * target.abs().max(1.0);
    let mut out = Schedule::new();
    let mut prev = 0.0;
    let mut n = 0u64;
    while target > tol && prev < target - tol {
        n += 1;
        if out.len() + spec.finish as usize >= limit {
            return Err(estimate(spec, target));
        }
        let mut c = step(n, prev);
        if c >= target - tol {
            c = target;
        }
        out.push((c, Role::Rough));
        prev = c;
    }
    for i in 0..spec.finish {
        match spec.finish_rule {
            FinishRule::Steps => out.push((spec.k, if i == 0 { Role::Finish } else { Role::Spring })),
            FinishRule::Split => {
                let share = (i + 1) as f64 / spec.finish as f64;
                out.push((target.max(0.0) + (spec.k - target.max(0.0)) * share, Role::Finish));
            }
        }
    }
    if out.len() > limit {
        return Err(out.len() as u64);
    }
    Ok(out)
}

/// How many passes the schedule needs, computed without planning them.
pub fn estimate(spec: &Spec, target: f64) -> u64 {
    let rough = match spec.mode {
        DepthMode::Equal => (target / spec.first.max(spec.min)).ceil(),
        DepthMode::Degressive => {
            if spec.min <= 0.0 {
                (target / spec.first).powi(2).ceil()
            } else {
                // Cuts Δd(√n − √(n−1)) fall below Δdmin near n0 = (Δd / 2Δdmin)²; Δdmin steps after that.
                let n0 = (spec.first / (2.0 * spec.min)).powi(2).max(1.0);
                let at = spec.first * n0.sqrt();
                if at >= target { (target / spec.first).powi(2).ceil() } else { n0 + ((target - at) / spec.min).ceil() }
            }
        }
    };
    let total = rough + spec.finish as f64;
    if total.is_finite() && total < u64::MAX as f64 { total as u64 } else { u64::MAX }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rules of the manual's steps; the tests set the rest.
    const SPEC: Spec = Spec {
        k: 0.0,
        first: 0.0,
        min: 0.0,
        allowance: 0.0,
        mode: DepthMode::Degressive,
        finish: 1,
        dmin_rule: DminRule::Previous,
        finish_rule: FinishRule::Steps,
    };

    fn depths(s: &Schedule) -> Vec<f64> {
        s.iter().map(|(d, _)| (d * 1e6).round() / 1e6).collect()
    }

    /// Fanuc's G76 example: k 3.68, Δd 1.8, Δdmin 0.1, d 0.2, m 1:
    /// 1.8, 1.8·√2 = 2.545584, 1.8·√3 = 3.117691, 1.8·√4 = 3.6 ≥ 3.48 → 3.48, then 3.68.
    #[test]
    fn degressive_fanuc_example() {
        let spec =
            Spec { k: 3.68, first: 1.8, min: 0.1, allowance: 0.2, mode: DepthMode::Degressive, finish: 1, ..SPEC };
        let s = plan(&spec, 999).unwrap();
        assert_eq!(depths(&s), vec![1.8, 2.545584, 3.117691, 3.48, 3.68]);
        assert_eq!(
            s.iter().map(|p| p.1).collect::<Vec<_>>(),
            [Role::Rough, Role::Rough, Role::Rough, Role::Rough, Role::Finish]
        );
    }

    /// Δdmin raises small degressive cuts: Δd 0.5, Δdmin 0.2, k 1.3, d 0.1 → target 1.2:
    /// 0.5; 0.5√2 = 0.7071 (cut 0.2071 ≥ 0.2); 0.5√3 = 0.8660 (cut 0.1589 < 0.2 → 0.9071);
    /// then 1.1071, then 1.3071 ≥ 1.2 → 1.2; finishing 1.3, spring 1.3.
    #[test]
    fn degressive_with_minimum() {
        let spec =
            Spec { k: 1.3, first: 0.5, min: 0.2, allowance: 0.1, mode: DepthMode::Degressive, finish: 2, ..SPEC };
        let s = plan(&spec, 999).unwrap();
        let want = [0.5, 0.5 * 2f64.sqrt(), 0.5 * 2f64.sqrt() + 0.2, 0.5 * 2f64.sqrt() + 0.4, 1.2, 1.3, 1.3];
        assert_eq!(depths(&s), want.map(|d| (d * 1e6).round() / 1e6).to_vec());
        assert_eq!(s[5].1, Role::Finish);
        assert_eq!(s[6].1, Role::Spring);
    }

    /// Equal depth: Δd 0.4 to k − d = 1.2 − 0.05 = 1.15: 0.4, 0.8, 1.15 (clamped), 1.2.
    #[test]
    fn equal_depth() {
        let spec = Spec { k: 1.2, first: 0.4, min: 0.0, allowance: 0.05, mode: DepthMode::Equal, finish: 1, ..SPEC };
        assert_eq!(depths(&plan(&spec, 999).unwrap()), vec![0.4, 0.8, 1.15, 1.2]);
        // Δdmin above Δd raises every equal cut: Δd 0.1, Δdmin 0.5 → 0.5, 1.0, 1.15.
        let spec = Spec { first: 0.1, min: 0.5, ..spec };
        assert_eq!(depths(&plan(&spec, 999).unwrap()), vec![0.5, 1.0, 1.15, 1.2]);
    }

    /// d ≥ k: no roughing, the finishing pass cuts everything; d = 0: the finishing pass is at the roughing depth.
    #[test]
    fn allowance_edges() {
        let spec = Spec { k: 1.0, first: 0.3, min: 0.0, allowance: 1.0, mode: DepthMode::Equal, finish: 1, ..SPEC };
        assert_eq!(depths(&plan(&spec, 999).unwrap()), vec![1.0]);
        let spec = Spec { allowance: 0.0, ..spec };
        assert_eq!(depths(&plan(&spec, 999).unwrap()), vec![0.3, 0.6, 0.9, 1.0, 1.0]);
    }

    /// A schedule over the limit is refused with an estimate: Δd 0.001 degressive to
    /// 10 without Δdmin needs (10 / 0.001)² = 10⁸ passes.
    #[test]
    fn limit_and_estimate() {
        let spec =
            Spec { k: 10.0, first: 0.001, min: 0.0, allowance: 0.0, mode: DepthMode::Degressive, finish: 1, ..SPEC };
        assert_eq!(plan(&spec, 999), Err(100_000_001));
        let spec = Spec { k: 10.0, first: 0.01, min: 0.0, allowance: 0.0, mode: DepthMode::Equal, finish: 1, ..SPEC };
        assert_eq!(plan(&spec, 999), Err(1001));
        assert_eq!(plan(&spec, 1001).unwrap().len(), 1001);
    }
}
