//! The tool against a shoulder. A threading insert is as wide as its form
//! above the tip: at height y over its tip, each flank lies y·tan(A/2) from
//! the tip along Z, for an included angle A. Where the program turned a
//! shoulder beyond the thread's end (a face rising above the thread's
//! crest; an internal thread's: falling inside its bore), the leading flank
//! must reach the face's edge before the tip reaches the face: the tip must
//! stay (edge − tip)·tan(A/2) from the face along Z, at the end of the cut
//! and where the run-out takes it. A pass that comes nearer cuts into the
//! shoulder (reference threading.md §11; the insert's geometry as in
//! ISO 965-1's basic profile: flanks at A/2 either side of the radial).

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::figures::Shoulder;
use crate::message as msg;
use crate::motion::{MoveKind, Point};
use crate::thread::{Axis, Thread};

/// A face of the turned outline: its Z and the radii it spans.
#[derive(Clone, Copy, Debug)]
struct Face {
    z: f64,
    lo: f64,
    hi: f64,
}

/// The shoulder nearest the tool over thread `i`'s passes, with a warning where the tool cuts into it.
pub fn check(threads: &[Thread], i: usize, ctx: &Context, diags: &mut Diagnostics) -> Option<Shoulder> {
    let t = &threads[i];
    let p0 = t.passes.first()?;
    let half = (t.tool_angle / 2.0).to_radians();
    if t.long_axis != Axis::Z || !(half > 0.0 && half < std::f64::consts::FRAC_PI_2) {
        return None;
    }
    let sense = (p0.to.z - p0.from.z).signum();
    if sense == 0.0 {
        return None;
    }
    // The outline turned since the previous thread: its faces (a feed along X).
    let lo = if i == 0 { 0 } else { threads[i - 1].first_move };
    let hi = t.first_move.min(ctx.moves.len());
    let crest = t.crest / 2.0;
    let out = if t.internal { -1.0 } else { 1.0 };
    let window = &ctx.moves[lo.min(hi)..hi];
    let feeds = || window.iter().filter(|m| m.kind == MoveKind::Feed);
    // The turned diameters (feeds along Z), read once: each face asks them.
    let axial: Vec<&crate::motion::Move> =
        feeds().filter(|m| (m.to.z - m.from.z).abs() > 1e-9 && (m.to.x - m.from.x).abs() < 1e-9).collect();
    // A face (a feed along X) is a shoulder when the outline goes on beyond
    // it, in the cut's direction, at a diameter standing proud of the crest.
    let beyond = |z: f64| -> Option<f64> {
        axial
            .iter()
            .filter(|m| {
                let (near, far) = if (m.from.z - z).abs() < 1e-9 { (m.from, m.to) } else { (m.to, m.from) };
                (near.z - z).abs() < 1e-9 && (far.z - z) * sense > 1e-9
            })
            .map(|m| m.to.x / 2.0)
            .find(|&r| (r - crest) * out > 1e-9)
    };
    let faces: Vec<Face> = feeds()
        .filter(|m| (m.to.z - m.from.z).abs() < 1e-9 && (m.to.x - m.from.x).abs() > 1e-9)
        .filter_map(|m| {
            let r = beyond(m.to.z)?;
            let (a, b) = (m.from.x.min(m.to.x) / 2.0, m.from.x.max(m.to.x) / 2.0);
            // Its edge: where the outline beyond it runs (an internal thread's: inward).
            Some(if t.internal {
                Face { z: m.to.z, lo: r.max(a), hi: b }
            } else {
                Face { z: m.to.z, lo: a, hi: r.min(b) }
            })
        })
        .collect();
    let tan = half.tan();
    let mut best: Option<Shoulder> = None;
    for (k, p) in t.passes.iter().enumerate() {
        for tip in [Some(p.to), p.runout_to].into_iter().flatten() {
            for f in &faces {
                // Faces behind the cut's start are the work's other end, not in its way.
                if (f.z - p.from.z) * sense <= 1e-9 {
                    continue;
                }
                let ahead = (f.z - tip.z) * sense;
                let edge = if t.internal { f.lo } else { f.hi };
                let needed = ((edge - tip.x / 2.0) * out).max(0.0) * tan;
                let clearance = ahead - needed;
                if best.is_none_or(|b| clearance < b.clearance) {
                    best =
                        Some(Shoulder { z: f.z, edge_x: 2.0 * edge, pass: k, tip: [tip.x, tip.z], clearance, needed });
                }
            }
        }
    }
    let b = best?;
    if b.clearance < -1e-9 {
        let p = &t.passes[b.pass];
        let span = ctx.moves.get(p.moves.cut.start).map_or_else(|| (ctx.spans)(t.line), |m| m.span);
        let tip = Point { x: b.tip[0], z: b.tip[1] };
        diags.push(
            &msg::TOOL_SHOULDER,
            span,
            args![
                n = p.index,
                start = p.start,
                angle = t.tool_angle,
                z = b.z,
                x = b.edge_x,
                into = -b.clearance,
                need = b.needed,
                tipx = tip.x,
                tipz = tip.z
            ],
        );
    }
    Some(b)
}

/// The approach: a pass whose cut starts where the program turned the part
/// to a diameter beyond the pass's (above it; an internal thread's: inside
/// it) plunges into the part in rapid at the start. Warned once per thread,
/// at its first such pass.
pub fn approach(threads: &[Thread], i: usize, ctx: &Context, diags: &mut Diagnostics) {
    let t = &threads[i];
    if t.long_axis != Axis::Z {
        return;
    }
    let lo = if i == 0 { 0 } else { threads[i - 1].first_move };
    let hi = t.first_move.min(ctx.moves.len());
    let out = if t.internal { -1.0 } else { 1.0 };
    // The turned diameters (feeds along Z) as (low Z, high Z, X), read once.
    let axial: Vec<(f64, f64, f64)> = ctx.moves[lo.min(hi)..hi]
        .iter()
        .filter(|m| m.kind == MoveKind::Feed && (m.to.x - m.from.x).abs() < 1e-9 && (m.to.z - m.from.z).abs() > 1e-9)
        .map(|m| (m.from.z.min(m.to.z), m.from.z.max(m.to.z), m.to.x))
        .collect();
    let turned = |z: f64| -> Option<f64> {
        axial
            .iter()
            .filter(|&&(a, b, _)| z > a + 1e-9 && z < b - 1e-9)
            .map(|&(_, _, x)| x)
            .reduce(|a, b| if (b - a) * out > 0.0 { b } else { a })
    };
    // Passes mostly start at one Z: its answer is kept.
    let mut last: Option<(f64, Option<f64>)> = None;
    for p in &t.passes {
        let start = p.screw_in_from.unwrap_or(p.from);
        let part = match last {
            Some((z, part)) if z == start.z => part,
            _ => turned(start.z),
        };
        last = Some((start.z, part));
        let Some(part) = part else { continue };
        if (part - start.x) * out > 1e-6 {
            let span = ctx.moves.get(p.moves.cut.start).map_or_else(|| (ctx.spans)(t.line), |m| m.span);
            diags.push(
                &msg::APPROACH_INTO_PART,
                span,
                args![n = p.index, start = p.start, z = start.z, x = start.x, part],
            );
            return;
        }
    }
}
