//! What the last reading had after the resume point ([`Tail`]), where the
//! new reading may join it, and where its threads rejoin the new plan ([`Join`]).

use super::Checkpoint;
use crate::diagnostic::Item;
use crate::exec::reads::Reads;
use crate::motion::Move;
use crate::plan::Snapshot;
use crate::span::Shift;
use crate::thread::Thread;

/// What the last reading had after the resume point, kept in case the new
/// reading comes back to the same state (see the module documentation).
pub(super) struct Tail {
    /// Checkpoints after the resume point.
    pub(super) checkpoints: Vec<Checkpoint>,
    /// Motions, threads and diagnostics from the resume point on (the
    /// motions: all of the last reading's when `whole_moves`).
    pub(super) moves: Vec<Move>,
    /// Whether `moves` holds every motion of the last reading (the ones
    /// before the resume point were fewer than the rest: they were copied
    /// for the new reading, and the rest stay where they are).
    pub(super) whole_moves: bool,
    /// Threads from the resume point on: all of the last reading's when
    /// `whole_threads` (those before the resume point moved out for the new
    /// reading, empty threads left in their places).
    pub(super) threads: Vec<Thread>,
    pub(super) whole_threads: bool,
    pub(super) diags: Vec<Item>,
    /// Their counts at the resume point.
    pub(super) at: (usize, usize, usize),
    /// Every line start of the last text.
    pub(super) line_starts: Vec<u32>,
    /// Where the bytes common to both texts' ends begin, in the new text.
    pub(super) common_from: usize,
    /// How the edit moved the old positions.
    pub(super) shift: Shift,
    /// The first of `checkpoints` after which the last reading never read
    /// the edited lines (nor, if the edit changed a label, looked one up):
    /// the new reading may join it there.
    pub(super) joinable_from: usize,
    /// Where (new offsets) the checkpoints from `joinable_from` on are.
    pub(super) places: std::collections::HashSet<usize>,
    /// What the last reading depended on after its last checkpoint.
    pub(super) last_reads: Reads,
    /// Blocks the last reading ran again in all, and the most allowed.
    pub(super) repeated: (u64, u64),
    /// The first changed byte (old text) and the old lines the edit touched.
    pub(super) edited_lines: (u32, u32),
    pub(super) inch: bool,
}

/// Where the last reading's threads rejoin the new plan: the first of its
/// threads kept, its index in the new plan, the edit's lines (old text,
/// inclusive) and how positions moved.
pub(super) struct Join {
    pub(super) old: usize,
    pub(super) new: usize,
    pub(super) lines: (u32, u32),
    pub(super) shift: Shift,
}

impl Tail {
    /// The index of the last reading's checkpoint that the new reading meets
    /// at byte `offset`, line `line` with state `snap`: at the same line, the
    /// same place in the common end of both texts, and the same state.
    pub(super) fn meets(&self, offset: usize, line: u32, snap: &Snapshot) -> Option<usize> {
        if snap.dropped() {
            return None;
        }
        let (total, limit) = self.repeated;
        (self.joinable_from..self.checkpoints.len()).find(|&k| {
            let c = &self.checkpoints[k];
            // Blocks run again are counted on from the new reading's count: the
            // last reading's rest must stay within the limit with it.
            let recount = snap.repeated() as i64 - c.snap.repeated() as i64;
            c.line == line
                && self.shift.pos(c.offset) == offset
                && total <= limit
                && total.saturating_add_signed(recount) <= limit
                && snap.same_state(
                    &c.snap
                        .shifted(
                            snap.moves() as isize - c.snap.moves() as isize,
                            snap.threads() as isize - c.snap.threads() as isize,
                            0,
                            self.shift,
                        )
                        .recounted(recount),
                )
        })
    }
}

/// The first of the last reading's checkpoints `later` after which it
/// never read the `edited` bytes `[from, to)` of the old text, nor looked
/// a label up if the edit changed one (`labels`, asked only when needed);
/// `None` when even its last stretch did.
pub(super) fn joinable_from(
    later: &[Checkpoint],
    last: &Reads,
    edited: (usize, usize),
    labels: impl FnOnce() -> bool,
) -> Option<usize> {
    let mut labels = Some(labels);
    let mut changed = None;
    let mut dirty = |r: &Reads| {
        r.touches(edited.0, edited.1)
            || (r.looked && *changed.get_or_insert_with(|| labels.take().is_some_and(|f| f())))
    };
    if dirty(last) {
        return None;
    }
    // Reads after checkpoint j are those of the checkpoints after it and the last stretch.
    let mut from = later.len();
    for j in (0..later.len()).rev() {
        from = j;
        if dirty(&later[j].reads) {
            break;
        }
    }
    (from < later.len()).then_some(from)
}

impl Join {
    /// The advice of new thread `i` when it is a kept thread of the last
    /// reading (the one before it kept too) whose text — from after the
    /// thread before it to its first line, where its comments are looked
    /// for — the edit did not touch: the last
    /// reading's, moved with the edit (taken out of `old`, which holds the
    /// last plan's advice after its first `dropped` threads: each is taken once).
    pub(super) fn advice_of(
        &self,
        threads: &[Thread],
        i: usize,
        old: &mut [Vec<Item>],
        dropped: usize,
    ) -> Option<Vec<Item>> {
        if i <= self.new {
            return None;
        }
        let j = (i - self.new + self.old).checked_sub(dropped)?;
        let (t, before) = (&threads[i], &threads[i - 1]);
        let from = (before.end_line + 1).min(t.line);
        if from <= self.lines.1 && t.line >= self.lines.0 {
            return None;
        }
        let mut items = std::mem::take(old.get_mut(j)?);
        items.iter_mut().for_each(|item| item.1 = self.shift.span(item.1));
        Some(items)
    }
}
