//! A scene at a transform as display-list operations: the highlight's halos
//! beneath everything, paths of one pen together (one operation per pen, in
//! the order the pens first appear; a path that repeats one of its pen to
//! 1/8 px adds no ink and is left out, as is one wholly off the page), then
//! the other shapes in item order, each label where it was placed with its
//! dimension line, arrowheads and halo, and what the pointer is over again on top.

use std::collections::hash_map::Entry;
use std::collections::{HashMap, HashSet};
use std::hash::{Hash, Hasher};

use crate::hash::{BuildKeyHasher, KeyHasher};

use super::labels::LINE;
use super::list::{Builder, Op, Pen};
use super::pens::{HALO, HIGHLIGHT, HIGHLIGHT_HALO, ItemPen, pen_of};
use super::visit::{BatchKey, Visit};
use super::{Placed, Transform, View};
use crate::diagram::scene::{Anchor, Glyph, Item, Pt, Scene, Shape, Style, hash_points, same_points};

/// Paths wholly this far off the page are left out.
const CULL: f64 = 12.0;

/// Slots of the paths held last, by address ([`Painter::paths`]).
const RECENT: usize = 1024;

/// One pen's paths: its first item, the points, where each subpath starts,
/// and the subpaths seen (by the hash of their points to 1/8 px: the
/// first subpath of each hash).
struct Batch {
    key: BatchKey,
    first: usize,
    points: Vec<Pt>,
    starts: Vec<usize>,
    seen: HashMap<u64, usize, BuildKeyHasher>,
}

/// A point to 1/8 px (halves to even: one instruction in the wasm build, where `round` is a call).
fn eighths(p: &Pt) -> [i64; 2] {
    [(p[0] * 8.0).round_ties_even() as i64, (p[1] * 8.0).round_ties_even() as i64]
}

impl Batch {
    /// Adds subpath `pts` unless it repeats one of the batch's to 1/8 px.
    fn add(&mut self, pts: &[Pt]) {
        let mut h = KeyHasher::default();
        pts.iter().for_each(|p| eighths(p).hash(&mut h));
        h.write_usize(pts.len());
        let key = h.finish();
        match self.seen.get(&key) {
            Some(&k) => {
                let end = self.starts.get(k + 1).copied().unwrap_or(self.points.len());
                let old = &self.points[self.starts[k]..end];
                // The same hash of other points (all but never): drawn as well.
                if old.len() == pts.len() && old.iter().zip(pts).all(|(a, b)| eighths(a) == eighths(b)) {
                    return;
                }
            }
            None => {
                self.seen.insert(key, self.starts.len());
            }
        }
        self.starts.push(self.points.len());
        self.points.extend_from_slice(pts);
    }
}

/// Paints `scene` (its parts visited as `visit` gives them) at `xf` into `b`,
/// with labels `placed` and the mark `mark`.
pub(super) fn paint(b: &mut Builder, scene: &Scene, visit: &Visit, xf: &Transform, placed: &[Placed], view: &View) {
    let mark = &view.mark;
    let marked: HashSet<usize, BuildKeyHasher> =
        mark.items.iter().copied().filter(|&i| i < scene.items.len()).collect();
    let mark = if b.list.stale || marked.is_empty() { None } else { Some((&marked, mark.light)) };
    let mut p = Painter { b, xf };
    if let Some((set, light)) = mark {
        let by_item: HashMap<usize, &Placed, BuildKeyHasher> = placed.iter().map(|l| (l.item, l)).collect();
        p.halos(scene, set, light, &by_item);
    }
    p.paths(scene, visit, view.roughing);
    // Paths went with their pens in `paths`, their halos in `halos`: the
    // other shapes and the placed labels, in item order.
    let mut labels: Vec<&Placed> = placed.iter().collect();
    crate::order::sort_by_key(&mut labels, |l| l.item);
    let mut labels = labels.into_iter().peekable();
    for &(start, items, part) in visit {
        let end = start + items.len();
        let mut shapes = part.shapes.iter().map(|&k| start + k as usize).peekable();
        loop {
            let shape = shapes.peek().copied();
            let (i, placed) = match (shape, labels.peek().map(|l| l.item).filter(|&i| i < end)) {
                (_, Some(l)) if shape.is_none_or(|s| l < s) => (l, labels.next()),
                (Some(s), _) => {
                    shapes.next();
                    (s, None)
                }
                (None, _) => break,
            };
            let halo = match mark {
                Some((set, light)) if set.contains(&i) => HIGHLIGHT_HALO[usize::from(light)],
                _ => HALO,
            };
            p.item(&items[i - start], placed, halo);
        }
    }
    if let Some((set, false)) = mark {
        // What the pointer is over comes to the front: its lines in their own
        // pens, a filled area outlined (a second fill would change its colour).
        let mut front: Vec<usize> = set.iter().copied().collect();
        crate::order::sort(&mut front);
        for i in front {
            let item = &scene.items[i];
            match &item.shape {
                Shape::Polygon { points } => {
                    let pts: Vec<Pt> = points.iter().map(|q| xf.at(*q)).collect();
                    p.b.path(&pts, true, Pen { fill: None, ..Pen::stroke(HIGHLIGHT, 1.5) });
                }
                Shape::Polyline { points } => {
                    let pts: Vec<Pt> = points.iter().map(|q| xf.at(*q)).collect();
                    p.b.path(&pts, false, pen_of(item).pen);
                }
                Shape::Arrow { .. } | Shape::Marker { .. } => p.item(item, None, HALO),
                _ => {}
            }
        }
    }
}

/// Halos of one shape kind and width (closed, the width's bits): their points and where each path starts.
type HaloGroup = ((bool, u64), Vec<Pt>, Vec<usize>);

struct Painter<'a> {
    b: &'a mut Builder,
    xf: &'a Transform,
}

impl Painter<'_> {
    /// Highlights beneath the items, which keep their own colours on top. The
    /// halos of one width are one path (their union at one alpha): halos of
    /// close lines do not pile up into a solid colour between them.
    fn halos(
        &mut self,
        scene: &Scene,
        set: &HashSet<usize, BuildKeyHasher>,
        light: bool,
        by_item: &HashMap<usize, &Placed, BuildKeyHasher>,
    ) {
        let alpha = if light { 0.3 } else { 0.5 };
        let grow = if light { 4.0 } else { 6.0 };
        let mut groups: Vec<HaloGroup> = Vec::new();
        let mut add = |closed: bool, width: f64, pts: Vec<Pt>| {
            let key = (closed, width.to_bits());
            let g = match groups.iter().position(|g| g.0 == key) {
                Some(k) => &mut groups[k],
                None => {
                    groups.push((key, Vec::new(), Vec::new()));
                    groups.last_mut().expect("just pushed")
                }
            };
            g.2.push(g.1.len());
            g.1.extend(pts);
        };
        let mut dots = Vec::new();
        let mut ordered: Vec<usize> = set.iter().copied().collect();
        crate::order::sort(&mut ordered);
        for i in ordered {
            let item = &scene.items[i];
            let width = pen_of(item).pen.width + grow;
            let at = |q: &Pt| self.xf.at(*q);
            match &item.shape {
                Shape::Polyline { points } => add(false, width, points.iter().map(at).collect()),
                Shape::Polygon { points } => add(true, width, points.iter().map(at).collect()),
                Shape::Arrow { from, to } => add(false, width, vec![at(from), at(to)]),
                Shape::Circle { center, radius } => {
                    let pen = Pen { fill: None, ..Pen::stroke(HIGHLIGHT, width) }.faded(alpha);
                    self.b.circle(at(center), radius * self.xf.sx, pen);
                }
                Shape::Marker { at: q, .. } => dots.push(at(q)),
                Shape::Dim { .. } | Shape::Text { .. } => {
                    let Some(l) = by_item.get(&i) else { continue };
                    let [x0, y0, x1, y1] = l.bounds;
                    let bx = [[x0 - 1.0, y0], [x1 + 1.0, y0], [x1 + 1.0, y1], [x0 - 1.0, y1]];
                    self.b.path(&bx, true, Pen::fill(HIGHLIGHT).faded(alpha));
                    if let Shape::Dim { a, b, .. } = &item.shape {
                        for (p, q) in dim_lines(self.xf.at(*a), self.xf.at(*b), item.style == Style::Diameter, l) {
                            add(false, width, vec![p, q]);
                        }
                    }
                }
            }
        }
        for ((closed, width), points, starts) in groups {
            let pen = Pen { fill: None, ..Pen::stroke(HIGHLIGHT, f64::from_bits(width)) }.faded(alpha);
            let pen = self.b.pen(pen);
            self.b.list.ops.push(Op::Paths { pen, closed, points, starts });
        }
        for d in dots {
            self.b.circle(d, 6.0, Pen::fill(HIGHLIGHT).faded(alpha));
        }
    }

    /// Every polyline and polygon on the page, one operation per pen (roughing cuts only with `roughing`).
    fn paths(&mut self, scene: &Scene, visit: &Visit, roughing: bool) {
        let (w, h) = (self.b.list.width, self.b.list.height);
        let mut batches: Vec<Batch> = Vec::new();
        let mut index: HashMap<BatchKey, usize, BuildKeyHasher> = HashMap::default();
        let mut pts: Vec<Pt> = Vec::new();
        // A path of one pen drawn again exactly (a program's repeated sections)
        // goes where its first did (left out, or culled): known by the address
        // of its points when it shares them (see `wasm::memo`), else by its world points.
        let mut worlds: HashMap<u64, &[Pt], BuildKeyHasher> = HashMap::default();
        let mut held: HashSet<(usize, BatchKey), BuildKeyHasher> = HashSet::default();
        // The last path held in each slot, by its address: a path repeated many
        // times (thousands of passes over a few diameters) is known without a lookup.
        let mut recent: Vec<Option<(usize, BatchKey)>> = vec![None; RECENT];
        // The lists of paths painted (`PathSets`): a part whose every path an
        // earlier part held (a repeated section) is passed over whole.
        let mut painted: Vec<bool> = Vec::new();
        for &(start, items, part) in visit {
            let n = part.set as usize;
            if painted.len() <= n {
                painted.resize(n + 1, false);
            }
            if std::mem::replace(&mut painted[n], true) {
                continue;
            }
            for path in &part.paths {
                if path.rough && !roughing {
                    continue;
                }
                let (at, key) = (path.points, path.key);
                let slot = &mut recent[(at / std::mem::align_of::<Pt>()) % RECENT];
                if *slot == Some((at, key)) {
                    continue;
                }
                *slot = Some((at, key));
                if !held.insert((at, key)) {
                    continue;
                }
                let i = start + path.at as usize;
                let (Shape::Polyline { points } | Shape::Polygon { points }) = &items[path.at as usize].shape else {
                    continue;
                };
                let mut wh = KeyHasher::default();
                key.hash(&mut wh);
                hash_points(&mut wh, points);
                match worlds.entry(wh.finish()) {
                    Entry::Occupied(e) if same_points(e.get(), points) => continue,
                    Entry::Occupied(_) => {}
                    Entry::Vacant(e) => {
                        e.insert(points);
                    }
                }
                pts.clear();
                pts.extend(points.iter().map(|p| self.xf.at(*p)));
                let off = |k: usize, lo: f64, hi: f64| pts.iter().all(|p| p[k] < lo) || pts.iter().all(|p| p[k] > hi);
                if pts.len() < 2 || off(0, -CULL, w + CULL) || off(1, -CULL, h + CULL) {
                    continue;
                }
                let k = *index.entry(key).or_insert_with(|| {
                    let seen = HashMap::default();
                    batches.push(Batch { key, first: i, points: Vec::new(), starts: Vec::new(), seen });
                    batches.len() - 1
                });
                batches[k].add(&pts);
            }
        }
        for bt in batches {
            let pen = self.b.pen(pen_of(&scene.items[bt.first]).pen);
            self.b.list.ops.push(Op::Paths { pen, closed: bt.key.2, points: bt.points, starts: bt.starts });
        }
    }

    /// One item that is not a path (paths went with their pens already); a
    /// label only where it was `placed`.
    fn item(&mut self, item: &Item, placed: Option<&Placed>, halo: &str) {
        let pen = pen_of(item);
        let xf = self.xf;
        match &item.shape {
            Shape::Polyline { .. } | Shape::Polygon { .. } => {}
            Shape::Circle { center, radius } => self.b.circle(xf.at(*center), radius * xf.sx, pen.pen.clone()),
            Shape::Arrow { from, to } => self.arrow(xf.at(*from), xf.at(*to), &pen),
            Shape::Marker { at, glyph } => self.marker(xf.at(*at), *glyph, &pen),
            Shape::Dim { a, b, .. } => {
                if let Some(l) = placed {
                    self.dimension(xf.at(*a), xf.at(*b), item.style == Style::Diameter, l, &pen);
                    self.label(l, &pen, halo);
                }
            }
            Shape::Text { .. } => {
                if let Some(l) = placed {
                    if let Some([x0, y0, x1, y1]) = l.lead {
                        self.b.path(&[[x0, y0], [x1, y1]], false, Pen::stroke(pen.colour(), 0.7).faded(0.8));
                    }
                    self.label(l, &pen, halo);
                }
            }
        }
    }

    /// An arrow: its line in the pen, a filled head of the pen's stroke at `b`.
    fn arrow(&mut self, a: Pt, b: Pt, pen: &ItemPen) {
        self.b.path(&[a, b], false, pen.pen.clone());
        let t = (b[1] - a[1]).atan2(b[0] - a[0]);
        let (l, s) = (9.0, 0.42);
        let head = [
            [b[0] - l * (t - s).cos(), b[1] - l * (t - s).sin()],
            b,
            [b[0] - l * (t + s).cos(), b[1] - l * (t + s).sin()],
        ];
        let head_pen = Pen { fill: pen.pen.stroke.clone(), dash: Vec::new(), ..pen.pen.clone() };
        self.b.path(&head, true, head_pen);
    }

    fn marker(&mut self, [x, y]: Pt, glyph: Glyph, pen: &ItemPen) {
        let stroke = pen.pen.stroke.clone().unwrap_or_else(|| "#374151".into());
        match glyph {
            Glyph::Dot => self.b.circle([x, y], 3.0, Pen::fill(&stroke)),
            Glyph::Bar => self.b.path(&[[x, y - 6.0], [x, y + 6.0]], false, Pen::stroke(&stroke, 2.0)),
            Glyph::Cross => {
                let points = vec![[x - 4.0, y - 4.0], [x + 4.0, y + 4.0], [x - 4.0, y + 4.0], [x + 4.0, y - 4.0]];
                let pen = self.b.pen(Pen::stroke(&stroke, 1.6));
                self.b.list.ops.push(Op::Paths { pen, closed: false, points, starts: vec![0, 2] });
            }
        }
    }

    /// A placed dimension: extension lines, its line and arrowheads.
    fn dimension(&mut self, a: Pt, b: Pt, half: bool, l: &Placed, pen: &ItemPen) {
        let Some((u, n)) = frame(a, b) else { return };
        let lines = dim_lines(a, b, half, l);
        let stroke = pen.pen.stroke.clone().unwrap_or_else(|| "#374151".into());
        for (p, q) in lines.iter().skip(1) {
            self.b.path(&[*p, *q], false, Pen::stroke(&stroke, 0.8));
        }
        let (p, q) = lines[0];
        self.b.path(&[p, q], false, pen.pen.clone());
        let at = |x: Pt, k: f64| [x[0] + n[0] * k, x[1] + n[1] * k];
        let mut head = |x: Pt, dir: f64| {
            let (lh, wh) = (7.0, 2.6);
            let base = [x[0] - u[0] * lh * dir, x[1] - u[1] * lh * dir];
            self.b.path(&[x, at(base, wh), at(base, -wh)], true, Pen::fill(&stroke));
        };
        if half {
            head(p, 1.0);
        } else if (q[0] - p[0]).hypot(q[1] - p[1]) > 20.0 {
            head(p, -1.0);
            head(q, 1.0);
        } else {
            head(p, 1.0);
            head(q, -1.0);
        }
    }

    /// A label's text in its box over a halo: one line centred (rotated by
    /// its angle), or several lines a line apart, lined up as placed.
    fn label(&mut self, l: &Placed, pen: &ItemPen, halo: &str) {
        let [x0, y0, x1, y1] = l.bounds;
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        let x = match l.align {
            Anchor::Start => x0 + 2.0,
            Anchor::End => x1 - 2.0,
            Anchor::Middle => cx,
        };
        let n = l.lines.len() as f64;
        for (k, line) in l.lines.iter().enumerate() {
            if !line.is_empty() {
                let y = cy + (k as f64 - (n - 1.0) / 2.0) * LINE;
                self.b.text([x, y], line, &pen.text, halo, l.align, l.angle);
            }
        }
    }
}

/// A dimension's direction `u` (a→b) and left normal `n` on the page; none when its ends meet.
fn frame(a: Pt, b: Pt) -> Option<(Pt, Pt)> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    if len.is_nan() || len <= 1e-9 {
        return None;
    }
    let u = [dx / len, dy / len];
    Some((u, [u[1], -u[0]]))
}

/// The lines a placed dimension draws, its own line first, then its
/// extension lines. A half dimension (of a diameter, from the axis `a`) has
/// one arrowhead, at `b`; its line runs towards the axis as far as placed.
fn dim_lines(a: Pt, b: Pt, half: bool, l: &Placed) -> Vec<(Pt, Pt)> {
    let Some((u, n)) = frame(a, b) else { return vec![(a, b)] };
    let o = l.off;
    let sgn = if o >= 0.0 { 1.0 } else { -1.0 };
    let at = |p: Pt, k: f64| [p[0] + n[0] * k, p[1] + n[1] * k];
    let (line, ends): ((Pt, Pt), &[Pt]) = if half {
        let s = at(b, o);
        ((s, [s[0] - u[0] * l.len, s[1] - u[1] * l.len]), &[b])
    } else {
        ((at(a, o), at(b, o)), &[a, b])
    };
    let mut out = vec![line];
    if o.abs() > 3.0 {
        out.extend(ends.iter().map(|&p| (at(p, 2.0 * sgn), at(p, o + 4.0 * sgn))));
    }
    out
}

#[cfg(test)]
pub(super) mod tests {
    use crate::diagram::scene::{Item, Scene, Shape, Style, ViewKind};
    use crate::draw::{Op, Transform, View, display};

    /// A polyline of `points` in `style`.
    pub(in crate::draw) fn line(points: &[[f64; 2]], style: Style) -> Item {
        Item::new(Shape::Polyline { points: points.into() }, style)
    }

    #[test]
    fn a_path_that_repeats_one_of_its_pen_to_an_eighth_of_a_pixel_is_left_out() {
        let mut s = Scene::new(ViewKind::Side);
        s.push(line(&[[0.0, 0.0], [10.0, 0.0]], Style::Cut), true);
        // 0.01 px off the first (at 1 px per unit): the same to 1/8 px.
        s.push(line(&[[0.01, 0.0], [10.0, 0.01]], Style::Cut), true);
        // 0.2 px off: another path.
        s.push(line(&[[0.2, 0.0], [10.0, 0.0]], Style::Cut), true);
        // The first again in another pen: drawn with that pen.
        s.push(line(&[[0.0, 0.0], [10.0, 0.0]], Style::Rapid), true);
        // Wholly off the page: left out.
        s.push(line(&[[-500.0, 0.0], [-400.0, 0.0]], Style::Cut), true);
        s.finish();
        let view = View { transform: Some(Transform { sx: 1.0, sy: 1.0, tx: 100.0, ty: 100.0 }), ..View::default() };
        let list = display(&s, &view);
        let paths: Vec<(usize, usize)> = list
            .ops
            .iter()
            .filter_map(|op| match op {
                Op::Paths { points, starts, .. } => Some((starts.len(), points.len())),
                _ => None,
            })
            .collect();
        assert_eq!(paths, [(2, 4), (1, 2)]);
    }

    /// Exact repeats of a path in its own pen are left out without being
    /// drawn again (found by their world points): the list is the one of the
    /// scene without them; a repeat in another pen, or of a path off the page, is not lost or drawn.
    #[test]
    fn exact_repeats_draw_what_the_scene_without_them_draws() {
        let mut next = crate::hash::unit_floats(0x2545_f491_4f6c_dd1d);
        let styles = [Style::Cut, Style::Rapid, Style::Outline];
        let mut firsts: Vec<Item> = Vec::new();
        for _ in 0..300 {
            let n = 2 + (next() * 4.0) as usize;
            // Some wholly off the page (x beyond 1,000 px).
            let off = if next() < 0.2 { 2000.0 } else { 0.0 };
            let pts: Vec<[f64; 2]> = (0..n).map(|_| [off + next() * 700.0, next() * 400.0]).collect();
            firsts.push(line(&pts, styles[(next() * 3.0) as usize]));
        }
        let mut with = Scene::new(ViewKind::Side);
        let mut without = Scene::new(ViewKind::Side);
        for (k, it) in firsts.iter().enumerate() {
            with.push(it.clone(), true);
            without.push(it.clone(), true);
            // An earlier path again: in its own pen (left out) or in the next pen (drawn).
            let again = &firsts[(next() * (k + 1) as f64) as usize];
            with.push(again.clone(), true);
            let mut other = again.clone();
            other.style = styles[(styles.iter().position(|s| *s == other.style).unwrap() + 1) % 3];
            with.push(other.clone(), true);
            without.push(other, true);
        }
        with.finish();
        without.finish();
        let view = View {
            width: 1000.0,
            height: 500.0,
            transform: Some(Transform { sx: 1.0, sy: 1.0, tx: 0.0, ty: 450.0 }),
            ..View::default()
        };
        let (a, b) = (display(&with, &view), display(&without, &view));
        assert_eq!(a.ops, b.ops);
        assert_eq!(a.pens, b.pens);
        let drawn: usize =
            a.ops.iter().map(|op| if let Op::Paths { starts, .. } = op { starts.len() } else { 0 }).sum();
        assert!(drawn > 300, "{drawn} paths drawn");
    }
}
