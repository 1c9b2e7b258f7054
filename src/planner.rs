//! Incremental planning for an editor: re-plan only from the first block an
//! edit changed.
//!
//! While reading a program the [`Planner`] keeps a snapshot of the
//! interpreter every [`CHECKPOINT_EVERY`] blocks. When the text changes, it
//! finds the first changed byte, goes back to the last snapshot before it,
//! cuts the motions, threads and diagnostics back to what they were there,
//! and reads on from that block.
//!
//! It also stops early: when the edit leaves the number of lines as it was,
//! the first block past the edited bytes where the last reading took a
//! snapshot, reached in the same modal, grouping and flow state, shows that
//! reading on would repeat the last reading — provided the last reading
//! never read the edited lines after that snapshot (a subprogram called
//! again, a loop run again), nor looked a label up if the edit changed one
//! (each snapshot keeps what the reading read since the one before:
//! [`Reads`]). The rest of it is kept, its motions' and diagnostics' byte
//! spans after the edit moved by the edit's length, the motion indices by
//! the motions before, and its count of blocks run again by the loops that
//! ran another number of times before the join. Depths, advice and shop-floor figures of the threads completed
//! before the resume point are kept (with their diagnostics); the threads
//! from there on are finished anew (they depend on the outline before each
//! thread). The result is the plan a full re-plan would give; the tests
//! check that for random edits.

mod changed;
mod edit;
mod tail;

pub use changed::Changed;

use crate::diagnostic::{Diagnostics, Found, Item};
use crate::exec::reads::Reads;
use crate::plan::{Plan, Reading, Snapshot, finish, finish_thread, finish_with, lexer_for};
use crate::settings::Settings;
use crate::span::Shift;
use crate::thread::Thread;
use edit::Edit;
use tail::{Join, Tail, joinable_from};

/// Blocks between two snapshots.
pub const CHECKPOINT_EVERY: usize = 256;

struct Checkpoint {
    /// Byte offset of the block about to be read.
    offset: usize,
    /// Its 1-based line.
    line: u32,
    /// The reading before it.
    snap: Snapshot,
    /// What the reading depended on since the checkpoint before.
    reads: Reads,
}

/// Plans successive versions of a program, reusing the work before each edit.
pub struct Planner {
    settings: Settings,
    text: String,
    checkpoints: Vec<Checkpoint>,
    /// The interpreter's own diagnostics of the last run (before advice).
    raw_diags: Diagnostics,
    /// Advice of each thread of the last plan, all formatted (kept for the
    /// threads an edit leaves before its resume point).
    advice: Vec<Vec<Item>>,
    inch: bool,
    line_starts: Vec<u32>,
    plan: Option<Plan>,
    resumed_at: u32,
    stopped_at: Option<u32>,
    /// What the last reading depended on after its last checkpoint.
    last_reads: Reads,
    /// Blocks the last reading ran again in all (against `limits.blocks`).
    last_repeated: u64,
    /// Where the last plan took over the reading before it (for its threads' advice).
    join: Option<Join>,
    /// What the last plan kept of the one before it.
    changed: Option<Changed>,
    /// Plans made so far.
    plans: u64,
}

impl Planner {
    /// A planner for `settings` (which carry the dialect).
    pub fn new(settings: Settings) -> Planner {
        Planner {
            settings,
            text: String::new(),
            checkpoints: Vec::new(),
            raw_diags: Diagnostics::default(),
            advice: Vec::new(),
            inch: false,
            line_starts: Vec::new(),
            plan: None,
            resumed_at: 1,
            stopped_at: None,
            last_reads: Reads::default(),
            last_repeated: 0,
            join: None,
            changed: None,
            plans: 0,
        }
    }

    /// The settings in force.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Changes the settings; the next plan starts from the top.
    pub fn set_settings(&mut self, settings: Settings) {
        if settings != self.settings {
            self.settings = settings;
            self.checkpoints.clear();
            self.plan = None;
        }
    }

    /// What the last plan kept of the plan before it (none when it was
    /// made from nothing: the first plan, new settings, a text too large).
    pub fn changed(&self) -> Option<&Changed> {
        self.changed.as_ref()
    }

    /// How many plans this planner has made (the last plan is the `plans()`-th).
    pub fn plans(&self) -> u64 {
        self.plans
    }

    /// The line the last plan resumed reading at (1 when it read everything).
    pub fn resumed_at(&self) -> u32 {
        self.resumed_at
    }

    /// The line where the last plan stopped reading because the rest was
    /// the last reading's (none when it read to the end).
    pub fn stopped_at(&self) -> Option<u32> {
        self.stopped_at
    }

    /// The text of the last plan.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The last plan, if any.
    pub fn last(&self) -> Option<&Plan> {
        self.plan.as_ref()
    }

    /// The last plan, to add findings about it as a whole (the next plan is
    /// built from the reading, not from these).
    pub fn last_mut(&mut self) -> Option<&mut Plan> {
        self.plan.as_mut()
    }

    /// Plans `text`, reading only from the last checkpoint before the first
    /// change, and only until the reading meets the last one again.
    pub fn plan(&mut self, text: &str) -> &Plan {
        let edit = Edit::of(&self.text, text);
        let (resume, moved) = match self.resume_point(text, &edit) {
            Some((ci, moved)) => (Some(ci), moved),
            None => (None, None),
        };
        self.plans += 1;
        let mut changed = self.plan.as_ref().map(|_| Changed::default());
        let mut r = Reading::new(&self.settings, if resume.is_some() { 0 } else { text.len() });
        let Some(mut lexer) = lexer_for(text, &self.settings, &mut r.diags) else {
            self.changed = None;
            self.reset(text);
            return self.plan.insert(finish(text, &self.settings, r.outputs(), Vec::new()));
        };
        let mut kept_threads = 0;
        self.join = None;
        let old_advice = std::mem::take(&mut self.advice);
        let mut tail = None;
        self.stopped_at = None;
        // The last plan's diagnostics, whose messages' texts the new plan's may reuse.
        let mut before = Vec::new();
        match resume {
            Some(ci) => {
                let old = self.plan.take().expect("a plan to resume");
                before = old.diagnostics;
                r.asm.moves = old.moves;
                r.asm.threads = old.threads;
                r.diags = std::mem::take(&mut self.raw_diags);
                let later = self.checkpoints.split_off(ci + 1);
                tail = self.tail_of(
                    text,
                    &edit,
                    later,
                    &self.checkpoints[ci],
                    &mut r,
                    old.units == crate::plan::Units::Inch,
                );
                if let Some(s) = moved {
                    // What was read before the checkpoint reaches past the edit (a
                    // subprogram written after it): its state and outputs move with the text.
                    for c in &mut self.checkpoints {
                        // A checkpoint taken inside a subprogram written after the edit moves too.
                        c.offset = s.pos(c.offset);
                        c.snap.shift(0, 0, 0, s);
                        c.reads.shift(s);
                    }
                }
                let cp = &self.checkpoints[ci];
                r.restore(&cp.snap);
                if let Some(s) = moved {
                    r.asm.moves.iter_mut().for_each(|m| m.span = s.span(m.span));
                    r.diags.shift_spans(s);
                }
                kept_threads = cp.snap.threads();
                if let Some(c) = &mut changed {
                    (c.moves_kept, c.threads_kept) = (cp.snap.moves(), kept_threads);
                }
                lexer.seek(cp.offset, cp.line);
                self.line_starts.truncate(cp.line as usize - 1);
                if self.line_starts.len() + 1 != cp.line as usize {
                    // The lines before the checkpoint were not all read in order: the rest is scanned.
                    lexer.stop_recording();
                }
                self.resumed_at = cp.line;
            }
            None => {
                // From the top; the last reading's tail may still be kept.
                let top = Checkpoint { offset: 0, line: 1, snap: r.snapshot(), reads: Reads::default() };
                if let Some(old) = self.plan.take() {
                    before = old.diagnostics;
                    r.asm.moves = old.moves;
                    r.asm.threads = old.threads;
                    r.diags = std::mem::take(&mut self.raw_diags);
                    let later = std::mem::take(&mut self.checkpoints);
                    tail = self.tail_of(text, &edit, later, &top, &mut r, old.units == crate::plan::Units::Inch);
                    r.restore(&top.snap);
                }
                self.checkpoints.clear();
                self.line_starts.clear();
                self.resumed_at = 1;
            }
        }
        let checkpoints = &mut self.checkpoints;
        let mut meet = None;
        let read_all = r.run(&mut lexer, CHECKPOINT_EVERY, |offset, line, due, r| {
            // The last reading may be joined where it had a checkpoint (loops
            // that ran other numbers of times put the new ones elsewhere).
            let join = tail.as_ref().filter(|t| offset >= t.common_from && t.places.contains(&offset));
            if !due && join.is_none() {
                return true;
            }
            let snap = r.snapshot();
            if let Some(k) = join.and_then(|t| t.meets(offset, line, &snap)) {
                meet = Some(k);
                return false;
            }
            if due {
                let reads = std::mem::take(&mut r.reads);
                checkpoints.push(Checkpoint { offset, line, snap, reads });
            }
            true
        });
        self.line_starts.extend(lexer.take_line_starts());
        let inch_now = r.it.m.inch;
        if let (false, Some(k), Some(t)) = (read_all, meet, tail) {
            self.stopped_at = Some(t.checkpoints[k].line);
            let (moves, threads) = self.splice(&mut r, t, k);
            if let Some(c) = &mut changed {
                (c.moves_rejoined, c.threads_rejoined) = (Some(moves), Some(threads));
            }
        } else {
            self.last_reads = std::mem::take(&mut r.reads);
            self.last_repeated = r.exec.repeated;
        }
        self.text.clear();
        self.text.push_str(text);
        let mut out = r.outputs();
        if !read_all {
            out.inch = self.inch;
        } else {
            out.inch = inch_now;
        }
        self.inch = out.inch;
        // Threads complete before the resume point are finished already and
        // their advice is kept; the rest are finished now, every message
        // formatted so it can be kept for the next edit.
        let mut old_advice = old_advice;
        if let Some(s) = moved {
            for items in old_advice.iter_mut().take(kept_threads) {
                items.iter_mut().for_each(|i| i.1 = s.span(i.1));
            }
        }
        let advice = &mut self.advice;
        *advice = old_advice.drain(..kept_threads.min(old_advice.len())).collect();
        let join = self.join.as_ref();
        let settings = &self.settings;
        // The last plan's diagnostics were finished on the text before the edit.
        let text_edit =
            crate::diagnostic::TextEdit { changed_at: edit.changed_at, new_end: edit.new_end, by: edit.shift.by };
        let mut refinished = Vec::new();
        let (finished, old_advice) = (&mut refinished, &mut old_advice);
        let before = (before, Some(text_edit));
        let (plan, raw_diags) =
            finish_with(text, settings, out, self.line_starts.clone(), before, move |threads, moves, spans, room| {
                for i in advice.len()..threads.len() {
                    // A thread of the last reading's rest, finished then, stays finished when
                    // the edit is not in the text it was finished from.
                    if let Some(kept) = join.and_then(|j| j.advice_of(threads, i, old_advice, kept_threads)) {
                        advice.push(kept);
                        continue;
                    }
                    let mut d = Diagnostics::with_limit(usize::MAX);
                    finished.push(i);
                    finish_thread(threads, i, moves, settings, text, &mut d, spans);
                    advice.push(d.into_items());
                }
                // The kept advice, borrowed, only as much as the plan keeps (the rest is counted).
                let advice: &Vec<Vec<_>> = advice;
                let mut found = Found::with_room(room);
                advice.iter().flatten().for_each(|item| found.push(std::borrow::Cow::Borrowed(item)));
                found
            });
        self.raw_diags = raw_diags;
        self.changed = changed.map(|c| Changed { refinished, ..c });
        self.plan.insert(plan)
    }

    /// The checkpoint to resume at: the last one before the edit (in the
    /// order read) such that nothing read up to it touched the edited
    /// lines, nor looked a label up if the edit changed one, and whose
    /// threads were finished from text the edit did not touch. When what
    /// it read reaches past the edit (a subprogram written after it), its
    /// state and outputs move with the text: `Some(shift)`, allowed only
    /// when the edit keeps the number of lines.
    fn resume_point(&self, text: &str, edit: &Edit) -> Option<(usize, Option<Shift>)> {
        let plan = self.plan.as_ref()?;
        let (old, changed_at) = (&self.text, edit.changed_at);
        let linuxcnc = self.settings.dialect() == crate::dialect::Dialect::LinuxCnc;
        // The first thread finished from text that holds the edit (it would
        // have to be finished again), worked out only when a checkpoint needs it.
        let mut dirty = None;
        let mut dirty_thread = || *dirty.get_or_insert_with(|| self.first_touched_thread(plan, edit));
        let mut best = None;
        for (k, c) in self.checkpoints.iter().enumerate() {
            let looked_changed = c.reads.looked && edit.labels_changed(old, text, linuxcnc);
            if c.reads.touches(changed_at, edit.old_end) || looked_changed {
                break;
            }
            if c.offset > changed_at {
                continue;
            }
            if c.snap.read_to() <= changed_at {
                best = Some((k, None));
            } else if edit.lines_kept && dirty_thread().is_none_or(|d| c.snap.threads() <= d) {
                best = Some((k, Some(edit.shift)));
            }
        }
        best
    }

    /// The first thread of the last plan finished from text holding the
    /// edited bytes: the lines its designation and
    /// crest comments are looked for in, from after the thread before it
    /// (or the start of its own program) to its first line (see
    /// `comment::find_back`).
    fn first_touched_thread(&self, plan: &Plan, edit: &Edit) -> Option<usize> {
        let old = &self.text;
        let edited = edit.lines(old, &self.line_starts);
        let index = crate::span::LineIndex::from_starts(old, self.line_starts.clone());
        let spans = |line: u32| {
            let start = index.line_start(line);
            let end = old[start..].find(['\n', '\r']).map_or(old.len(), |e| start + e);
            crate::span::Span::new(start, end)
        };
        plan.threads.iter().enumerate().position(|(i, t)| {
            let stop = i.checked_sub(1).map_or(1, |p| (plan.threads[p].end_line + 1).min(t.line));
            let from = crate::comment::window_start(old, &spans, stop, t.line);
            from <= edited.1 && t.line >= edited.0
        })
    }

    /// What of the last reading may be kept past the edit: its part after
    /// checkpoint `cp`, when the edit keeps the number of lines and the last
    /// reading neither dropped diagnostics nor stopped at the move limit.
    fn tail_of(
        &self,
        text: &str,
        edit: &Edit,
        later: Vec<Checkpoint>,
        cp: &Checkpoint,
        r: &mut Reading,
        inch: bool,
    ) -> Option<Tail> {
        let old = &self.text;
        if !edit.lines_kept || later.is_empty() || r.diags.dropped() > 0 || r.asm.stopped() {
            return None;
        }
        let linuxcnc = self.settings.dialect() == crate::dialect::Dialect::LinuxCnc;
        let labels = || edit.labels_changed(old, text, linuxcnc);
        let joinable_from = joinable_from(&later, &self.last_reads, (edit.changed_at, edit.old_end), labels)?;
        let at = (cp.snap.moves(), cp.snap.threads(), cp.snap.diagnostics());
        let shift = edit.shift;
        let places = later[joinable_from..].iter().map(|c| shift.pos(c.offset)).collect();
        // The fewer motions are copied: those before the resume point, or the rest.
        let (total, at_m) = (r.asm.moves.len(), at.0.min(r.asm.moves.len()));
        let (moves, whole_moves) = if at_m < total - at_m {
            let all = std::mem::take(&mut r.asm.moves);
            r.asm.moves = all[..at_m].to_vec();
            (all, true)
        } else {
            (r.asm.moves.split_off(at_m), false)
        };
        // The threads before the resume point, when fewer than the rest, are
        // moved out (empty threads left in their places); the rest stay where they are.
        let (total, at_t) = (r.asm.threads.len(), at.1.min(r.asm.threads.len()));
        let (threads, whole_threads) = if at_t < total - at_t {
            let mut all = std::mem::take(&mut r.asm.threads);
            r.asm.threads.reserve(at_t);
            for th in &mut all[..at_t] {
                r.asm.threads.push(std::mem::take(th));
            }
            (all, true)
        } else {
            (r.asm.threads.split_off(at_t), false)
        };
        Some(Tail {
            checkpoints: later,
            moves,
            whole_moves,
            threads,
            whole_threads,
            diags: r.diags.split_off(at.2),
            at,
            line_starts: self.line_starts.clone(),
            common_from: edit.new_end,
            edited_lines: edit.lines(old, &self.line_starts),
            shift,
            joinable_from,
            places,
            last_reads: self.last_reads.clone(),
            repeated: (self.last_repeated, self.settings.int(crate::settings::P::LimitBlocks).max(1) as u64),
            inch,
        })
    }

    /// Ends reading `r` with the last reading's tail from its checkpoint `k` on.
    /// Returns where the rest was joined: (new, old) places of its first
    /// motion and of its first thread.
    fn splice(&mut self, r: &mut Reading, mut t: Tail, k: usize) -> ((usize, usize), (usize, usize)) {
        let cp = &t.checkpoints[k].snap;
        let joined = ((r.asm.moves.len(), cp.moves()), (r.asm.threads.len(), cp.threads()));
        let (dm, dt, dd) = (
            r.asm.moves.len() as isize - cp.moves() as isize,
            r.asm.threads.len() as isize - cp.threads() as isize,
            r.diags.len() as isize - cp.diagnostics() as isize,
        );
        let (skip_m, skip_t, skip_d) = (cp.moves() - t.at.0, cp.threads() - t.at.1, cp.diagnostics() - t.at.2);
        self.join = Some(Join { old: cp.threads(), new: r.asm.threads.len(), lines: t.edited_lines, shift: t.shift });
        let s = t.shift;
        if t.whole_moves {
            // The new reading's motions replace the last one's up to the join;
            // the rest stay in place (moved once when the counts differ).
            let keep = (t.at.0 + skip_m).min(t.moves.len());
            let mut all = std::mem::take(&mut t.moves);
            all[keep..].iter_mut().for_each(|m| m.span = s.span(m.span));
            all.splice(..keep, std::mem::take(&mut r.asm.moves));
            r.asm.moves = all;
        } else {
            let rest = t.moves.drain(skip_m.min(t.moves.len())..);
            r.asm.moves.extend(rest.map(|mut m| {
                m.span = s.span(m.span);
                m
            }));
        }
        let shift_thread = |th: &mut Thread| {
            if dm != 0 {
                th.first_move = th.first_move.saturating_add_signed(dm);
                th.passes.iter_mut().for_each(|p| p.moves = p.moves.shifted(dm));
            }
        };
        if t.whole_threads {
            // As the motions: the new reading's threads replace the last one's up to the join.
            let keep = (t.at.1 + skip_t).min(t.threads.len());
            let mut all = std::mem::take(&mut t.threads);
            all[keep..].iter_mut().for_each(shift_thread);
            let mut new = std::mem::take(&mut r.asm.threads);
            if new.len() == keep {
                // As many threads as before the join (an edit of a number): in place.
                all[..keep].iter_mut().zip(new).for_each(|(old, th)| *old = th);
                r.asm.threads = all;
            } else {
                new.extend(all.drain(keep..));
                r.asm.threads = new;
            }
        } else {
            let rest = t.threads.drain(skip_t.min(t.threads.len())..);
            r.asm.threads.extend(rest.map(|mut th| {
                shift_thread(&mut th);
                th
            }));
        }
        let diags = t.diags.split_off(skip_d.min(t.diags.len()));
        r.diags.extend_shifted(diags, s);
        let line = t.checkpoints[k].line;
        // Loops before the joined checkpoint may have run other numbers of times.
        let recount = r.exec.repeated as i64 - cp.repeated() as i64;
        self.last_repeated = t.repeated.0.saturating_add_signed(recount);
        // The reads up to the joined checkpoint are the new reading's; after it, the last reading's.
        let mut reads = Some(std::mem::take(&mut r.reads));
        for mut c in t.checkpoints.drain(k..) {
            c.snap.shift(dm, dt, dd, s);
            let snap = c.snap.recounted(recount);
            let reads = reads.take().unwrap_or_else(|| {
                c.reads.shift(s);
                c.reads
            });
            self.checkpoints.push(Checkpoint { offset: s.pos(c.offset), line: c.line, snap, reads });
        }
        t.last_reads.shift(s);
        self.last_reads = std::mem::take(&mut t.last_reads);
        // The line starts before the joined line are the new reading's when it
        // recorded them all (in order); else the rest is scanned when finishing.
        if self.line_starts.len() + 1 >= line as usize {
            self.line_starts.truncate(line as usize - 1);
            let from = (line as usize - 1).min(t.line_starts.len());
            self.line_starts.extend(t.line_starts[from..].iter().map(|&p| s.pos(p as usize) as u32));
        }
        self.inch = t.inch;
        joined
    }
    fn reset(&mut self, text: &str) {
        self.stopped_at = None;
        self.checkpoints.clear();
        self.line_starts.clear();
        self.text.clear();
        self.text.push_str(text);
        self.raw_diags = Diagnostics::default();
        self.advice.clear();
        self.resumed_at = 1;
    }
}

#[cfg(test)]
mod tests;
