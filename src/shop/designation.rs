//! Which thread a program cuts, by name: the nearest comment before the
//! thread's first block (back to the previous thread) that names a thread
//! of the lead or pitch the program cuts, such as `(M48x2-6g)`; else the
//! setting `thread.designation`. A comment naming another pitch is about
//! something else (a tool, an operation, `M03` in a note) and is passed over.

use super::Context;
use crate::args;
use crate::comment;
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
    let named = comment::find_back(ctx.text, ctx.spans, stop, first, |line, c| {
        let d = standard::find(c)?;
        let ours = same(d.lead_mm, t.lead * mm) || same(d.pitch_mm, t.pitch * mm);
        ours.then_some(Found { d, source: DesignationSource::Comment, line: Some(line) })
    });
    if named.is_some() {
        return named;
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
