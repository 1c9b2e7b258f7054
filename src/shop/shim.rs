//! The insert's inclination against the thread's helix. The helix angle is
//! λ = arctan(lead / (π·d2)); the insert sits on a shim that leans it, 1°
//! in the holder as delivered, others in 1° steps from −2° to 4° (Sandvik
//! Coromant, Threading user manual, "Methods for selecting the correct
//! shim": P 6 on d2 40 → λ 2.7°, use a 3° shim; ZCC-CT catalogue: "the shim
//! λ = 1° is delivered with the tool holder"). Mitsubishi Materials (MMT
//! shim selection) keeps the insert's inclination within 1° of λ for 60° and
//! 55° forms (its window "2.5°–0.5°" around a shim on a holder leaning
//! 1.5°) and within 0.5° for 30° and 29° forms: beyond it the trailing
//! flank rubs. A left-hand thread leans the other way: negative shims.
//!
//! The program does not say the spindle's direction here: a cut towards −Z
//! is taken for a right-hand thread (M03), towards +Z for a left-hand one.

use super::Context;
use crate::args;
use crate::diagnostic::Diagnostics;
use crate::message as msg;
use crate::thread::{Axis, Thread};

/// The inclination of the shim a holder is delivered with, degrees.
pub const STANDARD: f64 = 1.0;
/// The shims made, degrees (Sandvik: −2° … 4° in 1° steps).
pub const RANGE: (f64, f64) = (-2.0, 4.0);

/// How far the insert's inclination may be from the helix, degrees, for a form of `angle`.
pub fn window(angle: f64) -> f64 {
    if angle < 45.0 { 0.5 } else { 1.0 }
}

/// The shim for helix angle `lambda` (signed: negative for a left-hand thread): the nearest degree, in the range made.
pub fn shim_for(lambda: f64) -> f64 {
    lambda.round().clamp(RANGE.0, RANGE.1)
}

/// A note with the shim to use where the standard one is not it, and a
/// warning where the standard shim leaves a flank rubbing.
pub fn check(t: &Thread, helix_deg: Option<f64>, ctx: &Context, diags: &mut Diagnostics) {
    let Some(lambda) = helix_deg.filter(|l| l.is_finite()) else { return };
    if t.long_axis != Axis::Z || t.passes.is_empty() {
        return;
    }
    let p = &t.passes[0];
    let left = p.to.z > p.from.z;
    let signed = if left { -lambda } else { lambda };
    let shim = shim_for(signed);
    if (shim - STANDARD).abs() < 1e-9 {
        return;
    }
    let span = (ctx.spans)(t.line);
    let hand = if left { &msg::LEFT_HAND } else { &msg::RIGHT_HAND };
    let off = (signed - STANDARD).abs();
    let win = window(t.tool_angle);
    let reach = if (shim - signed.round()).abs() > 1e-9 { &msg::SHIM_BEYOND } else { &msg::SHIM_WITHIN };
    if off > win + 1e-9 {
        diags.push(&msg::SHIM_RUB, span, args![lambda, hand, off, win, shim, reach]);
    } else {
        diags.push(&msg::SHIM, span, args![lambda, hand, shim]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shims_by_the_catalogues() {
        // Sandvik: P 6 on d2 40: λ = arctan(6 / (40π)) = 2.73° → a 3° shim; 5 t.p.i. on 4": 0.91° → 1°.
        let l = (6.0f64 / (40.0 * std::f64::consts::PI)).atan().to_degrees();
        assert!((l - 2.734).abs() < 1e-3);
        assert_eq!(shim_for(l), 3.0);
        assert_eq!(shim_for((1.0f64 / 5.0 / (4.0 * std::f64::consts::PI)).atan().to_degrees()), 1.0);
        // Left-hand: the mirror; beyond the shims made: the last one.
        assert_eq!(shim_for(-2.7), -2.0);
        assert_eq!(shim_for(5.3), 4.0);
        assert_eq!((window(60.0), window(55.0), window(30.0), window(29.0)), (1.0, 1.0, 0.5, 0.5));
    }
}
