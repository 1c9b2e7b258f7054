//! The spindle speed changed between the passes of one thread. The axis
//! follows the spindle with a lag, and the distance it lags by grows with
//! the feed, so with it the speed: a pass run at another S starts at
//! another place on the helix and cross-threads the part (reference
//! threading.md §11, "keep S constant across the passes of one thread").
//! With the lag known (setting `machine.servo_lag`, ms) the warning gives
//! the shift: the following error is the feed times the lag, lead·n/60·T,
//! so the start moves by lead·|n₂ − n₁|/60·T along the axis.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::message as msg;
use crate::settings::P;
use crate::thread::Thread;

/// Warns on the first pass of each run of passes cut at another S than the
/// thread's first pass (passes under G96 have the `thread-css` warning).
pub fn check(t: &Thread, ctx: &Context, diags: &mut Diagnostics) {
    let Some(first) = t.passes.iter().find(|p| !p.spindle.css).and_then(|p| p.spindle.s) else { return };
    let lag_ms = ctx.settings.get(P::ServoLag);
    let mut last = first;
    for p in t.passes.iter().filter(|p| !p.spindle.css) {
        let Some(s) = p.spindle.s else { continue };
        if (s - last).abs() < 1e-9 {
            continue;
        }
        last = s;
        if (s - first).abs() < 1e-9 {
            continue;
        }
        let span = ctx.moves.get(p.moves.cut.start).map_or_else(|| (ctx.spans)(t.line), |m| m.span);
        let shift = t.lead * (s - first).abs() / 60.0 * lag_ms / 1000.0;
        let a = args![n = p.index, s, first, start = p.start];
        let a = if lag_ms > 0.0 {
            a.with("shift", &msg::SPEED_SHIFT).with("lag", lag_ms).with("dz", shift).with("deg", 360.0 * shift / t.lead)
        } else {
            a.with("shift", &msg::SPEED_NO_LAG)
        };
        diags.push(&msg::SPEED_BETWEEN_PASSES, span, a);
    }
}
