//! What an edit changed, for the planner: where the old and new texts
//! differ, which lines the edit touched, and whether it changed a label a
//! jump or call looks up.

/// Whether an edit changed a label a jump or call looks up: the program,
/// sequence, loop-end and o-word lines among the edited lines, old and new
/// (`linuxcnc` reads `o` lines as o-words).
pub(super) fn labels_changed(old: &str, new: &str, changed_at: usize, common: usize, linuxcnc: bool) -> bool {
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
pub(super) fn lines_of(text: &str, starts: &[u32], from: usize, to: usize) -> (u32, u32) {
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
    a.bytes().rev().zip(b.bytes().rev()).take_while(|(x, y)| x == y).count()
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
