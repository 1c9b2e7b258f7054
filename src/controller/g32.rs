//! G32, constant-lead thread cutting (GSK980TDc and Fanuc 0i).
//!
//! One block is one straight synchronised cut from the current point to the
//! end point; consecutive G32 blocks make a continuous thread. On GSK the
//! block may end in a run-out given by J (short-axis amount, signed) and K
//! (long-axis length), modal across consecutive thread blocks; parameter
//! No.107 can instead fix the run-out speed. Q is the start angle.

use super::reader::axis_span;
use super::{Reader, ThreadRules, words};
use crate::args;
use crate::block::Block;
use crate::cycle::{classify, split_runout};
use crate::event::{Event, Piece, Seg};
use crate::geom::Frame;
use crate::message::{self as msg};
use crate::num::EPS;
use crate::settings::P;
use crate::thread::Source;

/// Effective run-out `(J, K)` from the J/K rules of the GSK manual, or `None`
/// for no run-out: J (or J and K) omitted → none; J = 0 → none; K omitted or
/// 0 → K = |J|. K has no sign.
pub fn runout_rule(j: Option<f64>, k: Option<f64>) -> Option<(f64, f64)> {
    match (j, k) {
        (None, _) => None,
        (Some(0.0), _) => None,
        (Some(j), None) => Some((j, j.abs())),
        (Some(j), Some(0.0)) => Some((j, j.abs())),
        (Some(j), Some(k)) => Some((j, k.abs())),
    }
}

/// Interprets one G32 block; `tool_angle` is the angle of the tool in force.
pub fn block(r: &mut Reader, t: &ThreadRules, b: &Block, tool_angle: f64) {
    if !r.check_words(b, t.g32_words, "G32") {
        r.end_chain();
        return;
    }
    let Some(lead) = words::lead(r, t, b, "G32") else {
        r.end_chain();
        return;
    };
    // Start angle: only the first block of a continuous thread counts.
    let mut angle = 0.0;
    if let Some(q) = b.get(b'Q').copied() {
        let Some(a) = words::start_angle(r, t, &q) else {
            r.end_chain();
            return;
        };
        if r.m.chain {
            r.diag(&msg::Q_IGNORED, q.span, args![word = q]);
        } else {
            angle = a;
        }
    }
    let start = r.current(b.span);
    let end = r.target(b).p;
    let Some((kind, long)) = classify(start, end) else {
        r.diag(&msg::G32_NO_MOVE, axis_span(b), args![]);
        r.end_chain();
        return;
    };
    let runout = if t.g32_runout { runout(r, b, lead, Frame(long).travel(start, end).abs()) } else { None };
    let (to, runout_to) = match runout {
        Some((j, k)) => {
            let (c, o) = split_runout(start, end, long, j, k);
            (c, Some(o))
        }
        None => (end, None),
    };
    let seg = Seg { from: start, to, runout_to, kind, long };
    piece(r, Source::G32, lead, angle, seg, end, b, tool_angle);
}

/// GSK's J/K run-out, modal across consecutive thread blocks, checked
/// against the long-axis `travel`.
fn runout(r: &mut Reader, b: &Block, lead: f64, travel: f64) -> Option<(f64, f64)> {
    let jw = b.get(b'J').copied();
    let kw = b.get(b'K').copied();
    let j = match jw {
        Some(w) => Some(r.length(&w)),
        None => r.m.jk.0,
    };
    let k = match kw {
        Some(w) => Some(r.length(&w)),
        None => r.m.jk.1,
    };
    r.m.jk = (j, k);
    let (j, k) = runout_rule(j, k)?;
    let k = runout_speed_rule(r, b, lead, j, k);
    if k > travel + EPS {
        let span = kw.or(jw).map_or(axis_span(b), |w| w.span);
        r.diag(&msg::RUNOUT_K_TOO_LONG, span, args![k, travel]);
        return None;
    }
    Some((j, k))
}

/// Gives a block-by-block thread piece — the synchronised cut, then the
/// run-out — and moves the tool to its end (`end` without a run-out).
#[allow(clippy::too_many_arguments)]
pub fn piece(
    r: &mut Reader,
    source: Source,
    lead: f64,
    angle: f64,
    seg: Seg,
    end: crate::motion::Point,
    b: &Block,
    tool_angle: f64,
) {
    let approach = r.m.last_x.0;
    r.arrive(seg.runout_to.unwrap_or(end), true, true, b.line);
    r.m.chain = true;
    let spindle = r.spindle();
    r.emit(Event::Piece(Piece { source, lead, angle, seg, line: b.line, span: b.span, approach, tool_angle, spindle }));
}

/// Parameter No.107: when non-zero the short axis retracts at that speed
/// (mm/min) while the long axis keeps the thread feed lead × S, so the
/// run-out takes `|J| × lead × S / No.107` of long-axis travel. Reports
/// which rule applied and returns the long-axis run-out length.
fn runout_speed_rule(r: &mut Reader, b: &Block, lead: f64, j: f64, k: f64) -> f64 {
    let v = r.s.get(P::No107);
    if v == 0.0 {
        return k;
    }
    let span = b.get(b'J').or(b.get(b'K')).map_or(axis_span(b), |w| w.span);
    match r.m.spindle {
        Some(s) if s > 0.0 && !r.m.css => {
            let unit = if r.m.inch { 25.4 } else { 1.0 };
            let feed = lead * unit * s; // mm/min along the long axis
            let len = j.abs() * feed / v;
            let angle = (j.abs()).atan2(len).to_degrees();
            let a = args![speed = v, feed, lead, s, j = j.abs(), len = len / unit, angle, k];
            r.diag(&msg::RUNOUT_BY_NO107, span, a);
            len / unit
        }
        _ => {
            r.diag(&msg::NO107_WITHOUT_SPINDLE, span, args![v]);
            k
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::Point;
    use crate::thread::{Axis, ThreadKind};

    #[test]
    fn runout_rules_of_the_manual() {
        // 1/2) J omitted, or J and K omitted: no run-out.
        assert_eq!(runout_rule(None, None), None);
        assert_eq!(runout_rule(None, Some(3.0)), None);
        // 2) K omitted: K = J.
        assert_eq!(runout_rule(Some(2.0), None), Some((2.0, 2.0)));
        assert_eq!(runout_rule(Some(-2.0), None), Some((-2.0, 2.0)));
        // 3) J = 0 or J = 0, K = 0: none.
        assert_eq!(runout_rule(Some(0.0), None), None);
        assert_eq!(runout_rule(Some(0.0), Some(0.0)), None);
        // 4) J ≠ 0, K = 0: K = J.
        assert_eq!(runout_rule(Some(1.5), Some(0.0)), Some((1.5, 1.5)));
        // 5) J = 0, K ≠ 0: none.
        assert_eq!(runout_rule(Some(0.0), Some(4.0)), None);
        // K has no direction.
        assert_eq!(runout_rule(Some(1.0), Some(-4.0)), Some((1.0, 4.0)));
    }

    #[test]
    fn long_axis_counts_x_as_radius() {
        // ΔX 21.4285 (radius 10.71) against ΔZ 75: Z is long.
        assert_eq!(classify(Point::new(27.4286, 3.0), Point::new(48.8571, -72.0)), Some((ThreadKind::Taper, Axis::Z)));
        // ΔX 30 (radius 15) against ΔZ 10: X is long.
        assert_eq!(classify(Point::new(20.0, 0.0), Point::new(50.0, -10.0)), Some((ThreadKind::Taper, Axis::X)));
        // ΔX 30 (radius 15) against ΔZ 20: Z is long although 30 > 20.
        assert_eq!(classify(Point::new(20.0, 0.0), Point::new(50.0, -20.0)), Some((ThreadKind::Taper, Axis::Z)));
        assert_eq!(classify(Point::new(20.0, 0.0), Point::new(20.0, -20.0)), Some((ThreadKind::Straight, Axis::Z)));
        assert_eq!(classify(Point::new(20.0, 0.0), Point::new(60.0, 0.0)), Some((ThreadKind::Face, Axis::X)));
        assert_eq!(classify(Point::new(20.0, 0.0), Point::new(20.0, 0.0)), None);
    }
}
