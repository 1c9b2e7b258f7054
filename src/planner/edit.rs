//! What an edit changed, for the planner: where the old and new texts
//! differ, which lines the edit touched, and whether it changed a label a
//! jump or call looks up.

use std::cell::OnceCell;

use crate::span::Shift;

/// One edit, worked out once per plan: the old bytes `changed_at` …
/// `old_end` became the new ones `changed_at` … `new_end`.
pub(super) struct Edit {
    /// The first byte that differs.
    pub changed_at: usize,
    /// Where the bytes common to both ends begin, in the old text.
    pub old_end: usize,
    /// The same in the new text.
    pub new_end: usize,
    /// Whether the edit kept the number of lines.
    pub lines_kept: bool,
    /// How it moved the old positions.
    pub shift: Shift,
    /// Whether it changed a label, asked at most once.
    labels: OnceCell<bool>,
    /// The old lines it touched, asked at most once.
    lines: OnceCell<(u32, u32)>,
}

impl Edit {
    /// The edit that makes `old` into `new`.
    pub fn of(old: &str, new: &str) -> Edit {
        // Byte-wise, the difference can fall inside a character both texts
        // begin alike: the edit is taken from, and to, whole characters.
        let mut changed_at = first_difference(old, new);
        while !(old.is_char_boundary(changed_at) && new.is_char_boundary(changed_at)) {
            changed_at -= 1;
        }
        let mut common = common_suffix(old, new).min(old.len() - changed_at).min(new.len() - changed_at);
        while !(old.is_char_boundary(old.len() - common) && new.is_char_boundary(new.len() - common)) {
            common -= 1;
        }
        let (old_end, new_end) = (old.len() - common, new.len() - common);
        let (old_mid, new_mid) = (&old[changed_at..old_end], &new[changed_at..new_end]);
        let lines_kept = old_mid.matches('\n').count() == new_mid.matches('\n').count()
            && old_mid.matches('\r').count() == new_mid.matches('\r').count();
        let shift = Shift { at: old_end, by: new.len() as isize - old.len() as isize };
        Edit { changed_at, old_end, new_end, lines_kept, shift, labels: OnceCell::new(), lines: OnceCell::new() }
    }

    /// Whether the edit changed a label a jump or call looks up (see [`labels_changed`]).
    pub fn labels_changed(&self, old: &str, new: &str, linuxcnc: bool) -> bool {
        *self.labels.get_or_init(|| labels_changed(old, new, self.changed_at, old.len() - self.old_end, linuxcnc))
    }

    /// The old lines (first, last) the edit touched (see [`lines_of`]).
    pub fn lines(&self, old: &str, starts: &[u32]) -> (u32, u32) {
        *self.lines.get_or_init(|| lines_of(old, starts, self.changed_at, self.old_end))
    }
}

/// Whether an edit changed a label a jump or call looks up: the program,
/// sequence, loop-end and o-word lines among the edited lines, old and new
/// (`linuxcnc` reads `o` lines as o-words).
fn labels_changed(old: &str, new: &str, changed_at: usize, common: usize, linuxcnc: bool) -> bool {
    let labels = |t: &str| {
        let end = t.len() - common;
        let from = t[..changed_at].rfind(['\n', '\r']).map_or(0, |i| i + 1);
        let to = t[end..].find(['\n', '\r']).map_or(t.len(), |i| end + i);
        crate::exec::index::Index::build(&t[from..to], linuxcnc).labels()
    };
    labels(old) != labels(new)
}

/// The 1-based lines (first, last) holding bytes `from` … `to` of `text`,
/// whose line starts were recorded in `starts` (all of them, or those up to
/// where a reading that jumped stopped recording: the rest is scanned).
fn lines_of(text: &str, starts: &[u32], from: usize, to: usize) -> (u32, u32) {
    let to = to.max(from);
    if starts.last().is_some_and(|&s| s as usize > to) {
        let line = |p: usize| starts.partition_point(|&s| s as usize <= p).max(1) as u32;
        return (line(from), line(to));
    }
    let index = crate::span::LineIndex::from_starts(text, starts.to_vec());
    (index.locate(text, from).line, index.locate(text, to).line)
}

/// How many bytes `a` and `b` have in common at their ends.
pub(super) fn common_suffix(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let n = a.len().min(b.len());
    let (ea, eb) = (a.len(), b.len());
    // In chunks first, as `first_difference`: an edit near the top leaves a long common end.
    let mut i = 0;
    while i + 64 <= n && a[ea - i - 64..ea - i] == b[eb - i - 64..eb - i] {
        i += 64;
    }
    while i < n && a[ea - i - 1] == b[eb - i - 1] {
        i += 1;
    }
    i
}

/// Byte offset of the first difference between `a` and `b` (the shorter
/// length when one is a prefix of the other).
pub(super) fn first_difference(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let n = a.len().min(b.len());
    // Compare in chunks first: long unchanged prefixes are the common case.
    let mut i = 0;
    while i + 64 <= n && a[i..i + 64] == b[i..i + 64] {
        i += 64;
    }
    while i < n && a[i] == b[i] {
        i += 1;
    }
    i
}
