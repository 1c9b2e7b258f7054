//! The drawing's lines, which labels prefer not to cross: the segments
//! of paths, arrows and circles in a grid of world cells built once per
//! scene; a label's box on the page is taken back to world coordinates to
//! find the lines near it. Between drawings of one view the segments are
//! kept by the scene's shared parts (`draw::held`).

use std::collections::HashSet;

use super::Transform;
use crate::diagram::scene::{Pt, Rect, Scene, Shape, Style};
use crate::hash::BuildKeyHasher;

/// Most of the drawing's segments labels keep off (those of threads first).
pub(super) const MAX_SEGMENTS: usize = 20_000;
/// Cells of the grid on each axis, plus one on each side for what lies beyond.
const CELLS: i64 = 64;
const N: usize = CELLS as usize + 2;
/// A segment across more cells than this is tested every time.
const WIDE: i64 = 256;

/// Whether segment p→q crosses box `b` (`[x0, y0, x1, y1]`).
pub(super) fn segment_hits_box(p: Pt, q: Pt, b: &[f64; 4]) -> bool {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (pp, qq) in [(-dx, p[0] - b[0]), (dx, b[2] - p[0]), (-dy, p[1] - b[1]), (dy, b[3] - p[1])] {
        if pp == 0.0 {
            if qq < 0.0 {
                return false;
            }
            continue;
        }
        let r = qq / pp;
        if pp < 0.0 {
            t0 = t0.max(r);
        } else {
            t1 = t1.min(r);
        }
        if t0 > t1 {
            return false;
        }
    }
    true
}

/// World segments `[x0, y0, x1, y1]` in a grid over a rectangle.
pub(super) struct LineIndex {
    world: Vec<[f64; 4]>,
    x0: f64,
    y0: f64,
    cw: f64,
    ch: f64,
    /// Cell `c` holds `list[start[c]..start[c + 1]]`.
    start: Vec<usize>,
    list: Vec<usize>,
    /// Segments across many cells, tested every time.
    wide: Vec<usize>,
}

impl LineIndex {
    /// The index of `world` segments, finest over `rect`.
    pub fn new(world: Vec<[f64; 4]>, rect: Rect) -> LineIndex {
        let mut ix = LineIndex {
            world: Vec::new(),
            x0: rect.x0,
            y0: rect.y0,
            cw: (rect.width() / CELLS as f64).max(1e-9),
            ch: (rect.height() / CELLS as f64).max(1e-9),
            start: vec![0; N * N + 1],
            list: Vec::new(),
            wide: Vec::new(),
        };
        // The cells of each segment (columns and rows, as usize), or none when wide or not finite.
        let mut spans: Vec<Option<[usize; 4]>> = Vec::with_capacity(world.len());
        for (k, s) in world.iter().enumerate() {
            let span = match ix.span(s) {
                Some((i0, i1, j0, j1)) if (i1 - i0 + 1) * (j1 - j0 + 1) <= WIDE => {
                    Some([i0 as usize, i1 as usize, j0 as usize, j1 as usize])
                }
                Some(_) => {
                    ix.wide.push(k);
                    None
                }
                None => None,
            };
            if let Some([i0, i1, j0, j1]) = span {
                // Plain loops: an iterator of cells is several times slower in the wasm build.
                for i in i0..=i1 {
                    ix.start[i * N + j0 + 1..=i * N + j1 + 1].iter_mut().for_each(|n| *n += 1);
                }
            }
            spans.push(span);
        }
        for c in 1..ix.start.len() {
            ix.start[c] += ix.start[c - 1];
        }
        let mut fill = ix.start.clone();
        ix.list = vec![0; ix.start[N * N]];
        for (k, span) in spans.iter().enumerate() {
            if let Some([i0, i1, j0, j1]) = *span {
                for i in i0..=i1 {
                    for at in &mut fill[i * N + j0..=i * N + j1] {
                        ix.list[*at] = k;
                        *at += 1;
                    }
                }
            }
        }
        ix.world = world;
        ix
    }

    /// The segments indexed, as bits, sorted.
    #[cfg(test)]
    pub(super) fn sorted(&self) -> Vec<[u64; 4]> {
        let mut v: Vec<[u64; 4]> = self.world.iter().map(|w| w.map(f64::to_bits)).collect();
        v.sort_unstable();
        v
    }

    /// The cell columns and rows (shifted by one) a finite segment spans.
    fn span(&self, s: &[f64; 4]) -> Option<(i64, i64, i64, i64)> {
        if !s.iter().all(|v| v.is_finite()) {
            return None;
        }
        let (i0, i1) = (self.col(s[0].min(s[2])) + 1, self.col(s[0].max(s[2])) + 1);
        let (j0, j1) = (self.row(s[1].min(s[3])) + 1, self.row(s[1].max(s[3])) + 1);
        Some((i0, i1, j0, j1))
    }

    /// The cells of columns `i0..=i1` and rows `j0..=j1`, as indices.
    fn cells(i0: i64, i1: i64, j0: i64, j1: i64) -> impl Iterator<Item = usize> {
        (i0..=i1).flat_map(move |i| (j0..=j1).map(move |j| i as usize * N + j as usize))
    }

    fn col(&self, x: f64) -> i64 {
        ((x - self.x0) / self.cw).floor().clamp(-1.0, CELLS as f64) as i64
    }

    fn row(&self, y: f64) -> i64 {
        ((y - self.y0) / self.ch).floor().clamp(-1.0, CELLS as f64) as i64
    }

    /// Whether a line crosses the page box `b` under transform `xf`.
    pub fn hits(&self, b: &[f64; 4], xf: &Transform) -> bool {
        let test = |k: usize| {
            let w = &self.world[k];
            segment_hits_box(xf.at([w[0], w[1]]), xf.at([w[2], w[3]]), b)
        };
        if self.wide.iter().any(|&k| test(k)) {
            return true;
        }
        let (i0, i1) = (self.col((b[0] - xf.tx) / xf.sx), self.col((b[2] - xf.tx) / xf.sx));
        let (j0, j1) = (self.row((xf.ty - b[3]) / xf.sy), self.row((xf.ty - b[1]) / xf.sy));
        if i0 > i1 || j0 > j1 {
            return false;
        }
        LineIndex::cells(i0 + 1, i1 + 1, j0 + 1, j1 + 1)
            .any(|c| self.list[self.start[c]..self.start[c + 1]].iter().any(|&k| test(k)))
    }
}

/// Styles whose lines labels may cross: centre lines and filled zones.
pub(super) fn crossable(style: Style) -> bool {
    matches!(style, Style::Axis | Style::ThreadZone | Style::Delta1 | Style::Delta2 | Style::Material)
}

/// The segments of one item: paths (polygons closed), arrows, circles as 24 chords.
pub(super) fn segments(shape: &Shape, out: &mut Vec<[f64; 4]>) {
    let path = |points: &[Pt], closed: bool, out: &mut Vec<[f64; 4]>| {
        out.extend(points.windows(2).map(|w| [w[0][0], w[0][1], w[1][0], w[1][1]]));
        if let (true, Some(first), Some(last)) = (closed && points.len() >= 3, points.first(), points.last()) {
            out.push([last[0], last[1], first[0], first[1]]);
        }
    };
    match shape {
        Shape::Polyline { points } => path(points, false, out),
        Shape::Polygon { points } => path(points, true, out),
        Shape::Arrow { from, to } => path(&[*from, *to], false, out),
        Shape::Circle { center: [x, y], radius: r } => {
            let at = |k: f64| {
                let a = k * std::f64::consts::PI / 12.0;
                [x + r * a.cos(), y + r * a.sin()]
            };
            out.extend((0..24).map(|k| {
                let (p, q) = (at(f64::from(k)), at(f64::from(k + 1)));
                [p[0], p[1], q[0], q[1]]
            }));
        }
        _ => {}
    }
}

/// The drawing's lines that labels keep off: every segment of the items
/// whose lines may not be crossed, the threads' items first, each once
/// (passes and rapids over the same path repeat them: a repeat would only
/// cost the grid), at most [`MAX_SEGMENTS`], in a grid over the scene's focus.
pub(super) fn scene_lines(scene: &Scene) -> LineIndex {
    let mut out = Vec::new();
    let mut seen: HashSet<[u64; 4], BuildKeyHasher> = HashSet::default();
    // Paths that share their points (see `wasm::memo`) add no segment after the first.
    let mut held: HashSet<PathKey, BuildKeyHasher> = HashSet::default();
    'all: for of_threads in [true, false] {
        for item in scene.items.iter().filter(|i| i.thread.is_some() == of_threads && !crossable(i.style)) {
            if path_key(&item.shape).is_some_and(|p| !held.insert(p)) {
                continue;
            }
            let from = out.len();
            segments(&item.shape, &mut out);
            let mut kept = from;
            for k in from..out.len() {
                let key = one_way(out[k]);
                if seen.insert(key) {
                    out[kept] = key.map(f64::from_bits);
                    kept += 1;
                }
            }
            out.truncate(kept);
            if out.len() > MAX_SEGMENTS {
                out.truncate(MAX_SEGMENTS);
                break 'all;
            }
        }
    }
    LineIndex::new(out, scene.focus)
}

/// A path's points (their address: paths drawn again exactly share them,
/// `wasm::memo`) and whether it is closed.
pub(super) type PathKey = (usize, bool);

/// The key of a path (polyline or polygon); none for other shapes.
pub(super) fn path_key(shape: &Shape) -> Option<PathKey> {
    match shape {
        Shape::Polyline { points } => Some((points.as_ptr() as usize, false)),
        Shape::Polygon { points } => Some((points.as_ptr() as usize, true)),
        _ => None,
    }
}

/// A segment's bits, one way round: either direction is the same line.
pub(super) fn one_way([x0, y0, x1, y1]: [f64; 4]) -> [u64; 4] {
    let key = if (x0, y0) <= (x1, y1) { [x0, y0, x1, y1] } else { [x1, y1, x0, y0] };
    key.map(f64::to_bits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_finds_exactly_the_segments_a_box_crosses() {
        let rect = Rect { x0: 0.0, y0: 0.0, x1: 100.0, y1: 40.0 };
        let mut next = crate::hash::unit_floats(0x9e37_79b9_7f4a_7c15);
        // Short segments, long ones (wide in the grid) and some beyond the rectangle.
        let world: Vec<[f64; 4]> = (0..3000)
            .map(|k| {
                let (x, y) = (next() * 140.0 - 20.0, next() * 60.0 - 10.0);
                let reach = if k % 10 == 0 { 120.0 } else { 6.0 };
                [x, y, x + (next() - 0.5) * reach, y + (next() - 0.5) * reach / 3.0]
            })
            .collect();
        let ix = LineIndex::new(world.clone(), rect);
        let xf = Transform { sx: 8.0, sy: 8.0, tx: 20.0, ty: 400.0 };
        let (mut hits, mut misses) = (0, 0);
        for _ in 0..2000 {
            let (x, y) = (next() * 1000.0 - 50.0, next() * 500.0 - 50.0);
            let b = [x, y, x + next() * 30.0, y + next() * 10.0];
            let brute = world.iter().any(|w| segment_hits_box(xf.at([w[0], w[1]]), xf.at([w[2], w[3]]), &b));
            assert_eq!(ix.hits(&b, &xf), brute, "box {b:?}");
            if brute { hits += 1 } else { misses += 1 }
        }
        // Both answers were asked for.
        assert!(hits > 100 && misses > 100, "{hits} hits, {misses} misses");
    }

    /// A polygon holding the points of a polyline before it keeps its closing side.
    #[test]
    fn a_polygon_sharing_a_polylines_points_keeps_its_closing_side() {
        use crate::diagram::scene::{Item, ViewKind};
        let pts: std::sync::Arc<[Pt]> = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]].into();
        let mut s = Scene::new(ViewKind::Side);
        s.push(Item::new(Shape::Polyline { points: pts.clone() }, Style::Cut), true);
        s.push(Item::new(Shape::Polygon { points: pts }, Style::Outline), true);
        s.finish();
        let xf = Transform { sx: 10.0, sy: 10.0, tx: 0.0, ty: 200.0 };
        // The closing side runs from (10, 10) to (0, 0): its middle (5, 5) is at page (50, 150).
        assert!(scene_lines(&s).hits(&[48.0, 148.0, 52.0, 152.0], &xf));
    }
}
