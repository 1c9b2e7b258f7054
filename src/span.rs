//! Byte spans into the source text and their line/column positions.

use serde::Serialize;

/// A half-open byte range `[start, end)` into the program text.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Span {
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

impl Span {
    /// A span from `start` to `end` (bytes).
    pub fn new(start: usize, end: usize) -> Span {
        Span { start: start as u32, end: end as u32 }
    }

    /// The span `d` bytes later (earlier for a negative `d`).
    pub fn shifted(self, d: isize) -> Span {
        Span { start: (self.start as isize + d).max(0) as u32, end: (self.end as isize + d).max(0) as u32 }
    }

    /// The smallest span covering both.
    pub fn cover(self, other: Span) -> Span {
        Span { start: self.start.min(other.start), end: self.end.max(other.end) }
    }
}

/// How an edit moves byte positions: every position at or after `at`
/// (where the edited bytes end, in the old text) moves by `by` bytes; the
/// positions before the edit stay.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shift {
    /// First old position that moves.
    pub at: usize,
    /// How far it moves (new length minus old length).
    pub by: isize,
}

impl Shift {
    /// Every position moves by `by`.
    pub fn all(by: isize) -> Shift {
        Shift { at: 0, by }
    }

    /// Where old position `p` is in the new text.
    pub fn pos(self, p: usize) -> usize {
        if p >= self.at { p.saturating_add_signed(self.by) } else { p }
    }

    /// Where old span `s` is in the new text.
    pub fn span(self, s: Span) -> Span {
        Span::new(self.pos(s.start as usize), self.pos(s.end as usize))
    }
}

/// A 1-based line and column; the column counts Unicode characters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct LineCol {
    /// 1-based line.
    pub line: u32,
    /// 1-based column in characters.
    pub column: u32,
}

/// Maps byte offsets of one source text to line/column positions.
#[derive(Clone, Debug)]
pub struct LineIndex {
    starts: Vec<u32>,
}

impl LineIndex {
    /// Indexes the line starts of `text` (`\n`, `\r\n` and a lone `\r` end a line).
    pub fn new(text: &str) -> LineIndex {
        let mut starts = vec![0u32];
        let b = text.as_bytes();
        let mut i = 0;
        while i < b.len() {
            match b[i] {
                b'\n' => starts.push(i as u32 + 1),
                b'\r' => {
                    if b.get(i + 1) == Some(&b'\n') {
                        i += 1;
                    }
                    starts.push(i as u32 + 1);
                }
                _ => {}
            }
            i += 1;
        }
        LineIndex { starts }
    }

    /// An index from line starts already known (strictly ascending, as a
    /// lexer records them, starting with 0 or not); lines after the last one
    /// given are found by scanning `text`.
    pub fn from_starts(text: &str, mut starts: Vec<u32>) -> LineIndex {
        debug_assert!(starts.windows(2).all(|w| w[0] < w[1]), "line starts not strictly ascending");
        if starts.first() != Some(&0) {
            starts.insert(0, 0);
        }
        let last = *starts.last().unwrap_or(&0) as usize;
        if last < text.len() {
            // The tail's starts after its first (`last` itself): all beyond `last`.
            let tail = LineIndex::new(&text[last..]);
            starts.extend(tail.starts.iter().skip(1).map(|s| s + last as u32));
        }
        LineIndex { starts }
    }

    /// Number of lines.
    pub fn lines(&self) -> usize {
        self.starts.len()
    }

    /// Byte offset where 1-based `line` starts.
    pub fn line_start(&self, line: u32) -> usize {
        self.starts[(line.max(1) as usize - 1).min(self.starts.len() - 1)] as usize
    }

    /// The 1-based line holding byte `offset`, and the byte where that line starts.
    pub fn line_of(&self, offset: usize) -> (u32, usize) {
        let line = match self.starts.binary_search(&(offset as u32)) {
            Ok(i) => i,
            Err(i) => i - 1,
        };
        (line as u32 + 1, self.starts[line] as usize)
    }

    /// Line and column of byte `offset` in `text` (the text that was indexed).
    pub fn locate(&self, text: &str, offset: usize) -> LineCol {
        let offset = offset.min(text.len());
        let (line, start) = self.line_of(offset);
        LineCol { line, column: char_column(&text[start..], offset - start) }
    }

    /// [`LineIndex::locate`] of a span's `start` and `end` (`start <= end`):
    /// the end's line found on from the start's (a span is most often on one line).
    pub fn locate_span(&self, text: &str, start: usize, end: usize) -> (LineCol, LineCol) {
        let a = self.locate(text, start);
        let end = end.min(text.len());
        if end < start.min(text.len()) {
            return (a, self.locate(text, end));
        }
        let first = a.line as usize - 1;
        for line in first..first + 8 {
            if self.starts.get(line + 1).is_none_or(|&s| s as usize > end) {
                let from = self.starts[line] as usize;
                return (a, LineCol { line: line as u32 + 1, column: char_column(&text[from..], end - from) });
            }
        }
        (a, self.locate(text, end))
    }
}

/// 1-based character column of byte `offset` within `line_text`.
pub fn char_column(line_text: &str, offset: usize) -> u32 {
    let prefix = &line_text.as_bytes()[..offset.min(line_text.len())];
    if prefix.is_ascii() {
        return offset as u32 + 1;
    }
    // Count characters: every byte that is not a UTF-8 continuation byte.
    prefix.iter().filter(|&&b| (b & 0xC0) != 0x80).count() as u32 + 1
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A span's two ends located together are each located alone: on one
    /// line, a few lines apart, many lines apart, past the text's end.
    #[test]
    fn a_spans_ends_are_located_as_each_alone() {
        let text = "G00 X1\r\nＧ32 Z2\rM30\n\n\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\nX（1）\n";
        for idx in [LineIndex::new(text), LineIndex::from_starts(text, vec![0, 8])] {
            for a in (0..=text.len() + 2).filter(|&a| a >= text.len() || text.is_char_boundary(a)) {
                for b in (a..=text.len() + 2).filter(|&b| b >= text.len() || text.is_char_boundary(b)) {
                    assert_eq!(idx.locate_span(text, a, b), (idx.locate(text, a), idx.locate(text, b)), "{a}..{b}");
                }
            }
        }
    }

    #[test]
    fn lines_and_columns() {
        let text = "G00 X1\r\nＧ32 Z2\rM30\n";
        let idx = LineIndex::new(text);
        assert_eq!(idx.lines(), 4);
        assert_eq!(idx.locate(text, 4), LineCol { line: 1, column: 5 });
        // "Ｇ" is three bytes: the '3' after it is column 2.
        let g = text.find("32").unwrap();
        assert_eq!(idx.locate(text, g), LineCol { line: 2, column: 2 });
        let m = text.find("M30").unwrap();
        assert_eq!(idx.locate(text, m), LineCol { line: 3, column: 1 });
        // The same from the first two line starts, the rest scanned.
        let partial = LineIndex::from_starts(text, vec![0, 8]);
        assert_eq!(partial.locate(text, m), LineCol { line: 3, column: 1 });
        assert_eq!(partial.lines(), 4);
    }
}
