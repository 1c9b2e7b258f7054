//! What a view's pointer is over, and what a hover or the cursor line marks:
//! scene items by source line or by pass, the item nearest a page point.

use super::Transform;
use super::held::ByPart;
use crate::diagram::scene::{Item, Pt, Scene, Shape};

/// How near the pointer an item must be, px.
pub const REACH: f64 = 7.0;

/// The lowest and highest source line of each part of a scene's items
/// (see [`crate::parts`]), kept from one scene to the next: a part the next
/// scene shares is not read again.
#[derive(Default)]
pub struct LineRanges {
    parts: ByPart<Lines>,
}

/// The lowest and highest line of some items (none: they draw no line).
type Lines = Option<(u32, u32)>;

impl LineRanges {
    /// The items drawn from any of `lines`, in order, each once: only the
    /// parts whose lines reach one of them are read.
    pub fn items_of_lines(&mut self, scene: &Scene, lines: &[u32]) -> Vec<usize> {
        self.parts.update(scene, range_of, |_| {});
        let mut out = Vec::new();
        for (start, part, range) in self.parts.each(scene) {
            let Some((lo, hi)) = *range else { continue };
            if !lines.iter().any(|l| (lo..=hi).contains(l)) {
                continue;
            }
            for (j, item) in part.iter().enumerate() {
                if item.lines.iter().any(|l| lines.contains(l)) {
                    out.push(start + j);
                }
            }
        }
        out
    }
}

/// The lowest and highest line the items of `part` draw (none: no line).
fn range_of(part: &[Item]) -> Lines {
    let all = part.iter().flat_map(|i| i.lines.iter().copied());
    all.fold(None, |r, l| Some(r.map_or((l, l), |(lo, hi): (u32, u32)| (lo.min(l), hi.max(l)))))
}

/// The items of pass `pass` of thread `thread`.
pub fn items_of_pass(scene: &Scene, thread: u32, pass: u32) -> Vec<usize> {
    let of = |it: &Item| it.thread == Some(thread) && it.pass == Some(pass);
    scene.items.iter().enumerate().filter(|(_, it)| of(it)).map(|(i, _)| i).collect()
}

/// The item under page point `p` at `xf`: the nearest within [`REACH`],
/// items of a pass before others; only items that point at a source line, a
/// thread or a pass.
pub fn pick(scene: &Scene, xf: &Transform, p: Pt) -> Option<usize> {
    let mut best: Option<(usize, f64, bool)> = None;
    for (i, item) in scene.items.iter().enumerate() {
        let has_pass = item.pass.is_some();
        if !has_pass && item.lines.is_empty() && item.thread.is_none() {
            continue;
        }
        let d = distance(item, xf, p);
        if d > REACH {
            continue;
        }
        let better = match best {
            None => true,
            Some((_, bd, bp)) => (has_pass && !bp) || (has_pass == bp && d < bd),
        };
        if better {
            best = Some((i, d, has_pass));
        }
    }
    best.map(|b| b.0)
}

/// Distance from page point `p` to the nearest part of `item`, px (0 inside
/// a polygon; infinite for labels and circles).
pub fn distance(item: &Item, xf: &Transform, p: Pt) -> f64 {
    match &item.shape {
        Shape::Polyline { points } | Shape::Polygon { points } => {
            let closed = matches!(item.shape, Shape::Polygon { .. });
            let pts: Vec<Pt> = points.iter().map(|q| xf.at(*q)).collect();
            let m = pts.len();
            let (mut best, mut inside) = (f64::INFINITY, false);
            for k in 0..m {
                let j = if closed { (k + 1) % m } else { k + 1 };
                if j >= m {
                    break;
                }
                let (a, b) = (pts[k], pts[j]);
                best = best.min(segment_distance(p, a, b));
                if closed
                    && (a[1] > p[1]) != (b[1] > p[1])
                    && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
                {
                    inside = !inside;
                }
            }
            if inside { 0.0 } else { best }
        }
        Shape::Marker { at, .. } => {
            let q = xf.at(*at);
            (p[0] - q[0]).hypot(p[1] - q[1])
        }
        Shape::Arrow { from, to } => segment_distance(p, xf.at(*from), xf.at(*to)),
        _ => f64::INFINITY,
    }
}

fn segment_distance(p: Pt, a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (p[0] - (a[0] + t * dx)).hypot(p[1] - (a[1] + t * dy))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::scene::{Style, ViewKind};
    use std::sync::Arc;

    /// The items drawn from source `line`, read item by item (what the parts' ranges must give).
    fn items_of_line(scene: &Scene, line: u32) -> Vec<usize> {
        scene.items.iter().enumerate().filter(|(_, it)| it.lines.contains(&line)).map(|(i, _)| i).collect()
    }

    #[test]
    fn the_nearest_pass_item_is_picked_before_a_nearer_other() {
        let mut s = Scene::new(ViewKind::Side);
        let line = |y: f64| Shape::Polyline { points: vec![[0.0, y], [10.0, y]].into() };
        s.push(Item::new(line(1.0), Style::OtherRapid).lines([3]), false);
        let mut pass = Item::new(line(1.4), Style::Cut).lines([7]);
        pass.thread = Some(0);
        pass.pass = Some(2);
        s.push(pass, false);
        let xf = Transform { sx: 10.0, sy: 10.0, tx: 0.0, ty: 100.0 };
        // y = 1.0 is page y 90, y = 1.4 is 86: at 89 the rapid is 1 px away, the pass 3 px.
        assert_eq!(pick(&s, &xf, [50.0, 89.0]), Some(1));
        assert_eq!(pick(&s, &xf, [50.0, 60.0]), None);
        assert_eq!(items_of_line(&s, 7), vec![1]);
        assert_eq!(items_of_pass(&s, 0, 2), vec![1]);
        assert_eq!(distance(&s.items[0], &xf, [50.0, 95.0]), 5.0);
    }

    /// The marked lines' items read by parts are those of every line read
    /// item by item, over scenes that share some parts with the one before
    /// (as the side section after a keystroke), parts replaced, and own items.
    #[test]
    fn items_of_lines_by_parts_are_those_of_each_line() {
        let mut next = crate::hash::unit_floats(0x2545_f491_4f6c_dd1d);
        let mut int = |n: u32| (next() * n as f64) as u32;
        let item = |lines: Vec<u32>| {
            Item::new(Shape::Polyline { points: vec![[0.0, 0.0], [1.0, 1.0]].into() }, Style::Cut).lines(lines)
        };
        let part = |int: &mut dyn FnMut(u32) -> u32| {
            let base = int(200);
            let n = 1 + int(6);
            Arc::new((0..n).map(|_| item((0..int(4)).map(|_| base + int(12)).collect())).collect::<Vec<_>>())
        };
        let mut parts: Vec<Arc<Vec<Item>>> = (0..30).map(|_| part(&mut int)).collect();
        let mut ranges = LineRanges::default();
        let mut read = 0;
        for round in 0..200 {
            // A keystroke: one part is new, the rest are shared with the scene before.
            let k = int(parts.len() as u32) as usize;
            parts[k] = part(&mut int);
            let mut s = Scene::new(ViewKind::Side);
            for _ in 0..int(3) {
                s.push(item(vec![int(220)]), false);
            }
            for p in &parts {
                s.items.push_shared(p.clone());
            }
            s.push(item(vec![int(220), int(220)]), false);
            let lines: Vec<u32> = (0..1 + int(3)).map(|_| int(220)).collect();
            let mut want: Vec<usize> = lines.iter().flat_map(|&l| items_of_line(&s, l)).collect();
            want.sort_unstable();
            want.dedup();
            assert_eq!(ranges.items_of_lines(&s, &lines), want, "round {round}, lines {lines:?}");
            // Only this scene's parts are held.
            assert_eq!(ranges.parts.len(), s.items.parts().count(), "round {round}");
            read += want.len();
        }
        assert!(read > 200, "the lines marked some items ({read})");
    }
}
