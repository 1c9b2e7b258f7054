//! The labels of a scene and where each may go: a
//! scene's dimensions and texts are anchored in world coordinates but sized
//! in pixels; each becomes a [`Label`] with its width, its priority and its
//! candidate places, best first; placement chooses among them.

use super::text::{measure, wrap};
use super::{FONT_SIZE, MAX_ANNOTATED, Transform, View};
use crate::diagram::scene::{Anchor, Item, Pt, Scene, Shape, Style};

/// Height of a label's box: 12 px text and its halo.
pub(super) const LINE: f64 = 15.0;
/// Space between a dimension line and its text.
const GAP: f64 = 3.0;
/// How much further out a stacked dimension line goes.
const STEP: f64 = LINE + 3.0;
/// Labels keep this far from the view's edges.
pub(super) const EDGE: f64 = 3.0;
/// Length of a dimension's arrowhead.
const HEAD: f64 = 7.0;

/// The order labels are placed in (lower first) by key.
fn rank(key: &str) -> i32 {
    match key {
        "dia_major" => 0,
        "dia_minor" => 1,
        "lead" => 2,
        "pitch" => 3,
        "height" => 4,
        "length" => 5,
        "taper" => 6,
        "detail_passes" | "detail_starts" | "detail_starts_passes" | "moves_capped" | "starts_capped" => 7,
        "start_of" => 8,
        "pass_depth_finish" | "pass_depth_spring" => 9,
        "tool_angle" | "infeed_radial" | "infeed_left" | "infeed_right" | "infeed_alternating"
        | "infeed_programmed" | "square_tool" => 10,
        "delta1" | "delta2" => 11,
        "one_rev" | "axial_offsets" | "radial_break" => 12,
        "shoulder_into" => 3,
        "shoulder_clear" => 13,
        "insert_full" | "insert_partial" => 10,
        "start_angle" => 13,
        "" => 14,
        "pass_depth" => 15,
        _ => 20,
    }
}

/// What a label belongs to.
#[derive(Clone, Copy, Debug)]
pub(super) enum Kind {
    /// A dimension between `a` and `b`, its line `offset` px left of a→b.
    Dim { a: Pt, b: Pt, offset: f64 },
    /// A diameter's half dimension: from the axis `a` to the diameter `b`, one arrowhead at `b`.
    Half { a: Pt, b: Pt, offset: f64 },
    /// A text at `p`, moved `dx` px right and `dy` px up.
    Text { p: Pt, dx: f64, dy: f64, anchor: Anchor },
}

/// A text's place in a stack of texts beside one edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Slot {
    /// Not in a stack.
    Free,
    /// In a stack but left out.
    Out,
    /// In a stack, its box centred at this y.
    At(f64),
}

/// A place: the box centre, a dimension line's offset, a half dimension's
/// line start `s` and length `len`, the box, the text's angle, a leader.
#[derive(Clone, Copy, Debug)]
pub(super) struct At {
    pub cx: f64,
    pub cy: f64,
    pub off: f64,
    pub s: Pt,
    pub len: f64,
    pub bx: [f64; 4],
    pub angle: f64,
    pub lead: Option<[f64; 4]>,
}

impl At {
    fn new(cx: f64, cy: f64, off: f64) -> At {
        At { cx, cy, off, s: [0.0; 2], len: 0.0, bx: [0.0; 4], angle: 0.0, lead: None }
    }
}

/// A label to place.
#[derive(Clone, Debug)]
pub(super) struct Label {
    /// The scene item.
    pub item: usize,
    /// The label's key (`dia_major`; empty for a bare value).
    pub key: &'static str,
    pub text: String,
    /// The text wrapped, when it is.
    pub lines: Option<Vec<String>>,
    /// Width of the text (of its widest line), px.
    pub w: f64,
    /// Whether it belongs to the chosen thread (or to none).
    pub chosen: bool,
    /// Placement order, lower first.
    pub prio: i32,
    /// Never dropped: the chosen thread's major, minor and lead.
    pub must: bool,
    pub kind: Kind,
    pub slot: Slot,
    pub at: Option<At>,
}

impl Label {
    fn new(item: usize, key: &'static str, text: String, kind: Kind, chosen: bool) -> Label {
        let dim = !matches!(kind, Kind::Text { .. });
        let w = if text.is_empty() { 0.0 } else { measure(&text, FONT_SIZE) };
        Label {
            item,
            key,
            text,
            lines: None,
            w,
            chosen,
            // Dimensions before texts of one rank; another thread's after all of the chosen one's.
            prio: if chosen { 0 } else { 1000 } + rank(key) * 2 + i32::from(!dim),
            must: chosen && dim && matches!(key, "dia_major" | "dia_minor" | "lead"),
            kind,
            slot: Slot::Free,
            at: None,
        }
    }

    /// The world point the fit keeps it by: a text's point, a diameter, a dimension's middle.
    pub fn anchor(&self) -> Pt {
        match self.kind {
            Kind::Text { p, .. } => p,
            Kind::Half { b, .. } => b,
            Kind::Dim { a, b, .. } => [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0],
        }
    }
}

/// Whether `item` has a label (a dimension or a text).
pub(super) fn has_label(item: &Item) -> bool {
    matches!(item.shape, Shape::Dim { .. } | Shape::Text { .. })
}

/// The items of `scene` that have labels, with their indices, in order.
pub(super) fn labelled(scene: &Scene) -> Vec<(usize, &Item)> {
    scene.items.iter().enumerate().filter(|(_, i)| has_label(i)).collect()
}

/// How many threads have labels among the `labelled` items of a scene
/// ([`labelled`]), counted up to one more than [`MAX_ANNOTATED`] (all that
/// [`scene_labels`] asks of the number).
pub(super) fn annotated(labelled: &[(usize, &Item)]) -> usize {
    let mut seen = [0u32; MAX_ANNOTATED + 1];
    let mut n = 0;
    // From the end: a scene's dimensions and notes follow its paths.
    for t in labelled.iter().rev().filter_map(|(_, i)| i.thread) {
        if !seen[..n].contains(&t) {
            seen[n] = t;
            n += 1;
            if n > MAX_ANNOTATED {
                break;
            }
        }
    }
    n
}

/// Whether [`scene_labels`] gives `item` a label in a scene of `annotated`
/// threads with labels, thread `chosen` chosen: above [`MAX_ANNOTATED`], only the chosen thread's.
pub(super) fn labelled_in(item: &Item, annotated: usize, chosen: usize) -> bool {
    let chosen = u32::try_from(chosen).unwrap_or(u32::MAX);
    has_label(item) && !(annotated > MAX_ANNOTATED && item.thread.is_some_and(|t| t != chosen))
}

/// The labels drawn of a scene's `labelled` items ([`labelled`]) with `o`: with
/// many annotated threads, only the chosen thread's; notes wider than about
/// half of a `width` px view wrapped.
pub(super) fn scene_labels(labelled: &[(usize, &Item)], o: &View, width: f64) -> Vec<Label> {
    let annotated = annotated(labelled);
    let chosen = u32::try_from(o.thread).unwrap_or(u32::MAX);
    let wrap_at = if width > 0.0 { (0.45 * width).max(160.0) } else { f64::INFINITY };
    let mut out = Vec::new();
    for &(i, item) in labelled {
        if !labelled_in(item, annotated, o.thread) {
            continue;
        }
        let mine = item.thread.is_none_or(|t| annotated <= 1 || t == chosen);
        match &item.shape {
            Shape::Dim { a, b, offset, label } => {
                let text = o.label_text(label.key, &label.value);
                let (a, b, offset) = (*a, *b, *offset);
                let kind = if item.style == Style::Diameter {
                    Kind::Half { a, b, offset }
                } else {
                    Kind::Dim { a, b, offset }
                };
                out.push(Label::new(i, label.key, text, kind, mine));
            }
            Shape::Text { at, label, anchor, dx, dy } => {
                let text = o.label_text(label.key, &label.value);
                if text.is_empty() {
                    continue;
                }
                let kind = Kind::Text { p: *at, dx: *dx, dy: *dy, anchor: *anchor };
                let mut l = Label::new(i, label.key, text, kind, mine);
                l.lines = wrap(&l.text, wrap_at, |s| measure(s, FONT_SIZE));
                if let Some(lines) = &l.lines {
                    l.w = lines.iter().map(|s| measure(s, FONT_SIZE)).fold(0.0, f64::max);
                }
                out.push(l);
            }
            _ => {}
        }
    }
    out
}

/// The view labels are placed in: `w × h` px, or without bounds (`all`, for the fit).
#[derive(Clone, Copy, Debug)]
pub(super) struct Room {
    pub w: f64,
    pub h: f64,
    pub all: bool,
}

/// A dimension on the page: its ends, length, direction `u` (a→b), left
/// normal `n`, the box size, the side of its offset and the box's half
/// extents across (`en`) and along (`eu`) the line.
#[derive(Clone, Copy, Debug)]
pub(super) struct DimFrame {
    pub a: Pt,
    pub b: Pt,
    pub len: f64,
    pub u: Pt,
    pub n: Pt,
    pub vertical: bool,
    pub bw: f64,
    pub bh: f64,
    pub sgn: f64,
    en: f64,
    eu: f64,
}

/// The page frame of a dimension label at `xf`; `None` for a text or a dimension of no length.
pub(super) fn dim_frame(lab: &Label, xf: &Transform) -> Option<DimFrame> {
    let (Kind::Dim { a, b, offset } | Kind::Half { a, b, offset }) = lab.kind else { return None };
    let (a, b) = (xf.at(a), xf.at(b));
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    if len.is_nan() || len <= 1e-9 {
        return None;
    }
    let u = [dx / len, dy / len];
    // Left of a→b in world terms is (dy, −dx) on the page (y down).
    let n = [u[1], -u[0]];
    let vertical = n[0].abs() > 0.7;
    let (bw, bh) = if vertical { (LINE, lab.w + 4.0) } else { (lab.w + 4.0, LINE) };
    let en = bw / 2.0 * n[0].abs() + bh / 2.0 * n[1].abs();
    let eu = bw / 2.0 * u[0].abs() + bh / 2.0 * u[1].abs();
    let sgn = if offset >= 0.0 { 1.0 } else { -1.0 };
    Some(DimFrame { a, b, len, u, n, vertical, bw, bh, sgn, en, eu })
}

/// Where the line of a dimension at offset `o` is inside the view: `[t0, t1]` of a→b, or `None`.
fn visible_range(fr: &DimFrame, o: f64, view: &Room) -> Option<(f64, f64)> {
    if view.all {
        return Some((0.0, 1.0));
    }
    let (x0, y0) = (fr.a[0] + fr.n[0] * o, fr.a[1] + fr.n[1] * o);
    let (dx, dy) = (fr.b[0] - fr.a[0], fr.b[1] - fr.a[1]);
    let m = EDGE + 4.0;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, x0 - m), (dx, view.w - m - x0), (-dy, y0 - m), (dy, view.h - m - y0)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
            continue;
        }
        let r = q / p;
        if p < 0.0 {
            if r > t1 {
                return None;
            }
            t0 = t0.max(r);
        } else {
            if r < t0 {
                return None;
            }
            t1 = t1.min(r);
        }
    }
    (t1 > t0).then_some((t0, t1))
}

/// The candidates of a half dimension (a diameter) from its arrowhead at b:
/// past the arrowhead in line with it, or beside its line towards the axis;
/// the line runs to the axis when the axis is in view, else as far as the
/// text needs.
fn half_candidates(offset: f64, fr: &DimFrame, view: &Room) -> Vec<At> {
    let (n, u, sgn, en, eu) = (fr.n, fr.u, fr.sgn, fr.en, fr.eu);
    let axis = fr.a;
    let shown = !view.all && (0.0..=view.w).contains(&axis[0]) && (0.0..=view.h).contains(&axis[1]);
    let stub = |reach: f64| if shown { fr.len } else { fr.len.min((reach + 6.0).max(28.0)) };
    let mut out = Vec::new();
    for k in 0..3 {
        let off = offset + sgn * f64::from(k) * STEP;
        let s = [fr.b[0] + n[0] * off, fr.b[1] + n[1] * off];
        let mut put = |cx: f64, cy: f64, len: f64| out.push(At { s, len, ..At::new(cx, cy, off) });
        for j in 0..2 {
            let q = GAP + eu + f64::from(j) * STEP;
            put(s[0] + u[0] * q, s[1] + u[1] * q, stub(0.0));
        }
        for j in 0..3 {
            let along = HEAD + GAP + eu + f64::from(j) * STEP;
            for side in [1.0, -1.0] {
                let d = sgn * side * (GAP + en);
                put(s[0] - u[0] * along + n[0] * d, s[1] - u[1] * along + n[1] * d, stub(along + eu));
            }
        }
    }
    out
}

/// The candidates of a dimension's label, best first: its preferred side
/// of the line, the other, along the line, past its ends, and the line
/// stacked further out.
pub(super) fn dim_candidates(lab: &Label, fr: &DimFrame, view: &Room) -> Vec<At> {
    let offset = match lab.kind {
        Kind::Half { offset, .. } => return half_candidates(offset, fr, view),
        Kind::Dim { offset, .. } => offset,
        Kind::Text { .. } => return Vec::new(),
    };
    const TS: [f64; 7] = [0.5, 0.35, 0.65, 0.2, 0.8, 0.08, 0.92];
    let (a, b, n, u, sgn) = (fr.a, fr.b, fr.n, fr.u, fr.sgn);
    let mut out = Vec::new();
    for k in 0..4 {
        let off = offset + sgn * f64::from(k) * STEP;
        let Some((t0, t1)) = visible_range(fr, off, view) else { continue };
        let sides: &[f64] = if k == 0 { &[1.0, -1.0] } else { &[1.0] };
        for side in sides {
            let d = off + sgn * side * (GAP + fr.en);
            for f in TS {
                let t = t0 + (t1 - t0) * f;
                out.push(At::new(a[0] + (b[0] - a[0]) * t + n[0] * d, a[1] + (b[1] - a[1]) * t + n[1] * d, off));
            }
        }
        // Past either end of the line, in line with it.
        for (p, s) in [(b, 1.0), (a, -1.0)] {
            let q = HEAD + GAP + fr.eu;
            out.push(At::new(p[0] + n[0] * off + u[0] * s * q, p[1] + n[1] * off + u[1] * s * q, off));
        }
    }
    out
}

/// A text on the page: its point, the preferred box centre (`px` plus
/// `half`, `py`) and the box size.
#[derive(Clone, Copy, Debug)]
pub(super) struct TextFrame {
    pub x: f64,
    pub y: f64,
    pub px: f64,
    pub py: f64,
    pub half: f64,
    pub bw: f64,
    pub bh: f64,
}

/// The page frame of a text label at `xf`; `None` for a dimension.
pub(super) fn text_frame(lab: &Label, xf: &Transform) -> Option<TextFrame> {
    let Kind::Text { p, dx, dy, anchor } = lab.kind else { return None };
    let [x, y] = xf.at(p);
    let n = lab.lines.as_ref().map_or(1, Vec::len) as f64;
    let (bw, bh) = (lab.w + 4.0, n * LINE);
    // A text of several lines grows away from its point.
    let sign = if dy > 0.0 {
        1.0
    } else if dy < 0.0 {
        -1.0
    } else {
        0.0
    };
    let py = y - dy - sign * ((n - 1.0) * LINE) / 2.0;
    let half = match anchor {
        Anchor::Start => bw / 2.0,
        Anchor::End => -bw / 2.0,
        Anchor::Middle => 0.0,
    };
    Some(TextFrame { x, y, px: x + dx, py, half, bw, bh })
}

/// The candidates of a text, best first: beside its point, shifted up or
/// down a line, mirrored about its point, slid into the view; a stacked
/// text only its slot.
pub(super) fn text_candidates(lab: &Label, fr: &TextFrame, view: &Room) -> Vec<At> {
    let Kind::Text { dx, anchor, .. } = lab.kind else { return Vec::new() };
    match lab.slot {
        Slot::At(y) => return vec![At::new(fr.px + fr.half, y, 0.0)],
        Slot::Out => return Vec::new(),
        Slot::Free => {}
    }
    let mut bases = vec![fr.px + fr.half];
    if anchor != Anchor::Middle {
        bases.push(fr.x - dx - fr.half);
    }
    let mut out = Vec::new();
    for cx in bases {
        for k in [0.0, -1.0, 1.0, -2.0, 2.0] {
            let cy = fr.py + k * (LINE + 1.0);
            out.push(At::new(cx, cy, 0.0));
            if view.all {
                continue;
            }
            // Slid into the view, by at most its width (it stays by its point).
            let x = cx.max(EDGE + fr.bw / 2.0).min(view.w - EDGE - fr.bw / 2.0);
            let y = cy.max(EDGE + fr.bh / 2.0).min(view.h - EDGE - fr.bh / 2.0);
            if (x != cx || y != cy) && (x - cx).abs() <= fr.bw && (y - cy).abs() <= LINE {
                out.push(At::new(x, y, 0.0));
            }
        }
    }
    out
}
