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
    for line in (stop..=first).rev() {
        let span = (ctx.spans)(line);
        let Some(text) = ctx.text.get(span.start as usize..span.end as usize) else { continue };
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
}
