//! The lexer: program text → [`Block`]s with byte spans, one line at a time.
//!
//! It never panics and never gives up on a program: every problem becomes a
//! diagnostic positioned at the offending characters, and the block that has
//! it is marked so the interpreter skips it.

#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod ahead;
mod blocks;
mod number;
mod source;

pub(crate) use blocks::Blocks;
use number::{NumAcc, NumError};
use source::{Ascii, Ch, OTHER, Src, fold};

use crate::args;
use crate::block::{Block, BlockKind, Word};
use crate::controller::Rules;
use crate::diagnostic::Diagnostics;
use crate::message as msg;
use crate::span::Span;

/// A full-width or look-alike character's ASCII twin.
pub fn fold_char(c: char) -> Option<u8> {
    fold(c)
}

/// Limits the lexer enforces (from the settings).
#[derive(Clone, Copy, Debug)]
pub struct LexLimits {
    /// Longest block in characters.
    pub block_chars: usize,
    /// Most significant digits in a number.
    pub digits: usize,
}

impl Default for LexLimits {
    fn default() -> Self {
        LexLimits { block_chars: 256, digits: 8 }
    }
}

/// Reads program text block by block.
#[derive(Clone)]
pub struct Lexer<'a> {
    text: &'a str,
    pos: usize,
    line: u32,
    rules: &'static Rules,
    limits: LexLimits,
    chars: Vec<Ch>,
    starts: Vec<u32>,
    /// The start of the first line whose start is not recorded yet: line
    /// starts are recorded only while lines are read in order from it.
    frontier: usize,
}

impl<'a> Lexer<'a> {
    /// A lexer over `text` for the words of a controller (its `rules`).
    pub fn new(text: &'a str, rules: &'static Rules, limits: LexLimits) -> Lexer<'a> {
        let pos = if text.starts_with('\u{FEFF}') { 3 } else { 0 };
        Lexer { text, pos, line: 0, rules, limits, chars: Vec::with_capacity(128), starts: Vec::new(), frontier: pos }
    }

    /// Lines read so far.
    pub fn line(&self) -> u32 {
        self.line
    }

    /// Byte offset of the next unread line.
    pub fn offset(&self) -> usize {
        self.pos
    }

    /// Byte offsets of the starts of the lines read so far (for a [`crate::span::LineIndex`]).
    pub fn take_line_starts(&mut self) -> Vec<u32> {
        std::mem::take(&mut self.starts)
    }

    /// Resumes lexing at byte `offset`, which must be a line start, as 1-based `line`.
    pub fn seek(&mut self, offset: usize, line: u32) {
        self.pos = offset.min(self.text.len());
        self.line = line.saturating_sub(1);
        self.frontier = self.pos;
    }

    /// Goes on at byte `offset` (a line start), 1-based `line`, as a jump
    /// does: line starts are not recorded until reading reaches the first
    /// unrecorded line again.
    pub fn jump(&mut self, offset: usize, line: u32) {
        self.pos = offset.min(self.text.len());
        self.line = line.saturating_sub(1);
    }

    /// Stops recording line starts (the caller's record no longer leads up to the lines read).
    pub fn stop_recording(&mut self) {
        self.frontier = usize::MAX;
    }

    /// The program text.
    pub fn text(&self) -> &'a str {
        self.text
    }

    /// Reads the next line into `block`. Returns false at the end of the text.
    pub fn next_block(&mut self, block: &mut Block, diags: &mut Diagnostics) -> bool {
        let text = self.text;
        if self.pos >= text.len() {
            // The end; a trailing newline does not start another block.
            return false;
        }
        let start = self.pos;
        let bytes = text.as_bytes();
        let rel = memchr::memchr2(b'\n', b'\r', &bytes[start..]);
        let end = rel.map_or(bytes.len(), |r| start + r);
        let next = match rel {
            None => bytes.len() + 1,
            Some(_) if bytes[end] == b'\r' && bytes.get(end + 1) == Some(&b'\n') => end + 2,
            Some(_) => end + 1,
        };
        self.passed(start, next);
        block.reset(self.line, Span::new(start, end));
        self.lex_line(&text[start..end], start, block, diags);
        true
    }

    /// The line at `start` is read (by this lexer or ahead of it) and the
    /// next begins at `next`: where the lexer is, and the line starts it records.
    pub(crate) fn passed(&mut self, start: usize, next: usize) {
        self.pos = next;
        if start == self.frontier && self.starts.len() < u32::MAX as usize {
            self.starts.push(start as u32);
            self.frontier = next;
        }
        self.line += 1;
    }

    fn lex_line(&mut self, line: &str, base: usize, block: &mut Block, diags: &mut Diagnostics) {
        let too_long = |n: usize, diags: &mut Diagnostics, block: &mut Block, limit: usize| {
            diags.push(&msg::BLOCK_TOO_LONG, Span::new(base, base + line.len()), args![n, limit]);
            block.has_error = true;
        };
        if line.is_ascii() {
            if line.len() > self.limits.block_chars {
                too_long(line.len(), diags, block, self.limits.block_chars);
                return;
            }
            let src = Ascii { bytes: line.as_bytes(), base };
            LineLexer::new(src, self.text, self.rules, self.limits).run(block, diags);
            return;
        }
        // Decode once into folded characters.
        self.chars.clear();
        let mut nchars = 0usize;
        for (i, c) in line.char_indices() {
            nchars += 1;
            if nchars > self.limits.block_chars {
                continue; // keep counting for the message
            }
            let (b, folded) = if c.is_ascii() {
                (c as u8, false)
            } else {
                match fold(c) {
                    Some(b) => (b, true),
                    None => (OTHER, false),
                }
            };
            self.chars.push(Ch { b, folded, at: (base + i) as u32 });
        }
        if nchars > self.limits.block_chars {
            too_long(nchars, diags, block, self.limits.block_chars);
            return;
        }
        self.chars.push(Ch { b: 0, folded: false, at: (base + line.len()) as u32 });
        let chars = std::mem::take(&mut self.chars);
        LineLexer::new(&chars[..], self.text, self.rules, self.limits).run(block, diags);
        self.chars = chars;
    }
}

struct LineLexer<'c, S: Src> {
    src: S,
    i: usize,
    text: &'c str,
    rules: &'static Rules,
    limits: LexLimits,
    first_fold: Option<usize>,
    last_fold: Option<usize>,
}

impl<'c, S: Src> LineLexer<'c, S> {
    fn new(src: S, text: &'c str, rules: &'static Rules, limits: LexLimits) -> Self {
        LineLexer { src, i: 0, text, rules, limits, first_fold: None, last_fold: None }
    }

    #[inline]
    fn peek(&self) -> u8 {
        self.src.b(self.i)
    }

    #[inline]
    fn at(&self, i: usize) -> usize {
        self.src.at(i.min(self.src.end()))
    }

    /// Byte offset just after character `i`.
    fn after(&self, i: usize) -> usize {
        self.at(i + 1)
    }

    fn span(&self, from: usize, to_excl: usize) -> Span {
        Span::new(self.at(from), self.at(to_excl))
    }

    /// Consumes one code character, noting full-width folds.
    #[inline]
    fn bump(&mut self) -> u8 {
        let i = self.i;
        if self.src.folded(i) {
            self.first_fold.get_or_insert(i);
            self.last_fold = Some(i);
        }
        self.i += 1;
        self.src.b(i)
    }

    fn run(mut self, block: &mut Block, diags: &mut Diagnostics) {
        let mut seen_code = false;
        loop {
            let c = self.peek();
            match c {
                0 => break,
                b' ' | b'\t' => {
                    self.bump();
                }
                b'(' => self.comment(diags),
                b')' => {
                    let i = self.i;
                    self.bump();
                    diags.push(&msg::UNMATCHED_PAREN, self.span(i, i + 1), args![]);
                    block.has_error = true;
                }
                b';' => {
                    self.bump();
                    self.after_semicolon(diags);
                    break;
                }
                b'%' if !seen_code => {
                    self.bump();
                    block.kind = BlockKind::Percent;
                    seen_code = true;
                }
                b'/' if !seen_code => {
                    self.bump();
                    block.deleted = true;
                    // "/1".."/9" select a block-delete switch; screwcut has one switch.
                    if self.peek().is_ascii_digit() {
                        self.bump();
                    }
                }
                b'#' | b'[' | b']' | b'=' if self.rules.macros.is_some() => {
                    block.macro_line();
                    return;
                }
                b'#' | b'[' | b']' | b'=' => {
                    let i = self.i;
                    diags.push(&msg::UNSUPPORTED_MACRO, self.span(i, i + 1), args![c = c as char]);
                    block.has_error = true;
                    // Skip to the end of the code part of the line.
                    while !matches!(self.peek(), 0 | b';') {
                        if self.peek() == b'(' {
                            self.comment(diags);
                        } else {
                            self.bump();
                        }
                    }
                }
                b'$' if self.rules.spindle_word => {
                    seen_code = true;
                    self.word(b'$', block, diags);
                }
                b':' if !seen_code => {
                    // ISO program number ":1234".
                    seen_code = true;
                    self.program_number(block, diags);
                }
                b'a'..=b'z' | b'A'..=b'Z' => {
                    let letter = c.to_ascii_uppercase();
                    // A letter followed at once by a digit is a word (`X45.1`),
                    // never macro syntax, unless it is a LinuxCNC o-word (`o100`).
                    let word = self.src.b(self.i + 1).is_ascii_digit() && (letter != b'O' || seen_code);
                    if !word && self.macro_start(letter, seen_code) {
                        block.macro_line();
                        return;
                    }
                    if letter == b'O' && !seen_code {
                        seen_code = true;
                        self.program_number(block, diags);
                    } else {
                        seen_code = true;
                        self.word(letter, block, diags);
                    }
                }
                b'0'..=b'9' | b'.' | b'+' | b'-' => {
                    let i = self.i;
                    while matches!(self.peek(), b'0'..=b'9' | b'.' | b'+' | b'-') {
                        self.bump();
                    }
                    diags.push(&msg::NUMBER_WITHOUT_ADDRESS, self.span(i, self.i), args![text = self.slice(i, self.i)]);
                    block.has_error = true;
                }
                _ => {
                    let i = self.i;
                    self.bump();
                    let what = self.slice(i, i + 1);
                    let hex = format!("{:04X}", what.chars().next().map_or(0, |c| c as u32));
                    diags.push(&msg::UNEXPECTED_CHARACTER, self.span(i, i + 1), args![c = what, hex]);
                    block.has_error = true;
                }
            }
        }
        if let (Some(a), Some(b)) = (self.first_fold, self.last_fold) {
            let original = &self.text[self.at(a)..self.after(b)];
            let folded: String = original.chars().map(|c| fold(c).map_or(c, |b| b as char)).collect();
            diags.push(&msg::FULL_WIDTH, Span::new(self.at(a), self.after(b)), args![original, folded]);
        }
    }

    /// Whether the letter at the cursor starts macro syntax: a keyword or
    /// function (a letter followed by a letter: `IF`, `GOTO`, `END1`, `SIN[`)
    /// or, on LinuxCNC, an o-word.
    fn macro_start(&self, letter: u8, seen_code: bool) -> bool {
        use crate::controller::macros::Flavor;
        let Some(m) = self.rules.macros.as_ref() else { return false };
        if letter == b'O' && !seen_code && m.flavor == Flavor::LinuxCnc {
            return true;
        }
        let mut k = self.i + 1;
        while matches!(self.src.b(k), b' ' | b'\t') {
            k += 1;
        }
        if !self.src.b(k).is_ascii_alphabetic() {
            // A value that is a variable or an expression: `X#1`, `Z-[#2+1]`.
            while matches!(self.src.b(k), b' ' | b'\t' | b'-' | b'+') {
                k += 1;
            }
            return matches!(self.src.b(k), b'#' | b'[');
        }
        // Two letters: a keyword or a function (every name has two or more).
        let names: &[&str] = match m.flavor {
            Flavor::Fanuc => &["IF", "WHILE", "GOTO", "END", "DO"],
            Flavor::LinuxCnc => &[
                "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX", "FUP", "LN", "EXP",
                "EXISTS",
            ],
        };
        // The letters from here, blanks skipped (rs274 ignores them), upper-cased.
        let mut word = [0u8; 8];
        let (mut j, mut n) = (self.i, 0);
        while n < word.len() {
            match self.src.b(j) {
                b' ' | b'\t' => {}
                c if c.is_ascii_alphabetic() => {
                    word[n] = c.to_ascii_uppercase();
                    n += 1;
                }
                _ => break,
            }
            j += 1;
        }
        let letters = &word[..n];
        names.iter().any(|k| letters.starts_with(k.as_bytes()))
    }

    fn slice(&self, from: usize, to_excl: usize) -> &'c str {
        &self.text[self.at(from)..self.at(to_excl)]
    }

    fn comment(&mut self, diags: &mut Diagnostics) {
        let open = self.i;
        self.bump();
        loop {
            match self.peek() {
                0 => {
                    diags.push(&msg::UNCLOSED_COMMENT, self.span(open, open + 1), args![]);
                    return;
                }
                b')' => {
                    self.bump();
                    return;
                }
                b'(' => {
                    diags.push(&msg::NESTED_COMMENT, self.span(self.i, self.i + 1), args![]);
                    self.i += 1;
                }
                _ => self.i += 1, // comment text is not folded or reported
            }
        }
    }

    /// After `;` the rest of the line is a comment; warn when it looks like code.
    fn after_semicolon(&mut self, diags: &mut Diagnostics) {
        let mut j = self.i;
        while matches!(self.src.b(j), b' ' | b'\t') {
            j += 1;
        }
        let c0 = self.src.b(j).to_ascii_uppercase();
        let c1 = self.src.b(j + (c0 != 0) as usize);
        let looks_like_code = matches!(c0, b'G' | b'M' | b'X' | b'Z' | b'U' | b'W' | b'N' | b'T' | b'S' | b'F')
            && (c1.is_ascii_digit() || c1 == b'-' || c1 == b'.');
        if looks_like_code {
            let end = self.src.end();
            diags.push(&msg::CODE_AFTER_SEMICOLON, self.span(j, end), args![text = self.slice(j, end).trim_end()]);
        }
    }

    fn program_number(&mut self, block: &mut Block, diags: &mut Diagnostics) {
        let at = self.i;
        self.bump();
        while matches!(self.peek(), b' ' | b'\t') {
            self.bump();
        }
        let ds = self.i;
        while self.peek().is_ascii_digit() {
            self.bump();
        }
        let digits = self.slice(ds, self.i).chars().filter(|c| !c.is_whitespace()).count();
        let text: String = (ds..self.i).map(|j| self.src.b(j) as char).collect();
        if digits == 0 || digits > 5 || self.peek() == b'.' {
            while matches!(self.peek(), b'0'..=b'9' | b'.') {
                self.bump();
            }
            diags.push(&msg::MALFORMED_PROGRAM_NUMBER, self.span(at, self.i), args![text = self.slice(at, self.i)]);
            block.has_error = true;
            return;
        }
        block.kind = BlockKind::ProgramNumber(text.parse().unwrap_or(0));
    }

    fn word(&mut self, letter: u8, block: &mut Block, diags: &mut Diagnostics) {
        let start = self.i;
        self.bump();
        let known = letter == b'$' || self.rules.has_address(letter);
        while matches!(self.peek(), b' ' | b'\t') {
            self.bump();
        }
        // Read the number while scanning it; a run that goes on with more
        // signs, points or digits after a complete number is malformed.
        let ns = self.i;
        let mut acc = NumAcc::default();
        if matches!(self.peek(), b'-' | b'+') {
            acc.neg = self.bump() == b'-';
        }
        while acc.push(self.peek()) {
            self.bump();
        }
        if matches!(self.peek(), b'0'..=b'9' | b'.' | b'+' | b'-') {
            acc.malformed = true;
            while matches!(self.peek(), b'0'..=b'9' | b'.' | b'+' | b'-') {
                self.bump();
            }
        }
        let ne = self.i;
        let span = self.span(start, ne);
        if !known {
            let controller = crate::message::Arg::lit(self.rules.title());
            diags.push(&msg::UNKNOWN_ADDRESS, self.span(start, start + 1), args![letter = letter as char, controller]);
            block.has_error = true;
            return;
        }
        if ns == ne {
            diags.push(&msg::MISSING_VALUE, self.span(start, start + 1), args![letter = letter as char]);
            block.has_error = true;
            return;
        }
        let num = match acc.finish(self.limits.digits) {
            Ok(n) => n,
            Err(NumError::Malformed) => {
                diags.push(&msg::MALFORMED_NUMBER, self.span(ns, ne), args![text = self.slice(ns, ne)]);
                block.has_error = true;
                return;
            }
            Err(NumError::TooManyDigits(n)) => {
                diags.push(&msg::TOO_MANY_DIGITS, self.span(ns, ne), args![n, limit = self.limits.digits]);
                block.has_error = true;
                return;
            }
        };
        let word = Word { letter, num, span };
        if letter == b'$' {
            if let Some(first) = block.spindle {
                diags.push(&msg::SECOND_SPINDLE, span, args![first]);
                block.has_error = true;
            } else {
                block.spindle = Some(word);
            }
            return;
        }
        if letter == b'N' {
            if let Some(first) = block.n {
                diags.push(&msg::SECOND_SEQUENCE_NUMBER, span, args![first]);
                block.has_error = true;
            } else {
                block.n = Some(word);
            }
            return;
        }
        if let Some(first) = block.push(word) {
            if letter != b'G' && letter != b'M' {
                block.pop_repeated();
                diags.push(&msg::REPEATED_ADDRESS, span, args![letter = letter as char, first, second = word]);
                block.has_error = true;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::number::parse_number;
    use super::*;

    fn lex(text: &str) -> (Vec<Block>, Vec<crate::diagnostic::Diagnostic>) {
        let mut lx =
            Lexer::new(text, &crate::controller::of(crate::dialect::Dialect::Gsk980tdc).rules, LexLimits::default());
        let mut d = Diagnostics::with_limit(100);
        let mut out = Vec::new();
        let mut b = Block::default();
        while lx.next_block(&mut b, &mut d) {
            out.push(b.clone());
        }
        let idx = crate::span::LineIndex::new(text);
        (out, d.finish(text, &idx))
    }

    #[test]
    fn numbers_parse_exactly() {
        for s in ["27.4286", "48.8571", "-75", "0.0001", "2.0", "1234.5678", "-0.5"] {
            let n = parse_number(s.as_bytes(), 8).ok().unwrap();
            assert_eq!(n.value, s.parse::<f64>().unwrap(), "{s}");
        }
        assert!(parse_number(b"27.", 8).ok().unwrap().has_point);
        assert!(!parse_number(b"27", 8).ok().unwrap().has_point);
        assert_eq!(parse_number(b".5", 8).ok().unwrap().value, 0.5);
        assert!(matches!(parse_number(b"1.2.3", 8), Err(NumError::Malformed)));
        assert!(matches!(parse_number(b"--1", 8), Err(NumError::Malformed)));
        assert!(matches!(parse_number(b"-", 8), Err(NumError::Malformed)));
        assert!(matches!(parse_number(b"123456789", 8), Err(NumError::TooManyDigits(9))));
        assert!(matches!(parse_number(b"12345678901234567890", 8), Err(NumError::TooManyDigits(_))));
        // Leading zeros and trailing fraction zeros are not significant.
        assert_eq!(parse_number(b"00000080", 8).ok().unwrap().value, 80.0);
        assert_eq!(parse_number(b"1.000000000", 8).ok().unwrap().value, 1.0);
    }

    #[test]
    fn seed_lines_lex_with_comments() {
        let (b, d) = lex("O0009;\nG00 X27.4286 Z3;\t(第一次切入 1mm)\nN40G32Z13.0F2.0\n");
        assert!(d.is_empty(), "{d:?}");
        assert_eq!(b[0].kind, BlockKind::ProgramNumber(9));
        assert_eq!(b[1].get(b'X').unwrap().value(), 27.4286);
        assert_eq!(b[2].n.unwrap().value(), 40.0);
        assert_eq!(b[2].get(b'F').unwrap().value(), 2.0);
        assert_eq!(b.len(), 3);
    }

    #[test]
    fn crlf_and_lone_cr() {
        let (b, _) = lex("G00 X1\r\nG01 Z2\rM30");
        assert_eq!(b.len(), 3);
        assert_eq!(b[2].line, 3);
        assert_eq!(b[2].get(b'M').unwrap().value(), 30.0);
    }
}
