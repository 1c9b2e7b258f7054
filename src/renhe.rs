//! Renhe: G30 run-out mode, G32 inch and G33 metric threads.

use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::interp::Interp;

/// Renhe modal state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenheState {}

/// G30: run-out mode.
pub fn g30(it: &mut Interp, _b: &Block, w: Word) {
    it.diag(Code::NotSimulated, w.span, "G30 is not drawn yet");
}

/// Renhe G32/G33 block.
pub fn thread_block(it: &mut Interp, b: &Block, _inch: bool) {
    it.diag(Code::NotSimulated, b.span, "Renhe threads are not drawn yet");
}
