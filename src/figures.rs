//! The shop-floor figures of a thread as the plan reports them: cycle time,
//! speeds, clearances, chip loads, helix angle and the thread check. Plain
//! records, filled by the shop-floor step (module `shop`) and carried by
//! each thread.

use serde::Serialize;

use crate::num::{ser_round, ser_round_opt};
use crate::standard::{Kind, System};

/// Where a thread's designation was read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DesignationSource {
    /// A comment before the thread.
    Comment,
    /// The setting `thread.designation`.
    Setting,
}

/// Where the lead-in and run-out a thread is judged by come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ClearanceSource {
    /// Measured against the work the program turned before the thread.
    Outline,
    /// The program does not turn the work: the settings `shop.assumed_lead_in` and `shop.assumed_run_out`.
    Assumed,
}

/// The shop-floor figures of one thread. Lengths are in program units,
/// times in seconds, speeds in rev/min; `None` where a figure cannot be
/// known (no spindle speed, no V tool, no designation).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Shop {
    /// Time of every synchronised motion (screw-in, thread, run-out) of every
    /// pass of every start: long-axis travel / (lead × n).
    #[serde(serialize_with = "ser_round_opt")]
    pub cut_time_s: Option<f64>,
    /// `cut_time_s` plus the approach, retract and return rapids at
    /// `machine.rapid_x` / `machine.rapid_z`.
    #[serde(serialize_with = "ser_round_opt")]
    pub time_s: Option<f64>,
    /// Each pass's time with its rapids, in the order of `passes` (empty when not known).
    #[serde(serialize_with = "ser_round_vec")]
    pub pass_time_s: Vec<f64>,
    /// Highest spindle speed of the passes (under G96 at the pass diameter, clamped).
    #[serde(serialize_with = "ser_round_opt")]
    pub rpm: Option<f64>,
    /// Thread feed lead × `rpm`, program units per minute.
    #[serde(serialize_with = "ser_round_opt")]
    pub thread_feed: Option<f64>,
    /// Highest spindle speed whose thread feed fits `machine.max_thread_feed`.
    #[serde(serialize_with = "ser_round_opt")]
    pub rpm_limit: Option<f64>,
    /// Lead-in the speed needs: n·L / `machine.delta1_divisor` (program units).
    #[serde(serialize_with = "ser_round_opt")]
    pub lead_in_needed: Option<f64>,
    /// Run-out the speed needs: n·L / `machine.delta2_divisor` (program units).
    #[serde(serialize_with = "ser_round_opt")]
    pub run_out_needed: Option<f64>,
    /// Lead-in δ1 of the program: measured or assumed (`clearance_source`).
    #[serde(serialize_with = "ser_round_opt")]
    pub lead_in: Option<f64>,
    /// Run-out δ2 of the program: measured or assumed.
    #[serde(serialize_with = "ser_round_opt")]
    pub run_out: Option<f64>,
    /// Where `lead_in` and `run_out` come from.
    pub clearance_source: Option<ClearanceSource>,
    /// Pitch diameter the passes cut (reference §9), with the tool angle,
    /// `tool.nose_radius` and pitch = lead / starts (the designation's pitch when there is one).
    #[serde(serialize_with = "ser_round_opt")]
    pub pitch_diameter: Option<f64>,
    /// Helix angle atan(lead / (π·d2)), degrees.
    #[serde(serialize_with = "ser_round_opt")]
    pub helix_angle_deg: Option<f64>,
    /// Chip load of each pass, in the order of `passes`.
    pub chip: Vec<ChipLoad>,
    /// The thread check against its designation, when one is named.
    pub gauge: Option<Gauge>,
    /// Where the tool comes nearest a shoulder at the end of the cut, when one stands there.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shoulder: Option<Shoulder>,
    /// The insert (setting `tool.insert`) as the tooth section draws it, when one is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub insert: Option<InsertForm>,
}

/// The insert's form where the thread is cut: a full profile forms the
/// standard's root (its nose radius) and crest; a partial one only the root.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InsertForm {
    /// The designation as the setting gives it.
    pub name: String,
    /// A full profile (root and crest), else a partial one (root only).
    pub full: bool,
    /// The nose radius, program units (0: not known, drawn sharp).
    #[serde(serialize_with = "crate::num::ser_round")]
    pub nose_radius: f64,
}

/// The tool against a shoulder the program turned beyond the thread's end:
/// where its leading flank comes nearest the shoulder's face.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Shoulder {
    /// The face's Z.
    #[serde(serialize_with = "crate::num::ser_round")]
    pub z: f64,
    /// The face's edge the flank must clear: its outer diameter (an internal thread's: its inner one).
    #[serde(serialize_with = "crate::num::ser_round")]
    pub edge_x: f64,
    /// The pass (0-based) whose tool comes nearest.
    pub pass: usize,
    /// The tool's tip there: X (diameter) and Z.
    #[serde(serialize_with = "crate::num::ser_round_pair")]
    pub tip: [f64; 2],
    /// How far the flank stays clear of the face at its edge, along Z (negative: that far into it).
    #[serde(serialize_with = "crate::num::ser_round")]
    pub clearance: f64,
    /// The distance the tip must stay from the face for the flank to clear it, along Z.
    #[serde(serialize_with = "crate::num::ser_round")]
    pub needed: f64,
}

fn ser_round_vec<S: serde::Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(v.iter().map(|x| crate::num::round_out(*x)))
}

/// The chip load of one pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ChipLoad {
    /// Area this pass removes (program units²); `None` for a 0° (square) tool.
    #[serde(serialize_with = "ser_round_opt")]
    pub area: Option<f64>,
    /// Area of the same pass in a constant-area schedule.
    #[serde(serialize_with = "ser_round_opt")]
    pub even_area: Option<f64>,
    /// Depth of the same pass in a constant-area schedule: H·√(k/N).
    #[serde(serialize_with = "ser_round_opt")]
    pub even_depth: Option<f64>,
}

/// The three-wire measurement of an external thread (reference
/// threading.md §11): wires of the best size w = P / (2·cos(a/2)) laid in
/// the thread space measure M = d2 + w·(1 + 1/sin(a/2)) − (P/2)·cot(a/2)
/// over them (60°: w = 0.57735·P, M = d2 + 3w − 0.866025·P; no helix
/// correction); the pitch diameter's limits give M's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OverWires {
    /// Best wire diameter.
    #[serde(serialize_with = "ser_round")]
    pub wire: f64,
    /// Measurement over the wires for the pitch diameter cut.
    #[serde(serialize_with = "ser_round")]
    pub m: f64,
    /// M at the pitch diameter's lower limit.
    #[serde(serialize_with = "ser_round_opt")]
    pub m_min: Option<f64>,
    /// M at its upper limit.
    #[serde(serialize_with = "ser_round_opt")]
    pub m_max: Option<f64>,
}

/// The thread check of one thread. Diameters in program units.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Gauge {
    /// The designation as written.
    pub designation: String,
    /// Where it was read.
    pub source: DesignationSource,
    /// The line of the comment it was read from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<u32>,
    /// Standard family.
    pub system: System,
    /// Tolerance class (`6g`, `2A`…); none for NPT.
    pub class: Option<String>,
    /// External or internal, as checked.
    pub kind: Kind,
    /// Basic major diameter.
    #[serde(serialize_with = "ser_round")]
    pub basic_major: f64,
    /// Basic pitch diameter (NPT: E0).
    #[serde(serialize_with = "ser_round")]
    pub basic_pitch: f64,
    /// Basic minor diameter.
    #[serde(serialize_with = "ser_round")]
    pub basic_minor: f64,
    /// Pitch diameter the program cuts (NPT: at the small end of the cut).
    #[serde(serialize_with = "ser_round")]
    pub pitch_diameter: f64,
    /// Lower limit of the pitch diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub pitch_diameter_min: Option<f64>,
    /// Upper limit of the pitch diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub pitch_diameter_max: Option<f64>,
    /// Major diameter of the thread as cut: the root the tool cuts (internal) or the turned crest (external, when turned).
    #[serde(serialize_with = "ser_round_opt")]
    pub major_diameter: Option<f64>,
    /// Lower limit of the major diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub major_diameter_min: Option<f64>,
    /// Upper limit of the major diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub major_diameter_max: Option<f64>,
    /// Minor diameter as cut: the root the tool cuts (external) or the turned bore (internal, when turned).
    #[serde(serialize_with = "ser_round_opt")]
    pub minor_diameter: Option<f64>,
    /// Lower limit of the minor diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub minor_diameter_min: Option<f64>,
    /// Upper limit of the minor diameter.
    #[serde(serialize_with = "ser_round_opt")]
    pub minor_diameter_max: Option<f64>,
    /// Whether the thread gauges: pitch diameter within its limits, the cut
    /// root clearing the gauge, a turned crest within its limits, lead,
    /// kind and tool angle as the designation says (NPT: the taper).
    pub ok: bool,
    /// Change of the final pass's X (diameter) that puts the pitch diameter
    /// in the middle of its tolerance.
    #[serde(serialize_with = "ser_round_opt")]
    pub delta_x: Option<f64>,
    /// The tool's nose radius the check used (program units).
    #[serde(serialize_with = "ser_round")]
    pub nose_radius: f64,
    /// Whether that radius was assumed (no `tool.nose_radius` given): a
    /// full-profile insert, 0.125·P.
    pub nose_radius_assumed: bool,
    /// With the tool not known: the nose radii (program units, from 0 to
    /// 0.25·P) for which the pitch diameter is within its limits, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gauges_with_nose: Option<[f64; 2]>,
    /// What the operator measures over three wires (external straight threads).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub over_wires: Option<OverWires>,
    /// NPT: the cut taper on diameter per unit length (1/16 = 0.0625 wanted).
    #[serde(serialize_with = "ser_round_opt", skip_serializing_if = "Option::is_none")]
    pub taper: Option<f64>,
    /// NPT: the Z where the cut pitch diameter is E0 (external) or E1 (internal): where the L1 gauge sits.
    #[serde(serialize_with = "ser_round_opt", skip_serializing_if = "Option::is_none")]
    pub gauge_plane_z: Option<f64>,
    /// What was found wrong, and what was not checked.
    pub notes: Vec<crate::message::Message>,
}
