//! Renhe (reference §5, seed 003): G30 run-out mode, G32 inch and G33
//! metric threads.
//!
//! Thread blocks are incremental only (X or Z is E18-03); U is a diameter
//! difference. |W| must exceed |U| and 4 mm (E18-04). An X feed (G00/G01)
//! must come first: the run-out retracts opposite to it (E18-05 without).
//! G30 sets the tail: standard (G30 alone or never given: radial
//! `renhe.runout` at `renhe.runout_angle`), none (`G30 U0 W0`, for tapping to
//! a shoulder) or spiral (`G30 U W`: X retracts U, a diameter, over the
//! last W of the thread).

use super::reader::g_span;
use super::{Command, Controller, Reader, Rules, ThreadWords, Writing, basic_g_code, g32};
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::{classify, split_runout};
use crate::dialect::{Dialect, letters};
use crate::event::Seg;
use crate::form::Form;
use crate::gcode::{G, Group};
use crate::message as msg;
use crate::settings::P;
use crate::span::Span;
use crate::state::{Motion, Tail};
use crate::thread::{Axis, Source};

/// The Renhe controller.
pub static CONTROLLER: Controller = Controller {
    rules: Rules {
        dialect: Dialect::Renhe,
        addresses: letters(b"FGIKLMNOPQRSTUWXZ"),
        increments_without_point: None,
        shared_f_register: false,
        axis_words: letters(b"XZUW"),
        free_words: 0,
        spindle_word: false,
        macros: None,
        spindle_stops: &[],
        pockets: false,
    },
    g_code,
    command,
    init: super::x_mode_parameter,
    check: None,
    finish: None,
    writing: Writing {
        preamble: &[],
        units: None,
        motion: ["G00", "G01", "G02", "G03"],
        points: false,
        spindle_on: None,
        thread: ThreadWords::Renhe,
        start_angle: false,
        forms: &[Form::RenheG33],
    },
    tool_angle: None,
};

fn g_code(code10: i64) -> Option<(Group, G)> {
    match code10 {
        300 => Some((Group::RunoutMode, G::RenheRunout)),
        320 => Some((Group::Motion, G::RenheInch)),
        330 => Some((Group::Motion, G::RenheMetric)),
        _ => basic_g_code(code10),
    }
}

fn command(r: &mut Reader, b: &Block, c: Command) {
    match c {
        Command::Motion(Motion::RenheInch) => thread_block(r, b, true),
        Command::Motion(Motion::RenheMetric) => thread_block(r, b, false),
        Command::OneShot(G::RenheRunout, w) => g30(r, b, w),
        _ => {}
    }
}

/// G30: sets the run-out mode.
fn g30(r: &mut Reader, b: &Block, w: &Word) {
    if !r.check_words(b, b"UW", "G30") {
        return;
    }
    let u = b.get(b'U').map(|w| w.value());
    let wv = b.get(b'W').map(|w| w.value());
    r.m.tail = match (u, wv) {
        (None, None) => Tail::Standard,
        (Some(u), Some(wv)) if u == 0.0 && wv == 0.0 => Tail::None,
        (Some(u), Some(wv)) => Tail::Spiral { u: u.abs(), w: wv.abs() },
        _ => {
            r.diag(&msg::G30_WORDS, w.span, args![]);
            return;
        }
    };
}

/// Reads the lead of a Renhe thread block in mm: G33 F is the pitch
/// (0.25–12 mm); G32 F is threads per inch (3–33), the digit after the point
/// being the denominator of a fraction (F11.2 = 11½) unless `renhe.inch_f` is
/// `decimal`.
fn lead(r: &mut Reader, b: &Block, inch: bool) -> Option<f64> {
    let name = if inch { "G32" } else { "G33" };
    let Some(f) = b.get(b'F').copied() else {
        if r.m.lead.is_none() {
            r.diag(if inch { &msg::RENHE_NO_TPI } else { &msg::RENHE_NO_PITCH }, g_span(b), args![name]);
        }
        return r.m.lead;
    };
    let lead = if inch {
        let tpi = if r.s.int(P::RenheInchF) == 0 { fraction_tpi(&f) } else { Some(f.value()) };
        let Some(tpi) = tpi.filter(|t| (3.0..=33.0).contains(t)) else {
            r.diag(&msg::RENHE_TPI_RANGE, f.span, args![word = f]);
            return None;
        };
        25.4 / tpi
    } else {
        let p = f.value();
        if !(0.25..=12.0).contains(&p) {
            r.diag(&msg::RENHE_PITCH_RANGE, f.span, args![word = f]);
            return None;
        }
        p
    };
    r.m.lead = Some(lead);
    Some(lead)
}

/// `F11.2` → 11 + 1/2 (the digits after the point are the denominator);
/// `F11` → 11; a denominator of 0 or 1 is refused.
fn fraction_tpi(f: &Word) -> Option<f64> {
    let v = f.value();
    let whole = v.trunc();
    if f.num.frac_digits == 0 {
        return Some(whole);
    }
    let den = ((v - whole) * 10f64.powi(f.num.frac_digits as i32)).round();
    match den {
        0.0 => Some(whole),
        1.0 => None,
        _ => Some(whole + 1.0 / den),
    }
}

/// E18-03 and the words of a thread block: incremental U and W only.
fn incremental_only(r: &mut Reader, b: &Block, name: &str) -> bool {
    let mut abs = false;
    for l in [b'X', b'Z'] {
        if let Some(w) = b.get(l) {
            r.diag(&msg::E18_03, w.span, args![name, inc = if l == b'X' { 'U' } else { 'W' }, abs = w]);
            abs = true;
        }
    }
    !abs && r.check_words(b, b"UW", name)
}

/// A Renhe G32 (inch, `inch`) or G33 (metric) block.
fn thread_block(r: &mut Reader, b: &Block, inch: bool) {
    let name = if inch { "G32" } else { "G33" };
    let g_span = g_span(b);
    if !incremental_only(r, b, name) {
        r.end_chain();
        return;
    }
    let Some(lead) = lead(r, b, inch) else {
        r.end_chain();
        return;
    };
    let u = b.get(b'U').map_or(0.0, |w| w.value());
    let w = b.get(b'W').map_or(0.0, |w| w.value());
    if !(w.abs() > u.abs() && w.abs() > 4.0) {
        let span = b.get(b'W').or(b.get(b'U')).map_or(g_span, |w| w.span);
        r.diag(&msg::E18_04, span, args![w = w.abs(), u = u.abs()]);
        r.end_chain();
        return;
    }
    let Some((dir, _)) = r.m.last_x_feed else {
        r.diag(&msg::E18_05, g_span, args![name]);
        r.end_chain();
        return;
    };
    spindle_advice(r, lead, g_span);
    let start = r.current(b.span);
    let end = start.offset_r(u / 2.0, w);
    let Some((kind, long)) = classify(start, end) else { return };
    let (to, runout_to) = match tail(r, w, g_span) {
        // The run-out retracts opposite to the last X feed.
        Some((j, k)) => {
            let (c, o) = split_runout(start, end, Axis::Z, -dir * j, k);
            (c, Some(o))
        }
        None => (end, None),
    };
    let seg = Seg { from: start, to, runout_to, kind, long };
    g32::piece(r, Source::Renhe, lead, 0.0, seg, end, b, 60.0);
}

/// The tail (radial J, axial K) of the G30 mode for a thread of length `w`; none
/// (and an alarm) when it is longer than the thread.
fn tail(r: &mut Reader, w: f64, span: Span) -> Option<(f64, f64)> {
    let (j, k) = match r.m.tail {
        Tail::None => return None,
        Tail::Standard => {
            let j = r.s.get(P::RenheRunout);
            (j, j / r.s.get(P::RenheRunoutAngle).to_radians().tan())
        }
        Tail::Spiral { u, w } => (u / 2.0, w),
    };
    if !(j > 0.0 && k > 0.0) {
        return None;
    }
    if k > w.abs() + 1e-9 {
        r.diag(&msg::TAIL_TOO_LONG, span, args![k, w = w.abs()]);
        return None;
    }
    Some((j, k))
}

/// The manual's spindle advice n ≤ 2300/t − 60 (t: pitch in mm).
fn spindle_advice(r: &mut Reader, pitch: f64, span: Span) {
    let Some(s) = r.m.spindle.filter(|s| *s > 0.0 && !r.m.css) else { return };
    let max = 2300.0 / pitch - 60.0;
    if s > max {
        let key = (s.to_bits(), pitch.to_bits());
        if r.m.spindle_warned == Some(key) {
            return;
        }
        r.m.spindle_warned = Some(key);
        r.diag(&msg::SPINDLE_SPEED, span, args![s, max = max.floor(), pitch]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::block::Number;

    fn f(v: f64, frac_digits: u8) -> Word {
        Word {
            letter: b'F',
            num: Number { value: v, has_point: true, int_digits: 2, frac_digits },
            span: Span::default(),
        }
    }

    #[test]
    fn fraction_reading() {
        assert_eq!(fraction_tpi(&f(11.2, 1)), Some(11.5));
        assert_eq!(fraction_tpi(&f(11.0, 1)), Some(11.0));
        assert_eq!(fraction_tpi(&f(11.0, 0)), Some(11.0));
        assert_eq!(fraction_tpi(&f(13.4, 1)), Some(13.25));
        assert_eq!(fraction_tpi(&f(11.1, 1)), None);
        assert_eq!(fraction_tpi(&f(8.16, 2)), Some(8.0625));
    }
}
