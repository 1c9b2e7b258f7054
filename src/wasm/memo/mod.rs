//! The side section built again after an edit from the pieces that did not
//! change: each thread's band and dimensions, runs of passes and blocks of
//! other motions are built once and kept by the key of what they are drawn
//! from. [`SideMemo::side`] gives exactly `side(plan)`; an edit to one
//! thread rebuilds that thread's pieces and the spindle axis only.

use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::hash::Hasher;
use std::sync::Arc;

use crate::motion::Move;
use crate::plan::Plan;

use super::keys::{KeyHasher, PlanKeys, combine, move_key, packed_key};
use super::pack::pack;
use crate::diagram::radial::{self, Break};
use crate::diagram::scene::{Item, Pt, Rect, Scene, Shape, Style, ViewKind, hash_points, same_points};
use crate::diagram::section;
use crate::diagram::side::{
    Band, Layout, axis, capped_note, detail_note, grow_focus_grouped, motion_item, pass_items, thread_items,
    unmatched_item, work_extent_in,
};

/// Motions per block of other motions.
const BLOCK: usize = 256;
/// Most passes in one cached run.
const RUN: usize = 16;

/// Where each piece is among the pieces, by key (the keys are hashes
/// already: no second hash with a random seed).
type ByKey = HashMap<u64, usize, crate::hash::BuildKeyHasher>;

/// A run of items with what the whole scene needs of it.
struct Chunk {
    items: Arc<Vec<Item>>,
    bounds: Rect,
    focus: Rect,
    /// Points of the passes' rapids (they may join the focus), and their bounds.
    rapids: Vec<Pt>,
    rapids_box: Rect,
    /// The lowest and highest radius of the items ([`radial::extent`]).
    extent: (f64, f64),
    /// The items drawn through the radial breaks they were last drawn through.
    mapped: Option<(Vec<Break>, Arc<Vec<Item>>)>,
    /// The call of [`SideMemo::side`] that last took it.
    taken: u32,
}

impl Chunk {
    fn of(items: impl IntoIterator<Item = (Item, bool)>) -> Chunk {
        let mut s = Scene::new(ViewKind::Side);
        for (item, focus) in items {
            s.push(item, focus);
        }
        Chunk::from_scene(s)
    }

    fn from_scene(s: Scene) -> Chunk {
        let mut rapids = Vec::new();
        for item in s.items.iter().filter(|i| i.style == Style::Rapid && i.pass.is_some()) {
            item.each_point(|p| rapids.push(p));
        }
        let mut rapids_box = Rect::EMPTY;
        rapids.iter().for_each(|p| rapids_box.add(*p));
        let extent = radial::extent(s.items.iter());
        let items = Arc::new(s.items.into_vec());
        Chunk { items, bounds: s.bounds, focus: s.focus, rapids, rapids_box, extent, mapped: None, taken: 0 }
    }

    /// The items drawn through the breaks `list`: mapped once per list, then
    /// kept; shared with the scenes they are put in.
    fn drawn(&mut self, list: &[Break], shared: &mut Shared) -> Arc<Vec<Item>> {
        if list.is_empty() {
            return self.items.clone();
        }
        match &self.mapped {
            Some((l, items)) if l.as_slice() == list => items.clone(),
            _ => {
                let mut items = (*self.items).clone();
                items.iter_mut().for_each(|i| radial::map_item(list, i));
                shared.share(&mut items);
                let items = Arc::new(items);
                self.mapped = Some((list.to_vec(), items.clone()));
                items
            }
        }
    }
}

/// The points of paths shared between pieces: a path drawn again exactly
/// (a program's repeated sections) holds the same points, so a drawing
/// knows it for a repeat by the address of its points
/// (`draw::paint`, `draw::lines`) without reading them.
#[derive(Default)]
struct Shared {
    /// Points by the hash of their bits.
    points: HashMap<u64, Arc<[Pt]>, crate::hash::BuildKeyHasher>,
}

impl Shared {
    /// Makes the paths among `items` hold the points of an earlier path equal to them, bit for bit.
    fn share(&mut self, items: &mut [Item]) {
        for item in items {
            let (Shape::Polyline { points } | Shape::Polygon { points }) = &mut item.shape else { continue };
            let mut h = KeyHasher::default();
            hash_points(&mut h, points);
            match self.points.entry(h.finish()) {
                Entry::Occupied(e) => {
                    if same_points(e.get(), points) {
                        *points = e.get().clone();
                    }
                }
                Entry::Vacant(e) => {
                    e.insert(points.clone());
                }
            }
        }
    }

    /// Forgets the points no item holds any more.
    fn forget_unused(&mut self) {
        self.points.retain(|_, p| Arc::strong_count(p) > 1);
    }
}

/// The pieces of one call: taken from the last call's by key, or built.
/// They stay in one list, each marked with the call that last took it; the
/// others are dropped at the end of the call ([`Pieces::keep_taken`]).
struct Pieces {
    chunks: Vec<Chunk>,
    index: ByKey,
    shared: Shared,
    /// This call's mark.
    call: u32,
    /// Keys of the pieces built in this call.
    built: Vec<u64>,
    reused: usize,
}

impl Pieces {
    /// Keeps the piece of `key`, built by `make` unless the last call had
    /// it; returns where it is.
    fn take(&mut self, key: u64, make: impl FnOnce() -> Chunk) -> usize {
        match self.index.get(&key) {
            Some(&i) => {
                let c = &mut self.chunks[i];
                if c.taken != self.call {
                    c.taken = self.call;
                    self.reused += 1;
                }
                i
            }
            None => {
                self.built.push(key);
                self.store(key, make())
            }
        }
    }

    /// Puts `c`, just built, under `key` (in place of the piece it had), marked and sharing its points.
    fn store(&mut self, key: u64, mut c: Chunk) -> usize {
        c.taken = self.call;
        if let Some(items) = Arc::get_mut(&mut c.items) {
            self.shared.share(items);
        }
        match self.index.get(&key) {
            Some(&i) => {
                self.chunks[i] = c;
                i
            }
            None => {
                self.chunks.push(c);
                self.index.insert(key, self.chunks.len() - 1);
                self.chunks.len() - 1
            }
        }
    }

    /// [`Pieces::take`] for two pieces built together.
    fn take_pair(&mut self, keys: (u64, u64), make: impl FnOnce() -> (Chunk, Chunk)) -> (usize, usize) {
        if !(self.index.contains_key(&keys.0) && self.index.contains_key(&keys.1)) {
            let (a, b) = make();
            self.built.extend([keys.0, keys.1]);
            return (self.store(keys.0, a), self.store(keys.1, b));
        }
        (self.take(keys.0, || Chunk::of([])), self.take(keys.1, || Chunk::of([])))
    }

    /// Keeps a piece built anyway (it is cheap and rare), under the key of its content.
    fn put(&mut self, chunk: Chunk) -> usize {
        let mut s = Scene::new(ViewKind::Side);
        s.items.push_shared(chunk.items.clone());
        let key = packed_key(&pack(&s));
        self.take(key, || chunk)
    }

    /// Drops the pieces this call did not take: emptied in place, or, once
    /// they are most of the list, left out (`order`, the places of taken
    /// pieces, follows the rest).
    fn keep_taken(&mut self, order: &mut [usize]) {
        let call = self.call;
        let dead = self.chunks.iter().filter(|c| c.taken != call).count();
        if dead * 2 <= self.chunks.len() {
            for c in self.chunks.iter_mut().filter(|c| c.taken != call && !c.items.is_empty()) {
                *c = Chunk::of([]);
            }
            let chunks = &self.chunks;
            self.index.retain(|_, i| chunks[*i].taken == call);
            return;
        }
        let mut to = vec![usize::MAX; self.chunks.len()];
        let mut kept = Vec::with_capacity(self.chunks.len() - dead);
        for (i, c) in std::mem::take(&mut self.chunks).into_iter().enumerate() {
            if c.taken == call {
                to[i] = kept.len();
                kept.push(c);
            }
        }
        self.chunks = kept;
        self.index.retain(|_, i| {
            *i = to[*i];
            *i != usize::MAX
        });
        order.iter_mut().for_each(|i| *i = to[*i]);
    }
}

/// Pieces of the last side section, by key; and how many of the last call's pieces were built.
#[derive(Default)]
pub struct SideMemo {
    chunks: Vec<Chunk>,
    index: ByKey,
    built: usize,
    reused: usize,
    /// Calls so far (the mark of the pieces each took).
    calls: u32,
    /// The points the pieces' paths share.
    shared: Shared,
}

/// One call's pieces: the head and the order, and which were built.
struct Built {
    head: Scene,
    /// Places of the part's filled sections among the memo's, in scene order (after the axis).
    sections: Vec<usize>,
    /// Places of the other pieces among the memo's, in scene order.
    order: Vec<usize>,
}

/// What a piece is, mixed into its key.
#[derive(Clone, Copy)]
enum Tag {
    Back = 1,
    Front = 2,
    Motions = 3,
    Passes = 4,
    Section = 5,
}

impl SideMemo {
    /// An empty memo.
    pub fn new() -> SideMemo {
        SideMemo::default()
    }

    /// `(built, reused)` pieces of the last call.
    pub fn counts(&self) -> (usize, usize) {
        (self.built, self.reused)
    }

    /// The side section of `plan`, whose threads and motions have the keys
    /// `keys` ([`PlanKeys`]); pieces are reused from the last call where
    /// their keys match.
    pub fn side(&mut self, plan: &Plan, keys: &PlanKeys) -> Scene {
        let b = self.build(plan, keys);
        // As `side(plan)`: the axis, the part's section after it (not in the
        // axis's length: `section::apply`), the pieces, then every item through the radial breaks.
        let mut scene = b.head;
        for &i in &b.sections {
            scene.bounds.union(&self.chunks[i].bounds);
        }
        let mut extent = radial::extent(scene.items.iter());
        for e in b.sections.iter().chain(&b.order).map(|&i| self.chunks[i].extent) {
            extent = (crate::num::min(extent.0, e.0), crate::num::max(extent.1, e.1));
        }
        let list = radial::breaks(plan, extent);
        scene.items.iter_mut().for_each(|i| radial::map_item(&list, i));
        // The pieces go in whole, shared: no item is copied.
        for &i in b.sections.iter().chain(&b.order) {
            scene.items.push_shared(self.chunks[i].drawn(&list, &mut self.shared));
        }
        self.shared.forget_unused();
        radial::finish(&list, &mut scene);
        scene.finish();
        scene
    }

    /// Builds or reuses every piece of `plan`'s side section.
    fn build(&mut self, plan: &Plan, keys: &PlanKeys) -> Built {
        let thread_keys = &keys.threads;
        // Each motion's key (the keys given, else worked out: they are the plan's).
        let motion = |k: usize| keys.motions.get(k).copied().unwrap_or_else(|| move_key(&plan.moves[k]));
        self.calls = self.calls.wrapping_add(1);
        let (chunks, index) = (std::mem::take(&mut self.chunks), std::mem::take(&mut self.index));
        let shared = std::mem::take(&mut self.shared);
        let mut pieces = Pieces { chunks, index, shared, call: self.calls, built: Vec::new(), reused: 0 };
        let layout = Layout::of(plan);
        let thread_key = |ti: usize| thread_keys.get(ti).copied().unwrap_or(0);
        // The part's filled sections first (they are put after the axis).
        let mut order = sections(plan, &motion, &mut pieces);
        let n_sections = order.len();
        // Each thread's band and dimensions: drawn from the thread and its turned work.
        let mut fronts = Vec::new();
        for (ti, t) in plan.threads.iter().enumerate() {
            let work = Band::of(t).and_then(|b| work_extent_in(t, &b, &plan.moves, &layout.feeds));
            let bits = work.map_or([0, 0, 0], |(lo, hi)| [1, lo.to_bits(), hi.to_bits()]);
            let key = combine(&[thread_key(ti), ti as u64, bits[0], bits[1], bits[2]]);
            let keys = (combine(&[Tag::Back as u64, key]), combine(&[Tag::Front as u64, key]));
            let (kb, kf) = pieces.take_pair(keys, || {
                let (mut back, mut front) = (Vec::new(), Vec::new());
                thread_items(plan, &layout.feeds, ti, t, &mut back, &mut front);
                front.extend(detail_note(ti, t, &layout.details[ti]).map(|i| (i, false)));
                (Chunk::of(back), Chunk::of(front))
            });
            order.push(kb);
            fronts.push(kf);
        }
        // Blocks of the motions of no pass.
        let drawn = layout.drawn;
        for start in (0..drawn).step_by(BLOCK) {
            let end = (start + BLOCK).min(drawn);
            let mut h = KeyHasher::default();
            h.write_u64(Tag::Motions as u64);
            h.write_u8(u8::from(layout.has_threads));
            for k in start..end {
                h.write_u8(u8::from(layout.owner[k]) | (u8::from(layout.roughing[k]) << 1));
                if !layout.owner[k] {
                    h.write_u64(motion(k));
                }
            }
            let (moves, owner, has_threads) = (&plan.moves[start..end], &layout.owner[start..end], layout.has_threads);
            let roughing = &layout.roughing[start..end];
            order.push(pieces.take(h.finish(), || Chunk::of(motions(moves, owner, roughing, has_threads))));
        }
        // Runs of passes of one thread, in cutting order.
        let paths: Vec<_> = layout.paths.iter().collect();
        let mut i = 0;
        while i < paths.len() {
            let mut j = i + 1;
            while j < paths.len() && j - i < RUN && paths[j].thread == paths[i].thread {
                j += 1;
            }
            let mut h = KeyHasher::default();
            h.write_u64(Tag::Passes as u64);
            for p in &paths[i..j] {
                h.write_u64(thread_key(p.thread));
                h.write_usize(p.thread);
                h.write_usize(p.pass);
                for r in [&p.lead_in, &p.cut, &p.tail] {
                    h.write_usize(r.end - r.start);
                }
                p.indices().for_each(|k| h.write_u64(motion(k)));
            }
            let run = &paths[i..j];
            order.push(pieces.take(h.finish(), || {
                let mut s = Scene::new(ViewKind::Side);
                run.iter().for_each(|p| pass_items(plan, p, &mut s));
                Chunk::from_scene(s)
            }));
            i = j;
        }
        // The passes drawn from their own points, and the note: built anyway.
        let unmatched: Vec<(Item, bool)> =
            layout.unmatched(plan).into_iter().map(|(ti, pi)| (unmatched_item(plan, ti, pi), true)).collect();
        if !unmatched.is_empty() {
            order.push(pieces.put(Chunk::of(unmatched)));
        }
        // Scene order: axis, bands, other motions, passes, unmatched passes, dimensions, note.
        order.extend(fronts);
        if let Some(n) = capped_note(plan, drawn) {
            order.push(pieces.put(Chunk::of([(n, false)])));
        }
        self.built = pieces.built.len();
        self.reused = pieces.reused;
        pieces.keep_taken(&mut order);
        let (sections, order) = {
            let rest = order.split_off(n_sections);
            (order, rest)
        };
        let head = {
            let chunks: Vec<&Chunk> = order.iter().map(|&i| &pieces.chunks[i]).collect();
            head(&chunks)
        };
        self.chunks = pieces.chunks;
        self.index = pieces.index;
        self.shared = pieces.shared;
        Built { head, sections, order }
    }
}

/// The part's filled sections of `plan` as pieces, one per block of
/// motions (the runs of feeds that begin in it, each read to its end),
/// capped as [`section::pieces`] caps them; `motion` gives each motion's key.
fn sections(plan: &Plan, motion: &impl Fn(usize) -> u64, pieces: &mut Pieces) -> Vec<usize> {
    let mut out = Vec::new();
    if !section::filled(plan) {
        return out;
    }
    let moves = &plan.moves;
    let mut total = 0;
    for start in (0..moves.len()).step_by(BLOCK) {
        let end = (start + BLOCK).min(moves.len());
        // What the block's sections are read from: the motion before it (does its
        // first run go on from there?) to the end of its last run.
        let mut h = KeyHasher::default();
        h.write_u64(Tag::Section as u64);
        h.write_u8(u8::from(start == 0));
        // Only the feeds are drawn from (of other motions, that they are not feeds).
        let from = start.saturating_sub(1);
        for (k, m) in moves[from..section::run_end(moves, end)].iter().enumerate() {
            h.write_u64(if section::is_feed(m) { motion(from + k) } else { 0 });
        }
        let i = pieces
            .take(h.finish(), || Chunk::of(section::pieces_from(moves, start, end).into_iter().map(|i| (i, false))));
        // Once past the cap no later section is drawn: the block's within it are a first few.
        let items = pieces.chunks[i].items.clone();
        let kept = items.iter().take_while(|item| section::within_cap(&mut total, item)).count();
        if kept == items.len() {
            if kept > 0 {
                out.push(i);
            }
            continue;
        }
        if kept > 0 {
            out.push(pieces.put(Chunk::of(items[..kept].iter().map(|item| (item.clone(), false)))));
        }
        break;
    }
    out
}

/// The items of the motions of no pass among `moves`.
fn motions<'a>(
    moves: &'a [Move],
    owner: &'a [bool],
    roughing: &'a [bool],
    has_threads: bool,
) -> impl Iterator<Item = (Item, bool)> + 'a {
    moves
        .iter()
        .zip(owner)
        .zip(roughing)
        .filter(|((_, o), _)| !**o)
        .map(move |((m, _), r)| motion_item(m, has_threads, *r))
}

/// The spindle axis with the bounds and focus of the scene of `pieces`.
fn head(pieces: &[&Chunk]) -> Scene {
    let (mut bounds, mut focus) = (Rect::EMPTY, Rect::EMPTY);
    for c in pieces {
        bounds.union(&c.bounds);
        focus.union(&c.focus);
    }
    grow_focus_grouped(&mut focus, pieces.iter().map(|c| (c.rapids_box, c.rapids.as_slice())));
    let axis_item = Item::new(axis(&mut bounds), Style::Axis);
    let mut head = Scene::new(ViewKind::Side);
    head.items.push(axis_item);
    head.bounds = bounds;
    head.focus = focus;
    head.finish();
    head
}

#[cfg(test)]
pub(crate) mod tests;
