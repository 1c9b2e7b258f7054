//! The modal interpreter: blocks → motions and thread cuts.
//!
//! It keeps the controller's modal state (motion group, units, feed and lead
//! registers, run-out J/K, spindle), turns each block into [`Move`]s tagged
//! with the block's line, and hands thread blocks to [`crate::g32`],
//! [`crate::renhe`] and the cycles of [`crate::cycle`].

use crate::block::{Block, BlockKind, Word};
use crate::cycle::{self, CycleState};
use crate::diagnostic::{Code, Diagnostics};
use crate::dialect::Dialect;
use crate::gcode::{self, G, Group};
use crate::group::Grouper;
use crate::motion::{ArcData, Move, MoveKind, Point};
use crate::num::{EPS, fmt};
use crate::renhe::RenheState;
use crate::settings::{P, Settings};
use crate::span::Span;
use crate::thread::Thread;

/// Modal motion (group 01).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// No motion command yet.
    None,
    /// G00.
    Rapid,
    /// G01.
    Linear,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// G32 (GSK/Fanuc).
    Thread,
    /// Renhe G32 inch thread.
    RenheInch,
    /// Renhe G33 metric thread.
    RenheMetric,
    /// G90 turning cycle.
    G90,
    /// G92 threading cycle.
    G92,
    /// G94 facing cycle.
    G94,
    /// A motion-group code that is not drawn.
    NotSimulated(&'static str, bool),
}

impl Motion {
    fn from_g(g: G) -> Motion {
        match g {
            G::Rapid => Motion::Rapid,
            G::Linear => Motion::Linear,
            G::ArcCw => Motion::ArcCw,
            G::ArcCcw => Motion::ArcCcw,
            G::Thread => Motion::Thread,
            G::RenheInch => Motion::RenheInch,
            G::RenheMetric => Motion::RenheMetric,
            G::G90 => Motion::G90,
            G::G92 => Motion::G92,
            G::G94 => Motion::G94,
            G::NotSimulated { what, returns } => Motion::NotSimulated(what, returns),
            _ => Motion::None,
        }
    }

    /// Whether blocks in this mode cut a thread block by block (continuous threads).
    pub fn is_thread_block(self) -> bool {
        matches!(self, Motion::Thread | Motion::RenheInch | Motion::RenheMetric)
    }
}

/// A position with per-axis knowledge: before any absolute word or G50 the
/// machine position is unknown, and nothing is drawn from it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Position {
    /// The point (valid where known).
    pub p: Point,
    /// X is known.
    pub kx: bool,
    /// Z is known.
    pub kz: bool,
}

/// The end point of a block's axis words.
#[derive(Clone, Copy, Debug)]
pub struct Target {
    /// End point.
    pub p: Point,
    /// An X or U word was given.
    pub has_x: bool,
    /// A Z or W word was given.
    pub has_z: bool,
}

/// The interpreter's state while a program is read.
pub struct Interp {
    /// Settings in force.
    pub s: Settings,
    /// Dialect in force.
    pub dialect: Dialect,
    /// Diagnostics so far.
    pub diags: Diagnostics,
    /// Motions so far.
    pub moves: Vec<Move>,
    /// Threads so far.
    pub threads: Vec<Thread>,
    /// Current tool position.
    pub pos: Position,
    /// Modal motion.
    pub motion: Motion,
    /// G20 in force.
    pub inch: bool,
    /// Feed register (non-thread F).
    pub feed: Option<f64>,
    /// Line where the feed register was last set.
    pub feed_line: u32,
    /// Lead register (thread F/I), program units per revolution.
    pub lead: Option<f64>,
    /// On Fanuc, whose single F register serves feed and lead: the line of
    /// the non-thread block whose F the lead register holds.
    pub lead_from_feed: Option<u32>,
    /// GSK G32 modal run-out J and K (cancelled by a non-thread motion block).
    pub jk: (Option<f64>, Option<f64>),
    /// Spindle speed S (rev/min under G97, m/min under G96).
    pub spindle: Option<f64>,
    /// G96 constant surface speed in force.
    pub css: bool,
    /// Block-by-block thread grouping.
    pub grouper: Grouper,
    /// Cycle state (G78/G76 first blocks, G92 continuation).
    pub cycle: CycleState,
    /// Renhe state (G30 mode, last X feed).
    pub renhe: RenheState,
    /// Direction of the last X motion (−1, 0, +1) and its line.
    pub last_x: (f64, u32),
    /// M30/M02 seen.
    pub ended: bool,
    motion_seen: bool,
    reported: u32,
    move_limit: usize,
}

/// The interpreter's state at a block boundary, without its outputs (only
/// their lengths): enough to resume reading from that block.
#[derive(Clone, Debug)]
pub struct Snapshot {
    pos: Position,
    motion: Motion,
    inch: bool,
    feed: Option<f64>,
    feed_line: u32,
    lead: Option<f64>,
    lead_from_feed: Option<u32>,
    jk: (Option<f64>, Option<f64>),
    spindle: Option<f64>,
    css: bool,
    grouper: Grouper,
    cycle: CycleState,
    renhe: RenheState,
    last_x: (f64, u32),
    ended: bool,
    motion_seen: bool,
    reported: u32,
    moves: usize,
    threads: usize,
    diags: (usize, usize, Option<Span>),
}

const REPORTED_START: u32 = 1;
const REPORTED_AFTER_END: u32 = 2;
const REPORTED_MOVE_LIMIT: u32 = 4;
const REPORTED_COMP: u32 = 8;

/// Letters every block may carry besides its command's own words.
const ALWAYS: &[u8] = b"GMSTF";

impl Interp {
    /// A fresh interpreter.
    pub fn new(s: &Settings) -> Interp {
        Self::with_capacity(s, 0)
    }

    /// A fresh interpreter expecting a program of `bytes` bytes.
    pub fn with_capacity(s: &Settings, bytes: usize) -> Interp {
        Interp {
            s: s.clone(),
            dialect: s.dialect(),
            diags: Diagnostics::with_limit(s.int(P::LimitDiagnostics).max(1) as usize),
            // About one motion per 8 bytes of a typical program; capped by the move limit.
            moves: Vec::with_capacity((bytes / 8).min(s.int(P::LimitMoves).max(0) as usize).min(1 << 24)),
            threads: Vec::new(),
            pos: Position::default(),
            motion: Motion::None,
            inch: false,
            feed: None,
            feed_line: 0,
            lead: None,
            lead_from_feed: None,
            jk: (None, None),
            spindle: None,
            css: false,
            grouper: Grouper::default(),
            cycle: CycleState::default(),
            renhe: RenheState::default(),
            last_x: (0.0, 0),
            ended: false,
            motion_seen: false,
            reported: 0,
            move_limit: s.int(P::LimitMoves).max(1) as usize,
        }
    }

    /// How many threads were complete at `snap`.
    pub fn threads_at(snap: &Snapshot) -> usize {
        snap.threads
    }

    /// The state now, to resume from later.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            pos: self.pos,
            motion: self.motion,
            inch: self.inch,
            feed: self.feed,
            feed_line: self.feed_line,
            lead: self.lead,
            lead_from_feed: self.lead_from_feed,
            jk: self.jk,
            spindle: self.spindle,
            css: self.css,
            grouper: self.grouper.clone(),
            cycle: self.cycle.clone(),
            renhe: self.renhe,
            last_x: self.last_x,
            ended: self.ended,
            motion_seen: self.motion_seen,
            reported: self.reported,
            moves: self.moves.len(),
            threads: self.threads.len(),
            diags: (self.diags.len(), self.diags.dropped(), self.diags.first_dropped()),
        }
    }

    /// Goes back to a snapshot taken earlier in the same run: the state is
    /// restored and the outputs cut back to what they were.
    pub fn restore(&mut self, snap: &Snapshot) {
        self.pos = snap.pos;
        self.motion = snap.motion;
        self.inch = snap.inch;
        self.feed = snap.feed;
        self.feed_line = snap.feed_line;
        self.lead = snap.lead;
        self.lead_from_feed = snap.lead_from_feed;
        self.jk = snap.jk;
        self.spindle = snap.spindle;
        self.css = snap.css;
        self.grouper = snap.grouper.clone();
        self.cycle = snap.cycle.clone();
        self.renhe = snap.renhe;
        self.last_x = snap.last_x;
        self.ended = snap.ended;
        self.motion_seen = snap.motion_seen;
        self.reported = snap.reported;
        self.moves.truncate(snap.moves);
        self.threads.truncate(snap.threads);
        self.diags.truncate(snap.diags.0, snap.diags.1, snap.diags.2);
    }

    /// Records a diagnostic.
    pub fn diag(&mut self, code: Code, span: Span, msg: impl Into<String>) {
        self.diags.push(code, span, msg);
    }

    fn once(&mut self, flag: u32) -> bool {
        let first = self.reported & flag == 0;
        self.reported |= flag;
        first
    }

    /// Appends a motion; false when the move limit is reached (an alarm is raised once).
    pub fn emit(
        &mut self,
        kind: MoveKind,
        from: Point,
        to: Point,
        line: u32,
        arc: Option<ArcData>,
        span: Span,
    ) -> bool {
        if self.moves.len() >= self.move_limit {
            if self.once(REPORTED_MOVE_LIMIT) {
                self.diag(
                    Code::MoveLimit,
                    span,
                    format!(
                        "more than {} motions (setting limits.moves): the rest of the program is not drawn",
                        self.move_limit
                    ),
                );
            }
            return false;
        }
        if !(from.is_finite() && to.is_finite()) {
            return false;
        }
        self.moves.push(Move { kind, from, to, line, span, arc });
        true
    }

    /// Whether the move limit stopped the plan.
    pub fn stopped(&self) -> bool {
        self.reported & REPORTED_MOVE_LIMIT != 0
    }

    /// The current position, assuming `start.x`/`start.z` for unknown axes (reported once).
    pub fn current(&mut self, span: Span) -> Point {
        if !(self.pos.kx && self.pos.kz) {
            let mut which = Vec::new();
            if !self.pos.kx {
                self.pos.p.x = self.s.get(P::StartX);
                self.pos.kx = true;
                which.push(format!("X{}", fmt(self.pos.p.x)));
            }
            if !self.pos.kz {
                self.pos.p.z = self.s.get(P::StartZ);
                self.pos.kz = true;
                which.push(format!("Z{}", fmt(self.pos.p.z)));
            }
            if self.once(REPORTED_START) {
                self.diag(
                    Code::StartAssumed,
                    span,
                    format!(
                        "tool position unknown (no absolute X/Z or G50 before this block): start taken as {} (settings start.x, start.z)",
                        which.join(" ")
                    ),
                );
            }
        }
        self.pos.p
    }

    /// Reads a length word in program units, applying the Fanuc decimal-point rule.
    pub fn length(&mut self, w: &Word) -> f64 {
        if self.dialect == Dialect::Fanuc0i && !w.num.has_point && !self.s.flag(P::Fanuc3401_0) {
            let inc = self.s.length_increment(self.inch);
            let v = w.value() * inc;
            let unit = if self.inch { "in" } else { "mm" };
            self.diags.push_with(Code::NoDecimalPoint, w.span, || {
                format!(
                    "{} has no decimal point: with parameter 3401#0 (DPI) = 0 it means {} {unit}, not {} {unit}; write {}{}. if you meant {}",
                    w.display(),
                    fmt(v),
                    fmt(w.value()),
                    w.letter(),
                    fmt(w.value()),
                    fmt(w.value())
                )
            });
            v
        } else {
            w.value()
        }
    }

    /// Reads an X/U word as a diameter (radius programming doubles it).
    pub fn x_len(&mut self, w: &Word) -> f64 {
        let v = self.length(w);
        if self.s.radius_x() { 2.0 * v } else { v }
    }

    /// Whether `X`/`Z` and `U`/`W` conflict in `b`; reports and returns true when they do.
    pub fn axis_conflict(&mut self, b: &Block) -> bool {
        let mut bad = false;
        for (abs, inc) in [(b'X', b'U'), (b'Z', b'W')] {
            if let (Some(a), Some(i)) = (b.get(abs), b.get(inc)) {
                self.diag(
                    Code::AxisConflict,
                    a.span.cover(i.span),
                    format!(
                        "{} and {} in one block: give the axis once, absolute or incremental",
                        a.display(),
                        i.display()
                    ),
                );
                bad = true;
            }
        }
        bad
    }

    /// The end point of the block's X/Z/U/W words from the current position.
    pub fn target(&mut self, b: &Block) -> Target {
        let mut t = Target { p: self.pos.p, has_x: false, has_z: false };
        if let Some(w) = b.get(b'X') {
            t.p.x = self.x_len(w);
            t.has_x = true;
        } else if let Some(w) = b.get(b'U') {
            let d = self.x_len(w);
            if !self.pos.kx {
                self.current(w.span);
            }
            t.p.x = self.pos.p.x + d;
            t.has_x = true;
        }
        if let Some(w) = b.get(b'Z') {
            t.p.z = self.length(w);
            t.has_z = true;
        } else if let Some(w) = b.get(b'W') {
            let d = self.length(w);
            if !self.pos.kz {
                self.current(w.span);
            }
            t.p.z = self.pos.p.z + d;
            t.has_z = true;
        }
        t
    }

    /// Moves the tool to `to` with a motion of `kind` (drawn when the start is known).
    pub fn go(&mut self, kind: MoveKind, t: &Target, line: u32, span: Span) {
        let from = self.pos;
        let to = t.p;
        if from.kx && from.kz && ((to.x - from.p.x).abs() > EPS || (to.z - from.p.z).abs() > EPS) {
            self.emit(kind, from.p, to, line, None, span);
        }
        self.arrive(to, t.has_x || from.kx, t.has_z || from.kz, line);
    }

    /// Sets the position after a motion; tracks the direction of X motion.
    pub fn arrive(&mut self, to: Point, kx: bool, kz: bool, line: u32) {
        if self.pos.kx && kx {
            let dx = to.x - self.pos.p.x;
            if dx.abs() > EPS {
                self.last_x = (dx.signum(), line);
            }
        }
        self.pos = Position { p: to, kx, kz };
    }

    /// Checks that `b` has only words from `allowed` (plus G/M/S/T/F);
    /// reports each other word and returns false if there was one.
    #[inline(always)]
    pub fn check_words(&mut self, b: &Block, allowed: &[u8], what: &str) -> bool {
        // Inlined, the mask of a literal `allowed` folds to a constant.
        let mask = crate::dialect::letters(ALWAYS) | crate::dialect::letters(allowed);
        if b.words.iter().all(|w| mask & (1 << (w.letter - b'A')) != 0) {
            return true;
        }
        self.report_words(b, mask, what)
    }

    #[cold]
    fn report_words(&mut self, b: &Block, mask: u32, what: &str) -> bool {
        let mut ok = true;
        for w in &b.words {
            if mask & (1 << (w.letter - b'A')) == 0 {
                self.diag(Code::UnexpectedWord, w.span, format!("{what} does not take {}", w.display()));
                ok = false;
            }
        }
        ok
    }

    /// Interprets one block.
    pub fn block(&mut self, b: &Block) {
        match b.kind {
            BlockKind::Percent | BlockKind::ProgramNumber(_) => return,
            BlockKind::Normal => {}
        }
        if b.is_empty() {
            return; // blank, comment-only or a bare sequence number: transparent
        }
        if self.ended {
            if self.once(REPORTED_AFTER_END) {
                self.diag(Code::AfterEnd, b.span, "blocks after M30/M02 are never executed");
            }
            return;
        }
        if b.deleted && self.s.flag(P::BlockDelete) {
            return;
        }
        if b.has_error {
            // The controller alarms on this block; the preview goes on from where the tool was.
            self.end_thread_chain();
            return;
        }
        // ---- G codes ----
        // At most one code per modal group: a small array, no allocation per block.
        let mut seen_buf: [Option<(Group, G, &Word)>; 16] = [None; 16];
        let mut n_seen = 0;
        for w in b.all(b'G') {
            let v10 = w.value() * 10.0;
            let code = if v10 >= 0.0 && (v10 - v10.round()).abs() < 1e-9 {
                gcode::lookup(self.dialect, v10.round() as i64)
            } else {
                None
            };
            let Some((group, g)) = code else {
                self.diag(
                    Code::UnsupportedGCode,
                    w.span,
                    format!("{} is not a G code of the {} controller", w.display(), self.dialect.title()),
                );
                self.end_thread_chain();
                return;
            };
            if let Some((_, _, other)) =
                seen_buf[..n_seen].iter().flatten().find(|(gr, _, _)| *gr == group && group != Group::Setup)
            {
                self.diag(
                    Code::ConflictingGCodes,
                    w.span,
                    format!("{} and {} are in the same modal group", other.display(), w.display()),
                );
                self.end_thread_chain();
                return;
            }
            if n_seen < seen_buf.len() {
                seen_buf[n_seen] = Some((group, g, w));
                n_seen += 1;
            }
        }
        let seen = &seen_buf[..n_seen];
        if self.axis_conflict(b) {
            self.end_thread_chain();
            return;
        }
        // ---- modal settings that take effect before motion ----
        let mut motion_g = None;
        let mut one_shot = None;
        for &(group, g, w) in seen.iter().flatten() {
            match g {
                G::Inch | G::Metric => {
                    let inch = g == G::Inch;
                    if inch != self.inch && self.motion_seen {
                        self.diag(
                            Code::UnitsChanged,
                            w.span,
                            "units changed after motion: earlier coordinates stay in the old unit and the drawing mixes them",
                        );
                    }
                    self.inch = inch;
                }
                G::Css => self.css = true,
                G::CssOff => self.css = false,
                G::CompOn => {
                    if self.once(REPORTED_COMP) {
                        self.diag(
                            Code::NotSimulated,
                            w.span,
                            "tool-nose radius compensation (G41/G42) is not simulated: the tool tip point is drawn",
                        );
                    }
                }
                G::RenheRunout => one_shot = Some((g, *w)),
                _ => match group {
                    Group::Motion => motion_g = Some((g, *w)),
                    Group::OneShot => one_shot = Some((g, *w)),
                    Group::Setup => {
                        if let G::NotSimulated { what, .. } = g {
                            self.diag(Code::NotSimulated, w.span, format!("{}: {what} is not simulated", w.display()));
                        }
                    }
                    _ => {}
                },
            }
        }
        if let Some(w) = b.get(b'S') {
            if one_shot.map(|(g, _)| g) != Some(G::SetCoord) {
                self.spindle = Some(w.value());
            }
        }
        // ---- the command ----
        if let Some((g, w)) = motion_g {
            self.motion = Motion::from_g(g);
            if self.motion != Motion::G92 {
                self.cycle.g92 = None;
            }
            if let Motion::NotSimulated(what, _) = self.motion {
                self.diag(Code::NotSimulated, w.span, format!("{}: {what} is not drawn", w.display()));
            }
        }
        let has_axes = b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W');
        let m_end = b.all(b'M').any(|m| matches!(m.num.integer(), Some(2 | 30)));
        for m in b.all(b'M') {
            if let Some(98 | 99) = m.num.integer() {
                self.diag(Code::NotSimulated, m.span, format!("{}: subprogram calls are not followed", m.display()));
            }
        }
        if let Some((g, w)) = one_shot {
            self.end_thread_chain();
            self.one_shot(b, g, w);
        } else if has_axes {
            let thread_block = self.motion.is_thread_block() && has_axes;
            if !thread_block {
                self.end_thread_chain();
            }
            self.motion_block(b, has_axes);
        } else {
            // No motion: F sets the feed register, anything else is setup.
            self.end_thread_chain();
            if let Some(f) = b.get(b'F') {
                let v = self.length(f);
                self.set_feed(v, b.line);
            }
        }
        if m_end {
            self.end_thread_chain();
            self.ended = true;
        }
    }

    fn one_shot(&mut self, b: &Block, g: G, w: Word) {
        match g {
            G::Dwell => {
                self.check_words(b, b"PXU", "G04");
                if !(b.has(b'P') || b.has(b'X') || b.has(b'U')) {
                    self.diag(Code::MissingWord, w.span, "G04 needs the dwell time: P (ms), X or U (s)");
                }
            }
            G::SetCoord => {
                if !self.check_words(b, b"XZUWS", "G50") {
                    return;
                }
                if !(b.has(b'X') || b.has(b'Z') || b.has(b'U') || b.has(b'W') || b.has(b'S')) {
                    self.diag(Code::MissingWord, w.span, "G50 needs X/Z (coordinate system) or S (spindle clamp)");
                    return;
                }
                // G50 X Z: the current position gets these coordinates; U/W shift them.
                if let Some(x) = b.get(b'X') {
                    self.pos.p.x = self.x_len(x);
                    self.pos.kx = true;
                } else if let Some(u) = b.get(b'U') {
                    let d = self.x_len(u);
                    let p = self.current(u.span);
                    self.pos.p.x = p.x + d;
                }
                if let Some(z) = b.get(b'Z') {
                    self.pos.p.z = self.length(z);
                    self.pos.kz = true;
                } else if let Some(wd) = b.get(b'W') {
                    let d = self.length(wd);
                    let p = self.current(wd.span);
                    self.pos.p.z = p.z + d;
                }
            }
            G::RefReturn => {
                if !self.check_words(b, b"XZUW", "G28") {
                    return;
                }
                self.jk = (None, None);
                let t = self.target(b);
                self.go(MoveKind::Rapid, &t, b.line, b.span);
                self.diag(
                    Code::NotSimulated,
                    w.span,
                    "G28: the move to the intermediate point is drawn; the reference point is machine-specific, so the position after it is unknown until the next absolute move",
                );
                if t.has_x {
                    self.pos.kx = false;
                }
                if t.has_z {
                    self.pos.kz = false;
                }
            }
            G::G76 | G::G78 => {
                self.jk = (None, None);
                crate::group::close(self);
                cycle::two_block(self, b, g, w);
            }
            G::RenheRunout => crate::renhe::g30(self, b, w),
            G::NotSimulated { what, returns } => {
                self.diag(Code::NotSimulated, w.span, format!("{}: {what} is not drawn", w.display()));
                if !returns {
                    // Where the tool ends is unknown.
                    self.pos.kx = false;
                    self.pos.kz = false;
                }
            }
            _ => {}
        }
    }

    fn motion_block(&mut self, b: &Block, has_axes: bool) {
        self.motion_seen = true;
        match self.motion {
            Motion::None | Motion::Rapid => {
                if !self.check_words(b, b"XZUW", "G00") {
                    return;
                }
                self.jk = (None, None);
                if let Some(f) = b.get(b'F') {
                    let v = self.length(f);
                    self.set_feed(v, b.line);
                }
                let t = self.target(b);
                let (x0, kx0) = (self.pos.p.x, self.pos.kx);
                self.go(MoveKind::Rapid, &t, b.line, b.span);
                if t.has_x && kx0 {
                    crate::renhe::note_x_feed(self, t.p.x - x0, b.line);
                }
                crate::group::after_rapid(self, &t, b.line);
            }
            Motion::Linear => {
                if !self.check_words(b, b"XZUW", "G01") {
                    return;
                }
                self.jk = (None, None);
                self.feed_word(b);
                let t = self.target(b);
                crate::group::close(self);
                let (x0, kx0) = (self.pos.p.x, self.pos.kx);
                self.go(MoveKind::Feed, &t, b.line, b.span);
                if t.has_x && kx0 {
                    crate::renhe::note_x_feed(self, t.p.x - x0, b.line);
                }
            }
            Motion::ArcCw | Motion::ArcCcw => {
                self.jk = (None, None);
                self.feed_word(b);
                crate::group::close(self);
                self.arc(b, self.motion == Motion::ArcCw);
            }
            Motion::Thread => {
                crate::g32::block(self, b);
            }
            Motion::RenheInch | Motion::RenheMetric => {
                crate::renhe::thread_block(self, b, self.motion == Motion::RenheInch);
            }
            Motion::G90 | Motion::G94 => {
                self.jk = (None, None);
                crate::group::close(self);
                self.feed_word(b);
                cycle::turning(self, b, self.motion == Motion::G94);
            }
            Motion::G92 => {
                self.jk = (None, None);
                cycle::g92::block(self, b, has_axes);
            }
            Motion::NotSimulated(_, returns) => {
                if !returns {
                    self.pos.kx = false;
                    self.pos.kz = false;
                }
            }
        }
    }

    /// Sets the feed register from a non-thread block's F. Fanuc has one F
    /// register: the same value is then the lead a following G32 uses.
    fn set_feed(&mut self, v: f64, line: u32) {
        self.feed = Some(v);
        self.feed_line = line;
        if self.dialect == Dialect::Fanuc0i {
            self.lead = Some(v);
            self.lead_from_feed = Some(line);
        }
    }

    /// F in a feed block sets the feed register; a feed move without any F warns.
    fn feed_word(&mut self, b: &Block) {
        if let Some(f) = b.get(b'F') {
            let v = self.length(f);
            self.set_feed(v, b.line);
        } else if self.feed.is_none() {
            let span = b.all(b'G').next().map_or(b.span, |w| w.span);
            self.diag(Code::MissingFeed, span, "feed move without a feed rate: no F has been given yet");
            self.feed = Some(0.0);
            self.feed_line = b.line;
        }
    }

    fn arc(&mut self, b: &Block, cw: bool) {
        let name = if cw { "G02" } else { "G03" };
        if !self.check_words(b, b"XZUWRIK", name) {
            return;
        }
        let t = self.target(b);
        let start = self.current(b.span);
        let end = t.p;
        // Work in (z, r).
        let (sz, sr, ez, er) = (start.z, start.r(), end.z, end.r());
        let center = if let Some(rw) = b.get(b'R') {
            let r = self.length(rw);
            let rad = r.abs();
            let (dz, dr) = (ez - sz, er - sr);
            let chord = (dz * dz + dr * dr).sqrt();
            if chord < EPS || chord > 2.0 * rad + 1e-7 {
                let msg = if chord < EPS {
                    "an R arc cannot be a full circle: its start and end are the same point".to_string()
                } else {
                    format!("radius {} is shorter than half the chord {}", fmt(rad), fmt(chord / 2.0))
                };
                self.diag(Code::ArcRadiusTooSmall, rw.span, msg);
                return;
            }
            let h = (rad * rad - chord * chord / 4.0).max(0.0).sqrt();
            let (mz, mr) = ((sz + ez) / 2.0, (sr + er) / 2.0);
            // Left normal of the chord (z right, r up is counter-clockwise positive).
            let (nz, nr) = (-dr / chord, dz / chord);
            // CCW minor arc: centre on the left; CW minor arc: on the right; R < 0 takes the major arc.
            let side = if cw { -1.0 } else { 1.0 } * if r < 0.0 { -1.0 } else { 1.0 };
            (mz + side * h * nz, mr + side * h * nr)
        } else if b.has(b'I') || b.has(b'K') {
            // I and K: centre minus start, I as a radius.
            let i = b.get(b'I').copied();
            let k = b.get(b'K').copied();
            let di = i.map_or(0.0, |w| self.length(&w));
            let dk = k.map_or(0.0, |w| self.length(&w));
            let (cz, cr) = (sz + dk, sr + di);
            let r0 = ((sz - cz).powi(2) + (sr - cr).powi(2)).sqrt();
            let r1 = ((ez - cz).powi(2) + (er - cr).powi(2)).sqrt();
            let tol = self.s.get(P::ArcTolerance);
            if (r0 - r1).abs() > tol {
                let span = i.or(k).map_or(b.span, |w| w.span);
                self.diag(
                    Code::ArcRadiusMismatch,
                    span,
                    format!(
                        "the centre is {} from the start but {} from the end (tolerance {}, setting arc.tolerance)",
                        fmt(r0),
                        fmt(r1),
                        fmt(tol)
                    ),
                );
                return;
            }
            (cz, cr)
        } else {
            let span = b.all(b'G').next().map_or(b.span, |w| w.span);
            self.diag(Code::ArcMissingCenter, span, format!("{name} needs R or I/K for its centre"));
            return;
        };
        let arc = ArcData { center: Point::new(center.1 * 2.0, center.0), cw };
        if (end.x - start.x).abs() > EPS || (end.z - start.z).abs() > EPS || b.has(b'I') || b.has(b'K') {
            self.emit(MoveKind::Arc, start, end, b.line, Some(arc), b.span);
        }
        self.arrive(end, true, true, b.line);
    }

    /// Ends the continuous thread being cut block by block, if any.
    pub fn end_thread_chain(&mut self) {
        if let Some(chain) = self.grouper.chain.take() {
            crate::group::add_chain(self, chain);
        }
    }

    /// Finishes the program: closes open threads.
    pub fn finish(&mut self) {
        self.end_thread_chain();
        crate::group::close(self);
    }
}
