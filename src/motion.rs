//! Points and motions in program coordinates (X as a diameter, Z).

use glam::DVec2;
use serde::{Serialize, Serializer};

use crate::num::round_out;
use crate::span::Span;

/// A point of the X–Z plane in program units, as the plan reports it: `x`
/// is a **diameter**, as the controller programs it. Geometry is computed
/// on glam's `DVec2` in true coordinates, (Z, radius): [`Point::zr`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Point {
    /// Diameter.
    pub x: f64,
    /// Axial position.
    pub z: f64,
}

impl Point {
    /// A point from a diameter and a Z.
    pub const fn new(x: f64, z: f64) -> Point {
        Point { x, z }
    }

    /// The point in true geometry: (Z, radius).
    pub fn zr(self) -> DVec2 {
        DVec2::new(self.z, self.x / 2.0)
    }

    /// The point at true coordinates (Z, radius).
    pub fn from_zr(v: DVec2) -> Point {
        Point { x: 2.0 * v.y, z: v.x }
    }

    /// Radius (half the diameter).
    pub fn r(self) -> f64 {
        self.x / 2.0
    }

    /// Moves by a radial `dr` and an axial `dz`.
    pub fn offset_r(self, dr: f64, dz: f64) -> Point {
        Point::from_zr(self.zr() + DVec2::new(dz, dr))
    }

    /// Linear interpolation towards `o` by `t`.
    pub fn lerp(self, o: Point, t: f64) -> Point {
        Point { x: self.x + (o.x - self.x) * t, z: self.z + (o.z - self.z) * t }
    }

    /// Euclidean distance in true geometry (radial, axial).
    pub fn dist(self, o: Point) -> f64 {
        self.zr().distance(o.zr())
    }

    /// Whether both coordinates are finite.
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.z.is_finite()
    }
}

impl Serialize for Point {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        [round_out(self.x), round_out(self.z)].serialize(s)
    }
}

/// What a motion is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MoveKind {
    /// G00 positioning.
    #[default]
    Rapid,
    /// Straight feed (G01, turning cycles).
    Feed,
    /// A roughing cut of a stock-removal cycle (G71/G72): a feed, not the part's outline.
    Rough,
    /// Circular feed (G02/G03).
    Arc,
    /// Spindle-synchronised thread cut.
    Thread,
    /// Thread run-out (retract while still synchronised).
    Runout,
    /// Thread screw-in (ramp into the cut, G78 E).
    ScrewIn,
}

impl MoveKind {
    /// Whether the tool cuts material along this motion (not a rapid).
    pub fn is_cutting(self) -> bool {
        !matches!(self, MoveKind::Rapid)
    }
}

/// Arc details of a [`MoveKind::Arc`] motion.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ArcData {
    /// Centre (X as a diameter).
    pub center: Point,
    /// Clockwise in the drawing (+Z right, +X up): G02.
    pub cw: bool,
}

/// One motion of the tool tip.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Move {
    /// Kind of motion.
    pub kind: MoveKind,
    /// Start point.
    pub from: Point,
    /// End point.
    pub to: Point,
    /// 1-based source line of the block that made it.
    pub line: u32,
    /// Byte span of that block in the source.
    pub span: Span,
    /// Arc centre and direction, for arcs.
    #[serde(skip_serializing_if = "Option::is_none", flatten)]
    pub arc: Option<ArcData>,
}

/// The points of an arc motion, tessellated (at most 3° per chord).
pub fn arc_points(m: &Move) -> Vec<[f64; 2]> {
    let world = |p: Point| [p.z, p.x / 2.0];
    let (a, b) = (world(m.from), world(m.to));
    let Some(arc) = m.arc else { return vec![a, b] };
    let c = world(arc.center);
    let r = ((a[0] - c[0]).powi(2) + (a[1] - c[1]).powi(2)).sqrt();
    if !(r.is_finite() && r > 0.0) {
        return vec![a, b];
    }
    let a0 = (a[1] - c[1]).atan2(a[0] - c[0]);
    let a1 = (b[1] - c[1]).atan2(b[0] - c[0]);
    let tau = std::f64::consts::TAU;
    let mut sweep = a1 - a0;
    if arc.cw {
        while sweep >= 0.0 {
            sweep -= tau;
        }
        if sweep <= -tau {
            sweep += tau;
        }
    } else {
        while sweep <= 0.0 {
            sweep += tau;
        }
        if sweep >= tau {
            sweep -= tau;
        }
    }
    let n = ((sweep.abs() / 3f64.to_radians()).ceil() as usize).clamp(2, 120);
    let mut pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = a0 + sweep * i as f64 / n as f64;
            [c[0] + r * t.cos(), c[1] + r * t.sin()]
        })
        .collect();
    pts.push(b);
    pts
}
