//! Where a thread sits in the side section: its band (crest and root along
//! the long axis), the turned work it is cut on and the lead-in and run-out
//! zones δ1/δ2 that follow from them.

use std::cell::RefCell;
use std::collections::HashMap;

use glam::DVec2;

use crate::geom::Frame;
use crate::hash::BuildKeyHasher;
use crate::motion::{Move, MoveKind, Point};
use crate::thread::{Axis, CrestSource, Thread};

use super::scene::Pt;

/// Where a thread sits: its crest and root as functions of the long axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// Long axis of the thread.
    pub long: Axis,
    /// Long-axis start and end of the first pass's cut (radius for X).
    pub l0: f64,
    /// See `l0`.
    pub l1: f64,
    /// Smallest and largest long-axis position of any pass's cut.
    pub lo: f64,
    /// See `lo`.
    pub hi: f64,
    /// Crest short-axis position at `l0` (radius for Z threads, Z for face threads).
    pub crest0: f64,
    /// Change of the crest from `l0` to `l1` (minus the taper R(i)).
    pub slope_total: f64,
    /// Radial (axial for face threads) direction in which the depth grows.
    pub dir: f64,
    /// Thread height (deepest pass depth).
    pub height: f64,
}

impl Band {
    /// The band of a thread, from its first pass, crest, taper and height.
    pub fn of(t: &Thread) -> Option<Band> {
        let p0 = t.passes.first()?;
        let dir = if t.depth_dir != 0.0 {
            t.depth_dir.signum()
        } else if t.internal {
            1.0
        } else {
            -1.0
        };
        let frame = Frame(t.long_axis);
        let (l0, l1) = (frame.long(p0.from), frame.long(p0.to));
        // The crest is a diameter for a thread along Z, a Z for a face thread.
        let (crest0, slope_total) = match t.long_axis {
            Axis::Z => (t.crest / 2.0, -t.taper),
            Axis::X => (t.crest, 0.0),
        };
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in &t.passes {
            for q in [p.from, p.to] {
                let l = frame.long(q);
                if l.is_finite() {
                    lo = crate::num::min(lo, l);
                    hi = crate::num::max(hi, l);
                }
            }
        }
        let b = Band { long: t.long_axis, l0, l1, lo, hi, crest0, slope_total, dir, height: t.height };
        (l0.is_finite() && l1.is_finite() && crest0.is_finite() && lo <= hi).then_some(b)
    }

    /// Crest position at long-axis position `l`.
    pub fn crest(&self, l: f64) -> f64 {
        let span = self.l1 - self.l0;
        if span.abs() < 1e-12 { self.crest0 } else { self.crest0 + self.slope_total * (l - self.l0) / span }
    }

    /// Root position (deepest pass) at `l`.
    pub fn root(&self, l: f64) -> f64 {
        self.crest(l) + self.dir * self.height
    }

    /// World point of a (long, short) pair.
    pub fn pt(&self, l: f64, s: f64) -> Pt {
        Frame(self.long).zr(DVec2::new(l, s)).to_array()
    }

    /// Direction of cutting along the long axis (+1 or −1).
    pub fn sense(&self) -> f64 {
        if self.l1 >= self.l0 { 1.0 } else { -1.0 }
    }
}

/// The work's extent along the thread: the turned moves that lie on the
/// crest line and overlap the cut. `None` when the crest is not turned.
pub fn work_extent(t: &Thread, band: &Band, moves: &[Move]) -> Option<(f64, f64)> {
    work_extent_in(t, band, moves, &FeedIndex::new(moves))
}

/// The feed motions of a plan by their start radius, so that the work of
/// each straight thread is found among the motions on its crest only; and the
/// work found so far, by crest and extent (threads cut again on one diameter
/// over one length, as a program often has, look once).
pub struct FeedIndex {
    /// The feed motions with a finite start radius, ordered by that radius
    /// rounded to `f32` ([`radius_key`]) and then by motion: `key << 32 | motion index`.
    by_radius: Vec<u64>,
    /// Work of straight threads by the bits of `(crest0, lo, hi)`.
    found: RefCell<WorkByBand>,
}

/// Work extents by the bits of `(crest0, lo, hi)`.
type WorkByBand = HashMap<[u64; 3], Option<(f64, f64)>, BuildKeyHasher>;

/// A radius's place in the index: `r` rounded to `f32` (which never
/// reorders two radii), its bits turned so that integers order as the
/// numbers do. Sorting these integers is several times faster than sorting
/// by comparing radii, and a range of radii is the range of their keys.
fn radius_key(r: f64) -> u32 {
    // +0.0 for -0.0: the two are one radius.
    let b = ((r + 0.0) as f32).to_bits();
    if b >> 31 == 1 { !b } else { b | 1 << 31 }
}

impl FeedIndex {
    /// Indexes the feed motions of `moves`.
    pub fn new(moves: &[Move]) -> FeedIndex {
        let mut by_radius: Vec<u64> = moves
            .iter()
            .enumerate()
            .filter(|(_, m)| m.kind == MoveKind::Feed && m.from.r().is_finite())
            .map(|(k, m)| (u64::from(radius_key(m.from.r())) << 32) | k as u64)
            .collect();
        by_radius.sort_unstable();
        FeedIndex { by_radius, found: RefCell::default() }
    }

    /// The indices of the feed motions whose start radius may be within
    /// `lo..=hi`: all of those, and some just outside (one `f32` step).
    fn near(&self, lo: f64, hi: f64) -> impl Iterator<Item = usize> + '_ {
        let (lo, hi) = (radius_key(lo), radius_key(hi));
        let first = self.by_radius.partition_point(|e| ((e >> 32) as u32) < lo);
        self.by_radius[first..]
            .iter()
            .take_while(move |e| ((*e >> 32) as u32) <= hi)
            .map(|e| (e & 0xffff_ffff) as usize)
    }
}

/// [`work_extent`] with the feed motions indexed. A straight thread's crest
/// is one radius, so only the motions starting within the tolerance of it
/// are tested; a tapered one tests every feed motion.
pub fn work_extent_in(t: &Thread, band: &Band, moves: &[Move], index: &FeedIndex) -> Option<(f64, f64)> {
    if t.crest_source != CrestSource::Outline || band.long != Axis::Z {
        return None;
    }
    let on_crest = |p: Point| {
        let c = band.crest(p.z);
        (p.r() - c).abs() <= 1e-4 + 1e-6 * c.abs()
    };
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut take = |m: &Move| {
        let (a, b) = (m.from.z.min(m.to.z), m.from.z.max(m.to.z));
        if b - a > 1e-9 && on_crest(m.from) && on_crest(m.to) && b > band.lo && a < band.hi {
            lo = lo.min(a);
            hi = hi.max(b);
        }
    };
    if band.slope_total == 0.0 {
        // crest(z) is crest0 (or NaN, never on the crest): a motion on it starts within tol of crest0.
        let key = [band.crest0.to_bits(), band.lo.to_bits(), band.hi.to_bits()];
        if let Some(found) = index.found.borrow().get(&key) {
            return *found;
        }
        // The motions starting within tol of crest0, and a few more, which `take` leaves out.
        let tol = 1e-4 + 1e-6 * band.crest0.abs();
        index.near(band.crest0 - tol, band.crest0 + tol).for_each(|k| take(&moves[k]));
        let found = (lo <= hi).then_some((lo, hi));
        index.found.borrow_mut().insert(key, found);
        return found;
    } else {
        moves.iter().filter(|m| m.kind == MoveKind::Feed).for_each(take);
    }
    (lo <= hi).then_some((lo, hi))
}

/// Lead-in δ1 and run-out δ2 of a thread on work spanning `lo..hi`.
pub fn deltas(band: &Band, work: (f64, f64)) -> (f64, f64) {
    let (lo, hi) = work;
    if band.sense() < 0.0 { (band.l0 - hi, lo - band.l1) } else { (lo - band.l0, band.l1 - hi) }
}

#[cfg(test)]
mod tests {
    use super::radius_key;

    /// The index's keys order radii as the numbers do (a range of radii is
    /// a range of keys): negative and positive, zero of either sign as one,
    /// radii closer than an `f32` step as one.
    #[test]
    fn radius_keys_order_as_the_radii() {
        let radii = [-1e300, -25.0, -1e-4, -1e-40, -0.0, 0.0, 1e-40, 1e-4, 19.99988, 20.0, 20.00012, 25.0, 1e300];
        for w in radii.windows(2) {
            assert!(radius_key(w[0]) <= radius_key(w[1]), "{} before {}", w[0], w[1]);
        }
        assert_eq!(radius_key(-0.0), radius_key(0.0));
        assert!(radius_key(-25.0) < radius_key(-1e-4) && radius_key(1e-4) < radius_key(25.0));
        assert!(radius_key(19.99988) < radius_key(20.0) && radius_key(20.0) < radius_key(20.00012));
    }
}
