//! Machine limits and the speed rules of a thread (reference threading.md §9):
//!
//! - the thread feed lead × n against `machine.max_thread_feed` (beyond it
//!   many controls clamp the feed without an alarm and the lead comes out
//!   wrong), with the highest speed that fits;
//! - the spindle speed against `machine.max_rpm`;
//! - threads cut under G96 (the speed changes with X: threads want G97);
//! - the lead-in δ1 ≈ n·L/500 and run-out δ2 ≈ n·L/1800 the axis needs to
//!   reach and leave the thread feed (`machine.delta1_divisor`,
//!   `machine.delta2_divisor`; L in mm, δ in mm), against the program's δ1
//!   and δ2: measured against the work it turned before the thread, or,
//!   when it turned none, the textbook's O1006 values (`shop.assumed_lead_in`,
//!   `shop.assumed_run_out`). The textbook's fixed 2–10 mm advice stays in
//!   [`crate::advice`].

use super::time::pass_rpm;
use super::{ClearanceSource, Context, Shop};
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::message::{self as msg, Arg};
use crate::settings::P;
use crate::span::Span;
use crate::thread::{Pass, Thread};

/// The span of a pass's first synchronised motion (its cut block), else the thread's first line.
fn cut_span(t: &Thread, p: &Pass, ctx: &Context) -> Span {
    ctx.moves.get(p.moves.cut.start).filter(|_| !p.moves.cut.is_empty()).map_or_else(|| (ctx.spans)(t.line), |m| m.span)
}

/// Speed checks of thread `i`; fills the speed figures of `shop`.
pub fn check(threads: &[Thread], i: usize, ctx: &Context, shop: &mut Shop, diags: &mut Diagnostics) {
    let t = &threads[i];
    let (mm, s) = (ctx.mm(), ctx.settings);
    let lead_mm = t.lead * mm;
    let speeds: Vec<Option<f64>> = t.passes.iter().map(|p| pass_rpm(p, mm, s)).collect();
    let Some((fast, n)) =
        speeds.iter().enumerate().filter_map(|(k, n)| n.map(|n| (k, n))).max_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return;
    };
    shop.rpm = Some(n);
    shop.thread_feed = Some(t.lead * n);
    let max_feed = s.get(P::MaxThreadFeed);
    let fits = (max_feed / lead_mm).floor();
    shop.rpm_limit = Some(fits);
    if lead_mm * n > max_feed + 1e-9 {
        let p = &t.passes[fast];
        diags.push_with(&msg::THREAD_FEED_LIMIT, cut_span(t, p, ctx), || {
            args![feed = lead_mm * n, lead = lead_mm, n, max = max_feed, fits]
        });
    }
    spindle_checks(t, ctx, diags);
    clearances(threads, i, ctx, n, shop, diags);
}

/// A spindle speed over `machine.max_rpm` (G97) and a thread under G96: once per thread each.
fn spindle_checks(t: &Thread, ctx: &Context, diags: &mut Diagnostics) {
    let max = ctx.settings.get(P::MaxRpm);
    let over = t.passes.iter().find(|p| !p.spindle.css && p.spindle.s.is_some_and(|v| v > max + 1e-9));
    if let Some(p) = over {
        let v = p.spindle.s.unwrap_or(0.0);
        diags.push_with(&msg::SPINDLE_LIMIT, cut_span(t, p, ctx), || args![s = v, max]);
    }
    let css = t.passes.iter().find(|p| p.spindle.css && p.spindle.s.is_some());
    if let Some(p) = css {
        let n = pass_rpm(p, ctx.mm(), ctx.settings).unwrap_or(0.0);
        let unit = if ctx.inch { "ft/min" } else { "m/min" };
        diags.push_with(&msg::THREAD_CSS, cut_span(t, p, ctx), || {
            args![s = p.spindle.s.unwrap_or(0.0), unit = Arg::lit(unit), n = n.round(), x = p.from.x]
        });
    }
}

/// δ1 and δ2 from the speed `n` against the program's, filled into `shop`.
fn clearances(threads: &[Thread], i: usize, ctx: &Context, n: f64, shop: &mut Shop, diags: &mut Diagnostics) {
    let t = &threads[i];
    let (mm, s) = (ctx.mm(), ctx.settings);
    let nl = n * t.lead * mm; // mm/min
    let need1 = nl / s.get(P::Delta1Divisor) / mm;
    let need2 = nl / s.get(P::Delta2Divisor) / mm;
    shop.lead_in_needed = Some(need1);
    shop.run_out_needed = Some(need2);
    let (d1, d2, source) = match crate::advice::measured_clearances(threads, i, ctx.moves, s) {
        Some((d1, d2)) => (Some(d1), Some(d2), ClearanceSource::Outline),
        None => {
            let pos = |v: f64| Some(v / mm).filter(|v| *v > 0.0);
            (pos(s.get(P::AssumedLeadIn)), pos(s.get(P::AssumedRunOut)), ClearanceSource::Assumed)
        }
    };
    if d1.is_none() && d2.is_none() {
        return;
    }
    shop.lead_in = d1;
    shop.run_out = d2;
    shop.clearance_source = Some(source);
    let span = (ctx.spans)(t.line);
    let assumed = source == ClearanceSource::Assumed;
    // The figures both messages give; the lower speed only when one fits.
    let figures = |d: f64, divisor: f64, need: f64, how: &'static msg::Phrase| {
        let a = args![d, divisor, need, n = n.round(), lead = t.lead, how, more = (need - d).abs()];
        let fits = (n * d / need).floor();
        if fits >= 1.0 { a.with("slower", &msg::SLOWER).with("fits", fits) } else { a.with("slower", &msg::NOTHING) }
    };
    if let Some(d1) = d1.filter(|d| *d < need1 - 1e-9) {
        diags.push_with(&msg::DELTA1_SPEED, span, || {
            let how = if assumed { &msg::ASSUMED_LEAD_IN } else { &msg::PROGRAM_LEAD_IN };
            figures(d1, s.get(P::Delta1Divisor), need1, how)
        });
    }
    // A cut that ends inside the turned work (δ2 ≤ 0) ends where the thread is
    // meant to end, which the program does not say: not judged, as the textbook's advice.
    if let Some(d2) = d2.filter(|d| *d > 0.0 && *d < need2 - 1e-9) {
        diags.push_with(&msg::DELTA2_SPEED, span, || {
            let how = if assumed { &msg::ASSUMED_RUN_OUT } else { &msg::PROGRAM_RUN_OUT };
            figures(d2, s.get(P::Delta2Divisor), need2, how)
        });
    }
}
