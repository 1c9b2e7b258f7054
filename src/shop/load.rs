//! Chip load: the area each pass removes from the thread space (the
//! envelope of the tool's cuts, [`crate::chip`]) against a constant-area
//! schedule for the same depth and number of passes, where pass k of N
//! reaches H·√(k/N) and every pass removes tan(a/2)·H²/N. Advice when the
//! first pass is heavier than the tool should take (`chip.first_pass_ratio`
//! times its even share, or more than `tool.max_chip_area`), when a pass
//! deepens the thread by less than `chip.min_infeed` (it rubs), and when a
//! pass removes nothing. Spring passes are meant to remove nothing and are
//! left alone.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::figures::ChipLoad;
use crate::geom::Frame;
use crate::message as msg;
use crate::settings::P;
use crate::thread::{Role, Thread};

/// Axial position of a pass's start along the long axis, reduced to one pitch
/// around `reference`: where its tool sits in the thread space (a start
/// later by a whole pitch cuts the same space one pitch on).
pub(super) fn offset(t: &Thread, p: &crate::thread::Pass, reference: f64, pitch: f64) -> f64 {
    let start = p.screw_in_from.unwrap_or(p.from);
    let d = Frame(t.long_axis).long(start) - reference;
    if pitch > 0.0 && d.is_finite() { d - pitch * (d / pitch).round() } else { 0.0 }
}

/// Passes of each start (indices into `t.passes`), starts in order.
pub(super) fn by_start(t: &Thread) -> Vec<Vec<usize>> {
    let mut out: Vec<Vec<usize>> = vec![Vec::new(); t.starts.max(1) as usize];
    for (k, p) in t.passes.iter().enumerate() {
        let si = (p.start.max(1) as usize - 1).min(out.len() - 1);
        out[si].push(k);
    }
    out
}

/// Most passes of one start whose areas are taken from the envelope of
/// their cuts (its work grows with the square of the passes); beyond it,
/// and whenever no pass is shifted along the axis, each pass removes the V
/// between the deepest depth before it and its own.
const ENVELOPE_PASSES: usize = 256;

/// The area each of `cuts` (depth, axial offset) removes with a V tool of `angle` degrees.
fn areas(angle: f64, cuts: &[(f64, f64)]) -> Vec<Option<f64>> {
    let shifted = cuts.iter().any(|c| c.1.abs() > 1e-12);
    if shifted && cuts.len() <= ENVELOPE_PASSES {
        return crate::chip::pass_areas(angle, cuts);
    }
    let mut deep = 0.0f64;
    cuts.iter()
        .map(|&(d, _)| {
            let a = crate::thread::v_area(angle, deep, d.max(deep));
            deep = deep.max(d);
            a
        })
        .collect()
}

/// Chip loads of every pass of `t`, and the advice about them.
pub fn chip_loads(t: &Thread, ctx: &Context, diags: &mut Diagnostics) -> Vec<ChipLoad> {
    let mut out = vec![ChipLoad::default(); t.passes.len()];
    let tan = (t.tool_angle > 0.0 && t.tool_angle < 180.0).then(|| (t.tool_angle.to_radians() / 2.0).tan());
    for (si, idx) in by_start(t).iter().enumerate() {
        let Some(&first) = idx.first() else { continue };
        let reference = Frame(t.long_axis).long(t.passes[first].screw_in_from.unwrap_or(t.passes[first].from));
        let cuts: Vec<(f64, f64)> =
            idx.iter().map(|&k| (t.passes[k].depth, offset(t, &t.passes[k], reference, t.pitch))).collect();
        let areas = areas(t.tool_angle, &cuts);
        let h = cuts.iter().map(|c| c.0).fold(0.0, f64::max);
        let n = idx.iter().filter(|&&k| t.passes[k].role != Role::Spring).count().max(1);
        let mut k = 0;
        for (j, &pi) in idx.iter().enumerate() {
            let spring = t.passes[pi].role == Role::Spring;
            if !spring {
                k += 1;
            }
            let even = if spring { 0.0 } else { 1.0 / n as f64 };
            out[pi] = ChipLoad {
                area: areas[j].map(|a| a.max(0.0)),
                even_area: tan.map(|tn| tn * h * h * even),
                even_depth: Some(h * (k as f64 / n as f64).sqrt()),
            };
        }
        if si == 0 {
            advise(t, idx, &out, ctx, diags);
        }
    }
    out
}

/// Advice about the passes `idx` (one start) of `t`.
fn advise(t: &Thread, idx: &[usize], loads: &[ChipLoad], ctx: &Context, diags: &mut Diagnostics) {
    if !ctx.settings.flag(P::Advice) {
        return;
    }
    let mm = ctx.mm();
    let s = ctx.settings;
    let span_of = |k: usize| (ctx.spans)(t.passes[k].lines.iter().copied().find(|l| *l >= t.line).unwrap_or(t.line));
    let a2 = |v: f64| v * mm * mm;
    if let Some(&k) = idx.first() {
        let (l, p) = (&loads[k], &t.passes[k]);
        let ratio = s.get(P::ChipFirstRatio);
        if let (Some(a), Some(e), true) = (l.area, l.even_area, ratio > 0.0) {
            if e > 0.0 && a > ratio * e * (1.0 + 1e-9) {
                diags.push_with(&msg::CHIP_HEAVY_FIRST, span_of(k), || {
                    let count = idx.iter().filter(|&&k| t.passes[k].role != Role::Spring).count();
                    let depth = idx.iter().map(|&k| t.passes[k].depth).fold(0.0, f64::max);
                    let start = l.even_depth.unwrap_or(0.0);
                    args![n = p.index, area = a2(a), ratio = a / e, even = a2(e), count, depth, limit = ratio, start]
                });
            }
        }
    }
    let max_area = s.get(P::ChipMaxArea);
    if max_area > 0.0 {
        let heavy = idx.iter().find(|&&k| loads[k].area.is_some_and(|a| a * mm * mm > max_area * (1.0 + 1e-9)));
        if let Some(&k) = heavy {
            diags.push_with(&msg::CHIP_OVER_TOOL, span_of(k), || {
                args![n = t.passes[k].index, area = a2(loads[k].area.unwrap_or(0.0)), max = max_area]
            });
        }
    }
    let min = s.get(P::ChipMinInfeed);
    for &k in idx {
        let p = &t.passes[k];
        if p.role == Role::Spring {
            continue;
        }
        let removes_nothing = match loads[k].area {
            Some(a) => a <= 1e-12,
            None => p.infeed <= 1e-9,
        };
        if removes_nothing {
            diags.push_with(&msg::CHIP_NONE, span_of(k), || args![n = p.index, depth = p.depth]);
        } else if p.infeed > 0.0 && p.infeed * mm < min - 1e-9 {
            diags.push_with(&msg::CHIP_THIN, span_of(k), || args![n = p.index, infeed = p.infeed, min]);
        }
    }
}
