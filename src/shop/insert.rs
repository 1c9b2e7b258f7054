//! The threading insert (setting `tool.insert`, read by
//! [`crate::insert`]) against each thread: its side, and its pitch (full
//! profile) or its range (partial profile). A full-profile insert forms the
//! standard's root and crest, so it gives the thread check its nose radius;
//! a partial one's nose radius is its maker's.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::figures::InsertForm;
use crate::insert::{Insert, Profile, parse};
use crate::message as msg;
use crate::settings::T;
use crate::thread::Thread;

/// The nose radius (× P) of a full-profile insert for an external thread,
/// taken when the tool is not known: ISO 965-1's smallest root radius of an
/// external thread, 0.125·P (the basic profile allows up to H/6 = 0.144·P).
pub const FULL_PROFILE_RADIUS: f64 = 0.125;

/// The same for an internal thread, whose root radius ISO 965-1 leaves
/// open: the largest nose that stays within ISO 68-1's basic profile, whose
/// root flat lies H/8 inside the sharp V — r·(1/sin 30° − 1) = H/8, so
/// r = H/8 = √3/16·P = 0.108·P.
pub const FULL_PROFILE_RADIUS_INTERNAL: f64 = 0.108_253_175_473_054_83;

/// The nose radius (program units) taken for pitch `p` when the tool is not known.
pub fn assumed_nose_radius(p: f64, internal: bool) -> f64 {
    p * if internal { FULL_PROFILE_RADIUS_INTERNAL } else { FULL_PROFILE_RADIUS }
}

/// The insert of the settings, if one is given and reads.
pub fn of<'a>(ctx: &Context<'a>) -> Option<(Insert, &'a str)> {
    let text = ctx.settings.text(T::Insert);
    parse(text).ok().map(|i| (i, text))
}

/// The insert's form on thread `t`: a full profile's nose radius is the
/// standard's root radius ([`assumed_nose_radius`]); a partial
/// profile's is its maker's (setting `tool.nose_radius`, else not known).
pub fn form(t: &Thread, ctx: &Context) -> Option<InsertForm> {
    let (insert, name) = of(ctx)?;
    let given = ctx.settings.get(crate::settings::P::NoseRadius) / ctx.mm();
    let full = matches!(insert.profile, Profile::Full { .. });
    let nose_radius = if given > 0.0 {
        given
    } else if full {
        assumed_nose_radius(t.pitch, t.internal)
    } else {
        0.0
    };
    Some(InsertForm { name: name.trim().to_string(), full, nose_radius })
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
