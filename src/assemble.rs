//! Events to plan: the motions of every event in program order, and the
//! threads — block-by-block pieces grouped into passes ([`Grouper`]),
//! cycles planned pass by pass ([`crate::cycle`]). Every pass gets the
//! indices of its motions as they are appended, so nothing downstream has
//! to find them again. Work is bounded: past `limits.moves` motions an
//! alarm is given once and the reading stops.

use std::ops::Range;

use crate::cycle::{self, PassPath};
use crate::diagnostic::Diagnostics;
use crate::event::{Event, G92Pass, Seg};
use crate::group::{Chain, Grouper};
use crate::motion::{Move, MoveKind};
use crate::settings::{P, Settings};
use crate::thread::{Axis, PassMoves, Source, Thread, Units};

/// The plan's motions and threads as events arrive.
#[derive(Clone, Debug)]
pub struct Assembler {
    /// Every motion so far.
    pub moves: Vec<Move>,
    /// Every complete thread so far.
    pub threads: Vec<Thread>,
    /// Grouping of block-by-block passes.
    pub group: Grouper,
    limit: usize,
    stopped: bool,
}

/// Where an assembler was: enough to cut it back to that point.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// The grouping state.
    pub group: Grouper,
    /// Motions then.
    pub moves: usize,
    /// Threads then.
    pub threads: usize,
}

impl Mark {
    /// Makes the mark as reached in a text edited as `s` says, with `moves` more motions and `threads` more threads.
    pub fn shift(&mut self, moves: isize, threads: isize, s: crate::span::Shift) {
        self.group.shift(moves, s);
        self.moves = self.moves.saturating_add_signed(moves);
        self.threads = self.threads.saturating_add_signed(threads);
    }
}

impl Assembler {
    /// An empty plan for a program of about `bytes` bytes.
    pub fn new(s: &Settings, bytes: usize) -> Assembler {
        let limit = s.int(P::LimitMoves).max(1) as usize;
        // About one motion per 8 bytes of a typical program; capped by the move limit.
        let cap = (bytes / 8).min(limit).min(1 << 24);
        let moves = Vec::with_capacity(cap);
        crate::huge::advise(&moves);
        Assembler { moves, threads: Vec::new(), group: Grouper::default(), limit, stopped: false }
    }

    /// Whether the move limit stopped the plan.
    pub fn stopped(&self) -> bool {
        self.stopped
    }

    /// Where the assembler is now.
    pub fn mark(&self) -> Mark {
        Mark { group: self.group.clone(), moves: self.moves.len(), threads: self.threads.len() }
    }

    /// Goes back to `mark` (taken earlier in the same reading, before any stop).
    pub fn restore(&mut self, mark: &Mark) {
        self.group = mark.group.clone();
        self.moves.truncate(mark.moves);
        self.threads.truncate(mark.threads);
        self.stopped = false;
    }

    /// Takes the events of one block (leaving `events` empty); `units` are
    /// those its words were read in, and the units of the threads it cuts.
    pub fn take(&mut self, events: &mut Vec<Event>, s: &Settings, units: Units, diags: &mut Diagnostics) {
        for e in events.drain(..) {
            match e {
                Event::Rapid { mv, x, z, line } => {
                    let at = mv.and_then(|m| self.push(m, diags));
                    self.group.rapid(x, z, line, at);
                }
                Event::Motion(m) => {
                    self.push(m, diags);
                }
                Event::Piece(p) => {
                    let start = self.moves.len();
                    let mv = |kind, from, to| Move { kind, from, to, line: p.line, span: p.span, arc: None };
                    // A G32 chamfer after the cut is a run-out (drawn and timed as one).
                    let runout = self.group.is_runout(&p, s);
                    let kind = if runout { MoveKind::Runout } else { MoveKind::Thread };
                    self.push(mv(kind, p.seg.from, p.seg.to), diags);
                    if let Some(o) = p.seg.runout_to {
                        self.push(mv(MoveKind::Runout, p.seg.to, o), diags);
                    }
                    let end = self.moves.len();
                    self.group.piece(p, start..end, units, runout);
                }
                Event::G92(g) => self.g92(&g, s, units, diags),
                Event::Multi(m) => self.multi(&m, s, units, diags),
                Event::LinuxG76(g) => self.linux_g76(&g, s, units, diags),
                Event::Break => self.group.end_chain(s, &mut self.threads, diags),
                Event::Close => self.group.close(s, &mut self.threads, diags),
            }
        }
    }

    /// Appends a motion: its index, or `None` past the move limit (an alarm, once) or when not finite.
    fn push(&mut self, m: Move, diags: &mut Diagnostics) -> Option<usize> {
        if self.moves.len() >= self.limit {
            if !self.stopped {
                self.stopped = true;
                diags.push(&crate::message::MOVE_LIMIT, m.span, crate::args![limit = self.limit]);
            }
            return None;
        }
        if !(m.from.is_finite() && m.to.is_finite()) {
            return None;
        }
        self.moves.push(m);
        Some(self.moves.len() - 1)
    }

    /// Appends the motions of a cycle pass; their ranges (approach, cut, way back).
    fn push_path(&mut self, path: &PassPath, diags: &mut Diagnostics) -> PassMoves {
        let mut ranges: [Range<usize>; 3] = [0..0, 0..0, 0..0];
        let mut moves = path.moves().iter();
        for (range, &n) in ranges.iter_mut().zip(&path.counts) {
            let start = self.moves.len();
            for m in moves.by_ref().take(n) {
                self.push(*m, diags);
            }
            *range = start..self.moves.len();
        }
        let [approach, cut, retract] = ranges;
        PassMoves { approach, cut, retract }
    }

    /// A G92 block: one pass of each start, grouped like block-by-block passes.
    fn g92(&mut self, g: &G92Pass, s: &Settings, units: Units, diags: &mut Diagnostics) {
        let path = g.geom.path(&g.pts, g.line, g.span);
        for n in 0..g.starts {
            let first_move = self.moves.len();
            let moves = self.push_path(&path, diags);
            let seg =
                Seg { from: g.pts.from, to: g.pts.to, runout_to: g.pts.runout_to, kind: g.geom.kind, long: Axis::Z };
            let chain = Chain {
                source: Source::G92,
                units,
                lead: g.lead,
                segs: vec![seg],
                angle: g.angle + 360.0 * n as f64 / g.starts as f64,
                lines: vec![g.line],
                approach: -g.geom.out,
                span: g.span,
                first_move,
                tool_angle: g.tool_angle,
                moves,
                spindle: g.spindle,
                pending: None,
                via: self.group.via.clone(),
            };
            self.group.add(chain, s, &mut self.threads, diags);
        }
    }

    /// LinuxCNC's G76: planned, its passes' motions appended, its thread added.
    fn linux_g76(&mut self, g: &cycle::linuxcnc::G76, s: &Settings, units: Units, diags: &mut Diagnostics) {
        let limit = s.int(P::LimitPasses).max(1) as usize;
        let warn = s.int(P::LinuxPassWarning).max(1) as usize;
        let planned = match cycle::linuxcnc::plan(g, limit, warn) {
            Ok(p) => p,
            Err(f) => return diags.push_message(f, g.span),
        };
        for f in planned.notes {
            diags.push_message(f, g.span);
        }
        let first_move = self.moves.len();
        let mut moves = Vec::with_capacity(planned.paths.len());
        for path in &planned.paths {
            let m = self.push_path(path, diags);
            if self.stopped {
                break;
            }
            moves.push(m);
        }
        if let Some(end) = planned.end {
            let at = self.push(end, diags);
            if let (Some(i), Some(last)) = (at, moves.last_mut()) {
                last.retract.end = i + 1;
            }
        }
        if let Some(mut t) = planned.thread {
            t.passes.truncate(moves.len());
            for (p, m) in t.passes.iter_mut().zip(moves) {
                p.moves = m;
            }
            t.first_move = first_move;
            t.units = units;
            self.mark_via(&mut t);
            if !t.passes.is_empty() {
                self.threads.push(t);
            }
        }
    }

    /// A multi-pass cycle: planned, its passes' motions appended, its thread added.
    fn multi(&mut self, m: &cycle::Multi, s: &Settings, units: Units, diags: &mut Diagnostics) {
        let (plan, warnings) = match cycle::multi::plan(m, s) {
            Ok(p) => p,
            Err(f) => return diags.push_message(f, m.span),
        };
        for f in warnings {
            diags.push_message(f, m.span);
        }
        let first_move = self.moves.len();
        let mut passes = Vec::with_capacity((plan.per_start() * m.starts as usize).min(self.limit / 3 + 1));
        'starts: for start in 0..m.starts {
            for n in 0..plan.per_start() {
                let (mut pass, path) = plan.pass(start, n);
                pass.moves = self.push_path(&path, diags);
                if self.stopped {
                    break 'starts;
                }
                passes.push(pass);
            }
        }
        if !passes.is_empty() {
            let mut t = plan.thread(passes, first_move);
            t.units = units;
            self.mark_via(&mut t);
            self.threads.push(t);
        }
    }

    /// Sets the calls a cycle was read through on each of its passes.
    fn mark_via(&self, t: &mut Thread) {
        if let Some(via) = &self.group.via {
            t.passes.iter_mut().for_each(|p| p.via = via.to_vec());
        }
    }
}
