//! The thread wizard (`screwcut generate`): a thread — a designation, or a
//! major diameter and a lead — its length or start and end Z, external or
//! internal, starts, the machine's limits, and a target controller and form
//! → a program that plans without alarms and cuts the standard's depth.
//!
//! The depth: the last pass puts the pitch diameter in the middle of the
//! class tolerance (the basic pitch diameter without a class) with a 60°
//! tool of nose radius r (reference §9: d2 = X − 2r + 0.866025·P; r not
//! given: a full-profile insert's 0.125·P, as the thread check takes): the final
//! diameter is d2 − 0.866025·P + 2r external, D2 + 0.866025·P − 2r internal
//! (with r = H/6 = 0.144·P an external thread ends at ISO's d3). The crest is
//! the middle of the major (external) or minor (internal) diameter limits. NPT is cut as a 1:16 taper to its
//! truncated height 0.8·P from the small end at the start Z. Infeeds: table
//! 4-3 of the textbook scaled to the depth where it lists the pitch, else
//! constant chip area in 2·P + 1 passes; the cycles get their first depth
//! from the same count.

mod write;

use serde::Serialize;

use crate::args;
use crate::controller;
use crate::dialect::Dialect;
use crate::message::{Arg, Remark, tools};
use crate::num::fmt;
use crate::standard::{self, Kind, System};

pub use crate::form::Form;

impl Form {
    /// The forms a dialect has.
    pub fn of(d: Dialect) -> &'static [Form] {
        controller::of(d).writing.forms
    }
}

/// What the wizard is asked for. Lengths in mm.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// A designation (`M30x2-6g`, `1/2-13 UNC-2B`, `1/2-14 NPT`); else `major` and `lead`.
    pub designation: Option<String>,
    /// Major diameter (nominal), without a designation.
    pub major: Option<f64>,
    /// Lead, without a designation.
    pub lead: Option<f64>,
    /// Starts (default: the designation's, else 1).
    pub starts: Option<u32>,
    /// Internal thread (default: the designation's kind, else external).
    pub internal: Option<bool>,
    /// Z where the thread starts (the face).
    pub start_z: f64,
    /// Z where the thread ends; else `start_z − length`.
    pub end_z: Option<f64>,
    /// Thread length, when no end Z is given.
    pub length: Option<f64>,
    /// Nose radius of the threading tool (mm; 0: not known, a full-profile insert's 0.125·P, as the thread check's `tool.nose_radius`).
    pub nose_radius: f64,
    /// Highest spindle speed, rev/min.
    pub max_rpm: f64,
    /// Highest thread feed (lead × speed), mm/min.
    pub max_feed: f64,
    /// Target controller.
    pub dialect: Dialect,
    /// Target form.
    pub form: Form,
}

impl Default for Request {
    fn default() -> Request {
        Request {
            designation: None,
            major: None,
            lead: None,
            starts: None,
            internal: None,
            start_z: 0.0,
            end_z: None,
            length: None,
            nose_radius: 0.0,
            max_rpm: 1000.0,
            max_feed: 3000.0,
            dialect: Dialect::Gsk980tdc,
            form: Form::G32,
        }
    }
}

/// The thread the program cuts: what the wizard worked out.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Spec {
    /// What was asked for, in words (`M30x2-6g external`).
    pub title: String,
    /// Internal thread.
    pub internal: bool,
    /// Lead (mm per revolution).
    pub lead: f64,
    /// Pitch = lead / starts.
    pub pitch: f64,
    /// Starts.
    pub starts: u32,
    /// Crest diameter at the start Z.
    pub crest: f64,
    /// Diameter of the last pass at the start Z.
    pub root: f64,
    /// Radial depth.
    pub height: f64,
    /// Diameter change per mm along the cut (1/16 for NPT, growing into the part).
    pub taper: f64,
    /// Thread start Z.
    pub z0: f64,
    /// Thread end Z.
    pub z1: f64,
    /// Start and return Z of every pass (the lead-in δ1 before the start).
    pub za: f64,
    /// Start and return X, clear of the thread.
    pub clear_x: f64,
    /// Spindle speed, rev/min.
    pub spindle: f64,
    /// Cumulative radial depth of each pass (block-by-block forms and G92).
    pub depths: Vec<f64>,
}

impl Spec {
    /// Cutting direction along Z (+1 or −1).
    pub fn sense(&self) -> f64 {
        if self.z1 >= self.z0 { 1.0 } else { -1.0 }
    }

    /// Diameter at depth `h` (radial) at `z`.
    pub fn x_at(&self, h: f64, z: f64) -> f64 {
        let grow = self.taper * (z - self.z0) * self.sense();
        let crest = self.crest + grow;
        if self.internal { crest + 2.0 * h } else { crest - 2.0 * h }
    }
}

/// A generated program.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Generated {
    /// The program text.
    pub program: String,
    /// The thread it cuts.
    pub spec: Spec,
    /// Choices made and what the user should know (tool, relief groove, limits).
    pub notes: Vec<Remark>,
}

/// Writes the program `r` asks for, or says why it cannot.
pub fn generate(r: &Request) -> Result<Generated, Remark> {
    if !Form::of(r.dialect).contains(&r.form) {
        let have: Vec<&str> = Form::of(r.dialect).iter().map(|f| f.name()).collect();
        let (dialect, form, forms) = (Arg::lit(r.dialect.title()), r.form.title_phrase(), have.join(", "));
        return Err(Remark::new(&tools::WZ_NO_FORM, args![dialect, form, forms]));
    }
    let (spec, mut notes) = spec(r)?;
    let program = write::program(r, &spec, &mut notes)?;
    Ok(Generated { program, spec, notes })
}

/// The thread's diameters and depth, by its standard.
struct Thread {
    title: String,
    internal: bool,
    lead: f64,
    starts: u32,
    crest: f64,
    root: f64,
    taper: f64,
}

fn thread(r: &Request, notes: &mut Vec<Remark>) -> Result<Thread, Remark> {
    let Some(text) = r.designation.as_deref().filter(|t| !t.trim().is_empty()) else {
        let (Some(d), Some(lead)) = (r.major, r.lead) else {
            return Err(Remark::new(&tools::WZ_NEED_SIZE, args![]));
        };
        let internal = r.internal.unwrap_or(false);
        let starts = r.starts.unwrap_or(1).max(1);
        let p = lead / starts as f64;
        if !(d > 0.0 && lead > 0.0 && d.is_finite() && lead.is_finite()) {
            return Err(Remark::new(&tools::WZ_SIZE_POSITIVE, args![]));
        }
        // A basic 60° thread: d2 = d − 0.649519·P.
        let d2 = d - 0.649_519 * p;
        let (crest, root) =
            if internal { (d - 1.082_532 * p, last_pass(r, d2, p, true)) } else { (d, last_pass(r, d2, p, false)) };
        notes.push(Remark::new(&tools::WZ_BASIC_PROFILE, args![]));
        let side = if internal { "internal" } else { "external" };
        let title = format!("D{} lead {} {side}", fmt(d), fmt(lead));
        return Ok(Thread { title, internal, lead, starts, crest, root, taper: 0.0 });
    };
    let refused = |e: standard::Error| Remark::new(&tools::WZ_DESIGNATION, args![error = e.detail]);
    let mut des = standard::parse(text).map_err(refused)?;
    if let Some(i) = r.internal {
        des = des.with_kind(if i { Kind::Internal } else { Kind::External });
    }
    let lim = standard::limits(&des).map_err(refused)?;
    let internal = des.kind == Kind::Internal;
    let starts = r.starts.unwrap_or(des.starts).max(1);
    let p = des.lead_mm / starts as f64;
    let mid = |l: standard::Limit, basic: f64| match (l.min, l.max) {
        (Some(a), Some(b)) => (a + b) / 2.0,
        (Some(a), None) | (None, Some(a)) => a,
        (None, None) => basic,
    };
    let m = &lim.mm;
    let (crest, root, taper) = if des.system == System::Npt {
        let t = lim.taper.unwrap_or_default();
        notes.push(Remark::new(&tools::WZ_NPT, args![]));
        let (major, minor) = (t.e0 + t.height, t.e0 - t.height);
        if internal { (minor, major, t.taper_on_diameter) } else { (major, minor, t.taper_on_diameter) }
    } else {
        let (radius, how) = nose(r, p, internal);
        notes.push(Remark::new(&tools::WZ_LAST_PASS, args![r = radius, how]));
        let crest = if internal { mid(m.minor, m.basic_minor) } else { mid(m.major, m.basic_major) };
        (crest, last_pass(r, mid(m.pitch, m.basic_pitch), p, internal), 0.0)
    };
    let side = if internal { "internal" } else { "external" };
    Ok(Thread { title: format!("{} {side}", des.text.trim()), internal, lead: des.lead_mm, starts, crest, root, taper })
}

/// The diameter of the last pass that cuts the pitch diameter `d2` with the
/// request's 60° tool (reference §9: d2 = X − 2r(1/sin 30° − 1) + P/(2·tan 30°)).
fn last_pass(r: &Request, d2: f64, p: f64, internal: bool) -> f64 {
    let v = 0.866_025_403_784_438_6 * p - 2.0 * nose(r, p, internal).0;
    if internal { d2 + v } else { d2 - v }
}

/// The nose radius the last pass is placed for: the request's, or, not
/// given (0), a full-profile insert's 0.125·P — the thread check's rule.
fn nose(r: &Request, p: f64, internal: bool) -> (f64, &'static crate::message::Phrase) {
    if r.nose_radius > 0.0 {
        (r.nose_radius, &tools::WZ_NOSE_GIVEN)
    } else {
        (crate::shop::gauge::assumed_nose_radius(p, internal), &tools::WZ_NOSE_ASSUMED)
    }
}

/// The pass depths: table 4-3 scaled to `height` where it lists `pitch`,
/// else constant chip area (depth ∝ √n) in 2·P + 1 passes.
pub fn depths(pitch: f64, height: f64) -> Vec<f64> {
    if let Some(t) = crate::advice::table_4_3(pitch) {
        let total: f64 = t.iter().sum();
        let mut acc = 0.0;
        return t
            .iter()
            .map(|d| {
                acc += d;
                height * acc / total
            })
            .collect();
    }
    let n = ((2.0 * pitch + 1.0).round() as usize).clamp(2, 40);
    (1..=n).map(|k| height * (k as f64 / n as f64).sqrt()).collect()
}

fn spec(r: &Request) -> Result<(Spec, Vec<Remark>), Remark> {
    let mut notes = Vec::new();
    let t = thread(r, &mut notes)?;
    let z0 = r.start_z;
    let z1 = match (r.end_z, r.length) {
        (Some(z), _) => z,
        (None, Some(l)) if l > 0.0 => z0 - l,
        _ => return Err(Remark::new(&tools::WZ_NEED_END, args![])),
    };
    if !(z0.is_finite() && z1.is_finite()) || (z1 - z0).abs() < 1e-6 {
        return Err(Remark::new(&tools::WZ_NO_LENGTH, args![]));
    }
    let height = (t.root - t.crest).abs() / 2.0;
    let pitch = t.lead / t.starts as f64;
    if !(height > 0.0 && height.is_finite() && t.lead.is_finite()) {
        return Err(Remark::new(&tools::WZ_NO_DEPTH, args![]));
    }
    // The textbook's O1006 clearances, δ1 = 5 mm before the work and δ2 = 2 mm
    // past the end (a relief groove), must cover the acceleration zones
    // n·L/500 and n·L/1800: the speed is kept within them.
    let rpm = r.max_rpm.min(r.max_feed / t.lead).min(500.0 * 5.0 / t.lead).min(1800.0 * 2.0 / t.lead).floor();
    if rpm.is_nan() || rpm < 1.0 {
        return Err(Remark::new(&tools::WZ_NO_SPEED, args![lead = t.lead, feed = r.max_feed]));
    }
    notes.push(Remark::new(&tools::WZ_SPINDLE, args![s = rpm, rpm = r.max_rpm, feed = r.max_feed]));
    // Lead-in δ1: at least the textbook's 5 mm and two leads.
    let delta1 = (5.0f64).max(2.0 * t.lead);
    let delta1 = (delta1 * 2.0).ceil() / 2.0;
    let sense = if z1 >= z0 { 1.0 } else { -1.0 };
    let za = z0 - sense * delta1;
    let c = (1.0f64).max(pitch);
    let mut spec = Spec {
        title: t.title,
        internal: t.internal,
        lead: t.lead,
        pitch,
        starts: t.starts,
        crest: t.crest,
        root: t.root,
        height,
        taper: t.taper,
        z0,
        z1,
        za,
        clear_x: 0.0,
        spindle: rpm,
        depths: depths(pitch, height),
    };
    let crests = [spec.x_at(0.0, za), spec.x_at(0.0, z1)];
    spec.clear_x = if t.internal {
        let x = crests[0].min(crests[1]) - 2.0 * c;
        if x <= 0.0 {
            return Err(Remark::new(&tools::WZ_BORE_TOO_SMALL, args![bore = crests[0], clearance = c]));
        }
        x
    } else {
        crests[0].max(crests[1]) + 2.0 * c
    };
    Ok((spec, notes))
}
