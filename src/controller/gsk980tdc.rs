//! GSK980TDc: G32 with J/K run-out and Q start angle, G92 with J/K and L
//! starts, G76, and its own G78 enhanced threading cycle (reference §3,
//! seed 002). Lengths are whole units with or without a decimal point; the
//! state parameter NO182.7 sets the unit of Q and of the cycle depths.
//!
//! `G78 P(m)(r)(a) Q(Δdmin) R(d) J K D L E;`
//! `G78 X(U) Z(W) R(i) P(k) Q(Δd) F(I);`

use super::macros::{Depth, Flavor, Macros};
use super::words::{self, Unit};
use super::{Command, Controller, Reader, Rules, ThreadRules, ThreadWords, Writing, g32, g76, g92, lathe_g_code};
use crate::args;
use crate::block::{Block, Word};
use crate::cycle::{Anchor, Geometry, Multi, runout, schedule};
use crate::dialect::{Dialect, letters};
use crate::event::Event;
use crate::form::Form;
use crate::gcode::{G, Group};
use crate::message::{self as msg};
use crate::settings::P;
use crate::state::{G78First, Motion};
use crate::thread::{Infeed, Source};

/// The GSK980TDc.
pub static CONTROLLER: Controller = Controller {
    rules: Rules {
        dialect: Dialect::Gsk980tdc,
        // No B, V, Y on a two-axis lathe.
        addresses: letters(b"ACDEFGHIJKLMNOPQRSTUWXZ"),
        increments_without_point: None,
        shared_f_register: false,
        axis_words: letters(b"XZUW"),
        free_words: 0,
        spindle_word: false,
        // M98/M99 and macro A: G65 Hm P#i Q#j R#k (GSK980TDi user manual,
        // G commands, macro command list); #i at addresses. Subprograms
        // nest four deep.
        macros: Some(Macros {
            flavor: Flavor::Fanuc,
            subprograms: true,
            macro_calls: false,
            sub_depth: Depth::Setting(P::GskSubNesting),
            macro_depth: Depth::Fixed(4),
            max_loop: 3,
            h_codes: true,
            source: "GSK980TDc",
        }),
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
        units: Some(("G20", "G21")),
        motion: ["G00", "G01", "G02", "G03"],
        points: false,
        spindle_on: None,
        thread: ThreadWords::G32 { runout: true },
        start_angle: true,
        forms: &[Form::G32, Form::G92, Form::G76, Form::G78],
    },
    tool_angle: Some(P::No058),
};

/// How the shared thread readers read GSK programs.
static THREADS: ThreadRules = ThreadRules {
    g32_words: b"XZUWIJKQ",
    tpi_word: true,
    g32_runout: true,
    angle: Unit::ByParameter(P::No182_7),
    depth: Unit::ByParameter(P::No182_7),
    g92: g92::Form::RunoutAndStarts { words: b"XZUWRIJKL", runout: P::No019 },
    g76: g76::Form {
        words: b"XZUWRPQFI",
        m: P::No057,
        r: P::No019,
        a: P::No058,
        dmin: P::No059,
        d: P::No060,
        angles: None,
        chamfer_angle: None,
        m_min: 0,
        rewrites_depths: false,
    },
};

fn g_code(code10: i64) -> Option<(Group, G)> {
    match code10 {
        330 => Some((Group::Motion, G::NotSimulated { what: &msg::NS_G33_TAPPING, returns: true })),
        780 => Some((Group::OneShot, G::G78)),
        _ => lathe_g_code(code10),
    }
}

fn command(r: &mut Reader, b: &Block, c: Command) {
    let angle = CONTROLLER.tool_angle(r);
    match c {
        Command::Motion(Motion::Thread) => g32::block(r, &THREADS, b, angle),
        Command::Motion(Motion::G92) => g92::block(r, &THREADS, b, angle),
        Command::OneShot(G::G76, w) => g76::block(r, &THREADS, b, w),
        Command::OneShot(G::G78, w) => g78(r, b, w),
        _ => {}
    }
}

/// A G78 block: the first (no axis words) stores its words, the second plans the thread.
fn g78(r: &mut Reader, b: &Block, g: &Word) {
    r.m.jk = (None, None);
    r.close();
    if b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W') {
        g78_second(r, b, g);
    } else {
        g78_first(r, b);
    }
}

/// Reads `P(m)(r)(a)` right to left: the last two digits are a, the next r,
/// the next m. Digits not written take their parameter, or 0 with the
/// setting `g78.missing_p_digits = zero`.
fn pmra(r: &mut Reader, w: &Word, f: &mut G78First) -> bool {
    if w.num.has_point || w.value() < 0.0 {
        r.diag(&msg::G78_P_POINT, w.span, args![word = w]);
        return false;
    }
    let digits = w.num.int_digits as u32;
    if digits > 4 {
        r.diag(&msg::G78_P_DIGITS, w.span, args![word = w]);
        return false;
    }
    let v = w.value() as u32;
    let zero = r.s.int(P::G78MissingDigits) == 1;
    let digit = |written: bool, value: u32| if written { Some(value) } else { zero.then_some(0) };
    f.a = Some(v % 100);
    f.r = digit(digits >= 3, (v / 100) % 10);
    f.m = digit(digits >= 4, (v / 1000) % 10);
    if let Some(m) = f.m.filter(|m| *m > 1) {
        r.diag(&msg::G78_DEPTH_MODE, w.span, args![word = w, m]);
        return false;
    }
    if let Some(rr) = f.r.filter(|r| *r > 3) {
        r.diag(&msg::G78_INFEED_MODE, w.span, args![word = w, r = rr]);
        return false;
    }
    true
}

/// The first block: stores its words for the following second blocks.
fn g78_first(r: &mut Reader, b: &Block) {
    if !r.check_words(b, b"PQRJKDLE", "G78 (first block)") {
        return;
    }
    let mut f = G78First { line: b.line, ..G78First::default() };
    if let Some(w) = b.get(b'P').copied() {
        if !pmra(r, &w, &mut f) {
            return;
        }
    }
    if !words::min_cut_and_allowance(r, &THREADS, b, &mut f.dmin, &mut f.d) {
        return;
    }
    f.j = b.get(b'J').map(|w| w.value().abs());
    f.k = b.get(b'K').map(|w| w.value().abs());
    if let Some(w) = b.get(b'D').copied() {
        if !r.in_range(&w, w.value(), 0.0, 99.0, &msg::FINISH_COUNT_D) || w.num.integer().is_none() {
            return;
        }
        f.count = Some(w.value() as u32);
    }
    if let Some(w) = b.get(b'L').copied() {
        if !r.in_range(&w, w.value(), 1.0, 99.0, &msg::STARTS_L) || w.num.integer().is_none() {
            return;
        }
        f.starts = Some(w.value() as u32);
    }
    if let Some(w) = b.get(b'E').copied() {
        if !r.in_range(&w, w.value(), -9999.9999, 9999.9999, &msg::SCREW_IN_E) {
            return;
        }
        f.e = Some(w.value().abs());
    }
    r.m.cycle.g78 = Some(f);
}

/// The second block: plans the cycle from A (the tool position) to X/Z.
fn g78_second(r: &mut Reader, b: &Block, g: &Word) {
    if !r.check_words(b, b"XZUWRPQFI", "G78") {
        return;
    }
    let Some((lead, k, dd)) = words::height_and_first_depth(r, &THREADS, b, g, "G78") else { return };
    let i = match b.get(b'R').copied() {
        Some(w) => {
            let v = r.length(&w);
            if !r.in_range(&w, v, -99999.999, 99999.999, &msg::TAPER_R) {
                return;
            }
            v
        }
        None => 0.0,
    };
    // The first block: stored values, J/K used once.
    let f = r.m.cycle.g78.clone().unwrap_or_default();
    if let Some(stored) = r.m.cycle.g78.as_mut() {
        stored.j = None;
        stored.k = None;
    }
    let m = f.m.unwrap_or(r.param(P::No061) as u32);
    let infeed_mode = f.r.unwrap_or(r.param(P::No062) as u32);
    let a = f.a.unwrap_or(r.param(P::No058) as u32) as f64;
    let inc = r.s.length_increment(r.m.inch);
    let dmin = f.dmin.unwrap_or(r.param(P::No059) * inc);
    let d = f.d.unwrap_or(r.param(P::No060) * inc);
    let count = f.count.unwrap_or(r.s.int(P::G78DefaultD) as u32);
    let start = r.current(b.span);
    let target = r.target(b);
    let mut geom = match Geometry::new(start, target.p, i, "G78") {
        Ok(geom) => geom,
        Err(f) => return r.finding(f, g.span),
    };
    geom.runout = runout::gsk(f.j, f.k, r.param(P::No019), lead);
    geom.screw_in = f.e.filter(|e| *e > 0.0).map(|e| (e, r.s.get(P::ScrewInLeads) * lead));
    let infeed = match infeed_mode {
        0 => Infeed::Radial,
        1 => Infeed::Left,
        2 => Infeed::Right,
        _ => Infeed::Alternating,
    };
    let mode = if m == 0 { schedule::DepthMode::Equal } else { schedule::DepthMode::Degressive };
    let mut lines = Vec::new();
    if f.line != 0 {
        lines.push(f.line);
    }
    lines.push(b.line);
    let multi = Multi {
        source: Source::G78,
        lines,
        span: g.span,
        geom,
        lead,
        starts: f.starts.unwrap_or(1),
        schedule: schedule::Spec {
            k,
            first: dd,
            min: dmin,
            allowance: d,
            mode,
            finish: count,
            dmin_rule: words::dmin_rule(r),
            finish_rule: words::finish_rule(r),
        },
        infeed,
        angle: a,
        // `flank.r1_side` places G78's "left" flank.
        left_side: if r.s.int(P::FlankR1Side) == 1 { 1.0 } else { -1.0 },
        anchor: if r.s.int(P::G78FlankAnchor) == 1 { Anchor::Thread } else { Anchor::Start },
        spindle: r.spindle(),
    };
    r.emit(Event::Multi(Box::new(multi)));
    r.arrive(start, true, true, b.line);
}
