//! Geometry of the work plane on glam's `DVec2`.
//!
//! The plan reports points as the controller programs them ([`Point`]: X a
//! diameter, Z). Computations work in true geometry instead: a `DVec2` of
//! (Z, radius) ([`Point::zr`]), or of (long, short) in the axis frame of a
//! thread ([`Frame`]: the long axis is the one the lead is measured along,
//! radii for X). One frame serves the thread pieces, the grouping of
//! passes, the advice on crests and clearances and the drawings.

use glam::DVec2;

use crate::motion::Point;
use crate::num::EPS;
use crate::thread::Axis;

/// The long/short axis frame of a thread: coordinates (long, short), radii for X.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame(pub Axis);

impl Frame {
    /// The frame whose long axis is `long`.
    pub const fn along(long: Axis) -> Frame {
        Frame(long)
    }

    /// (long, short) of a point.
    pub fn of(self, p: Point) -> DVec2 {
        // The swap of a face thread's frame is its own inverse.
        self.zr(p.zr())
    }

    /// The point at (long, short).
    pub fn point(self, v: DVec2) -> Point {
        Point::from_zr(self.zr(v))
    }

    /// True coordinates (Z, radius) of the frame coordinates `v` = (long, short).
    pub fn zr(self, v: DVec2) -> DVec2 {
        match self.0 {
            Axis::Z => v,
            Axis::X => DVec2::new(v.y, v.x),
        }
    }

    /// Long-axis coordinate of a point (radius for X).
    pub fn long(self, p: Point) -> f64 {
        self.of(p).x
    }

    /// Short-axis coordinate of a point (radius for X).
    pub fn short(self, p: Point) -> f64 {
        self.of(p).y
    }

    /// Long-axis travel from `a` to `b` (signed).
    pub fn travel(self, a: Point, b: Point) -> f64 {
        self.long(b) - self.long(a)
    }

    /// `p` moved by `d` = (along the long axis, along the short axis).
    pub fn offset(self, p: Point, d: DVec2) -> Point {
        self.point(self.of(p) + d)
    }

    /// Short-axis value, at long-axis position `l`, of the line through `a` and `b`.
    pub fn line_at(self, a: Point, b: Point, l: f64) -> f64 {
        let (a, b) = (self.of(a), self.of(b));
        if (b.x - a.x).abs() < EPS { a.y } else { a.y + (b.y - a.y) * (l - a.x) / (b.x - a.x) }
    }
}

/// Centre of the arc of radius `r` from `start` to `end` (true geometry,
/// (Z, radius)): the minor arc for `r > 0`, the major one for `r < 0`,
/// clockwise in the drawing (+Z right, +X up) when `cw`. `None` when the
/// chord is zero or longer than the diameter.
pub fn arc_centre(start: DVec2, end: DVec2, r: f64, cw: bool) -> Option<DVec2> {
    let rad = r.abs();
    let d = end - start;
    let chord = d.length();
    if chord < EPS || chord > 2.0 * rad + 1e-7 {
        return None;
    }
    let h = (rad * rad - chord * chord / 4.0).max(0.0).sqrt();
    // Left normal of the chord (counter-clockwise positive), the minor arc's centre side.
    let normal = d.perp() / chord;
    let side = if cw { -1.0 } else { 1.0 } * if r < 0.0 { -1.0 } else { 1.0 };
    Some((start + end) / 2.0 + side * h * normal)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_swap_for_face_threads() {
        let p = Point::new(40.0, -5.0);
        assert_eq!(Frame(Axis::Z).of(p), DVec2::new(-5.0, 20.0));
        assert_eq!(Frame(Axis::X).of(p), DVec2::new(20.0, -5.0));
        for f in [Frame(Axis::Z), Frame(Axis::X)] {
            assert_eq!(f.point(f.of(p)), p);
            assert_eq!(f.offset(p, DVec2::ZERO), p);
        }
        // One long-axis unit on a face thread is one radius: two of diameter.
        assert_eq!(Frame(Axis::X).offset(p, DVec2::new(1.0, 0.5)), Point::new(42.0, -4.5));
        assert_eq!(Frame(Axis::Z).line_at(Point::new(20.0, 0.0), Point::new(40.0, -10.0), -5.0), 15.0);
    }

    /// R10 from (0, 0) to (10, 10), counter-clockwise: the minor arc (a quarter
    /// from −90° to 0°) turns about (0, 10); clockwise about (10, 0); a
    /// negative R takes the other centre.
    #[test]
    fn arc_centres() {
        let (a, b) = (DVec2::new(0.0, 0.0), DVec2::new(10.0, 10.0));
        let near = |c: Option<DVec2>, want: DVec2| c.is_some_and(|c| c.distance(want) < 1e-9);
        assert!(near(arc_centre(a, b, 10.0, false), DVec2::new(0.0, 10.0)));
        assert!(near(arc_centre(a, b, 10.0, true), DVec2::new(10.0, 0.0)));
        assert!(near(arc_centre(a, b, -10.0, false), DVec2::new(10.0, 0.0)));
        assert_eq!(arc_centre(a, b, 5.0, false), None);
        assert_eq!(arc_centre(a, a, 5.0, false), None);
    }
}
