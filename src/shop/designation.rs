//! Which thread a program cuts, by name: the nearest comment before the
//! thread's first block (back to the previous thread) that names a thread
//! of the lead or pitch the program cuts, such as `(M48x2-6g)`; else the
//! setting `thread.designation`. A comment naming another pitch is about
//! something else (a tool, an operation, `M03` in a note) and is passed over.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::figures::DesignationSource;
use crate::message as msg;
use crate::settings::T;
use crate::standard::{self, Designation};
use crate::thread::Thread;

/// A designation found for a thread.
pub(super) struct Found {
    /// The designation.
    pub d: Designation,
    /// Where it was read.
    pub source: DesignationSource,
    /// The comment's line.
    pub line: Option<u32>,
}

/// Whether a source line may hold a comment with a designation: a `(` (or
/// its full-width form) or text after a `;` (GSK and Renhe end every block
/// with one). Most lines have neither and are passed over unread.
fn may_comment(line: &str) -> bool {
    let b = line.as_bytes();
    // Full-width `（` is EF BC 88 and `；` EF BC 9B in UTF-8.
    let wide = |tail: u8| b.windows(3).position(|w| w == [0xEF, 0xBC, tail]);
    if memchr::memchr(b'(', b).is_some() || (memchr::memchr(0xEF, b).is_some() && wide(0x88).is_some()) {
        return true;
    }
    let semi = match (memchr::memchr(b';', b), memchr::memchr(0xEF, b).and_then(|_| wide(0x9B))) {
        (Some(a), Some(w)) if w < a => Some(w + 3),
        (Some(a), _) => Some(a + 1),
        (None, Some(w)) => Some(w + 3),
        (None, None) => None,
    };
    semi.is_some_and(|i| !line[i..].trim().is_empty())
}

/// The lines of `s`, ended by `\n`, `\r\n` or a lone `\r` (as the line index counts them).
fn split_lines(s: &str) -> Vec<&str> {
    let b = s.as_bytes();
    let (mut out, mut start) = (Vec::new(), 0);
    while let Some(k) = memchr::memchr2(b'\n', b'\r', &b[start..]) {
        let i = start + k;
        out.push(&s[start..i]);
        start = if b[i] == b'\r' && b.get(i + 1) == Some(&b'\n') { i + 2 } else { i + 1 };
    }
    out.push(&s[start..]);
    out
}

/// The comments of a source line: `( … )` and what follows `;`, full-width
/// characters folded to ASCII, each cut at 256 bytes.
fn comments(line: &str) -> Vec<String> {
    let folded: String = line
        .chars()
        .take(4096)
        .map(|c| match c {
            '\u{FF01}'..='\u{FF5E}' => char::from_u32(c as u32 - 0xFEE0).unwrap_or(c),
            '\u{3000}' => ' ',
            _ => c,
        })
        .collect();
    let mut out = Vec::new();
    let mut open: Option<usize> = None;
    for (i, c) in folded.char_indices() {
        match (c, open) {
            ('(', None) => open = Some(i + 1),
            (')', Some(s)) => {
                out.push(folded[s..i].to_string());
                open = None;
            }
            (';', None) => {
                out.push(folded[i + 1..].to_string());
                break;
            }
            _ => {}
        }
    }
    for c in &mut out {
        if c.len() > 256 {
            let mut end = 256;
            while !c.is_char_boundary(end) {
                end -= 1;
            }
            c.truncate(end);
        }
    }
    out
}

/// The designation of `t`: the nearest comment from its first line back to
/// the line after `lower` (the previous thread's last line) naming a
/// thread of its lead or pitch, else the setting.
pub(super) fn designation(t: &Thread, lower: Option<u32>, ctx: &Context, diags: &mut Diagnostics) -> Option<Found> {
    let first = t.line.max(1);
    let stop = match lower {
        Some(l) if l < first => l + 1,
        Some(_) => first,
        None => 1,
    };
    let mm = ctx.mm();
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-6 * a.abs().max(1.0);
    // The lines from `stop` to `first`, read from the last back (one slice, split at line ends).
    let (from, to) = ((ctx.spans)(stop).start as usize, (ctx.spans)(first).end as usize);
    let region = ctx.text.get(from..to.max(from)).unwrap_or("");
    for (back, text) in split_lines(region).into_iter().rev().enumerate() {
        let line = first.saturating_sub(back as u32);
        if !may_comment(text) {
            continue;
        }
        for c in comments(text).iter().rev() {
            if let Some(d) = standard::find(c) {
                if same(d.lead_mm, t.lead * mm) || same(d.pitch_mm, t.pitch * mm) {
                    return Some(Found { d, source: DesignationSource::Comment, line: Some(line) });
                }
            }
        }
    }
    let text = ctx.settings.text(T::Designation);
    if text.is_empty() {
        return None;
    }
    match standard::parse(text) {
        Ok(d) => Some(Found { d, source: DesignationSource::Setting, line: None }),
        Err(e) => {
            diags.push_with(&msg::BAD_DESIGNATION_SETTING, (ctx.spans)(t.line), || args![text, error = e.detail]);
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_of_a_line() {
        assert_eq!(comments("N20 G00 X58 (M48x2-6g) Z70; note"), vec!["M48x2-6g", " note"]);
        assert_eq!(comments("（Ｍ４８×２－６ｇ）"), vec!["M48×2-6g"]);
        assert!(comments("G00 X10").is_empty());
        assert_eq!(comments("(open").len(), 0);
    }

    #[test]
    fn lines_end_as_the_line_index_says() {
        assert_eq!(split_lines("a\nb\r\nc\rd"), ["a", "b", "c", "d"]);
        assert_eq!(split_lines("a\n\nb"), ["a", "", "b"]);
        assert_eq!(split_lines(""), [""]);
    }

    #[test]
    fn lines_without_a_comment_are_passed_over() {
        assert!(!may_comment("N10 G00 X58 Z70;"));
        assert!(!may_comment("N10 G00 X58 Z70;  "));
        assert!(!may_comment("G32 Z13 F2"));
        assert!(may_comment("N10 G00 X58; M48x2-6g"));
        assert!(may_comment("G00 X58 (M48x2-6g)"));
        assert!(may_comment("（Ｍ４８×２－６ｇ）"));
        assert!(may_comment("G00；注释"));
    }
}
