//! Where jumps land: the program numbers, sequence numbers, `END m` lines
//! and LinuxCNC o-word lines of a text, found by one scan of its lines the
//! first time a program jumps or calls.

use std::collections::HashMap;

use super::stmt::{OKWS, OKw};

/// A line of the text: its byte offset and 1-based number.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct At {
    /// Byte offset of the line's start.
    pub offset: usize,
    /// 1-based line number.
    pub line: u32,
}

/// A labelled line and the line after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The line itself.
    pub at: At,
    /// The line after it.
    pub next: At,
}

/// What the lookups of a text can find, positions aside: program numbers,
/// sequence numbers, loop ends, and each o-word label's keywords.
pub type Labels = (Vec<u32>, Vec<u32>, Vec<u8>, Vec<(Box<str>, Vec<OKw>)>);

/// The labels of a text.
#[derive(Debug, Default)]
pub struct Index {
    /// `O` program numbers in text order.
    pub programs: Vec<(u32, Entry)>,
    /// `N` sequence numbers in text order.
    pub sequences: Vec<(u32, Entry)>,
    /// `END m` lines in text order.
    pub ends: Vec<(u8, Entry)>,
    /// LinuxCNC o-word lines by label, each in text order with its keyword.
    pub owords: HashMap<Box<str>, Vec<(OKw, Entry)>>,
    /// The end of the text.
    pub end: At,
}

impl Index {
    /// What a lookup can find, without where: the program numbers, sequence
    /// numbers and loop ends in order, and each o-word label's keywords.
    pub fn labels(&self) -> Labels {
        let mut owords: Vec<(Box<str>, Vec<OKw>)> =
            self.owords.iter().map(|(k, v)| (k.clone(), v.iter().map(|(kw, _)| *kw).collect())).collect();
        crate::order::sort_by(&mut owords, |a, b| a.0.cmp(&b.0));
        (
            self.programs.iter().map(|p| p.0).collect(),
            self.sequences.iter().map(|p| p.0).collect(),
            self.ends.iter().map(|p| p.0).collect(),
            owords,
        )
    }

    /// Scans `text`; `linuxcnc` reads `o` lines as o-words instead of program numbers.
    pub fn build(text: &str, linuxcnc: bool) -> Index {
        let mut ix = Index::default();
        let bytes = text.as_bytes();
        let mut pos = if text.starts_with('\u{FEFF}') { 3 } else { 0 };
        let mut line = 1u32;
        while pos < bytes.len() {
            let rel = memchr::memchr2(b'\n', b'\r', &bytes[pos..]);
            let end = rel.map_or(bytes.len(), |r| pos + r);
            let next = match rel {
                None => bytes.len(),
                Some(_) if bytes[end] == b'\r' && bytes.get(end + 1) == Some(&b'\n') => end + 2,
                Some(_) => end + 1,
            };
            let e = Entry { at: At { offset: pos, line }, next: At { offset: next, line: line + 1 } };
            ix.scan_line(&bytes[pos..end], e, linuxcnc);
            pos = next;
            line += 1;
        }
        ix.end = At { offset: bytes.len(), line };
        ix
    }

    fn scan_line(&mut self, b: &[u8], e: Entry, linuxcnc: bool) {
        let mut i = 0;
        let skip = |i: &mut usize| {
            while matches!(b.get(*i), Some(b' ' | b'\t')) {
                *i += 1;
            }
        };
        skip(&mut i);
        if b.get(i) == Some(&b'/') {
            i += 1;
            if b.get(i).is_some_and(u8::is_ascii_digit) {
                i += 1;
            }
            skip(&mut i);
        }
        let digits = |i: &mut usize| -> Option<u32> {
            skip(i);
            let from = *i;
            while b.get(*i).is_some_and(u8::is_ascii_digit) {
                *i += 1;
            }
            std::str::from_utf8(&b[from..*i]).ok()?.parse().ok()
        };
        match b.get(i).map(u8::to_ascii_uppercase) {
            Some(b'O') if linuxcnc => self.oword(b, i + 1, e),
            Some(b'O' | b':') => {
                i += 1;
                if let Some(n) = digits(&mut i) {
                    self.programs.push((n, e));
                }
            }
            Some(b'N') => {
                i += 1;
                if let Some(n) = digits(&mut i) {
                    self.sequences.push((n, e));
                    skip(&mut i);
                    if linuxcnc && b.get(i).is_some_and(|c| c.eq_ignore_ascii_case(&b'O')) {
                        self.oword(b, i + 1, e);
                    } else {
                        self.end_line(b, i, e);
                    }
                }
            }
            _ => self.end_line(b, i, e),
        }
    }

    fn end_line(&mut self, b: &[u8], mut i: usize, e: Entry) {
        if b.len() >= i + 3 && b[i..i + 3].eq_ignore_ascii_case(b"END") {
            i += 3;
            while matches!(b.get(i), Some(b' ' | b'\t')) {
                i += 1;
            }
            if let Some(d) = b.get(i).filter(|c| c.is_ascii_digit()) {
                self.ends.push((d - b'0', e));
            }
        }
    }

    fn oword(&mut self, b: &[u8], mut i: usize, e: Entry) {
        let mut label = String::new();
        if b.get(i) == Some(&b'<') {
            i += 1;
            while let Some(&c) = b.get(i) {
                i += 1;
                match c {
                    b'>' => break,
                    b' ' | b'\t' => {}
                    _ => label.push(c.to_ascii_lowercase() as char),
                }
            }
        } else {
            while let Some(&c) = b.get(i).filter(|c| c.is_ascii_digit() || **c == b' ') {
                i += 1;
                if c != b' ' {
                    label.push(c as char);
                }
            }
            let trimmed = label.trim_start_matches('0');
            label = if trimmed.is_empty() { "0".into() } else { trimmed.into() };
        }
        while matches!(b.get(i), Some(b' ' | b'\t')) {
            i += 1;
        }
        let rest = &b[i.min(b.len())..];
        let found = OKWS.iter().find(|(n, _)| {
            rest.len() >= n.len()
                && rest[..n.len()].eq_ignore_ascii_case(n.as_bytes())
                && !rest.get(n.len()).is_some_and(u8::is_ascii_alphabetic)
        });
        if let Some(&(_, k)) = found {
            self.owords.entry(label.into_boxed_str()).or_default().push((k, e));
        }
    }

    /// The program numbered `n` (the first of that number).
    pub fn program(&self, n: u32) -> Option<Entry> {
        self.programs.iter().find(|(k, _)| *k == n).map(|(_, e)| *e)
    }

    /// Where the program holding `offset` starts and ends (the next program number, or the text's end).
    pub fn program_range(&self, offset: usize) -> (usize, usize) {
        let k = self.programs.partition_point(|(_, e)| e.at.offset <= offset);
        let start = if k == 0 { 0 } else { self.programs[k - 1].1.at.offset };
        let end = self.programs.get(k).map_or(self.end.offset, |(_, e)| e.at.offset);
        (start, end)
    }

    /// Sequence number `n` in the program holding `offset`: searched forward
    /// from `offset`, then from the program's start.
    pub fn sequence(&self, n: u32, offset: usize) -> Option<Entry> {
        let (start, end) = self.program_range(offset);
        let inside = |e: &Entry| e.at.offset >= start && e.at.offset < end;
        let ahead = self.sequences.iter().find(|(k, e)| *k == n && e.at.offset >= offset && inside(e));
        ahead.or_else(|| self.sequences.iter().find(|(k, e)| *k == n && inside(e))).map(|(_, e)| *e)
    }

    /// The first `END m` after `offset` in its program.
    pub fn end_of_loop(&self, m: u8, offset: usize) -> Option<Entry> {
        let (_, end) = self.program_range(offset);
        self.ends.iter().find(|(k, e)| *k == m && e.at.offset > offset && e.at.offset < end).map(|(_, e)| *e)
    }

    /// The first o-word line of `label` after `offset` whose keyword is one of `kws`.
    pub fn next_oword(&self, label: &str, offset: usize, kws: &[OKw]) -> Option<(OKw, Entry)> {
        self.owords.get(label)?.iter().find(|(k, e)| e.at.offset > offset && kws.contains(k)).copied()
    }

    /// The last o-word line of `label` before `offset` whose keyword is one of `kws`.
    pub fn prev_oword(&self, label: &str, offset: usize, kws: &[OKw]) -> Option<(OKw, Entry)> {
        self.owords.get(label)?.iter().rev().find(|(k, e)| e.at.offset < offset && kws.contains(k)).copied()
    }

    /// The `sub` line of `label`.
    pub fn sub(&self, label: &str) -> Option<Entry> {
        self.owords.get(label)?.iter().find(|(k, _)| *k == OKw::Sub).map(|(_, e)| *e)
    }
}
