//! What the program flow sees besides its own state while it runs one
//! block: the text, its labels (built on first use), the diagnostics, the
//! interpreter's modal state, the settings and rules, and where the block
//! is; lookups note how far into the text their answer depended.

use super::index::{At, Entry, Index};
use super::stmt;
use crate::controller::Rules;
use crate::diagnostic::Diagnostics;
use crate::message as msg;
use crate::settings::Settings;
use crate::span::Span;
use crate::state::Modal;

use super::eval::Fail;
use super::expr::Flavor;

/// What the flow needs besides its own state for one block.
pub struct Ctx<'a> {
    /// The program text.
    pub text: &'a str,
    /// The labels of the text, built on first use.
    pub index: &'a mut Option<Index>,
    /// Diagnostics.
    pub diags: &'a mut Diagnostics,
    /// The interpreter's modal state (system variables read it).
    pub modal: &'a Modal,
    /// Settings.
    pub settings: &'a Settings,
    /// The controller's rules.
    pub rules: &'static Rules,
    /// The line just read.
    pub here: At,
    /// The line after it.
    pub next: At,
    /// Where to go next, when not to `next`.
    pub jump: Option<At>,
    /// The furthest byte a lookup depended on (a later edit there could change its answer).
    pub read_to: usize,
    /// Whether a label was looked up.
    pub looked: bool,
}

impl Ctx<'_> {
    /// The labels of the text.
    fn index(&mut self) -> &Index {
        self.looked = true;
        let linuxcnc = self.rules.macros.as_ref().is_some_and(|m| m.flavor == Flavor::LinuxCnc);
        self.index.get_or_insert_with(|| Index::build(self.text, linuxcnc))
    }

    /// Notes that an answer depended on the text up to the entry found, or
    /// to its end when nothing was found.
    fn found(&mut self, e: Option<Entry>) -> Option<Entry> {
        let to = e.map_or(self.text.len(), |e| e.next.offset);
        self.read_to = self.read_to.max(to);
        e
    }

    /// Program `O(n)`, the first of that number in the text.
    pub fn program(&mut self, n: u32) -> Option<Entry> {
        let e = self.index().program(n);
        self.found(e)
    }

    /// Sequence number `n` in the program holding `from` (forward first, then from its start).
    pub fn sequence(&mut self, n: u32, from: usize) -> Option<Entry> {
        let (_, end) = self.index().program_range(from);
        self.read_to = self.read_to.max(end);
        self.index().sequence(n, from)
    }

    /// The first `END m` after `offset`.
    pub fn end_of_loop(&mut self, m: u8, offset: usize) -> Option<Entry> {
        let e = self.index().end_of_loop(m, offset);
        self.found(e)
    }

    /// The next o-word line of `label` after `offset` with one of `kws`.
    pub fn next_oword(&mut self, label: &str, offset: usize, kws: &[stmt::OKw]) -> Option<(stmt::OKw, Entry)> {
        let e = self.index().next_oword(label, offset, kws);
        self.found(e.map(|(_, e)| e));
        e
    }

    /// The last o-word line of `label` before `offset` with one of `kws`.
    pub fn prev_oword(&mut self, label: &str, offset: usize, kws: &[stmt::OKw]) -> Option<(stmt::OKw, Entry)> {
        self.index().prev_oword(label, offset, kws)
    }

    /// The `sub` line of `label`.
    pub fn sub(&mut self, label: &str) -> Option<Entry> {
        let e = self.index().sub(label);
        self.found(e)
    }

    /// Records an alarm or note.
    pub fn diag(&mut self, t: &'static msg::Template, span: Span, a: msg::Args) {
        self.diags.push(t, span, a);
    }

    /// Records a failed evaluation.
    pub fn fail(&mut self, f: Fail) {
        self.diags.push(f.template, f.span, f.args);
    }
}
