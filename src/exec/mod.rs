//! Running a program: which block runs next. Between the lexer and the
//! interpreter, it follows subprogram and macro calls, jumps and loops,
//! keeps the macro variables, evaluates expressions and hands the
//! interpreter plain blocks.
//!
//! A line without macro syntax is read by the lexer alone and passes
//! through untouched; a macro line ([`crate::block::BlockKind::Macro`]) is
//! parsed here ([`stmt`]), and either changes the flow or the variables, or
//! becomes a block of plain words. Calls and jumps move the lexer; where
//! they land is found in the text's [`index::Index`], built once, the first
//! time a program jumps. The state ([`Exec`]) is one cloneable value, so a
//! snapshot of a reading holds the variables and the call stack.
//!
//! Each controller's forms are data ([`Macros`] in its rules): Fanuc custom
//! macro B with `M98`/`M99`, `G65` and `G66` (`fanuc`), GSK's macro A
//! `G65 Hm` (`gsk`), LinuxCNC's o-words (`oword`). The work is bounded: blocks run again by loops, jumps and
//! calls count against `limits.blocks`, and calls nest at most as deep as
//! the controller allows and `limits.call_depth`.

mod ctx;
pub mod eval;
pub mod expr;
mod fanuc;
mod gsk;
pub mod index;
mod oword;
mod profile;
pub mod reads;
pub mod stmt;
pub mod vars;

use crate::args;
use crate::block::{Block, BlockKind, Number, Word};
use crate::diagnostic::Via;
use crate::message as msg;
use crate::motion::Point;
use crate::settings::{P, Settings, T};
use crate::span::{Shift, Span};
use crate::state::Modal;
use eval::{Env, Fail, Val};
use expr::Flavor;
use index::At;
use vars::Vars;

pub use ctx::Ctx;
pub use profile::{Capture, Cycle};

pub use crate::controller::macros::Macros;

/// Most stretches of text read apart that the state keeps (see [`Exec::read`]).
const MAX_STRETCHES: usize = 64;

/// What the reading does with the block just read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flow {
    /// The interpreter reads it (it may have been rewritten into plain words).
    Run,
    /// Nothing more to do: it was a macro statement, a skipped line or a label.
    Skip,
    /// The program has ended here.
    Stop,
    /// The interpreter stopped at an error (LinuxCNC): nothing after it runs, no end-of-program check.
    Abort,
}

/// Why a frame was entered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CallKind {
    /// `M98`: the caller's local variables stay.
    Sub,
    /// `G65`, LinuxCNC `call`: a new level of local variables.
    Macro,
}

/// One active call.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// How it was called.
    pub kind: CallKind,
    /// Where to go back to.
    pub ret: At,
    /// The first line of the called body (for repeats).
    pub body: At,
    /// Runs still to make after this one (`L`).
    pub repeats: u32,
    /// The loops open in this frame.
    pub loops: Vec<Loop>,
    /// The arguments of a macro call, given again to each repeat.
    pub args: Option<Box<[Option<f64>; 33]>>,
    /// The 1-based line of the call.
    pub site: u32,
    /// A G70 running a contour: the sequence number of its last block.
    pub until: Option<u32>,
    /// A G71/G72 reading its contour to rough over it: what it reads.
    pub capture: Option<Box<Capture>>,
    /// A G70 running a contour: its start point and its block's span, where
    /// the tool returns in rapid after the contour.
    pub back_to: Option<(Point, Span)>,
}

/// A modal macro call (`G66`) in force: the macro runs after each block
/// that moves an axis, until `G67`.
#[derive(Clone, Debug, PartialEq)]
pub struct ModalCall {
    /// The macro's program number.
    pub program: u32,
    /// Where its `P` was written.
    pub span: Span,
    /// Runs per call (`L`).
    pub count: u32,
    /// The arguments (argument specification I).
    pub args: Box<[Option<f64>; 33]>,
    /// The macro level it was given at: blocks of the macro itself do not call it again.
    pub level: usize,
}

/// An open loop.
#[derive(Clone, Debug, PartialEq)]
pub struct Loop {
    /// Fanuc's loop number, or LinuxCNC's label.
    pub id: Box<str>,
    /// The loop's first line (WHILE, DO, repeat).
    pub head: At,
    /// Runs left of a LinuxCNC repeat.
    pub left: Option<u64>,
}

/// Where a program is in its flow: variables, calls, loops, counters. A
/// value, cloned into every snapshot.
#[derive(Clone, Debug, PartialEq)]
pub struct Exec {
    /// The variables.
    pub vars: Vars,
    /// Active calls, innermost last.
    pub frames: Vec<Frame>,
    /// Loops open in the main program.
    pub loops: Vec<Loop>,
    /// Blocks run again (loops, jumps, calls), against `limits.blocks`.
    pub repeated: u64,
    /// The stretches of text read so far, `[start, end)` in order and apart:
    /// a block inside one runs again.
    pub read: Vec<(usize, usize)>,
    /// The furthest byte read or looked at so far (a snapshot is valid for
    /// a text whose edit starts after it).
    pub high: usize,
    /// Whether the flow ever left the order of the text.
    pub jumped: bool,
    /// The lines of the active calls, innermost first (`None` in the main program).
    pub via: Via,
    /// The modal macro call in force (`G66`).
    pub modal_call: Option<Box<ModalCall>>,
    /// The main program's first line, once known.
    main: Option<At>,
    /// Runs of the main program made (M99 in the main program).
    main_runs: u32,
    /// Whether the main program's own number has been read.
    main_named: bool,
    /// LinuxCNC: the subroutines defined so far (passed over, or found by a call).
    pub defined: Vec<Box<str>>,
    /// LinuxCNC: repeat loops by label, with the runs left (kept across a return, as rs274 keeps them).
    pub repeats: Vec<Loop>,
    /// LinuxCNC: a break's flag, cleared by the next do/while's condition.
    pub broke: bool,
    /// LinuxCNC: a continue's flag (its loop's label), which makes a break of another loop do nothing.
    pub continued: Option<Box<str>>,
    /// A contour read for a stock-removal cycle, complete: the reading roughs over it next.
    pub captured: Option<Box<Capture>>,
    /// A G70's contour has run: the rapid back to its start point (the
    /// point, the G70 block's line and span), which the reading makes next.
    pub returned: Option<(Point, u32, Span)>,
}

impl Exec {
    /// The state a program starts in.
    pub fn new(settings: &Settings) -> Exec {
        let start = vars::parse_start(settings.text(T::MacroVariables)).unwrap_or_default();
        Exec {
            vars: Vars::new(&start),
            frames: Vec::new(),
            loops: Vec::new(),
            repeated: 0,
            read: Vec::new(),
            high: 0,
            jumped: false,
            via: None,
            modal_call: None,
            main: None,
            main_runs: 0,
            main_named: false,
            defined: Vec::new(),
            repeats: Vec::new(),
            broke: false,
            continued: None,
            captured: None,
            returned: None,
        }
    }

    /// Whether the block `[from, to)` was read before; if not, it is now.
    /// (The furthest byte read is not enough: a call of a subprogram written
    /// after the main program, or a forward jump, reads past blocks that
    /// have yet to run once.)
    fn read_again(&mut self, from: usize, to: usize) -> bool {
        let k = self.read.partition_point(|r| r.0 <= from);
        if k > 0 && from < self.read[k - 1].1 {
            return true;
        }
        if from >= to {
            return false; // the end of the text
        }
        let k = if k > 0 && self.read[k - 1].1 == from {
            self.read[k - 1].1 = to;
            k - 1
        } else {
            self.read.insert(k, (from, to));
            k
        };
        // Reaching the start of the next stretch joins the two.
        if self.read.get(k + 1).is_some_and(|r| r.0 <= to) {
            let next = self.read.remove(k + 1);
            self.read[k].1 = self.read[k].1.max(next.1);
        }
        if self.read.len() > MAX_STRETCHES {
            // Too many gaps (a jump over every few lines): the narrowest is
            // closed (a block in it, read later, counts as run again), so
            // snapshots stay small.
            let k = (1..self.read.len()).min_by_key(|&k| self.read[k].0 - self.read[k - 1].1).unwrap_or(1);
            let r = self.read.remove(k);
            self.read[k - 1].1 = r.1;
        }
        false
    }

    /// Decides what happens to `block`, the line at `ctx.here`: a macro line
    /// is executed or rewritten into plain words; a program number ends the
    /// program being run.
    pub fn before(&mut self, ctx: &mut Ctx, block: &mut Block) -> Flow {
        if self.read_again(ctx.here.offset, ctx.next.offset) {
            self.repeated += 1;
            let limit = ctx.settings.int(P::LimitBlocks).max(1) as u64;
            if self.repeated > limit {
                ctx.diag(&msg::BLOCK_LIMIT, block.span, args![limit, setting = "limits.blocks"]);
                return Flow::Stop;
            }
        }
        self.high = self.high.max(ctx.next.offset);
        let Some(macros) = ctx.rules.macros.as_ref() else { return Flow::Run };
        if self.main.is_none() {
            if let Some(flow) = self.start(ctx, block, macros) {
                return flow;
            }
        }
        match block.kind {
            BlockKind::ProgramNumber(_) if macros.flavor == Flavor::Fanuc => self.program_boundary(ctx, block),
            BlockKind::Macro => self.macro_line(ctx, block, macros),
            _ if macros.flavor == Flavor::Fanuc && macros.macro_calls => fanuc::g65(self, ctx, block, macros),
            _ if macros.h_codes && gsk::is_g65(block) => gsk::plain(self, ctx, block),
            _ => Flow::Run,
        }
    }

    /// Runs a macro line: parsed, then run by the controller's language. A
    /// line that does not parse is an alarm and is not run.
    fn macro_line(&mut self, ctx: &mut Ctx, block: &mut Block, macros: &Macros) -> Flow {
        type Run = fn(&mut Exec, &mut Ctx, &mut Block, &stmt::Line, &Macros) -> Result<Flow, Fail>;
        let Some(line) = parse_line(ctx, block, macros.flavor) else {
            block.has_error = true;
            return Flow::Run;
        };
        if line.deleted && ctx.settings.flag(P::BlockDelete) {
            return Flow::Skip;
        }
        let (run, on_error): (Run, Flow) = match macros.flavor {
            Flavor::Fanuc => (fanuc::statement, Flow::Run),
            // rs274 stops at its first error.
            Flavor::LinuxCnc => (oword::statement, Flow::Abort),
        };
        run(self, ctx, block, &line, macros).unwrap_or_else(|f| {
            ctx.fail(f);
            block.has_error = true;
            on_error
        })
    }

    /// After the interpreter ran `block`: subprogram calls and returns.
    pub fn after(&mut self, ctx: &mut Ctx, block: &Block, ended: bool) -> Flow {
        let Some(macros) = ctx.rules.macros.as_ref() else { return Flow::Run };
        if ended && (!self.frames.is_empty() || macros.flavor == Flavor::LinuxCnc) {
            // M30/M02 in a subprogram ends the program; rs274 reads nothing after it.
            return Flow::Stop;
        }
        if self.modal_call.is_some() && fanuc::g66_call(self, ctx, block, macros) {
            return Flow::Run;
        }
        if macros.flavor == Flavor::LinuxCnc && !block.has_error {
            if let Some(flow) = profile::linux_profile(self, ctx, block, macros) {
                return flow;
            }
        }
        if macros.subprograms && !block.has_error {
            if profile::contour_end(self, ctx, block) {
                return Flow::Run;
            }
            if let Some(flow) = profile::after(self, ctx, block, macros) {
                return flow;
            }
        }
        if macros.subprograms { fanuc::m98_m99(self, ctx, block, macros) } else { Flow::Run }
    }

    /// At the end of the text: a call still open returns (with a warning).
    pub fn at_end(&mut self, ctx: &mut Ctx) -> Flow {
        if self.frames.is_empty() {
            return Flow::Stop;
        }
        let span = Span::new(ctx.text.len(), ctx.text.len());
        ctx.diag(&msg::SUB_RUNS_OFF, span, args![]);
        self.return_from(ctx);
        Flow::Skip
    }

    /// The first block: where the main program starts (`program.main`).
    fn start(&mut self, ctx: &mut Ctx, block: &Block, macros: &Macros) -> Option<Flow> {
        let wanted = ctx.settings.int(P::MainProgram);
        if macros.flavor != Flavor::Fanuc || wanted <= 0 {
            self.main = Some(ctx.here);
            return None;
        }
        let Some(e) = ctx.program(wanted as u32) else {
            ctx.diag(&msg::PROGRAM_NOT_FOUND, block.span, args![n = wanted, setting = "program.main"]);
            return Some(Flow::Stop);
        };
        self.main = Some(e.next);
        self.main_named = true;
        self.go(ctx, e.next);
        Some(Flow::Skip)
    }

    /// A program number after the first: the program being run has ended.
    fn program_boundary(&mut self, ctx: &mut Ctx, block: &Block) -> Flow {
        if !self.main_named && self.frames.is_empty() {
            // The main program's own number (after a `%` or a comment, perhaps).
            self.main_named = true;
            return Flow::Skip;
        }
        if self.main.is_some_and(|m| m.offset < ctx.here.offset) && self.frames.is_empty() {
            // The main program ends where the next program starts.
            return Flow::Stop;
        }
        ctx.diag(&msg::SUB_RUNS_OFF, block.span, args![]);
        self.return_from(ctx);
        Flow::Skip
    }

    /// Goes on at `to`.
    pub fn go(&mut self, ctx: &mut Ctx, to: At) {
        self.jumped = true;
        ctx.jump = Some(to);
    }

    /// The loops open at the current call level.
    pub fn loops(&mut self) -> &mut Vec<Loop> {
        match self.frames.last_mut() {
            Some(f) => &mut f.loops,
            None => &mut self.loops,
        }
    }

    /// Enters a call of `body`, returning to `ctx.next`; false (after an
    /// alarm) when the nesting would be too deep.
    pub fn call(&mut self, ctx: &mut Ctx, kind: CallKind, body: At, repeats: u32, span: Span, macros: &Macros) -> bool {
        let depth = |k: CallKind| self.frames.iter().filter(|f| f.kind == k).count() as u32;
        let (limit, what) = match kind {
            CallKind::Sub => (macros.sub_depth, "M98"),
            CallKind::Macro if macros.flavor == Flavor::LinuxCnc => (macros.macro_depth, "call"),
            CallKind::Macro => (macros.macro_depth, "G65"),
        };
        let ours = ctx.settings.int(P::LimitCallDepth).max(1) as u32;
        let (source, limit) = (limit.setting().unwrap_or(macros.source), limit.get(ctx.settings));
        if depth(kind) >= limit {
            let t = if macros.flavor == Flavor::LinuxCnc { &msg::LCNC_TOO_DEEP } else { &msg::CALL_TOO_DEEP };
            ctx.diag(t, span, args![what, limit, source]);
            return false;
        }
        if self.frames.len() as u32 >= ours {
            ctx.diag(&msg::CALL_TOO_DEEP, span, args![what, limit = ours, source = "limits.call_depth"]);
            return false;
        }
        let site = ctx.here.line;
        self.frames.push(Frame {
            kind,
            ret: ctx.next,
            body,
            repeats,
            loops: Vec::new(),
            args: None,
            site,
            until: None,
            capture: None,
            back_to: None,
        });
        self.set_via();
        if kind == CallKind::Macro {
            self.vars.levels.push(vars::Locals::default());
        }
        self.go(ctx, body);
        true
    }

    /// Leaves the innermost call, back to its caller.
    pub fn return_from(&mut self, ctx: &mut Ctx) -> Option<Frame> {
        let mut f = self.frames.pop()?;
        // A contour or profile read for a cycle is complete: the planner takes it.
        if let Some(c) = f.capture.take() {
            self.captured = Some(c);
        }
        if let Some((p, span)) = f.back_to {
            self.returned = Some((p, f.site, span));
        }
        self.set_via();
        if f.kind == CallKind::Macro && self.vars.levels.len() > 1 {
            self.vars.levels.pop();
        }
        self.go(ctx, f.ret);
        Some(f)
    }

    /// Keeps `via` in step with the frames.
    fn set_via(&mut self) {
        self.via = if self.frames.is_empty() { None } else { Some(self.frames.iter().rev().map(|f| f.site).collect()) };
    }

    /// The state as reached in a text edited as `s` says (the edit kept the
    /// number of lines).
    pub fn shift(&mut self, s: Shift) {
        let at = |a: &mut At| a.offset = s.pos(a.offset);
        self.high = s.pos(self.high);
        for r in &mut self.read {
            *r = (s.pos(r.0), s.pos(r.1));
        }
        for f in &mut self.frames {
            at(&mut f.ret);
            at(&mut f.body);
            if let Some(b) = &mut f.back_to {
                b.1 = s.span(b.1);
            }
            f.loops.iter_mut().for_each(|l| at(&mut l.head));
        }
        self.loops.iter_mut().for_each(|l| at(&mut l.head));
        self.repeats.iter_mut().for_each(|l| at(&mut l.head));
        if let Some(m) = &mut self.main {
            at(m);
        }
        if let Some(m) = &mut self.modal_call {
            m.span = s.span(m.span);
        }
    }
}

/// Reads the variables for an expression.
pub struct Vals<'a> {
    /// The variables.
    pub vars: &'a Vars,
    /// The modal state.
    pub modal: &'a Modal,
    /// The language.
    pub flavor: Flavor,
    /// The controller's title (for messages).
    pub title: &'static str,
}

impl Env for Vals<'_> {
    fn get(&mut self, n: i64, span: Span) -> Result<Val, Fail> {
        match self.flavor {
            Flavor::Fanuc => fanuc::read(self, n, span),
            Flavor::LinuxCnc => oword::read(self, n, span),
        }
    }

    fn named(&mut self, name: &str, span: Span) -> Result<Val, Fail> {
        oword::named(self, name, span)
    }

    fn exists(&mut self, name: &str) -> bool {
        self.vars.named(name).is_some()
    }

    fn increment(&self) -> f64 {
        if self.modal.inch { 0.0001 } else { 0.001 }
    }

    fn flavor(&self) -> Flavor {
        self.flavor
    }
}

/// Evaluates `e` against the current variables.
pub fn eval(ex: &Exec, ctx: &Ctx, e: &expr::Expr) -> Result<Val, Fail> {
    let flavor = ctx.rules.macros.as_ref().map_or(Flavor::Fanuc, |m| m.flavor);
    let mut env = Vals { vars: &ex.vars, modal: ctx.modal, flavor, title: ctx.rules.title() };
    eval::eval(e, &mut env)
}

/// Fills `block` with the words of a macro line, their values evaluated;
/// false after an alarm. A vacant value drops its word (Fanuc).
pub fn fill(ex: &Exec, ctx: &mut Ctx, block: &mut Block, line: &stmt::Line, words: &[stmt::MWord]) -> bool {
    block.clear_words();
    block.deleted = line.deleted;
    block.n = line.n;
    block.kind = BlockKind::Normal;
    let lengths = b"XYZUVWIJKRFECABH";
    for w in words {
        let num = match &w.value {
            stmt::Value::Num(n) => *n,
            stmt::Value::Expr(e) => match eval(ex, ctx, e) {
                Ok(None) => continue,
                Ok(Some(v)) => {
                    // Fanuc rounds a variable at an address to the least input increment; rs274 does not.
                    let inc = if ctx.modal.inch { 1e4 } else { 1e3 };
                    let length = lengths.contains(&w.letter);
                    let fanuc = ctx.rules.macros.as_ref().is_some_and(|m| m.flavor == Flavor::Fanuc);
                    let value = if length && fanuc { (v * inc).round() / inc } else { v };
                    number(value, length)
                }
                Err(f) => {
                    ctx.fail(f);
                    return false;
                }
            },
        };
        let word = Word { letter: w.letter, num, span: w.span };
        if w.letter == b'N' {
            block.n = Some(word);
            continue;
        }
        if let Some(first) = block.push(word) {
            if w.letter != b'G' && w.letter != b'M' {
                ctx.diag(&msg::REPEATED_ADDRESS, w.span, args![letter = w.letter as char, first, second = word]);
                return false;
            }
        }
    }
    true
}

/// A computed value as a number: a length always reads as if written with
/// a decimal point (in mm or inch), any other address as a whole number
/// when it is one.
fn number(value: f64, length: bool) -> Number {
    let value = if value == 0.0 { 0.0 } else { value };
    let has_point = length || value.fract() != 0.0;
    let int = value.abs().trunc();
    let int_digits = if int < 1.0 { 1 } else { (int.log10().floor() as u8).saturating_add(1) };
    Number { value, has_point, int_digits, frac_digits: if has_point { 4 } else { 0 } }
}

/// The text of a line for the macro parser.
pub fn source_of(ctx: &Ctx, span: Span) -> expr::Src {
    stmt::source(ctx.text, span)
}

/// Parses the macro line `block`; `None` after an alarm.
pub fn parse_line(ctx: &mut Ctx, block: &Block, flavor: Flavor) -> Option<stmt::Line> {
    let src = source_of(ctx, block.span);
    let rules = ctx.rules;
    match stmt::parse(&src, flavor, &|c| rules.has_address(c)) {
        Ok(l) => Some(l),
        Err(e) => {
            ctx.diag(&msg::MACRO_SYNTAX, e.span, e.args());
            None
        }
    }
}

/// The truth of a condition: not vacant and not zero.
pub fn truth(v: Val) -> bool {
    v.is_some_and(|v| v != 0.0)
}
