//! What a view keeps of its last scene between drawings, part by part (a
//! scene's items as [`crate::parts::Parts`] shares them): the lines each
//! part adds to the drawing's lines, and which of its items have labels. A
//! scene put together again from the pieces that did not change (a
//! keystroke in a large program) reads only its new parts; what is drawn
//! is what reading the whole scene gives.

use std::collections::HashMap;
use std::sync::Arc;

use super::labels::has_label;
use super::lines::{LineIndex, MAX_SEGMENTS, crossable, one_way, scene_lines, segments};
use crate::diagram::scene::{Item, Scene, Shape};
use crate::hash::BuildKeyHasher;

/// What one item of a part adds to the drawing's lines: a path (by the
/// address of its points, which paths drawn again exactly share), or a segment.
enum Line {
    Path(PathKey),
    Segment([u64; 4]),
}

/// A path's points (their address) and whether it is closed.
type PathKey = (usize, bool);

/// How many times each segment is held.
type Counts = HashMap<[u64; 4], u32, BuildKeyHasher>;

/// Each path held: how many items hold it, and its segments.
type Paths = HashMap<PathKey, (u32, Vec<[u64; 4]>), BuildKeyHasher>;

/// One part of the last scene.
struct Part {
    /// The part itself, held so that no other part takes its address.
    _held: Arc<Vec<Item>>,
    /// What its items add to the drawing's lines.
    lines: Vec<Line>,
    /// Its items with labels, by their place in the part.
    labelled: Vec<u32>,
    /// The drawing that last had it.
    last: u32,
}

/// What a view keeps of the parts of its last scene (see the module
/// documentation), and how many times each path and each segment of the
/// drawing's lines is held.
#[derive(Default)]
pub struct Held {
    /// The last scene's parts by the address of their items.
    parts: HashMap<usize, Part, BuildKeyHasher>,
    paths: Paths,
    counts: Counts,
    /// Drawings so far.
    calls: u32,
}

impl Held {
    /// Takes in `scene`: its new parts are read, the parts it no longer has are let go.
    pub(super) fn update(&mut self, scene: &Scene) {
        self.calls = self.calls.wrapping_add(1);
        let call = self.calls;
        let Held { parts, paths, counts, .. } = self;
        for (_, part) in scene.items.parts() {
            let at = Arc::as_ptr(part) as usize;
            match parts.get_mut(&at) {
                Some(kept) => kept.last = call,
                None => {
                    let lines = add(part, paths, counts);
                    let labelled =
                        part.iter().enumerate().filter(|(_, i)| has_label(i)).map(|(k, _)| k as u32).collect();
                    parts.insert(at, Part { _held: part.clone(), lines, labelled, last: call });
                }
            }
        }
        parts.retain(|_, part| {
            if part.last == call {
                return true;
            }
            remove(&part.lines, paths, counts);
            false
        });
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

    /// The items of `scene` (taken in by [`Held::update`]) that have labels, with their indices, in order.
    pub(super) fn labelled<'s>(&self, scene: &'s Scene) -> Vec<(usize, &'s Item)> {
        let mut out = Vec::new();
        for (start, part) in scene.items.parts() {
            let Some(kept) = self.parts.get(&(Arc::as_ptr(part) as usize)) else { continue };
            out.extend(kept.labelled.iter().map(|&k| (start + k as usize, &part[k as usize])));
        }
        out
    }
}

/// Counts in the lines of the items of a part whose lines may not be crossed; what they add.
fn add(items: &[Item], paths: &mut Paths, counts: &mut Counts) -> Vec<Line> {
    let mut lines = Vec::new();
    let mut world = Vec::new();
    for item in items.iter().filter(|i| !crossable(i.style)) {
        let key = match &item.shape {
            Shape::Polyline { points } => Some((points.as_ptr() as usize, false)),
            Shape::Polygon { points } => Some((points.as_ptr() as usize, true)),
            _ => None,
        };
        world.clear();
        if let Some(key) = key {
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
    use crate::diagram::scene::{Rect, Style};

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
        let a = of_parts(&parts, whole.focus);
        // A pass moved (its part built again), a part gone, a new one at the end.
        let mut b_parts = parts.clone();
        let at = b_parts.iter().position(|p| p.iter().any(|i| i.style == Style::Cut)).expect("a part with a cut");
        let mut moved = (*b_parts[at]).clone();
        for item in moved.iter_mut().filter(|i| i.style == Style::Cut) {
            if let Shape::Polyline { points } = &mut item.shape {
                *points = points.iter().map(|p| [p[0], p[1] - 0.25]).collect();
            }
        }
        b_parts[at] = Arc::new(moved);
        b_parts.remove(at + 2);
        b_parts.push(Arc::new(vec![Item::new(Shape::Arrow { from: [1.0, 2.0], to: [3.0, 5.0] }, Style::Cut)]));
        let b = of_parts(&b_parts, whole.focus);
        // More segments than are kept: the first ones, as `scene_lines` takes them.
        let many: Vec<Item> = (0..MAX_SEGMENTS + 10)
            .map(|k| {
                let x = k as f64 * 0.01;
                Item::new(Shape::Polyline { points: vec![[x, 0.0], [x, 1.0]].into() }, Style::Cut)
            })
            .collect();
        let mut c_parts = b_parts.clone();
        c_parts.push(Arc::new(many));
        let c = of_parts(&c_parts, whole.focus);
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
        }
        // What was asked for: the changed pass, the part gone and the arrow each changed the lines.
        let (la, lb) = (scene_lines(&a).sorted(), scene_lines(&b).sorted());
        assert!(la.len() > 20 && la != lb);
        assert_eq!(scene_lines(&c).sorted().len(), MAX_SEGMENTS);
        // Only the last scene's parts are kept.
        assert_eq!(held.parts.len(), parts.len());
    }
}
