//! The side section's broken radial scale, as a manual draws a long part:
//! beyond a little above the crest of the threads (below it, for internal
//! threads) the radial distance is compressed — logarithmically, so the
//! retract a few millimetres out stays readable while a far return takes
//! little room — and a break line with a note marks where. The passes, the
//! crest and the root keep their true scale; the labels keep the true values.
//! The side section's first fit then frames the thread and its passes.

use super::band::Band;
use super::scene::{Anchor, Item, Label, Pt, Rect, Scene, Shape, Style};
use crate::plan::Plan;
use crate::thread::Axis;

/// How far beyond the crest the true scale goes, in thread heights.
const KEEP: f64 = 0.5;
/// The compressed scale's unit, in thread heights: distance `d` beyond the break becomes `S·ln(1 + d/S)`.
const UNIT: f64 = 0.75;
/// Distances beyond the break shorter than this many units are not worth breaking for.
const WORTH: f64 = 4.0;

/// One break: at radius `at`, compressing beyond it outward (`out`: larger radii) or inward.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Break {
    /// The radius where the true scale ends.
    pub at: f64,
    /// The compressed scale's unit (mm).
    pub unit: f64,
    /// Compress the radii above `at` (external threads), else below.
    pub out: bool,
}

impl Break {
    /// The drawn radius of radius `r`.
    pub fn map(&self, r: f64) -> f64 {
        let d = if self.out { r - self.at } else { self.at - r };
        if d <= 0.0 || !d.is_finite() {
            return r;
        }
        let c = self.unit * (d / self.unit).ln_1p();
        if self.out { self.at + c } else { self.at - c }
    }

    /// The drawn point of world point `p`.
    fn point(&self, p: Pt) -> Pt {
        [p[0], self.map(p[1])]
    }

    /// Where segment a→b crosses the break line, if it does (strictly).
    fn crossing(&self, a: Pt, b: Pt) -> Option<Pt> {
        let (da, db) = (a[1] - self.at, b[1] - self.at);
        if da * db >= 0.0 {
            return None;
        }
        let t = da / (da - db);
        Some([a[0] + t * (b[0] - a[0]), self.at])
    }

    /// A path through the break: crossings inserted so that the true-scale part stays straight.
    fn path(&self, points: &[Pt], closed: bool) -> Vec<Pt> {
        let mut out = Vec::with_capacity(points.len() + 2);
        let n = points.len();
        for (k, &p) in points.iter().enumerate() {
            out.push(self.point(p));
            let next = if k + 1 < n {
                Some(points[k + 1])
            } else if closed && n > 2 {
                Some(points[0])
            } else {
                None
            };
            if let Some(c) = next.and_then(|q| self.crossing(p, q)) {
                out.push(c);
            }
        }
        out
    }
}

/// The lowest and highest radius of `items`, the axis and the diameter
/// dimensions left out (what [`breaks`] weighs).
pub fn extent<'a>(items: impl IntoIterator<Item = &'a Item>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for item in items.into_iter().filter(|i| !matches!(i.style, Style::Axis | Style::Diameter)) {
        item.each_point(|p| (lo, hi) = (crate::num::min(lo, p[1]), crate::num::max(hi, p[1])));
    }
    (lo, hi)
}

/// The breaks the side section of `plan` takes: one outward for its
/// external threads along Z, one inward for its internal ones, each only
/// where something lies far enough beyond it — its items' radii reach from
/// `lo` to `hi` ([`extent`]).
pub fn breaks(plan: &Plan, (lo, hi): (f64, f64)) -> Vec<Break> {
    let mut out = Vec::new();
    for internal in [false, true] {
        // The deepest thread's height and the outermost crest (innermost for internal threads), in one pass.
        use crate::num::{max, min};
        let crest = |b: &Band| {
            let (c0, c1) = (b.crest(b.l0), b.crest(b.l1));
            if internal { min(c0, c1) } else { max(c0, c1) }
        };
        let (mut h, mut edge, mut any) = (0.0, if internal { f64::INFINITY } else { f64::NEG_INFINITY }, false);
        let bands = plan.threads.iter().filter(|t| t.internal == internal && t.long_axis == Axis::Z);
        for b in bands.filter_map(|t| Band::of(t).filter(|b| b.height.is_finite() && t.height > 0.0)) {
            any = true;
            h = max(h, b.height);
            edge = if internal { min(edge, crest(&b)) } else { max(edge, crest(&b)) };
        }
        if !any {
            continue;
        }
        let at = if internal { edge - KEEP * h } else { edge + KEEP * h };
        let unit = UNIT * h;
        let far = if internal { at - lo } else { hi - at }.max(0.0);
        if far > WORTH * unit && at.is_finite() && (!internal || at > 0.0) {
            out.push(Break { at, unit, out: !internal });
        }
    }
    out
}

/// Applies the breaks of `plan` to its side section `scene`: every item's
/// radii through each break, the bounds and focus too, and a break line
/// with its note across the focus.
pub fn apply(scene: &mut Scene, plan: &Plan) {
    let list = breaks(plan, extent(scene.items.iter()));
    if list.is_empty() {
        return;
    }
    for item in scene.items.iter_mut() {
        map_item(&list, item);
    }
    finish(&list, scene);
}

/// `item` drawn through each break of `list` in turn.
pub fn map_item(list: &[Break], item: &mut Item) {
    for b in list {
        map_shape(&mut item.shape, b);
    }
}

/// The rest of [`apply`] once the items are mapped: the bounds and focus
/// through each break of `list`, then each break's line and note.
pub fn finish(list: &[Break], scene: &mut Scene) {
    for b in list {
        let map_rect = |r: &mut Rect| {
            if !r.is_empty() {
                let (y0, y1) = (b.map(r.y0), b.map(r.y1));
                (r.y0, r.y1) = (y0.min(y1), y0.max(y1));
            }
        };
        map_rect(&mut scene.bounds);
        map_rect(&mut scene.focus);
    }
    for b in list {
        mark(scene, b);
    }
}

fn map_shape(shape: &mut Shape, b: &Break) {
    match shape {
        Shape::Polyline { points } => *points = b.path(points, false).into(),
        Shape::Polygon { points } => *points = b.path(points, true).into(),
        Shape::Circle { center, .. } => *center = b.point(*center),
        Shape::Arrow { from, to } => (*from, *to) = (b.point(*from), b.point(*to)),
        Shape::Dim { a, b: q, .. } => (*a, *q) = (b.point(*a), b.point(*q)),
        Shape::Text { at, .. } | Shape::Marker { at, .. } => *at = b.point(*at),
    }
}

/// The break line across the focus (a zigzag in the middle) and its note:
/// four fifths of the way from the break to the focus's edge beyond it (the passes'
/// retract as drawn), clear of the dimensions beside the crest.
fn mark(scene: &mut Scene, b: &Break) {
    let f = scene.focus;
    if f.is_empty() {
        return;
    }
    let reach = (if b.out { f.y1 - b.at } else { b.at - f.y0 }).max(0.5 * b.unit);
    let (x0, x1) = (f.x0, f.x1);
    let (w, y) = ((x1 - x0).max(1e-6), b.at + if b.out { 0.8 } else { -0.8 } * reach);
    let (m, s, a) = ((x0 + x1) / 2.0, 0.008 * w, 0.15 * b.unit);
    let zig = vec![[x0, y], [m - s, y], [m - s / 2.0, y + a], [m + s / 2.0, y - a], [m + s, y], [x1, y]];
    scene.push(Item::new(Shape::Polyline { points: zig.into() }, Style::Break), false);
    // Clear of the line: the note's box (15 px high) sits 4 px above it (below, inward).
    let dy = if b.out { 12.0 } else { -12.0 };
    let note = Shape::Text { at: [x0, y], label: Label::new("radial_break", ""), anchor: Anchor::Start, dx: 4.0, dy };
    scene.push(Item::new(note, Style::Break), false);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_is_true_to_the_break_and_logarithmic_beyond() {
        let b = Break { at: 24.65, unit: 0.975, out: true };
        assert_eq!(b.map(23.0), 23.0);
        assert_eq!(b.map(24.65), 24.65);
        // The retract at X58 (r 29): 4.35 beyond becomes 0.975·ln(1 + 4.35/0.975) = 1.655.
        assert!((b.map(29.0) - 26.305).abs() < 1e-3, "{}", b.map(29.0));
        // The return at X100 (r 50): 25.35 beyond becomes 3.213.
        assert!((b.map(50.0) - 27.863).abs() < 1e-3, "{}", b.map(50.0));
        let inward = Break { at: 10.0, unit: 1.0, out: false };
        assert_eq!(inward.map(12.0), 12.0);
        assert!((inward.map(0.0) - (10.0 - 11f64.ln())).abs() < 1e-12);
        // A segment across the break keeps its true-scale part straight: the crossing is inserted.
        let p = b.path(&[[70.0, 29.0], [70.0, 23.55]], false);
        assert_eq!(p.len(), 3);
        assert_eq!(p[1], [70.0, 24.65]);
    }
}
