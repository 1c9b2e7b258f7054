//! Expansion: a plan written back as a block-by-block program for a
//! controller (`screwcut expand FILE --dialect D --to D2`).
//!
//! Every motion of the plan becomes a block, in order: each pass with its
//! approach, its synchronised cut (screw-in, thread, run-out), its retract
//! and return; the turning moves as G01/G02/G03. How the target writes a
//! synchronised move is data of its controller ([`Writing`]): GSK's `G32` with a
//! `J K` run-out, Fanuc's `G32` with the run-out as a second block, Renhe's
//! incremental `G33` after a `G30` tail, LinuxCNC's `G33 X Z K` with K along
//! the move. Multi-start threads keep their start angles where the target
//! has the word (`Q`); elsewhere each start's passes start lead × angle /
//! 360° further back along the axis (the same helix) and end where they
//! did. Planned again, the program gives the same passes and starts.

use crate::args;
use crate::controller::{self, ThreadWords, Writing};
use crate::cycle::classify;
use crate::dialect::Dialect;
use crate::geom::Frame;
use crate::message::{Arg, Remark, tools};
use crate::motion::{Move, MoveKind, Point};
use crate::num::EPS;
use crate::plan::{Plan, Units};
use crate::thread::{Axis, CrestSource, Thread};

/// A program written for a controller, with what could not be kept.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Expansion {
    /// The program text.
    pub program: String,
    /// What the target could not express as the source did, and other remarks.
    pub notes: Vec<Remark>,
}

/// Writes `plan` as a block-by-block program for `to`.
pub fn expand(plan: &Plan, to: Dialect) -> Expansion {
    let mut w = Writer::new(plan, to);
    w.header(to);
    w.body();
    w.line("M30");
    Expansion { program: w.out, notes: w.notes }
}

/// Which part of a pass a motion is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    Approach,
    Cut,
    Back,
}

/// The Renhe tail mode written last (`G30`).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Tail {
    /// G30 alone or never given: the standard run-out.
    Standard,
    /// `G30 U W`: (diameter retract, axial length); (0, 0) is none.
    Set(f64, f64),
}

/// One synchronised segment of a pass: kind, ends (shifted), advance along it per revolution.
#[derive(Clone, Copy, Debug)]
struct Seg {
    kind: MoveKind,
    from: Point,
    to: Point,
    along: f64,
}

struct Writer<'p> {
    plan: &'p Plan,
    /// The target controller.
    to: Dialect,
    w: &'static Writing,
    out: String,
    notes: Vec<Remark>,
    /// Program units per plan unit (25.4 for an inch plan on a millimetre controller).
    scale: f64,
    at: Option<Point>,
    feed_given: bool,
    tail: Tail,
    /// Direction of the last X move (Renhe's run-out goes the other way).
    last_x: f64,
    owner: Vec<Option<(usize, usize, Part)>>,
    /// The spindle speed last written (rev/min).
    speed: Option<f64>,
    /// The units last written (G20/G21, or the scale of a millimetre-only controller).
    units: Option<Units>,
}

impl<'p> Writer<'p> {
    fn new(plan: &'p Plan, to: Dialect) -> Writer<'p> {
        let w = &controller::of(to).writing;
        let mut owner = vec![None; plan.moves.len()];
        for (ti, t) in plan.threads.iter().enumerate() {
            for (pi, p) in t.passes.iter().enumerate() {
                let m = &p.moves;
                for (r, part) in [(&m.approach, Part::Approach), (&m.cut, Part::Cut), (&m.retract, Part::Back)] {
                    let n = owner.len();
                    for slot in &mut owner[r.start.min(n)..r.end.min(n)] {
                        *slot = Some((ti, pi, part));
                    }
                }
            }
        }
        Writer {
            plan,
            to,
            w,
            out: String::new(),
            notes: Vec::new(),
            scale: 1.0,
            at: None,
            feed_given: false,
            tail: Tail::Standard,
            last_x: 0.0,
            owner,
            speed: None,
            units: None,
        }
    }

    fn line(&mut self, s: impl AsRef<str>) {
        self.out.push_str(s.as_ref());
        self.out.push('\n');
    }

    /// Says `r` once (a remark repeated by every thread or pass is kept once).
    fn note(&mut self, r: Remark) {
        if !self.notes.contains(&r) {
            self.notes.push(r);
        }
    }

    /// A length as the target reads it.
    fn len(&self, v: f64) -> String {
        self.w.length(v * self.scale)
    }

    /// A point rounded as [`Writer::len`] writes it.
    fn snap(&self, p: Point) -> Point {
        let r = |v: f64| (v * self.scale * 1e4).round() / 1e4 / self.scale;
        Point::new(r(p.x), r(p.z))
    }

    /// A lead or pitch (six decimals).
    fn lead(&self, v: f64) -> String {
        self.w.lead(v * self.scale)
    }

    fn header(&mut self, to: Dialect) {
        let from = self.plan.dialect.title();
        self.line(format!("(expanded by screwcut from {from} to {}: every pass block by block)", to.title()));
        // The moves before the first thread were written in its units (or the program's, without one).
        let first = self.plan.threads.first().map_or(self.plan.units, |t| t.units);
        self.set_units(first);
        for l in self.w.preamble {
            self.line(l);
        }
        // The spindle is started with its speed before the first pass that has one (see `spindle`).
        let speeds = self.plan.threads.iter().flat_map(|t| &t.passes).any(|p| p.spindle.s.is_some() && !p.spindle.css);
        if let (Some(on), false) = (self.w.spindle_on, speeds) {
            self.line(on);
        }
    }

    /// Writes the unit code of `u` when it is not the one in force (a
    /// program may switch G20/G21 between threads); a controller that reads
    /// millimetres only gets every length scaled instead.
    fn set_units(&mut self, u: Units) {
        if self.units == Some(u) {
            return;
        }
        self.units = Some(u);
        self.scale = 1.0;
        match (u, self.w.units) {
            (Units::Inch, Some((inch, _))) => self.line(inch),
            (Units::Mm, Some((_, mm))) => self.line(mm),
            (Units::Inch, None) => {
                self.scale = 25.4;
                self.note(Remark::new(&tools::EX_MM_ONLY, args![dialect = Arg::lit(self.to.title())]));
            }
            (Units::Mm, None) => {}
        }
    }

    /// Before thread `t`: the crest its cycle gave, as a comment the planner
    /// reads (`(crest X68.)`): a block-by-block program does not say it, and
    /// without it the crest would be assumed by the 1.3·P rule. A crest the
    /// program turned or that was assumed comes back by itself.
    fn crest(&mut self, t: usize) {
        let th = &self.plan.threads[t];
        if !matches!(th.crest_source, CrestSource::Cycle | CrestSource::Comment) {
            return;
        }
        let axis = if th.long_axis == Axis::Z { "X" } else { "Z" };
        let line = format!("(crest {axis}{})", self.len(th.crest));
        self.line(line);
    }

    /// Before pass `p` of thread `t`: its spindle speed, when it differs from
    /// the last written (`M03 S…`, LinuxCNC `M3 S…`). Constant surface
    /// speed is not written (a note says so): the target's G96 words differ.
    fn spindle(&mut self, t: usize, p: usize) {
        let sp = &self.plan.threads[t].passes[p].spindle;
        match sp.s {
            Some(_) if sp.css => {
                self.note(Remark::new(&tools::EX_NO_CSS, args![]));
            }
            Some(s) if self.speed != Some(s) => {
                self.speed = Some(s);
                let on = self.w.spindle_on.unwrap_or("M03");
                self.line(format!("{on} S{}", crate::num::fmt(s)));
            }
            _ => {}
        }
    }

    fn body(&mut self) {
        let moves = &self.plan.moves;
        if let Some(first) = moves.first() {
            self.rapid(first.from);
        }
        let mut i = 0;
        while i < moves.len() {
            if let Some((t, p, _)) = self.owner[i]
                && self.plan.threads[t].passes[p].moves.all().start == i
            {
                self.set_units(self.plan.threads[t].units);
                if p == 0 {
                    self.crest(t);
                }
                self.spindle(t, p);
            }
            match self.owner[i] {
                Some((t, p, Part::Cut)) => {
                    let cut = self.plan.threads[t].passes[p].moves.cut.clone();
                    self.chain(t, p, &moves[cut.start..cut.end.min(moves.len())]);
                    i = cut.end.max(i + 1);
                    continue;
                }
                Some((t, p, _)) => {
                    // The approach goes to the start moved along the axis (when it is).
                    let before = i < self.plan.threads[t].passes[p].moves.cut.start;
                    let to = if before { self.shift(t, p, moves[i].to) } else { moves[i].to };
                    self.plain(&moves[i], to);
                }
                None => self.plain(&moves[i], moves[i].to),
            }
            i += 1;
        }
    }

    /// `pt`, a point of pass `p`'s approach or its start, moved where the
    /// pass starts when the target has no start angle word: back along its
    /// first synchronised move by lead × angle / 360° along the axis (the
    /// same helix), so that the cut, one part turn longer at most, still
    /// ends where it did (on a taper the start stays on the cone).
    fn shift(&self, t: usize, p: usize, pt: Point) -> Point {
        let th = &self.plan.threads[t];
        let pass = &th.passes[p];
        if self.w.start_angle {
            return pt;
        }
        let Some(first) = self.plan.moves.get(pass.moves.cut.start) else { return pt };
        match crate::helix::start_back(first.from, first.to, pass.angle, th.lead, th.long_axis) {
            Some(back) => Point::from_zr(pt.zr() + back),
            None => pt,
        }
    }

    fn plain(&mut self, m: &Move, to: Point) {
        match m.kind {
            MoveKind::Rapid => self.rapid(to),
            MoveKind::Arc | MoveKind::Rough if m.arc.is_some() => self.arc(m),
            MoveKind::Feed | MoveKind::Rough | MoveKind::Arc => self.feed(to),
            MoveKind::Thread | MoveKind::ScrewIn | MoveKind::Runout => {
                self.note(Remark::new(&tools::EX_STRAY_THREAD_MOVE, args![line = m.line]));
                self.feed(to);
            }
        }
    }

    /// The X and Z words of a move to `to` (only the axes that change, unless `both`).
    fn axes(&self, to: Point, both: bool) -> String {
        let mut s = String::new();
        let at = self.at;
        let to = self.snap(to);
        if both || at.is_none_or(|a| (a.x - to.x).abs() > EPS) {
            s += &format!(" X{}", self.len(to.x));
        }
        if both || at.is_none_or(|a| (a.z - to.z).abs() > EPS) {
            s += &format!(" Z{}", self.len(to.z));
        }
        s
    }

    fn arrive(&mut self, to: Point) {
        self.at = Some(self.snap(to));
    }

    /// Notes the direction of a G00/G01 move in X (Renhe's run-out goes against it).
    fn x_move(&mut self, to: Point) {
        let to = self.snap(to);
        if let Some(a) = self.at.filter(|a| (to.x - a.x).abs() > EPS) {
            self.last_x = (to.x - a.x).signum();
        }
    }

    fn rapid(&mut self, to: Point) {
        let words = self.axes(to, false);
        if !words.is_empty() {
            self.line(format!("{}{words}", self.w.motion[0]));
        }
        self.x_move(to);
        self.arrive(to);
    }

    fn feed(&mut self, to: Point) {
        let words = self.axes(to, false);
        if words.is_empty() {
            return;
        }
        let f = if self.feed_given { String::new() } else { format!(" F{}", self.lead(0.2 / self.scale)) };
        if !self.feed_given {
            self.note(Remark::new(&tools::EX_NO_FEED, args![]));
        }
        self.feed_given = true;
        self.line(format!("{}{words}{f}", self.w.motion[1]));
        self.x_move(to);
        self.arrive(to);
    }

    fn arc(&mut self, m: &Move) {
        let Some(a) = m.arc else { return self.feed(m.to) };
        let code = if a.cw { self.w.motion[2] } else { self.w.motion[3] };
        let (i, k) = ((a.center.x - m.from.x) / 2.0, a.center.z - m.from.z);
        let words = self.axes(m.to, true);
        self.line(format!("{code}{words} I{} K{}", self.len(i), self.len(k)));
        self.arrive(m.to);
    }

    /// The synchronised moves of pass `p` of thread `t`, written by the target's thread words.
    fn chain(&mut self, t: usize, p: usize, cut: &[Move]) {
        let th = &self.plan.threads[t];
        // The points as the target will read them, so the long axis of each
        // block (which its F is along) is the one the controller finds.
        // Only the start moves (when it does): the cut ends where it did.
        let start = cut.first().map(|m| m.from);
        let at = |pt: Point| {
            let moved = if Some(pt) == start { self.shift(t, p, pt) } else { pt };
            self.snap(moved)
        };
        let segs = segments(th, cut.iter().map(|m| (m.kind, at(m.from), at(m.to))));
        if segs.is_empty() {
            return;
        }
        if self.at.is_none_or(|a| a.dist(segs[0].from) > EPS) {
            self.rapid(segs[0].from);
        }
        let angle = th.passes[p].angle;
        if self.w.thread == ThreadWords::Renhe && self.last_x == 0.0 {
            self.renhe_x_feed(t, p, segs[0].from);
        }
        match self.w.thread {
            ThreadWords::G32 { runout } => self.g32(&segs, runout, angle),
            ThreadWords::Renhe => self.renhe(&segs, th.lead),
            ThreadWords::AlongPath => {
                for s in &segs {
                    let words = self.axes(s.to, true);
                    self.line(format!("G33{words} K{}", self.lead(s.along)));
                    self.arrive(s.to);
                }
            }
        }
    }

    /// G32 blocks: F along each block's long axis, Q on the first, a J/K run-out where the target has it.
    fn g32(&mut self, segs: &[Seg], runout: bool, angle: f64) {
        let mut k = 0;
        while k < segs.len() {
            let s = segs[k];
            let q = if k == 0 && self.w.start_angle && angle != 0.0 {
                format!(" Q{}", (angle * 1000.0).round() as i64)
            } else {
                String::new()
            };
            let merged =
                if runout && k + 2 == segs.len() && s.kind == MoveKind::Thread { jk(&s, &segs[k + 1]) } else { None };
            let Some((_, long)) = classify(s.from, s.to) else {
                k += 1;
                continue;
            };
            let len = s.from.dist(s.to);
            let f = s.along * Frame(long).travel(s.from, s.to).abs() / len;
            match merged {
                Some((end, j, kk)) => {
                    let words = self.axes(end, true);
                    self.line(format!("G32{words} F{} J{} K{}{q}", self.lead(f), self.len(j), self.len(kk)));
                    self.arrive(segs[k + 1].to);
                    k += 2;
                }
                None => {
                    let words = self.axes(s.to, true);
                    self.line(format!("G32{words} F{}{q}", self.lead(f)));
                    self.arrive(s.to);
                    k += 1;
                }
            }
        }
    }

    /// Renhe: the tail by `G30`, then incremental `G33 U W F` blocks (F the pitch along Z).
    fn renhe(&mut self, segs: &[Seg], lead: f64) {
        let n = segs.len();
        let tail = if n >= 2 && segs[n - 1].kind == MoveKind::Runout && segs[n - 2].kind == MoveKind::Thread {
            jk(&segs[n - 2], &segs[n - 1]).filter(|(_, j, _)| -j.signum() == self.last_x)
        } else {
            None
        };
        let body = if tail.is_some() { &segs[..n - 2] } else { segs };
        let r4 = |v: f64| (v * 1e4).round() / 1e4;
        let want = match tail {
            Some((_, j, k)) => Tail::Set(r4(2.0 * j.abs()), r4(k)),
            None => Tail::Set(0.0, 0.0),
        };
        if body.len() + usize::from(tail.is_some()) > 1 && want != Tail::Set(0.0, 0.0) {
            self.note(Remark::new(&tools::EX_RENHE_TAIL_LAST, args![]));
        }
        let set = |w: &mut Writer, t: Tail| {
            if w.tail != t {
                if let Tail::Set(u, k) = t {
                    let line = format!("G30 U{} W{}", w.len(u), w.len(k));
                    w.line(line);
                }
                w.tail = t;
            }
        };
        if !body.is_empty() {
            set(self, Tail::Set(0.0, 0.0));
        }
        for s in body {
            if s.kind == MoveKind::Runout {
                self.note(Remark::new(&tools::EX_RENHE_RUNOUT, args![]));
            }
            self.renhe_block(s.to, lead);
            self.arrive(s.to);
        }
        if let Some((end, _, _)) = tail {
            set(self, want);
            self.renhe_block(end, lead);
            self.arrive(segs[n - 1].to);
        }
    }

    /// Before the first Renhe thread block when no X move has set the
    /// run-out direction (the tool came from an unknown place): out to the
    /// pass's retract diameter (else two pitches out) and back in to `start`.
    fn renhe_x_feed(&mut self, t: usize, p: usize, start: Point) {
        let th = &self.plan.threads[t];
        let pass = &th.passes[p];
        let outward = -th.depth_dir;
        let retract = self.plan.moves.get(pass.moves.retract.start).map(|m| m.to.x);
        let out_x =
            retract.filter(|x| (x - start.x) * outward > EPS).unwrap_or(start.x + outward * 4.0 * th.pitch.max(0.5));
        let out = Point::new(out_x, start.z);
        self.note(Remark::new(&tools::EX_RENHE_X_FEED, args![x = self.snap(out).x]));
        self.rapid(out);
        self.rapid(start);
    }

    fn renhe_block(&mut self, end: Point, lead: f64) {
        let at = self.at.unwrap_or(end);
        let (u, w) = (end.x - at.x, end.z - at.z);
        if !(w.abs() * self.scale > 4.0 && w.abs() > u.abs()) {
            let (w, u) = (self.len(w), self.len(u));
            self.note(Remark::new(&tools::EX_RENHE_SHORT, args![w, u]));
        }
        let uw =
            if u.abs() > EPS { format!(" U{} W{}", self.len(u), self.len(w)) } else { format!(" W{}", self.len(w)) };
        self.line(format!("G33{uw} F{}", self.lead(lead)));
    }
}

/// The synchronised segments of a pass with the advance along each per
/// revolution: lead × length / travel along the thread's axis; a segment
/// that does not move along that axis (an X-only entry of a LinuxCNC taper)
/// takes its neighbour's.
fn segments(th: &Thread, moves: impl Iterator<Item = (MoveKind, Point, Point)>) -> Vec<Seg> {
    let f = Frame(th.long_axis);
    let mut segs: Vec<(Seg, bool)> = moves
        .filter(|(_, a, b)| a.dist(*b) > EPS)
        .map(|(kind, from, to)| {
            let axial = f.travel(from, to).abs();
            let known = axial > EPS;
            let along = if known { th.lead * from.dist(to) / axial } else { th.lead };
            (Seg { kind, from, to, along }, known)
        })
        .collect();
    for k in 0..segs.len() {
        if !segs[k].1 {
            let near = segs[k + 1..].iter().chain(segs[..k].iter().rev()).find(|s| s.1).map(|s| s.0.along);
            if let Some(a) = near {
                segs[k].0.along = a;
            }
        }
    }
    segs.into_iter().map(|s| s.0).collect()
}

/// A cut followed by its run-out as one G32 with `J K`: the end point on
/// the cut's line at the run-out's long-axis end, J the short-axis offset
/// (radius for X), K the long-axis length of the run-out.
fn jk(cut: &Seg, runout: &Seg) -> Option<(Point, f64, f64)> {
    let (_, long) = classify(cut.from, cut.to)?;
    let f = Frame(long);
    let (tc, to) = (f.travel(cut.from, cut.to), f.travel(cut.from, runout.to));
    if tc.abs() < EPS || tc * to <= 0.0 || to.abs() <= tc.abs() + EPS || runout.from.dist(cut.to) > EPS {
        return None;
    }
    let end = cut.from.lerp(cut.to, to / tc);
    let j = f.short(runout.to) - f.short(end);
    (j.abs() > EPS).then_some((end, j, (to - tc).abs()))
}
