//! The fit that makes room for labels:
//! the transform whose scale leaves room, inside the page, for the scene's
//! focus and for every label where placement puts it in a view without
//! bounds. World extents grow with the scale, pixel margins do not, so the
//! largest scale is solved per axis (a bisection on a convex function), a
//! few rounds since the places depend on the scale.

use super::Read;
use super::labels::{EDGE, Kind, Label, Room, dim_frame, scene_labels};
use super::lines::LineIndex;
use super::place::{dim_segment, place};
use super::{Transform, View};
use crate::diagram::scene::{Pt, Scene};

/// The geometry keeps this far from the page's edges.
const GEOMETRY_PAD: f64 = 16.0;

/// What the fit must hold: a world point with a pixel box around it
/// (page x from `sx·x + l` to `sx·x + r`, page y from `−sy·y + t` to `−sy·y + b`).
#[derive(Clone, Copy, Debug)]
struct Element {
    x: f64,
    y: f64,
    l: f64,
    r: f64,
    t: f64,
    b: f64,
}

/// What a label placed at `xf` (translation 0) asks of the fit: its box
/// and, for a dimension, the ends of its line with room for arrowheads.
fn elements_of(lab: &Label, xf: &Transform, out: &mut Vec<Element>) {
    let Some(at) = lab.at else { return };
    let p = lab.anchor();
    let (x, y) = (xf.sx * p[0], -xf.sy * p[1]);
    let mut rel =
        |b: [f64; 4]| out.push(Element { x: p[0], y: p[1], l: b[0] - x, r: b[2] - x, t: b[1] - y, b: b[3] - y });
    rel(at.bx);
    if matches!(lab.kind, Kind::Text { .. }) {
        return;
    }
    if let Some(fr) = dim_frame(lab, xf) {
        let (e0, e1) = dim_segment(lab, &fr, &at);
        for e in [e0, e1] {
            rel([e[0] - 4.0, e[1] - 4.0, e[0] + 4.0, e[1] + 4.0]);
        }
    }
}

/// The largest scale `s ≥ 0` at which every element, at coordinate `c·s`
/// plus its pixel extent `lo..hi`, spans at most `avail` px; 0 when even
/// `s = 0` does not fit. The span is convex in `s`, so the scales that fit
/// are an interval from 0.
fn max_scale(
    els: &[Element],
    c: impl Fn(&Element) -> f64,
    lo: impl Fn(&Element) -> f64,
    hi: impl Fn(&Element) -> f64,
    avail: f64,
) -> f64 {
    let span = |s: f64| {
        let (mut a, mut b) = (f64::INFINITY, f64::NEG_INFINITY);
        for e in els {
            a = a.min(s * c(e) + lo(e));
            b = b.max(s * c(e) + hi(e));
        }
        b - a
    };
    if span(0.0) > avail {
        return 0.0;
    }
    let (cmin, cmax) = els.iter().map(&c).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let mut top = avail / (cmax - cmin).max(1e-12);
    if span(top) <= avail {
        return top;
    }
    let mut bottom = 0.0;
    for _ in 0..48 {
        let m = (bottom + top) / 2.0;
        if span(m) <= avail {
            bottom = m;
        } else {
            top = m;
        }
    }
    bottom
}

/// The labels near the focus (a note at the end of far motions does not widen the fit), by priority.
fn near_labels(scene: &Scene, read: &Read, o: &View, width: f64) -> Vec<Label> {
    let zone = crate::diagram::side::near_focus(&scene.focus);
    let near = |p: Pt| zone.is_some_and(|z| z.contains(p));
    let mut set: Vec<Label> = scene_labels(&read.labelled, o, width).into_iter().filter(|l| near(l.anchor())).collect();
    crate::order::sort_by_key(&mut set, |l| l.prio);
    set
}

/// The elements to fit at `xf`: the focus's corners and every label of `set` where it goes.
fn elements(scene: &Scene, set: &mut [Label], xf: &Transform, lines: &LineIndex) -> Vec<Element> {
    let f = scene.focus;
    let p = GEOMETRY_PAD;
    let mut els = vec![
        Element { x: f.x0, y: f.y0, l: -p, r: p, t: -p, b: p },
        Element { x: f.x1, y: f.y1, l: -p, r: p, t: -p, b: p },
    ];
    place(set, xf, &Room { w: 0.0, h: 0.0, all: true }, Some(lines));
    for l in set.iter() {
        elements_of(l, xf, &mut els);
    }
    els
}

/// The transform that fits the scene's focus and its labels (drawn with
/// `o`) into a `w × h` page, centred, off the drawing's lines (`read`); with
/// `o.stretch`, the vertical scale may exceed the horizontal one to fill the height.
pub(super) fn fit(scene: &Scene, o: &View, (w, h): (f64, f64), read: &Read) -> Transform {
    let lines = &read.lines;
    let f = scene.focus.or_unit();
    let (fw, fh) = (f.width().max(1e-9), f.height().max(1e-9));
    let p = GEOMETRY_PAD;
    let aw = (w - 2.0 * EDGE).max(10.0);
    let ah = (h - 2.0 * EDGE).max(10.0);
    let iso = ((aw - 2.0 * p) / fw).min((ah - 2.0 * p) / fh).max(1e-12);
    let mut set = near_labels(scene, read, o, w);
    let stretched = |s: f64, v: f64| if o.stretch { s.max(v) } else { s };
    let mut xf = Transform { sx: iso, sy: stretched(iso, (ah - 2.0 * p) / fh), tx: 0.0, ty: 0.0 };
    let mut round = 0;
    while round < 4 {
        let els = elements(scene, &mut set, &xf, lines);
        let sxh = max_scale(&els, |e| e.x, |e| e.l, |e| e.r, aw);
        let syv = max_scale(&els, |e| -e.y, |e| e.t, |e| e.b, ah);
        let s = sxh.min(syv);
        // Labels that would shrink the drawing below a third of its size are
        // left to placement (which moves or drops them), the least important first.
        if s < iso / 3.0 {
            if let Some(drop) = set.iter().rposition(|l| !l.must) {
                set.remove(drop);
                continue;
            }
        }
        let s = s.max(iso / 3.0);
        xf = Transform { sx: s, sy: stretched(s, syv), tx: 0.0, ty: 0.0 };
        round += 1;
    }
    // Places depend on the scale: where the last round's places ask for less
    // room than those at the final scale, the scale gives way once more.
    let els = elements(scene, &mut set, &xf, lines);
    let sxh = max_scale(&els, |e| e.x, |e| e.l, |e| e.r, aw);
    let syv = max_scale(&els, |e| -e.y, |e| e.t, |e| e.b, ah);
    if sxh.min(syv) < xf.sx {
        let s = sxh.min(syv).max(iso / 3.0);
        xf = Transform { sx: s, sy: stretched(s, syv.max(s)), tx: 0.0, ty: 0.0 };
    }
    // Centre the whole: geometry and labels.
    let els = elements(scene, &mut set, &xf, lines);
    let (mut xa, mut xb, mut ya, mut yb) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for e in &els {
        xa = xa.min(xf.sx * e.x + e.l);
        xb = xb.max(xf.sx * e.x + e.r);
        ya = ya.min(-xf.sy * e.y + e.t);
        yb = yb.max(-xf.sy * e.y + e.b);
    }
    xf.tx = (w - xa - xb) / 2.0;
    xf.ty = (h - ya - yb) / 2.0;
    xf
}
