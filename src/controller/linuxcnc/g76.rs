//! LinuxCNC G76: `G76 P Z I J R K Q H E L $`, read in the interpreter's
//! order (`convert_straight`, then `convert_threading_cycle`): cutter
//! compensation, the spindle, rotary axes, then I, J, K. The cycle is
//! planned by [`crate::cycle::linuxcnc`].
//!
//! The tool position is the drive point: X0 is the drive line, Z0 the start
//! of the thread. I, J, K are diameters under G7 (halved), P and E are not.
//! Values the interpreter reads as others are warned: Q−1 (no Q), R below 1
//! (R1), E below 0 (no taper), L as a bit mask.

use super::{Reader, g_word_span, plane_warning, spindle_number};
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::linuxcnc::G76;
use crate::event::Event;
use crate::message::{self as msg, Args, Template};
use crate::motion::Point;
use crate::settings::P;
use crate::span::Span;

/// One G76 block (its words were checked before).
pub fn block(r: &mut Reader, b: &Block) {
    r.close();
    let g = g_word_span(b, 760);
    if !preconditions(r, b, g) {
        return;
    }
    let radius = |r: &mut Reader, w: Option<Word>| w.map_or(0.0, |w| r.length(&w) / if r.m.radius { 1.0 } else { 2.0 });
    let (i, j, k) = (radius(r, b.get(b'I').copied()), radius(r, b.get(b'J').copied()), radius(r, b.get(b'K').copied()));
    if let Some((t, a)) = ijk_error(i, j, k) {
        let w = if i == 0.0 {
            b'I'
        } else if j <= 0.0 {
            b'J'
        } else {
            b'K'
        };
        return r.diag(t, b.get(w).map_or(g, |w| w.span), a);
    }
    plane_warning(r, g, "G76");
    let pw = b.get(b'P').copied();
    let pitch = pw.map_or(0.0, |w| r.length(&w));
    if let (Some(w), true) = (pw, pitch <= 0.0) {
        let what = if pitch == 0.0 { &msg::P_ZERO } else { &msg::P_NEGATIVE };
        r.diag(&msg::LCNC_ODD_P, w.span, args![word = w, what]);
    }
    let start = r.current(b.span);
    let target = r.target(b);
    let (x0, z0) = (start.r(), start.z);
    let x_end = if target.has_x { target.p.r() } else { x0 };
    let z1 = if target.has_z { target.p.z } else { z0 };
    end_words(r, b, x0);
    let cycle = G76 {
        line: b.line,
        span: g,
        x0,
        z0,
        z1,
        x_end,
        pitch,
        i,
        j,
        k,
        r: read_r(r, b),
        q: read_q(r, b),
        h: read_h(r, b),
        e: read_e(r, b),
        l: read_l(r, b),
        tool_angle: r.param(P::LinuxToolAngle),
        spindle: r.spindle(),
    };
    r.emit(Event::LinuxG76(Box::new(cycle)));
    r.arrive(Point::new(2.0 * x_end, z1), true, true, b.line);
}

/// Compensation, spindle and axes, in the interpreter's order; false after an alarm.
fn preconditions(r: &mut Reader, b: &Block, g: Span) -> bool {
    let comp = r.m.comp;
    if let Some(rad) = comp.filter(|rad| *rad > 0.0) {
        r.diag(&msg::LCNC_COMP_RADIUS_G76, g, args![radius = rad]);
        return false;
    }
    if !spindle_number(r, b, "Invalid D-number in G76 cycle") {
        return false;
    }
    if !r.m.spindle_on {
        let n = b.spindle.map_or(0.0, |w| w.value());
        r.diag(&msg::LCNC_SPINDLE_NOT_TURNING_G76, g, args![n]);
        return false;
    }
    if let Some(w) = b.words().iter().find(|w| matches!(w.letter, b'A' | b'B' | b'C')) {
        r.diag(&msg::LCNC_ROTARY_G76, w.span, args![word = w]);
        return false;
    }
    if comp.is_some() {
        r.diag(&msg::LCNC_COMP_G76, g, args![]);
        return false;
    }
    true
}

/// LinuxCNC's checks of I, J, K (radius values).
fn ijk_error(i: f64, j: f64, k: f64) -> Option<(&'static Template, Args)> {
    if i == 0.0 {
        Some((&msg::LCNC_I_ZERO, args![]))
    } else if j <= 0.0 {
        Some((&msg::LCNC_J_NOT_POSITIVE, args![j]))
    } else if k <= j {
        Some((&msg::LCNC_K_NOT_OVER_J, args![k, j]))
    } else {
        None
    }
}

/// X and Y words do not move the drive line: the passes still start from the tool's X.
fn end_words(r: &mut Reader, b: &Block, x0: f64) {
    for w in b.words().iter().filter(|w| matches!(w.letter, b'X' | b'Y')) {
        // As the program writes X: a radius under G8, a diameter under G7.
        let shown = if r.m.radius { x0 } else { 2.0 * x0 };
        r.diag(&msg::LCNC_DRIVE_LINE, w.span, args![word = w, x = shown, letter = w.letter()]);
    }
}

/// R, the depth degression: default 1; below 1 it is read as 1.
fn read_r(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'R').copied() else { return 1.0 };
    let v = w.value();
    if v < 1.0 {
        r.diag(&msg::LCNC_R_BELOW_1, w.span, args![word = w]);
        return 1.0;
    }
    v
}

/// Q, the compound angle: default 0; Q−1 is the interpreter's "no Q".
fn read_q(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'Q').copied() else { return 0.0 };
    if w.value() == -1.0 {
        r.diag(&msg::LCNC_Q_MINUS_ONE, w.span, args![]);
        return 0.0;
    }
    w.value()
}

/// H, spring passes: default 0; below 0 the full-depth pass is dropped.
fn read_h(r: &mut Reader, b: &Block) -> i64 {
    let Some(w) = b.get(b'H').copied() else { return 0 };
    let h = w.value().round().clamp(-1.0e15, 1.0e15) as i64;
    if h < 0 {
        r.diag(&msg::LCNC_NEGATIVE_H, w.span, args![word = w]);
    }
    h
}

/// E, the taper length: default 0; below 0 read as 0.
fn read_e(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'E').copied() else { return 0.0 };
    let v = r.length(&w);
    if v < 0.0 {
        r.diag(&msg::LCNC_NEGATIVE_E, w.span, args![word = w]);
        return 0.0;
    }
    v
}

/// L, the taper ends as a bit mask (1 entry, 2 exit); warns when E and L do not make a taper.
fn read_l(r: &mut Reader, b: &Block) -> u32 {
    let l = b.get(b'L').map_or(0, |w| w.value().round().clamp(0.0, 1.0e9) as u32);
    let e = b.get(b'E').map_or(0.0, |w| w.value());
    let bits = l & 3;
    let ends = [&msg::NO_TAPER, &msg::ENTRY_TAPER, &msg::EXIT_TAPER, &msg::BOTH_TAPERS][bits as usize];
    if let Some(w) = b.get(b'L').filter(|_| l > 3) {
        r.diag(&msg::LCNC_L_MASK, w.span, args![word = w, l, ends]);
    } else if let (Some(w), true) = (b.get(b'E'), e > 0.0 && bits == 0) {
        r.diag(&msg::LCNC_E_WITHOUT_L, w.span, args![word = w]);
    } else if let (Some(w), true) = (b.get(b'L'), bits != 0 && e == 0.0) {
        r.diag(&msg::LCNC_L_WITHOUT_E, w.span, args![word = w]);
    }
    l
}
