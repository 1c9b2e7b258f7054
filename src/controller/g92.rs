//! G92, the simple threading cycle: one pass per block.
//!
//! From the start point A: rapid in X to the pass, thread cut to Z (taper
//! R), run-out, rapid retract in X to A's diameter, rapid back to A's Z.
//! Modal: following blocks with X (or U) cut further passes. GSK adds J/K
//! run-out (as G78) and L starts, modal as the cycle is; Fanuc chamfers by
//! parameters 5130/5131 and takes a start angle Q.

use super::reader::g_span;
use super::{Reader, ThreadRules, words};
use crate::args;
use crate::block::Block;
use crate::cycle::{Geometry, runout};
use crate::event::{Event, G92Pass};
use crate::message::{self as msg};
use crate::motion::Point;
use crate::settings::P;
use crate::state::G92Modal;

/// How a controller's G92 ends its thread and counts its starts.
#[derive(Clone, Copy, Debug)]
pub enum Form {
    /// GSK: `J`/`K` run-out (default: the parameter, tenths of a lead at
    /// 45°) and `L` starts.
    RunoutAndStarts {
        /// Words G92 takes.
        words: &'static [u8],
        /// The run-out parameter (No.019).
        runout: P,
    },
    /// Fanuc: a chamfer set by parameters (length in tenths of a lead,
    /// angle) and a start angle `Q`.
    ChamferAndAngle {
        /// Words G92 takes.
        words: &'static [u8],
        /// Chamfer length parameter (5130).
        length: P,
        /// Chamfer angle parameter (5131).
        angle: P,
    },
}

impl Form {
    fn words(self) -> &'static [u8] {
        match self {
            Form::RunoutAndStarts { words, .. } | Form::ChamferAndAngle { words, .. } => words,
        }
    }
}

/// One G92 block (the cycle call or a further pass).
pub fn block(r: &mut Reader, t: &ThreadRules, b: &Block, tool_angle: f64) {
    r.m.jk = (None, None);
    if !r.check_words(b, t.g92.words(), "G92") {
        return;
    }
    let g_span = g_span(b);
    let Some(lead) = words::lead(r, t, b, "G92") else { return };
    let a = r.current(b.span);
    let target = r.target(b);
    let modal = r.m.cycle.g92;
    let z = match (target.has_z, modal) {
        (true, _) => target.p.z,
        (false, Some(m)) => m.z,
        (false, None) => {
            r.diag(&msg::G92_NEEDS_Z, g_span, args![]);
            return;
        }
    };
    let taper = match b.get(b'R').copied() {
        Some(w) => r.length(&w),
        None if !target.has_z => modal.map_or(0.0, |m| m.r),
        None => 0.0,
    };
    let end = Point::new(target.p.x, z);
    let mut geom = match Geometry::new(a, end, taper, "G92") {
        Ok(g) => g,
        Err(f) => return r.finding(f, g_span),
    };
    // J, K and L are modal: every later pass block keeps them, with or
    // without Z, until they are given again (GSK980TDc §3.21.6; GSK988TA G92).
    let j = b.get(b'J').map(|w| w.value()).or(modal.and_then(|m| m.j));
    let k = b.get(b'K').map(|w| w.value()).or(modal.and_then(|m| m.k));
    let mut starts = modal.map_or(1, |m| m.starts);
    let mut angle = 0.0;
    match t.g92 {
        Form::RunoutAndStarts { runout: p, .. } => {
            geom.runout = runout::gsk(j, k, r.param(p), lead);
            if let Some(w) = b.get(b'L').copied() {
                if !r.in_range(&w, w.value(), 1.0, 99.0, &msg::STARTS_L) || w.num.integer().is_none() {
                    return;
                }
                starts = w.value() as u32;
            }
        }
        Form::ChamferAndAngle { length, angle: chamfer, .. } => {
            geom.runout = runout::fanuc(r.param(length), r.param(chamfer), lead);
            if let Some(q) = b.get(b'Q').copied() {
                let Some(q) = words::start_angle(r, t, &q) else { return };
                angle = q;
            }
        }
    }
    r.m.cycle.g92 = Some(G92Modal { z, r: taper, j, k, starts });
    if let Err(f) = geom.check_ends(0.0) {
        return r.finding(f, g_span);
    }
    let pts = geom.pass(0.0, 0.0, 0.0);
    let spindle = r.spindle();
    r.emit(Event::G92(Box::new(G92Pass {
        geom,
        pts,
        lead,
        angle,
        starts,
        line: b.line,
        span: b.span,
        tool_angle,
        spindle,
    })));
    r.arrive(a, true, true, b.line);
}
