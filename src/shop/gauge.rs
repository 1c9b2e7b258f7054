//! Will it gauge: the pitch diameter the passes cut, against the limits of
//! the thread's designation ([`crate::standard`]).
//!
//! The designation is the nearest comment before the thread's first block
//! (back to the previous thread) that names a thread of the lead or pitch
//! the program cuts, e.g. `(M48x2-6g)`; else the setting `thread.designation`.
//!
//! Pitch diameter (reference threading.md §9): a V tool of included angle
//! a and nose radius r (`tool.nose_radius`) whose final pass is at
//! diameter X cuts, on an external thread of pitch P,
//! d2 = X − 2r·(1/sin(a/2) − 1) + P/(2·tan(a/2)) — for 60°,
//! X − 2r + 0.866025·P; an internal thread mirrors it. The flanks are those
//! of the virtual sharp tip r·(1/sin(a/2) − 1) beyond the nose. With several
//! passes the thread space is the envelope of all of them, each placed along
//! the axis by where its synchronised cut started (a flank or alternating
//! infeed, a Z shift of a manual pass), so d2 is where that envelope is P/2
//! wide. Multi-start threads use pitch = lead / starts, each start on its
//! own. NPT (1:16 taper) has no pitch-diameter class: the cut taper is
//! compared with 1/16 and the plane where the cut pitch diameter is E0
//! (external; E1 internal) is where the L1 gauge sits.

use super::Context;
use super::designation::designation;
use super::load::{by_start, offset};
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::figures::{Gauge, OverWires};
use crate::message::{self as msg, Arg, Args, Message, Template};
use crate::settings::P;
use crate::standard::{self, Designation, Diameters, Kind, Limits, Taper};
use crate::thread::{Axis, CrestSource, Pass, Thread};

/// The tool as the pitch diameter sees it.
#[derive(Clone, Copy, Debug)]
struct Tool {
    /// tan(a/2).
    tan: f64,
    /// sin(a/2).
    sin: f64,
    /// Nose radius, program units.
    r: f64,
}

pub use super::insert::{FULL_PROFILE_RADIUS, FULL_PROFILE_RADIUS_INTERNAL, assumed_nose_radius};

impl Tool {
    /// The thread's tool for pitch `pitch`, and whether its nose radius was
    /// assumed (`tool.nose_radius` = 0: not known); `None` unless its angle
    /// is between 0° and 180°.
    fn of(t: &Thread, ctx: &Context, pitch: f64) -> Option<(Tool, bool)> {
        let a = t.tool_angle;
        if !(a > 0.0 && a < 180.0) {
            return None;
        }
        let h = a.to_radians() / 2.0;
        let given = ctx.settings.get(P::NoseRadius) / ctx.mm();
        // A full-profile insert forms the standard's root: its radius is known.
        let full =
            super::insert::of(ctx).is_some_and(|(i, _)| matches!(i.profile, crate::insert::Profile::Full { .. }));
        let (r, assumed) = if given > 0.0 { (given, false) } else { (assumed_nose_radius(pitch, t.internal), !full) };
        Some((Tool { tan: h.tan(), sin: h.sin(), r }, assumed))
    }

    /// How far the virtual sharp tip lies beyond the nose: r·(1/sin(a/2) − 1).
    fn beyond(&self) -> f64 {
        self.r * (1.0 / self.sin - 1.0)
    }

    /// Height above the virtual tip where the flanks leave the nose arc: r·cos²(a/2)/sin(a/2).
    fn tangent_height(&self) -> f64 {
        self.r * (1.0 - self.sin * self.sin) / self.sin
    }
}

/// What one start's passes cut.
#[derive(Clone, Copy, Debug)]
struct Cut {
    /// Pitch diameter.
    d2: f64,
    /// Diameter of the root the tool cuts (the deepest nose point).
    root: f64,
    /// The pitch line crosses the nose arc: the straight-flank formula does not hold.
    on_nose: bool,
}

/// Radius of the pass line at `z`.
fn radius_at(p: &Pass, z: f64) -> f64 {
    let dz = p.to.z - p.from.z;
    if dz.abs() < 1e-12 { p.from.r() } else { p.from.r() + (p.to.r() - p.from.r()) * (z - p.from.z) / dz }
}

/// The pitch diameter cut by the passes `idx` (one start) at `z`, the final
/// passes (those at the start's full depth) moved by `dx` (diameter).
fn envelope(t: &Thread, idx: &[usize], tool: Tool, pitch: f64, z: f64, dx: f64) -> Option<Cut> {
    let sigma = if t.internal { -1.0 } else { 1.0 };
    let full = idx.iter().map(|&k| t.passes[k].depth).fold(f64::MIN, f64::max);
    let last = &t.passes[*idx.last()?];
    let reference = last.screw_in_from.unwrap_or(last.from).z;
    // Each pass as (σ·radius of its virtual sharp tip, axial offset); depth grows as σ·radius falls.
    let mut tips = Vec::with_capacity(idx.len());
    let mut root = f64::INFINITY;
    for &k in idx {
        let p = &t.passes[k];
        let rho = radius_at(p, z) + if p.depth >= full - 1e-9 { dx / 2.0 } else { 0.0 };
        root = root.min(sigma * rho);
        tips.push((sigma * rho - tool.beyond(), offset(t, p, reference, pitch)));
    }
    let y0 = tips.iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
    let top = y0 + pitch / (4.0 * tool.tan);
    if !(y0.is_finite() && top.is_finite() && pitch > 0.0) {
        return None;
    }
    // The deepest pass alone is P/2 wide at `top`: higher tips do not matter.
    // Sorted by height, the space at height h spans from the lowest left
    // edge to the highest right edge of the tips below h: prefix extremes of
    // u + y·tan (left) and u − y·tan (right), each edge moving by h·tan.
    tips.retain(|t| t.0 <= top);
    crate::order::sort_by(&mut tips, |a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let (mut left, mut right) = (Vec::with_capacity(tips.len()), Vec::with_capacity(tips.len()));
    let (mut l, mut r) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(y, u) in &tips {
        l = l.min(u + y * tool.tan);
        r = r.max(u - y * tool.tan);
        left.push(l);
        right.push(r);
    }
    let y = pitch_height(&tips, &left, &right, tool.tan, pitch / 2.0, top);
    Some(Cut { d2: 2.0 * sigma * y, root: 2.0 * sigma * root, on_nose: y - y0 < tool.tangent_height() - 1e-12 })
}

/// The lowest height at which the space between the tips (sorted by height
/// `y`, with the prefix extremes `left` and `right` of their edges) is
/// `half` wide, at most `top`. Between two tip heights the width grows
/// linearly, c + 2·h·tan, and it jumps up where a tip joins: the first piece
/// that reaches `half` holds the answer.
fn pitch_height(tips: &[(f64, f64)], left: &[f64], right: &[f64], tan: f64, half: f64, top: f64) -> f64 {
    for k in 1..=tips.len() {
        let (lo, hi) = (tips[k - 1].0, tips.get(k).map_or(top, |t| t.0));
        let c = right[k - 1] - left[k - 1];
        if c + 2.0 * lo * tan >= half {
            return lo;
        }
        if tan > 0.0 {
            let at = (half - c) / (2.0 * tan);
            if at < hi {
                return at;
            }
        }
    }
    top
}

/// The passes of each start that has some.
fn starts(t: &Thread) -> Vec<Vec<usize>> {
    by_start(t).into_iter().filter(|idx| !idx.is_empty()).collect()
}

/// Z in the middle of the deepest pass: where a taper thread is measured.
fn middle_z(t: &Thread) -> f64 {
    let p = t.passes.iter().max_by(|a, b| a.depth.total_cmp(&b.depth)).unwrap_or(&t.passes[0]);
    (p.from.z + p.to.z) / 2.0
}

/// The pitch diameter the first start of `t` cuts with pitch `pitch`
/// (program units), for a thread along Z cut by a V tool.
pub fn cut_pitch_diameter(t: &Thread, pitch: f64, ctx: &Context) -> Option<f64> {
    if t.long_axis != Axis::Z || t.passes.is_empty() {
        return None;
    }
    let (tool, _) = Tool::of(t, ctx, pitch)?;
    envelope(t, starts(t).first()?, tool, pitch, middle_z(t), 0.0).map(|c| c.d2).filter(|d| d.is_finite())
}

/// The limits in program units.
fn dims(l: &Limits, mm: f64) -> (Diameters, Option<Taper>) {
    match (&l.inch, mm != 1.0) {
        (Some(inch), true) => (*inch, l.taper_inch),
        _ => {
            let s = |v: f64| v / mm;
            let lim = |x: standard::Limit| standard::Limit { min: x.min.map(s), max: x.max.map(s) };
            let d = &l.mm;
            let scaled = Diameters {
                basic_major: s(d.basic_major),
                basic_pitch: s(d.basic_pitch),
                basic_minor: s(d.basic_minor),
                basic_root: d.basic_root.map(s),
                major: lim(d.major),
                pitch: lim(d.pitch),
                minor: lim(d.minor),
            };
            let taper = l.taper.map(|t| Taper {
                e0: s(t.e0),
                e1: s(t.e1),
                l1: s(t.l1),
                l2: s(t.l2),
                e2: s(t.e2),
                height: s(t.height),
                ..t
            });
            (scaled, taper)
        }
    }
}

/// The thread check of `t` (whose previous thread ended on line `lower`),
/// with its verdict as a diagnostic; `None` when no designation names it
/// or the thread does not run along Z.
pub fn check(t: &Thread, lower: Option<u32>, ctx: &Context, diags: &mut Diagnostics) -> Option<Gauge> {
    if t.long_axis != Axis::Z || t.passes.is_empty() {
        return None;
    }
    let found = designation(t, lower, ctx, diags)?;
    let kind = if t.internal { Kind::Internal } else { Kind::External };
    let d = found.d.with_kind(kind);
    let span = (ctx.spans)(t.line);
    let limits = match standard::limits(&d) {
        Ok(l) => l,
        Err(e) => {
            diags.push_with(&msg::DESIGNATION_WITHOUT_LIMITS, span, || {
                args![designation = d.text.trim(), error = e.detail]
            });
            return None;
        }
    };
    let pitch = d.pitch_mm / ctx.mm();
    let Some((tool, assumed)) = Tool::of(t, ctx, pitch) else {
        diags.push_with(&msg::GAUGE_UNKNOWN_ANGLE, span, || args![designation = d.text.trim(), angle = t.tool_angle]);
        return None;
    };
    let (dm, taper) = dims(&limits, ctx.mm());
    let mut g = Gauge {
        designation: d.text.trim().to_string(),
        source: found.source,
        line: found.line,
        system: d.system,
        class: d.class.map(|c| c.to_string()),
        kind: d.kind,
        basic_major: dm.basic_major,
        basic_pitch: dm.basic_pitch,
        basic_minor: dm.basic_minor,
        pitch_diameter: f64::NAN,
        pitch_diameter_min: dm.pitch.min,
        pitch_diameter_max: dm.pitch.max,
        major_diameter: None,
        major_diameter_min: dm.major.min,
        major_diameter_max: dm.major.max,
        minor_diameter: None,
        minor_diameter_min: dm.minor.min,
        minor_diameter_max: dm.minor.max,
        ok: true,
        delta_x: None,
        nose_radius: tool.r,
        nose_radius_assumed: assumed,
        gauges_with_nose: None,
        taper: None,
        gauge_plane_z: None,
        over_wires: None,
        notes: Vec::new(),
    };
    match_designation(t, &d, ctx, &mut g);
    let from_insert = super::insert::of(ctx).filter(|(i, _)| matches!(i.profile, crate::insert::Profile::Full { .. }));
    if let (false, Some((_, name))) = (assumed || ctx.settings.get(P::NoseRadius) > 0.0, from_insert) {
        note(&mut g, &msg::NOTE_TOOL_INSERT, args![r = tool.r, insert = name.trim().to_string()]);
    }
    let done = match taper {
        Some(tp) => npt(t, tool, pitch, &tp, ctx, &mut g),
        None => straight(t, tool, pitch, &dm, &mut g),
    };
    done?;
    if !t.internal && g.taper.is_none() {
        g.over_wires = Some(over_wires(&g, t.tool_angle, pitch));
    }
    verdict(t, &g, span, diags);
    Some(g)
}

/// The best wire and the measurement over three wires for the check's pitch
/// diameter and its limits (see [`OverWires`]).
fn over_wires(g: &Gauge, angle: f64, pitch: f64) -> OverWires {
    let h = angle.to_radians() / 2.0;
    let wire = pitch / (2.0 * h.cos());
    let m = |d2: f64| d2 + wire * (1.0 + 1.0 / h.sin()) - pitch / 2.0 / h.tan();
    OverWires { wire, m: m(g.pitch_diameter), m_min: g.pitch_diameter_min.map(m), m_max: g.pitch_diameter_max.map(m) }
}

/// Notes (and a failed check) where the program is not the thread the designation names.
fn match_designation(t: &Thread, d: &Designation, ctx: &Context, g: &mut Gauge) {
    let mm = ctx.mm();
    let kind = if t.internal { Kind::Internal } else { Kind::External };
    if d.kind != kind {
        g.ok = false;
        let side = |internal: bool| if internal { &msg::INTERNAL } else { &msg::EXTERNAL };
        note(g, &msg::NOTE_KIND, args![want = side(d.kind == Kind::Internal), got = side(t.internal)]);
    }
    if (d.lead_mm - t.lead * mm).abs() > 1e-6 * d.lead_mm.max(1.0) {
        g.ok = false;
        let a = args![lead = t.lead * mm, designation = g.designation.clone(), want = d.lead_mm];
        note(g, &msg::NOTE_LEAD, a);
    } else if d.starts != t.starts {
        let a = args![designation = g.designation.clone(), n = d.starts, m = t.starts, pitch = d.pitch_mm];
        note(g, &msg::NOTE_STARTS, a);
    }
    if (t.tool_angle - 60.0).abs() > 1e-9 {
        g.ok = false;
        note(g, &msg::NOTE_TOOL_ANGLE, args![angle = t.tool_angle]);
    }
    if t.starts > 1 {
        note(g, &msg::NOTE_MULTI_START, args![pitch = t.lead / f64::from(t.starts)]);
    }
}

/// The check of an ISO or Unified thread (not tapered by its standard).
fn straight(t: &Thread, tool: Tool, pitch: f64, dm: &Diameters, g: &mut Gauge) -> Option<()> {
    let z = middle_z(t);
    let groups = starts(t);
    let all: Vec<Cut> = groups.iter().map(|idx| envelope(t, idx, tool, pitch, z, 0.0)).collect::<Option<_>>()?;
    let mid = match (dm.pitch.min, dm.pitch.max) {
        (Some(a), Some(b)) => Some((a + b) / 2.0),
        _ => None,
    };
    // The start farthest from the middle of the tolerance decides.
    let worst = (0..all.len()).max_by(|&a, &b| {
        let off = |k: usize| mid.map_or(0.0, |m| (all[k].d2 - m).abs());
        off(a).total_cmp(&off(b)).then(b.cmp(&a))
    })?;
    let cut = all[worst];
    g.pitch_diameter = cut.d2;
    if !cut.d2.is_finite() {
        return None;
    }
    let eps = 1e-9;
    let in_pitch = dm.pitch.min.is_none_or(|v| cut.d2 >= v - eps) && dm.pitch.max.is_none_or(|v| cut.d2 <= v + eps);
    if !in_pitch {
        g.ok = false;
    }
    if cut.on_nose {
        note(g, &msg::NOTE_ON_NOSE, args![]);
    }
    // The crest the program turned: the thread's own (from the outline), or the surface turned for a cycle's thread.
    let turned = if t.crest_source == CrestSource::Outline { Some(t.crest) } else { t.turned };
    let (outline, crest) = (turned.is_some(), turned.unwrap_or(t.crest));
    if t.internal {
        g.major_diameter = Some(cut.root);
        g.minor_diameter = turned;
        if dm.major.min.is_some_and(|v| cut.root < v - eps) {
            g.ok = false;
            note(g, &msg::NOTE_ROOT_BELOW_MAJOR, args![root = cut.root, min = dm.major.min.unwrap_or(0.0)]);
        }
        crest_check(g, outline, crest, dm.minor, &msg::BORE);
    } else {
        g.minor_diameter = Some(cut.root);
        g.major_diameter = turned;
        if dm.minor.max.is_some_and(|v| cut.root > v + eps) {
            g.ok = false;
            note(g, &msg::NOTE_ROOT_ABOVE_MINOR, args![root = cut.root, max = dm.minor.max.unwrap_or(0.0)]);
        }
        if dm.minor.min.is_some_and(|v| cut.root < v - eps) {
            note(g, &msg::NOTE_ROOT_BELOW_MINOR, args![root = cut.root, min = dm.minor.min.unwrap_or(0.0)]);
        }
        crest_check(g, outline, crest, dm.major, &msg::MAJOR);
    }
    if let Some(m) = mid {
        g.delta_x = delta_x(t, tool, pitch, z, &groups[worst], m);
    }
    if g.nose_radius_assumed {
        g.gauges_with_nose = nose_range(t, tool, pitch, z, &groups, dm.pitch);
        let range = match g.gauges_with_nose {
            Some([lo, hi]) => args![range = &msg::NOSE_RANGE, lo, hi],
            None => args![range = &msg::NOSE_NONE, hi = 0.25 * pitch],
        };
        let (template, factor) =
            if t.internal { (&msg::NOTE_TOOL_ASSUMED_INTERNAL, "0.108") } else { (&msg::NOTE_TOOL_ASSUMED, "0.125") };
        note(g, template, args![r = tool.r, factor = Arg::lit(factor)].with_all(range));
    }
    Some(())
}

/// The nose radii from 0 to 0.25·P for which every start's pitch diameter
/// is within `lim` (d2 moves steadily with r): sampled, then each end found
/// by bisection to 0.0001.
fn nose_range(
    t: &Thread,
    tool: Tool,
    pitch: f64,
    z: f64,
    groups: &[Vec<usize>],
    lim: standard::Limit,
) -> Option<[f64; 2]> {
    let fits = |r: f64| {
        let tool = Tool { r, ..tool };
        groups.iter().all(|idx| {
            envelope(t, idx, tool, pitch, z, 0.0)
                .is_some_and(|c| lim.min.is_none_or(|v| c.d2 >= v - 1e-9) && lim.max.is_none_or(|v| c.d2 <= v + 1e-9))
        })
    };
    let top = 0.25 * pitch;
    let steps = 50;
    let at = |k: usize| top * k as f64 / steps as f64;
    let first = (0..=steps).find(|&k| fits(at(k)))?;
    let last = (first..=steps).take_while(|&k| fits(at(k))).last().unwrap_or(first);
    // Narrow each end between a radius that fits and one that does not.
    let edge = |mut inside: f64, mut outside: f64| {
        while (inside - outside).abs() > 1e-5 {
            let mid = (inside + outside) / 2.0;
            if fits(mid) { inside = mid } else { outside = mid }
        }
        inside
    };
    let lo = if first == 0 { 0.0 } else { edge(at(first), at(first - 1)) };
    let hi = if last == steps { top } else { edge(at(last), at(last + 1)) };
    let round = |v: f64| (v * 1e4).round() / 1e4;
    Some([round(lo), round(hi)])
}

/// A turned crest within its limits; a note when the program did not turn it.
fn crest_check(g: &mut Gauge, turned: bool, crest: f64, lim: standard::Limit, what: &'static msg::Phrase) {
    if !turned {
        note(g, &msg::NOTE_CREST_NOT_TURNED, args![what]);
        return;
    }
    let eps = 1e-9;
    if lim.min.is_some_and(|v| crest < v - eps) || lim.max.is_some_and(|v| crest > v + eps) {
        g.ok = false;
        let show = |v: Option<f64>| v.map_or(Arg::lit("—"), Arg::Num);
        note(g, &msg::NOTE_CREST_OUTSIDE, args![what, crest, min = show(lim.min), max = show(lim.max)]);
    }
}

/// The change of the final passes' X that puts the pitch diameter of the
/// start whose passes are `idx` at `target`. d2 follows X one to one when
/// the final pass makes both flanks, more slowly when an earlier pass makes one.
fn delta_x(t: &Thread, tool: Tool, pitch: f64, z: f64, idx: &[usize], target: f64) -> Option<f64> {
    let mut dx = 0.0;
    for _ in 0..40 {
        let d2 = envelope(t, idx, tool, pitch, z, dx)?.d2;
        let err = target - d2;
        if err.abs() < 1e-9 {
            return Some(dx);
        }
        dx += err;
    }
    None
}

/// The check of an NPT thread: the taper and where the gauge plane is.
fn npt(t: &Thread, tool: Tool, pitch: f64, tp: &Taper, ctx: &Context, g: &mut Gauge) -> Option<()> {
    let p = t.passes.iter().max_by(|a, b| a.depth.total_cmp(&b.depth))?;
    let (za, zb) = (p.from.z, p.to.z);
    if (zb - za).abs() < 1e-9 {
        return None;
    }
    let taper = (p.to.x - p.from.x).abs() / (zb - za).abs();
    let first = starts(t).into_iter().next()?;
    let (a, b) = (envelope(t, &first, tool, pitch, za, 0.0)?.d2, envelope(t, &first, tool, pitch, zb, 0.0)?.d2);
    g.pitch_diameter = a.min(b);
    g.taper = Some(taper);
    let tol = ctx.settings.get(P::NptTaperTolerance);
    if (taper - tp.taper_on_diameter).abs() > tol + 1e-12 {
        g.ok = false;
        note(g, &msg::NOTE_NPT_TAPER, args![taper, tol]);
    }
    let (target, name) = if t.internal { (tp.e1, "E1") } else { (tp.e0, "E0") };
    if (b - a).abs() > 1e-12 {
        let z = za + (target - a) / (b - a) * (zb - za);
        g.gauge_plane_z = Some(z);
        if z < za.min(zb) - 1e-9 || z > za.max(zb) + 1e-9 {
            g.ok = false;
            note(g, &msg::NOTE_NPT_NEVER, args![name = Arg::lit(name), target]);
        }
        let end = if t.internal { &msg::FITTING_FACE } else { &msg::PIPE_END };
        note(g, &msg::NOTE_NPT_PLANE, args![name = Arg::lit(name), target, z, end, pitch]);
    }
    Some(())
}

/// The verdict as a diagnostic: `gauge-ok` with the numbers, or `gauge-fail` with the fix.
fn verdict(t: &Thread, g: &Gauge, span: crate::span::Span, diags: &mut Diagnostics) {
    let x = t.passes.iter().max_by(|a, b| a.depth.total_cmp(&b.depth)).map_or(0.0, |p| p.from.x);
    let side = match (g.pitch_diameter_min, g.pitch_diameter_max) {
        (_, Some(max)) if g.pitch_diameter > max + 1e-9 => &msg::TOO_LARGE,
        (Some(min), _) if g.pitch_diameter < min - 1e-9 => &msg::TOO_SMALL,
        _ => &msg::NOTHING,
    };
    let (template, side): (&'static Template, _) =
        if g.ok { (&msg::GAUGE_OK, None) } else { (&msg::GAUGE_FAIL, Some(side)) };
    diags.push_with(template, span, || {
        let mut a = args![designation = g.designation.clone(), d2 = g.pitch_diameter];
        if let Some(side) = side {
            a = a.with("side", side);
        }
        a = match (g.pitch_diameter_min, g.pitch_diameter_max, g.class.as_deref()) {
            (Some(lo), Some(hi), Some(c)) => {
                a.with("range", &msg::RANGE_CLASS).with("min", lo).with("max", hi).with("class", c)
            }
            (Some(lo), Some(hi), None) => a.with("range", &msg::RANGE).with("min", lo).with("max", hi),
            _ => a.with("range", &msg::NOTHING),
        };
        a = match g.delta_x {
            Some(dx) => a.with("fix", &msg::FIX).with("dx", dx).with("x", x + dx),
            None => a.with("fix", &msg::NOTHING),
        };
        a.with("notes", Arg::Notes(g.notes.clone()))
    });
}

/// Adds a note to the check.
fn note(g: &mut Gauge, template: &'static Template, args: Args) {
    g.notes.push(Message::new(template, args));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tool_geometry_of_a_60_degree_insert() {
        let tool = Tool { tan: 30f64.to_radians().tan(), sin: 0.5, r: 0.25 };
        // r·(1/sin 30° − 1) = 0.25; the flanks leave the nose at r·cos²30°/sin 30° = 0.375.
        assert!((tool.beyond() - 0.25).abs() < 1e-12);
        assert!((tool.tangent_height() - 0.375).abs() < 1e-12);
    }
}
