//! Incremental planning for an editor: re-plan only from the first block an
//! edit changed.
//!
//! While reading a program the [`Planner`] keeps a snapshot of the
//! interpreter every [`CHECKPOINT_EVERY`] blocks. When the text changes, it
//! finds the first changed byte, goes back to the last snapshot before it,
//! cuts the motions, threads and diagnostics back to what they were there,
//! and reads on from that block. Depths, advice and shop-floor figures of
//! the threads completed before that block are kept (with their
//! diagnostics); the threads read again are finished anew. The result is
//! the plan a full re-plan would give; the tests check that for random edits.

use crate::diagnostic::{Code, Diagnostics};
use crate::plan::{Plan, Reading, Snapshot, finish, finish_thread, finish_with, lexer_for};
use crate::settings::Settings;
use crate::span::Span;

/// Blocks between two snapshots.
pub const CHECKPOINT_EVERY: usize = 256;

struct Checkpoint {
    /// Byte offset of the block about to be read.
    offset: usize,
    /// Its 1-based line.
    line: u32,
    /// The reading before it.
    snap: Snapshot,
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
    advice: Vec<Vec<(Code, String, Span)>>,
    inch: bool,
    line_starts: Vec<u32>,
    plan: Option<Plan>,
    resumed_at: u32,
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

    /// The line the last plan resumed reading at (1 when it read everything).
    pub fn resumed_at(&self) -> u32 {
        self.resumed_at
    }

    /// The last plan, if any.
    pub fn last(&self) -> Option<&Plan> {
        self.plan.as_ref()
    }

    /// Plans `text`, reading only from the last checkpoint before the first change.
    pub fn plan(&mut self, text: &str) -> &Plan {
        let changed_at = first_difference(&self.text, text);
        let resume = match self.plan.as_ref() {
            Some(_) => self.checkpoints.iter().rposition(|c| c.offset <= changed_at),
            None => None,
        };
        let mut r = Reading::new(&self.settings, if resume.is_some() { 0 } else { text.len() });
        let Some(mut lexer) = lexer_for(text, &self.settings, &mut r.diags) else {
            self.reset(text);
            return self.plan.insert(finish(text, &self.settings, r.outputs(), Vec::new()));
        };
        let mut kept_threads = 0;
        match resume {
            Some(ci) => {
                let old = self.plan.take().expect("a plan to resume");
                r.asm.moves = old.moves;
                r.asm.threads = old.threads;
                r.diags = std::mem::take(&mut self.raw_diags);
                self.checkpoints.truncate(ci + 1);
                let cp = &self.checkpoints[ci];
                r.restore(&cp.snap);
                kept_threads = cp.snap.threads();
                lexer.seek(cp.offset, cp.line);
                self.line_starts.truncate(cp.line as usize - 1);
                self.resumed_at = cp.line;
            }
            None => {
                self.checkpoints.clear();
                self.line_starts.clear();
                self.advice.clear();
                self.resumed_at = 1;
            }
        }
        let checkpoints = &mut self.checkpoints;
        r.run(&mut lexer, CHECKPOINT_EVERY, |offset, line, r| {
            checkpoints.push(Checkpoint { offset, line, snap: r.snapshot() });
        });
        self.line_starts.extend(lexer.take_line_starts());
        self.text.clear();
        self.text.push_str(text);
        let out = r.outputs();
        self.raw_diags = out.diags.clone();
        let inch = out.inch;
        self.inch = inch;
        // Threads complete before the resume point are finished already and
        // their advice is kept; the rest are finished now, every message
        // formatted so it can be kept for the next edit.
        let advice = &mut self.advice;
        advice.truncate(kept_threads);
        let settings = &self.settings;
        let plan = finish_with(text, settings, out, self.line_starts.clone(), |threads, moves, spans, _| {
            for i in advice.len()..threads.len() {
                let mut d = Diagnostics::with_limit(usize::MAX);
                finish_thread(threads, i, moves, settings, inch, text, &mut d, spans);
                advice.push(d.into_items());
            }
            let mut all = Diagnostics::with_limit(usize::MAX);
            for (code, message, span) in advice.iter().flatten() {
                all.push(*code, *span, message.clone());
            }
            all
        });
        self.plan.insert(plan)
    }

    fn reset(&mut self, text: &str) {
        self.checkpoints.clear();
        self.line_starts.clear();
        self.text.clear();
        self.text.push_str(text);
        self.raw_diags = Diagnostics::default();
        self.advice.clear();
        self.resumed_at = 1;
    }
}

/// Byte offset of the first difference between `a` and `b` (the shorter
/// length when one is a prefix of the other).
fn first_difference(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let n = a.len().min(b.len());
    // Compare in chunks first: long unchanged prefixes are the common case.
    let mut i = 0;
    while i + 64 <= n && a[i..i + 64] == b[i..i + 64] {
        i += 64;
    }
    while i < n && a[i] == b[i] {
        i += 1;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::Dialect;

    #[test]
    fn first_difference_finds_the_edit() {
        assert_eq!(first_difference("abc", "abc"), 3);
        assert_eq!(first_difference("abc", "abd"), 2);
        assert_eq!(first_difference("", "x"), 0);
        let long = "G01 X1\n".repeat(100);
        let mut edited = long.clone();
        edited.replace_range(500..501, "9");
        assert_eq!(first_difference(&long, &edited), 500);
    }

    /// An edit near the end resumes at the last checkpoint before it and gives the full plan.
    #[test]
    fn late_edit_resumes_and_matches_a_full_plan() {
        let s = Settings::new(Dialect::Gsk980tdc);
        let pass = "G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n";
        let mut text = pass.repeat(300);
        let mut p = Planner::new(s.clone());
        p.plan(&text);
        assert_eq!(p.resumed_at(), 1);
        text.push_str("X46.5\nG32 Z13\nG00 X58\nZ70\n");
        let inc = p.plan(&text).clone();
        // 1500 blocks: checkpoints at 257, 513, ..., 1281; the edit is past 1500.
        assert_eq!(p.resumed_at(), 1281);
        assert_eq!(inc, crate::plan(&text, &s));
        // An edit at the top starts over.
        text.insert_str(0, "G21\n");
        let inc = p.plan(&text).clone();
        assert_eq!(p.resumed_at(), 1);
        assert_eq!(inc, crate::plan(&text, &s));
    }
}
