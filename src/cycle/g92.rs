//! G92, the simple threading cycle: one pass per block.
//!
//! From the start point A: rapid in X to the pass, thread cut to Z (taper
//! R), run-out, rapid retract in X to A's diameter, rapid back to A's Z.
//! Modal: following blocks with only X (or U) cut further passes. GSK adds
//! J/K run-out (as G78) and L starts; Fanuc chamfers by parameters 5130/5131
//! and takes a start angle Q.

use super::{Geometry, in_range, runout};
use crate::block::Block;
use crate::diagnostic::Code;
use crate::dialect::Dialect;
use crate::g32::{read_lead, start_angle};
use crate::group::{Chain, Seg, add_chain};
use crate::interp::Interp;
use crate::settings::P;
use crate::thread::{Axis, Source};

/// Values a G92 continuation block takes from the block before it: a block
/// with only X (or U) repeats the cycle at the new diameter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Modal {
    /// Absolute end Z.
    pub z: f64,
    /// Taper R(i).
    pub r: f64,
    /// GSK run-out J.
    pub j: Option<f64>,
    /// GSK run-out K.
    pub k: Option<f64>,
    /// GSK starts L.
    pub starts: u32,
}

/// One G92 block (the cycle call or a continuation).
pub fn block(it: &mut Interp, b: &Block, has_axes: bool) {
    let gsk = it.dialect == Dialect::Gsk980tdc;
    let allowed: &[u8] = if gsk { b"XZUWRIJKL" } else { b"XZUWRQ" };
    if !it.check_words(b, allowed, "G92") || !has_axes {
        return;
    }
    let g_span = b.all(b'G').next().map_or(b.span, |w| w.span);
    let Some(lead) = read_lead(it, b, "G92") else { return };
    let a = it.current(b.span);
    let t = it.target(b);
    let modal = it.cycle.g92;
    let z = if t.has_z {
        t.p.z
    } else if let Some(m) = modal {
        m.z
    } else {
        it.diag(Code::MissingWord, g_span, "G92 needs the thread end Z (or W)");
        return;
    };
    let r = match b.get(b'R').copied() {
        Some(w) => it.length(&w),
        None if !t.has_z => modal.map_or(0.0, |m| m.r),
        None => 0.0,
    };
    let end = crate::motion::Point::new(t.p.x, z);
    let Some(mut geom) = Geometry::new(it, a, end, r, g_span, "G92") else { return };
    // A continuation block (no Z/W) keeps the run-out and starts of the block before it.
    let carried = if t.has_z { None } else { modal };
    let j = b.get(b'J').map(|w| w.value()).or(carried.and_then(|m| m.j));
    let k = b.get(b'K').map(|w| w.value()).or(carried.and_then(|m| m.k));
    let mut starts = carried.map_or(1, |m| m.starts);
    let mut angle0 = 0.0;
    if gsk {
        geom.runout = runout::gsk(j, k, it.s.get(P::No019), lead);
        if let Some(w) = b.get(b'L').copied() {
            if !in_range(it, &w, w.value(), 1.0, 99.0, "starts L") || w.num.integer().is_none() {
                return;
            }
            starts = w.value() as u32;
        }
    } else {
        geom.runout = runout::fanuc(it.s.get(P::Fanuc5130), it.s.get(P::Fanuc5131), lead);
        if let Some(q) = b.get(b'Q').copied() {
            let Some(q) = start_angle(it, &q) else { return };
            angle0 = q;
        }
    }
    it.cycle.g92 = Some(Modal { z, r, j, k, starts });
    if !geom.check_ends(it, g_span) {
        return;
    }
    let pts = geom.pass(0.0, 0.0, 0.0);
    for s in 0..starts {
        let first_move = it.moves.len();
        geom.emit(it, &pts, b.line, b.span);
        let kind = geom.kind;
        add_chain(
            it,
            Chain {
                source: Source::G92,
                lead,
                segs: vec![Seg { from: pts.from, to: pts.to, runout_to: pts.runout_to, kind, long: Axis::Z }],
                angle: angle0 + 360.0 * s as f64 / starts as f64,
                lines: vec![b.line],
                approach: -geom.out,
                span: b.span,
                first_move,
            },
        );
    }
    it.arrive(a, true, true, b.line);
}
