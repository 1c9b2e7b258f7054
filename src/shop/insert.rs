//! The threading insert (setting `tool.insert`, read by
//! [`crate::insert`]) against each thread: its side, and its pitch (full
//! profile) or its range (partial profile). A full-profile insert forms the
//! standard's root and crest, so it gives the thread check its nose radius;
//! a partial one's nose radius is its maker's.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::insert::{Insert, Profile, parse};
use crate::message as msg;
use crate::settings::T;
use crate::thread::Thread;

/// The insert of the settings, if one is given and reads.
pub fn of<'a>(ctx: &Context<'a>) -> Option<(Insert, &'a str)> {
    let text = ctx.settings.text(T::Insert);
    parse(text).ok().map(|i| (i, text))
}

/// The checks of thread `t` against the insert: its side, its pitch (full
/// profile) or its range (partial profile).
pub fn check(t: &Thread, ctx: &Context, diags: &mut Diagnostics) {
    let Some((insert, name)) = of(ctx) else { return };
    let span = (ctx.spans)(t.line);
    let name = name.trim().to_string();
    if insert.internal != t.internal {
        let (is, thread) =
            if insert.internal { (&msg::INTERNAL, &msg::EXTERNAL) } else { (&msg::EXTERNAL, &msg::INTERNAL) };
        diags.push(&msg::INSERT_SIDE, span, args![insert = name.clone(), is, thread]);
    }
    let pitch = t.pitch * ctx.mm();
    match insert.profile {
        Profile::Full { pitch_mm } if (pitch_mm - pitch).abs() > 1e-3 => {
            diags.push(&msg::INSERT_PITCH, span, args![insert = name, made = pitch_mm, pitch]);
        }
        Profile::Partial { min_mm, max_mm, .. } if pitch < min_mm - 1e-9 || pitch > max_mm + 1e-9 => {
            diags.push(&msg::INSERT_RANGE, span, args![insert = name, min = min_mm, max = max_mm, pitch]);
        }
        _ => {}
    }
}
