//! Reading one block: the modal state, the settings and the controller's
//! unit rules, with the events and diagnostics the block gives. Controller
//! modules and the interpreter read words through a [`Reader`]; none of
//! them sees the plan being built.

use crate::args;
use crate::block::{Block, Word};
use crate::diagnostic::Diagnostics;
use crate::dialect::{Dialect, letters};
use crate::event::Event;
use crate::message::{self as msg, Args, Phrase, Template};
use crate::motion::{Move, MoveKind, Point};
use crate::num::{EPS, fmt};
use crate::settings::{P, Settings};
use crate::span::Span;
use crate::state::{Modal, Position, Target, once};

/// How a controller reads numbers and registers: the data its word helpers need.
#[derive(Debug)]
pub struct Rules {
    /// The dialect.
    pub dialect: Dialect,
    /// Letters that are addresses of this controller (bit 0 = A).
    pub addresses: u32,
    /// A length without a decimal point is in least input increments unless
    /// this parameter (DPI, "calculator input") is set; `None`: always a whole unit.
    pub increments_without_point: Option<P>,
    /// One F register serves feed and thread lead (a feed's F becomes the lead).
    pub shared_f_register: bool,
    /// Letters that are axis words: a block with one of them is a motion block.
    pub axis_words: u32,
    /// Letters any block may carry besides its command's own words (the
    /// controller checks them itself, before the block runs).
    pub free_words: u32,
    /// `$` is the spindle selection word (LinuxCNC).
    pub spindle_word: bool,
    /// The controller's subprograms and macros (`None`: it has none).
    pub macros: Option<super::macros::Macros>,
    /// M codes besides M5 that stop the spindle, before the block's M3/M4
    /// start it again (LinuxCNC's M6 tool change).
    pub spindle_stops: &'static [i64],
    /// G71/G72 rough a contour with pockets (type II) when its first block
    /// moves both axes (Fanuc 0i); `false`: a contour must be monotone both
    /// ways (GSK980TDc, whose manual has type I only).
    pub pockets: bool,
}

impl Rules {
    /// Whether `letter` (uppercase ASCII) is an address of this controller.
    pub fn has_address(&self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.addresses & (1 << (letter - b'A')) != 0
    }

    /// The controller's display title.
    pub fn title(&self) -> &'static str {
        self.dialect.title()
    }
}

/// Letters every block may carry besides its command's own words.
const ALWAYS: &[u8] = b"GMSTF";

/// One block's view of the reading: state to change, settings and rules to
/// read by, events and diagnostics to give.
pub struct Reader<'a> {
    /// The modal state.
    pub m: &'a mut Modal,
    /// Settings in force.
    pub s: &'a Settings,
    /// The controller's unit rules.
    pub rules: &'static Rules,
    /// A length without a decimal point is in least input increments (the rules and settings, read once).
    pub increments: bool,
    /// Events of the block.
    pub events: &'a mut Vec<Event>,
    /// Diagnostics.
    pub diags: &'a mut Diagnostics,
}

impl Rules {
    /// Whether a length without a decimal point is in least input increments under settings `s`.
    pub fn increments(&self, s: &Settings) -> bool {
        self.increments_without_point.is_some_and(|dpi| !s.flag(dpi))
    }
}

impl Reader<'_> {
    /// Records a diagnostic: `template` with `args` at `span`.
    pub fn diag(&mut self, template: &'static Template, span: Span, args: Args) {
        self.diags.push(template, span, args);
    }

    /// Records a finding of a pure step at `span`.
    pub fn finding(&mut self, f: crate::diagnostic::Finding, span: Span) {
        self.diags.push_message(f, span);
    }

    /// Says `template` about G word `w` (what it does: `what`) once per code in a program.
    pub fn noted(&mut self, template: &'static Template, w: &Word, what: &'static Phrase) {
        let code = crate::num::round_i64(w.value() * 10.0);
        if !self.m.noted.contains(&code) {
            self.m.noted.push(code);
            self.diag(template, w.span, args![word = w, what]);
        }
    }

    /// A parameter's value in force (as the program rewrote it, else the setting).
    pub fn param(&self, p: P) -> f64 {
        self.m.param(self.s, p)
    }

    /// The spindle in force (S, G96, the G50 S clamp), for the thread events.
    pub fn spindle(&self) -> crate::thread::Spindle {
        crate::thread::Spindle { s: self.m.spindle, css: self.m.css, clamp: self.m.clamp }
    }

    /// Gives an event.
    pub fn emit(&mut self, e: Event) {
        if matches!(e, Event::Piece(_) | Event::G92(_)) {
            self.m.grouping = true;
        }
        self.events.push(e);
    }

    /// Ends the continuous thread being cut, if any.
    pub fn end_chain(&mut self) {
        if self.m.chain {
            self.m.chain = false;
            self.events.push(Event::Break);
        }
    }

    /// Ends the continuous thread and closes the threads being grouped (when any may be open).
    pub fn close(&mut self) {
        self.end_chain();
        if self.m.grouping {
            self.m.grouping = false;
            self.events.push(Event::Close);
        }
    }

    /// The current position, assuming `start.x`/`start.z` for unknown axes (reported once).
    pub fn current(&mut self, span: Span) -> Point {
        let pos = &mut self.m.pos;
        if !(pos.kx && pos.kz) {
            let mut which = Vec::new();
            if !pos.kx {
                pos.p.x = self.s.get(P::StartX);
                pos.kx = true;
                which.push(format!("X{}", fmt(pos.p.x)));
            }
            if !pos.kz {
                pos.p.z = self.s.get(P::StartZ);
                pos.kz = true;
                which.push(format!("Z{}", fmt(pos.p.z)));
            }
            if self.m.first(once::START) {
                self.diag(&msg::START_ASSUMED, span, args![start = which.join(" ")]);
            }
        }
        self.m.pos.p
    }

    /// Reads a length word in program units, by the controller's decimal-point rule.
    /// Zero is zero in millimetres, inches and increments alike: no warning.
    pub fn length(&mut self, w: &Word) -> f64 {
        if w.num.has_point {
            self.finer(w);
        }
        if !self.increments || w.num.has_point || w.value() == 0.0 {
            return w.value();
        }
        let inch = self.m.inch;
        let v = w.value() * self.s.length_increment(inch);
        self.diags.push_with(&msg::NO_DECIMAL_POINT, w.span, || {
            args![word = w, value = v, unit = msg::unit(inch), written = w.value(), letter = w.letter()]
        });
        v
    }

    /// Notes (once per program) a length written with more decimals than
    /// the least input increment has: the control cannot place the tool
    /// finer. LinuxCNC has no input increment.
    fn finer(&mut self, w: &Word) {
        // Said already, or cannot be finer: nothing to work out (this runs for every length).
        if self.s.dialect() == crate::Dialect::LinuxCnc
            || self.m.said & crate::state::once::FINER != 0
            || w.num.frac_digits <= self.s.length_digits(self.m.inch)
        {
            return;
        }
        let inc = self.s.length_increment(self.m.inch);
        if w.num.frac_digits > 0 && (w.value() / inc).fract().abs() > 1e-6 && self.m.first(crate::state::once::FINER) {
            let inch = self.m.inch;
            self.diags.push_with(&msg::FINER_THAN_INCREMENT, w.span, || {
                args![word = w, increment = inc, unit = msg::unit(inch)]
            });
        }
    }

    /// Reads an X/U word as a diameter (radius programming doubles it).
    pub fn x_len(&mut self, w: &Word) -> f64 {
        let v = self.length(w);
        if self.m.radius { 2.0 * v } else { v }
    }

    /// Whether the block has an axis word of this controller.
    pub fn has_axes(&self, b: &Block) -> bool {
        b.words().iter().any(|w| self.rules.axis_words & (1 << (w.letter - b'A')) != 0)
    }

    /// Whether `X`/`Z` and `U`/`W` conflict in `b`; reports and returns true when they do.
    pub fn axis_conflict(&mut self, b: &Block) -> bool {
        let mut bad = false;
        for (abs, inc) in [(b'X', b'U'), (b'Z', b'W')] {
            if let (Some(a), Some(i)) = (b.get(abs), b.get(inc)) {
                self.diag(&msg::AXIS_CONFLICT, a.span.cover(i.span), args![abs = a, inc = i]);
                bad = true;
            }
        }
        bad
    }

    /// The end point of the block's X/Z/U/W words from the current position.
    pub fn target(&mut self, b: &Block) -> Target {
        let mut t = Target { p: self.m.pos.p, has_x: false, has_z: false };
        let inc = self.m.incremental;
        if let Some(w) = b.get(b'X') {
            let v = self.x_len(w);
            if inc && !self.m.pos.kx {
                self.current(w.span);
            }
            t.p.x = if inc { self.m.pos.p.x + v } else { v };
            t.has_x = true;
        } else if let Some(w) = b.get(b'U') {
            let d = self.x_len(w);
            if !self.m.pos.kx {
                self.current(w.span);
            }
            t.p.x = self.m.pos.p.x + d;
            t.has_x = true;
        }
        if let Some(w) = b.get(b'Z') {
            let v = self.length(w);
            if inc && !self.m.pos.kz {
                self.current(w.span);
            }
            t.p.z = if inc { self.m.pos.p.z + v } else { v };
            t.has_z = true;
        } else if let Some(w) = b.get(b'W') {
            let d = self.length(w);
            if !self.m.pos.kz {
                self.current(w.span);
            }
            t.p.z = self.m.pos.p.z + d;
            t.has_z = true;
        }
        t
    }

    /// The motion to `t` from the current position, when it is known and moves.
    pub fn motion_to(&self, kind: MoveKind, t: &Target, line: u32, span: Span) -> Option<Move> {
        let from = self.m.pos;
        let to = t.p;
        let moves = (to.x - from.p.x).abs() > EPS || (to.z - from.p.z).abs() > EPS;
        (from.kx && from.kz && moves && from.p.is_finite() && to.is_finite()).then_some(Move {
            kind,
            from: from.p,
            to,
            line,
            span,
            arc: None,
        })
    }

    /// Moves the tool to `t` with a motion of `kind`.
    pub fn go(&mut self, kind: MoveKind, t: &Target, line: u32, span: Span) {
        if let Some(mv) = self.motion_to(kind, t, line, span) {
            self.events.push(Event::Motion(mv));
        }
        self.arrive_at(t, line);
    }

    /// A G00 block's rapid to `t`: its motion (if the tool moves) and its
    /// axis words, which tell an infeed from a retract or a return.
    pub fn rapid(&mut self, t: &Target, line: u32, span: Span) {
        let mv = self.motion_to(MoveKind::Rapid, t, line, span);
        self.events.push(Event::Rapid { mv, x: t.has_x, z: t.has_z, line });
        self.arrive_at(t, line);
    }

    fn arrive_at(&mut self, t: &Target, line: u32) {
        let (kx, kz) = (t.has_x || self.m.pos.kx, t.has_z || self.m.pos.kz);
        self.arrive(t.p, kx, kz, line);
    }

    /// Sets the position after a motion; tracks the direction of X motion.
    pub fn arrive(&mut self, to: Point, kx: bool, kz: bool, line: u32) {
        if self.m.pos.kx && kx {
            let dx = to.x - self.m.pos.p.x;
            if dx.abs() > EPS {
                self.m.last_x = (dx.signum(), line);
            }
        }
        self.m.pos = Position { p: to, kx, kz };
    }

    /// Checks that `b` has only words from `allowed` (plus G/M/S/T/F);
    /// reports each other word and returns false if there was one.
    #[inline(always)]
    pub fn check_words(&mut self, b: &Block, allowed: &[u8], what: &str) -> bool {
        // Inlined, the mask of a literal `allowed` folds to a constant.
        let mask = letters(ALWAYS) | letters(allowed) | self.rules.free_words;
        if b.words().iter().all(|w| mask & (1 << (w.letter - b'A')) != 0) {
            return true;
        }
        self.report_words(b, mask, what)
    }

    #[cold]
    fn report_words(&mut self, b: &Block, mask: u32, what: &str) -> bool {
        let mut ok = true;
        for w in b.words() {
            if mask & (1 << (w.letter - b'A')) == 0 {
                match what.strip_suffix(" (first block)") {
                    Some(g) => self.diag(&msg::UNEXPECTED_WORD_FIRST_BLOCK, w.span, args![what = g, word = w]),
                    None => self.diag(&msg::UNEXPECTED_WORD, w.span, args![what, word = w]),
                }
                ok = false;
            }
        }
        ok
    }

    /// Sets the feed register from a non-thread block's F. With one F
    /// register the same value is then the lead a following G32 uses.
    pub fn set_feed(&mut self, v: f64, line: u32) {
        self.m.feed = Some(v);
        self.m.feed_line = line;
        if self.rules.shared_f_register {
            self.m.lead = Some(v);
            self.m.lead_from_feed = Some(line);
        }
    }

    /// Checks `lo ≤ v ≤ hi`, reporting at `w` otherwise.
    pub fn in_range(&mut self, w: &Word, v: f64, lo: f64, hi: f64, what: &'static Phrase) -> bool {
        if v >= lo - EPS && v <= hi + EPS {
            return true;
        }
        self.diag(&msg::VALUE_OUT_OF_RANGE, w.span, args![word = w, what, value = v, lo, hi]);
        false
    }
}

/// Span of the block's first G word, else of the block.
pub fn g_span(b: &Block) -> Span {
    b.all(b'G').next().map_or(b.span, |w| w.span)
}

/// Span of the block's axis words (for alarms about the motion itself).
pub fn axis_span(b: &Block) -> Span {
    let mut span: Option<Span> = None;
    for w in b.words() {
        if matches!(w.letter, b'X' | b'Z' | b'U' | b'W') {
            span = Some(span.map_or(w.span, |s| s.cover(w.span)));
        }
    }
    span.unwrap_or(b.span)
}
