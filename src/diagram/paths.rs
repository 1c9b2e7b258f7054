//! Which motions make each pass: the synchronised cut (screw-in, thread
//! segments, run-out) and the rapids around it (infeed before, retract and
//! return after). The plan lists motions and passes separately; the side
//! section draws every pass as its own path, so the motions are matched to
//! the passes here.
//!
//! A pass's cut is the screw-in or thread motion that starts where the pass
//! starts, on one of the pass's lines, and the thread and run-out motions
//! joined to it up to the pass's end. Rapids between two cuts go to the
//! pass whose lines they are on; when both passes claim them (a cycle, all
//! on one line) the last rapid is the next pass's infeed and the others are
//! the previous pass's retract and return.

use std::ops::Range;

use crate::motion::{Move, MoveKind, Point};
use crate::plan::Plan;
use crate::thread::Pass;

/// The motions of one pass, as ranges of `plan.moves`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PassPath {
    /// Index of the thread in `plan.threads`.
    pub thread: usize,
    /// Index of the pass in the thread's `passes`.
    pub pass: usize,
    /// Rapids before the cut.
    pub lead_in: Range<usize>,
    /// Screw-in, thread segments and run-out.
    pub cut: Range<usize>,
    /// Rapids after the cut.
    pub tail: Range<usize>,
}

/// Whether two points agree to well below any least input increment.
fn same(a: Point, b: Point) -> bool {
    let tol = 1e-6 * (1.0 + a.x.abs().max(a.z.abs()));
    (a.x - b.x).abs() <= tol && (a.z - b.z).abs() <= tol
}

/// Ranges of motion indices per source line (motions are in program order,
/// so a line's motions are usually contiguous; only the first run is kept).
struct LineIndex {
    ranges: Vec<Range<usize>>,
}

impl LineIndex {
    fn new(moves: &[Move]) -> LineIndex {
        let max = moves.iter().map(|m| m.line as usize).max().unwrap_or(0);
        let mut ranges: Vec<Range<usize>> = vec![0..0; max + 1];
        let mut i = 0;
        while i < moves.len() {
            let line = moves[i].line as usize;
            let start = i;
            while i < moves.len() && moves[i].line as usize == line {
                i += 1;
            }
            if ranges[line].is_empty() {
                ranges[line] = start..i;
            }
        }
        LineIndex { ranges }
    }

    fn of(&self, line: u32) -> Range<usize> {
        self.ranges.get(line as usize).cloned().unwrap_or(0..0)
    }
}

/// The end of a pass's cut: the run-out end, else the cut end.
fn pass_end(p: &Pass) -> Point {
    p.runout_to.unwrap_or(p.to)
}

/// The start of a pass's cut: the screw-in start, else the cut start.
fn pass_start(p: &Pass) -> Point {
    p.screw_in_from.unwrap_or(p.from)
}

/// Finds the cut of `p` among the motions of its lines, searching each
/// line's run from where the previous pass on that line was found.
fn find_cut(
    p: &Pass,
    moves: &[Move],
    index: &LineIndex,
    cursors: &mut [usize],
    claimed: &[bool],
) -> Option<Range<usize>> {
    let start = pass_start(p);
    let end = pass_end(p);
    for &line in &p.lines {
        let range = index.of(line);
        if range.is_empty() {
            continue;
        }
        let cursor = cursors.get(line as usize).copied().unwrap_or(range.start).clamp(range.start, range.end);
        let order = (cursor..range.end).chain(range.start..cursor);
        for k in order {
            let m = &moves[k];
            if claimed[k] || !matches!(m.kind, MoveKind::Thread | MoveKind::ScrewIn) || !same(m.from, start) {
                continue;
            }
            // Extend through the joined thread and run-out motions up to the pass end.
            let mut e = k;
            while !same(moves[e].to, end)
                && e + 1 < moves.len()
                && matches!(moves[e + 1].kind, MoveKind::Thread | MoveKind::Runout)
                && same(moves[e + 1].from, moves[e].to)
            {
                e += 1;
            }
            if let Some(c) = cursors.get_mut(line as usize) {
                *c = e + 1;
            }
            return Some(k..e + 1);
        }
    }
    None
}

/// Matches the plan's motions to its passes. Passes whose cut is not among
/// the motions (a plan cut short by a limit) are left out; draw them from
/// their own points.
pub fn pass_paths(plan: &Plan) -> Vec<PassPath> {
    let moves = &plan.moves;
    let index = LineIndex::new(moves);
    let mut cursors: Vec<usize> = index.ranges.iter().map(|r| r.start).collect();
    let mut claimed = vec![false; moves.len()];
    let mut found: Vec<PassPath> = Vec::new();
    for (ti, t) in plan.threads.iter().enumerate() {
        for (pi, p) in t.passes.iter().enumerate() {
            if let Some(cut) = find_cut(p, moves, &index, &mut cursors, &claimed) {
                for c in &mut claimed[cut.clone()] {
                    *c = true;
                }
                found.push(PassPath {
                    thread: ti,
                    pass: pi,
                    lead_in: cut.start..cut.start,
                    cut: cut.clone(),
                    tail: cut.end..cut.end,
                });
            }
        }
    }
    found.sort_by_key(|f| f.cut.start);
    let lines: Vec<&[u32]> = found.iter().map(|f| plan.threads[f.thread].passes[f.pass].lines.as_slice()).collect();
    let rapid_on = |k: usize, lines: &[u32]| moves[k].kind == MoveKind::Rapid && lines.contains(&moves[k].line);
    for i in 0..found.len() {
        // The gap between the previous cut (or the program start) and this one.
        let gap_start = if i == 0 { 0 } else { found[i - 1].cut.end };
        let here = lines[i];
        let prev = if i == 0 { None } else { Some(lines[i - 1]) };
        let mut lead = found[i].cut.start;
        while lead > gap_start && rapid_on(lead - 1, here) {
            let shared = prev.is_some_and(|pl| pl.contains(&moves[lead - 1].line));
            if shared && lead < found[i].cut.start {
                break; // both claim it: only the last rapid is this pass's infeed
            }
            lead -= 1;
        }
        found[i].lead_in = lead..found[i].cut.start;
        // The previous pass's retract and return: rapids on its lines up to this lead-in.
        if i > 0 {
            let pl = lines[i - 1];
            let mut e = found[i - 1].cut.end;
            while e < lead && rapid_on(e, pl) {
                e += 1;
            }
            found[i - 1].tail = found[i - 1].cut.end..e;
        }
    }
    if let (Some(last), Some(pl)) = (found.last_mut(), lines.last()) {
        let mut e = last.cut.end;
        while e < moves.len() && rapid_on(e, pl) {
            e += 1;
        }
        last.tail = last.cut.end..e;
    }
    found
}
