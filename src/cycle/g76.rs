//! G76, the multiple threading cycle (Fanuc 0i and GSK980TDc two-block form).
//!
//! `G76 P(m)(r)(a) Q(Δdmin) R(d);` — m finishing passes (2 digits), r
//! chamfer in tenths of a lead (2 digits), a tool angle (2 digits).
//! `G76 X(U) Z(W) R(i) P(k) Q(Δd) F;` — degressive depth Δd·√n, single
//! flank infeed along the flank that leads into the cut.

use super::{Geometry, Multi, height_and_first_depth, min_cut_and_allowance, plan_multi, runout, schedule};
use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::dialect::Dialect;
use crate::interp::Interp;
use crate::num::fmt;
use crate::settings::P;
use crate::thread::{Infeed, Source};

/// The first G76 block.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct First {
    /// Finishing passes m.
    pub m: u32,
    /// Chamfer r, tenths of a lead.
    pub r: u32,
    /// Tool angle a.
    pub a: u32,
    /// Δdmin.
    pub dmin: Option<f64>,
    /// Finishing allowance d.
    pub d: Option<f64>,
    /// Line of the block.
    pub line: u32,
}

const FANUC_ANGLES: [u32; 6] = [80, 60, 55, 30, 29, 0];

/// Defaults of the first block from the parameters.
fn defaults(it: &Interp) -> First {
    let inc = it.s.length_increment(it.inch);
    match it.dialect {
        Dialect::Fanuc0i => First {
            m: it.s.int(P::Fanuc5142) as u32,
            r: it.s.int(P::Fanuc5130) as u32,
            a: it.s.int(P::Fanuc5143) as u32,
            dmin: Some(it.s.get(P::Fanuc5140) * inc),
            d: Some(it.s.get(P::Fanuc5141) * inc),
            line: 0,
        },
        _ => First {
            m: it.s.int(P::No057) as u32,
            r: it.s.int(P::No019) as u32,
            a: it.s.int(P::No058) as u32,
            dmin: Some(it.s.get(P::No059) * inc),
            d: Some(it.s.get(P::No060) * inc),
            line: 0,
        },
    }
}

/// The first block.
pub fn first(it: &mut Interp, b: &Block) {
    if !it.check_words(b, b"PQR", "G76 (first block)") {
        return;
    }
    let mut f = First { line: b.line, ..defaults(it) };
    if let Some(w) = b.get(b'P').copied() {
        if w.num.has_point || w.value() < 0.0 || w.num.int_digits > 6 {
            it.diag(Code::ValueOutOfRange, w.span, format!("{}: P(m)(r)(a) is six digits, mmrraa", w.display()));
            return;
        }
        let v = w.value() as u32;
        f.m = v / 10000;
        f.r = (v / 100) % 100;
        f.a = v % 100;
        if f.m == 0 {
            it.diag(Code::ValueOutOfRange, w.span, format!("{}: the finishing count m must be 01..99", w.display()));
            return;
        }
        if it.dialect == Dialect::Fanuc0i && !FANUC_ANGLES.contains(&f.a) {
            it.diag(
                Code::ValueOutOfRange,
                w.span,
                format!("{}: tool angle {}°; Fanuc G76 takes 80, 60, 55, 30, 29 or 0", w.display(), f.a),
            );
            return;
        }
    }
    if !min_cut_and_allowance(it, b, &mut f.dmin, &mut f.d) {
        return;
    }
    it.cycle.g76 = Some(f);
}

/// The second block.
pub fn second(it: &mut Interp, b: &Block, g: Word) {
    let allowed: &[u8] = if it.dialect == Dialect::Gsk980tdc { b"XZUWRPQFI" } else { b"XZUWRPQF" };
    if !it.check_words(b, allowed, "G76") {
        return;
    }
    let Some((lead, k, dd)) = height_and_first_depth(it, b, &g, "G76") else { return };
    let i = match b.get(b'R').copied() {
        Some(w) => it.length(&w),
        None => 0.0,
    };
    let f = it.cycle.g76.clone().unwrap_or_else(|| defaults(it));
    let start = it.current(b.span);
    let t = it.target(b);
    let Some(mut geom) = Geometry::new(it, start, t.p, i, g.span, "G76") else { return };
    let chamfer_angle = if it.dialect == Dialect::Fanuc0i { it.s.get(P::Fanuc5131) } else { 45.0 };
    geom.runout = runout::fanuc(f.r as f64, chamfer_angle, lead);
    // Single flank infeed along the flank that leads into the cut: cutting
    // towards −Z the tip moves −Z as it deepens (the +Z flank).
    let toward_minus = geom.root_end.z < geom.root_start.z;
    let infeed = if toward_minus { Infeed::Right } else { Infeed::Left };
    let mut lines = Vec::new();
    if f.line != 0 {
        lines.push(f.line);
    }
    lines.push(b.line);
    let d = f.d.unwrap_or(0.0);
    if d > k {
        it.diag(
            Code::ValueOutOfRange,
            g.span,
            format!("finishing allowance d = {} is more than the thread height k = {}", fmt(d), fmt(k)),
        );
        return;
    }
    plan_multi(
        it,
        Multi {
            source: Source::G76,
            lines,
            span: g.span,
            geom,
            lead,
            starts: 1,
            schedule: schedule::Spec {
                k,
                first: dd,
                min: f.dmin.unwrap_or(0.0),
                allowance: d,
                mode: schedule::DepthMode::Degressive,
                finish: f.m.max(1),
            },
            infeed,
            angle: f.a as f64,
        },
    );
}
