//! What the painter visits of a scene's parts: each part's paths with
//! their pens' keys and the addresses of their points, and its other
//! shapes. Kept with the parts a view holds (`draw::held`), so that a
//! drawing after a keystroke does not read every item again; parts of the
//! same paths (a program's repeated sections) share a number, and the
//! painter passes over all but the first of them.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};

use super::labels::has_label;
use super::lines::path_key;
use crate::diagram::scene::{Item, Style};
use crate::hash::{BuildKeyHasher, KeyHasher};

/// The pen a path goes with: style, role and shape; an area's pass and thread too (a colour each).
pub(super) type BatchKey = (u32, u8, bool, Option<(u32, u32)>);

/// The pen `item` is drawn with as a path (`closed`: a polygon).
pub(super) fn batch_key(item: &Item, closed: bool) -> BatchKey {
    let role = match item.role {
        None => 0,
        Some(crate::thread::Role::Rough) => 1,
        Some(crate::thread::Role::Finish) => 2,
        Some(crate::thread::Role::Spring) => 3,
    };
    let area = (item.style == Style::Area).then(|| (item.thread.map_or(0, |t| t + 1), item.pass.map_or(0, |p| p + 1)));
    (item.style.code(), role, closed, area)
}

/// A part's items as the painter visits them, each in item order: its
/// paths (see [`PathAt`]), the number of its list of paths among the
/// view's ([`PathSets`]), and its other shapes (their places in the part;
/// labels are drawn from where they were placed). Kept with the part
/// between drawings (`draw::held`), so that a drawing goes through the
/// paths without reading every item.
pub(super) struct PartPaint {
    pub(super) paths: Vec<PathAt>,
    pub(super) set: u32,
    pub(super) shapes: Vec<u32>,
}

/// A path of a part: its place in the part, the address of its points, its
/// pen's key and whether it is a roughing cut.
pub(super) struct PathAt {
    pub(super) at: u32,
    pub(super) points: usize,
    pub(super) key: BatchKey,
    pub(super) rough: bool,
}

/// What makes two parts' paths the same: each path's points (by address), pen and roughing flag.
type PathSig = (usize, BatchKey, bool);

impl PartPaint {
    /// What the painter visits of `items`, its list of paths numbered in `sets`.
    pub(super) fn of(items: &[Item], sets: &mut PathSets) -> PartPaint {
        let (mut paths, mut shapes) = (Vec::new(), Vec::new());
        for (k, item) in items.iter().enumerate() {
            match path_key(&item.shape) {
                Some((points, closed)) => paths.push(PathAt {
                    at: k as u32,
                    points,
                    key: batch_key(item, closed),
                    rough: item.style == Style::Roughing,
                }),
                None if !has_label(item) => shapes.push(k as u32),
                None => {}
            }
        }
        let set = sets.number(paths.iter().map(|p| (p.points, p.key, p.rough)).collect());
        PartPaint { paths, set, shapes }
    }
}

/// The distinct lists of paths of the parts a view holds, numbered: parts
/// of the same paths (a program's repeated sections, whose points are
/// shared) have the same number, and the painter passes over all but the
/// first of them whole. A number is free again once no part holds it.
#[derive(Default)]
pub(super) struct PathSets {
    /// The number of a list, by the list's hash (a list whose hash another
    /// list holds keeps a number of its own, shared with no other part).
    by_hash: HashMap<u64, usize, BuildKeyHasher>,
    /// Each number's list, its hash and how many parts hold it; `None`: free.
    sets: Vec<Option<(Vec<PathSig>, u64, u32)>>,
    free: Vec<usize>,
}

impl PathSets {
    /// The number of `list`, held once more.
    fn number(&mut self, list: Vec<PathSig>) -> u32 {
        let mut h = KeyHasher::default();
        list.hash(&mut h);
        let hash = h.finish();
        if let Some(&n) = self.by_hash.get(&hash)
            && let Some((l, _, count)) = &mut self.sets[n]
            && *l == list
        {
            *count += 1;
            return n as u32;
        }
        let n = self.free.pop().unwrap_or_else(|| {
            self.sets.push(None);
            self.sets.len() - 1
        });
        self.sets[n] = Some((list, hash, 1));
        self.by_hash.entry(hash).or_insert(n);
        n as u32
    }

    /// Lets go of `part`'s list of paths once.
    pub(super) fn release(&mut self, part: &PartPaint) {
        let n = part.set as usize;
        let Some((_, hash, count)) = &mut self.sets[n] else { return };
        *count -= 1;
        if *count > 0 {
            return;
        }
        let hash = *hash;
        self.sets[n] = None;
        self.free.push(n);
        if self.by_hash.get(&hash) == Some(&n) {
            self.by_hash.remove(&hash);
        }
    }

    /// How many numbers are held.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.sets.iter().flatten().count()
    }
}

/// A scene's parts as the painter visits them: each part's first item's index, its items, what is visited of them.
pub(super) type Visit<'a> = [(usize, &'a [Item], &'a PartPaint)];

#[cfg(test)]
mod tests {
    use crate::diagram::scene::{Item, Scene, Shape, Style, ViewKind};
    use crate::draw::paint::tests::line;
    use crate::draw::{Transform, View, display};

    /// A part whose paths repeat an earlier part's (the same points, shared,
    /// in the same pens: a program's repeated section) is passed over whole:
    /// the list is the one of the same items each with its own copy of its
    /// points (which no address joins). A repeat with one path in another
    /// pen, or with its paths in another order, is drawn as its paths say.
    #[test]
    fn repeated_parts_draw_what_their_items_draw() {
        use std::sync::Arc;
        let mut next = crate::hash::unit_floats(0x9e37_79b9_7f4a_7c15);
        let styles = [Style::Cut, Style::Rapid, Style::Outline];
        let mut firsts: Vec<Arc<Vec<Item>>> = Vec::new();
        for _ in 0..60 {
            let n = 1 + (next() * 4.0) as usize;
            let part: Vec<Item> = (0..n)
                .map(|_| {
                    let pts: Vec<[f64; 2]> =
                        (0..2 + (next() * 3.0) as usize).map(|_| [next() * 900.0, next() * 450.0]).collect();
                    line(&pts, styles[(next() * 3.0) as usize])
                })
                .collect();
            firsts.push(Arc::new(part));
        }
        let (mut shared, mut copied) = (Scene::new(ViewKind::Side), Scene::new(ViewKind::Side));
        let mut add = |part: Arc<Vec<Item>>| {
            for item in part.iter() {
                let Shape::Polyline { points } = &item.shape else { unreachable!() };
                copied.push(Item { shape: Shape::Polyline { points: points.to_vec().into() }, ..item.clone() }, true);
            }
            shared.items.push_shared(part);
        };
        let (mut repeated, mut varied) = (0, 0);
        for k in 0..firsts.len() {
            add(firsts[k].clone());
            let again = &firsts[(next() * (k + 1) as f64) as usize];
            let mut other = again.as_ref().clone();
            match (next() * 3.0) as usize {
                // The same part again.
                0 => {
                    add(again.clone());
                    repeated += 1;
                    continue;
                }
                // One path in the next pen.
                1 => {
                    let i = (next() * other.len() as f64) as usize;
                    other[i].style = styles[(styles.iter().position(|s| *s == other[i].style).unwrap() + 1) % 3];
                }
                // Its paths in reverse order.
                _ => other.reverse(),
            }
            varied += 1;
            add(Arc::new(other));
        }
        let view = View {
            width: 1000.0,
            height: 500.0,
            transform: Some(Transform { sx: 1.0, sy: 1.0, tx: 0.0, ty: 470.0 }),
            ..View::default()
        };
        let (a, b) = (display(&shared, &view), display(&copied, &view));
        assert!(repeated > 10 && varied > 20, "{repeated} repeated, {varied} varied");
        assert_eq!(a.ops, b.ops);
        assert_eq!(a.pens, b.pens);
    }
}
