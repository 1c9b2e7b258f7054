//! LinuxCNC (rs274ngc), reference §8: G7/G8 diameter/radius mode, G17–G19,
//! G20/G21, G90/G91 distance mode, G33 (K = distance along the move per
//! revolution) and G76 (drive line, peak offset I, depths J/K, degression R,
//! compound angle Q, spring passes H, tapers E/L), the lathe profile cycles
//! G70–G72 (`g7x`: the profile in subroutine o(Q)), with LinuxCNC's own word
//! checks and messages.
//!
//! The oracle is LinuxCNC's interpreter, `rs274` (Debian `linuxcnc-uspace`):
//! `tests/linuxcnc.rs` compares the synchronised moves of the plan with its
//! canonical output, and the error programs of `tests/linuxcnc/` with its
//! messages. U, V, W are not axes of a lathe configuration (rs274 refuses
//! them); `$` selects a spindle.

mod check;
mod g33;
mod g76;
mod g7x;

use super::macros::{Depth, Flavor, Macros};
use super::{Command, Controller, Reader, Rules, ThreadWords, Writing, basic_g_code};
use crate::args;
use crate::block::Block;
use crate::dialect::{Dialect, letters};
use crate::form::Form;
use crate::gcode::{G, Group};
use crate::message::{self as msg, Arg};
use crate::settings::{P, Settings};
use crate::span::Span;
use crate::state::{Modal, Motion, once};

/// The LinuxCNC interpreter.
pub static CONTROLLER: Controller = Controller {
    rules: Rules {
        dialect: Dialect::LinuxCnc,
        addresses: letters(b"ABCDEFGHIJKLMNOPQRSTXYZ"),
        increments_without_point: None,
        shared_f_register: false,
        axis_words: letters(b"XYZABC"),
        // Every word is checked by `check` before a block runs, with LinuxCNC's messages.
        free_words: letters(b"ABCDEFGHIJKLMNOPQRSTUVWXYZ"),
        spindle_word: true,
        // o-words, parameters and expressions as rs274ngc runs them.
        macros: Some(Macros {
            flavor: Flavor::LinuxCnc,
            subprograms: false,
            macro_calls: false,
            sub_depth: Depth::Fixed(9),
            macro_depth: Depth::Fixed(9),
            max_loop: 255,
            h_codes: false,
            source: "rs274ngc",
        }),
        // rs274 stops the spindle for a tool change (M6) before it runs M3/M4.
        spindle_stops: &[6],
        pockets: false,
    },
    g_code,
    command,
    init,
    check: Some(check::block),
    finish: Some(finish),
    writing: Writing {
        preamble: &["G18 G7 G90"],
        units: Some(("G20", "G21")),
        motion: ["G0", "G1", "G2", "G3"],
        points: false,
        spindle_on: Some("M3"),
        thread: ThreadWords::AlongPath,
        start_angle: false,
        forms: &[Form::G33, Form::LinuxG76],
    },
    tool_angle: Some(P::LinuxToolAngle),
};

/// The state a program starts in: G8 or G7, and the plane, by the settings.
fn init(m: &mut Modal, s: &Settings) {
    m.radius = s.int(P::LinuxStartupX) == 0;
    m.plane = [17, 18, 19][s.int(P::LinuxStartupPlane).clamp(0, 2) as usize];
}

fn g_code(code10: i64) -> Option<(Group, G)> {
    use G::*;
    use Group::*;
    let ns = |what, returns| NotSimulated { what, returns };
    Some(match code10 {
        50..=52 => (Motion, ns(&crate::message::NS_G5, false)),
        70 => (LatheMode, DiameterMode),
        80 => (LatheMode, RadiusMode),
        100 => (OneShot, ns(&crate::message::NS_G10, true)),
        170 | 180 | 190 => (Group::Plane, G::Plane((code10 / 10) as u8)),
        200 => (Units, Inch),
        210 => (Units, Metric),
        280 | 300 => (OneShot, RefReturn),
        281 | 301 => (Setup, Accepted),
        330 => (Motion, SyncThread),
        331 => (Motion, ns(&crate::message::NS_G33_1, true)),
        382..=385 => (Motion, ns(&crate::message::NS_G38, false)),
        400 => (NoseComp, CompOff),
        410 | 420 => (NoseComp, CompOn),
        411 | 421 => (NoseComp, CompOnDynamic),
        430 | 431 | 432 | 490 => (Setup, Accepted),
        520 => (OneShot, ns(&crate::message::NS_G52, false)),
        530 => (OneShot, ns(&crate::message::NS_G53, false)),
        540 | 550 | 560 | 570 | 580 | 590 | 591 | 592 | 593 | 610 | 611 | 640 | 800 | 911 | 980 | 990 => {
            (Setup, Accepted)
        }
        700 | 710..=712 | 720..=722 => (OneShot, LinuxProfile(code10)),
        730 | 740 | 810..=890 => (Motion, ns(&crate::message::NS_DRILLING, true)),
        760 => (Motion, ThreadCycle),
        900 => (Distance, Absolute),
        901 => (Setup, ns(&crate::message::NS_G90_1, true)),
        910 => (Distance, Incremental),
        920 => (OneShot, SetCoord),
        921..=923 => (OneShot, ns(&crate::message::NS_G92_1, false)),
        930 => (FeedMode, Accepted),
        940 => (FeedMode, PerMinute),
        950 => (FeedMode, PerRev),
        960 => (Group::Css, G::Css),
        970 => (Group::Css, CssOff),
        _ => return basic_g_code(code10),
    })
}

fn command(r: &mut Reader, b: &Block, c: Command) {
    match c {
        Command::Motion(Motion::SyncThread) => g33::block(r, b),
        Command::Motion(Motion::ThreadCycle) => g76::block(r, b),
        Command::OneShot(G::LinuxProfile(code10), w) => g7x::block(r, b, w, code10),
        _ => {}
    }
}

/// A program must end with M2/M30 or be wrapped in `%` lines.
fn finish(r: &mut Reader) {
    if r.s.flag(P::LinuxRequireEnd) && !r.m.ended && !r.m.percent && r.m.last_span != Span::default() {
        let span = r.m.last_span;
        r.diag(&msg::LCNC_NO_PROGRAM_END, span, args![]);
    }
}

/// The span of the block's G word with code `code10`, else of the block.
fn g_word_span(b: &Block, code10: i64) -> Span {
    b.all(b'G').find(|w| (w.value() * 10.0).round() as i64 == code10).map_or(b.span, |w| w.span)
}

/// The `$` spindle number is one of the configured spindles; else `message` (an alarm).
fn spindle_number(r: &mut Reader, b: &Block, message: &'static str) -> bool {
    let Some(w) = b.spindle else { return true };
    let n = r.s.int(P::LinuxSpindles);
    let v = w.value();
    if v.fract() == 0.0 && v >= 0.0 && v < n as f64 {
        return true;
    }
    r.diag(&msg::LCNC_SPINDLE_NUMBER, w.span, args![message = Arg::lit(message), word = w, n, last = n - 1]);
    false
}

/// G33 and G76 outside G18 run, but the manual requires the XZ plane.
fn plane_warning(r: &mut Reader, span: Span, what: &str) {
    if r.m.plane != 18 && r.m.first(once::PLANE) {
        let plane = r.m.plane;
        r.diag(&msg::LCNC_PLANE, span, args![what, plane]);
    }
}
