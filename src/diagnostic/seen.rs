//! Diagnostics said again: the same message at the same place after the
//! same calls (a loop or a subprogram run again). The collector keeps such
//! repeats past its limit without counting them against it
//! ([`Seen`]), and the finished list keeps one of each with its count
//! ([`collapse`]).

use std::borrow::Borrow;
use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::hash::Hasher;

use super::{Diagnostic, Item};
use crate::hash::{BuildKeyHasher, KeyHasher};

/// Most items a collector keeps, repeats included, as a multiple of its
/// limit (its memory stays bounded whatever a loop raises).
pub(super) const REPEATS: usize = 16;

/// The key repeats are told by: the message's, the place and the calls.
fn key(message: u64, start: u32, end: u32, via: &[u32]) -> u64 {
    let mut h = KeyHasher::default();
    h.write_u64(message);
    h.write_u32(start);
    h.write_u32(end);
    via.iter().for_each(|&l| h.write_u32(l));
    h.write_usize(via.len());
    h.finish()
}

/// The key of a collector's item.
fn item_key(item: &Item) -> u64 {
    let (m, span, via) = item;
    key(super::message_key(m.template, &m.args), span.start, span.end, via.as_deref().unwrap_or(&[]))
}

/// Whether two items say the same at the same place after the same calls.
fn same(a: &Item, b: &Item) -> bool {
    std::ptr::eq(a.0.template, b.0.template) && a.0.args == b.0.args && a.1 == b.1 && a.2.as_deref() == b.2.as_deref()
}

/// The distinct items of a collector: the first of each, by key.
#[derive(Clone, Debug, Default)]
pub(super) struct Seen {
    first: HashMap<u64, usize, BuildKeyHasher>,
    distinct: usize,
}

impl Seen {
    /// The distinct items among `items`.
    pub(super) fn of<T: Borrow<Item>>(items: &[T]) -> Seen {
        let mut seen = Seen::default();
        for (i, item) in items.iter().enumerate() {
            seen.add(&items[..i], item.borrow(), i);
        }
        seen
    }

    /// Whether `item` says again what one of `items` said.
    fn repeats<T: Borrow<Item>>(&self, items: &[T], item: &Item) -> bool {
        self.first.get(&item_key(item)).is_some_and(|&i| same(items[i].borrow(), item))
    }

    /// Notes `item`, about to be kept at `at` after `items`.
    fn add<T: Borrow<Item>>(&mut self, items: &[T], item: &Item, at: usize) {
        match self.first.entry(item_key(item)) {
            Entry::Vacant(e) => {
                e.insert(at);
                self.distinct += 1;
            }
            // Another item with the same key (a collision): distinct all the same.
            Entry::Occupied(e) if !same(items[*e.get()].borrow(), item) => self.distinct += 1,
            Entry::Occupied(_) => {}
        }
    }

    /// How many distinct items there are.
    pub(super) fn distinct(&self) -> usize {
        self.distinct
    }
}

/// Whether a collector with room for `limit` distinct diagnostics, which
/// holds `limit` or more `items` already (`seen` of them, when worked out),
/// keeps `item` too (noting it): a repeat of one it holds, up to
/// [`REPEATS`] times `limit` items in all, or a distinct one while fewer
/// than `limit` are distinct. Below `limit` items a collector keeps every
/// one (and forgets `seen`).
pub(super) fn keeps<T: Borrow<Item>>(seen: &mut Option<Seen>, items: &[T], limit: usize, item: &Item) -> bool {
    if items.len() >= limit.saturating_mul(REPEATS) {
        return false;
    }
    let s = seen.get_or_insert_with(|| Seen::of(items));
    let kept = s.repeats(items, item) || s.distinct() < limit;
    if kept {
        s.add(items, item, items.len());
    }
    kept
}

/// Keeps the first of each diagnostic said again (the same message at the
/// same place after the same calls), counting them all in its `repeats`: a
/// loop that runs a bad block fifty times lists it once, not fifty times.
pub(super) fn collapse(out: &mut Vec<Diagnostic>) {
    out.iter_mut().for_each(|d| d.repeats = 1);
    if out.len() < 2 {
        return;
    }
    let mut first: HashMap<u64, usize, BuildKeyHasher> = HashMap::default();
    let mut again = vec![false; out.len()];
    for i in 0..out.len() {
        let d = &out[i];
        match first.entry(key(d.key, d.span.start, d.span.end, &d.via)) {
            Entry::Vacant(e) => {
                e.insert(i);
            }
            Entry::Occupied(e) => {
                let j = *e.get();
                let a = &out[j];
                if a.code == d.code && a.via == d.via && a.span == d.span && a.message == d.message {
                    out[j].repeats = out[j].repeats.saturating_add(1);
                    again[i] = true;
                }
            }
        }
    }
    let mut i = 0;
    out.retain(|_| {
        i += 1;
        !again[i - 1]
    });
}
