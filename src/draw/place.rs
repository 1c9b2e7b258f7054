//! Label placement: at a given
//! transform, a place for each label among its candidates so that no two
//! labels overlap and every label lies inside the view, crossing no
//! dimension line and none of the drawing's lines where it can. Greedy in a
//! stable priority order, the chosen thread's dimensions first. A label that
//! fits nowhere is dropped, never the chosen thread's major, minor or lead;
//! another thread's label is also dropped where it would cross a dimension.

use std::collections::HashMap;

use super::labels::{
    At, DimFrame, EDGE, Kind, LINE, Label, Room, Slot, dim_candidates, dim_frame, scene_labels, text_candidates,
    text_frame,
};
use super::lines::{LineIndex, segment_hits_box};
use super::{Placed, Read, Transform, View};
use crate::diagram::scene::{Anchor, Pt};

/// Whether boxes `a` and `b` overlap.
fn overlaps(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Placed boxes in a grid of 64 px cells, for overlap tests in about constant time.
#[derive(Default)]
struct Boxes {
    cells: HashMap<(i64, i64), Vec<usize>>,
    all: Vec<[f64; 4]>,
}

impl Boxes {
    /// The cells `b` covers.
    fn cells_of(b: &[f64; 4]) -> impl Iterator<Item = (i64, i64)> {
        let c = |v: f64| (v / 64.0).floor().clamp(-1e6, 1e6) as i64;
        let (i0, j0, i1, j1) = (c(b[0]), c(b[1]), c(b[2]), c(b[3]));
        (i0..=i1.min(i0 + 4096)).flat_map(move |i| (j0..=j1.min(j0 + 4096)).map(move |j| (i, j)))
    }

    fn hits(&self, b: &[f64; 4]) -> bool {
        Boxes::cells_of(b).any(|c| self.cells.get(&c).is_some_and(|l| l.iter().any(|&k| overlaps(b, &self.all[k]))))
    }

    /// Area of `b` covered by placed boxes (for a label that must go somewhere).
    fn cover(&self, b: &[f64; 4]) -> f64 {
        let part = |o: &[f64; 4]| (b[2].min(o[2]) - b[0].max(o[0])) * (b[3].min(o[3]) - b[1].max(o[1]));
        self.all.iter().filter(|o| overlaps(b, o)).map(part).sum()
    }

    fn add(&mut self, b: [f64; 4]) {
        let k = self.all.len();
        self.all.push(b);
        for c in Boxes::cells_of(&b) {
            self.cells.entry(c).or_default().push(k);
        }
    }
}

/// Whether segments p→q and r→s run along each other (nearly parallel, within 5 px, side by side).
fn segments_clash(p: Pt, q: Pt, r: Pt, s: Pt) -> bool {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let l = dx.hypot(dy);
    let (ex, ey) = (s[0] - r[0], s[1] - r[1]);
    let m = ex.hypot(ey);
    if l.is_nan() || m.is_nan() || l <= 0.0 || m <= 0.0 || (dx * ey - dy * ex).abs() > 0.17 * l * m {
        return false;
    }
    let across = |w: Pt| ((w[0] - p[0]) * dy - (w[1] - p[1]) * dx).abs() / l;
    if across(r) > 5.0 || across(s) > 5.0 {
        return false;
    }
    let along = |w: Pt| ((w[0] - p[0]) * dx + (w[1] - p[1]) * dy) / l;
    let (a, b) = (along(r), along(s));
    a.max(b) > 0.0 && a.min(b) < l
}

/// The line a dimension placed at `c` draws, on the page.
pub(super) fn dim_segment(lab: &Label, fr: &DimFrame, c: &At) -> (Pt, Pt) {
    if matches!(lab.kind, Kind::Half { .. }) {
        let s = c.s;
        return (s, [s[0] - fr.u[0] * c.len, s[1] - fr.u[1] * c.len]);
    }
    let (a, b, n, o) = (fr.a, fr.b, fr.n, c.off);
    ([a[0] + n[0] * o, a[1] + n[1] * o], [b[0] + n[0] * o, b[1] + n[1] * o])
}

/// The box of a candidate centred at (cx, cy).
fn box_at(c: &At, bw: f64, bh: f64) -> [f64; 4] {
    [c.cx - bw / 2.0, c.cy - bh / 2.0, c.cx + bw / 2.0, c.cy + bh / 2.0]
}

/// Whether box `b` is inside the view, `EDGE` from its sides.
fn inside(b: &[f64; 4], view: &Room) -> bool {
    view.all
        || (b[0] >= EDGE - 0.01 && b[1] >= EDGE - 0.01 && b[2] <= view.w - EDGE + 0.01 && b[3] <= view.h - EDGE + 0.01)
}

/// A label's box less its halo and padding: the drawing may touch that much.
fn shrink(b: &[f64; 4]) -> [f64; 4] {
    [b[0] + 2.0, b[1] + 2.0, b[2] - 2.0, b[3] - 2.0]
}

/// What the labels placed so far occupy.
#[derive(Default)]
struct Taken {
    boxes: Boxes,
    /// The lines of the dimensions placed.
    lines: Vec<(Pt, Pt)>,
}

/// The best place of `lab` among its candidates, and its score (0 clean, 1
/// crossing the drawing, 2 crossing a dimension): else, for a label that
/// must go somewhere, the place least covered by others.
fn choose(lab: &Label, xf: &Transform, view: &Room, taken: &Taken, drawing: Option<&LineIndex>) -> Option<(At, u8)> {
    let dim = dim_frame(lab, xf);
    let text = text_frame(lab, xf);
    let (bw, bh, cands) = match (&dim, &text) {
        (Some(fr), _) => (fr.bw, fr.bh, dim_candidates(lab, fr, view)),
        (None, Some(fr)) => (fr.bw, fr.bh, text_candidates(lab, fr, view)),
        (None, None) => return None,
    };
    let mut best: Option<(At, u8)> = None;
    let mut least: Option<(At, f64)> = None;
    for mut c in cands {
        c.bx = box_at(&c, bw, bh);
        if !inside(&c.bx, view) {
            continue;
        }
        if taken.boxes.hits(&c.bx) {
            if lab.must {
                let cover = taken.boxes.cover(&c.bx);
                if least.is_none_or(|(_, l)| cover < l) {
                    least = Some((c, cover));
                }
            }
            continue;
        }
        let mut crossing = taken.lines.iter().any(|&(p, q)| segment_hits_box(p, q, &c.bx));
        if let (false, Some(fr)) = (crossing, &dim) {
            let (p, q) = dim_segment(lab, fr, &c);
            crossing = taken.boxes.all.iter().any(|o| segment_hits_box(p, q, o))
                || taken.lines.iter().any(|&(r, t)| segments_clash(p, q, r, t));
        }
        let mut score = if crossing { 2 } else { 0 };
        let best_score = best.map_or(u8::MAX, |b| b.1);
        if score < best_score && drawing.is_some_and(|d| d.hits(&shrink(&c.bx), xf)) {
            score += 1;
        }
        if score < best_score {
            best = Some((c, score));
            if score == 0 {
                break;
            }
        }
    }
    // Another thread's label goes only where it crosses no dimension: else it is left out.
    best.filter(|&(_, s)| lab.chosen || s < 2).or_else(|| least.filter(|_| lab.must).map(|(c, _)| (c, 3)))
}

/// Places `labels` at `xf` in `view` (see the module documentation): sets
/// each label's `at`, or `None` when it is dropped. `drawing`: the lines
/// labels keep off.
pub(super) fn place(labels: &mut [Label], xf: &Transform, view: &Room, drawing: Option<&LineIndex>) {
    if !view.all {
        stack_texts(labels, xf, view);
    }
    let mut order: Vec<usize> = (0..labels.len()).collect();
    crate::order::sort_by_key(&mut order, |&k| labels[k].prio);
    let mut taken = Taken::default();
    for k in order {
        let lab = &labels[k];
        let Some((mut at, _)) = choose(lab, xf, view, &taken, drawing) else {
            labels[k].at = None;
            continue;
        };
        let dim = dim_frame(lab, xf);
        at.angle = if dim.is_some_and(|d| d.vertical) { -90.0 } else { 0.0 };
        if let (Some(fr), Kind::Text { dx, dy, .. }) = (text_frame(lab, xf), lab.kind) {
            let moved = (at.cy - fr.py).abs() >= if lab.slot == Slot::Free { LINE / 2.0 } else { 2.0 };
            if dx.hypot(dy) < LINE && moved {
                // A text beside its point, moved off its line, gets a leader from the point to its box.
                let lx = fr.x.max(at.bx[0]).min(at.bx[2]);
                let ly = fr.y.max(at.bx[1]).min(at.bx[3]);
                at.lead = Some([fr.x, fr.y, lx, ly]);
            }
        }
        taken.boxes.add(at.bx);
        if let Some(fr) = dim {
            taken.lines.push(dim_segment(lab, &fr, &at));
        }
        labels[k].at = Some(at);
    }
}

/// The labels of a scene (what `read` read of it) placed at `xf` on a `w × h`
/// page off the drawing's lines, as the painter takes them. Also the items of the labels dropped.
pub(super) fn placed(read: &Read, o: &View, xf: &Transform, (w, h): (f64, f64)) -> (Vec<Placed>, Vec<usize>) {
    let mut labels = scene_labels(&read.labelled, o, w);
    place(&mut labels, xf, &Room { w, h, all: false }, Some(&read.lines));
    let dropped = labels.iter().filter(|l| l.at.is_none()).map(|l| l.item).collect();
    (labels.iter().filter_map(placed_of).collect(), dropped)
}

/// A placed label as the painter takes it.
fn placed_of(l: &Label) -> Option<Placed> {
    let at = l.at?;
    let (lines, align) = match (&l.lines, l.kind) {
        (Some(lines), Kind::Text { anchor, .. }) => (lines.clone(), anchor),
        _ => (vec![l.text.clone()], Anchor::Middle),
    };
    Some(Placed {
        item: l.item,
        key: l.key.to_string(),
        lines,
        align,
        bounds: at.bx,
        angle: at.angle,
        off: at.off,
        len: at.len,
        lead: at.lead,
    })
}

/// A stack: texts that start (true) or end at one x, rounded.
type StackKey = (bool, i64);

/// The texts of stacks: three or more beside their points (no vertical
/// offset) that start or end at one x, as the depth of each pass beside the
/// tooth. Their order down the stack is kept: the stack keeps as many as fit
/// in the view (dropping the least important, from where they crowd most)
/// and moves each as little as it can (least squares, one line apart). Sets
/// `slot` on every label.
fn stack_texts(labels: &mut [Label], xf: &Transform, view: &Room) {
    let mut groups: Vec<(StackKey, Vec<(usize, f64)>)> = Vec::new();
    for (k, lab) in labels.iter_mut().enumerate() {
        lab.slot = Slot::Free;
        let Kind::Text { dy, anchor, .. } = lab.kind else { continue };
        if anchor == Anchor::Middle || dy.abs() > 1e-9 || lab.lines.is_some() {
            continue;
        }
        let Some(fr) = text_frame(lab, xf) else { continue };
        let key = (anchor == Anchor::Start, fr.px.round().clamp(-1e15, 1e15) as i64);
        match groups.iter_mut().find(|g| g.0 == key) {
            Some(g) => g.1.push((k, fr.py)),
            None => groups.push((key, vec![(k, fr.py)])),
        }
    }
    for (_, group) in groups.into_iter().filter(|g| g.1.len() >= 3) {
        for &(k, _) in &group {
            labels[k].slot = Slot::Out;
        }
        // Those beside the view are left out; the rest in order down the view.
        let mut g: Vec<(usize, f64)> = group.into_iter().filter(|&(_, y)| y >= 0.0 && y <= view.h).collect();
        crate::order::sort_by(&mut g, |p, q| p.1.total_cmp(&q.1).then(labels[p.0].item.cmp(&labels[q.0].item)));
        let s = LINE + 1.0;
        let (top, bottom) = (EDGE + LINE / 2.0, view.h - EDGE - LINE / 2.0);
        let room = ((bottom - top) / s).floor().max(-1.0) as i64 + 1;
        while g.len() as i64 > room {
            let Some(worst) = crowded(labels, &g) else { break };
            g.remove(worst);
        }
        for (&(k, _), y) in g.iter().zip(stack_slots(&g, s, top, bottom)) {
            labels[k].slot = Slot::At(y);
        }
    }
}

/// The label of a stack to leave out first: the least important, then the
/// one with the least room beside it, then the last; never a must.
fn crowded(labels: &[Label], g: &[(usize, f64)]) -> Option<usize> {
    let gap = |j: usize| {
        let before = if j > 0 { g[j].1 - g[j - 1].1 } else { f64::INFINITY };
        let after = if j + 1 < g.len() { g[j + 1].1 - g[j].1 } else { f64::INFINITY };
        before.min(after)
    };
    let mut worst: Option<usize> = None;
    for k in 0..g.len() {
        let a = &labels[g[k].0];
        if a.must {
            continue;
        }
        let Some(w) = worst else {
            worst = Some(k);
            continue;
        };
        let b = &labels[g[w].0];
        let (gk, gw) = (gap(k), gap(w));
        if a.prio > b.prio || (a.prio == b.prio && (gk < gw || (gk == gw && a.item > b.item))) {
            worst = Some(k);
        }
    }
    worst
}

/// The centres of a stack's boxes: each as near its own `y` as it can be,
/// one line (`s`) apart in order (pool-adjacent-violators on `y[k] − k·s`),
/// within `top..bottom`.
fn stack_slots(g: &[(usize, f64)], s: f64, top: f64, bottom: f64) -> Vec<f64> {
    let mut blocks: Vec<(f64, usize)> = Vec::new();
    for (k, &(_, y)) in g.iter().enumerate() {
        blocks.push((y - k as f64 * s, 1));
        while blocks.len() > 1 {
            let (b, a) = (blocks[blocks.len() - 1], blocks[blocks.len() - 2]);
            if a.0 / a.1 as f64 <= b.0 / b.1 as f64 {
                break;
            }
            blocks.pop();
            let last = blocks.len() - 1;
            blocks[last] = (a.0 + b.0, a.1 + b.1);
        }
    }
    let mut y: Vec<f64> = Vec::with_capacity(g.len());
    for (sum, n) in blocks {
        for _ in 0..n {
            y.push(sum / n as f64 + y.len() as f64 * s);
        }
    }
    for k in 0..y.len() {
        y[k] = y[k].max(if k > 0 { y[k - 1] + s } else { top });
    }
    for k in (0..y.len()).rev() {
        y[k] = y[k].min(if k + 1 < y.len() { y[k + 1] - s } else { bottom });
    }
    y
}
