//! The first and second blocks of the stock-removal cycles of Fanuc 0i and
//! GSK980TDc: G71/G72 (roughing along Z or X) and G73 (pattern
//! repeating). The first block sets the cycle's registers; the second,
//! with P and Q, leaves the cycle in the modal state for the program flow,
//! which reads the contour N(P) … N(Q) and plans the passes over it
//! (`exec::profile`, `cycle::rough`, `cycle::pattern`).

use super::Reader;
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::pattern::Pattern;
use crate::cycle::rough::{Along, Rough};
use crate::message as msg;
use crate::settings::P;

/// G71/G72 (Fanuc Series 21i-TB operator's manual B-63604EN §13.2.1–2;
/// GSK980TDc user manual §3.20): the first block `G71 U(Δd) R(e)` (`G72
/// W(Δd) R(e)`) sets the depth of cut and the escape; the second, with P
/// and Q, takes the finishing allowances U(Δu) W(Δw) and F, and leaves the
/// cycle for the program flow, which roughs over the contour. Without a
/// first block the roughing is not drawn (said once). A depth of cut of 0
/// is an alarm (Fanuc's alarm list, PS0062: "a zero or a negative value …
/// as the depth of cut").
pub fn rough(r: &mut Reader, b: &Block, w: &Word, along: Along) {
    let k = usize::from(along == Along::X);
    r.m.rough_call = None;
    if !(b.has(b'P') && b.has(b'Q')) {
        let depth = b.get(if along == Along::Z { b'U' } else { b'W' }).copied();
        let escape = b.get(b'R').copied();
        if let (Some(d), Some(e)) = (depth, escape) {
            let (dv, e) = (r.length(&d), r.length(&e));
            if dv == 0.0 {
                r.diag(&msg::ROUGH_DEPTH_ZERO, d.span, args![word = &d]);
                r.m.rough_regs[k] = None;
                return;
            }
            r.m.rough_regs[k] = Some((dv.abs(), e.abs()));
        }
        return;
    }
    let what = if along == Along::Z { &msg::NS_G71 } else { &msg::NS_G72 };
    let Some((depth, escape)) = r.m.rough_regs[k] else {
        r.noted(&msg::NOT_DRAWN, w, what);
        return;
    };
    let (du, dw) = allowances(r, b);
    r.m.rough_call = Some(Rough { along, depth, escape, du, dw, pockets: r.rules.pockets });
}

/// The finishing allowances U(Δu) (a diameter, or a radius under radius
/// programming) and W(Δw) of a second block, 0 when not given; its F is the feed.
fn allowances(r: &mut Reader, b: &Block) -> (f64, f64) {
    let du = b.get(b'U').copied().map_or(0.0, |u| r.x_len(&u));
    let dw = b.get(b'W').copied().map_or(0.0, |w| r.length(&w));
    if let Some(f) = b.get(b'F') {
        r.m.feed = Some(f.value());
        r.m.feed_line = b.line;
    }
    (du, dw)
}

/// G73, pattern repeating: the first block `G73 U(Δi) W(Δk) R(d)` sets the
/// relief across (a radius) and along Z and the number of divisions, each
/// word kept until another first block gives it; the second `G73 P(ns)
/// Q(nf) U(Δu) W(Δw) F` takes the allowances and leaves the cycle for the
/// program flow, which cuts the contour d times (`cycle::pattern`).
/// Without any first block the passes are not drawn (said once).
pub fn pattern(r: &mut Reader, b: &Block, w: &Word) {
    r.m.pattern_call = None;
    if !(b.has(b'P') && b.has(b'Q')) {
        return pattern_first(r, b, w);
    }
    let regs = r.m.pattern_regs;
    let d = match regs.d {
        None => return r.noted(&msg::NOT_DRAWN, w, &msg::NS_G73),
        // Its first block was refused: said there.
        Some(0) => return,
        Some(d) => d,
    };
    let (du, dw) = allowances(r, b);
    r.m.pattern_call = Some(Pattern { di: regs.di, dk: regs.dk, d, du, dw });
}

/// A first block `G73 U(Δi) W(Δk) R(d)`. R is a count, whole and at least
/// 1 (the YASNAC LX3's "D command out of the above range causes data
/// error"; Fanuc's PS0062 for a count of 0), at most
/// `limits.passes_per_start`; a relief with no R, before any R, is an alarm.
fn pattern_first(r: &mut Reader, b: &Block, w: &Word) {
    if let Some(u) = b.get(b'U').copied() {
        r.m.pattern_regs.di = r.length(&u);
    }
    if let Some(k) = b.get(b'W').copied() {
        r.m.pattern_regs.dk = r.length(&k);
    }
    let Some(rw) = b.get(b'R').copied() else {
        if r.m.pattern_regs.d.is_none() && (b.has(b'U') || b.has(b'W')) {
            r.diag(&msg::G73_NO_DIVISIONS, w.span, args![word = w]);
            r.m.pattern_regs.d = Some(0);
        }
        return;
    };
    let v = rw.value();
    let limit = r.s.int(P::LimitPasses).max(1);
    r.m.pattern_regs.d = Some(0);
    if !(v >= 1.0 && v.fract() == 0.0) {
        r.diag(&msg::G73_DIVISIONS, rw.span, args![word = &rw]);
    } else if v > limit as f64 {
        r.diag(&msg::G73_DIVISIONS_OVER, rw.span, args![word = &rw, d = v as i64, limit]);
    } else {
        r.m.pattern_regs.d = Some(v as u32);
    }
}
