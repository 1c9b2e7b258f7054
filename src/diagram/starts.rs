//! The starts view of a multi-start thread: an end view with each start's
//! angle on a unit circle (0°, the one-revolution signal, at the top;
//! angles clockwise), and to its right a ruler one lead long with each
//! start's axial offset lead·θ/360° (lead/starts apart for evenly spaced starts).

use crate::geom::Frame;
use crate::helix;
use crate::plan::Plan;
use crate::thread::Pass;

use super::scene::{Anchor, Glyph, Item, Label, Pt, Scene, Shape, Style, ViewKind, num};

/// Most starts drawn; more are summarised in a note.
pub const MAX_STARTS_DRAWN: usize = 360;

/// Left end of the offset ruler.
pub const RULER_X: f64 = 1.8;
/// Length of the offset ruler (one lead).
pub const RULER_LEN: f64 = 2.6;

/// One start: its number, angle, axial offset and first pass.
#[derive(Clone, Debug, PartialEq)]
pub struct Start {
    /// 1-based start number.
    pub number: u32,
    /// Start angle in degrees.
    pub angle: f64,
    /// Axial offset lead·θ/360, in `[0, lead)`.
    pub offset: f64,
    /// Index of the start's first pass.
    pub pass: usize,
}

/// The starts of thread `ti`, from their first passes: their start angles,
/// or, for starts cut at one angle by moving them along the axis, the angle
/// that helix has (its axial shift from start 1's first pass, 360°/lead each).
pub fn starts_of(plan: &Plan, ti: usize) -> Vec<Start> {
    let Some(t) = plan.threads.get(ti) else { return Vec::new() };
    let mut out: Vec<Start> = Vec::new();
    let f = Frame::along(t.long_axis);
    let phase = |p: &Pass| helix::phase(p.angle, f.long(p.from), f.long(p.to), p.shift, t.lead);
    let by_shift = t.starts > 1 && t.lead > 0.0 && t.passes.iter().all(|p| p.angle == t.passes[0].angle);
    let first = t.passes.iter().find(|p| p.start == 1).map(phase);
    for (i, p) in t.passes.iter().enumerate() {
        if out.iter().any(|s| s.number == p.start) {
            continue;
        }
        let angle = match first.filter(|_| by_shift) {
            Some(p1) => {
                let turn = (phase(p) - p1).rem_euclid(1.0);
                // Rounding near a whole turn is start 1's helix.
                let turn = if 1.0 - turn < 1e-6 { 0.0 } else { turn };
                p.angle + 360.0 * turn
            }
            None if p.angle.is_finite() => p.angle,
            None => 0.0,
        };
        let offset = if t.lead > 0.0 { (t.lead * angle / 360.0).rem_euclid(t.lead) } else { 0.0 };
        out.push(Start { number: p.start, angle, offset, pass: i });
    }
    crate::order::sort_by_key(&mut out, |s| s.number); // numbers are unique
    out
}

/// Builds the starts view of thread `ti`.
pub fn starts(plan: &Plan, ti: usize) -> Option<Scene> {
    let t = plan.threads.get(ti)?;
    let list = starts_of(plan, ti);
    if list.is_empty() {
        return None;
    }
    let mut scene = Scene::new(ViewKind::Starts);
    let own = |shape: Shape, style: Style| Item::new(shape, style).lines([t.line]).of(ti, None);
    scene.push(own(Shape::Circle { center: [0.0, 0.0], radius: 1.0 }, Style::Circle), true);
    for (a, b) in [([-1.2, 0.0], [1.2, 0.0]), ([0.0, -1.2], [0.0, 1.2])] {
        scene.push(Item::new(Shape::Polyline { points: vec![a, b].into() }, Style::Axis), true);
    }
    scene.push(own(Shape::Marker { at: [0.0, 1.0], glyph: Glyph::Bar }, Style::Note), true);
    let one_rev = Label::new("one_rev", "0°");
    scene.push(
        own(Shape::Text { at: [0.0, 1.0], label: one_rev, anchor: Anchor::Middle, dx: 0.0, dy: 30.0 }, Style::Note),
        true,
    );
    let lead = if t.lead > 0.0 { t.lead } else { 1.0 };
    let x_of = |offset: f64| RULER_X + RULER_LEN * offset / lead;
    let ruler = vec![[RULER_X, 0.0], [RULER_X + RULER_LEN, 0.0]];
    scene.push(own(Shape::Polyline { points: ruler.into() }, Style::Ruler), true);
    for x in [RULER_X, RULER_X + RULER_LEN] {
        scene.push(own(Shape::Polyline { points: vec![[x, -0.1], [x, 0.1]].into() }, Style::Ruler), true);
    }
    let caption = Label::new("axial_offsets", "");
    scene.push(
        own(Shape::Text { at: [RULER_X, -1.3], label: caption, anchor: Anchor::Start, dx: 0.0, dy: 0.0 }, Style::Note),
        true,
    );
    let lead_dim = Shape::Dim {
        a: [RULER_X, 0.0],
        b: [RULER_X + RULER_LEN, 0.0],
        offset: 28.0,
        label: Label::new("lead", num(t.lead)),
    };
    scene.push(own(lead_dim, Style::Dimension), true);
    let many = list.len() > 12;
    for s in list.iter().take(MAX_STARTS_DRAWN) {
        let pass = &t.passes[s.pass];
        let of = |item: Item| item.lines(pass.drawn_lines()).of(ti, Some(s.pass));
        let th = s.angle.to_radians();
        let dir: Pt = [th.sin(), th.cos()];
        scene.push(of(Item::new(Shape::Polyline { points: vec![[0.0, 0.0], dir].into() }, Style::Start)), true);
        scene.push(of(Item::new(Shape::Marker { at: dir, glyph: Glyph::Dot }, Style::Start)), true);
        let x = x_of(s.offset);
        scene.push(of(Item::new(Shape::Polyline { points: vec![[x, -0.12], [x, 0.12]].into() }, Style::Start)), true);
        scene.push(of(Item::new(Shape::Marker { at: [x, 0.0], glyph: Glyph::Dot }, Style::Start)), true);
        if !many || s.number == 1 || s.number as usize == list.len() {
            let at = [1.12 * dir[0], 1.12 * dir[1]];
            let anchor = if dir[0] > 0.2 {
                Anchor::Start
            } else if dir[0] < -0.2 {
                Anchor::End
            } else {
                Anchor::Middle
            };
            let label = Label::new("start_angle", format!("{}: {}°", s.number, num(s.angle)));
            scene.push(of(Item::new(Shape::Text { at, label, anchor, dx: 0.0, dy: 6.0 * dir[1] }, Style::Start)), true);
            let label = Label::new("", format!("{}: {}", s.number, num(s.offset)));
            scene.push(
                of(Item::new(
                    Shape::Text { at: [x, -0.12], label, anchor: Anchor::Middle, dx: 0.0, dy: -12.0 },
                    Style::Start,
                )),
                true,
            );
        }
    }
    if t.starts > 1 {
        let p = t.pitch;
        let dim =
            Shape::Dim { a: [x_of(0.0), -0.5], b: [x_of(p), -0.5], offset: -6.0, label: Label::new("pitch", num(p)) };
        scene.push(own(dim, Style::Dimension), true);
    }
    if list.len() > MAX_STARTS_DRAWN {
        let label = Label::new("starts_capped", list.len().to_string());
        scene.push(
            own(Shape::Text { at: [0.0, -1.2], label, anchor: Anchor::Middle, dx: 0.0, dy: -16.0 }, Style::Note),
            true,
        );
    }
    scene.finish();
    Some(scene)
}
