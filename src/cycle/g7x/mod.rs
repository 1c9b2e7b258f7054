//! LinuxCNC's lathe roughing cycles `G71 Q- X- Z- D- I- R- F-` (turning,
//! cuts along Z) and `G72 …` (facing, cuts along X), with G71.1/G72.1 (no
//! pockets roughed) and G71.2/G72.2 (only the pockets), and the finishing
//! cycle G70, planned move for move as LinuxCNC 2.9's interpreter plans
//! them. Learnt from the G-code manual's sections "G70 Lathe finishing
//! cycle" and "G71 G72 Lathe roughing cycles" (`docs/src/gcode/g-code.adoc`:
//! Q the profile subroutine, X/Z the start point, D the distance left to
//! the profile, I the cutting increment, R the retract; A and C corners)
//! and from the interpreter's source `src/emc/rs274ngc/interp_g7x.cc`
//! (`convert_g7x`, `g7x::do_g70`, `do_g71`, `add_distance`, `pocket`), at
//! the packaged commit, compared with what `rs274` prints
//! (`tests/linuxcnc/oword-g70-*`, `oword-g71-*`, `oword-g72-*`).
//!
//! The profile is the subroutine's moves from the start point (the first,
//! the lead-in, is the move to its first point). G72 turns it a quarter
//! turn, so that both cycles cut along the real axis of the frame (`cx`);
//! it is then mirrored so that it runs with the cut coordinate falling
//! from the start and the depth growing to its end, which lets one walk
//! rough an external or internal, left or right profile. A profile that
//! turns back along the cut is refused ("Not monotonic"). The profile is
//! offset by D away from the material (`offset`: outside corners become
//! arcs) and, when it ends below the start's depth, closed by a move up to
//! it. Then `walk` roughs it: cuts at depths I apart from the start's
//! depth, each to where the profile next crosses it, and the profile
//! followed where it rises; pockets (type II profiles) are roughed as they
//! come. The rapids in from the start follow the lead-in, so the cuts'
//! starts step along the line to the profile's first point. There is no
//! finishing pass: the profile offset by D is the last pass, and the tool
//! stays at its end (rs274 does not go back to the start).
//!
//! G70, the finishing cycle, runs the same profile through the same frame,
//! corners and offset (`finish`). Each move is checked as rs274 checks it
//! when it makes it (`emit`: an arc whose radius from where the tool is
//! differs from its end's is refused).
//!
//! Pure: the profile's moves in, the moves out (the cuts and the returns
//! inside pockets are roughing cuts; the moves along the profile are too,
//! unless D is 0, when they turn the part's finished outline).

mod corner;
mod cx;
mod emit;
pub mod finish;
mod offset;
pub mod read;
mod seg;
mod walk;

use crate::args;
use crate::cycle::rough::Along;
use crate::diagnostic::Finding;
use crate::message::{self as msg, Message};
use crate::motion::{ArcData, Move, Point};
use crate::span::Span;
use cx::{C, I};
use emit::Emit;
use seg::Seg;
use walk::{Out, Walk};

/// Most cuts planned of one cycle (as for the Fanuc roughing).
pub const MAX_CUTS: usize = crate::cycle::rough::MAX_CUTS;

/// What a cycle does with pockets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pockets {
    /// G71, G72: roughs them as they come.
    All,
    /// G71.1, G72.1: roughs over them.
    None,
    /// G71.2, G72.2: roughs only them, after going down the profile to the first.
    AfterFirst,
}

/// A roughing cycle's words.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Words {
    /// The code ×10: 710, 711, 712, 720, 721, 722.
    pub code10: i64,
    /// G71 cuts along Z, G72 along X.
    pub along: Along,
    /// What it does with pockets.
    pub pockets: Pockets,
    /// D: the distance left to the profile (0 without D).
    pub d: f64,
    /// I: the depth of each cut (1 without I).
    pub i: f64,
    /// R: the retract (0.5 without R).
    pub r: f64,
    /// Where I is written (else the block).
    pub i_span: Span,
    /// The program's lengths are inches (rs274's arc tolerances).
    pub inch: bool,
}

impl Words {
    /// The axis and the pockets of cycle G(`code10`/10): 710–712, 720–722.
    pub fn kind(code10: i64) -> Option<(Along, Pockets)> {
        let along = match code10 / 10 {
            71 => Along::Z,
            72 => Along::X,
            _ => return None,
        };
        let pockets = match code10 % 10 {
            0 => Pockets::All,
            1 => Pockets::None,
            2 => Pockets::AfterFirst,
            _ => return None,
        };
        Some((along, pockets))
    }

    /// The cycle's name: `G71`, `G72.2`.
    pub fn title(&self) -> String {
        match self.code10 % 10 {
            0 => format!("G{}", self.code10 / 10),
            k => format!("G{}.{k}", self.code10 / 10),
        }
    }
}

/// A LinuxCNC G70–G72 block read: the subroutine of its profile and what
/// the cycle does with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Call {
    /// The subroutine number, Q.
    pub q: u32,
    /// The cycle.
    pub job: Job,
}

/// What a LinuxCNC profile cycle does with its profile.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Job {
    /// G70: finishing passes.
    Finish(finish::Passes),
    /// G71, G72: roughing.
    Rough(Words),
}

/// A corner a profile move rounds or bevels at its end (`A`, `C`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Corner {
    /// A fillet of this radius.
    Fillet(f64),
    /// A chamfer of this size.
    Chamfer(f64),
}

/// One move of the profile as read: its end, the arc it follows, the corner after it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    /// Where it ends.
    pub to: Point,
    /// Its centre and sense, for an arc.
    pub arc: Option<ArcData>,
    /// A corner at its end.
    pub corner: Option<Corner>,
}

/// Why the cycle stops: rs274's own errors, and where planning it would not end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fail {
    /// I is zero or negative.
    IZero,
    /// The profile turns back along the cut.
    NotMonotone,
    /// A cut is deeper than a lead-in reaches.
    XTooLarge,
    /// The walk lost the profile.
    Lost,
    /// Two offset lines do not meet.
    Parallel,
    /// A corner cannot be made between its two pieces; the first's end, in the walk's frame.
    Corner {
        /// Its real part.
        re: f64,
        /// Its imaginary part.
        im: f64,
    },
    /// The offset by D does not come to an end.
    Offset,
    /// The profile does not cross the depth of the cut from this point:
    /// rs274 repeats that cut for ever.
    Endless {
        /// X (a diameter; in the walk, its frame's depth).
        x: f64,
        /// Z (in the walk, its frame's cut coordinate).
        z: f64,
    },
    /// More than `limit` cuts.
    TooMany {
        /// The bound.
        limit: usize,
    },
    /// A profile arc with R and I or K.
    RAndIk,
    /// A profile arc with neither R nor I and K.
    NoIk,
    /// A profile move with both A (fillet) and C (chamfer).
    BothCorners,
    /// An arc of the path that rs274 refuses as it makes it, from where
    /// the tool is (Z, radius): its radii there and at its end differ, or
    /// one is nothing.
    Arc {
        /// No radius, rather than different radii.
        zero: bool,
        /// The tool's point.
        from: (f64, f64),
        /// The centre.
        c: (f64, f64),
        /// The end.
        to: (f64, f64),
    },
}

impl Fail {
    /// rs274's message after "G7X error: ", for its own errors.
    pub fn rs274(self) -> Option<&'static str> {
        Some(match self {
            Fail::IZero => "I must be greater than zero.",
            Fail::NotMonotone => "Not monotonic",
            Fail::XTooLarge => "x too large in straight dive",
            Fail::Lost => "How did we get here?",
            Fail::Parallel => "Cannot intersect parallel lines",
            Fail::Corner { .. } => "Corner finish failed at",
            Fail::RAndIk => "both R and I or K flag used for arc",
            Fail::NoIk => "either I or K must be present for arc",
            Fail::BothCorners => "Both A and C parameters on a corner",
            Fail::Offset | Fail::Endless { .. } | Fail::TooMany { .. } | Fail::Arc { .. } => return None,
        })
    }
}

/// The cycle a failure is about, for what is said of it.
#[derive(Clone, Copy, Debug)]
pub enum Who<'a> {
    /// A G71/G72.
    Rough(&'a Words),
    /// A G70.
    Finish(&'a finish::Passes),
}

impl Fail {
    /// What to say about the failure of cycle `who` over the profile of
    /// o(`q`), and whether it is about the I word (else the block).
    pub fn finding(self, who: Who, q: u32) -> (Finding, bool) {
        let sub = format!("o{q}");
        let (name, d, along, i) = match who {
            Who::Rough(w) => (w.title(), w.d, Some(w.along), w.i),
            Who::Finish(p) => ("G70".to_string(), p.d, None, 1.0),
        };
        let m = match self {
            Fail::IZero => {
                let word = format!("I{}", crate::num::fmt(i));
                return (Message::new(&msg::LCNC_G7X_I, args![word]), true);
            }
            Fail::NotMonotone => match along {
                Some(along) => {
                    let (axis, other) = if along == Along::Z { ("Z", "X") } else { ("X", "Z") };
                    Message::new(&msg::LCNC_G7X_NOT_MONOTONIC, args![sub, name, axis, other])
                }
                None => Message::new(&msg::LCNC_G70_NOT_MONOTONIC, args![sub]),
            },
            Fail::Corner { re, im } => {
                let message = format!("Corner finish failed at ({},{})", cx::g(re), cx::g(im));
                Message::new(&msg::LCNC_G7X_PROFILE, args![message, sub, d])
            }
            Fail::Parallel => Message::new(&msg::LCNC_G7X_PARALLEL, args![sub, d]),
            Fail::XTooLarge | Fail::Lost => {
                let message = self.rs274().unwrap_or_default();
                Message::new(&msg::LCNC_G7X_PROFILE, args![message, sub, d])
            }
            Fail::RAndIk | Fail::NoIk | Fail::BothCorners => {
                let message = self.rs274().unwrap_or_default();
                Message::new(&msg::LCNC_G7X_MOVE, args![message, sub])
            }
            Fail::Offset => Message::new(&msg::LCNC_G7X_OFFSET, args![name, sub, d]),
            Fail::Arc { zero, from, c, to } => {
                let message = emit::arc_message(zero, from, c, to);
                Message::new(&msg::LCNC_G7X_ARC, args![message, name])
            }
            Fail::Endless { x, z } => Message::new(&msg::LCNC_G7X_ENDLESS, args![name, sub, x, z]),
            Fail::TooMany { limit } => match who {
                Who::Rough(_) => Message::new(&msg::LCNC_G7X_TOO_MANY, args![name, limit, i]),
                Who::Finish(w) => Message::new(&msg::LCNC_G70_TOO_MANY, args![limit, p = w.p]),
            },
        };
        (m, false)
    }
}

/// A cycle planned: its moves, and why it stopped early, if it did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Roughing {
    /// The moves, made by the cycle's block.
    pub moves: Vec<Move>,
    /// The error that stopped it (with the moves before it).
    pub fail: Option<Fail>,
}

/// The pieces of the profile from `start` through `steps`, in the frame of
/// G71 (Z, radius); moves that go nowhere add none.
fn pieces(start: Point, steps: &[Step]) -> Vec<Seg> {
    let c = |p: Point| C::new(p.z, p.x / 2.0);
    let mut out = Vec::with_capacity(steps.len());
    let mut at = c(start);
    for s in steps {
        let to = c(s.to);
        if to == at {
            continue;
        }
        out.push(match s.arc {
            Some(a) => Seg::arc(!a.cw, at, c(a.center), to),
            None => Seg::line(at, to),
        });
        // A corner at the move's end: a piece of no size there until it is made.
        out.extend(s.corner.map(|k| match k {
            Corner::Fillet(d) => Seg { corner: Some(d), ..Seg::arc(false, to, to, to) },
            Corner::Chamfer(d) => Seg { corner: Some(d), ..Seg::line(to, to) },
        }));
        at = to;
    }
    out
}

/// How the profile was turned and mirrored into the walk's frame: bit 4 a
/// quarter turn (G72), bit 2 mirrored in depth, bit 1 mirrored along the cut.
#[derive(Clone, Copy, Debug, Default)]
struct Frame(u8);

impl Frame {
    /// A point of the walk's frame back in the program's (Z, radius).
    fn back(self, q: C) -> C {
        let q = if self.0 & 1 != 0 { -q.conj() } else { q };
        let q = if self.0 & 2 != 0 { q.conj() } else { q };
        if self.0 & 4 != 0 { I * q } else { q }
    }

    /// A point of the walk's frame in the program: X a diameter.
    fn point(self, q: C) -> Point {
        let p = self.back(q);
        Point::new(2.0 * p.im, p.re)
    }

    /// Whether arcs turn the other way in the program.
    fn mirrored(self) -> bool {
        (self.0 & 1 != 0) != (self.0 & 2 != 0)
    }
}

/// Turns the profile a quarter turn, into G72's frame.
fn turn(path: &mut [Seg], f: &mut Frame) {
    path.iter_mut().for_each(|s| s.map(|p| (-p) * I, false));
    f.0 ^= 4;
}

/// Mirrors the profile so that its first piece's end is above its last
/// piece's end in depth and beyond it along the cut (rs274's `swap`).
fn mirror(path: &mut [Seg], f: &mut Frame) {
    let d = path[0].e - path[path.len() - 1].e;
    if d.im > 0.0 {
        path.iter_mut().for_each(|s| s.map(C::conj, true));
        f.0 ^= 2;
    }
    if d.re < 0.0 {
        path.iter_mut().for_each(|s| s.map(|p| -p.conj(), true));
        f.0 ^= 1;
    }
}

/// A first piece that starts behind its end along the cut starts square
/// above it instead (the lead-in comes straight down); then every piece
/// must run one way along the cut (rs274's `monotonic`).
fn monotone(path: &mut [Seg]) -> Result<(), Fail> {
    if let Some(first) = path.first_mut() {
        if first.e.re > first.s.re {
            first.s.re = first.e.re;
        }
    }
    if path.iter().all(Seg::monotone) { Ok(()) } else { Err(Fail::NotMonotone) }
}

/// Makes the profile's corners and drops the pieces rs274 drops; `false`
/// when nothing is left.
fn finish_corners(path: &mut Vec<Seg>) -> Result<bool, Fail> {
    corner::make(path)?;
    path.retain(|s| !s.tiny());
    Ok(!path.is_empty())
}

/// Plans cycle `w` from the start point `start` over the profile `steps`,
/// its moves made by the block at `line`/`span`. A profile of less than
/// two pieces (the lead-in included) cuts nothing.
pub fn plan(w: &Words, start: Point, steps: &[Step], line: u32, span: Span) -> Roughing {
    let mut path = pieces(start, steps);
    if path.len() <= 1 {
        return Roughing::default();
    }
    let fail = |f| Roughing { moves: Vec::new(), fail: Some(f) };
    if w.i.is_nan() || w.i <= 0.0 {
        return fail(Fail::IZero);
    }
    let mut frame = Frame::default();
    if w.along == Along::X {
        turn(&mut path, &mut frame);
    }
    mirror(&mut path, &mut frame);
    match finish_corners(&mut path) {
        Ok(true) => {}
        Ok(false) => return Roughing::default(),
        Err(f) => return fail(f),
    }
    if let Err(f) = monotone(&mut path).and_then(|()| offset::add_distance(&mut path, w.d)) {
        return fail(f);
    }
    let (first, last) = (path[0].s, path[path.len() - 1].e);
    if last.im < first.im {
        path.push(Seg::line(last, C::new(last.re, first.im)));
    }
    let delta = if w.i < 2.0 * seg::TOL { 2.0 * seg::TOL } else { w.i };
    let mut walk = Walk::new(&path, delta, w.r, MAX_CUTS);
    walk.out.push(Out::Rapid(first));
    let fail = walk.run(w.pockets).err().map(|f| match f {
        Fail::Endless { x, z } => {
            let p = frame.point(C::new(z, x));
            Fail::Endless { x: p.x, z: p.z }
        }
        f => f,
    });
    let mut moves = Vec::with_capacity(walk.out.len());
    let emit = Emit { frame, finished: w.d == 0.0, inch: w.inch, line, span };
    let refused = emit.moves(&walk.out, &mut start.clone(), &mut moves);
    Roughing { moves, fail: refused.or(fail) }
}

#[cfg(test)]
mod tests;
