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

use crate::block::{Block, Word};
use crate::diagnostic::Code;
use crate::g32::{classify, split_runout};
use crate::group::{Seg, cut_piece};
use crate::interp::Interp;
use crate::num::fmt;
use crate::settings::P;
use crate::thread::{Axis, Source};

/// The G30 run-out mode.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Tail {
    /// Standard run-out (G30 alone, or no G30).
    #[default]
    Standard,
    /// No run-out (`G30 U0 W0`).
    None,
    /// Spiral tail: retract `u` (diameter) over the last `w` of Z.
    Spiral {
        /// Diameter retract.
        u: f64,
        /// Axial length.
        w: f64,
    },
}

/// Renhe modal state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenheState {
    /// The G30 mode.
    pub tail: Tail,
    /// Direction (−1/+1) and line of the last G00/G01 move in X.
    pub last_x_feed: Option<(f64, u32)>,
    /// Last spindle advice given (S, pitch), to say it once.
    warned: Option<(u64, u64)>,
}

/// Notes a G00/G01 X move (the run-out goes the other way).
pub fn note_x_feed(it: &mut Interp, dx: f64, line: u32) {
    if dx.abs() > 1e-12 {
        it.renhe.last_x_feed = Some((dx.signum(), line));
    }
}

/// G30: sets the run-out mode.
pub fn g30(it: &mut Interp, b: &Block, w: Word) {
    if !it.check_words(b, b"UW", "G30") {
        return;
    }
    let u = b.get(b'U').map(|w| w.value());
    let wv = b.get(b'W').map(|w| w.value());
    it.renhe.tail = match (u, wv) {
        (None, None) => Tail::Standard,
        (Some(u), Some(wv)) if u == 0.0 && wv == 0.0 => Tail::None,
        (Some(u), Some(wv)) => Tail::Spiral { u: u.abs(), w: wv.abs() },
        _ => {
            it.diag(
                Code::MissingWord,
                w.span,
                "G30 takes both U and W (a spiral tail), U0 W0 (no tail) or neither (standard)",
            );
            return;
        }
    };
}

/// Reads the lead of a Renhe thread block in mm: G33 F is the pitch
/// (0.25–12 mm); G32 F is threads per inch (3–33), the digit after the point
/// being the denominator of a fraction (F11.2 = 11½) unless `renhe.inch_f` is
/// `decimal`.
fn lead(it: &mut Interp, b: &Block, inch: bool) -> Option<f64> {
    let name = if inch { "G32" } else { "G33" };
    let Some(f) = b.get(b'F').copied() else {
        if it.lead.is_none() {
            let span = b.all(b'G').next().map_or(b.span, |w| w.span);
            it.diag(
                Code::MissingLead,
                span,
                format!("{name} without F: give the {}", if inch { "threads per inch" } else { "pitch" }),
            );
        }
        return it.lead;
    };
    let lead = if inch {
        let tpi = if it.s.int(P::RenheInchF) == 0 { fraction_tpi(&f) } else { Some(f.value()) };
        let Some(tpi) = tpi.filter(|t| (3.0..=33.0).contains(t)) else {
            it.diag(
                Code::ValueOutOfRange,
                f.span,
                format!(
                    "{}: G32 takes 3..33 threads per inch (F11.2 = 11½; the digit after the point is a denominator)",
                    f.display()
                ),
            );
            return None;
        };
        25.4 / tpi
    } else {
        let p = f.value();
        if !(0.25..=12.0).contains(&p) {
            it.diag(Code::ValueOutOfRange, f.span, format!("{}: G33 takes a pitch of 0.25..12 mm", f.display()));
            return None;
        }
        p
    };
    it.lead = Some(lead);
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

/// A Renhe G32 (inch, `inch`) or G33 (metric) block.
pub fn thread_block(it: &mut Interp, b: &Block, inch: bool) {
    let name = if inch { "G32" } else { "G33" };
    let g_span = b.all(b'G').next().map_or(b.span, |w| w.span);
    let mut abs = false;
    for l in [b'X', b'Z'] {
        if let Some(w) = b.get(l) {
            it.diag(
                Code::E18_03,
                w.span,
                format!(
                    "E18-03: {name} takes incremental dimensions only; write {} instead of {}",
                    if l == b'X' { 'U' } else { 'W' },
                    w.display()
                ),
            );
            abs = true;
        }
    }
    if abs || !it.check_words(b, b"UW", name) {
        it.end_thread_chain();
        return;
    }
    let Some(lead) = lead(it, b, inch) else {
        it.end_thread_chain();
        return;
    };
    let u = b.get(b'U').map_or(0.0, |w| w.value());
    let w = b.get(b'W').map_or(0.0, |w| w.value());
    if !(w.abs() > u.abs() && w.abs() > 4.0) {
        let span = b.get(b'W').or(b.get(b'U')).map_or(g_span, |w| w.span);
        it.diag(
            Code::E18_04,
            span,
            format!("E18-04: the thread length |W| = {} must exceed |U| = {} and 4 mm", fmt(w.abs()), fmt(u.abs())),
        );
        it.end_thread_chain();
        return;
    }
    let Some((dir, _)) = it.renhe.last_x_feed else {
        it.diag(
            Code::E18_05,
            g_span,
            format!("E18-05: {name} needs an X feed (G00 or G01 with U/X) before it to set the run-out direction"),
        );
        it.end_thread_chain();
        return;
    };
    spindle_advice(it, lead, g_span);
    let start = it.current(b.span);
    let end = start.offset_r(u / 2.0, w);
    let Some((kind, long)) = classify(start, end) else { return };
    // The run-out retracts opposite to the last X feed.
    let out = -dir;
    let runout = match it.renhe.tail {
        Tail::None => None,
        Tail::Standard => {
            let j = it.s.get(P::RenheRunout);
            let k = j / it.s.get(P::RenheRunoutAngle).to_radians().tan();
            Some((j, k))
        }
        Tail::Spiral { u, w } => Some((u / 2.0, w)),
    };
    let (cut_end, tail_end) = match runout {
        Some((j, k)) if j > 0.0 && k > 0.0 => {
            if k > w.abs() + 1e-9 {
                it.diag(
                    Code::RunoutTooLong,
                    g_span,
                    format!("the tail is {} long, more than the thread's |W| = {}", fmt(k), fmt(w.abs())),
                );
                (end, None)
            } else {
                let (c, o) = split_runout(start, end, Axis::Z, out * j, k);
                (c, Some(o))
            }
        }
        _ => (end, None),
    };
    let seg = Seg { from: start, to: cut_end, runout_to: tail_end, kind, long };
    cut_piece(it, Source::Renhe, lead, 0.0, seg, end, b.line, b.span);
}

/// The manual's spindle advice n ≤ 2300/t − 60 (t: pitch in mm).
fn spindle_advice(it: &mut Interp, pitch: f64, span: crate::span::Span) {
    let Some(s) = it.spindle.filter(|s| *s > 0.0 && !it.css) else { return };
    let max = 2300.0 / pitch - 60.0;
    if s > max {
        let key = (s.to_bits(), pitch.to_bits());
        if it.renhe.warned == Some(key) {
            return;
        }
        it.renhe.warned = Some(key);
        it.diag(
            Code::SpindleSpeed,
            span,
            format!(
                "S{} is above the advised n ≤ 2300/t − 60 = {} rev/min for a pitch of {} mm: the thread may be damaged",
                fmt(s),
                fmt(max.floor()),
                fmt(pitch)
            ),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::block::Number;
    use crate::span::Span;

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
