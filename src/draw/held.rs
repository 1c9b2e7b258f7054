//! What a view keeps of its last scene between drawings, part by part (a
//! scene's items as [`crate::parts::Parts`] shares them): the lines each
//! part adds to the drawing's lines, and which of its items have labels. A
//! scene put together again from the pieces that did not change (a
//! keystroke in a large program) reads only its new parts; what is drawn
//! is what reading the whole scene gives.

use std::collections::HashMap;
use std::sync::Arc;

use super::labels::has_label;
use super::lines::{LineIndex, MAX_SEGMENTS, PathKey, crossable, one_way, path_key, scene_lines, segments};
use super::visit::{PartPaint, PathSets};
use crate::diagram::scene::{Item, Scene};
use crate::hash::BuildKeyHasher;

/// What one item of a part adds to the drawing's lines: a path (by the
/// address of its points, which paths drawn again exactly share), or a segment.
enum Line {
    Path(PathKey),
    Segment([u64; 4]),
}

/// How many times each segment is held.
type Counts = HashMap<[u64; 4], u32, BuildKeyHasher>;

/// Each path held: how many items hold it, and its segments.
type Paths = HashMap<PathKey, (u32, Vec<[u64; 4]>), BuildKeyHasher>;

/// What a view keeps of one part: what its items add to the drawing's
/// lines, its items with labels, and what the painter visits of it.
struct Part {
    lines: Vec<Line>,
    /// Its items with labels, by their place in the part.
    labelled: Vec<u32>,
    paint: PartPaint,
}

/// What a view keeps of the parts of its last scene (see the module
/// documentation), and how many times each path and each segment of the
/// drawing's lines is held.
#[derive(Default)]
pub struct Held {
    parts: ByPart<Part>,
    paths: Paths,
    counts: Counts,
    sets: PathSets,
}

impl Held {
    /// Takes in `scene`: its new parts are read, the parts it no longer has are let go.
    pub(super) fn update(&mut self, scene: &Scene) {
        let Held { parts, paths, counts, sets } = self;
        let mut gone = Vec::new();
        parts.update(
            scene,
            |part| {
                let lines = add(part, paths, counts);
                let labelled = part.iter().enumerate().filter(|(_, i)| has_label(i)).map(|(k, _)| k as u32).collect();
                Part { lines, labelled, paint: PartPaint::of(part, sets) }
            },
            |part| gone.push(part),
        );
        for part in &gone {
            remove(&part.lines, paths, counts);
            sets.release(&part.paint);
        }
    }

    /// The drawing's lines of `scene`, taken in by [`Held::update`]: the
    /// set of segments [`scene_lines`] finds, unless there are more than it
    /// keeps (then [`scene_lines`]'s own).
    pub(super) fn lines(&self, scene: &Scene) -> LineIndex {
        if self.counts.len() > MAX_SEGMENTS {
            return scene_lines(scene);
        }
        LineIndex::new(self.counts.keys().map(|k| k.map(f64::from_bits)).collect(), scene.focus)
    }

    /// The parts of `scene` (taken in by [`Held::update`]) as the painter visits them.
    pub(super) fn visit<'a, 's: 'a>(&'a self, scene: &'s Scene) -> Vec<(usize, &'s [Item], &'a PartPaint)> {
        self.parts.each(scene).map(|(start, items, part)| (start, items, &part.paint)).collect()
    }

    /// The items of `scene` (taken in by [`Held::update`]) that have labels, with their indices, in order.
    pub(super) fn labelled<'s>(&self, scene: &'s Scene) -> Vec<(usize, &'s Item)> {
        let mut out = Vec::new();
        for (start, part, kept) in self.parts.each(scene) {
            out.extend(kept.labelled.iter().map(|&k| (start + k as usize, &part[k as usize])));
        }
        out
    }
}

/// A value kept for each part of the last scene taken in. A part is
/// known by the address of its items, and held, so that no other part
/// takes that address while its value is kept; a scene put together
/// again from the last one's parts mostly has them where they were, so
/// each is looked for at its place in the last scene first.
pub(super) struct ByPart<T> {
    /// The parts held and their values; `None`: a free slot.
    slots: Vec<Option<Slot<T>>>,
    free: Vec<usize>,
    /// The slot of each part held, by its address.
    by_address: HashMap<usize, usize, BuildKeyHasher>,
    /// The slots of the last scene's parts, in its order.
    order: Vec<usize>,
    /// Scenes taken in so far.
    calls: u32,
}

/// A part held, its value, and the scene that last had it.
struct Slot<T> {
    part: Arc<Vec<Item>>,
    value: T,
    last: u32,
}

impl<T> Default for ByPart<T> {
    fn default() -> ByPart<T> {
        ByPart { slots: Vec::new(), free: Vec::new(), by_address: HashMap::default(), order: Vec::new(), calls: 0 }
    }
}

impl<T> ByPart<T> {
    /// Takes in the parts of `scene`: a part not held gets the value `make`
    /// gives it; the value of a part the scene no longer has goes to `gone`.
    pub(super) fn update(&mut self, scene: &Scene, mut make: impl FnMut(&[Item]) -> T, mut gone: impl FnMut(T)) {
        self.calls = self.calls.wrapping_add(1);
        let call = self.calls;
        let last = std::mem::take(&mut self.order);
        let mut order = Vec::with_capacity(last.len());
        for (k, (_, part)) in scene.items.parts().enumerate() {
            let slot = match last.get(k) {
                Some(&s) if self.slots[s].as_ref().is_some_and(|held| Arc::ptr_eq(&held.part, part)) => s,
                _ => self.slot_of(part, &mut make),
            };
            if let Some(held) = &mut self.slots[slot] {
                held.last = call;
            }
            order.push(slot);
        }
        // Only the last scene's parts are held: those this one did not take are let go.
        for s in last {
            if self.slots[s].as_ref().is_some_and(|held| held.last != call) {
                let held = self.slots[s].take().expect("a held slot");
                self.by_address.remove(&(Arc::as_ptr(&held.part) as usize));
                self.free.push(s);
                gone(held.value);
            }
        }
        self.order = order;
    }

    /// The slot of `part`, found by its address or made.
    fn slot_of(&mut self, part: &Arc<Vec<Item>>, make: &mut impl FnMut(&[Item]) -> T) -> usize {
        let at = Arc::as_ptr(part) as usize;
        if let Some(&s) = self.by_address.get(&at) {
            return s;
        }
        let held = Slot { part: part.clone(), value: make(part), last: 0 };
        let s = match self.free.pop() {
            Some(s) => {
                self.slots[s] = Some(held);
                s
            }
            None => {
                self.slots.push(Some(held));
                self.slots.len() - 1
            }
        };
        self.by_address.insert(at, s);
        s
    }

    /// The parts of `scene` (the last taken in) with their first item's index and their values, in order.
    pub(super) fn each<'a, 's>(
        &'a self,
        scene: &'s Scene,
    ) -> impl Iterator<Item = (usize, &'s [Item], &'a T)> + use<'a, 's, T> {
        scene.items.parts().zip(&self.order).filter_map(move |((start, part), &s)| {
            let held = self.slots[s].as_ref()?;
            Some((start, part.as_slice(), &held.value))
        })
    }

    /// How many parts are held.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.by_address.len()
    }
}

/// Counts in the lines of the items of a part whose lines may not be crossed; what they add.
fn add(items: &[Item], paths: &mut Paths, counts: &mut Counts) -> Vec<Line> {
    let mut lines = Vec::new();
    let mut world = Vec::new();
    for item in items.iter().filter(|i| !crossable(i.style)) {
        world.clear();
        if let Some(key) = path_key(&item.shape) {
            let path = paths.entry(key).or_insert_with(|| {
                segments(&item.shape, &mut world);
                let segs: Vec<[u64; 4]> = world.iter().map(|s| one_way(*s)).collect();
                segs.iter().for_each(|s| *counts.entry(*s).or_insert(0) += 1);
                (0, segs)
            });
            path.0 += 1;
            lines.push(Line::Path(key));
        } else {
            segments(&item.shape, &mut world);
            for s in world.iter().map(|s| one_way(*s)) {
                *counts.entry(s).or_insert(0) += 1;
                lines.push(Line::Segment(s));
            }
        }
    }
    lines
}

/// Counts out the lines a part added.
fn remove(lines: &[Line], paths: &mut Paths, counts: &mut Counts) {
    for line in lines {
        match line {
            Line::Segment(s) => count_out(counts, s),
            Line::Path(key) => {
                let Some(path) = paths.get_mut(key) else { continue };
                path.0 -= 1;
                if path.0 == 0 {
                    path.1.iter().for_each(|s| count_out(counts, s));
                    paths.remove(key);
                }
            }
        }
    }
}

/// One hold of segment `s` less.
fn count_out(counts: &mut Counts, s: &[u64; 4]) {
    if let Some(n) = counts.get_mut(s) {
        *n -= 1;
        if *n == 0 {
            counts.remove(s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::scene::{Rect, Shape, Style};

    /// Values by part through scenes whose parts move, repeat, come and go:
    /// each part's value is the one made for it, made once while it is held
    /// (a part the last scene had is not made again), and let go when a scene no longer has it.
    #[test]
    fn values_by_part_follow_the_parts() {
        let mut next = crate::hash::unit_floats(0x5851_f42d_4c95_7f2d);
        let mut int = |n: usize| (next() * n as f64) as usize;
        let item = || Item::new(Shape::Arrow { from: [0.0, 0.0], to: [1.0, 1.0] }, Style::Cut);
        let new_part = |k: usize| Arc::new(vec![item(); 1 + k % 3]);
        let mut pool: Vec<Arc<Vec<Item>>> = (0..12).map(new_part).collect();
        let mut by = ByPart::<(usize, usize)>::default();
        let mut made = 0;
        let mut last: Vec<usize> = Vec::new();
        for round in 0..300 {
            // A new part now and then, and a scene of some of the pool's parts (a part may come twice).
            if int(3) == 0 {
                let k = int(pool.len());
                pool[k] = new_part(round);
            }
            let mut parts: Vec<Arc<Vec<Item>>> = (0..int(10)).map(|_| pool[int(pool.len())].clone()).collect();
            if round % 7 == 0 {
                parts = last.iter().filter_map(|&a| pool.iter().find(|p| p.as_ptr() as usize == a).cloned()).collect();
                parts.insert(0, new_part(round));
            }
            let scene = of_parts(&parts, Rect::EMPTY);
            // Each part known by its first item's address.
            let addresses: Vec<usize> = parts.iter().map(|p| p.as_ptr() as usize).collect();
            let mut gone = Vec::new();
            let before = made;
            by.update(
                &scene,
                |part| {
                    made += 1;
                    (part.as_ptr() as usize, made)
                },
                |v| gone.push(v.0),
            );
            // Made: the parts the last scene did not have, once each.
            let mut fresh: Vec<usize> = addresses.iter().copied().filter(|a| !last.contains(a)).collect();
            fresh.sort_unstable();
            fresh.dedup();
            assert_eq!(made - before, fresh.len(), "round {round}");
            // Let go: the last scene's parts this one does not have, once each.
            let mut left: Vec<usize> = last.iter().copied().filter(|a| !addresses.contains(a)).collect();
            left.sort_unstable();
            left.dedup();
            gone.sort_unstable();
            assert_eq!(gone, left, "round {round}");
            // Each part of the scene with its first item's index and its own value.
            let seen: Vec<(usize, usize)> = by.each(&scene).map(|(start, _, v)| (start, v.0)).collect();
            let want: Vec<(usize, usize)> =
                scene.items.parts().map(|(start, p)| (start, p.as_ptr() as usize)).collect();
            assert_eq!(seen, want, "round {round}");
            let mut distinct = addresses.clone();
            distinct.sort_unstable();
            distinct.dedup();
            assert_eq!(by.len(), distinct.len(), "round {round}");
            last = addresses;
        }
        assert!(made > 100, "{made} values made");
    }

    /// A view's drawings from what it keeps of its scenes' parts are the
    /// drawings of each scene read whole: labels placed, paths joined and left out alike.
    #[test]
    fn drawings_from_kept_parts_are_the_whole_scenes() {
        use crate::draw::{FitMemo, Transform, View, display, display_kept};
        let (parts, focus) = side_parts();
        let mut moved = parts.clone();
        let at = moved.iter().position(|p| p.iter().any(|i| i.style == Style::Cut)).expect("a part with a cut");
        moved[at] = Arc::new(moved_cuts(&moved[at]));
        moved.remove(at + 3);
        let (a, b) = (of_parts(&parts, focus), of_parts(&moved, focus));
        let mut memo = FitMemo::new();
        let fitted = View { width: 936.0, height: 420.0, ..View::default() };
        assert_eq!(display_kept(&a, &fitted, &mut memo), display(&a, &fitted));
        let xf = display(&a, &fitted).transform;
        let at_xf = View { transform: Some(Transform { sy: xf.sy * 1.5, ..xf }), ..fitted };
        let mut placed = 0;
        for scene in [&a, &b, &b, &a, &b] {
            let kept = display_kept(scene, &at_xf, &mut memo);
            assert_eq!(kept, display(scene, &at_xf));
            placed += kept.labels.len();
        }
        assert!(placed >= 10, "{placed} labels placed");
        assert_ne!(display(&a, &at_xf).ops, display(&b, &at_xf).ops, "the scenes differ");
    }

    /// The side section of six threads of three passes, in parts of five items; its focus.
    fn side_parts() -> (Vec<Arc<Vec<Item>>>, Rect) {
        use crate::dialect::Dialect;
        use crate::settings::Settings;
        let mut text = String::from("G50 X100 Z100\nS300 M03\n");
        for k in 0..6 {
            let d = 30 + 3 * k;
            text += &format!("G00 X{} Z70\nG01 X{d} F0.2\nZ20\nX{}\nG00 Z70\n", d + 10, d + 5);
            for x in [0.9, 1.3, 1.6] {
                text += &format!("X{:.1}\nG32 Z13 F2\nG00 X{}\nZ70\n", d as f64 - x, d + 10);
            }
        }
        let whole = crate::diagram::side(&crate::plan(&text, &Settings::new(Dialect::Gsk980tdc)));
        let items: Vec<Item> = whole.items.iter().cloned().collect();
        let parts: Vec<Arc<Vec<Item>>> = items.chunks(5).map(|c| Arc::new(c.to_vec())).collect();
        assert!(parts.len() > 8, "{} parts", parts.len());
        (parts, whole.focus)
    }

    /// The items of `part` with its cuts 0.25 mm lower.
    fn moved_cuts(part: &[Item]) -> Vec<Item> {
        let mut moved = part.to_vec();
        for item in moved.iter_mut().filter(|i| i.style == Style::Cut) {
            if let Shape::Polyline { points } = &mut item.shape {
                *points = points.iter().map(|p| [p[0], p[1] - 0.25]).collect();
            }
        }
        moved
    }

    /// A scene of `parts`, shared, with `focus`.
    fn of_parts(parts: &[Arc<Vec<Item>>], focus: Rect) -> Scene {
        let mut s = Scene::new(crate::diagram::ViewKind::Side);
        parts.iter().for_each(|p| s.items.push_shared(p.clone()));
        s.focus = focus;
        s
    }

    /// The lines and labelled items held by parts are those of the whole
    /// scene, drawing after drawing: parts changed, dropped, added, too many
    /// segments, then back.
    #[test]
    fn held_lines_and_labels_are_the_scenes() {
        let (parts, focus) = side_parts();
        let a = of_parts(&parts, focus);
        // A pass moved (its part built again), a part gone, a new one at the end.
        let mut b_parts = parts.clone();
        let at = b_parts.iter().position(|p| p.iter().any(|i| i.style == Style::Cut)).expect("a part with a cut");
        b_parts[at] = Arc::new(moved_cuts(&b_parts[at]));
        b_parts.remove(at + 2);
        b_parts.push(Arc::new(vec![Item::new(Shape::Arrow { from: [1.0, 2.0], to: [3.0, 5.0] }, Style::Cut)]));
        let b = of_parts(&b_parts, focus);
        // More segments than are kept: the first ones, as `scene_lines` takes them.
        let many: Vec<Item> = (0..MAX_SEGMENTS + 10)
            .map(|k| {
                let x = k as f64 * 0.01;
                Item::new(Shape::Polyline { points: vec![[x, 0.0], [x, 1.0]].into() }, Style::Cut)
            })
            .collect();
        let mut c_parts = b_parts.clone();
        c_parts.push(Arc::new(many));
        let c = of_parts(&c_parts, focus);
        let mut held = Held::default();
        for scene in [&a, &b, &b, &c, &b, &a] {
            held.update(scene);
            assert_eq!(held.lines(scene).sorted(), scene_lines(scene).sorted());
            // And the items with labels are those of the scene.
            let labelled: Vec<(usize, *const Item)> =
                held.labelled(scene).iter().map(|&(i, it)| (i, it as *const Item)).collect();
            let expected: Vec<(usize, *const Item)> = scene
                .items
                .iter()
                .enumerate()
                .filter(|(_, i)| has_label(i))
                .map(|(i, it)| (i, it as *const Item))
                .collect();
            assert!(!expected.is_empty());
            assert_eq!(labelled, expected);
            // The lists of paths held are the scene's: those of parts gone are let go.
            let mut fresh = PathSets::default();
            scene.items.parts().for_each(|(_, part)| drop(PartPaint::of(part, &mut fresh)));
            assert_eq!(held.sets.len(), fresh.len());
        }
        // What was asked for: the changed pass, the part gone and the arrow each changed the lines.
        let (la, lb) = (scene_lines(&a).sorted(), scene_lines(&b).sorted());
        assert!(la.len() > 20 && la != lb);
        assert_eq!(scene_lines(&c).sorted().len(), MAX_SEGMENTS);
        // Only the last scene's parts are kept.
        assert_eq!(held.parts.len(), parts.len());
    }
}
