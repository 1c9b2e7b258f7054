//! The threading cycles G92, G76 and G78, planned pass by pass (and the
//! lathe profile cycles' roughing: [`rough`] for Fanuc's and GSK's G71/G72,
//! [`pattern`] for their G73, [`g7x`] for LinuxCNC's).
//!
//! Pure functions of what a cycle block gave (read by the controller's
//! module) and the settings: a [`Geometry`] (start point A, the root line of
//! the finished thread, which side is outside, run-out and screw-in), a
//! depth [`schedule`], the axial [`infeed`] shift, the [`runout`] rules, and
//! the plan of a multi-pass cycle ([`multi`]). Nothing here reads or
//! changes the interpreter.

pub mod g7x;
pub mod infeed;
pub mod linuxcnc;
pub mod multi;
pub mod pattern;
pub mod pockets;
pub mod rough;
pub mod runout;
pub mod schedule;

pub use multi::{Anchor, Multi, MultiPlan};

use glam::DVec2;

use crate::args;
use crate::diagnostic::Finding;
use crate::message::{self as msg, Message};
use crate::motion::{Move, MoveKind, Point};
use crate::num::EPS;
use crate::span::Span;
use crate::thread::{Axis, ThreadKind};

/// The shape of a cycle's thread: start point A, the root line of the
/// finished thread from A's Z to the programmed end, and which side is out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    /// Start and return point A.
    pub a: Point,
    /// Root of the finished thread at A's Z (end X plus the taper R(i)).
    pub root_start: Point,
    /// Root at the programmed end point.
    pub root_end: Point,
    /// +1 when A is outside the root (external thread), −1 inside (internal).
    pub out: f64,
    /// Straight or taper.
    pub kind: ThreadKind,
    /// Run-out: radial amount J and axial length K.
    pub runout: Option<(f64, f64)>,
    /// Screw-in: radial amount E and axial length.
    pub screw_in: Option<(f64, f64)>,
}

/// The points of one pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PassPoints {
    /// Where the screw-in starts.
    pub screw_in_from: Option<Point>,
    /// Start of the synchronised cut.
    pub from: Point,
    /// End of the synchronised cut.
    pub to: Point,
    /// End of the run-out.
    pub runout_to: Option<Point>,
}

/// The motions of one cycle pass: approach, cut (screw-in, thread, run-out),
/// retract and return, with how many of each part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PassPath {
    moves: [Move; 8],
    /// Motions in the approach, the cut and the way back.
    pub counts: [usize; 3],
}

impl PassPath {
    /// A path of up to eight motions in all: `approach`, `cut`, `back` (the
    /// motions past the eighth are dropped).
    pub fn of(approach: &[Move], cut: &[Move], back: &[Move]) -> PassPath {
        let mut moves = [Move::default(); 8];
        let mut counts = [0; 3];
        let mut n = 0;
        for (part, count) in [approach, cut, back].into_iter().zip(&mut counts) {
            for m in part.iter().take(8 - n) {
                moves[n] = *m;
                n += 1;
                *count += 1;
            }
        }
        PassPath { moves, counts }
    }

    /// The motions in order.
    pub fn moves(&self) -> &[Move] {
        &self.moves[..self.counts.iter().sum::<usize>()]
    }
}

/// The kind and long axis of a thread piece from `from` to `end`; `None`
/// when it does not move.
pub fn classify(from: Point, end: Point) -> Option<(ThreadKind, Axis)> {
    let d = end.zr() - from.zr();
    if d.y.abs() < EPS && d.x.abs() < EPS {
        return None;
    }
    let kind = if d.y.abs() < EPS {
        ThreadKind::Straight
    } else if d.x.abs() < EPS {
        ThreadKind::Face
    } else {
        ThreadKind::Taper
    };
    // Equal travels (a 45° run-out) within rounding are Z's.
    let long = if d.y.abs() > d.x.abs() + EPS { Axis::X } else { Axis::Z };
    Some((kind, long))
}

/// Splits a piece into its synchronised cut and run-out: the run-out takes
/// the last `k` of the long-axis travel and ends displaced by `j` on the
/// short axis (radial when the short axis is X). Returns (cut end, run-out end).
pub fn split_runout(from: Point, end: Point, long: Axis, j: f64, k: f64) -> (Point, Point) {
    let frame = crate::geom::Frame(long);
    let travel = frame.travel(from, end).abs();
    let t = if travel > 0.0 { ((travel - k) / travel).clamp(0.0, 1.0) } else { 1.0 };
    (from.lerp(end, t), frame.offset(end, DVec2::new(0.0, j)))
}

impl Geometry {
    /// The geometry of a cycle from A whose thread ends at `end` with taper
    /// `i` (radius, start minus end); an alarm for a thread that does not run
    /// along Z or does not move. `what` names the cycle in messages.
    pub fn new(a: Point, end: Point, i: f64, what: &str) -> Result<Geometry, Finding> {
        let root_start = Point::new(end.x + 2.0 * i, a.z);
        if (end.z - a.z).abs() < EPS {
            return Err(Message::new(&msg::FACE_THREAD_CYCLE, args![what]));
        }
        // GSK980TDc manual §3.21.6: when R and U have opposite signs, |R| ≤ |U/2|.
        let half_u = end.r() - a.r();
        if i * half_u < 0.0 && i.abs() > half_u.abs() + EPS {
            let a = args![what, i, half_u, x = root_start.x, ax = a.x];
            return Err(Message::new(&msg::TAPER_BEYOND_START, a));
        }
        match classify(root_start, end) {
            None => Err(Message::new(&msg::CYCLE_NO_LENGTH, args![what])),
            Some((ThreadKind::Face, _)) | Some((_, Axis::X)) => Err(Message::new(&msg::CYCLE_ALONG_X, args![what])),
            Some((kind, Axis::Z)) => {
                let out = if a.r() >= root_start.r() { 1.0 } else { -1.0 };
                Ok(Geometry { a, root_start, root_end: end, out, kind, runout: None, screw_in: None })
            }
        }
    }

    /// The direction of cutting along Z (+1 or −1).
    pub fn sense(&self) -> f64 {
        if self.root_end.z >= self.root_start.z { 1.0 } else { -1.0 }
    }

    /// Thread length along Z.
    pub fn length(&self) -> f64 {
        (self.root_end.z - self.root_start.z).abs()
    }

    /// The pass at depth `h` of a thread of height `k` whose line is shifted
    /// axially by `shift` (a flank infeed): it starts on the shifted line at
    /// the start point's Z plus `shift` and ends where that line meets the
    /// programmed end's Z (GSK980TDc §3.21.7: each pass cuts parallel to C→D
    /// up to the line D→E), run-out and screw-in included.
    pub fn pass(&self, h: f64, k: f64, shift: f64) -> PassPoints {
        let off = self.out * (k - h);
        let p0 = self.root_start.offset_r(off, shift);
        let shifted_end = self.root_end.offset_r(off, shift);
        let p1 = if shift == 0.0 {
            shifted_end
        } else {
            p0.lerp(shifted_end, (self.root_end.z - p0.z) / (shifted_end.z - p0.z))
        };
        let len = (p1.z - p0.z).abs();
        let (screw_in_from, from) = match self.screw_in {
            Some((e, ls)) if len > 0.0 => (Some(p0.offset_r(self.out * e, 0.0)), p0.lerp(p1, (ls / len).min(1.0))),
            _ => (None, p0),
        };
        let (to, runout_to) = match self.runout {
            Some((j, kk)) => {
                let (c, o) = split_runout(p0, p1, Axis::Z, self.out * j, kk);
                (c, Some(o))
            }
            None => (p1, None),
        };
        PassPoints { screw_in_from, from, to, runout_to }
    }

    /// An alarm when screw-in and run-out, with passes starting up to
    /// `shift` further along the cut, are longer than the thread.
    pub fn check_ends(&self, shift: f64) -> Result<(), Finding> {
        let si = self.screw_in.map_or(0.0, |s| s.1);
        let ro = self.runout.map_or(0.0, |r| r.1);
        let shift = shift.max(0.0);
        if si + ro + shift > self.length() + EPS {
            let len = self.length();
            return Err(if shift > 0.0 {
                Message::new(&msg::ENDS_TOO_LONG_SHIFTED, args![ro, si, shift, len])
            } else {
                Message::new(&msg::ENDS_TOO_LONG, args![ro, si, len])
            });
        }
        Ok(())
    }

    /// The motions of one pass: approach from A, screw-in, cut, run-out,
    /// retract in X to A's diameter, return in Z to A.
    pub fn path(&self, p: &PassPoints, line: u32, span: Span) -> PassPath {
        let mv = |kind, from, to| Move { kind, from, to, line, span, arc: None };
        let approach = mv(MoveKind::Rapid, self.a, p.screw_in_from.unwrap_or(p.from));
        let screw_in = p.screw_in_from.map(|s| mv(MoveKind::ScrewIn, s, p.from));
        let runout = p.runout_to.map(|r| mv(MoveKind::Runout, p.to, r));
        let last = p.runout_to.unwrap_or(p.to);
        let up = Point::new(self.a.x, last.z);
        let mut moves = [Move::default(); 8];
        let mut n = 0;
        let cut = [screw_in, Some(mv(MoveKind::Thread, p.from, p.to)), runout];
        let all = std::iter::once(approach)
            .chain(cut.into_iter().flatten())
            .chain([mv(MoveKind::Rapid, last, up), mv(MoveKind::Rapid, up, self.a)]);
        for m in all {
            moves[n] = m;
            n += 1;
        }
        PassPath { moves, counts: [1, n - 3, 2] }
    }
}
