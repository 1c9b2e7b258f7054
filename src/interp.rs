//! The modal interpreter: one block at a time, the controller's modal state
//! ([`Modal`]) changes and the block's events come out.
//!
//! G codes are looked up in the table of the controller in force; the
//! motions every controller shares (G00–G03, G04, G28, G50, G90, G94) are
//! read here, thread and cycle blocks by the controller's own module
//! ([`crate::controller`]). The interpreter never sees the plan being
//! built: grouping passes and planning cycles happen downstream, from the
//! events ([`crate::assemble`]).

use crate::args;
use crate::block::{Block, BlockKind, Word};
use crate::controller::{self, Command, Controller, Reader};
use crate::diagnostic::Diagnostics;
use crate::event::Event;
use crate::gcode::{G, Group};
use crate::geom::arc_centre;
use crate::message::{self as msg, Arg};
use crate::motion::{ArcData, Move, MoveKind, Point};
use crate::num::EPS;
use crate::settings::{P, Settings};
use crate::state::{Modal, Motion, once};

/// The interpreter: the modal state, the settings and the controller.
#[derive(Clone, Debug)]
pub struct Interp {
    /// The modal state.
    pub m: Modal,
    /// Settings in force.
    pub s: Settings,
    /// The controller of the settings' dialect.
    pub ctl: &'static Controller,
    /// A length without a decimal point is in least input increments.
    increments: bool,
}

impl std::fmt::Debug for Controller {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.rules.title())
    }
}

/// A G code of the block, read.
type Seen<'b> = (Group, G, &'b Word);

/// A G code and its word.
type Code1<'b> = Option<(G, &'b Word)>;

impl Interp {
    /// A fresh interpreter.
    pub fn new(s: &Settings) -> Interp {
        let ctl = controller::of(s.dialect());
        let mut m = Modal::default();
        (ctl.init)(&mut m, s);
        Interp { m, s: s.clone(), ctl, increments: ctl.rules.increments(s) }
    }

    /// Reads one block: its events go to `events`, its findings to `diags`.
    pub fn step(&mut self, b: &Block, events: &mut Vec<Event>, diags: &mut Diagnostics) {
        let ctl = self.ctl;
        let mut r =
            Reader { m: &mut self.m, s: &self.s, rules: &ctl.rules, increments: self.increments, events, diags };
        block(&mut r, ctl, b);
    }

    /// Reading is over: the continuous thread and the threads being grouped
    /// end; `checks`: the controller's end-of-program checks run (not after
    /// an error that stopped the interpreter).
    pub fn finish(&mut self, events: &mut Vec<Event>, diags: &mut Diagnostics, checks: bool) {
        let ctl = self.ctl;
        let mut r =
            Reader { m: &mut self.m, s: &self.s, rules: &ctl.rules, increments: self.increments, events, diags };
        r.close();
        if let Some(finish) = ctl.finish.filter(|_| checks) {
            finish(&mut r);
        }
    }
}

/// Interprets one block.
fn block(r: &mut Reader, ctl: &Controller, b: &Block) {
    match b.kind {
        BlockKind::Percent => {
            r.m.percent = true;
            return;
        }
        BlockKind::ProgramNumber(_) | BlockKind::Macro => return,
        BlockKind::Normal => {}
    }
    if b.is_empty() && b.spindle.is_none() {
        return; // blank, comment-only or a bare sequence number: transparent
    }
    r.m.last_span = b.span;
    if r.m.ended {
        if r.m.first(once::AFTER_END) {
            r.diag(&msg::AFTER_END, b.span, args![]);
        }
        return;
    }
    if b.deleted && r.s.flag(P::BlockDelete) {
        return;
    }
    if b.has_error {
        // The controller alarms on this block; the preview goes on from where the tool was.
        r.end_chain();
        return;
    }
    // At most one code per modal group: a small array, no allocation per block.
    let mut seen_buf: [Option<Seen>; 16] = [None; 16];
    let Some(n_seen) = g_codes(r, ctl, b, &mut seen_buf) else {
        r.end_chain();
        return;
    };
    if r.axis_conflict(b) {
        r.end_chain();
        return;
    }
    if let Some(check) = ctl.check {
        let code = seen_buf[..n_seen].iter().flatten().find(|(g, _, _)| *g == Group::Motion).map(|(_, _, w)| code10(w));
        let motion = code.or(if r.has_axes(b) { r.m.motion_code } else { None });
        if !check(r, b, motion) {
            r.end_chain();
            return;
        }
    }
    let (motion_g, one_shot) = modal_codes(r, b, &seen_buf[..n_seen]);
    if let Some(w) = b.get(b'S') {
        if one_shot.map(|(g, _)| g) != Some(G::SetCoord) {
            r.m.spindle = Some(w.value());
        }
    }
    command(r, ctl, b, motion_g, one_shot);
}

/// Reads the block's G codes into `seen`: how many, or `None` after an alarm
/// (a code the controller does not have, two of one modal group).
fn g_codes<'b>(r: &mut Reader, ctl: &Controller, b: &'b Block, seen: &mut [Option<Seen<'b>>; 16]) -> Option<usize> {
    let mut n = 0;
    for w in b.all(b'G') {
        let v10 = w.value() * 10.0;
        let code =
            if v10 >= 0.0 && (v10 - crate::num::round(v10)).abs() < 1e-9 { (ctl.g_code)(code10(w)) } else { None };
        let Some((group, g)) = code else {
            r.diag(&msg::UNSUPPORTED_G_CODE, w.span, args![word = w, controller = Arg::lit(r.rules.title())]);
            return None;
        };
        if let Some((_, _, other)) = seen[..n].iter().flatten().find(|(gr, _, _)| *gr == group && group != Group::Setup)
        {
            r.diag(&msg::CONFLICTING_G_CODES, w.span, args![first = other, second = w]);
            return None;
        }
        if n < seen.len() {
            seen[n] = Some((group, g, w));
            n += 1;
        }
    }
    Some(n)
}

/// A G word's code times ten (G33.1 is 331).
fn code10(w: &Word) -> i64 {
    crate::num::round_i64(w.value() * 10.0)
}

/// Applies the modal settings that take effect before motion (units,
/// surface speed, compensation, distance and X mode, plane); returns the
/// block's motion and one-shot codes.
fn modal_codes<'b>(r: &mut Reader, b: &Block, seen: &[Option<Seen<'b>>]) -> (Code1<'b>, Code1<'b>) {
    let mut motion_g = None;
    let mut one_shot = None;
    for &(group, g, w) in seen.iter().flatten() {
        match g {
            G::Absolute | G::Incremental => r.m.incremental = g == G::Incremental,
            G::DiameterMode | G::RadiusMode => r.m.radius = g == G::RadiusMode,
            G::Plane(p) => r.m.plane = p,
            G::Accepted => {}
            G::CompOff => r.m.comp = None,
            G::Inch | G::Metric => {
                let inch = g == G::Inch;
                if inch != r.m.inch && r.m.motion_seen {
                    r.diag(&msg::UNITS_CHANGED, w.span, args![]);
                }
                r.m.inch = inch;
            }
            G::Css => r.m.css = true,
            G::CssOff => r.m.css = false,
            G::CompOn | G::CompOnDynamic => {
                // G41.1/G42.1 give the tool diameter in D; G41/G42 take it from a tool table screwcut does not have.
                let d = if g == G::CompOnDynamic { b.get(b'D').map_or(0.0, |d| d.value().abs()) } else { 0.0 };
                r.m.comp = Some(d / 2.0);
                if r.m.first(once::COMP) {
                    r.diag(&msg::NOSE_COMP_NOT_SIMULATED, w.span, args![]);
                }
            }
            G::RenheRunout => one_shot = Some((g, w)),
            G::CycleCancel => r.m.drilling = false,
            _ => match group {
                Group::Motion => {
                    r.m.motion_code = Some(code10(w));
                    // A motion code ends a canned cycle for drilling (Fanuc group 10).
                    r.m.drilling = false;
                    motion_g = Some((g, w));
                }
                Group::OneShot => one_shot = Some((g, w)),
                Group::Setup => {
                    if let G::NotSimulated { what, .. } = g {
                        r.noted(&msg::SETUP_NOT_SIMULATED, w, what);
                    }
                }
                Group::Drilling => {
                    if let G::NotSimulated { what, .. } = g {
                        r.m.drilling = true;
                        r.noted(&msg::NOT_DRAWN, w, what);
                    }
                }
                _ => {}
            },
        }
    }
    (motion_g, one_shot)
}

/// The block's command: a one-shot code, a motion in the modal mode, or setup.
fn command(r: &mut Reader, ctl: &Controller, b: &Block, motion_g: Code1, one_shot: Code1) {
    if let Some((g, w)) = motion_g {
        r.m.motion = motion_of(g);
        if r.m.motion != Motion::G92 {
            r.m.cycle.g92 = None;
        }
        if let Motion::NotSimulated(what, _) = r.m.motion {
            r.noted(&msg::NOT_DRAWN, w, what);
        }
    }
    let has_axes = r.has_axes(b);
    let m_end = b.all(b'M').any(|m| matches!(m.num.integer(), Some(2 | 30)));
    if b.all(b'M').any(|m| m.num.integer().is_some_and(|c| r.rules.spindle_stops.contains(&c))) {
        r.m.spindle_on = false;
    }
    for m in b.all(b'M') {
        match m.num.integer() {
            Some(98 | 99) if !r.rules.macros.as_ref().is_some_and(|x| x.subprograms) => {
                r.diag(&msg::SUBPROGRAM_NOT_FOLLOWED, m.span, args![word = m])
            }
            Some(3 | 4) => r.m.spindle_on = true,
            Some(5) => r.m.spindle_on = false,
            _ => {}
        }
    }
    if let Some((g, w)) = one_shot {
        r.end_chain();
        one_shot_block(r, ctl, b, g, w);
    } else if has_axes {
        if !r.m.motion.is_thread_block() {
            r.end_chain();
        }
        motion_block(r, ctl, b);
    } else {
        // No motion: F sets the feed register, anything else is setup.
        r.end_chain();
        if let Some(f) = b.get(b'F') {
            let v = r.length(f);
            r.set_feed(v, b.line);
        }
    }
    if m_end {
        r.end_chain();
        r.m.ended = true;
    }
}

/// The modal motion a motion-group code selects.
fn motion_of(g: G) -> Motion {
    match g {
        G::Rapid => Motion::Rapid,
        G::Linear => Motion::Linear,
        G::ArcCw => Motion::ArcCw,
        G::ArcCcw => Motion::ArcCcw,
        G::Thread => Motion::Thread,
        G::RenheInch => Motion::RenheInch,
        G::RenheMetric => Motion::RenheMetric,
        G::SyncThread => Motion::SyncThread,
        G::ThreadCycle => Motion::ThreadCycle,
        G::G90 => Motion::G90,
        G::G92 => Motion::G92,
        G::G94 => Motion::G94,
        G::NotSimulated { what, returns } => Motion::NotSimulated(what, returns),
        _ => Motion::None,
    }
}

fn one_shot_block(r: &mut Reader, ctl: &Controller, b: &Block, g: G, w: &Word) {
    match g {
        G::Dwell => {
            r.check_words(b, b"PXU", "G04");
            if !(b.has(b'P') || b.has(b'X') || b.has(b'U')) {
                r.diag(&msg::G04_NEEDS_TIME, w.span, args![]);
            }
        }
        G::SetCoord => set_coordinates(r, b, w),
        G::RefReturn => {
            if !r.check_words(b, b"XZUW", "G28") {
                return;
            }
            r.m.jk = (None, None);
            let t = r.target(b);
            r.go(MoveKind::Rapid, &t, b.line, b.span);
            r.diag(&msg::G28_INTERMEDIATE, w.span, args![]);
            r.m.pos.kx &= !t.has_x;
            r.m.pos.kz &= !t.has_z;
        }
        G::RefCheck => {
            // G27: a rapid to the point, where the controller checks the reference position.
            if !r.check_words(b, b"XZUW", "G27") {
                return;
            }
            r.m.jk = (None, None);
            let t = r.target(b);
            r.rapid(&t, b.line, b.span);
        }
        G::Rough(along) => controller::stock::rough(r, b, w, along),
        G::Pattern => controller::stock::pattern(r, b, w),
        G::NotSimulated { what, returns } => {
            r.noted(&msg::NOT_DRAWN, w, what);
            if !returns {
                // Where the tool ends is unknown.
                r.m.pos.kx = false;
                r.m.pos.kz = false;
            }
        }
        _ => (ctl.command)(r, b, Command::OneShot(g, w)),
    }
}

/// G50 X Z: the current position gets these coordinates; U/W shift them. G50 S clamps the spindle.
fn set_coordinates(r: &mut Reader, b: &Block, w: &Word) {
    if !r.check_words(b, b"XZUWS", "G50") {
        return;
    }
    if !(b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W') || b.has(b'S')) {
        r.diag(&msg::G50_NEEDS_WORDS, w.span, args![]);
        return;
    }
    if let Some(x) = b.get(b'X') {
        r.m.pos.p.x = r.x_len(x);
        r.m.pos.kx = true;
    } else if let Some(u) = b.get(b'U') {
        let d = r.x_len(u);
        let p = r.current(u.span);
        r.m.pos.p.x = p.x + d;
    }
    if let Some(z) = b.get(b'Z') {
        r.m.pos.p.z = r.length(z);
        r.m.pos.kz = true;
    } else if let Some(wd) = b.get(b'W') {
        let d = r.length(wd);
        let p = r.current(wd.span);
        r.m.pos.p.z = p.z + d;
    }
    if let Some(s) = b.get(b'S') {
        r.m.clamp = Some(s.value()).filter(|v| v.is_finite() && *v > 0.0);
    }
}

fn motion_block(r: &mut Reader, ctl: &Controller, b: &Block) {
    r.m.motion_seen = true;
    if r.m.drilling {
        // A hole of the canned cycle (noted with its code): where the tool ends is not drawn.
        r.close();
        r.m.pos.kx = false;
        r.m.pos.kz = false;
        return;
    }
    match r.m.motion {
        Motion::None | Motion::Rapid | Motion::Linear => {
            let rapid = matches!(r.m.motion, Motion::None | Motion::Rapid);
            if !r.check_words(b, b"XZUW", if rapid { "G00" } else { "G01" }) {
                return;
            }
            r.m.jk = (None, None);
            if rapid {
                if let Some(f) = b.get(b'F') {
                    let v = r.length(f);
                    r.set_feed(v, b.line);
                }
            } else {
                feed_word(r, b);
            }
            let t = r.target(b);
            if !rapid {
                r.close();
            }
            let (x0, kx0) = (r.m.pos.p.x, r.m.pos.kx);
            if rapid {
                r.rapid(&t, b.line, b.span);
            } else {
                r.go(MoveKind::Feed, &t, b.line, b.span);
            }
            if t.has_x && kx0 && (t.p.x - x0).abs() > 1e-12 {
                r.m.last_x_feed = Some(((t.p.x - x0).signum(), b.line));
            }
        }
        Motion::ArcCw | Motion::ArcCcw => {
            r.m.jk = (None, None);
            feed_word(r, b);
            r.close();
            arc(r, b, r.m.motion == Motion::ArcCw);
        }
        Motion::G90 | Motion::G94 => {
            r.m.jk = (None, None);
            r.close();
            feed_word(r, b);
            turning(r, b, r.m.motion == Motion::G94);
        }
        Motion::Thread
        | Motion::RenheInch
        | Motion::RenheMetric
        | Motion::G92
        | Motion::SyncThread
        | Motion::ThreadCycle => {
            let motion = r.m.motion;
            (ctl.command)(r, b, Command::Motion(motion));
        }
        Motion::NotSimulated(_, returns) => {
            if !returns {
                r.m.pos.kx = false;
                r.m.pos.kz = false;
            }
        }
    }
}

/// F in a feed block sets the feed register; a feed move without any F warns.
fn feed_word(r: &mut Reader, b: &Block) {
    if let Some(f) = b.get(b'F') {
        let v = r.length(f);
        r.set_feed(v, b.line);
    } else if r.m.feed.is_none() {
        let span = b.all(b'G').next().map_or(b.span, |w| w.span);
        r.diag(&msg::MISSING_FEED, span, args![]);
        r.m.feed = Some(0.0);
        r.m.feed_line = b.line;
    }
}

/// G02/G03 by R (radius; negative for the major arc) or I/K (centre minus start, I as a radius).
fn arc(r: &mut Reader, b: &Block, cw: bool) {
    let name = if cw { "G02" } else { "G03" };
    if !r.check_words(b, b"XZUWRIK", name) {
        return;
    }
    let t = r.target(b);
    let start = r.current(b.span);
    let end = t.p;
    let (s, e) = (start.zr(), end.zr());
    let center = if let Some(rw) = b.get(b'R') {
        let rad = r.length(rw);
        match arc_centre(s, e, rad, cw) {
            Some(c) => c,
            None => {
                let chord = s.distance(e);
                if chord < EPS {
                    r.diag(&msg::ARC_FULL_CIRCLE, rw.span, args![]);
                } else {
                    r.diag(&msg::ARC_RADIUS_TOO_SMALL, rw.span, args![radius = rad.abs(), half = chord / 2.0]);
                }
                return;
            }
        }
    } else if b.has(b'I') || b.has(b'K') {
        let i = b.get(b'I').copied();
        let k = b.get(b'K').copied();
        let di = i.map_or(0.0, |w| r.length(&w));
        let dk = k.map_or(0.0, |w| r.length(&w));
        let c = s + glam::DVec2::new(dk, di);
        let (r0, r1) = (s.distance(c), e.distance(c));
        let tol = r.s.get(P::ArcTolerance);
        if (r0 - r1).abs() > tol {
            let span = i.or(k).map_or(b.span, |w| w.span);
            r.diag(&msg::ARC_RADIUS_MISMATCH, span, args![r0, r1, tol]);
            return;
        }
        c
    } else {
        let span = b.all(b'G').next().map_or(b.span, |w| w.span);
        r.diag(&msg::ARC_MISSING_CENTER, span, args![word = name]);
        return;
    };
    let arc = ArcData { center: Point::from_zr(center), cw };
    let moves = (end.x - start.x).abs() > EPS || (end.z - start.z).abs() > EPS || b.has(b'I') || b.has(b'K');
    if moves && start.is_finite() && end.is_finite() {
        r.emit(Event::Motion(Move {
            kind: MoveKind::Arc,
            from: start,
            to: end,
            line: b.line,
            span: b.span,
            arc: Some(arc),
        }));
    }
    r.arrive(end, true, true, b.line);
}

/// G90 (turning) and G94 (facing) single cycles: from the start point A,
/// rapid to the cut's start, feed along the cut (taper R), feed back out,
/// rapid home. Modal: a following block with axis words repeats it.
fn turning(r: &mut Reader, b: &Block, facing: bool) {
    let name = if facing { "G94" } else { "G90" };
    if !r.check_words(b, b"XZUWR", name) {
        return;
    }
    let a = r.current(b.span);
    let t = r.target(b);
    let taper = b.get(b'R').copied().map_or(0.0, |w| r.length(&w));
    let end = t.p;
    let pts: [(MoveKind, Point); 4] = if facing {
        // R: taper along Z, start minus end.
        let p1 = Point::new(a.x, end.z + taper);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(end.x, a.z)), (MoveKind::Rapid, a)]
    } else {
        // R: taper as a radius difference, start minus end.
        let p1 = Point::new(end.x + 2.0 * taper, a.z);
        [(MoveKind::Rapid, p1), (MoveKind::Feed, end), (MoveKind::Feed, Point::new(a.x, end.z)), (MoveKind::Rapid, a)]
    };
    let mut from = a;
    for (kind, to) in pts {
        if from != to && from.is_finite() && to.is_finite() {
            r.emit(Event::Motion(Move { kind, from, to, line: b.line, span: b.span, arc: None }));
        }
        from = to;
    }
    r.arrive(a, true, true, b.line);
}
