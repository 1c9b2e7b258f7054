//! Threads and their passes: what the planner produces for every thread in
//! the program, whether cut block by block (G32/G33) or by a cycle.

use std::ops::Range;

use serde::Serialize;

use crate::motion::Point;
use crate::num::{ser_round, ser_round_opt};

/// Units of a program's lengths: of the whole program where it is said
/// (`Plan::units`, in force at its end), of one thread's words and figures
/// (`Thread::units`, in force where the thread was written).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres (G21).
    #[default]
    Mm,
    /// Inches (G20).
    Inch,
}

impl Units {
    /// The units of a G20 (`inch`) or G21 state.
    pub fn of(inch: bool) -> Units {
        if inch { Units::Inch } else { Units::Mm }
    }

    /// Whether these are inches.
    pub fn is_inch(self) -> bool {
        self == Units::Inch
    }

    /// Millimetres per unit: 25.4 for inches, 1 for millimetres.
    pub fn mm(self) -> f64 {
        if self.is_inch() { 25.4 } else { 1.0 }
    }
}

/// The shape of a thread.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ThreadKind {
    /// Cylindrical: only Z moves.
    #[default]
    Straight,
    /// Conical: both axes move.
    Taper,
    /// Face (scroll): only X moves.
    Face,
}

/// A machine axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    /// Cross slide.
    X,
    /// Spindle axis.
    #[default]
    Z,
}

/// Which command cut a thread.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Source {
    /// GSK/Fanuc G32 blocks.
    #[default]
    G32,
    /// Renhe G32 (inch) / G33 (metric) blocks.
    Renhe,
    /// GSK G78 cycle.
    G78,
    /// G92 cycle.
    G92,
    /// G76 cycle.
    G76,
    /// LinuxCNC G33 blocks (K along the move).
    #[serde(rename = "linuxcnc_g33")]
    LinuxG33,
    /// LinuxCNC G76 cycle (drive line, degression R, compound angle Q, tapers E/L).
    #[serde(rename = "linuxcnc_g76")]
    LinuxG76,
}

/// How the tool feeds into the thread from pass to pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Infeed {
    /// Straight in along the thread middle (both flanks cut).
    Radial,
    /// Along the left flank (−Z side unless `flank.r1_side` says otherwise).
    Left,
    /// Along the right flank.
    Right,
    /// Alternating left and right.
    Alternating,
    /// As programmed block by block (G32/G33): whatever the blocks do.
    #[default]
    Programmed,
}

/// What a pass does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Role {
    /// A roughing pass.
    #[default]
    Rough,
    /// The finishing pass that removes the allowance d.
    Finish,
    /// A spring pass at full depth.
    Spring,
}

/// Where a thread's crest (the reference its depths are measured from) came from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum CrestSource {
    /// The cycle's own geometry (end point and thread height k).
    Cycle,
    /// The diameter the program turned before threading.
    Outline,
    /// Assumed from the deepest pass and the 1.3·P rule.
    #[default]
    Assumed,
    /// Stated by a comment before the thread (`(crest X68.)`).
    Comment,
}

/// The motions of one pass, as index ranges into the plan's `moves`: the
/// rapids that bring the tool to the cut, the cut itself (screw-in, thread
/// segments, run-out) and the rapids that take it back (retract, return).
/// Serialised as `[start, end)` pairs.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct PassMoves {
    /// Approach (infeed) rapids before the cut.
    #[serde(serialize_with = "ser_range")]
    pub approach: Range<usize>,
    /// Screw-in, thread and run-out motions.
    #[serde(serialize_with = "ser_range")]
    pub cut: Range<usize>,
    /// Retract and return rapids after the cut.
    #[serde(serialize_with = "ser_range")]
    pub retract: Range<usize>,
}

impl PassMoves {
    /// Every motion of the pass, approach to return.
    pub fn all(&self) -> Range<usize> {
        self.approach.start..self.retract.end
    }

    /// The ranges moved by `d` motions (a plan cut at a snapshot and read on).
    pub fn shifted(&self, d: isize) -> PassMoves {
        let s = |r: &Range<usize>| r.start.saturating_add_signed(d)..r.end.saturating_add_signed(d);
        PassMoves { approach: s(&self.approach), cut: s(&self.cut), retract: s(&self.retract) }
    }
}

fn ser_range<S: serde::Serializer>(r: &Range<usize>, s: S) -> Result<S::Ok, S::Error> {
    [r.start, r.end].serialize(s)
}

/// The spindle as the program left it when a pass was cut: the modal S and
/// G96, and the G50 S clamp.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Spindle {
    /// S in force: rev/min under G97, surface speed (m/min, ft/min after G20) under G96; `None` before any S.
    #[serde(serialize_with = "ser_round_opt")]
    pub s: Option<f64>,
    /// G96 (constant surface speed) in force.
    pub css: bool,
    /// Spindle clamp of the last G50 S (rev/min), if any.
    #[serde(serialize_with = "ser_round_opt", skip_serializing_if = "Option::is_none")]
    pub clamp: Option<f64>,
}

/// One spindle-synchronised pass of a thread.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Pass {
    /// 1-based start (helix) number.
    pub start: u32,
    /// 1-based pass number within the start.
    pub index: u32,
    /// Start of the synchronised cut (screw-in excluded).
    pub from: Point,
    /// End of the synchronised cut (run-out excluded).
    pub to: Point,
    /// Cumulative depth from the crest, radial (axial for face threads).
    #[serde(serialize_with = "ser_round")]
    pub depth: f64,
    /// Depth added by this pass over the previous pass of the same start.
    #[serde(serialize_with = "ser_round")]
    pub infeed: f64,
    /// What the pass does.
    pub role: Role,
    /// Source lines whose blocks make this pass (infeed, cut, retract, return).
    pub lines: Vec<u32>,
    /// Cut in a subprogram or macro: the lines of the calls that led to it, innermost first.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub via: Vec<u32>,
    /// Corner points of a continuous (multi-segment) cut, `from` and `to` included.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub segments: Vec<Point>,
    /// Where the run-out ends (it starts at `to`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runout_to: Option<Point>,
    /// Where the screw-in starts (it ends at `from`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub screw_in_from: Option<Point>,
    /// Axial shift of this pass from the thread middle (flank infeed, multi-start offset excluded).
    #[serde(serialize_with = "ser_round")]
    pub shift: f64,
    /// Start angle in degrees (Q, or 360°·(start−1)/starts).
    #[serde(serialize_with = "ser_round")]
    pub angle: f64,
    /// Area of the thread space this pass removes (program units²), when the tool angle is known.
    #[serde(serialize_with = "ser_round_opt", skip_serializing_if = "Option::is_none")]
    pub area: Option<f64>,
    /// The pass's motions in the plan's `moves`.
    pub moves: PassMoves,
    /// The spindle when the pass was cut.
    pub spindle: Spindle,
}

impl Pass {
    /// The lines a drawing of the pass stands for: its own, then the calls that cut it.
    pub fn drawn_lines(&self) -> impl Iterator<Item = u32> + '_ {
        self.lines.iter().chain(&self.via).copied()
    }
}

/// A thread: every pass that cuts the same helix (or helices, when multi-start).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Thread {
    /// First source line of the thread.
    pub line: u32,
    /// Last source line of the thread.
    pub end_line: u32,
    /// Which command cut it.
    pub source: Source,
    /// The units its words were written in (G20/G21 in force at its
    /// blocks): its lengths, lead and shop-floor figures are in these.
    pub units: Units,
    /// Straight, taper or face.
    pub kind: ThreadKind,
    /// Axis along which the lead is measured.
    pub long_axis: Axis,
    /// Lead: long-axis advance per spindle revolution.
    #[serde(serialize_with = "ser_round")]
    pub lead: f64,
    /// Pitch = lead / starts.
    #[serde(serialize_with = "ser_round")]
    pub pitch: f64,
    /// Number of starts.
    pub starts: u32,
    /// Internal thread (depth grows outward).
    pub internal: bool,
    /// How the passes feed in.
    pub infeed: Infeed,
    /// Tool (thread) angle in degrees, when known.
    #[serde(serialize_with = "ser_round")]
    pub tool_angle: f64,
    /// Crest diameter at the start of the first pass (X), or crest Z for face threads.
    #[serde(serialize_with = "ser_round")]
    pub crest: f64,
    /// Where `crest` came from.
    pub crest_source: CrestSource,
    /// A cycle's thread (whose crest is the cycle's) cut on a surface the
    /// program turned before it: that surface's diameter at the first pass
    /// (its Z for a face thread), which the thread check measures the major
    /// (an internal thread's minor) against.
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "ser_round_opt")]
    pub turned: Option<f64>,
    /// Total depth of the deepest pass.
    #[serde(serialize_with = "ser_round")]
    pub height: f64,
    /// Taper: start radius minus end radius of the thread (R(i)).
    #[serde(serialize_with = "ser_round")]
    pub taper: f64,
    /// The passes, start by start, in cutting order.
    pub passes: Vec<Pass>,
    /// Direction along the short axis in which depth grows (−1 or +1, radial for Z threads).
    #[serde(skip)]
    pub depth_dir: f64,
    /// Index in the plan's moves of the thread's first motion.
    #[serde(skip)]
    pub first_move: usize,
    /// Shop-floor figures: cycle time, speed, helix angle, chip load, the thread check.
    #[serde(flatten)]
    pub shop: crate::figures::Shop,
}

/// Area a V tool of included angle `angle_deg` removes between depths `h0`
/// and `h1` (radial): `tan(a/2)·(h1² − h0²)`. `None` for a 0° (square) tool.
pub fn v_area(angle_deg: f64, h0: f64, h1: f64) -> Option<f64> {
    if angle_deg <= 0.0 {
        return None;
    }
    let t = (angle_deg.to_radians() / 2.0).tan();
    Some(t * (h1 * h1 - h0 * h0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn v_area_of_a_60_degree_tool() {
        // Depth 1 with a 60° tool: half-width tan 30° = 0.57735, triangle area 0.57735.
        let a = v_area(60.0, 0.0, 1.0).unwrap();
        assert!((a - 0.5773502691896257).abs() < 1e-12);
        // From 1 to 2: 0.57735·(4 − 1).
        assert!((v_area(60.0, 1.0, 2.0).unwrap() - 3.0 * 0.5773502691896257).abs() < 1e-12);
        assert_eq!(v_area(0.0, 0.0, 1.0), None);
    }
}
