//! The characters of one line as the lexer reads them: ASCII lines as they
//! are, others with full-width and look-alike characters folded to their
//! ASCII twins, each keeping its byte offset in the program.

/// A character of the line being lexed, after folding full-width forms.
#[derive(Clone, Copy)]
pub(super) struct Ch {
    /// ASCII byte after folding; `0x80` for any other non-ASCII character.
    pub(super) b: u8,
    /// Whether this came from a full-width or look-alike character.
    pub(super) folded: bool,
    /// Byte offset of the original character in the program.
    pub(super) at: u32,
}

/// The byte standing for any non-ASCII character that does not fold.
pub(super) const OTHER: u8 = 0x80;

/// The characters of one line as the lexer sees them: a folded byte, its
/// original offset and whether it was folded; index `end()` is a NUL sentinel.
pub(super) trait Src {
    fn b(&self, i: usize) -> u8;
    fn at(&self, i: usize) -> usize;
    fn folded(&self, i: usize) -> bool;
    fn end(&self) -> usize;
}

/// An ASCII line: bytes are characters, no copy needed.
pub(super) struct Ascii<'a> {
    /// The line's bytes.
    pub(super) bytes: &'a [u8],
    /// Byte offset of the line in the program.
    pub(super) base: usize,
}

impl Src for Ascii<'_> {
    #[inline]
    fn b(&self, i: usize) -> u8 {
        *self.bytes.get(i).unwrap_or(&0)
    }
    #[inline]
    fn at(&self, i: usize) -> usize {
        self.base + i.min(self.bytes.len())
    }
    #[inline]
    fn folded(&self, _: usize) -> bool {
        false
    }
    #[inline]
    fn end(&self) -> usize {
        self.bytes.len()
    }
}

/// A line with non-ASCII characters, decoded and folded (with a sentinel).
impl Src for &[Ch] {
    #[inline]
    fn b(&self, i: usize) -> u8 {
        self[i].b
    }
    #[inline]
    fn at(&self, i: usize) -> usize {
        self[i].at as usize
    }
    #[inline]
    fn folded(&self, i: usize) -> bool {
        self[i].folded
    }
    #[inline]
    fn end(&self) -> usize {
        self.len() - 1
    }
}

/// Folds a non-ASCII character to its ASCII twin when it has one.
pub(super) fn fold(c: char) -> Option<u8> {
    let u = c as u32;
    match u {
        0xFF01..=0xFF5E => Some((u - 0xFEE0) as u8),
        0x3000 => Some(b' '),
        0x3002 => Some(b'.'), // ideographic full stop, typed for '.' in Chinese input mode
        0x2212 => Some(b'-'), // minus sign from documents
        _ => None,
    }
}
