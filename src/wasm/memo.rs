//! The side section built again after an edit from the pieces that did not
//! change: each thread's band and dimensions, runs of passes and blocks of
//! other motions are packed once and kept by the key of what they are drawn
//! from. [`SideMemo::side`] gives exactly `pack(&side(plan))`; an edit to one
//! thread rebuilds that thread's pieces and the spindle axis only.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use crate::motion::Move;
use crate::plan::Plan;

use super::keys::{KeyHasher, combine, hash_move, packed_key};
use super::pack::{Packed, RECORD_SEP, STRIDE, pack};
use crate::diagram::scene::{Item, Pt, Rect, Scene, Style, ViewKind};
use crate::diagram::side::{
    Band, Layout, axis, capped_note, detail_note, grow_focus, motion_item, pass_items, thread_items, unmatched_item,
    work_extent_in,
};

/// Motions per block of other motions.
const BLOCK: usize = 256;
/// Most passes in one cached run.
const RUN: usize = 16;

/// Pieces by key (the keys are hashes already: no second hash with a random seed).
type ByKey = HashMap<u64, Chunk, BuildHasherDefault<KeyHasher>>;

/// A packed run of items with what the whole scene needs of it.
struct Chunk {
    packed: Packed,
    labels: u32,
    bounds: Rect,
    focus: Rect,
    /// Points of the passes' rapids (they may join the focus).
    rapids: Vec<Pt>,
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
        let packed = pack(&s);
        let labels = packed.items.chunks_exact(STRIDE).filter(|r| r[8] > 0).count() as u32;
        Chunk { packed, labels, bounds: s.bounds, focus: s.focus, rapids }
    }
}

/// The pieces of one call: taken from the last call's by key, or built.
struct Pieces {
    old: ByKey,
    kept: ByKey,
    /// Keys of the pieces built in this call.
    built: Vec<u64>,
    reused: usize,
}

impl Pieces {
    /// Keeps the piece of `key`, built by `make` unless the last call had it; returns the key.
    fn take(&mut self, key: u64, make: impl FnOnce() -> Chunk) -> u64 {
        if !self.kept.contains_key(&key) {
            let c = match self.old.remove(&key) {
                Some(c) => {
                    self.reused += 1;
                    c
                }
                None => {
                    self.built.push(key);
                    make()
                }
            };
            self.kept.insert(key, c);
        }
        key
    }

    /// [`Pieces::take`] for two pieces built together.
    fn take_pair(&mut self, keys: (u64, u64), make: impl FnOnce() -> (Chunk, Chunk)) -> (u64, u64) {
        let has = |k: &u64| self.kept.contains_key(k) || self.old.contains_key(k);
        if !(has(&keys.0) && has(&keys.1)) {
            let (a, b) = make();
            self.built.extend([keys.0, keys.1]);
            self.old.remove(&keys.0);
            self.old.remove(&keys.1);
            self.kept.insert(keys.0, a);
            self.kept.insert(keys.1, b);
            return keys;
        }
        (self.take(keys.0, || Chunk::of([])), self.take(keys.1, || Chunk::of([])))
    }

    /// Keeps a piece built anyway (it is cheap and rare), under the key of its content.
    fn put(&mut self, chunk: Chunk) -> u64 {
        let key = packed_key(&chunk.packed);
        self.take(key, || chunk)
    }
}

/// The side section as pieces: what the caller needs to put it together from
/// the pieces it holds of the last answer.
#[derive(Clone, Debug, PartialEq)]
pub struct SidePieces {
    /// The spindle axis alone, with the scene's bounds and focus.
    pub head: Packed,
    /// Keys of the pieces in drawing order (after the axis).
    pub order: Vec<u64>,
    /// Keys of the pieces sent, in the order of `sent`'s parts.
    pub keys: Vec<u64>,
    /// The pieces sent, one after the other; each item's offsets and label
    /// number are its piece's own.
    pub sent: Packed,
    /// Per sent piece, where it ends in `sent`: coordinates, items (numbers),
    /// lines, label text (UTF-16 units, as JavaScript counts) and labels.
    pub ends: Vec<[u32; 5]>,
}

/// Pieces of the last side section, by key; and how many of the last call's pieces were built.
#[derive(Default)]
pub struct SideMemo {
    chunks: ByKey,
    built: usize,
    reused: usize,
    /// The key of the last section answered as pieces ([`SideMemo::pieces`]).
    last: Option<u64>,
}

/// One call's pieces: the head and the order, and which were built.
struct Built {
    head: Packed,
    order: Vec<u64>,
    built: Vec<u64>,
}

/// What a piece is, mixed into its key.
#[derive(Clone, Copy)]
enum Tag {
    Back = 1,
    Front = 2,
    Motions = 3,
    Passes = 4,
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

    /// The packed side section of `plan`, whose threads have the keys
    /// `thread_keys` ([`super::keys::thread_key`]); pieces are reused
    /// from the last call where their keys match.
    pub fn side(&mut self, plan: &Plan, thread_keys: &[u64]) -> Packed {
        let b = self.build(plan, thread_keys);
        self.last = None;
        let pieces: Vec<&Chunk> = b.order.iter().map(|k| &self.chunks[k]).collect();
        join(b.head, &pieces)
    }

    /// The key of the last section answered as pieces, if the last answer was pieces.
    pub fn last(&self) -> Option<u64> {
        self.last
    }

    /// The side section of `plan` (key `side_key`) as pieces: when the
    /// caller `holds` the pieces of [`SideMemo::last`], only the pieces it
    /// lacks are sent, else every piece.
    pub fn pieces(&mut self, plan: &Plan, thread_keys: &[u64], side_key: u64, holds: bool) -> SidePieces {
        let holds = holds && self.last.is_some();
        let b = self.build(plan, thread_keys);
        self.last = Some(side_key);
        let mut keys = if holds { b.built } else { b.order.clone() };
        let mut seen =
            std::collections::HashSet::with_capacity_and_hasher(keys.len(), BuildHasherDefault::<KeyHasher>::default());
        keys.retain(|k| seen.insert(*k));
        let mut sent = Packed {
            view: ViewKind::Side,
            bounds: [0.0; 4],
            focus: [0.0; 4],
            coords: Vec::new(),
            items: Vec::new(),
            lines: Vec::new(),
            labels: String::new(),
        };
        let mut ends = Vec::with_capacity(keys.len());
        let (mut labels, mut units) = (0u32, 0u32);
        for k in &keys {
            let c = &self.chunks[k];
            sent.coords.extend_from_slice(&c.packed.coords);
            sent.items.extend_from_slice(&c.packed.items);
            sent.lines.extend_from_slice(&c.packed.lines);
            sent.labels.push_str(&c.packed.labels);
            labels += c.labels;
            units += c.packed.labels.encode_utf16().count() as u32;
            let len = |v: &[_]| v.len() as u32;
            ends.push([sent.coords.len() as u32, len(&sent.items), len(&sent.lines), units, labels]);
        }
        SidePieces { head: b.head, order: b.order, keys, sent, ends }
    }

    /// Builds or reuses every piece of `plan`'s side section.
    fn build(&mut self, plan: &Plan, thread_keys: &[u64]) -> Built {
        let mut pieces =
            Pieces { old: std::mem::take(&mut self.chunks), kept: ByKey::default(), built: Vec::new(), reused: 0 };
        let layout = Layout::of(plan);
        let thread_key = |ti: usize| thread_keys.get(ti).copied().unwrap_or(0);
        let mut order: Vec<u64> = Vec::new();
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
                h.write_u8(u8::from(layout.owner[k]));
                if !layout.owner[k] {
                    hash_move(&mut h, &plan.moves[k]);
                }
            }
            let (moves, owner, has_threads) = (&plan.moves[start..end], &layout.owner[start..end], layout.has_threads);
            order.push(pieces.take(h.finish(), || Chunk::of(motions(moves, owner, has_threads))));
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
                p.indices().for_each(|k| hash_move(&mut h, &plan.moves[k]));
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
        let head = {
            let chunks: Vec<&Chunk> = order.iter().map(|k| &pieces.kept[k]).collect();
            head(&chunks)
        };
        self.chunks = pieces.kept;
        Built { head, order, built: pieces.built }
    }
}

/// The items of the motions of no pass among `moves`.
fn motions<'a>(moves: &'a [Move], owner: &'a [bool], has_threads: bool) -> impl Iterator<Item = (Item, bool)> + 'a {
    moves.iter().zip(owner).filter(|(_, o)| !**o).map(move |(m, _)| motion_item(m, has_threads))
}

/// The spindle axis with the bounds and focus of the scene of `pieces`.
fn head(pieces: &[&Chunk]) -> Packed {
    let (mut bounds, mut focus) = (Rect::EMPTY, Rect::EMPTY);
    for c in pieces {
        bounds.union(&c.bounds);
        focus.union(&c.focus);
    }
    grow_focus(&mut focus, pieces.iter().flat_map(|c| c.rapids.iter().copied()));
    let axis_item = Item::new(axis(&mut bounds), Style::Axis);
    let mut head = Scene::new(ViewKind::Side);
    head.items.push(axis_item);
    head.bounds = bounds;
    head.focus = focus;
    head.finish();
    pack(&head)
}

/// The whole scene: the head (the axis), then the pieces.
fn join(head: Packed, pieces: &[&Chunk]) -> Packed {
    let mut out = head;
    let n: usize = pieces.iter().map(|c| c.packed.items.len()).sum();
    out.items.reserve(n);
    out.coords.reserve(pieces.iter().map(|c| c.packed.coords.len()).sum());
    out.lines.reserve(pieces.iter().map(|c| c.packed.lines.len()).sum());
    let mut labels = 0u32;
    for c in pieces {
        let (co, lo) = (out.coords.len() as u32, out.lines.len() as u32);
        let first = out.items.len();
        out.items.extend_from_slice(&c.packed.items);
        for r in out.items[first..].chunks_exact_mut(STRIDE) {
            r[2] += co;
            r[6] += lo;
            if r[8] > 0 {
                r[8] += labels;
            }
        }
        out.coords.extend_from_slice(&c.packed.coords);
        out.lines.extend_from_slice(&c.packed.lines);
        if c.labels > 0 {
            if labels > 0 {
                out.labels.push(RECORD_SEP);
            }
            out.labels.push_str(&c.packed.labels);
            labels += c.labels;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::side;
    use crate::dialect::Dialect;
    use crate::settings::Settings;
    use crate::wasm::keys::PlanKeys;

    /// Threads turned on their own diameters (13 lines each), as an editor would hold them.
    fn program(threads: usize) -> String {
        let mut out = String::from("G50 X100 Z100\n");
        for k in 0..threads {
            let d = 30 + (k % 7) as u32;
            out += &format!("G00 X{} Z70\nG01 X{d} F0.2\nZ20\nX{}\nG00 Z70\n", d + 10, d + 5);
            for x in [0.9, 1.5] {
                out += &format!("X{:.1}\nG32 Z13 F2\nG00 X{}\nZ70\n", f64::from(d) - x, d + 10);
            }
        }
        out + "M30\n"
    }

    fn check(memo: &mut SideMemo, text: &str, settings: &Settings) -> (usize, usize) {
        let plan = crate::plan(text, settings);
        let keys = PlanKeys::of(&plan);
        let got = memo.side(&plan, &keys.threads);
        assert_eq!(got, pack(&side(&plan)), "{text}");
        memo.counts()
    }

    /// What a caller holds of the pieces, and how it puts a section together (as www/src/parts.js does).
    #[derive(Default)]
    struct Holder {
        key: Option<u64>,
        pieces: HashMap<u64, (Packed, u32)>,
    }

    impl Holder {
        /// The whole section from an answer; returns it and the number of pieces sent.
        fn take(&mut self, a: SidePieces, side_key: u64) -> (Packed, usize) {
            let mut fresh = HashMap::new();
            let mut start = [0u32; 5];
            let labels: Vec<u16> = a.sent.labels.encode_utf16().collect();
            for (k, end) in a.keys.iter().zip(&a.ends) {
                let r = |i: usize| start[i] as usize..end[i] as usize;
                let piece = Packed {
                    view: ViewKind::Side,
                    bounds: [0.0; 4],
                    focus: [0.0; 4],
                    coords: a.sent.coords[r(0)].to_vec(),
                    items: a.sent.items[r(1)].to_vec(),
                    lines: a.sent.lines[r(2)].to_vec(),
                    labels: String::from_utf16(&labels[r(3)]).unwrap(),
                };
                fresh.insert(*k, (piece, end[4] - start[4]));
                start = *end;
            }
            let mut out = a.head;
            let mut count = 0;
            let mut kept = HashMap::new();
            for k in &a.order {
                let (p, n) = fresh.get(k).or_else(|| self.pieces.get(k)).cloned().expect("a piece held or sent");
                let (co, lo) = (out.coords.len() as u32, out.lines.len() as u32);
                for r in p.items.chunks_exact(STRIDE) {
                    out.items.extend([r[0], r[1], r[2] + co, r[3], r[4], r[5], r[6] + lo, r[7]]);
                    out.items.extend([if r[8] > 0 { r[8] + count } else { 0 }, r[9]]);
                }
                out.coords.extend_from_slice(&p.coords);
                out.lines.extend_from_slice(&p.lines);
                if n > 0 {
                    if count > 0 {
                        out.labels.push(RECORD_SEP);
                    }
                    out.labels.push_str(&p.labels);
                    count += n;
                }
                kept.insert(*k, (p, n));
            }
            self.pieces = kept;
            self.key = Some(side_key);
            (out, a.keys.len())
        }
    }

    /// Plans `text` and checks that the pieces `holder` gets make the whole section; the number of pieces sent.
    fn check_pieces(memo: &mut SideMemo, holder: &mut Holder, text: &str, s: &Settings) -> usize {
        let plan = crate::plan(text, s);
        let keys = PlanKeys::of(&plan);
        let holds = holder.key.is_some() && holder.key == memo.last();
        let (got, sent) = holder.take(memo.pieces(&plan, &keys.threads, keys.side, holds), keys.side);
        assert_eq!(got, pack(&side(&plan)), "{text}");
        sent
    }

    #[test]
    fn pieces_sent_and_held_make_the_whole_scene() {
        let s = Settings::new(Dialect::Gsk980tdc);
        let (mut memo, mut holder) = (SideMemo::new(), Holder::default());
        let base = program(40);
        let all = check_pieces(&mut memo, &mut holder, &base, &s);
        assert!(all > 80, "{all}");
        let lines: Vec<&str> = base.lines().collect();
        let n = lines.len();
        let edited = lines.iter().enumerate().map(|(i, l)| if i == n - 9 { format!("{l}1") } else { l.to_string() });
        let edited: String = edited.map(|l| l + "\n").collect();
        assert_eq!(check_pieces(&mut memo, &mut holder, &edited, &s), 3, "one thread's pieces");
        for text in [
            base.replacen("X29.1", "X29.1\nG00 X80", 1),
            base[..base.len() / 2].to_string(),
            String::new(),
            base.clone(),
        ] {
            check_pieces(&mut memo, &mut holder, &text, &s);
        }
        // Another caller's answer in between: the first caller gets every piece again.
        let mut other = Holder::default();
        check_pieces(&mut memo, &mut other, include_str!("../../examples/o1006.nc"), &s);
        assert_eq!(check_pieces(&mut memo, &mut holder, &edited, &s), all);
        // A full section answered in between: the same.
        memo.side(&crate::plan(&base, &s), &PlanKeys::of(&crate::plan(&base, &s)).threads);
        assert_eq!(memo.last(), None);
        assert_eq!(check_pieces(&mut memo, &mut holder, &base, &s), all);
    }

    #[test]
    fn reused_pieces_give_the_whole_scene() {
        let s = Settings::new(Dialect::Gsk980tdc);
        let mut memo = SideMemo::new();
        let base = program(40);
        let (built, reused) = check(&mut memo, &base, &s);
        assert_eq!(reused, 0);
        assert!(built > 80, "{built} pieces");
        // The same program again: nothing is built.
        assert_eq!(check(&mut memo, &base, &s), (0, built));
        // One pass of the last thread: its band, dimensions and passes only.
        let lines: Vec<&str> = base.lines().collect();
        let n = lines.len();
        let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        edited[n - 9] = format!("{}1", edited[n - 9]);
        let edited = edited.join("\n") + "\n";
        let (b, r) = check(&mut memo, &edited, &s);
        assert_eq!(b, 3, "band, dimensions and the passes of one thread");
        assert_eq!(b + r, built);
        // Edits of every kind, one after the other on one memo.
        let edits = [
            base.replacen("Z20", "Z21", 1),
            base.replacen("G50 X100 Z100", "G50 X100 Z100 (a comment)", 1),
            base.replacen("X29.1", "X29.1\nG00 X80", 1),
            base[..base.len() / 3].to_string(),
            format!("G00 X90 Z90\n{base}"),
            base.replace("G32 Z13 F2", "G32 Z13 F2.5"),
            String::new(),
            base.clone(),
            include_str!("../../examples/g78-flank-alternating.nc").to_string(),
            include_str!("../../examples/g92-two-start.nc").to_string(),
            include_str!("../../examples/o0009.nc").to_string(),
            include_str!("../../examples/g32-continuous.nc").to_string(),
        ];
        for text in &edits {
            check(&mut memo, text, &s);
        }
        for text in [include_str!("../../examples/renhe-tails.nc"), "G33 W-40 F1.5\n"] {
            check(&mut memo, text, &Settings::new(Dialect::Renhe));
        }
        // A plan cut short by the motion limit; and one whose last passes
        // lost their motions, drawn from their own points.
        let mut few = Settings::new(Dialect::Fanuc0i);
        few.assign("limits.moves=12").unwrap();
        let g76 = include_str!("../../examples/g76-fanuc.nc");
        check(&mut memo, g76, &few);
        let mut plan = crate::plan(g76, &Settings::new(Dialect::Fanuc0i));
        plan.moves.truncate(plan.moves.len() / 2);
        assert!(!Layout::of(&plan).unmatched(&plan).is_empty(), "some passes have no motions");
        let keys = PlanKeys::of(&plan);
        assert_eq!(memo.side(&plan, &keys.threads), pack(&side(&plan)));
    }
}
