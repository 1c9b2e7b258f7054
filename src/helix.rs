//! Passes that cut another helix on the surface the others thread: a
//! different lead, or a start (angle or axial position) that is not a whole
//! number of leads from theirs. On the machine that pass cross-threads the
//! part.
//!
//! A pass's helix is its lead and its phase, the fraction of a turn
//! `Q/360 + z/lead` (a pass that starts one lead further along, or at the
//! same place one turn later, cuts the same helix). Threads the grouper
//! made one after another on the same stretch of the same diameter are one
//! surface. Where the passes of a surface cut several helices, the few that
//! differ from the most are warned about; helices cut by equal numbers of
//! passes are the starts of a multi-start thread and are not.

use crate::args;
use crate::diagnostic::Diagnostics;
use crate::geom::Frame;
use crate::message as msg;
use crate::motion::{Move, Point};
use crate::num::{EPS, close, round_out, same_lead};
use crate::span::Span;
use crate::thread::{Axis, Pass, Thread};
use glam::DVec2;

/// The most helices one surface is sorted into; past it the passes drift
/// and none is warned about (the sorting stays linear in the passes).
const MAX_HELICES: usize = 360;

/// One pass as a helix: its thread, lead and phase (turns, 0 ≤ φ < 1).
struct Helix<'a> {
    pass: &'a Pass,
    lead: f64,
    phase: f64,
    start: f64,
}

impl<'a> Helix<'a> {
    /// Pass `p` of thread `t` as a helix, along the axis of frame `f`.
    fn of(f: Frame, t: &Thread, p: &'a Pass) -> Helix<'a> {
        let start = f.long(p.from);
        // A cycle's flank infeed moves each pass along the axis on purpose (its shift).
        let phase = phase(p.angle, start, f.long(p.to), p.shift, t.lead);
        Helix { pass: p, lead: t.lead, phase, start }
    }
}

/// Adds a `cross-thread` warning to each pass of `threads` that cuts
/// another helix than most passes on its surface. `max_infeed` (leads) is
/// how far apart two passes may start across the axis and still be on the
/// same surface (setting `group.max_infeed`); `spans` gives each line's span.
pub fn check(
    threads: &[Thread],
    moves: &[Move],
    max_infeed: f64,
    spans: &dyn Fn(u32) -> Span,
    diags: &mut Diagnostics,
) {
    let mut i = 0;
    while i < threads.len() {
        let mut j = i + 1;
        while j < threads.len() && same_surface(&threads[j - 1], &threads[j], max_infeed) {
            j += 1;
        }
        surface(&threads[i..j], moves, spans, diags);
        i = j;
    }
}

/// Whether `b` threads the same stretch of the same diameter as `a`.
fn same_surface(a: &Thread, b: &Thread, max_infeed: f64) -> bool {
    if a.long_axis != b.long_axis || a.units != b.units || a.passes.is_empty() || b.passes.is_empty() {
        return false;
    }
    let f = Frame::along(a.long_axis);
    let range = |t: &Thread| {
        let p = &t.passes[0];
        let (x, y) = (f.long(p.from), f.long(p.to));
        (x.min(y), x.max(y))
    };
    let ((a0, a1), (b0, b1)) = (range(a), range(b));
    let overlap = a1.min(b1) - a0.max(b0);
    let shorter = (a1 - a0).min(b1 - b0);
    let across = (f.short(a.passes[0].from) - f.short(b.passes[0].from)).abs();
    overlap >= 0.5 * shorter && across <= max_infeed * a.lead.max(b.lead)
}

/// Warns about the passes of one surface that cut a minority helix.
fn surface(threads: &[Thread], moves: &[Move], spans: &dyn Fn(u32) -> Span, diags: &mut Diagnostics) {
    let f = Frame::along(threads[0].long_axis);
    let same = |a: &Helix, b: &Helix| same_lead(a.lead, b.lead) && same_phase(a.phase, b.phase);
    // Most surfaces cut one helix: nothing to warn about, and nothing to
    // collect (every plan checks every surface again).
    let Some(first) = threads.iter().find_map(|t| t.passes.first().map(|p| Helix::of(f, t, p))) else { return };
    if threads.iter().all(|t| t.passes.iter().all(|p| same(&first, &Helix::of(f, t, p)))) {
        return;
    }
    let helices: Vec<Helix> = threads.iter().flat_map(|t| t.passes.iter().map(move |p| Helix::of(f, t, p))).collect();
    if helices.len() < 3 {
        return;
    }
    // Each helix with how many passes cut it.
    let mut kinds: Vec<(usize, usize)> = Vec::new(); // (first pass index, count)
    for (k, h) in helices.iter().enumerate() {
        if let Some(kind) = kinds.iter_mut().find(|(f, _)| same(&helices[*f], h)) {
            kind.1 += 1;
        } else if kinds.len() >= MAX_HELICES {
            // Passes drifting along the axis pass by pass (a flank infeed written block by
            // block) cut as many helices as passes: no main helix to warn against.
            return;
        } else {
            kinds.push((k, 1));
        }
    }
    let most = kinds.iter().map(|k| k.1).max().unwrap_or(0);
    if kinds.len() < 2 || kinds.iter().all(|k| k.1 == most) {
        return;
    }
    let main = kinds.iter().find(|k| k.1 == most).map_or(0, |k| k.0);
    let m = &helices[main];
    let lines = helices.iter().filter(|h| same(m, h)).flat_map(|h| h.pass.lines.iter().copied());
    let (from, to) = lines.fold((u32::MAX, 0), |(a, b), l| (a.min(l), b.max(l)));
    for &(first, count) in &kinds {
        // A helix cut by at most half as many passes as the main one is a mistake, not a start.
        if 2 * count > most {
            continue;
        }
        for h in helices.iter().filter(|h| same(&helices[first], h)) {
            let span = cut_span(h.pass, moves, spans);
            if !same_lead(h.lead, m.lead) {
                diags.push(&msg::CROSS_LEAD, span, args![lead = h.lead, n = most, from, to, other = m.lead]);
                continue;
            }
            let turn = round_out(360.0 * signed_gap(h.phase, m.phase).abs());
            let a = args![turn, n = most, from, to];
            let a = if close(h.pass.angle, m.pass.angle) {
                a.with("why", &msg::START_Z).with("z", h.start).with("at", m.start)
            } else {
                a.with("why", &msg::START_ANGLE).with("q", h.pass.angle).with("at", m.pass.angle)
            };
            diags.push(&msg::CROSS_PHASE, span, a);
        }
    }
}

/// The helix a cut starts, as a fraction of a turn (0 ≤ φ < 1): its start
/// angle `angle` (degrees) plus its start `start` along the thread's axis in
/// leads, less the axial `shift` a cycle gives it on purpose; a cut toward
/// larger coordinates (`end` > `start`) turns the phase the other way. Two
/// cuts of one lead with equal phases cut one groove: a start angle θ is
/// the same helix as an axial shift of lead·θ/360° (GSK980TDc user manual
/// §3.24.1, G32's Q: the starts of a multi-start thread are its passes
/// 360°/starts apart).
pub fn phase(angle: f64, start: f64, end: f64, shift: f64, lead: f64) -> f64 {
    let sense = if end < start { 1.0 } else { -1.0 };
    turns(angle / 360.0 + sense * (start - shift) / lead)
}

/// `x` in whole turns dropped (0 ≤ result ≤ 1): `x.rem_euclid(1.0)`, the
/// same value (a zero may differ in sign), by `floor` instead of the
/// remainder, which is a slow call natively and a loop in wasm; the check
/// takes one per pass of a plan at every keystroke.
fn turns(x: f64) -> f64 {
    // Exact for x ≥ 0; for x < 0 one rounding of the same sum as rem_euclid's.
    x - x.floor()
}

/// How far back a cut at start angle `angle` (degrees) begins at angle 0
/// on the same helix, as a shift of its points (true (Z, radius)): lead·θ/360°
/// (within one lead) along the axis, back along its first synchronised move
/// `from` → `to` (on a taper, along the cone). `None` when the angle is 0,
/// the lead is not positive or that move does not run along `axis`.
pub fn start_back(from: Point, to: Point, angle: f64, lead: f64, axis: Axis) -> Option<DVec2> {
    if angle == 0.0 || lead <= 0.0 {
        return None;
    }
    let along = Frame::along(axis).travel(from, to);
    if along.abs() < EPS {
        return None;
    }
    let d = (lead * angle / 360.0).rem_euclid(lead);
    Some((from.zr() - to.zr()) * (d / along.abs()))
}

/// Whether two phases (turns) are one helix.
pub fn same_phase(a: f64, b: f64) -> bool {
    phase_gap(a, b) < 1e-3
}

/// The span of the block that cuts `p` (its synchronised move), else of its first line.
fn cut_span(p: &Pass, moves: &[Move], spans: &dyn Fn(u32) -> Span) -> Span {
    moves.get(p.moves.cut.start).map_or_else(|| spans(p.lines.first().copied().unwrap_or(1)), |m| m.span)
}

/// How far apart two phases are, either way round (turns, 0 … 0.5).
fn phase_gap(a: f64, b: f64) -> f64 {
    let d = turns(a - b);
    crate::num::min(d, 1.0 - d)
}

/// `a − b` in turns, in −0.5 … 0.5.
fn signed_gap(a: f64, b: f64) -> f64 {
    let d = turns(a - b);
    if d > 0.5 { d - 1.0 } else { d }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `turns` is `rem_euclid(1.0)`: the same number for phases as they come
    /// (angles / 360 plus starts in leads, either sign, tiny and large).
    #[test]
    fn turns_are_the_euclidean_remainder() {
        let mut xs = vec![0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1e-20, -1e-20, 1e-300, -1e-300, 123456.789, -123456.789];
        xs.extend([f64::EPSILON, -f64::EPSILON, 1.0 - f64::EPSILON, -(1.0 - f64::EPSILON), 3e15 + 0.5, -3e15 - 0.5]);
        let mut x = -7.3;
        while x < 7.3 {
            xs.push(x);
            x += 0.013_7;
        }
        for lead in [0.35, 0.7, 1.5, 2.0, 25.4 / 13.0, 4.0] {
            for z in [-47.3, -5.0, -0.001, 0.0, 3.1, 70.0] {
                xs.push(z / lead);
                xs.push(90.0 / 360.0 - z / lead);
            }
        }
        for x in xs {
            let (got, want) = (turns(x), x.rem_euclid(1.0));
            assert!(got == want && (0.0..=1.0).contains(&got), "{x}: {got} ≠ {want}");
        }
    }

    #[test]
    fn a_start_angle_is_an_axial_shift_of_lead_times_angle() {
        // Lead 4 toward −Z: Q180 at Z5 and Q0 at Z7 cut one groove; Z6 is another.
        let at = |angle, z: f64| phase(angle, z, -30.0, 0.0, 4.0);
        assert!(same_phase(at(180.0, 5.0), at(0.0, 7.0)));
        assert!((phase_gap(at(0.0, 5.0), at(0.0, 7.0)) - 0.5).abs() < 1e-12);
        assert!(!same_phase(at(0.0, 5.0), at(0.0, 6.0)));
        // Toward +Z the shift turns the other way: Q90 at Z0 is Z−1 at Q0.
        assert!(same_phase(phase(90.0, 0.0, 30.0, 0.0, 4.0), phase(0.0, -1.0, 30.0, 0.0, 4.0)));
    }

    #[test]
    fn phases_wrap() {
        assert!((phase_gap(0.95, 0.05) - 0.1).abs() < 1e-12);
        assert!((signed_gap(0.05, 0.95) - 0.1).abs() < 1e-12);
        assert!((signed_gap(0.95, 0.05) + 0.1).abs() < 1e-12);
    }
}
