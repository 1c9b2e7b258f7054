//! Canned cycles: the turning cycles G90/G94 and the threading cycles
//! G92, G76 and G78, planned pass by pass.

pub mod g92;

use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::gcode::G;
use crate::interp::Interp;
use crate::motion::{MoveKind, Point};

/// State the cycles keep between blocks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CycleState {}

impl CycleState {
    /// Whether a G92 continuation block may follow.
    pub fn g92_active(&self) -> bool {
        false
    }
}

/// G76/G78 blocks.
pub fn two_block(it: &mut Interp, _b: &Block, _g: G, w: Word) {
    it.diag(Code::NotSimulated, w.span, "not drawn yet");
}

/// G90 (turning) and G94 (facing) single cycles: from the start point A,
/// rapid to the cut's start, feed along the cut (taper R), feed back out,
/// rapid home. Modal: a following block with only X (G90) or Z (G94) repeats it.
pub fn turning(it: &mut Interp, b: &Block, facing: bool) {
    let name = if facing { "G94" } else { "G90" };
    if !it.check_words(b, b"XZUWR", name) {
        return;
    }
    let a = it.current(b.span);
    let t = it.target(b);
    let r = b.get(b'R').copied().map_or(0.0, |w| it.length(&w));
    let end = t.p;
    let line = b.line;
    let pts: [(MoveKind, Point); 4] = if facing {
        // R: taper along Z, start minus end.
        let p1 = Point::new(a.x, end.z + r);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(end.x, a.z)), (MoveKind::Rapid, a)]
    } else {
        // R: taper as a radius difference, start minus end.
        let p1 = Point::new(end.x + 2.0 * r, a.z);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(a.x, end.z)), (MoveKind::Rapid, a)]
    };
    let mut from = a;
    for (kind, to) in pts {
        if from != to {
            it.emit(kind, from, to, line, None, b.span);
        }
        from = to;
    }
    it.arrive(a, true, true, line);
}
