//! The roughing walk over the offset profile, as rs274 cuts it
//! (`g7x::pocket` and the pieces' `dive`, `climb` and `climb_only` in
//! `interp_g7x.cc`), in the cycle's frame: the profile runs from the start
//! point down the lead-in and on with `re` never growing; the tool cuts
//! along `re` at depths `im` a step I apart, from the start's depth down.
//!
//! At each depth the tool comes down the piece it is on (in rapid on the
//! lead-in, fed in a pocket), feeds along the depth to where the profile
//! next crosses it, retracts by R at 45° (less when the cut was shorter
//! than 2R), goes back at that height to R before where it started and
//! down to it (in rapid outside pockets, fed inside). Where the profile
//! stops going down, the tool follows it up (fed, arcs as arcs) until it
//! goes down again, a pocket, which is roughed the same way from the
//! first depth of the same grid below where the profile turned. G71.1
//! follows the profile without roughing pockets; G71.2 skips the first
//! roughing, down the profile to its first pocket, and roughs only the pockets.

use super::cx::{self, C};
use super::seg::{Seg, Shape, TOL};
use super::{Fail, Pockets};

/// What the tool does, in the cycle's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Out {
    /// A rapid to a point.
    Rapid(C),
    /// A feed to a point; `contour`: along the profile (else across the material).
    Feed(C, bool),
    /// An arc of the profile about `c` to `to`.
    Arc {
        /// Counter-clockwise in the frame.
        ccw: bool,
        /// Centre.
        c: C,
        /// End.
        to: C,
    },
}

/// The walk's state: the profile, the grid and the moves made.
pub struct Walk<'a> {
    path: &'a [Seg],
    delta: f64,
    escape: C,
    starts: Vec<C>,
    /// The moves made, in order.
    pub out: Vec<Out>,
    cuts: usize,
    steps: usize,
    limit: usize,
}

impl<'a> Walk<'a> {
    /// A walk over `path` (lead-in first) at depth step `delta`, retract `r`;
    /// at most `limit` cuts (rs274 has no bound: a tiny I takes it millions).
    pub fn new(path: &'a [Seg], delta: f64, r: f64, limit: usize) -> Walk<'a> {
        let starts = path.first().map(|s| vec![s.s]).unwrap_or_default();
        Walk { path, delta, escape: C::new(r, r), starts, out: Vec::new(), cuts: 0, steps: 0, limit }
    }

    /// Roughs from the start point, down the lead-in.
    pub fn run(&mut self, pockets: Pockets) -> Result<(), Fail> {
        let Some(&start) = self.starts.first() else { return Ok(()) };
        let mode = match pockets {
            Pockets::All => Mode::All,
            Pockets::None => Mode::Outline,
            Pockets::AfterFirst => Mode::SkipFirst,
        };
        self.pocket(mode, start, 0)
    }

    fn arc(&mut self, ccw: bool, c: C, to: C) {
        self.out.push(Out::Arc { ccw, c, to });
    }

    fn go(&mut self, fast: bool, to: C) {
        self.out.push(if fast { Out::Rapid(to) } else { Out::Feed(to, true) });
    }

    /// Comes down piece `k` from `at` to depth `x` (to its end if that is
    /// above `x`); false when the piece does not go down (then nothing moves).
    fn dive(&mut self, k: usize, at: &mut C, x: f64, fast: bool) -> Result<bool, Fail> {
        let p = self.path[k];
        match p.shape {
            Shape::Line => {
                if p.s.im <= p.e.im + TOL {
                    return Ok(false);
                }
                let to = if x < p.e.im { p.e } else { C::new(p.crossings(x).front().ok_or(Fail::XTooLarge)?, x) };
                self.go(fast, to);
                *at = to;
            }
            Shape::Arc { ccw, c } => {
                if (*at - p.e).abs() < TOL || (*at - p.e).re <= TOL {
                    *at = p.e;
                    return Ok(true);
                }
                let mut hits = p.crossings(x);
                if hits.is_empty() {
                    hits = p.crossings(x - TOL);
                }
                if ccw {
                    if at.re - TOL > c.re {
                        return Ok(false);
                    }
                    let to = match hits.back() {
                        Some(z) if z <= c.re => C::new(z, x),
                        _ => p.e,
                    };
                    self.arc(ccw, c, to);
                    *at = to;
                } else {
                    if at.re <= c.re {
                        return Ok(false);
                    }
                    match hits.front() {
                        None => {
                            self.arc(ccw, c, p.e);
                            *at = p.e;
                        }
                        // Only the arc's far side is at this depth: the next depth.
                        Some(z) if z < c.re => {}
                        Some(z) => {
                            self.arc(ccw, c, C::new(z, x));
                            *at = C::new(z, x);
                        }
                    }
                }
            }
        }
        Ok(true)
    }

    /// Follows piece `k` up from `at`; false when it goes down (a pocket
    /// starts there). A counter-clockwise arc is followed to its top at most,
    /// and always hands on to the pocket roughing.
    fn climb(&mut self, k: usize, at: &mut C) -> Result<bool, Fail> {
        let p = self.path[k];
        match p.shape {
            Shape::Line => {
                if p.e.im + TOL < p.s.im {
                    return Ok(false);
                }
                if (*at - p.s).abs() > TOL {
                    return Err(Fail::Lost);
                }
                self.out.push(Out::Feed(p.e, true));
                *at = p.e;
                Ok(true)
            }
            Shape::Arc { ccw: false, c } => {
                if at.re > c.re {
                    return Ok(false);
                }
                if (*at - p.e).abs() > 1e-3 {
                    self.arc(false, c, p.e);
                }
                *at = p.e;
                Ok(true)
            }
            Shape::Arc { ccw: true, c } => {
                if at.re < c.re {
                    return Ok(false);
                }
                let top = if p.e.re < c.re { C::new(c.re, c.im + (p.s - c).abs()) } else { p.e };
                if (*at - top).abs() > 1e-3 {
                    self.arc(true, c, top);
                }
                *at = top;
                Ok(false)
            }
        }
    }

    /// G71.1's finish: the part of piece `k` at or above the depth of `at`,
    /// reached across at that depth.
    fn climb_only(&mut self, k: usize, at: &mut C) {
        let p = self.path[k];
        if p.shape == Shape::Line && p.e.im < p.s.im {
            return;
        }
        let hits = p.crossings(at.im);
        let (Some(front), Some(back)) = (hits.front(), hits.back()) else { return };
        let to = match p.shape {
            Shape::Line => {
                at.re = front;
                p.e
            }
            Shape::Arc { ccw: false, c } => {
                if back > c.re {
                    return;
                }
                at.re = back;
                p.e
            }
            Shape::Arc { ccw: true, c } => {
                if front < c.re {
                    return;
                }
                at.re = front;
                if p.e.re < c.re { C::new(c.re, c.im + (p.s - c).abs()) } else { p.e }
            }
        };
        self.out.push(Out::Feed(*at, false));
        match p.shape {
            Shape::Line => self.out.push(Out::Feed(to, true)),
            Shape::Arc { ccw, c } if (*at - to).abs() > 1e-3 => self.arc(ccw, c, to),
            Shape::Arc { .. } => {}
        }
        *at = to;
    }
}

/// How the walk treats pockets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// Roughs every pocket (G71, G72).
    All,
    /// Follows the profile over pockets (G71.1, G72.1).
    Outline,
    /// Skips the first roughing (G71.2, G72.2).
    SkipFirst,
    /// G71.2 past its first roughing: pockets start at the first depth of theirs.
    Pockets,
}

impl Walk<'_> {
    /// Roughs from `at` on piece `k`: depth by depth down while the profile
    /// goes down, then along it up to the next pocket, and that pocket the same way.
    fn pocket(&mut self, mut mode: Mode, mut at: C, mut k: usize) -> Result<(), Fail> {
        let n = self.path.len();
        'pocket: loop {
            let mut x = self.starts.last().map_or(at.im, |s| s.im);
            if mode == Mode::SkipFirst {
                while k < n && self.dive(k, &mut at, -1e9, k == 0)? {
                    k += 1;
                }
                mode = Mode::Pockets;
            }
            // The state of the last round that cut nothing: the same again never ends.
            let mut idle = None;
            while k < n {
                self.count()?;
                let round = (k, x, at);
                while x - TOL > at.im {
                    x -= self.delta;
                    self.count()?;
                }
                if !self.dive(k, &mut at, x, k == 0)? {
                    if mode == Mode::Outline {
                        for q in k..n {
                            self.climb_only(q, &mut at);
                        }
                        return Ok(());
                    }
                    let Some(q) = self.climb_from(k, &mut at)? else { return Ok(()) };
                    if mode == Mode::Pockets {
                        self.new_pocket(at);
                    }
                    k = q;
                    continue 'pocket;
                }
                if (at.im - x).abs() > TOL {
                    // Below this piece's end: on to the next.
                    k += 1;
                    continue;
                }
                match self.cut(k, at) {
                    Some(Next::Piece(q)) => k = q,
                    Some(Next::Depth) => x -= self.delta,
                    Some(Next::Stop) => return Err(Fail::TooMany { limit: self.limit }),
                    // rs274 goes round again: coming down the piece may move the tool a little.
                    None if idle == Some(round) => return Err(Fail::Endless { x: at.im, z: at.re }),
                    None => idle = Some(round),
                }
            }
            return Ok(());
        }
    }

    /// Follows the profile up from piece `k`: the piece where it goes down
    /// again, a pocket; `None` when it climbs to its end.
    fn climb_from(&mut self, k: usize, at: &mut C) -> Result<Option<usize>, Fail> {
        for q in k..self.path.len() {
            if !self.climb(q, at)? {
                return Ok(Some(q));
            }
        }
        Ok(None)
    }

    /// G71.2: a pocket whose profile turned down at `at` starts its grid there,
    /// unless it is below the pocket it is in (which then ends).
    fn new_pocket(&mut self, at: C) {
        if self.starts.len() > 1 && self.starts.last().is_some_and(|s| at.im > s.im) {
            self.starts.pop();
        }
        if self.starts.len() == 1 {
            self.starts.push(at);
        }
    }

    /// Counts a step of the walk (a round, a depth passed over): at most
    /// `STEPS_PER_CUT` times the cuts allowed.
    fn count(&mut self) -> Result<(), Fail> {
        self.steps += 1;
        if self.steps > STEPS_PER_CUT * self.limit { Err(Fail::TooMany { limit: self.limit }) } else { Ok(()) }
    }

    /// The cut at the depth of `at` (on piece `k`) to where the profile next
    /// crosses it, with the retract and the return; what comes next. `None`:
    /// the profile does not cross this depth (rs274 then tries again).
    fn cut(&mut self, k: usize, at: C) -> Option<Next> {
        for q in k..self.path.len() {
            let hits = self.path[q].crossings(at.im);
            let Some(z) = (if q != k { hits.front() } else { hits.back() }) else { continue };
            let dist = (z - at.re).abs();
            if z - TOL > at.re {
                continue;
            }
            if dist < TOL {
                if q == k {
                    continue;
                }
                if (at - self.path[q].s).abs() < TOL {
                    return Some(Next::Piece(q));
                }
                return Some(Next::Depth);
            }
            self.cuts += 1;
            if self.cuts > self.limit {
                return Some(Next::Stop);
            }
            let mut to = C::new(z, at.im);
            self.out.push(Out::Feed(to, false));
            let scale = cx::min(1.0, dist / 2.0 / self.escape.re);
            to += self.escape.scale(scale);
            self.out.push(Out::Rapid(to));
            self.out.push(Out::Rapid(at - self.escape.scale(scale).conj()));
            self.out.push(if k == 0 { Out::Rapid(at) } else { Out::Feed(at, false) });
            return Some(Next::Depth);
        }
        None
    }
}

/// What the walk does after a depth.
enum Next {
    /// Goes on along piece `q`, at the same depth.
    Piece(usize),
    /// Goes down to the next depth.
    Depth,
    /// Too many cuts: the walk stops.
    Stop,
}

/// Rounds and depths passed over that a walk may take per cut allowed.
const STEPS_PER_CUT: usize = 20;
