//! The plan of a program: diagnostics, motions and threads. This is what the
//! CLI prints and what the wasm binding returns.
//!
//! Reading a program is a pipeline: the lexer gives blocks, the interpreter
//! turns each block into events ([`crate::interp`]), the assembler turns
//! events into motions and threads ([`crate::assemble`]), and the advice
//! step finishes the threads ([`crate::advice`]) and adds the shop-floor
//! figures and checks ([`crate::shop`]).

use serde::Serialize;

use crate::assemble::{Assembler, Mark};
use crate::block::Block;
use crate::cycle::g7x::Who;
use crate::diagnostic::{Code, Diagnostic, Diagnostics, Found, Severity};
use crate::dialect::Dialect;
use crate::event::Event;
use crate::exec::index::{At, Index};
use crate::exec::reads::Reads;
use crate::exec::{Ctx, Cycle, Exec, Flow};
use crate::interp::Interp;
use crate::lexer::{Blocks, LexLimits, Lexer};
use crate::motion::{Move, MoveKind};
use crate::num::ser_round_opt;
use crate::settings::{P, Settings};
use crate::span::{LineIndex, Shift, Span};
use crate::state::{Modal, Motion};
use crate::thread::Thread;

pub use crate::thread::Units;

/// Everything screwcut knows about a program.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plan {
    /// Dialect the program was read as.
    pub dialect: Dialect,
    /// Units in force at the end of the program.
    pub units: Units,
    /// Alarms, warnings and advice, by position.
    pub diagnostics: Vec<Diagnostic>,
    /// Every motion in program order.
    pub moves: Vec<Move>,
    /// Every thread with its passes.
    pub threads: Vec<Thread>,
    /// Threading time of the whole program, seconds: the sum of the
    /// threads' `time_s`; `None` when a thread's time is not known (no S).
    #[serde(serialize_with = "ser_round_opt")]
    pub time_s: Option<f64>,
}

impl Plan {
    /// Whether any diagnostic is an alarm.
    pub fn has_alarm(&self) -> bool {
        self.diagnostics.iter().any(|d| d.severity == Severity::Error)
    }

    /// The diagnostics with `code`.
    pub fn with_code(&self, code: Code) -> impl Iterator<Item = &Diagnostic> {
        self.diagnostics.iter().filter(move |d| d.code == code)
    }

    /// Serialises to JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
    }
}

/// Plans `text` with `settings` (which also carry the dialect).
pub fn plan(text: &str, settings: &Settings) -> Plan {
    plan_from(text, settings, text.len() >= AHEAD_FROM && two_cores())
}

/// Plans `text` with its blocks lexed on a second thread whatever its size
/// (what [`plan`] does natively from 64 KiB on a machine with two cores):
/// the same plan as a reading on one thread. In wasm, [`plan`].
pub fn plan_lexed_ahead(text: &str, settings: &Settings) -> Plan {
    plan_from(text, settings, true)
}

/// The size from which a native plan lexes ahead on a second core (when
/// the machine has one): below it a thread costs more than it saves.
pub const AHEAD_FROM: usize = 64 << 10;

/// Plans `text`, lexing ahead on a second thread (natively) when `ahead`.
fn plan_from(text: &str, settings: &Settings, ahead: bool) -> Plan {
    let mut r = Reading::new(settings, text.len());
    #[cfg(target_arch = "wasm32")]
    let _ = ahead; // one thread in wasm
    let starts = match lexer_for(text, settings, &mut r.diags) {
        #[cfg(not(target_arch = "wasm32"))]
        Some(lexer) if ahead => read_ahead(&mut r, lexer),
        Some(mut lexer) => {
            r.run(&mut lexer, usize::MAX, |_, _, _, _| true);
            lexer.take_line_starts()
        }
        None => Vec::new(),
    };
    finish(text, settings, r.outputs(), starts)
}

/// Whether the machine runs two threads at once (never in wasm, which runs
/// one); asked of the system once (it reads the process's CPU limits).
fn two_cores() -> bool {
    #[cfg(not(target_arch = "wasm32"))]
    {
        static TWO: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        *TWO.get_or_init(|| std::thread::available_parallelism().is_ok_and(|n| n.get() > 1))
    }
    #[cfg(target_arch = "wasm32")]
    {
        false
    }
}

/// Reads the whole program with its blocks lexed ahead on a second thread;
/// the line starts recorded.
#[cfg(not(target_arch = "wasm32"))]
fn read_ahead(r: &mut Reading, lexer: Lexer) -> Vec<u32> {
    let ((), mut lexer) = crate::lexer::ahead::with(lexer, |blocks| {
        r.run(blocks, usize::MAX, |_, _, _, _| true);
    });
    lexer.take_line_starts()
}

/// A program being read: the interpreter, the plan being assembled and
/// the diagnostics.
pub(crate) struct Reading {
    pub it: Interp,
    pub asm: Assembler,
    pub diags: Diagnostics,
    /// The program's flow: variables, calls, loops.
    pub exec: Exec,
    /// The labels of the text being read, built on first use.
    index: Option<Index>,
    events: Vec<Event>,
    /// What the reading depended on since the planner last took it.
    pub reads: Reads,
}

/// Where a reading was at a block boundary: the modal state (a clone) and
/// how far the outputs went.
#[derive(Clone, Debug)]
pub struct Snapshot {
    modal: Modal,
    exec: Exec,
    plan: Mark,
    diags: (usize, usize, Option<Span>),
}

impl Snapshot {
    /// How many threads were complete.
    pub fn threads(&self) -> usize {
        self.plan.threads
    }

    /// How many motions there were.
    pub fn moves(&self) -> usize {
        self.plan.moves
    }

    /// How many diagnostics were kept.
    pub fn diagnostics(&self) -> usize {
        self.diags.0
    }

    /// Whether diagnostics had been dropped over the limit.
    pub fn dropped(&self) -> bool {
        self.diags.1 > 0
    }

    /// The snapshot as reached in a text edited as `s` says, with `moves`,
    /// `threads` and `diags` more motions, threads and diagnostics.
    pub fn shifted(&self, moves: isize, threads: isize, diags: isize, s: Shift) -> Snapshot {
        let mut c = self.clone();
        c.shift(moves, threads, diags, s);
        c
    }

    /// [`Snapshot::shifted`] in place.
    pub fn shift(&mut self, moves: isize, threads: isize, diags: isize, s: Shift) {
        // The one byte position the modal state holds (where an end-of-program finding goes).
        self.modal.last_span = s.span(self.modal.last_span);
        self.exec.shift(s);
        self.plan.shift(moves, threads, s);
        self.diags = (self.diags.0.saturating_add_signed(diags), self.diags.1, self.diags.2.map(|d| s.span(d)));
    }

    /// Whether reading goes on from here exactly as from `other` (the same
    /// modal and grouping state, whatever the outputs before it).
    pub fn same_state(&self, other: &Snapshot) -> bool {
        self.modal == other.modal && self.plan.group == other.plan.group && self.exec == other.exec
    }

    /// Blocks run again so far (counted against `limits.blocks`).
    pub fn repeated(&self) -> u64 {
        self.exec.repeated
    }

    /// The same snapshot with `d` more blocks run again before it (a reading
    /// whose loops ran a different number of times before it joined this one).
    pub fn recounted(mut self, d: i64) -> Snapshot {
        self.exec.repeated = self.exec.repeated.saturating_add_signed(d);
        self
    }

    /// The furthest byte of the text the reading depended on up to here.
    pub fn read_to(&self) -> usize {
        self.exec.high
    }
}

impl Reading {
    /// A reading of a program of about `bytes` bytes.
    pub fn new(settings: &Settings, bytes: usize) -> Reading {
        Reading {
            it: Interp::new(settings),
            asm: Assembler::new(settings, bytes),
            diags: Diagnostics::with_limit(settings.int(P::LimitDiagnostics).max(1) as usize),
            exec: Exec::new(settings),
            index: None,
            events: Vec::new(),
            reads: Reads::default(),
        }
    }

    /// Where the reading is now.
    pub fn snapshot(&self) -> Snapshot {
        let d = &self.diags;
        Snapshot {
            modal: self.it.m.clone(),
            exec: self.exec.clone(),
            plan: self.asm.mark(),
            diags: (d.len(), d.dropped(), d.first_dropped()),
        }
    }

    /// Goes back to a snapshot taken earlier in the same reading.
    pub fn restore(&mut self, snap: &Snapshot) {
        self.it.m = snap.modal.clone();
        self.exec = snap.exec.clone();
        self.asm.restore(&snap.plan);
        self.diags.truncate(snap.diags.0, snap.diags.1, snap.diags.2);
        self.sync_via();
    }

    /// Reads one block.
    pub fn block(&mut self, b: &Block) {
        if self.exec.capturing() {
            return self.capture(b);
        }
        self.it.step(b, &mut self.events, &mut self.diags);
        self.asm.take(&mut self.events, &self.it.s, Units::of(self.it.m.inch), &mut self.diags);
    }

    /// A block of a stock-removal cycle's contour: read, its motions kept,
    /// nothing drawn or said (G70 runs the contour, and says what is wrong
    /// with it, where it does). A LinuxCNC roughing reads its profile's
    /// words as rs274 does.
    fn capture(&mut self, b: &Block) {
        let mut quiet = Diagnostics::with_limit(1);
        self.exec.capture_first(b);
        self.it.step(b, &mut self.events, &mut quiet);
        if self.exec.capturing_words() {
            self.events.clear();
            self.exec.capture_block(b, &self.it.m);
            return;
        }
        for e in self.events.drain(..) {
            match e {
                Event::Rapid { mv: Some(m), .. } | Event::Motion(m) => self.exec.capture_move(&m),
                _ => {}
            }
        }
    }

    /// A contour read for a stock-removal cycle is complete: back to the
    /// modal state at the cycle block, and the roughing passes planned as
    /// motions of that block.
    fn rough(&mut self, c: crate::exec::Capture) {
        let profile_motion = self.it.m.motion;
        self.it.m = (*c.modal).clone();
        self.it.m.rough_call = None;
        self.it.m.pattern_call = None;
        self.it.m.profile_call = None;
        let moves = match &c.cycle {
            Cycle::Rough(r) => self.stock(r, &c),
            Cycle::Pattern(p) => self.pattern(p, &c),
            Cycle::LinuxRough { words, q } => self.linux_cycle(&c, Who::Rough(words), *q, profile_motion),
            Cycle::LinuxFinish { passes, q } => self.linux_cycle(&c, Who::Finish(passes), *q, profile_motion),
        };
        self.events.push(Event::Close);
        for m in moves {
            self.events.push(match m.kind {
                MoveKind::Rapid => Event::Rapid { mv: Some(m), x: true, z: true, line: c.line },
                _ => Event::Motion(m),
            });
        }
        self.asm.take(&mut self.events, &self.it.s, Units::of(self.it.m.inch), &mut self.diags);
    }

    /// G71/G72 over the contour read in `c`: type II (pockets) when the
    /// controller has it and the contour's first block moves both axes,
    /// else type I; a contour its type refuses is an alarm at the cycle block.
    fn stock(&mut self, r: &crate::cycle::rough::Rough, c: &crate::exec::Capture) -> Vec<Move> {
        use crate::cycle::rough::{Along, Unfit, check, passes};
        let type2 = r.pockets && c.first == Some((true, true));
        let (what, cut, across, zero) = match r.along {
            Along::Z => ("G71", 'Z', 'X', "W0"),
            Along::X => ("G72", 'X', 'Z', "U0"),
        };
        let (template, args) = match check(r, &c.points, type2) {
            Ok(()) if type2 => return crate::cycle::pockets::passes(r, c.start, &c.points, c.line, c.span),
            Ok(()) => return passes(r, c.start, &c.points, c.line, c.span),
            Err(Unfit::Back) => (&crate::message::CONTOUR_GOES_BACK, crate::args![what, cut]),
            Err(Unfit::Pockets) if r.pockets => (&crate::message::CONTOUR_TYPE_ONE, crate::args![what, across, zero]),
            Err(Unfit::Pockets) => {
                let controller = self.it.s.dialect().title();
                (&crate::message::CONTOUR_NO_POCKETS, crate::args![what, across, controller])
            }
        };
        self.diags.push(template, c.span, args);
        Vec::new()
    }

    /// G73's passes over the contour read in `c`; too many motions are an alarm at the cycle block.
    fn pattern(&mut self, p: &crate::cycle::pattern::Pattern, c: &crate::exec::Capture) -> Vec<Move> {
        use crate::cycle::pattern::{MAX_MOVES, passes};
        passes(p, c.start, &c.points, c.line, c.span).unwrap_or_else(|moves| {
            let args = crate::args![d = p.d, points = c.points.len(), moves, limit = MAX_MOVES];
            self.diags.push(&crate::message::G73_TOO_MANY_MOVES, c.span, args);
            Vec::new()
        })
    }

    /// LinuxCNC's G70–G72 over the profile of o(`q`) read in `c`: its moves
    /// (what stopped it said at the block). The tool ends at the last move,
    /// in its motion mode; without moves, where the profile does, in the
    /// profile's last mode (rs274 reads the profile's moves as if making them).
    fn linux_cycle(&mut self, c: &crate::exec::Capture, who: Who, q: u32, profile_motion: Motion) -> Vec<Move> {
        let r = match (c.refused, who) {
            (Some((f, span)), _) => {
                self.diags.push_message(f.finding(who, q).0, span);
                crate::cycle::g7x::Roughing::default()
            }
            (None, Who::Rough(w)) => crate::cycle::g7x::plan(w, c.start, &c.steps, c.line, c.span),
            (None, Who::Finish(p)) => crate::cycle::g7x::finish::plan(p, c.start, &c.steps, c.line, c.span),
        };
        if let Some(f) = r.fail {
            let (finding, on_i) = f.finding(who, q);
            let span = match who {
                Who::Rough(w) if on_i => w.i_span,
                _ => c.span,
            };
            self.diags.push_message(finding, span);
        }
        match r.moves.last() {
            Some(m) => {
                self.it.m.pos.p = m.to;
                self.it.m.motion = match (m.kind, m.arc) {
                    (MoveKind::Rapid, _) => Motion::Rapid,
                    (_, Some(a)) if a.cw => Motion::ArcCw,
                    (_, Some(_)) => Motion::ArcCcw,
                    _ => Motion::Linear,
                };
            }
            None => {
                if let Some(s) = c.steps.last() {
                    self.it.m.pos.p = s.to;
                }
                self.it.m.motion = profile_motion;
            }
        }
        r.moves
    }

    /// Reads blocks from `lexer` to the end of the program, calling
    /// `checkpoint(offset, line, due, reading)` before every block but the
    /// first (the byte offset and 1-based line of the block about to be
    /// read; `due` every `every`-th block), then closes what is still open. A checkpoint that answers `false`
    /// stops the reading there, nothing closed (the caller keeps the rest
    /// of an earlier reading); `run` then answers `false`.
    pub fn run<'t>(
        &mut self,
        lexer: &mut impl Blocks<'t>,
        every: usize,
        mut checkpoint: impl FnMut(usize, u32, bool, &mut Reading) -> bool,
    ) -> bool {
        let mut block = Block::default();
        let mut count = 0usize;
        let mut aborted = false;
        loop {
            if count > 0 && !checkpoint(lexer.offset(), lexer.line() + 1, count % every == 0, self) {
                return false;
            }
            let here = At { offset: lexer.offset(), line: lexer.line() + 1 };
            let more = lexer.next_block(&mut block, &mut self.diags);
            let next = At { offset: lexer.offset(), line: lexer.line() + 1 };
            let (flow, jump) = if more {
                self.reads.read(here.offset, next.offset);
                self.flow(lexer.text(), here, next, &mut block)
            } else {
                self.step_flow(lexer.text(), here, next, |ex, ctx| ex.at_end(ctx))
            };
            if let Some(to) = jump {
                lexer.jump(to.offset, to.line);
            }
            count += 1;
            if flow == Flow::Abort {
                aborted = true;
            }
            if matches!(flow, Flow::Stop | Flow::Abort) || self.asm.stopped() {
                break;
            }
        }
        self.it.finish(&mut self.events, &mut self.diags, !aborted);
        self.asm.take(&mut self.events, &self.it.s, Units::of(self.it.m.inch), &mut self.diags);
        true
    }

    /// Runs one block through the program flow and the interpreter; where
    /// to go next when not to the next line.
    fn flow(&mut self, text: &str, here: At, next: At, block: &mut Block) -> (Flow, Option<At>) {
        let (flow, jump) = self.step_flow(text, here, next, |ex, ctx| ex.before(ctx, block));
        if flow != Flow::Run {
            // An o-word `endsub` or `return` may end a profile read for a cycle.
            if let Some(c) = self.exec.captured.take() {
                self.rough(*c);
            }
            return (flow, jump);
        }
        self.block(block);
        if jump.is_some() {
            return (flow, jump);
        }
        let ended = self.it.m.ended;
        let out = self.step_flow(text, here, next, |ex, ctx| ex.after(ctx, block, ended));
        if let Some(c) = self.exec.captured.take() {
            self.rough(*c);
        }
        if let Some((to, line, span)) = self.exec.returned.take() {
            self.back_to_start(to, line, span);
        }
        out
    }

    /// After a G70's contour: the rapid back to its start point, a motion of
    /// the G70 block, when the tool's place is known.
    fn back_to_start(&mut self, to: crate::motion::Point, line: u32, span: Span) {
        let pos = self.it.m.pos;
        if !(pos.kx && pos.kz) {
            return;
        }
        let mv = Move { kind: MoveKind::Rapid, from: pos.p, to, line, span, arc: None };
        self.events.push(Event::Rapid { mv: Some(mv), x: true, z: true, line });
        self.it.m.pos.p = to;
        self.asm.take(&mut self.events, &self.it.s, Units::of(self.it.m.inch), &mut self.diags);
    }

    /// Runs `f` on the program flow with a context for the line at `here`.
    fn step_flow(
        &mut self,
        text: &str,
        here: At,
        next: At,
        f: impl FnOnce(&mut Exec, &mut Ctx) -> Flow,
    ) -> (Flow, Option<At>) {
        let mut ctx = Ctx {
            text,
            index: &mut self.index,
            diags: &mut self.diags,
            modal: &self.it.m,
            settings: &self.it.s,
            rules: &self.it.ctl.rules,
            here,
            next,
            jump: None,
            read_to: 0,
            looked: false,
        };
        let flow = f(&mut self.exec, &mut ctx);
        let (jump, read_to) = (ctx.jump, ctx.read_to);
        self.reads.looked |= ctx.looked;
        self.exec.high = self.exec.high.max(read_to);
        self.sync_via();
        (flow, jump)
    }

    /// What is found from here on is found through the calls active now.
    fn sync_via(&mut self) {
        if self.asm.group.via != self.exec.via || self.diags.via() != &self.exec.via {
            self.asm.group.via = self.exec.via.clone();
            self.diags.set_via(self.exec.via.clone());
        }
    }

    /// The outputs, the reading done.
    pub fn outputs(self) -> Outputs {
        Outputs { diags: self.diags, moves: self.asm.moves, threads: self.asm.threads, inch: self.it.m.inch }
    }
}

/// What a reading produced: the parts of a plan before finishing.
pub(crate) struct Outputs {
    pub diags: Diagnostics,
    pub moves: Vec<Move>,
    pub threads: Vec<Thread>,
    pub inch: bool,
}

/// A lexer over `text`, or `None` (with an alarm in `diags`) when the
/// program is larger than `limits.program_bytes`.
pub(crate) fn lexer_for<'t>(text: &'t str, settings: &Settings, diags: &mut Diagnostics) -> Option<Lexer<'t>> {
    let limit = settings.get(P::LimitProgramBytes) as usize;
    if text.len() > limit {
        diags.push(&crate::message::PROGRAM_TOO_LARGE, Span::new(0, 0), crate::args![bytes = text.len(), limit]);
        return None;
    }
    let limits = LexLimits {
        block_chars: settings.int(P::LimitBlockChars).max(1) as usize,
        digits: settings.int(P::LimitDigits).clamp(1, 17) as usize,
    };
    Some(Lexer::new(text, &crate::controller::of(settings.dialect()).rules, limits))
}

/// Turns the outputs into a plan: depths and advice of the block-by-block
/// threads, the shop-floor figures and checks of every thread, diagnostics
/// positioned and sorted.
pub(crate) fn finish(text: &str, settings: &Settings, out: Outputs, starts: Vec<u32>) -> Plan {
    let advice = |threads: &mut [Thread], moves: &[Move], spans: &dyn Fn(u32) -> Span, room| {
        let mut advice = Diagnostics::with_limit(room);
        (0..threads.len()).for_each(|i| finish_thread(threads, i, moves, settings, text, &mut advice, spans));
        Found::of(advice)
    };
    finish_with(text, settings, out, starts, (Vec::new(), None), advice).0
}

/// Finishes thread `i`: its depths and textbook advice, then its
/// shop-floor figures and checks, in the thread's own units. A function of
/// the thread, the motions before it, the settings and the program text up
/// to it, so a thread finished once stays finished while later text changes.
pub(crate) fn finish_thread(
    threads: &mut [Thread],
    i: usize,
    moves: &[Move],
    settings: &Settings,
    text: &str,
    diags: &mut Diagnostics,
    spans: &dyn Fn(u32) -> Span,
) {
    let lower = i.checked_sub(1).map(|p| threads[p].end_line);
    let stated = crate::advice::Stated::of(&threads[i], lower, text, spans);
    crate::advice::finish_thread(threads, i, moves, settings, stated, diags, spans);
    let inch = threads[i].units.is_inch();
    let ctx = crate::shop::Context { moves, settings, inch, text, spans };
    crate::shop::finish_thread(threads, i, &ctx, diags);
}

/// [`finish`] with the advice step given by the caller: `advice(threads,
/// moves, spans, room)` finishes the threads and gives their diagnostics
/// (found, or borrowed from the caller); a message that is one of
/// `before.0`'s (the last plan's, before the edit `before.1`) keeps its
/// text. Gives the plan and the reading's diagnostics, as in `out`, back.
pub(crate) fn finish_with<'a>(
    text: &str,
    settings: &Settings,
    out: Outputs,
    starts: Vec<u32>,
    before: (Vec<Diagnostic>, Option<crate::diagnostic::TextEdit>),
    advice: impl FnOnce(&mut [Thread], &[Move], &dyn Fn(u32) -> Span, usize) -> Found<'a>,
) -> (Plan, Diagnostics) {
    let Outputs { mut diags, moves, mut threads, inch } = out;
    let index = LineIndex::from_starts(text, starts);
    let spans = |line: u32| {
        let start = index.line_start(line);
        let end = text[start..].find(['\n', '\r']).map_or(text.len(), |e| start + e);
        Span::new(start, end)
    };
    // The advice keeps what the collector has room for (distinct ones: repeats take none).
    let room = diags.room();
    let found = advice(&mut threads, &moves, &spans, room);
    // Across threads: a pass on another helix (recomputed, it is cheap), found after the reading.
    let mut across = Diagnostics::with_limit(room.saturating_sub(found.len()));
    crate::helix::check(&threads, &moves, settings.get(P::GroupMaxInfeed), &spans, &mut across);
    let diagnostics = diags.finish_parts(found, across, text, &index, before);
    let time_s = crate::shop::total_time(&threads);
    let plan = Plan {
        dialect: settings.dialect(),
        units: if inch { Units::Inch } else { Units::Mm },
        diagnostics,
        moves,
        threads,
        time_s,
    };
    (plan, diags)
}

/// Plans `text` with the default settings of `dialect`.
pub fn plan_default(text: &str, dialect: Dialect) -> Plan {
    plan(text, &Settings::new(dialect))
}
