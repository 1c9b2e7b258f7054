//! Where a reading takes its blocks from: the lexer itself, or (natively)
//! the blocks lexed ahead of it on a second thread.

use super::Lexer;
use crate::block::Block;
use crate::diagnostic::Diagnostics;

/// Where a reading takes its blocks from: a [`Lexer`], or (natively) blocks
/// lexed ahead on a second thread (`ahead`), which give the same blocks,
/// diagnostics and line starts.
pub(crate) trait Blocks<'a> {
    /// Byte offset of the next unread line.
    fn offset(&self) -> usize;
    /// Lines read so far (the 1-based line of the last block read).
    fn line(&self) -> u32;
    /// The program text.
    fn text(&self) -> &'a str;
    /// Goes on at byte `offset` (a line start), 1-based `line`, as a jump does.
    fn jump(&mut self, offset: usize, line: u32);
    /// Reads the next line into `block`. Returns false at the end of the text.
    fn next_block(&mut self, block: &mut Block, diags: &mut Diagnostics) -> bool;
}

impl<'a> Blocks<'a> for Lexer<'a> {
    fn offset(&self) -> usize {
        Lexer::offset(self)
    }
    fn line(&self) -> u32 {
        Lexer::line(self)
    }
    fn text(&self) -> &'a str {
        Lexer::text(self)
    }
    fn jump(&mut self, offset: usize, line: u32) {
        Lexer::jump(self, offset, line)
    }
    fn next_block(&mut self, block: &mut Block, diags: &mut Diagnostics) -> bool {
        Lexer::next_block(self, block, diags)
    }
}
