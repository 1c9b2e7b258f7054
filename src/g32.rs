//! G32, constant-lead thread cutting (GSK980TDc and Fanuc 0i).
//!
//! One block is one straight synchronised cut from the current point to the
//! end point; consecutive G32 blocks make a continuous thread. On GSK the
//! block may end in a run-out given by J (short-axis amount, signed) and K
//! (long-axis length), modal across consecutive thread blocks; parameter
//! No.107 can instead fix the run-out speed. Q is the start angle.

use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::dialect::Dialect;
use crate::group::{Seg, cut_piece};
use crate::interp::Interp;
use crate::motion::Point;
use crate::num::{EPS, fmt};
use crate::settings::P;
use crate::span::Span;
use crate::thread::{Axis, Source, ThreadKind};

/// Reads the lead of a thread block: F (lead per revolution) or, on GSK, I
/// (threads per inch: 25.4/I mm, 1/I in an inch program). Both are modal in
/// the lead register. Reports a missing lead and returns `None`.
pub fn read_lead(it: &mut Interp, b: &Block, what: &str) -> Option<f64> {
    let f = b.get(b'F').copied();
    let i = if it.dialect == Dialect::Gsk980tdc { b.get(b'I').copied() } else { None };
    if let (Some(_), Some(i)) = (f, i) {
        it.diag(
            Code::UnexpectedWord,
            i.span,
            format!("{what}: give the lead once, F (lead) or I (threads per inch), not both"),
        );
        return None;
    }
    if let Some(f) = f {
        let v = it.length(&f);
        let max = if it.inch { 500.0 / 25.4 } else { 500.0 };
        if !(v > 0.0 && v <= max) {
            it.diag(
                Code::ValueOutOfRange,
                f.span,
                format!("lead {} is outside 0.001..{} {}", f.display(), fmt(max), if it.inch { "in" } else { "mm" }),
            );
            return None;
        }
        it.lead = Some(v);
        it.lead_from_feed = None;
    } else if let Some(i) = i {
        let tpi = i.value();
        if !(0.06..=25400.0).contains(&tpi) {
            it.diag(Code::ValueOutOfRange, i.span, format!("{} threads per inch is outside 0.06..25400", fmt(tpi)));
            return None;
        }
        it.lead = Some(if it.inch { 1.0 / tpi } else { 25.4 / tpi });
        it.lead_from_feed = None;
    }
    if let (None, Some(line), Some(lead)) = (f, it.lead_from_feed, it.lead) {
        let span = b.all(b'G').next().map_or(b.span, |w| w.span);
        let max = if it.inch { 500.0 / 25.4 } else { 500.0 };
        if !(lead > 0.0 && lead <= max) {
            it.diag(
                Code::MissingLead,
                span,
                format!(
                    "{what} has no F, and the F register holds F{} from line {line}, which cannot be a lead; give the lead in this block",
                    fmt(lead)
                ),
            );
            return None;
        }
        it.diag(
            Code::LeadFromFeed,
            span,
            format!(
                "{what} has no F: the single F register holds F{} from line {line}, a feed rate, so this thread is cut with a lead of {}; give the lead in this block",
                fmt(lead),
                fmt(lead)
            ),
        );
    }
    if it.lead.is_none() {
        let span = b.all(b'G').next().map_or(b.span, |w| w.span);
        let msg = match (it.dialect, it.feed) {
            (Dialect::Gsk980tdc, Some(feed)) if feed > 0.0 => format!(
                "{what} without a lead: the feed F{} of line {} is not a lead (GSK keeps the thread lead apart); give F (lead) or I (threads per inch)",
                fmt(feed),
                it.feed_line
            ),
            _ => format!(
                "{what} without a lead: give F (lead){}",
                if it.dialect == Dialect::Gsk980tdc { " or I (threads per inch)" } else { "" }
            ),
        };
        it.diag(Code::MissingLead, span, msg);
        return None;
    }
    it.lead
}

/// Reads a start angle word in degrees by the dialect's unit rule.
pub fn start_angle(it: &mut Interp, q: &Word) -> Option<f64> {
    let deg = match it.dialect {
        Dialect::Fanuc0i => {
            if q.num.has_point {
                it.diag(
                    Code::DecimalPointNotAllowed,
                    q.span,
                    format!(
                        "{}: the start angle is in 0.001° and takes no decimal point (Q180000 = 180°)",
                        q.display()
                    ),
                );
                return None;
            }
            q.value() * 0.001
        }
        _ => {
            if it.s.flag(P::No182_7) {
                q.value()
            } else {
                // Increment mode: the decimal point does not change the unit (Q180.0 = 0.18°).
                q.value() * it.s.angle_increment()
            }
        }
    };
    if !(0.0..=360.0 + EPS).contains(&deg) {
        it.diag(
            Code::ValueOutOfRange,
            q.span,
            format!("start angle {} is {}°, outside 0..360°", q.display(), fmt(deg)),
        );
        return None;
    }
    Some(deg)
}

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

/// Geometry of one thread piece from `from` to the programmed `end`.
pub fn classify(from: Point, end: Point) -> Option<(ThreadKind, Axis)> {
    let dr = (end.x - from.x) / 2.0;
    let dz = end.z - from.z;
    if dr.abs() < EPS && dz.abs() < EPS {
        return None;
    }
    let kind = if dr.abs() < EPS {
        ThreadKind::Straight
    } else if dz.abs() < EPS {
        ThreadKind::Face
    } else {
        ThreadKind::Taper
    };
    let long = if dr.abs() > dz.abs() { Axis::X } else { Axis::Z };
    Some((kind, long))
}

/// Splits a piece into its synchronised cut and run-out: the run-out takes
/// the last `k` of the long-axis travel and ends displaced by `j` on the
/// short axis (radial when the short axis is X). Returns (cut end, run-out end).
pub fn split_runout(from: Point, end: Point, long: Axis, j: f64, k: f64) -> (Point, Point) {
    let travel = match long {
        Axis::Z => (end.z - from.z).abs(),
        Axis::X => ((end.x - from.x) / 2.0).abs(),
    };
    let t = if travel > 0.0 { ((travel - k) / travel).clamp(0.0, 1.0) } else { 1.0 };
    let cut_end = from.lerp(end, t);
    let out = match long {
        Axis::Z => end.offset_r(j, 0.0),
        Axis::X => Point::new(end.x, end.z + j),
    };
    (cut_end, out)
}

/// Interprets one G32 block.
pub fn block(it: &mut Interp, b: &Block) {
    let gsk = it.dialect == Dialect::Gsk980tdc;
    let allowed: &[u8] = if gsk { b"XZUWIJKQ" } else { b"XZUWQ" };
    if !it.check_words(b, allowed, "G32") {
        it.end_thread_chain();
        return;
    }
    let Some(lead) = read_lead(it, b, "G32") else {
        it.end_thread_chain();
        return;
    };
    // Start angle: only the first block of a continuous thread counts.
    let continuing = it.grouper.chain.is_some();
    let mut angle = 0.0;
    if let Some(q) = b.get(b'Q').copied() {
        let Some(a) = start_angle(it, &q) else {
            it.end_thread_chain();
            return;
        };
        if continuing {
            it.diag(
                Code::QIgnored,
                q.span,
                format!(
                    "{}: in a continuous thread only the first block's start angle counts; this Q is ignored",
                    q.display()
                ),
            );
        } else {
            angle = a;
        }
    }
    let start = it.current(b.span);
    let t = it.target(b);
    let end = t.p;
    let Some((kind, long)) = classify(start, end) else {
        it.diag(Code::ZeroLengthThread, axis_span(b), "G32 does not move: the end point is the start point");
        it.end_thread_chain();
        return;
    };
    // Run-out (GSK): J/K modal across consecutive thread blocks.
    let mut runout = None;
    if gsk {
        let jw = b.get(b'J').copied();
        let kw = b.get(b'K').copied();
        let j = match jw {
            Some(w) => Some(it.length(&w)),
            None => it.jk.0,
        };
        let k = match kw {
            Some(w) => Some(it.length(&w)),
            None => it.jk.1,
        };
        it.jk = (j, k);
        if let Some((j, k)) = runout_rule(j, k) {
            let travel = match long {
                Axis::Z => (end.z - start.z).abs(),
                Axis::X => ((end.x - start.x) / 2.0).abs(),
            };
            let k = runout_speed_rule(it, b, lead, j, k);
            if k > travel + EPS {
                let span = kw.or(jw).map_or(axis_span(b), |w| w.span);
                it.diag(
                    Code::RunoutTooLong,
                    span,
                    format!(
                        "run-out length K = {} is longer than the thread's {} of long-axis travel",
                        fmt(k),
                        fmt(travel)
                    ),
                );
            } else {
                runout = Some((j, k));
            }
        }
    }
    let (cut_end, out) = match runout {
        Some((j, k)) => {
            let (c, o) = split_runout(start, end, long, j, k);
            (c, Some(o))
        }
        None => (end, None),
    };
    let seg = Seg { from: start, to: cut_end, runout_to: out, kind, long };
    cut_piece(it, Source::G32, lead, angle, seg, end, b.line, b.span);
}

/// Parameter No.107: when non-zero the short axis retracts at that speed
/// (mm/min) while the long axis keeps the thread feed lead × S, so the
/// run-out takes `|J| × lead × S / No.107` of long-axis travel. Reports
/// which rule applied and returns the long-axis run-out length.
fn runout_speed_rule(it: &mut Interp, b: &Block, lead: f64, j: f64, k: f64) -> f64 {
    let v = it.s.get(P::No107);
    if v == 0.0 {
        return k;
    }
    let span = b.get(b'J').or(b.get(b'K')).map_or(axis_span(b), |w| w.span);
    match it.spindle {
        Some(s) if s > 0.0 && !it.css => {
            let unit = if it.inch { 25.4 } else { 1.0 };
            let feed = lead * unit * s; // mm/min along the long axis
            let len = j.abs() * feed / v;
            let angle = (j.abs()).atan2(len).to_degrees();
            it.diag(
                Code::RunoutSpeed,
                span,
                format!(
                    "run-out by parameter No.107: short axis at {} mm/min against the thread feed {} mm/min (lead {} × S{}): it retracts {} over {} of long-axis travel, {}° from the axis (K = {} is not used)",
                    fmt(v),
                    fmt(feed),
                    fmt(lead),
                    fmt(s),
                    fmt(j.abs()),
                    fmt(len / unit),
                    fmt(angle),
                    fmt(k)
                ),
            );
            len / unit
        }
        _ => {
            it.diag(
                Code::RunoutSpeed,
                span,
                format!(
                    "parameter No.107 = {} sets the run-out speed, but the spindle speed (S under G97) is unknown: the run-out is drawn from J and K",
                    fmt(v)
                ),
            );
            k
        }
    }
}

/// Span of the block's axis words (for alarms about the motion itself).
pub fn axis_span(b: &Block) -> Span {
    let mut span: Option<Span> = None;
    for w in &b.words {
        if matches!(w.letter, b'X' | b'Z' | b'U' | b'W') {
            span = Some(span.map_or(w.span, |s| s.cover(w.span)));
        }
    }
    span.unwrap_or(b.span)
}

#[cfg(test)]
mod tests {
    use super::*;

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
