//! Thread standards: designations and tolerance limits.
//!
//! A leaf module (it uses no other module of the crate). It reads a thread
//! designation from free text, such as a G-code comment `(M48x2-6g)` or a
//! setting value, with [`parse`] or [`find`], and computes the limits of size
//! of the thread with [`limits`]. All lengths of the API are millimetres;
//! inch threads also carry their inch values ([`Limits::inch`]).
//!
//! # Standards and formulas
//!
//! **ISO metric** (ISO 68-1 profile, ISO 261/262 pitches, ISO 965-1
//! tolerances, ISO 965-2 / DIN 13 limits):
//! basic pitch diameter d2 = d − 0.649519·P, basic minor diameter
//! D1 = d1 = d − 1.082532·P, external root d3 = d − 1.226869·P. Limits are
//! basic + fundamental deviation (es for e f g h, EI for G H), then ∓ the
//! tolerance of the grade: Td2 (grades 3–9) and TD2 (4–8) keyed by pitch and
//! diameter range (0.99–1.4–2.8–5.6–11.2–22.4–45–90–180–355 mm, "over … up
//! to and including"), Td (grades 4, 6, 8) and TD1 (4–8) keyed by pitch.
//! The standard's formulas (e.g. es(g) = −(15 + 11·P) µm,
//! Td2(6) = 90·P^0.4·d^0.1 µm with d the geometric mean of the range, TD2 =
//! 1.32·Td2, grade factors 0.5 … 2) are rounded in the published tables to
//! values that no single rounding rule reproduces (e.g. es(g) at P 0.75 is
//! −22 µm, Td2(6) for M4×0.5 is 75 µm where the formula rounds to 80), so the
//! published table values are embedded, not the formulas. Basic diameters
//! are rounded to 0.001 mm before the deviations (whole µm) are applied, as
//! in the ISO 965-2 tables. The external minor diameter is given as
//! d3 min = d2 min − 0.616025·P (root radius R ≥ 0.125·P, ISO 965-1) and a
//! reference maximum D1 + es (flat root, as tabulated by ASME B1.13M and
//! DIN 13).
//!
//! **Unified inch** (ASME B1.1): allowance es = 0.300·Td2(2A) for classes
//! 1A and 2A (0 for 3A); Td2(2A) = 0.0015·∛D + 0.0015·√LE + 0.015·∛P² in,
//! with LE = D for UNC, UNF and the 4-, 6-, 8-UN series and LE = 9·P for
//! UNEF, the 12- to 32-UN series and UNS; Td2(1A) = 1.5·Td2(2A),
//! Td2(3A) = 0.75·Td2(2A); internal TD2 = 1.3·Td2 of the matching external
//! class (1B 1.95, 2B 1.3, 3B 0.975 × Td2(2A)); major tolerance
//! 0.060·∛P² (2A, 3A) or 0.090·∛P² (1A); internal minor tolerance
//! 0.05·∛P² + 0.03·P/D − 0.002 bounded by 0.394·P above and, for 1B/2B,
//! 0.25·P − 0.4·P² below (used alone from 1/4 in up), for 3B by
//! 0.23·P − 1.5·P² (13 tpi and finer) or 0.12·P below. Tolerances, allowance
//! and basic diameters are rounded to 0.0001 in and then added, as the
//! published tables are (the three terms of Td2(2A) are carried to
//! 0.000001 in first, which the 1/4-20 2B tolerance 0.0049 requires); 1B/2B minor diameter limits are rounded to 0.001 in
//! from #6 (0.138 in) up. The UNR external minor diameter (reference) is
//! d2 max − 0.541266·P (5/8·H below the pitch line).
//!
//! **NPT** (ASME B1.20.1): taper 1:16 on diameter, E0 = D − (0.05·D + 1.1)·p
//! at the small end of the pipe, E1 = E0 + L1/16 at the hand-tight plane,
//! L2 = (0.8·D + 6.8)·p, E2 = E0 + L2/16, thread height 0.8·p; L1 is
//! tabulated. NPT has no pitch-diameter class tolerance: the thread is gauged
//! ±1 turn from the L1 gauge plane.
//!
//! # Sources
//!
//! Values were read from, and the tests cite: ISO 965-1:1998 tables as
//! reproduced in public transcriptions (checked against each other and
//! against the ISO 965-2 / DIN 13 6g/6H limit tables of the `threadlib`
//! project's `metric_thread.csv`), the Yamawa tap catalogue (TD2 of 4H/5H/6H),
//! efunda's Unified tables, MachineCalcs' ASME B1.1 calculator notes, and the
//! ASME B1.20.1 basic dimension tables of unifiedalloys.com. Where a
//! transcription disagreed with the others it is noted in the table's
//! comment. See `tests/standards.rs` for the published values checked.

mod iso;
mod npt;
mod parse;
mod unified;

use serde::Serialize;

use crate::args;
use crate::message as msg;

pub use parse::find;

/// Millimetres per inch.
pub const MM_PER_INCH: f64 = 25.4;

/// The family of standards a designation belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum System {
    /// ISO general purpose metric screw threads (ISO 261, ISO 965).
    IsoMetric,
    /// Unified inch screw threads (ASME B1.1).
    Unified,
    /// American taper pipe threads (ASME B1.20.1).
    Npt,
}

/// The pitch series of a designation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Series {
    /// ISO 261 coarse pitch.
    Coarse,
    /// ISO 261 fine pitch (any pitch other than the coarse one).
    Fine,
    /// Unified coarse.
    Unc,
    /// Unified fine.
    Unf,
    /// Unified extra fine.
    Unef,
    /// Unified constant pitch (UN).
    Un,
    /// Unified special (UNS).
    Uns,
    /// National pipe taper.
    Npt,
}

/// External (bolt) or internal (nut) thread.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// External thread (turned on a shaft).
    External,
    /// Internal thread (bored in a nut).
    Internal,
}

/// One ISO tolerance zone: a grade and a position letter, e.g. `6g`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct IsoZone {
    /// Tolerance grade (3–9).
    pub grade: u8,
    /// Position: `e`, `f`, `g`, `h` external; `G`, `H` internal.
    pub position: char,
}

/// A tolerance class.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Class {
    /// ISO 965-1: pitch-diameter zone, then the crest-diameter zone
    /// (major for external, minor for internal); equal for `6g`.
    Iso {
        /// Zone of the pitch diameter.
        pitch: IsoZone,
        /// Zone of the crest diameter.
        crest: IsoZone,
    },
    /// ASME B1.1 class 1, 2 or 3 (A external, B internal).
    Unified {
        /// 1, 2 or 3.
        grade: u8,
    },
}

impl std::fmt::Display for Class {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Class::Iso { pitch, crest } if pitch == crest => write!(f, "{}{}", pitch.grade, pitch.position),
            Class::Iso { pitch, crest } => {
                write!(f, "{}{}{}{}", pitch.grade, pitch.position, crest.grade, crest.position)
            }
            Class::Unified { grade } => write!(f, "{grade}"),
        }
    }
}

/// A parsed thread designation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Designation {
    /// The text as given.
    pub text: String,
    /// Standard family.
    pub system: System,
    /// Pitch series.
    pub series: Series,
    /// Nominal (basic major) diameter, mm. For NPT the pipe's outside diameter.
    pub nominal_mm: f64,
    /// Nominal diameter in inches (inch standards only).
    pub nominal_in: Option<f64>,
    /// Pitch, mm (axial distance between adjacent threads).
    pub pitch_mm: f64,
    /// Threads per inch (inch standards only).
    pub tpi: Option<f64>,
    /// Lead, mm (advance per turn: pitch × starts).
    pub lead_mm: f64,
    /// Number of starts.
    pub starts: u32,
    /// External or internal.
    pub kind: Kind,
    /// Tolerance class; `None` for NPT.
    pub class: Option<Class>,
    /// True when the text gave no class and the standard's medium default
    /// (6g/6H, 2A/2B) was used.
    pub class_defaulted: bool,
    /// Left-hand thread.
    pub left_hand: bool,
    /// Remarks made while reading (defaults applied, parts ignored).
    pub notes: Vec<String>,
}

impl Designation {
    /// Sets external/internal. The class follows only when it was defaulted
    /// (6g ↔ 6H, 2A ↔ 2B); an explicit class keeps its own kind.
    pub fn with_kind(mut self, kind: Kind) -> Designation {
        if self.class_defaulted && self.kind != kind {
            self.kind = kind;
            self.class = match self.class {
                Some(Class::Iso { .. }) => Some(parse::iso_default(kind)),
                other => other,
            };
        } else if self.class.is_none() {
            self.kind = kind;
        }
        self
    }
}

/// A designation or limits request that could not be understood or served.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Error {
    /// What was not understood, in words (English).
    pub message: String,
    /// The same as a message of the catalogue (in any language).
    #[serde(skip)]
    pub detail: crate::message::Message,
}

impl Error {
    fn new(template: &'static crate::message::Template, args: crate::message::Args) -> Error {
        let detail = crate::message::Message::new(template, args);
        Error { message: detail.render(crate::message::Lang::En), detail }
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

/// The lower and upper limit of a diameter; `None` where the standard sets none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Limit {
    /// Smallest allowed diameter.
    pub min: Option<f64>,
    /// Largest allowed diameter.
    pub max: Option<f64>,
}

impl Limit {
    fn both(min: f64, max: f64) -> Limit {
        Limit { min: Some(min), max: Some(max) }
    }

    fn scaled(self, k: f64) -> Limit {
        Limit { min: self.min.map(|v| v * k), max: self.max.map(|v| v * k) }
    }
}

/// Basic and toleranced diameters, all in one unit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Diameters {
    /// Basic major diameter (d, D).
    pub basic_major: f64,
    /// Basic pitch diameter (d2, D2); for NPT, E0 at the small end.
    pub basic_pitch: f64,
    /// Basic minor diameter of the internal thread (D1 = d − 1.082532·P).
    pub basic_minor: f64,
    /// Basic root diameter of the external thread where the standard names
    /// one (ISO d3 = d − 1.226869·P).
    pub basic_root: Option<f64>,
    /// Major diameter limits.
    pub major: Limit,
    /// Pitch diameter limits.
    pub pitch: Limit,
    /// Minor diameter limits (internal: D1; external: root, see module doc).
    pub minor: Limit,
}

impl Diameters {
    fn scaled(&self, k: f64) -> Diameters {
        Diameters {
            basic_major: self.basic_major * k,
            basic_pitch: self.basic_pitch * k,
            basic_minor: self.basic_minor * k,
            basic_root: self.basic_root.map(|v| v * k),
            major: self.major.scaled(k),
            pitch: self.pitch.scaled(k),
            minor: self.minor.scaled(k),
        }
    }
}

/// Deviation and tolerances applied, in the unit of their [`Diameters`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Tolerances {
    /// Fundamental deviation (es external, EI internal) or, for Unified,
    /// minus the allowance (signed: negative moves an external thread down).
    pub deviation: f64,
    /// Pitch-diameter tolerance.
    pub pitch: f64,
    /// Crest-diameter tolerance (major external, minor internal).
    pub crest: f64,
}

/// Taper pipe thread dimensions (NPT), mm.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Taper {
    /// Taper on diameter (1/16).
    pub taper_on_diameter: f64,
    /// Pitch diameter at the small end of the external thread.
    pub e0: f64,
    /// Pitch diameter at the hand-tight (L1 gauge) plane.
    pub e1: f64,
    /// Length of hand-tight engagement from the small end.
    pub l1: f64,
    /// Effective thread length from the small end.
    pub l2: f64,
    /// Pitch diameter at the end of the effective thread.
    pub e2: f64,
    /// Thread height (0.8·p).
    pub height: f64,
}

/// Limits of size of a designation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Limits {
    /// Standard family.
    pub system: System,
    /// External or internal.
    pub kind: Kind,
    /// Class used (after defaults).
    pub class: Option<Class>,
    /// Diameters, mm.
    pub mm: Diameters,
    /// Diameters in inches, as tabulated by the inch standards.
    pub inch: Option<Diameters>,
    /// Deviation and tolerances used, mm; `None` for NPT.
    pub tolerances: Option<Tolerances>,
    /// Taper dimensions, mm (NPT only).
    pub taper: Option<Taper>,
    /// Taper dimensions in inches (NPT only).
    pub taper_inch: Option<Taper>,
    /// What the limits mean and what they leave out.
    pub notes: Vec<String>,
}

/// Reads one thread designation, e.g. `M10x1.5-6g`, `M30xPh6P2`,
/// `1/4-20 UNC-2A`, `#10-32 UNF`, `1/2-14 NPT`.
pub fn parse(text: &str) -> Result<Designation, Error> {
    parse::parse(text)
}

/// Computes the limits of size of a designation per its standard.
pub fn limits(d: &Designation) -> Result<Limits, Error> {
    if !(d.nominal_mm.is_finite() && d.pitch_mm.is_finite() && d.nominal_mm > 0.0 && d.pitch_mm > 0.0) {
        return Err(Error::new(&msg::STD_NOT_POSITIVE, args![]));
    }
    match d.system {
        System::IsoMetric => iso::limits(d),
        System::Unified => unified::limits(d),
        System::Npt => npt::limits(d),
    }
}

/// Rounds to `decimals` places (half away from zero), free of binary noise.
fn round_to(v: f64, decimals: i32) -> f64 {
    let k = 10f64.powi(decimals);
    (v * k).round() / k
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn class_display() {
        let z = |grade, position| IsoZone { grade, position };
        assert_eq!(Class::Iso { pitch: z(6, 'g'), crest: z(6, 'g') }.to_string(), "6g");
        assert_eq!(Class::Iso { pitch: z(5, 'g'), crest: z(6, 'g') }.to_string(), "5g6g");
        assert_eq!(Class::Unified { grade: 2 }.to_string(), "2");
    }

    #[test]
    fn with_kind_flips_only_defaults() {
        let d = parse("M10").unwrap().with_kind(Kind::Internal);
        assert_eq!(d.kind, Kind::Internal);
        assert_eq!(d.class.unwrap().to_string(), "6H");
        let d = parse("M10-6g").unwrap().with_kind(Kind::Internal);
        assert_eq!(d.kind, Kind::External);
        let d = parse("1/4-20 UNC").unwrap().with_kind(Kind::Internal);
        assert_eq!(d.kind, Kind::Internal);
        assert_eq!(d.class, Some(Class::Unified { grade: 2 }));
    }

    #[test]
    fn limits_reject_nonsense_numbers() {
        let mut d = parse("M10").unwrap();
        d.pitch_mm = f64::NAN;
        assert!(limits(&d).is_err());
        d.pitch_mm = -1.0;
        assert!(limits(&d).is_err());
    }
}
