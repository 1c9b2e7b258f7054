//! What a plan kept of the plan before it ([`Changed`]): the motions and
//! threads before the resume point, and those of the last reading's rest
//! after the join, so that what is worked out from them (content keys,
//! drawing pieces) can be taken from the last plan's instead of again.

/// Which of a plan's motions and threads are the last plan's (see the
/// module documentation). A motion kept is the same but for its byte span
/// (an edit before it moves it); a thread kept is the same but for where its
/// motions are in the plan (`first_move`, its passes' `moves`) and its byte
/// spans.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Changed {
    /// Motions before this one are the last plan's, at the same place.
    pub moves_kept: usize,
    /// Threads before this one are the last plan's, at the same place.
    pub threads_kept: usize,
    /// Where the last reading's rest was joined: its motions from `.0` on
    /// (new plan) are the last plan's from `.1` on.
    pub moves_rejoined: Option<(usize, usize)>,
    /// The same for the threads (those finished anew excepted: `refinished`).
    pub threads_rejoined: Option<(usize, usize)>,
    /// Threads of the new plan finished anew (their depths, advice and
    /// figures worked out again), in order.
    pub refinished: Vec<usize>,
}

impl Changed {
    /// The index in the last plan of thread `i` of the new plan when it is
    /// the last plan's thread, unchanged.
    pub fn thread_was(&self, i: usize) -> Option<usize> {
        if self.refinished.binary_search(&i).is_ok() {
            return None;
        }
        if i < self.threads_kept {
            return Some(i);
        }
        self.threads_rejoined.and_then(|(new, old)| (i >= new).then(|| i - new + old))
    }
}
