//! LinuxCNC's lathe profile cycles, the block itself: G70 `Q- X- Z- D- E-
//! P- F-` (finishing) and G71/G72 `Q- X- Z- D- I- R- F-` (roughing, and
//! their .1/.2 forms), with the profile in subroutine o(Q) (the G-code
//! manual's "G70 Lathe finishing cycle" and "G71 G72 Lathe roughing
//! cycles"; the interpreter's `convert_g7x` in `interp_g7x.cc`). rs274
//! checks Q, cutter compensation (G71/G72 only) and the plane, in that
//! order, before anything moves; then rapids to X and Z, and reads the
//! profile, which the program flow does here (`exec::profile`); the cycles
//! themselves are `cycle::g7x`. D, E, I and R are lengths as written (not
//! halved under G7).

use super::Reader;
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::g7x::finish::Passes;
use crate::cycle::g7x::{Call, Job, Words};
use crate::message as msg;

/// A G70 (`code10` 700) or G71/G72 (710–712, 720–722) block.
pub fn block(r: &mut Reader, b: &Block, w: &Word, code10: i64) {
    r.m.profile_call = None;
    let name = format!("G{}.{}", code10 / 10, code10 % 10);
    let Some(q) = b.get(b'Q').copied() else {
        r.diag(&msg::LCNC_G7X_NO_Q, w.span, args![word = w]);
        return;
    };
    // G70 runs under compensation (its path is then not drawn compensated, as said where G41/G42 is).
    if r.m.comp.is_some() && code10 != 700 {
        r.diag(&msg::LCNC_G7X_COMP, w.span, args![name]);
        return;
    }
    if r.m.plane != 18 {
        r.diag(&msg::LCNC_G7X_PLANE, w.span, args![name]);
        return;
    }
    if r.m.incremental {
        // rs274 moves to X/Z as absolute, and reads the profile as increments from them.
        r.noted(&msg::NOT_DRAWN, w, &msg::NS_G7X_INCREMENTAL);
        r.m.pos.kx = false;
        r.m.pos.kz = false;
        return;
    }
    if b.has(b'X') || b.has(b'Z') {
        let t = r.target(b);
        r.rapid(&t, b.line, b.span);
    }
    r.current(b.span);
    // rs274 makes that rapid a G0: the profile's moves without a motion code are lines.
    r.m.motion = crate::state::Motion::Rapid;
    if let Some(f) = b.get(b'F') {
        r.m.feed = Some(f.value());
        r.m.feed_line = b.line;
    }
    // rs274 calls "O<q> CALL": a Q that is no whole number is refused when the call is read.
    let v = q.value();
    if (v - v.round()).abs() > 1e-4 {
        r.diag(&msg::LCNC_NON_INTEGER, q.span, args![word = q, what = &msg::PROFILE_Q]);
        return;
    }
    if !(0.0..1e9).contains(&v.round()) {
        r.noted(&msg::NOT_DRAWN, w, &msg::NS_LATHE_CYCLE);
        return;
    }
    let q = v.round() as u32;
    let job = match Words::kind(code10) {
        Some((along, pockets)) => Job::Rough(words(r, b, code10, along, pockets)),
        None => {
            let mut value = |c: u8, default: f64| b.get(c).copied().map_or(default, |w| r.length(&w));
            let (d, e) = (value(b'D', 0.0), value(b'E', 0.0));
            Job::Finish(Passes { d, e, p: b.get(b'P').map_or(1.0, |w| w.value()), inch: r.m.inch })
        }
    };
    r.m.profile_call = Some(Call { q, job });
}

/// The roughing's words: D (0 if not given), I (1) and R (0.5); G70's are
/// D (0), E (0) and P (1).
fn words(
    r: &mut Reader,
    b: &Block,
    code10: i64,
    along: crate::cycle::rough::Along,
    pockets: crate::cycle::g7x::Pockets,
) -> Words {
    let mut value = |c: u8, default: f64| b.get(c).copied().map_or(default, |w| r.length(&w));
    let (d, i, rr) = (value(b'D', 0.0), value(b'I', 1.0), value(b'R', 0.5));
    let i_span = b.get(b'I').map_or(b.span, |w| w.span);
    Words { code10, along, pockets, d, i, r: rr, i_span, inch: r.m.inch }
}
