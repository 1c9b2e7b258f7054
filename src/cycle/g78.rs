//! G78, the GSK980TDc enhanced threading cycle (reference §3, seed 002).
//!
//! `G78 P(m)(r)(a) Q(Δdmin) R(d) J K D L E;`
//! `G78 X(U) Z(W) R(i) P(k) Q(Δd) F(I);`

use super::{Geometry, Multi, height_and_first_depth, in_range, min_cut_and_allowance, plan_multi, runout, schedule};
use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::interp::Interp;
use crate::settings::P;
use crate::thread::{Infeed, Source};

/// The first G78 block: what it gave (None: take the parameter or default).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct First {
    /// Depth mode m (0 equal, 1 degressive).
    pub m: Option<u32>,
    /// Infeed mode r (0 radial, 1 left, 2 right, 3 alternating).
    pub r: Option<u32>,
    /// Tool angle a.
    pub a: Option<u32>,
    /// Δdmin.
    pub dmin: Option<f64>,
    /// Finishing allowance d.
    pub d: Option<f64>,
    /// Run-out J (non-modal: used by the next cycle only).
    pub j: Option<f64>,
    /// Run-out K (non-modal).
    pub k: Option<f64>,
    /// Finishing passes D.
    pub count: Option<u32>,
    /// Starts L.
    pub starts: Option<u32>,
    /// Screw-in E.
    pub e: Option<f64>,
    /// Line of the block.
    pub line: u32,
}

/// Reads `P(m)(r)(a)` right to left: the last two digits are a, the next r,
/// the next m. Digits not written take their parameter, or 0 with the
/// setting `g78.missing_p_digits = zero`.
fn pmra(it: &mut Interp, w: &Word, f: &mut First) -> bool {
    if w.num.has_point || w.value() < 0.0 {
        it.diag(
            Code::DecimalPointNotAllowed,
            w.span,
            format!("{}: P(m)(r)(a) is a plain four-digit number", w.display()),
        );
        return false;
    }
    let digits = w.num.int_digits as u32;
    if digits > 4 {
        it.diag(Code::ValueOutOfRange, w.span, format!("{}: P(m)(r)(a) has at most four digits", w.display()));
        return false;
    }
    let v = w.value() as u32;
    let zero = it.s.int(P::G78MissingDigits) == 1;
    let digit = |written: bool, value: u32| {
        if written {
            Some(value)
        } else if zero {
            Some(0)
        } else {
            None
        }
    };
    f.a = Some(v % 100);
    f.r = digit(digits >= 3, (v / 100) % 10);
    f.m = digit(digits >= 4, (v / 1000) % 10);
    if let Some(m) = f.m {
        if m > 1 {
            it.diag(
                Code::ValueOutOfRange,
                w.span,
                format!("{}: depth mode m = {m}; 0 (equal) or 1 (degressive)", w.display()),
            );
            return false;
        }
    }
    if let Some(r) = f.r {
        if r > 3 {
            it.diag(
                Code::ValueOutOfRange,
                w.span,
                format!("{}: infeed mode r = {r}; 0 middle, 1 left, 2 right or 3 alternating", w.display()),
            );
            return false;
        }
    }
    true
}

/// The first block: stores its words for the following second blocks.
pub fn first(it: &mut Interp, b: &Block) {
    if !it.check_words(b, b"PQRJKDLE", "G78 (first block)") {
        return;
    }
    let mut f = First { line: b.line, ..First::default() };
    if let Some(w) = b.get(b'P').copied() {
        if !pmra(it, &w, &mut f) {
            return;
        }
    }
    if !min_cut_and_allowance(it, b, &mut f.dmin, &mut f.d) {
        return;
    }
    f.j = b.get(b'J').map(|w| w.value().abs());
    f.k = b.get(b'K').map(|w| w.value().abs());
    if let Some(w) = b.get(b'D').copied() {
        if !in_range(it, &w, w.value(), 0.0, 99.0, "finishing count D") || w.num.integer().is_none() {
            return;
        }
        f.count = Some(w.value() as u32);
    }
    if let Some(w) = b.get(b'L').copied() {
        if !in_range(it, &w, w.value(), 1.0, 99.0, "starts L") || w.num.integer().is_none() {
            return;
        }
        f.starts = Some(w.value() as u32);
    }
    if let Some(w) = b.get(b'E').copied() {
        if !in_range(it, &w, w.value(), -9999.9999, 9999.9999, "screw-in E") {
            return;
        }
        f.e = Some(w.value().abs());
    }
    it.cycle.g78 = Some(f);
}

/// The second block: plans the cycle from A (the tool position) to X/Z.
pub fn second(it: &mut Interp, b: &Block, g: Word) {
    if !it.check_words(b, b"XZUWRPQFI", "G78") {
        return;
    }
    let Some((lead, k, dd)) = height_and_first_depth(it, b, &g, "G78") else { return };
    let i = match b.get(b'R').copied() {
        Some(w) => {
            let v = it.length(&w);
            if !in_range(it, &w, v, -99999.999, 99999.999, "taper R(i)") {
                return;
            }
            v
        }
        None => 0.0,
    };
    // The first block: stored values, J/K used once.
    let f = it.cycle.g78.clone().unwrap_or_default();
    if let Some(stored) = it.cycle.g78.as_mut() {
        stored.j = None;
        stored.k = None;
    }
    let m = f.m.unwrap_or(it.s.int(P::No061) as u32);
    let r = f.r.unwrap_or(it.s.int(P::No062) as u32);
    let a = f.a.unwrap_or(it.s.int(P::No058) as u32) as f64;
    let inc = it.s.length_increment(it.inch);
    let dmin = f.dmin.unwrap_or(it.s.get(P::No059) * inc);
    let d = f.d.unwrap_or(it.s.get(P::No060) * inc);
    let count = f.count.unwrap_or(it.s.int(P::G78DefaultD) as u32);
    let starts = f.starts.unwrap_or(1);
    let start = it.current(b.span);
    let t = it.target(b);
    let Some(mut geom) = Geometry::new(it, start, t.p, i, g.span, "G78") else { return };
    geom.runout = runout::gsk(f.j, f.k, it.s.get(P::No019), lead);
    geom.screw_in = f.e.filter(|e| *e > 0.0).map(|e| (e, it.s.get(P::ScrewInLeads) * lead));
    let infeed = match r {
        0 => Infeed::Radial,
        1 => Infeed::Left,
        2 => Infeed::Right,
        _ => Infeed::Alternating,
    };
    let mode = if m == 0 { schedule::DepthMode::Equal } else { schedule::DepthMode::Degressive };
    let mut lines = Vec::new();
    if f.line != 0 {
        lines.push(f.line);
    }
    lines.push(b.line);
    plan_multi(
        it,
        Multi {
            source: Source::G78,
            lines,
            span: g.span,
            geom,
            lead,
            starts,
            schedule: schedule::Spec { k, first: dd, min: dmin, allowance: d, mode, finish: count },
            infeed,
            angle: a,
        },
    );
}
