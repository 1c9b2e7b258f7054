//! Words the threading commands share: the lead (F, I), the start angle
//! (Q) and the cycle depths (P(k), Q(Δd), Q(Δdmin), R(d)), each read by the
//! unit rule of the controller ([`Unit`], [`super::ThreadRules`]).

use super::{Reader, ThreadRules};
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::schedule::{DminRule, FinishRule};
use crate::message::{self as msg, Arg};
use crate::num::EPS;
use crate::settings::P;

use super::reader::g_span;

/// The unit of a word that carries an angle or a cycle depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// An integer in least input increments (0.001 mm, 0.001°); a decimal point is an alarm (Fanuc).
    IncrementsNoPoint,
    /// By a parameter (GSK NO182.7): 0 = least input increments, a decimal
    /// point changes nothing (`Q180.0` is 0.18°); 1 = mm and degrees.
    ByParameter(P),
}

/// The largest lead F takes (500 mm, in the program's unit).
fn max_lead(inch: bool) -> f64 {
    if inch { 500.0 / 25.4 } else { 500.0 }
}

/// Reads the lead of a thread block: F (lead per revolution) or, where the
/// controller has it, I (threads per inch: 25.4/I mm, 1/I in an inch
/// program). Both are modal in the lead register. Reports a missing lead
/// and returns `None`.
pub fn lead(r: &mut Reader, t: &ThreadRules, b: &Block, what: &str) -> Option<f64> {
    let f = b.get(b'F').copied();
    let i = if t.tpi_word { b.get(b'I').copied() } else { None };
    if let (Some(_), Some(i)) = (f, i) {
        r.diag(&msg::LEAD_TWICE, i.span, args![what]);
        return None;
    }
    let inch = r.m.inch;
    if let Some(f) = f {
        let v = r.length(&f);
        if !(v > 0.0 && v <= max_lead(inch)) {
            r.diag(&msg::LEAD_OUT_OF_RANGE, f.span, args![word = f, max = max_lead(inch), unit = msg::unit(inch)]);
            return None;
        }
        r.m.lead = Some(v);
        r.m.lead_from_feed = None;
    } else if let Some(i) = i {
        let tpi = i.value();
        if !(0.06..=25400.0).contains(&tpi) {
            r.diag(&msg::TPI_OUT_OF_RANGE, i.span, args![tpi]);
            return None;
        }
        r.m.lead = Some(if inch { 1.0 / tpi } else { 25.4 / tpi });
        r.m.lead_from_feed = None;
    }
    if let (None, Some(line), Some(lead)) = (f, r.m.lead_from_feed, r.m.lead) {
        lead_from_feed(r, b, what, line, lead)?;
    }
    if r.m.lead.is_none() {
        missing_lead(r, t, b, what);
        return None;
    }
    r.m.lead
}

/// With one F register, a thread block without F cuts the feed's F as its
/// lead: warned, or an alarm when that F cannot be a lead.
fn lead_from_feed(r: &mut Reader, b: &Block, what: &str, line: u32, lead: f64) -> Option<()> {
    let span = g_span(b);
    if !(lead > 0.0 && lead <= max_lead(r.m.inch)) {
        r.diag(&msg::FEED_REGISTER_NOT_A_LEAD, span, args![what, lead, line]);
        return None;
    }
    r.diag(&msg::LEAD_FROM_FEED, span, args![what, lead, line]);
    Some(())
}

#[cold]
fn missing_lead(r: &mut Reader, t: &ThreadRules, b: &Block, what: &str) {
    let span = g_span(b);
    let or_tpi = if t.tpi_word { &msg::OR_TPI } else { &msg::NOTHING };
    match r.m.feed {
        Some(feed) if feed > 0.0 && !r.rules.shared_f_register => {
            let a = args![what, feed, line = r.m.feed_line, controller = Arg::lit(short_title(r)), or_tpi];
            r.diag(&msg::MISSING_LEAD_FEED_APART, span, a)
        }
        _ => r.diag(&msg::MISSING_LEAD, span, args![what, or_tpi]),
    }
}

/// The controller's title up to its model number ("GSK" of "GSK980TDc").
pub(super) fn short_title(r: &Reader) -> &'static str {
    let t = r.rules.title();
    t.find(|c: char| c.is_ascii_digit() || c == ' ').map_or(t, |i| &t[..i])
}

/// Reads a start angle word in degrees by the controller's unit rule.
pub fn start_angle(r: &mut Reader, t: &ThreadRules, q: &Word) -> Option<f64> {
    let deg = match t.angle {
        Unit::IncrementsNoPoint => {
            if q.num.has_point {
                r.diag(&msg::START_ANGLE_NO_POINT, q.span, args![word = q]);
                return None;
            }
            q.value() * 0.001
        }
        Unit::ByParameter(p) => {
            if r.s.flag(p) {
                q.value()
            } else {
                q.value() * r.s.angle_increment()
            }
        }
    };
    if !(0.0..=360.0 + EPS).contains(&deg) {
        r.diag(&msg::START_ANGLE_OUT_OF_RANGE, q.span, args![word = q, deg]);
        return None;
    }
    Some(deg)
}

/// Reads a cycle depth word (P(k), Q(Δd), Q(Δdmin)) by the controller's unit rule.
pub fn depth(r: &mut Reader, t: &ThreadRules, w: &Word, what: &str) -> Option<f64> {
    let inc = r.s.length_increment(r.m.inch);
    match t.depth {
        Unit::IncrementsNoPoint => {
            if w.num.has_point {
                r.diag(&msg::DEPTH_NO_POINT, w.span, args![word = w, what, per = 1.0 / inc]);
                return None;
            }
            Some(w.value() * inc)
        }
        Unit::ByParameter(p) => {
            if r.s.flag(p) {
                return Some(w.value());
            }
            if w.num.has_point {
                let a = args![word = w, what, value = w.value() * inc, unit = msg::unit(r.m.inch)];
                r.diag(&msg::DEPTH_POINT_IGNORED, w.span, a);
            }
            Some(w.value() * inc)
        }
    }
}

/// What the second block of G76 and G78 always gives: the lead, the thread
/// height P(k) and the first depth Q(Δd), each checked; `None` after an
/// alarm. `what` names the cycle in messages.
pub fn height_and_first_depth(
    r: &mut Reader,
    t: &ThreadRules,
    b: &Block,
    g: &Word,
    what: &str,
) -> Option<(f64, f64, f64)> {
    let lead = lead(r, t, b, what)?;
    let Some(pk) = b.get(b'P').copied() else {
        r.diag(&msg::MISSING_THREAD_HEIGHT, g.span, args![what]);
        return None;
    };
    let Some(qd) = b.get(b'Q').copied() else {
        r.diag(&msg::MISSING_FIRST_DEPTH, g.span, args![what]);
        return None;
    };
    let k = depth(r, t, &pk, "P(k)")?;
    let dd = depth(r, t, &qd, "Q(Δd)")?;
    let inc = r.s.length_increment(r.m.inch);
    let ok = r.in_range(&pk, k, inc, 99999.999, &msg::THREAD_HEIGHT_K)
        && r.in_range(&qd, dd, inc, 99999.999, &msg::FIRST_DEPTH);
    ok.then_some((lead, k, dd))
}

/// Reads the first block's Q(Δdmin) and R(d) (G76, G78) into `dmin` and
/// `d` when written (they keep their value otherwise); false after an alarm.
pub fn min_cut_and_allowance(
    r: &mut Reader,
    t: &ThreadRules,
    b: &Block,
    dmin: &mut Option<f64>,
    d: &mut Option<f64>,
) -> bool {
    if let Some(w) = b.get(b'Q').copied() {
        let Some(v) = depth(r, t, &w, "Q(Δdmin)") else { return false };
        if !r.in_range(&w, v, 0.0, 99.9999, &msg::MIN_DEPTH) {
            return false;
        }
        *dmin = Some(v);
    }
    if let Some(w) = b.get(b'R').copied() {
        let v = r.length(&w);
        if !r.in_range(&w, v, 0.0, 99.9999, &msg::FINISH_ALLOWANCE) {
            return false;
        }
        *d = Some(v);
    }
    true
}

/// How a degressive cut below Δdmin is raised (setting `cycle.dmin_rule`).
pub fn dmin_rule(r: &Reader) -> DminRule {
    if r.s.int(P::DminRule) == 1 { DminRule::Printed } else { DminRule::Previous }
}

/// How the finishing passes share the allowance (setting `cycle.finish_rule`).
pub fn finish_rule(r: &Reader) -> FinishRule {
    if r.s.int(P::FinishRule) == 1 { FinishRule::Split } else { FinishRule::Steps }
}
