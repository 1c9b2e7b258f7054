//! G76, the multiple threading cycle (Fanuc 0i and GSK980TDc two-block form).
//!
//! `G76 P(m)(r)(a) Q(Δdmin) R(d);` — m finishing passes (2 digits), r
//! chamfer in tenths of a lead (2 digits), a tool angle (2 digits).
//! `G76 X(U) Z(W) R(i) P(k) Q(Δd) F;` — degressive depth Δd·√n, single
//! flank infeed along the flank that leads into the cut.

use super::{Reader, ThreadRules, words};
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::{Anchor, Geometry, Multi, runout, schedule};
use crate::event::Event;
use crate::message::{self as msg, Arg};
use crate::settings::P;
use crate::state::G76First;
use crate::thread::{Infeed, Source};

/// How a controller's G76 differs: its words, parameters and accepted angles.
#[derive(Clone, Copy, Debug)]
pub struct Form {
    /// Words of the second block.
    pub words: &'static [u8],
    /// Parameter of the finishing pass count m.
    pub m: P,
    /// Parameter of the chamfer r (tenths of a lead).
    pub r: P,
    /// Parameter of the tool angle a.
    pub a: P,
    /// Parameter of Δdmin (least input increments).
    pub dmin: P,
    /// Parameter of the finishing allowance d (least input increments).
    pub d: P,
    /// The tool angles the controller accepts (`None`: any of 00–99).
    pub angles: Option<&'static [u32]>,
    /// Parameter of the chamfer angle (`None`: 45°).
    pub chamfer_angle: Option<P>,
    /// The smallest finishing count m the first block takes (GSK 00, Fanuc 01).
    pub m_min: u32,
    /// The first block rewrites the Δdmin and d parameters too, not only m, r and a.
    pub rewrites_depths: bool,
}

/// The first block's values as the parameters give them.
fn defaults(r: &Reader, f: &Form) -> G76First {
    let inc = r.s.length_increment(r.m.inch);
    G76First {
        m: r.param(f.m) as u32,
        r: r.param(f.r) as u32,
        a: r.param(f.a) as u32,
        dmin: Some(r.param(f.dmin) * inc),
        d: Some(r.param(f.d) * inc),
        line: 0,
    }
}

/// A G76 block: the first (no axis words) stores its words, the second plans the thread.
pub fn block(r: &mut Reader, t: &ThreadRules, b: &Block, g: &Word) {
    r.m.jk = (None, None);
    r.close();
    if b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W') {
        second(r, t, b, g);
    } else {
        first(r, t, b);
    }
}

/// The first block.
fn first(r: &mut Reader, t: &ThreadRules, b: &Block) {
    if !r.check_words(b, b"PQR", "G76 (first block)") {
        return;
    }
    let form = &t.g76;
    let mut f = G76First { line: b.line, ..defaults(r, form) };
    if let Some(w) = b.get(b'P').copied() {
        if w.num.has_point || w.value() < 0.0 || w.num.int_digits > 6 {
            r.diag(&msg::G76_P_DIGITS, w.span, args![word = w]);
            return;
        }
        let v = w.value() as u32;
        f.m = v / 10000;
        f.r = (v / 100) % 100;
        f.a = v % 100;
        if f.m < form.m_min {
            r.diag(&msg::G76_FINISH_COUNT, w.span, args![word = w, min = format!("{:02}", form.m_min)]);
            return;
        }
        if let Some(angles) = form.angles.filter(|a| !a.contains(&f.a)) {
            let mut list = angles.iter().map(u32::to_string).collect::<Vec<_>>();
            let last = list.pop().unwrap_or_default();
            let a =
                args![word = w, a = f.a, controller = Arg::lit(words::short_title(r)), list = list.join(", "), last];
            r.diag(&msg::G76_TOOL_ANGLE, w.span, a);
            return;
        }
    }
    if !words::min_cut_and_allowance(r, t, b, &mut f.dmin, &mut f.d) {
        return;
    }
    // The values rewrite their parameters for the rest of the program
    // (GSK980TDc §3.21.7: "the system parameter №057 value is rewritten to m", №019 to r, №058 to a).
    r.m.rewrite(form.m, f.m as f64);
    r.m.rewrite(form.r, f.r as f64);
    r.m.rewrite(form.a, f.a as f64);
    if form.rewrites_depths {
        let inc = r.s.length_increment(r.m.inch);
        if let Some(v) = f.dmin {
            r.m.rewrite(form.dmin, (v / inc).round());
        }
        if let Some(v) = f.d {
            r.m.rewrite(form.d, (v / inc).round());
        }
    }
    r.m.cycle.g76 = Some(f);
}

/// The second block.
fn second(r: &mut Reader, t: &ThreadRules, b: &Block, g: &Word) {
    let form = &t.g76;
    if !r.check_words(b, form.words, "G76") {
        return;
    }
    let Some((lead, k, dd)) = words::height_and_first_depth(r, t, b, g, "G76") else { return };
    let i = match b.get(b'R').copied() {
        Some(w) => r.length(&w),
        None => 0.0,
    };
    let f = r.m.cycle.g76.clone().unwrap_or_else(|| defaults(r, form));
    let start = r.current(b.span);
    let target = r.target(b);
    let mut geom = match Geometry::new(start, target.p, i, "G76") {
        Ok(geom) => geom,
        Err(f) => return r.finding(f, g.span),
    };
    let chamfer_angle = form.chamfer_angle.map_or(45.0, |p| r.param(p));
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
        r.diag(&msg::ALLOWANCE_OVER_HEIGHT, g.span, args![d, k]);
        return;
    }
    let multi = Multi {
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
            dmin_rule: words::dmin_rule(r),
            finish_rule: words::finish_rule(r),
        },
        infeed,
        angle: f.a as f64,
        left_side: -1.0,
        anchor: Anchor::Start,
        spindle: r.spindle(),
    };
    r.emit(Event::Multi(Box::new(multi)));
    r.arrive(start, true, true, b.line);
}
