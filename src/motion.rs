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
