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
use crate::block::{Block, Word};
use crate::cycle::linuxcnc::G76;
use crate::diagnostic::Code;
use crate::event::Event;
use crate::motion::Point;
use crate::num::fmt;
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
    if let Some(msg) = ijk_error(i, j, k) {
        let w = if i == 0.0 {
            b'I'
        } else if j <= 0.0 {
            b'J'
        } else {
            b'K'
        };
        return r.diag(Code::ValueOutOfRange, b.get(w).map_or(g, |w| w.span), msg);
    }
    plane_warning(r, g, "G76");
    let pw = b.get(b'P').copied();
    let pitch = pw.map_or(0.0, |w| r.length(&w));
    if let (Some(w), true) = (pw, pitch <= 0.0) {
        let what = if pitch == 0.0 { "no thread is drawn, only the moves" } else { "the thread is drawn with |P|" };
        r.diag(
            Code::OddPitch,
            w.span,
            format!("{}: LinuxCNC passes a P of zero or below on as the spindle sync ratio; {what}", w.display()),
        );
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
        r.diag(
            Code::CutterCompActive,
            g,
            format!(
                "Bug code not g0 or g1: with cutter radius compensation on (radius {}) LinuxCNC sends G76 to the compensation path, which knows only G0 and G1; cancel it with G40 before G76",
                fmt(rad)
            ),
        );
        return false;
    }
    if !spindle_number(r, b, "Invalid D-number in G76 cycle") {
        return false;
    }
    if !r.m.spindle_on {
        let n = b.spindle.map_or(0.0, |w| w.value());
        r.diag(
            Code::SpindleNotTurning,
            g,
            format!("Chosen spindle ({}) not turning in G76: start it with M3 or M4 first", fmt(n)),
        );
        return false;
    }
    if let Some(w) = b.words.iter().find(|w| matches!(w.letter, b'A' | b'B' | b'C')) {
        r.diag(Code::UnexpectedWord, w.span, format!("{}: Cannot move rotary axes with G76", w.display()));
        return false;
    }
    if comp.is_some() {
        r.diag(
            Code::CutterCompActive,
            g,
            "Cannot use G76 threading cycle with cutter radius compensation on: cancel it with G40 before G76",
        );
        return false;
    }
    true
}

/// LinuxCNC's checks of I, J, K (radius values).
fn ijk_error(i: f64, j: f64, k: f64) -> Option<String> {
    if i == 0.0 {
        Some("In G76, I must not be 0: I is the peak's offset from the drive line (negative external, positive internal)".into())
    } else if j <= 0.0 {
        Some(format!("In G76, J must be greater than 0 (J is the first pass depth; here {})", fmt(j)))
    } else if k <= j {
        Some(format!(
            "In G76, K must be greater than J (K {} is the thread depth, J {} the first pass depth)",
            fmt(k),
            fmt(j)
        ))
    } else {
        None
    }
}

/// X and Y words do not move the drive line: the passes still start from the tool's X.
fn end_words(r: &mut Reader, b: &Block, x0: f64) {
    for w in b.words.iter().filter(|w| matches!(w.letter, b'X' | b'Y')) {
        // As the program writes X: a radius under G8, a diameter under G7.
        let shown = if r.m.radius { x0 } else { 2.0 * x0 };
        r.diag(
            Code::DriveLineKept,
            w.span,
            format!(
                "{}: the passes are cut from the drive line X{} (where the tool is); {} only moves the tool at the end of the cycle",
                w.display(),
                fmt(shown),
                w.letter()
            ),
        );
    }
}

/// R, the depth degression: default 1; below 1 it is read as 1.
fn read_r(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'R').copied() else { return 1.0 };
    let v = w.value();
    if v < 1.0 {
        r.diag(
            Code::ValueReadAs,
            w.span,
            format!("{}: a degression below 1 is read as R1 (constant depth J per pass)", w.display()),
        );
        return 1.0;
    }
    v
}

/// Q, the compound angle: default 0; Q−1 is the interpreter's "no Q".
fn read_q(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'Q').copied() else { return 0.0 };
    if w.value() == -1.0 {
        r.diag(
            Code::ValueReadAs,
            w.span,
            "Q-1 is the interpreter's value for no Q: the passes feed straight in (Q0), not at -1°",
        );
        return 0.0;
    }
    w.value()
}

/// H, spring passes: default 0; below 0 the full-depth pass is dropped.
fn read_h(r: &mut Reader, b: &Block) -> i64 {
    let Some(w) = b.get(b'H').copied() else { return 0 };
    let h = w.value().round().clamp(-1.0e15, 1.0e15) as i64;
    if h < 0 {
        r.diag(
            Code::FullDepthSkipped,
            w.span,
            format!(
                "{}: LinuxCNC cuts H + 1 passes at full depth, so with a negative H the thread is never cut to K",
                w.display()
            ),
        );
    }
    h
}

/// E, the taper length: default 0; below 0 read as 0.
fn read_e(r: &mut Reader, b: &Block) -> f64 {
    let Some(w) = b.get(b'E').copied() else { return 0.0 };
    let v = r.length(&w);
    if v < 0.0 {
        r.diag(
            Code::ValueReadAs,
            w.span,
            format!("{}: a negative taper length is read as E0: no taper is cut", w.display()),
        );
        return 0.0;
    }
    v
}

/// L, the taper ends as a bit mask (1 entry, 2 exit); warns when E and L do not make a taper.
fn read_l(r: &mut Reader, b: &Block) -> u32 {
    let l = b.get(b'L').map_or(0, |w| w.value().round().clamp(0.0, 1.0e9) as u32);
    let e = b.get(b'E').map_or(0.0, |w| w.value());
    let bits = l & 3;
    let ends = ["no taper", "an entry taper", "an exit taper", "tapers at both ends"][bits as usize];
    if let Some(w) = b.get(b'L').filter(|_| l > 3) {
        r.diag(
            Code::ValueReadAs,
            w.span,
            format!("{}: L is a bit mask (1 entry, 2 exit): L{l} gives {ends}", w.display()),
        );
    } else if let (Some(w), true) = (b.get(b'E'), e > 0.0 && bits == 0) {
        r.diag(
            Code::ValueReadAs,
            w.span,
            format!("{}: without L1, L2 or L3 the taper length gives no taper", w.display()),
        );
    } else if let (Some(w), true) = (b.get(b'L'), bits != 0 && e == 0.0) {
        r.diag(Code::ValueReadAs, w.span, format!("{}: without a taper length E it gives no taper", w.display()));
    }
    l
}
