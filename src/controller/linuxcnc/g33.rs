//! LinuxCNC G33: one spindle-synchronised straight move from the current
//! point to the end point, K = the distance **along the move** per spindle
//! revolution (not along the long axis as G32's F). K is required in every
//! block (checked before); consecutive G33 blocks make a continuous thread.

use super::{Reader, g_word_span, plane_warning, spindle_number};
use crate::args;
use crate::block::Block;
use crate::controller::g32;
use crate::cycle::classify;
use crate::event::{Event, Seg};
use crate::geom::Frame;
use crate::message::{self as msg, Arg};
use crate::motion::{Move, MoveKind};
use crate::state::once;
use crate::thread::{Source, ThreadKind};

/// One G33 block.
pub fn block(r: &mut Reader, b: &Block) {
    let g = g_word_span(b, 330);
    if !spindle_number(r, b, "Invalid spindle ($) number in G33 move") {
        return r.end_chain();
    }
    if !r.m.spindle_on {
        r.diag(&msg::LCNC_SPINDLE_NOT_TURNING_G33, g, args![]);
        return r.end_chain();
    }
    plane_warning(r, g, "G33");
    let Some(kw) = b.get(b'K').copied() else { return r.end_chain() };
    let k = r.length(&kw);
    let start = r.current(b.span);
    let end = r.target(b).p;
    let Some((kind, long)) = classify(start, end) else {
        // A zero-length G33 is accepted and cuts nothing.
        r.arrive(end, true, true, b.line);
        return r.end_chain();
    };
    if k <= 0.0 {
        let what = if k == 0.0 { &msg::K_ZERO } else { &msg::K_NEGATIVE };
        r.diag(&msg::LCNC_ODD_K, kw.span, args![word = kw, what]);
    }
    if k == 0.0 || !k.is_finite() {
        r.end_chain();
        r.emit(Event::Motion(Move {
            kind: MoveKind::Thread,
            from: start,
            to: end,
            line: b.line,
            span: b.span,
            arc: None,
        }));
        return r.arrive(end, true, true, b.line);
    }
    // K along the move: the lead along the long axis is K·(long travel / length).
    let along = Frame(long).travel(start, end).abs() / start.dist(end);
    let lead = k.abs() * along;
    if kind == ThreadKind::Taper && r.m.first(once::LEAD_ALONG_PATH) {
        let axis = Arg::lit(if long == crate::thread::Axis::Z { "Z" } else { "X" });
        r.diag(&msg::LCNC_LEAD_ALONG_PATH, kw.span, args![word = kw, lead, axis, alpha = along.acos().to_degrees()]);
    }
    let tool_angle = r.param(crate::settings::P::LinuxToolAngle);
    let seg = Seg { from: start, to: end, runout_to: None, kind, long };
    g32::piece(r, Source::LinuxG33, lead, 0.0, seg, end, b, tool_angle);
}
