//! Diagnostics: alarms, warnings and advice, each with a stable code and a
//! source position.

use std::borrow::Cow;

use serde::Serialize;

use crate::message::{Args, Lang, Message, Template};
use crate::span::{LineIndex, Span};

mod seen;
use seen::Seen;

pub use crate::code::{Code, Severity};

impl Severity {
    /// The word a reader sees for it (the command line's summary, an
    /// element's list): alarm, warning or note.
    pub fn word(self) -> &'static crate::message::Phrase {
        use crate::message::words as w;
        match self {
            Severity::Error => &w::ALARM,
            Severity::Warning => &w::WARNING,
            Severity::Info => &w::NOTE,
        }
    }
}

/// A finding before it is placed at a span: its template (with the code)
/// and arguments. Pure planning steps return these; the caller knows where
/// they belong.
pub type Finding = Message;

/// The lines of the calls (`M98`, `G65`, LinuxCNC `call`) that led to a
/// line, innermost first; `None` in the main program. Shared by every
/// diagnostic of one call.
pub type Via = Option<std::sync::Arc<[u32]>>;

/// A kept diagnostic before its position is resolved.
pub type Item = (Message, Span, Via);

/// Where an edit changed the text the last diagnostics were finished on:
/// bytes `changed_at..new_end` of the new text took the place of bytes
/// `changed_at..new_end - by` of the old one; the rest of both is the same.
#[derive(Clone, Copy, Debug)]
pub struct TextEdit {
    /// The first byte that differs.
    pub changed_at: usize,
    /// Where the bytes common to both ends begin, in the new text.
    pub new_end: usize,
    /// The new text's length less the old one's.
    pub by: isize,
}

/// Diagnostics found after a reading (a thread's advice), each kept as it
/// was found or borrowed from where it is kept, up to a room; the rest counted.
#[derive(Debug, Default)]
pub struct Found<'a> {
    items: Vec<Cow<'a, Item>>,
    room: usize,
    dropped: usize,
    first_dropped: Option<Span>,
    /// The distinct items, once past the room (as [`Diagnostics`] keeps them).
    seen: Option<Seen>,
}

impl<'a> Found<'a> {
    /// Room for `room` diagnostics.
    pub fn with_room(room: usize) -> Found<'a> {
        Found { room, ..Found::default() }
    }

    /// Keeps `item` while there is room, else counts it dropped; the room
    /// is for distinct diagnostics, as a collector's ([`Diagnostics`]).
    pub fn push(&mut self, item: Cow<'a, Item>) {
        if self.items.len() < self.room {
            self.items.push(item);
            self.seen = None;
        } else if seen::keeps(&mut self.seen, &self.items, self.room, &item) {
            self.items.push(item);
        } else {
            self.dropped += 1;
            earliest(&mut self.first_dropped, item.1);
        }
    }

    /// What a collector kept and dropped (its room is this one's).
    pub fn of(d: Diagnostics) -> Found<'a> {
        let mut f = Found::with_room(usize::MAX);
        f.items.extend(d.items.into_iter().map(Cow::Owned));
        (f.dropped, f.first_dropped) = (d.dropped, d.first_dropped);
        f
    }

    /// How many are kept.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// Whether none is kept.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }
}

/// One finding about the program, positioned at a span of the source.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Diagnostic {
    /// Severity (fixed by the code).
    pub severity: Severity,
    /// Stable code.
    pub code: Code,
    /// Human-readable message, in English.
    pub message: String,
    /// 1-based line of the span start.
    pub line: u32,
    /// 1-based column (characters) of the span start.
    pub column: u32,
    /// 1-based line of the span end.
    pub end_line: u32,
    /// 1-based column of the span end (exclusive).
    pub end_column: u32,
    /// Byte span in the source.
    pub span: Span,
    /// The message's template in the catalogue.
    #[serde(skip)]
    pub template: &'static Template,
    /// The values the message names (numbers, texts kept verbatim).
    pub args: Args,
    /// Inside a subprogram or macro: the 1-based lines of the calls that
    /// led here, innermost first (the call chain).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub via: Vec<u32>,
    /// How many times the program raised it: a loop or a subprogram run
    /// again says the same at the same place after the same calls, and the
    /// list keeps one of them (1 for a diagnostic raised once; serialised
    /// only when more).
    #[serde(skip_serializing_if = "is_once")]
    pub repeats: u32,
    /// The key of the message, worked out once when the diagnostic is made
    /// (see [`Diagnostic::message_key`]).
    #[serde(skip)]
    key: u64,
}

impl Diagnostic {
    /// A key of the message (template and arguments): equal messages have
    /// equal keys, in every language.
    pub fn message_key(&self) -> u64 {
        self.key
    }

    /// The message in `lang`.
    pub fn render(&self, lang: Lang) -> std::borrow::Cow<'_, str> {
        match lang {
            Lang::En => std::borrow::Cow::Borrowed(&self.message),
            _ => std::borrow::Cow::Owned(crate::message::render(self.template, &self.args, lang)),
        }
    }
}

/// Collects diagnostics while a program is read.
#[derive(Clone, Debug, Default)]
pub struct Diagnostics {
    items: Vec<Item>,
    limit: usize,
    dropped: usize,
    first_dropped: Option<Span>,
    via: Via,
    /// The distinct items among `items`, once past the limit (built when
    /// first needed; forgotten when the items change but by a push).
    seen: Option<Seen>,
}

impl Diagnostics {
    /// A collector that keeps at most `limit` distinct diagnostics (the
    /// rest are counted; one said again past the limit is kept and counted).
    pub fn with_limit(limit: usize) -> Diagnostics {
        Diagnostics { items: Vec::new(), limit, dropped: 0, first_dropped: None, via: None, seen: None }
    }

    /// Sets the call chain the next diagnostics are found in.
    pub fn set_via(&mut self, via: Via) {
        self.via = via;
    }

    /// The call chain diagnostics are found in now.
    pub fn via(&self) -> &Via {
        &self.via
    }

    /// Records a diagnostic: `template` with `args` at `span`.
    pub fn push(&mut self, template: &'static Template, span: Span, args: Args) {
        self.push_message(Message::new(template, args), span);
    }

    /// Records a finding at `span`.
    pub fn push_message(&mut self, message: Message, span: Span) {
        self.keep(span, |via| (message, span, via.clone()));
    }

    /// Keeps the item `make` gives (from the current call chain) while
    /// there is room; else counts one dropped at `span`. The limit counts
    /// distinct diagnostics: past it, one said again (the same message at
    /// the same place after the same calls: a loop run again) is still
    /// kept, up to [`seen::REPEATS`] times the limit in all, so a loop's
    /// repeats neither crowd out what comes after it nor count as dropped.
    fn keep(&mut self, span: Span, make: impl FnOnce(&Via) -> Item) {
        if self.items.len() < self.limit {
            self.items.push(make(&self.via));
            self.seen = None;
            return;
        }
        let item = make(&self.via);
        if seen::keeps(&mut self.seen, &self.items, self.limit, &item) {
            self.items.push(item);
        } else {
            self.drop_one(span);
        }
    }

    /// How many more distinct diagnostics there is room for.
    pub fn room(&mut self) -> usize {
        let seen = self.seen.get_or_insert_with(|| Seen::of(&self.items));
        self.limit.saturating_sub(seen.distinct())
    }

    fn drop_one(&mut self, span: Span) {
        self.dropped += 1;
        earliest(&mut self.first_dropped, span);
    }

    /// Records a diagnostic whose arguments are only worked out when it will be kept.
    pub fn push_with(&mut self, template: &'static Template, span: Span, args: impl FnOnce() -> Args) {
        self.keep(span, |via| (Message::new(template, args()), span, via.clone()));
    }

    /// Whether an error-level diagnostic was recorded.
    pub fn has_error(&self) -> bool {
        self.items.iter().any(|(m, _, _)| m.code().severity() == Severity::Error)
    }

    /// Number recorded so far.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// True when nothing was recorded.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// How many were dropped over the limit.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Cuts the list back to `len` kept and `dropped` dropped diagnostics.
    pub fn truncate(&mut self, len: usize, dropped: usize, first_dropped: Option<Span>) {
        self.items.truncate(len);
        self.seen = None;
        self.dropped = dropped;
        self.first_dropped = first_dropped;
    }

    /// Where the first dropped diagnostic was.
    pub fn first_dropped(&self) -> Option<Span> {
        self.first_dropped
    }

    /// Moves every diagnostic kept so far to the end of `out` (this collector keeps its room).
    pub fn move_into(&mut self, out: &mut Vec<Item>) {
        out.append(&mut self.items);
        self.seen = None;
    }

    /// Takes the diagnostics from the `len`-th on out of the collector (none were dropped).
    pub fn split_off(&mut self, len: usize) -> Vec<Item> {
        self.seen = None;
        self.items.split_off(len.min(self.items.len()))
    }

    /// Appends `items` (kept from a reading of the text before an edit that
    /// moved positions as `s` says), keeping this collector's limit.
    pub fn extend_shifted(&mut self, items: Vec<Item>, s: crate::span::Shift) {
        for (message, span, via) in items {
            self.push_item((message, s.span(span), via));
        }
    }

    /// Moves the kept diagnostics' spans as an edit moved the text (the
    /// first dropped one's place is a snapshot's, moved with the snapshot).
    pub fn shift_spans(&mut self, s: crate::span::Shift) {
        self.seen = None;
        for item in &mut self.items {
            item.1 = s.span(item.1);
        }
    }

    /// Records a diagnostic with its own call chain.
    pub fn push_item(&mut self, item: Item) {
        self.keep(item.1, |_| item);
    }

    /// The diagnostics kept, in the order they came.
    pub fn into_items(self) -> Vec<Item> {
        self.items
    }

    /// The limit this collector keeps to.
    pub fn limit(&self) -> usize {
        self.limit
    }

    /// Resolves spans to line/column positions, sorted by position; when
    /// some were dropped, a last `more-diagnostics` note says how many, at
    /// the first one dropped.
    pub fn finish(self, text: &str, index: &LineIndex) -> Vec<Diagnostic> {
        self.finish_after(text, index, Vec::new(), None)
    }

    /// [`Diagnostics::finish`], taking the English text of a message equal
    /// to one in `before` (the last plan's diagnostics) from there instead
    /// of writing it again: after an edit most messages are the last
    /// plan's, moved or not. The texts are moved out of `before`, not copied.
    /// With `edit` (how the text changed since `before` was finished), a
    /// diagnostic of `before` at the same place in text the edit left alone,
    /// with the same message and calls, is taken whole: only its line
    /// numbers move.
    pub fn finish_after(
        self,
        text: &str,
        index: &LineIndex,
        before: Vec<Diagnostic>,
        edit: Option<TextEdit>,
    ) -> Vec<Diagnostic> {
        let more = self.more();
        let items = self.items.into_iter().map(Cow::Owned);
        finish_items(&mut items.chain(more.map(Cow::Owned)), text, index, before, edit)
    }

    /// [`Diagnostics::finish_after`] of this collector's diagnostics (left
    /// as they are), then `found`'s, then `extra`'s, as one collector with
    /// their dropped ones counted together: a message is copied only when it
    /// is not one of `before`'s taken whole.
    pub fn finish_parts(
        &self,
        found: Found<'_>,
        extra: Diagnostics,
        text: &str,
        index: &LineIndex,
        (before, edit): (Vec<Diagnostic>, Option<TextEdit>),
    ) -> Vec<Diagnostic> {
        let mut all = Diagnostics { dropped: self.dropped, first_dropped: self.first_dropped, ..Default::default() };
        for (dropped, first) in [(found.dropped, found.first_dropped), (extra.dropped, extra.first_dropped)] {
            all.dropped += dropped;
            if let Some(f) = first {
                earliest(&mut all.first_dropped, f);
            }
        }
        let items =
            self.items.iter().map(Cow::Borrowed).chain(found.items).chain(extra.items.into_iter().map(Cow::Owned));
        finish_items(&mut items.chain(all.more().map(Cow::Owned)), text, index, before, edit)
    }

    /// The `more-diagnostics` note, when some were dropped: how many, at the first one dropped.
    fn more(&self) -> Option<Item> {
        let span = self.first_dropped.filter(|_| self.dropped > 0)?;
        Some((Message::new(&crate::message::MORE_DIAGNOSTICS, crate::args![n = self.dropped]), span, None))
    }
}

/// Makes `first` `span` when `span` begins earlier (or `first` is none).
fn earliest(first: &mut Option<Span>, span: Span) {
    if first.is_none_or(|f| span.start < f.start) {
        *first = Some(span);
    }
}

/// The diagnostics of `items`, positioned and sorted (see [`Diagnostics::finish_after`]).
fn finish_items<'a>(
    items: &mut dyn Iterator<Item = Cow<'a, Item>>,
    text: &str,
    index: &LineIndex,
    before: Vec<Diagnostic>,
    edit: Option<TextEdit>,
) -> Vec<Diagnostic> {
    let mut written = Written::of(before, edit);
    let mut out: Vec<Diagnostic> = Vec::with_capacity(items.size_hint().0);
    for item in items {
        let (m, span, via) = &*item;
        if let Some(d) = written.whole(m, *span, via.as_deref(), index) {
            written.taken.entry(d.key).or_insert(out.len());
            out.push(d);
            continue;
        }
        let (m, span, via) = item.into_owned();
        let (start, end) = index.locate_span(text, span.start as usize, span.end as usize);
        let code = m.code();
        let key = message_key(m.template, &m.args);
        let message = written.text(key, &m, &out);
        out.push(Diagnostic {
            severity: code.severity(),
            code,
            message,
            template: m.template,
            args: m.args,
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
            span,
            via: via.map_or_else(Vec::new, |v| v.to_vec()),
            repeats: 1,
            key,
        });
    }
    seen::collapse(&mut out);
    crate::order::sort_by_key(&mut out, |d| (d.span.start, std::cmp::Reverse(d.severity)));
    out
}

/// Whether a diagnostic was raised once (its `repeats` is not serialised).
fn is_once(n: &u32) -> bool {
    *n == 1
}

/// The English texts of earlier diagnostics, found by their message
/// (template and arguments), wherever they were: each moved out once, then
/// copied from the new diagnostic that took it.
struct Written {
    /// The last plan's diagnostics, in order of place (as finished).
    before: Vec<Diagnostic>,
    by_key: std::collections::HashMap<u64, usize, crate::hash::BuildKeyHasher>,
    /// Where among the new diagnostics the first with each key is.
    taken: std::collections::HashMap<u64, usize, crate::hash::BuildKeyHasher>,
    /// How the text changed since `before` was finished.
    edit: Option<TextEdit>,
}

impl Written {
    /// The texts of `before`.
    fn of(before: Vec<Diagnostic>, edit: Option<TextEdit>) -> Written {
        let mut by_key = std::collections::HashMap::default();
        by_key.reserve(before.len());
        for (i, d) in before.iter().enumerate() {
            by_key.insert(d.key, i);
        }
        Written { before, by_key, taken: std::collections::HashMap::default(), edit }
    }

    /// The diagnostic of `before` that message `m` at `span` after the calls
    /// `via` is again, moved out whole, when the edit left the text from its
    /// line's start to its end as it was: before the first byte changed
    /// (nothing of it moved), or after the last, from a line that begins
    /// after it (its columns are the same; its lines are found again).
    fn whole(&mut self, m: &Message, span: Span, via: Option<&[u32]>, index: &LineIndex) -> Option<Diagnostic> {
        let e = self.edit?;
        let (start, end) = (span.start as usize, span.end as usize);
        let (old, line) = if end < e.changed_at {
            (span, None)
        } else {
            let (line, line_start) = index.line_of(start);
            // The line break before the line is the old text's too.
            if line_start <= e.new_end || end < start {
                return None;
            }
            (span.shifted(-e.by), Some(line))
        };
        let from = self.before.partition_point(|d| d.span.start < old.start);
        let same = |d: &Diagnostic| {
            d.span == old
                && std::ptr::eq(d.template, m.template)
                && !d.message.is_empty()
                && d.args == m.args
                && d.via == via.unwrap_or(&[])
        };
        let i = (from..self.before.len())
            .take_while(|&i| self.before[i].span.start == old.start)
            .find(|&i| same(&self.before[i]))?;
        let d = &mut self.before[i];
        let (message, args, via) =
            (std::mem::take(&mut d.message), std::mem::take(&mut d.args), std::mem::take(&mut d.via));
        let mut out = Diagnostic { message, args, via, span, ..*d };
        if let Some(line) = line {
            out.end_line = (i64::from(out.end_line) + i64::from(line) - i64::from(out.line)) as u32;
            out.line = line;
        }
        Some(out)
    }

    /// The English text of message `m`, whose key is `key`, for the new
    /// diagnostic that goes next in `out` (the new ones so far): copied from
    /// the first of `out` with the same message, else moved out of `before`,
    /// else written.
    fn text(&mut self, key: u64, m: &Message, out: &[Diagnostic]) -> String {
        let same = |d: &Diagnostic| std::ptr::eq(d.template, m.template) && d.args == m.args;
        let first = *self.taken.entry(key).or_insert(out.len());
        let found = match out.get(first) {
            Some(d) => same(d).then(|| d.message.clone()),
            None => self.by_key.get(&key).and_then(|&i| {
                let d = &mut self.before[i];
                (same(d) && !d.message.is_empty()).then(|| std::mem::take(&mut d.message))
            }),
        };
        found.unwrap_or_else(|| m.render(Lang::En))
    }
}

/// A key of a message's template and arguments (equal messages, equal keys).
fn message_key(template: &'static Template, args: &crate::message::Args) -> u64 {
    use std::hash::Hasher;
    let mut h = crate::hash::KeyHasher::default();
    crate::message::hash_message(template, args, &mut h);
    h.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::message::MORE_DIAGNOSTICS;

    fn one(n: i64, at: usize) -> Diagnostics {
        let mut d = Diagnostics::with_limit(10);
        d.push(&MORE_DIAGNOSTICS, Span::new(at, at + 2), crate::args![n = n]);
        d
    }

    #[test]
    fn a_severity_is_named_as_the_json_names_it_and_read_as_its_word() {
        for (s, word) in [(Severity::Error, "alarm"), (Severity::Warning, "warning"), (Severity::Info, "note")] {
            assert_eq!(serde_json::to_string(&s).unwrap(), format!("\"{}\"", s.name()));
            assert_eq!(s.word().text(Lang::En), word);
        }
        assert_eq!(Severity::Error.word().text(Lang::Zh), "报警");
    }

    #[test]
    fn an_equal_message_keeps_the_last_plans_text_wherever_it_moved() {
        let text = "G00 X1\nG00 X2\n";
        let index = LineIndex::new(text);
        let mut before = one(3, 0).finish(text, &index);
        assert_eq!(before[0].message, "3 more diagnostics from here on are not shown (setting limits.diagnostics)");
        // A marked text shows that it was taken, not written again.
        before[0].message = "kept".into();
        let moved = one(3, 7).finish_after(text, &index, before.clone(), None);
        assert_eq!((moved[0].message.as_str(), moved[0].line), ("kept", 2));
        // Other arguments: written anew.
        let other = one(4, 7).finish_after(text, &index, before.clone(), None);
        assert_eq!(other[0].message, "4 more diagnostics from here on are not shown (setting limits.diagnostics)");
        // Two equal messages now where there was one: both take its text.
        let mut two = one(3, 0);
        two.push(&MORE_DIAGNOSTICS, Span::new(7, 9), crate::args![n = 3]);
        let both = two.finish_after(text, &index, before, None);
        assert_eq!(both.iter().map(|d| (d.message.as_str(), d.line)).collect::<Vec<_>>(), [("kept", 1), ("kept", 2)]);
    }
}
