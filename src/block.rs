//! Blocks and words: one program line as read by the lexer, with spans.

use crate::span::Span;

/// A number as written in a word.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Number {
    /// The value as written (`27.4286`, `180`, `-75`).
    pub value: f64,
    /// Whether the text had a decimal point (`X27.` and `X27.0` do; `X27` does not).
    pub has_point: bool,
    /// Digits written before the decimal point, leading zeros included (`P060` has 3).
    pub int_digits: u8,
    /// Digits written after the decimal point (`F11.2` has 1).
    pub frac_digits: u8,
}

impl Number {
    /// The value when it is a whole number without a point (`G32`, `M30`, `P1160`).
    pub fn integer(&self) -> Option<i64> {
        // Below 2^63 the cast truncates exactly: a whole number casts back to itself (no `fract`, a library call).
        let v = self.value;
        if v.abs() < 9.0e15 && (v as i64) as f64 == v { Some(v as i64) } else { None }
    }
}

/// One address word: a letter and its number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Word {
    /// Upper-case ASCII letter.
    pub letter: u8,
    /// The number.
    pub num: Number,
    /// Span from the letter to the end of the number.
    pub span: Span,
}

impl Word {
    /// The letter as a `char`.
    pub fn letter(&self) -> char {
        self.letter as char
    }

    /// The value as written.
    pub fn value(&self) -> f64 {
        self.num.value
    }

    /// `G32` style text of the word for messages.
    pub fn display(&self) -> String {
        format!("{}{}", self.letter(), crate::num::fmt(self.num.value))
    }
}

/// What kind of line a block is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BlockKind {
    /// An ordinary block (possibly empty or comment-only).
    #[default]
    Normal,
    /// A `%` tape start/end line.
    Percent,
    /// An `O1234` (or `:1234`) program number line.
    ProgramNumber(u32),
    /// A macro line (variables, expressions, jumps, loops, o-words): the
    /// lexer leaves it to the program flow, which parses it.
    Macro,
}

/// One block (program line) with its words.
#[derive(Clone, Debug, Default)]
pub struct Block {
    /// 1-based line number.
    pub line: u32,
    /// Span of the line without its line ending.
    pub span: Span,
    /// Kind of line.
    pub kind: BlockKind,
    /// Starts with `/` (block delete).
    pub deleted: bool,
    /// Words in order, excluding the `N` sequence number and `O` program number
    /// (private: `index` must follow every change; see [`Block::words`]).
    words: Vec<Word>,
    /// The `N` sequence number, if any.
    pub n: Option<Word>,
    /// A `$` spindle selection word (LinuxCNC), kept apart from the letter words; its letter is `$`.
    pub spindle: Option<Word>,
    /// Whether the lexer found an error in this block (the block is then not executed).
    pub has_error: bool,
    /// First index into `words` for each letter A–Z, plus one (0 = absent).
    index: [u8; 26],
}

impl Block {
    /// Clears the block for reuse.
    pub fn reset(&mut self, line: u32, span: Span) {
        self.line = line;
        self.span = span;
        self.kind = BlockKind::Normal;
        self.deleted = false;
        self.words.clear();
        self.n = None;
        self.spindle = None;
        self.has_error = false;
        self.index = [0; 26];
    }

    /// Adds a word; returns the earlier word of the same letter, if there was one.
    pub fn push(&mut self, w: Word) -> Option<Word> {
        let slot = (w.letter - b'A') as usize;
        let earlier = if self.index[slot] != 0 { Some(self.words[self.index[slot] as usize - 1]) } else { None };
        if earlier.is_none() && self.words.len() < 255 {
            self.index[slot] = self.words.len() as u8 + 1;
        }
        self.words.push(w);
        earlier
    }

    /// The words in order, excluding the `N` sequence number and `O` program number.
    pub fn words(&self) -> &[Word] {
        &self.words
    }

    /// Removes all words (the `N` word and the block's kind stay).
    pub fn clear_words(&mut self) {
        self.words.clear();
        self.index = [0; 26];
    }

    /// Removes the last word pushed, when it repeats a letter already present
    /// (the index still points at the first of that letter).
    pub fn pop_repeated(&mut self) {
        if let Some(w) = self.words.last() {
            let first = self.index[(w.letter - b'A') as usize] as usize;
            if first != 0 && first != self.words.len() {
                self.words.pop();
            }
        }
    }

    /// Keeps only the words for which `keep` is true, in order.
    pub fn retain_words(&mut self, mut keep: impl FnMut(&Word) -> bool) {
        let words = std::mem::take(&mut self.words);
        self.index = [0; 26];
        // Pushed again, so the index is made by `push`'s one rule.
        for w in words.into_iter().filter(|w| keep(w)) {
            self.push(w);
        }
    }

    /// The first word with `letter`.
    pub fn get(&self, letter: u8) -> Option<&Word> {
        let i = self.index[(letter - b'A') as usize];
        if i == 0 { None } else { Some(&self.words[i as usize - 1]) }
    }

    /// Marks the block a macro line: its words are left to the program flow.
    pub fn macro_line(&mut self) {
        self.kind = BlockKind::Macro;
        self.words.clear();
        self.n = None;
        self.index = [0; 26];
    }

    /// Whether a word with `letter` is present.
    pub fn has(&self, letter: u8) -> bool {
        self.index[(letter - b'A') as usize] != 0
    }

    /// All words with `letter` (G and M may repeat).
    pub fn all(&self, letter: u8) -> impl Iterator<Item = &Word> {
        self.words.iter().filter(move |w| w.letter == letter)
    }

    /// True when the block has no words at all (blank or comment-only).
    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::{Block, Number, Word};
    use crate::span::Span;

    fn word(letter: u8, value: f64) -> Word {
        let num = Number { value, has_point: false, int_digits: 1, frac_digits: 0 };
        Word { letter, num, span: Span::default() }
    }

    /// After every change of the words, `get` finds the first word of each
    /// letter present and nothing for a letter gone (the index follows).
    #[test]
    fn the_index_follows_the_words() {
        let mut b = Block::default();
        for (l, v) in [(b'G', 0.0), (b'G', 66.0), (b'P', 9011.0), (b'X', 47.1), (b'U', 1.0), (b'G', 20.0)] {
            b.push(word(l, v));
        }
        assert_eq!(b.get(b'X').map(|w| w.value()), Some(47.1));
        b.retain_words(|w| w.letter == b'G' && w.value() != 66.0);
        let left: Vec<f64> = b.words().iter().map(|w| w.value()).collect();
        assert_eq!(left, [0.0, 20.0]);
        assert!(b.get(b'X').is_none() && b.get(b'U').is_none() && b.get(b'P').is_none());
        assert_eq!(b.get(b'G').map(|w| w.value()), Some(0.0));
        // A repeated letter popped: the first stays found; a first word is not popped.
        assert!(b.push(word(b'G', 1.0)).is_some());
        b.pop_repeated();
        assert_eq!(b.words().len(), 2);
        assert!(b.push(word(b'Z', 5.0)).is_none());
        b.pop_repeated();
        assert_eq!(b.get(b'Z').map(|w| w.value()), Some(5.0));
        b.clear_words();
        assert!(b.words().is_empty() && b.get(b'G').is_none() && b.get(b'Z').is_none());
        assert!(b.push(word(b'X', 2.0)).is_none());
        assert_eq!(b.get(b'X').map(|w| w.value()), Some(2.0));
    }

    /// `integer` is the value when it is whole and below 9e15 in size, as `fract() == 0` says.
    #[test]
    fn integer_is_the_whole_value() {
        let xs = [
            0.0f64,
            -0.0,
            32.0,
            -75.0,
            32.5,
            0.1,
            1e-300,
            8.9e15,
            9.0e15,
            1e300,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
        ];
        for x in xs.into_iter().chain(xs.iter().map(|x| x.next_up())) {
            let n = Number { value: x, has_point: false, int_digits: 1, frac_digits: 0 };
            let want = if x.fract() == 0.0 && x.abs() < 9.0e15 { Some(x as i64) } else { None };
            assert_eq!(n.integer(), want, "{x:e}");
        }
    }
}
