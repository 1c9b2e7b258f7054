//! Cycle time of a thread (reference threading.md §9): every synchronised
//! motion takes its long-axis travel / (lead × n) — the run-out and the
//! screw-in are synchronised too — and the approach, retract and return
//! rapids take the longer of their axes' times at the machine's rapid rates
//! (`machine.rapid_x` for the cross slide's radial travel,
//! `machine.rapid_z`). Acceleration is not modelled.

use super::Context;
use crate::motion::Move;
use crate::settings::{P, Settings};
use crate::thread::{Pass, Thread};

/// Spindle speed (rev/min) a pass is cut at: S under G97; under G96 the
/// speed of surface speed S at the pass's start diameter (n = 1000·V/(π·D),
/// V m/min; 12·V/(π·D) with V ft/min and D inches after G20), clamped by the
/// G50 S clamp and `machine.max_rpm`. `None` without a positive S.
pub fn pass_rpm(p: &Pass, mm: f64, s: &Settings) -> Option<f64> {
    let v = p.spindle.s.filter(|v| v.is_finite() && *v > 0.0)?;
    if !p.spindle.css {
        return Some(v);
    }
    // Surface speed in mm/min: m/min × 1000, ft/min × 304.8.
    let surface = if mm == 1.0 { v * 1000.0 } else { v * 304.8 };
    let d = p.from.x.abs() * mm;
    let mut n = if d > 0.0 { surface / (std::f64::consts::PI * d) } else { f64::INFINITY };
    if let Some(c) = p.spindle.clamp {
        n = n.min(c);
    }
    Some(n.min(s.get(P::MaxRpm)))
}

/// Travel along the long axis of a motion: the larger of |ΔZ| and |ΔX|/2
/// (X counted as a radius, reference §2).
pub fn long_travel(m: &Move) -> f64 {
    (m.to.z - m.from.z).abs().max((m.to.x - m.from.x).abs() / 2.0)
}

/// Seconds a rapid takes: each axis at its own rate, the slower one sets the time.
pub fn rapid_time(m: &Move, mm: f64, s: &Settings) -> f64 {
    let x = (m.to.x - m.from.x).abs() / 2.0 * mm / s.get(P::RapidX);
    let z = (m.to.z - m.from.z).abs() * mm / s.get(P::RapidZ);
    60.0 * x.max(z)
}

/// The motions `r` of the plan (none when the range is not there).
fn slice(moves: &[Move], r: std::ops::Range<usize>) -> &[Move] {
    moves.get(r).unwrap_or(&[])
}

/// The times of a thread, seconds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Times {
    /// Synchronised motions of every pass.
    pub cut: f64,
    /// With the rapids.
    pub total: f64,
    /// Each pass's time with its rapids, in the order of the passes.
    pub passes: Vec<f64>,
}

/// The times of a thread; `None` when a pass has no known spindle speed.
pub fn thread_times(t: &Thread, ctx: &Context) -> Option<Times> {
    let (mm, s) = (ctx.mm(), ctx.settings);
    let mut times = Times { passes: Vec::with_capacity(t.passes.len()), ..Times::default() };
    for p in &t.passes {
        let n = pass_rpm(p, mm, s)?;
        let feed = t.lead * n; // program units per minute
        if !(feed.is_finite() && feed > 0.0) {
            return None;
        }
        let cut = slice(ctx.moves, p.moves.cut.clone()).iter().map(long_travel).sum::<f64>() / feed * 60.0;
        let rapid: f64 = [p.moves.approach.clone(), p.moves.retract.clone()]
            .into_iter()
            .map(|r| slice(ctx.moves, r).iter().map(|m| rapid_time(m, mm, s)).sum::<f64>())
            .sum();
        times.cut += cut;
        times.total += cut + rapid;
        times.passes.push(cut + rapid);
    }
    (times.total.is_finite()).then_some(times)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::Dialect;
    use crate::motion::{MoveKind, Point};
    use crate::thread::Spindle;

    #[test]
    fn rapids_take_the_slower_axis() {
        let s = Settings::new(Dialect::Gsk980tdc);
        // X58 → X100 is 21 mm of radius at 5000 mm/min: 0.252 s; Z 10 mm at 10000: 0.06 s.
        let m =
            Move { kind: MoveKind::Rapid, from: Point::new(58.0, 0.0), to: Point::new(100.0, 10.0), ..Move::default() };
        assert!((rapid_time(&m, 1.0, &s) - 0.252).abs() < 1e-12);
        // The same in inches: 25.4 times longer.
        assert!((rapid_time(&m, 25.4, &s) - 0.252 * 25.4).abs() < 1e-9);
    }

    #[test]
    fn css_speed_follows_the_diameter_and_its_clamps() {
        let s = Settings::new(Dialect::Fanuc0i);
        let mut p = Pass { from: Point::new(50.0, 0.0), ..Pass::default() };
        p.spindle = Spindle { s: Some(150.0), css: true, clamp: None };
        // 1000·150/(π·50) = 954.93 rev/min.
        assert!((pass_rpm(&p, 1.0, &s).unwrap() - 954.929_658_551_372).abs() < 1e-9);
        p.spindle.clamp = Some(800.0);
        assert_eq!(pass_rpm(&p, 1.0, &s), Some(800.0));
        // On the axis the machine's maximum holds.
        p.from.x = 0.0;
        p.spindle.clamp = None;
        assert_eq!(pass_rpm(&p, 1.0, &s), Some(4000.0));
        p.spindle = Spindle { s: Some(300.0), css: false, clamp: None };
        assert_eq!(pass_rpm(&p, 1.0, &s), Some(300.0));
        p.spindle.s = None;
        assert_eq!(pass_rpm(&p, 1.0, &s), None);
    }
}
