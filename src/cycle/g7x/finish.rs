//! LinuxCNC's G70 `Q- X- Z- D- E- P- F-`, the finishing cycle, as rs274
//! runs it (`g7x::do_g70` in `interp_g7x.cc`; the G-code manual's G70: D
//! the distance of the first pass, E of the last, P the number of passes):
//! the profile is read as for G71 (`read`), turned when it goes back along
//! Z but not along X (a facing profile), mirrored, its corners made and
//! its lead-in squared; then each pass, from P down to 1, runs it offset
//! by `(pass − 1)·(D − E)/P + E`: a rapid to the start, a rapid to the
//! offset profile's first point, and the rest fed (arcs as arcs). P counts
//! whole passes (P2.5 runs two, the distances still over 2.5); the tool
//! stays at the end of the last.

use super::seg::Seg;
use super::walk::Out;
use super::{Emit, Fail, Frame, MAX_CUTS, Roughing, Step, finish_corners, mirror, monotone, offset, pieces, turn};
use crate::motion::Point;
use crate::span::Span;

/// G70's words: the distances of the first and last passes and how many passes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Passes {
    /// D: the first pass's distance from the profile (0 without D).
    pub d: f64,
    /// E: the last pass's distance (0 without E).
    pub e: f64,
    /// P: the number of passes (1 without P).
    pub p: f64,
    /// The program's lengths are inches (rs274's arc tolerances).
    pub inch: bool,
}

/// Most passes planned of one G70.
const MAX_PASSES: i64 = 1000;

/// G70 from `start` over the profile `steps`, made by the block at `line`/`span`.
pub fn plan(w: &Passes, start: Point, steps: &[Step], line: u32, span: Span) -> Roughing {
    let mut path = pieces(start, steps);
    if path.len() <= 1 {
        return Roughing::default();
    }
    let fail = |f| Roughing { moves: Vec::new(), fail: Some(f) };
    let mut frame = Frame::default();
    match turned(&path[1..]) {
        Ok(true) => turn(&mut path, &mut frame),
        Ok(false) => {}
        Err(f) => return fail(f),
    }
    mirror(&mut path, &mut frame);
    match finish_corners(&mut path) {
        Ok(true) => {}
        Ok(false) => return Roughing::default(),
        Err(f) => return fail(f),
    }
    if let Err(f) = monotone(&mut path) {
        return fail(f);
    }
    // C++ turns P into a whole number of passes by dropping its fraction.
    let count = if w.p.is_finite() { w.p.trunc().clamp(0.0, 1e15) as i64 } else { 0 };
    let mut moves = Vec::new();
    let mut at = start;
    // The passes rs274 runs first, at most MAX_PASSES of them.
    for pass in ((count - MAX_PASSES).max(0) + 1..=count).rev() {
        let distance = (pass - 1) as f64 * (w.d - w.e) / w.p + w.e;
        let mut offset = path.clone();
        if let Err(f) = offset::add_distance(&mut offset, distance) {
            return Roughing { moves, fail: Some(f) };
        }
        let out = pass_moves(&offset);
        let emit = Emit { frame, finished: distance == 0.0, inch: w.inch, line, span };
        if let Some(f) = emit.moves(&out, &mut at, &mut moves) {
            return Roughing { moves, fail: Some(f) };
        }
        if moves.len() > 8 * MAX_CUTS {
            return Roughing { moves, fail: Some(Fail::TooMany { limit: MAX_CUTS }) };
        }
    }
    let fail = (count > MAX_PASSES).then_some(Fail::TooMany { limit: MAX_PASSES as usize });
    Roughing { moves, fail }
}

/// Whether the profile without its lead-in runs one way along the cut only
/// once turned a quarter (a facing profile); `Err` when neither way.
fn turned(profile: &[Seg]) -> Result<bool, Fail> {
    let mut probe = profile.to_vec();
    let mut f = Frame::default();
    mirror(&mut probe, &mut f);
    let turn_it = !probe.iter().all(Seg::monotone);
    if turn_it {
        turn(&mut probe, &mut f);
        mirror(&mut probe, &mut f);
    }
    monotone(&mut probe).map(|()| turn_it)
}

/// One pass over the offset profile: a rapid to the start, a rapid to the
/// profile's first point, and the rest fed.
fn pass_moves(path: &[Seg]) -> Vec<Out> {
    let mut out = Vec::with_capacity(path.len() + 1);
    if let Some(lead) = path.first() {
        out.push(Out::Rapid(lead.s));
        out.push(Out::Rapid(lead.e));
    }
    for s in path.iter().skip(1) {
        out.push(match s.shape {
            super::seg::Shape::Line => Out::Feed(s.e, true),
            super::seg::Shape::Arc { ccw, c } => Out::Arc { ccw, c, to: s.e },
        });
    }
    out
}
