//! G92 threading cycle.

use crate::block::Block;
use crate::diagnostic::Code;
use crate::interp::Interp;

/// One G92 block.
pub fn block(it: &mut Interp, b: &Block, _has_axes: bool) {
    it.diag(Code::NotSimulated, b.span, "not drawn yet");
}
