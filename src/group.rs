//! Grouping of block-by-block thread cuts (G32, Renhe G32/G33) and G92
//! passes into threads, from the interpreter's events.
//!
//! The textbook pattern cuts each pass with four blocks — infeed (G00 X),
//! cut (G32), retract (G00 X), return (G00 Z) — and repeats it deeper. Each
//! run of thread pieces (a continuous thread) is one [`Chain`]; consecutive
//! chains that cut the same helix become one [`Thread`] whose passes carry
//! the lines and the motions of their blocks. The grouper is a state
//! machine over events: it never reads the interpreter.

use std::ops::Range;
use std::rc::Rc;

use crate::diagnostic::{Diagnostics, Via};
use crate::event::{Piece, Seg};
use crate::helix;
use crate::num::{EPS, same_lead};
use crate::settings::{P, Settings};
use crate::span::{Shift, Span};
use crate::thread::{Axis, CrestSource, Infeed, Pass, PassMoves, Role, Source, Spindle, Thread, Units};

/// A continuous thread cut: consecutive thread blocks without a wait for
/// the one-rev signal (or one start of a G92 pass).
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// Command family.
    pub source: Source,
    /// The units its blocks were written in.
    pub units: Units,
    /// Lead of the first block.
    pub lead: f64,
    /// The pieces.
    pub segs: Vec<Seg>,
    /// Start angle in degrees (the first block's Q).
    pub angle: f64,
    /// Lines of the blocks (the infeed, retract and return are added by the grouper).
    pub lines: Vec<u32>,
    /// Direction of the last X motion before the cut (−1 inward, +1 outward, 0 unknown).
    pub approach: f64,
    /// Span of the first block.
    pub span: Span,
    /// Index in the plan's moves of the chain's first motion.
    pub first_move: usize,
    /// Tool angle in force when it was cut.
    pub tool_angle: f64,
    /// Its motions in the plan's moves.
    pub moves: PassMoves,
    /// The spindle when it was cut (its first block).
    pub spindle: Spindle,
    /// The last piece, read as the run-out of the segment before it
    /// ([`Grouper::is_runout`]), until another piece continues the cut.
    pub pending: Option<Seg>,
    /// The calls its first block was read in.
    pub via: Via,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum After {
    #[default]
    Nothing,
    Retract,
    Return,
}

/// The infeed rapid last seen on one axis: its line and its motion, if it moved.
type Infeed1 = Option<(u32, Option<usize>)>;

/// The chains of the thread being grouped, in chunks shared between the
/// reading and its snapshots: a snapshot (every few hundred blocks of an
/// incremental plan) copies the chunks' pointers, not the chains. A chunk
/// shared with a snapshot is never copied whole: a push after the snapshot
/// begins a new chunk, and a change to the last chain copies that chain
/// alone into a chunk of its own. Each chunk is seen to a length (a
/// snapshot's chunk may hold chains pushed after it; they are not its).
/// A thread of 50,000 passes cut block by block costs its snapshots little
/// (copying every chain at every snapshot grew with the square of the passes).
#[derive(Clone, Debug, Default)]
struct Cuts {
    /// The chunks and how many of each chunk's chains are this list's.
    chunks: Vec<(Rc<Vec<Chain>>, usize)>,
    len: usize,
}

/// Chains per chunk.
const CHUNK: usize = 64;

/// Whether `c` is this list's alone (no snapshot holds it).
fn unshared<T>(c: &Rc<T>) -> bool {
    Rc::strong_count(c) == 1 && Rc::weak_count(c) == 0
}

impl Cuts {
    fn push(&mut self, c: Chain) {
        match self.chunks.last_mut() {
            // A chunk of this list alone, with room (chains past its view were a dropped snapshot's).
            Some((last, n)) if *n < CHUNK && unshared(last) => {
                let v = Rc::get_mut(last).expect("unshared");
                v.truncate(*n);
                v.push(c);
                *n += 1;
            }
            _ => self.chunks.push((Rc::new(vec![c]), 1)),
        }
        self.len += 1;
    }

    fn last(&self) -> Option<&Chain> {
        self.chunks.last().map(|(c, n)| &c[n - 1])
    }

    fn last_mut(&mut self) -> Option<&mut Chain> {
        let (last, n) = self.chunks.last_mut()?;
        if !unshared(last) {
            // Shared with a snapshot: the last chain alone is copied, into a chunk of its own.
            let c = last[*n - 1].clone();
            *n -= 1;
            if *n == 0 {
                self.chunks.pop();
            }
            self.chunks.push((Rc::new(vec![c]), 1));
        }
        let (last, n) = self.chunks.last_mut()?;
        let v = Rc::get_mut(last).expect("unshared");
        // Chains past the view were a dropped snapshot's: not this list's.
        v.truncate(*n);
        v.last_mut()
    }

    fn iter(&self) -> impl Iterator<Item = &Chain> {
        self.chunks.iter().flat_map(|(c, n)| c[..*n].iter())
    }

    /// Changes every chain (a chunk shared with a snapshot is copied first).
    fn each_mut(&mut self, mut f: impl FnMut(&mut Chain)) {
        for (c, n) in &mut self.chunks {
            if !unshared(c) {
                *c = Rc::new(c[..*n].to_vec());
            }
            let v = Rc::get_mut(c).expect("unshared");
            v.truncate(*n);
            v.iter_mut().for_each(&mut f);
        }
    }
}

impl PartialEq for Cuts {
    fn eq(&self, other: &Cuts) -> bool {
        if self.len != other.len {
            return false;
        }
        // A reading resumed from a snapshot shares its chunks: those are equal without a look.
        let aligned = self.chunks.len() == other.chunks.len()
            && self.chunks.iter().zip(&other.chunks).all(|((_, n), (_, m))| n == m);
        if aligned {
            return self
                .chunks
                .iter()
                .zip(&other.chunks)
                .all(|((a, n), (b, _))| Rc::ptr_eq(a, b) || a[..*n] == b[..*n]);
        }
        self.iter().eq(other.iter())
    }
}

impl FromIterator<Chain> for Cuts {
    fn from_iter<I: IntoIterator<Item = Chain>>(it: I) -> Cuts {
        let mut c = Cuts::default();
        it.into_iter().for_each(|x| c.push(x));
        c
    }
}

/// Grouping state between events.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Grouper {
    /// The continuous cut in progress.
    chain: Option<Chain>,
    cuts: Cuts,
    after: After,
    /// The last rapid that moved X (the infeed of a Z thread) and that moved Z (of a face thread).
    infeed: [Infeed1; 2],
    /// A rapid back along the axis and across at once after a pass's
    /// retract (a cycle written block by block returns so): the motion that
    /// begins the next pass's approach.
    back_across: Option<usize>,
    /// The calls the block being read was reached through.
    pub via: Via,
}

impl Chain {
    /// Makes the chain as read from a text edited as `s` says, with `moves` more motions before it.
    pub fn shift(&mut self, moves: isize, s: Shift) {
        self.span = s.span(self.span);
        self.first_move = self.first_move.saturating_add_signed(moves);
        self.moves = self.moves.shifted(moves);
    }
}

impl Grouper {
    /// Makes the state as reached in a text edited as `s` says, with `moves`
    /// more motions before it (to compare with a reading of an edited text).
    pub fn shift(&mut self, moves: isize, s: Shift) {
        self.infeed = self.infeed.map(|i| i.map(|(line, mv)| (line, mv.map(|m| m.saturating_add_signed(moves)))));
        if let Some(c) = &mut self.chain {
            c.shift(moves, s);
        }
        self.cuts.each_mut(|c| c.shift(moves, s));
        self.back_across = self.back_across.map(|m| m.saturating_add_signed(moves));
    }

    /// A rapid with axis words `x`, `z` on `line` (its motion's index, if it
    /// moved): after a cut the first rapid on the cut's short axis is its
    /// retract and the next rapid on its long axis its return; otherwise
    /// the last rapid on a short axis is the next cut's infeed (X for a
    /// thread along Z, Z for a face thread).
    pub fn rapid(&mut self, x: bool, z: bool, line: u32, mv: Option<usize>) {
        let long_z = self.cuts.last().is_none_or(|c| c.segs[0].long == Axis::Z);
        let (on_short, on_long) = if long_z { (x, z) } else { (z, x) };
        let consumed = match self.after {
            After::Retract if on_short || on_long => {
                self.after = if on_short && !on_long { After::Return } else { After::Nothing };
                true
            }
            After::Return if on_long && !on_short => {
                self.after = After::Nothing;
                true
            }
            After::Return => {
                self.after = After::Nothing;
                if on_long {
                    self.back_across = mv;
                }
                false
            }
            _ => false,
        };
        if consumed {
            if let Some(last) = self.cuts.last_mut() {
                last.lines.push(line);
                if let Some(i) = mv {
                    last.moves.retract.end = i + 1;
                }
            }
            return;
        }
        if x {
            self.infeed[0] = Some((line, mv));
        }
        if z {
            self.infeed[1] = Some((line, mv));
        }
    }

    /// Whether piece `p` would be the run-out of the continuous thread being
    /// cut: a G32 block after a cut without a run-out, going on along the
    /// thread's axis (Z) while it leaves the work (against the infeed) at
    /// `group.runout_angle` or more to the axis — the chamfer Fanuc programs
    /// write as a second G32 block, Fanuc's G32 having no run-out word, and
    /// LinuxCNC programs as a second G33.
    pub fn is_runout(&self, p: &Piece, s: &Settings) -> bool {
        let Some(c) = &self.chain else { return false };
        if !matches!(p.source, Source::G32 | Source::LinuxG33) {
            return false;
        }
        let Some(last) = c.segs.last() else { return false };
        if c.source != p.source || last.runout_to.is_some() || p.seg.runout_to.is_some() {
            return false;
        }
        if last.long != Axis::Z || c.approach == 0.0 {
            return false;
        }
        let f = last.frame();
        let along = f.travel(p.seg.from, p.seg.to);
        let out = f.short(p.seg.to) - f.short(p.seg.from);
        if along * last.long_travel() < 0.0 || out * -c.approach <= EPS {
            return false;
        }
        out.abs().atan2(along.abs()).to_degrees() >= s.get(P::GroupRunoutAngle) - 1e-9
    }

    /// A thread piece whose motions are `moves` (the cut, then its run-out),
    /// written in `units`: it continues the continuous thread being cut, or
    /// starts one. With `runout` ([`Grouper::is_runout`]) it is the run-out
    /// of the segment before it, unless another piece follows.
    pub fn piece(&mut self, p: Piece, moves: Range<usize>, units: Units, runout: bool) {
        match &mut self.chain {
            Some(c) => {
                if let Some(seg) = c.pending.take() {
                    // The cut goes on: what looked like its run-out is a segment of it.
                    if let Some(last) = c.segs.last_mut() {
                        last.runout_to = None;
                    }
                    c.segs.push(seg);
                }
                if runout {
                    if let Some(last) = c.segs.last_mut() {
                        last.runout_to = Some(p.seg.to);
                    }
                    c.pending = Some(p.seg);
                } else {
                    c.segs.push(p.seg);
                }
                c.lines.push(p.line);
                c.moves.cut.end = moves.end;
                c.moves.retract = moves.end..moves.end;
            }
            None => {
                let at = moves.start;
                self.chain = Some(Chain {
                    source: p.source,
                    units,
                    lead: p.lead,
                    segs: vec![p.seg],
                    angle: p.angle,
                    lines: vec![p.line],
                    approach: p.approach,
                    span: p.span,
                    first_move: at,
                    tool_angle: p.tool_angle,
                    moves: PassMoves { approach: at..at, cut: moves.clone(), retract: moves.end..moves.end },
                    spindle: p.spindle,
                    pending: None,
                    via: self.via.clone(),
                });
            }
        }
    }

    /// The continuous thread being cut ends: it joins the current thread or
    /// starts a new one (completed threads go to `out`).
    pub fn end_chain(&mut self, s: &Settings, out: &mut Vec<Thread>, diags: &mut Diagnostics) {
        if let Some(chain) = self.chain.take() {
            self.add(chain, s, out, diags);
        }
    }

    /// Adds a finished chain: it joins the current thread or starts a new one.
    pub fn add(&mut self, mut chain: Chain, s: &Settings, out: &mut Vec<Thread>, diags: &mut Diagnostics) {
        // Block-by-block passes own their infeed, retract and return; a G92 block is all of its pass.
        let blockwise = chain.source != Source::G92;
        let short = if chain.segs[0].long == Axis::Z { 0 } else { 1 };
        let infeed = self.infeed[short];
        self.infeed = [None, None];
        let back_across = self.back_across.take();
        if let (Some((line, mv)), true) = (infeed, blockwise) {
            chain.lines.insert(0, line);
            if let Some(i) = mv.filter(|i| *i < chain.moves.cut.start) {
                // The return back and across just before the infeed is the approach's start, as a cycle's is.
                let from = back_across.filter(|&k| k + 1 == i).unwrap_or(i);
                chain.moves.approach = from..chain.moves.cut.start.min(i + 1);
            }
        }
        let max_infeed = s.get(P::GroupMaxInfeed);
        if let Some(last) = self.cuts.last() {
            if !same_thread(last, &chain, max_infeed) {
                self.close(s, out, diags);
            }
        }
        self.cuts.push(chain);
        self.after = if blockwise { After::Retract } else { After::Nothing };
    }

    /// Closes the thread being grouped, if any, into `out`.
    pub fn close(&mut self, s: &Settings, out: &mut Vec<Thread>, diags: &mut Diagnostics) {
        // The thread is built from the chains where they are: the snapshots
        // of a reading share them, and taking them out would copy them all.
        let taken = std::mem::take(&mut self.cuts);
        self.after = After::Nothing;
        if taken.len == 0 {
            return;
        }
        let cuts: Vec<&Chain> = taken.iter().collect();
        let limit = s.int(P::LimitStarts).max(1) as usize;
        let thread = build(&cuts);
        if thread.starts as usize > limit {
            too_many_starts(&cuts, thread.starts, limit, diags);
        }
        out.push(thread);
    }
}

/// Reports the chain that brought the starts over `limit`.
#[cold]
fn too_many_starts(cuts: &[&Chain], starts: u32, limit: usize, diags: &mut Diagnostics) {
    let mut seen: Vec<f64> = Vec::new();
    for c in cuts {
        if !seen.iter().any(|a| (a - c.angle).abs() < 1e-6) {
            seen.push(c.angle);
            if seen.len() > limit {
                diags.push(&crate::message::TOO_MANY_STARTS, c.span, crate::args![n = starts, limit]);
                return;
            }
        }
    }
}

/// Whether `b` cuts the same helix as `a` (one more pass of it).
fn same_thread(a: &Chain, b: &Chain, max_infeed: f64) -> bool {
    if a.source != b.source || a.units != b.units || !same_lead(a.lead, b.lead) || a.segs.len() != b.segs.len() {
        return false;
    }
    for (x, y) in a.segs.iter().zip(&b.segs) {
        if x.kind != y.kind || x.long != y.long || x.long_travel().signum() != y.long_travel().signum() {
            return false;
        }
    }
    let (x, y) = (&a.segs[0], &b.segs[0]);
    let (a0, a1) = minmax(x.long_of(x.from), x.long_of(x.to));
    let (b0, b1) = minmax(y.long_of(y.from), y.long_of(y.to));
    let overlap = a1.min(b1) - a0.max(b0);
    let shorter = (a1 - a0).min(b1 - b0);
    if overlap < 0.5 * shorter - EPS {
        return false;
    }
    (x.short_of(x.from) - y.short_of(y.from)).abs() <= max_infeed * a.lead + EPS
}

fn minmax(a: f64, b: f64) -> (f64, f64) {
    if a <= b { (a, b) } else { (b, a) }
}

/// The pass a chain cuts, as start `start` (1-based) of its thread.
fn pass_of(c: &Chain, start: u32, index: u32) -> Pass {
    let first = c.segs[0];
    let last = *c.segs.last().unwrap_or(&first);
    let mut segments = Vec::new();
    if c.segs.len() > 1 {
        segments.push(first.from);
        for (i, s) in c.segs.iter().enumerate() {
            segments.push(s.to);
            if let (Some(r), true) = (s.runout_to, i + 1 < c.segs.len()) {
                segments.push(r);
            }
        }
    }
    let mut lines = c.lines.clone();
    crate::order::sort(&mut lines);
    lines.dedup();
    Pass {
        start,
        index,
        from: first.from,
        to: last.to,
        depth: 0.0,
        infeed: 0.0,
        role: Role::Rough,
        lines,
        via: c.via.as_deref().map_or_else(Vec::new, <[u32]>::to_vec),
        segments,
        runout_to: last.runout_to,
        screw_in_from: None,
        shift: 0.0,
        angle: c.angle,
        area: None,
        moves: c.moves.clone(),
        spindle: c.spindle,
    }
}

/// Builds a thread from its chains: starts from the helices they cut
/// ([`starts_of`]), passes in order.
fn build(cuts: &[&Chain]) -> Thread {
    let (of, starts) = starts_of(cuts);
    let mut counts = vec![0u32; starts];
    let mut passes = Vec::with_capacity(cuts.len());
    for (c, &si) in cuts.iter().zip(&of) {
        counts[si] += 1;
        passes.push(pass_of(c, si as u32 + 1, counts[si]));
    }
    let c0 = &cuts[0];
    let main =
        *c0.segs.iter().max_by(|a, b| a.long_travel().abs().total_cmp(&b.long_travel().abs())).unwrap_or(&c0.segs[0]);
    let depth_dir = depth_direction(cuts, &main);
    let starts = starts as u32;
    let line = cuts.iter().flat_map(|c| c.lines.iter().copied()).min().unwrap_or(0);
    let end_line = cuts.iter().flat_map(|c| c.lines.iter().copied()).max().unwrap_or(0);
    let p0 = &passes[0];
    let taper = match main.long {
        Axis::Z => p0.from.r() - p0.to.r(),
        Axis::X => 0.0,
    };
    Thread {
        line,
        end_line,
        source: c0.source,
        units: c0.units,
        kind: main.kind,
        long_axis: main.long,
        lead: c0.lead,
        pitch: c0.lead / starts as f64,
        starts,
        internal: main.long == Axis::Z && depth_dir > 0.0,
        infeed: Infeed::Programmed,
        tool_angle: c0.tool_angle,
        crest: 0.0,
        crest_source: CrestSource::Assumed,
        turned: None,
        height: 0.0,
        taper,
        passes,
        depth_dir,
        first_move: cuts.iter().map(|c| c.first_move).min().unwrap_or(0),
        shop: Default::default(),
    }
}

/// Each chain's start (0-based) and the number of starts. The helices the
/// chains cut (their phases: start angle and axial start, [`helix::phase`])
/// are the starts when there are several, evenly spaced round the turn, each
/// cut by as many passes: a multi-start thread cut by start angles (`Q`) or
/// by moving each start's passes lead/starts along the axis, as a controller
/// without a start angle word (Renhe, LinuxCNC) cuts one. Otherwise the
/// distinct start angles are the starts (a pass on a stray helix is the
/// cross-thread check's to report, [`helix::check`]). Starts are numbered
/// from the first chain's, by angle.
fn starts_of(cuts: &[&Chain]) -> (Vec<usize>, usize) {
    let phase = |c: &Chain| {
        let s = c.segs[0];
        helix::phase(c.angle, s.long_of(s.from), s.long_of(s.to), 0.0, c.lead)
    };
    let phases: Vec<f64> = cuts.iter().map(|c| phase(c)).collect();
    // (phase from the first chain's, passes, the start angle of its first chain)
    let mut helices: Vec<(f64, usize, f64)> = Vec::new();
    let mut of = Vec::with_capacity(cuts.len());
    for (c, &p) in cuts.iter().zip(&phases) {
        if helices.len() > MAX_EVEN_STARTS {
            // Passes drifting along the axis (a flank infeed written block by block): no even starts.
            break;
        }
        let turn = (p - phases[0]).rem_euclid(1.0);
        match helices.iter().position(|h| helix::same_phase(h.0, turn)) {
            Some(i) => {
                helices[i].1 += 1;
                of.push(i);
            }
            None => {
                of.push(helices.len());
                helices.push((turn, 1, c.angle));
            }
        }
    }
    let n = helices.len();
    let mut by_turn: Vec<usize> = (0..n).collect();
    let complete = of.len() == cuts.len();
    crate::order::sort_by(&mut by_turn, |&a, &b| helices[a].0.total_cmp(&helices[b].0));
    let even = complete
        && n > 1
        && by_turn.iter().enumerate().all(|(k, &i)| helix::same_phase(helices[i].0, k as f64 / n as f64))
        && helices.iter().all(|h| h.1 == helices[0].1);
    if even {
        // Numbered by start angle, then by axial place round the turn.
        let mut order: Vec<usize> = (0..n).collect();
        crate::order::sort_by(&mut order, |&a, &b| {
            helices[a].2.total_cmp(&helices[b].2).then(helices[a].0.total_cmp(&helices[b].0))
        });
        let mut rank = vec![0; n];
        for (k, &i) in order.iter().enumerate() {
            rank[i] = k;
        }
        return (of.into_iter().map(|i| rank[i]).collect(), n);
    }
    // The distinct start angles, sorted (in n log n: a thread may have tens of thousands of passes).
    let mut angles: Vec<f64> = cuts.iter().map(|c| c.angle).collect();
    crate::order::sort_floats(&mut angles);
    angles.dedup_by(|a, kept| (*a - *kept).abs() < 1e-6);
    let last = angles.len().saturating_sub(1);
    let of = cuts.iter().map(|c| angles.partition_point(|a| *a < c.angle - 1e-6).min(last)).collect();
    (of, angles.len())
}

/// The most starts read from the helices the passes cut (evenly spaced);
/// passes on more helices than this are no multi-start thread.
const MAX_EVEN_STARTS: usize = 360;

/// Which way the depth grows along the short axis: from the passes'
/// progression, else from the approach of the first cut, else from its
/// run-out (which leaves the work), else outward-in (external thread).
fn depth_direction(cuts: &[&Chain], main: &Seg) -> f64 {
    let s0 = main.short_of(cuts[0].segs[0].from);
    for c in &cuts[1..] {
        let d = main.short_of(c.segs[0].from) - s0;
        if d.abs() > EPS {
            return d.signum();
        }
    }
    if main.long == Axis::Z && cuts[0].approach != 0.0 {
        return cuts[0].approach;
    }
    if let Some(r) = cuts[0].segs.last().and_then(|s| s.runout_to.map(|r| (s, r))) {
        let d = main.short_of(r.1) - main.short_of(r.0.to);
        if d.abs() > EPS {
            return -d.signum();
        }
    }
    -1.0
}

#[cfg(test)]
mod tests;
