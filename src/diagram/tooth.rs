//! The tooth section: one thread space at large scale. The horizontal axis
//! is the axial offset from the thread middle, the vertical axis the radial
//! position from the crest; an external thread's depth grows downward, an
//! internal thread's upward. It shows the material and the finished
//! profile (with the neighbouring spaces one pitch away), the tool at every
//! pass of one start with its depth and shift, the area each pass removes,
//! the infeed direction, and dimensions of the height and pitch.

use crate::plan::Plan;
use crate::thread::{Infeed, Pass, Role, Thread};

use super::scene::{Anchor, Glyph, Item, Label, Pt, Scene, Shape, Style, ViewKind, num};
use crate::chip::{Pl, Tool, area};

/// Most depth labels written beside the space; more passes are labelled sparsely.
pub const MAX_DEPTH_LABELS: usize = 40;

/// The tool of a thread: a V of its tool angle, or for a 0° (square) tool a
/// flat tip half a pitch wide (the drawing's assumption).
pub fn tool_of(t: &Thread, pitch: f64) -> Tool {
    if t.tool_angle > 0.0 && t.tool_angle < 180.0 {
        Tool { t: (t.tool_angle.to_radians() / 2.0).tan(), flat: 0.0 }
    } else {
        Tool { t: 1e-4, flat: pitch / 4.0 }
    }
}

/// One pass's area polygons (external orientation), with the surface after it.
pub struct PassCut {
    /// Index of the pass in the thread.
    pub index: usize,
    /// Region(s) the pass removes.
    pub regions: Vec<Vec<(f64, f64)>>,
    /// Total area removed.
    pub area: f64,
}

/// The cuts of `passes` (in order) on one space over `[u0, u1]`, and the final surface.
pub fn cuts(tool: Tool, passes: &[(usize, &Pass)], u0: f64, u1: f64) -> (Vec<PassCut>, Pl) {
    let mut surface = Pl::flat(u0, u1);
    let mut out = Vec::with_capacity(passes.len());
    for &(index, p) in passes {
        let next = surface.min(&tool.cut(p.depth, p.shift, u0, u1));
        let regions = surface.regions_above(&next);
        let a = regions.iter().map(|r| area(r)).sum();
        out.push(PassCut { index, regions, area: a });
        surface = next;
    }
    (out, surface)
}

/// The cuts of `passes` as groups that end at the passes marked in `shown`:
/// each group's regions are what all its passes remove together (the level
/// of detail of a thread of many passes).
pub fn grouped_cuts(tool: Tool, passes: &[(usize, &Pass)], shown: &[bool], u0: f64, u1: f64) -> Vec<PassCut> {
    let mut surface = Pl::flat(u0, u1);
    let mut group_top = surface.clone();
    let mut out = Vec::new();
    for (k, &(index, p)) in passes.iter().enumerate() {
        surface = surface.min(&tool.cut(p.depth, p.shift, u0, u1));
        if shown[k] {
            let regions = group_top.regions_above(&surface);
            let a = regions.iter().map(|r| area(r)).sum();
            out.push(PassCut { index, regions, area: a });
            group_top = surface.clone();
        }
    }
    out
}

/// Builds the tooth section of thread `ti`, start `start` (1-based).
pub fn tooth(plan: &Plan, ti: usize, start: u32) -> Option<Scene> {
    let t = plan.threads.get(ti)?;
    let passes: Vec<(usize, &Pass)> = t.passes.iter().enumerate().filter(|(_, p)| p.start == start).collect();
    if passes.is_empty() {
        return None;
    }
    let max_depth = passes.iter().map(|(_, p)| p.depth).fold(0.0f64, f64::max);
    let pitch = [t.pitch, t.lead, 1.0].into_iter().find(|v| v.is_finite() && *v > 0.0).unwrap_or(1.0);
    let h = [t.height, max_depth, 0.6495 * pitch].into_iter().find(|v| v.is_finite() && *v > 0.0).unwrap_or(1.0);
    let tool = tool_of(t, pitch);
    let max_shift = passes.iter().map(|(_, p)| p.shift.abs()).filter(|v| v.is_finite()).fold(0.0f64, f64::max);
    let half = (tool.flat + h * tool.t + max_shift).max(pitch / 2.0);
    let l = pitch.max(half * 1.15);
    let (u0, u1) = (-l - pitch, l + pitch);
    let (all_cuts, surface) = cuts(tool, &passes, u0, u1);
    // Level of detail: many passes are drawn as groups ending at every k-th pass.
    let indices: Vec<usize> = passes.iter().map(|(i, _)| *i).collect();
    let (keep, every) = super::detail::thin(&t.passes, &indices);
    let shown: Vec<bool> = indices.iter().map(|i| keep.binary_search(i).is_ok()).collect();
    let cut_list = if every > 1 { grouped_cuts(tool, &passes, &shown, u0, u1) } else { all_cuts };
    // Final profile with the neighbouring spaces (same profile a pitch away).
    let neighbours = surface.min(&surface.shifted(pitch, u0, u1)).min(&surface.shifted(-pitch, u0, u1));
    let bottom = -h * 1.35 - 0.1 * pitch;
    let top = 0.35 * h;
    let flip = if t.internal { -1.0 } else { 1.0 };
    let pt = |u: f64, w: f64| -> Pt { [u, w * flip] };
    let mut scene = Scene::new(ViewKind::Tooth);
    let tl = vec![t.line];
    let own = |shape: Shape, style: Style| Item::new(shape, style).lines(tl.clone()).of(ti, None);
    // Material and finished profile over [-l, l].
    let mut prof: Vec<Pt> = vec![pt(-l, neighbours.at(-l))];
    prof.extend(neighbours.pts.iter().filter(|p| p.0 > -l && p.0 < l).map(|p| pt(p.0, p.1)));
    prof.push(pt(l, neighbours.at(l)));
    let mut material = vec![pt(-l, bottom)];
    material.extend(prof.iter().copied());
    material.push(pt(l, bottom));
    scene.push(own(Shape::Polygon { points: material.into() }, Style::Material), true);
    scene.push(own(Shape::Polyline { points: vec![pt(0.0, bottom), pt(0.0, top)].into() }, Style::Axis), true);
    // Areas, then tools, so every outline stays visible.
    for c in &cut_list {
        let p = &t.passes[c.index];
        for r in &c.regions {
            let points = r.iter().map(|q| pt(q.0, q.1)).collect();
            scene.push(
                Item::new(Shape::Polygon { points }, Style::Area)
                    .lines(p.drawn_lines())
                    .of(ti, Some(c.index))
                    .role(p.role),
                true,
            );
        }
    }
    scene.push(own(Shape::Polyline { points: prof.into() }, Style::Profile), true);
    let drawn: Vec<(usize, &Pass)> = passes.iter().zip(&shown).filter(|(_, s)| **s).map(|(p, _)| *p).collect();
    let label_every = drawn.len().div_ceil(MAX_DEPTH_LABELS).max(1);
    let tick = 0.08 * l;
    for (k, &(index, p)) in drawn.iter().enumerate() {
        let of = |item: Item| item.lines(p.drawn_lines()).of(ti, Some(index)).role(p.role);
        let (d, s) = (p.depth, p.shift);
        let rise = d + top;
        let edge = vec![
            pt(s - tool.flat - rise * tool.t, top),
            pt(s - tool.flat, -d),
            pt(s + tool.flat, -d),
            pt(s + tool.flat + rise * tool.t, top),
        ];
        scene.push(of(Item::new(Shape::Polyline { points: edge.into() }, Style::Tool)), true);
        let glyph = if p.role == Role::Rough { Glyph::Dot } else { Glyph::Cross };
        scene.push(of(Item::new(Shape::Marker { at: pt(s, -d), glyph }, Style::Tool)), true);
        scene.push(
            of(Item::new(Shape::Polyline { points: vec![pt(l, -d), pt(l + tick, -d)].into() }, Style::DepthTick)),
            true,
        );
        if k % label_every == 0 || k + 1 == drawn.len() {
            let key = match p.role {
                Role::Rough => "pass_depth",
                Role::Finish => "pass_depth_finish",
                Role::Spring => "pass_depth_spring",
            };
            let value = if s.abs() > 1e-9 {
                format!("{}: {} ↔{}{}", p.index, num(d), if s > 0.0 { "+" } else { "" }, num(s))
            } else {
                format!("{}: {}", p.index, num(d))
            };
            let label = Label::new(key, value);
            let text = Shape::Text { at: pt(l + tick, -d), label, anchor: Anchor::Start, dx: 4.0, dy: 0.0 };
            scene.push(of(Item::new(text, Style::DepthTick)), false);
        }
    }
    if let (Some(form), Some(&(index, last))) = (&t.shop.insert, drawn.last()) {
        for item in insert_items(form, last, tool, pitch, (top, bottom, l), flip) {
            scene.push(item.lines(last.drawn_lines()).of(ti, Some(index)), false);
        }
    }
    infeed_arrows(&mut scene, t, &passes, tool, h, top, flip, ti);
    // Dimensions: height at the left, pitch below the material.
    let dim = |a: Pt, b: Pt, offset: f64, key: &'static str, v: f64| Shape::Dim {
        a,
        b,
        offset: offset * flip,
        label: Label::new(key, num(v)),
    };
    scene.push(own(dim(pt(-l, 0.0), pt(-l, -h), -16.0, "height", h), Style::Dimension), true);
    scene.push(own(dim(pt(0.0, bottom), pt(pitch, bottom), -16.0, "pitch", pitch), Style::Dimension), true);
    let angle = Label::new("tool_angle", format!("{}°", num(t.tool_angle)));
    scene.push(
        own(
            Shape::Text { at: pt(-l, bottom), label: angle, anchor: Anchor::Start, dx: 0.0, dy: -34.0 * flip },
            Style::Note,
        ),
        true,
    );
    if t.starts > 1 {
        let label = Label::new("start_of", format!("{start}/{}", t.starts));
        scene.push(
            own(Shape::Text { at: pt(l, top), label, anchor: Anchor::End, dx: 0.0, dy: 8.0 * flip }, Style::Note),
            true,
        );
    }
    if every > 1 {
        let label = Label::new("detail_passes", format!("{every}/{}", passes.len()));
        scene.push(
            own(Shape::Text { at: pt(-l, top), label, anchor: Anchor::Start, dx: 0.0, dy: 8.0 * flip }, Style::Note),
            true,
        );
    }
    if tool.flat > 0.0 {
        let label = Label::new("square_tool", num(2.0 * tool.flat));
        scene.push(
            own(
                Shape::Text { at: pt(0.0, bottom), label, anchor: Anchor::Middle, dx: 0.0, dy: 22.0 * flip },
                Style::Note,
            ),
            false,
        );
    }
    scene.finish();
    Some(scene)
}

/// Arrows above the space showing how the tool feeds in: straight down the
/// middle, along a flank, or both flanks in turn.
#[allow(clippy::too_many_arguments)]
fn infeed_arrows(
    scene: &mut Scene,
    t: &Thread,
    passes: &[(usize, &Pass)],
    tool: Tool,
    h: f64,
    top: f64,
    flip: f64,
    ti: usize,
) {
    let tip = |p: &Pass| (p.shift, -p.depth);
    let direction = |ps: &[&Pass]| -> Option<(f64, f64)> {
        let (a, b) = (ps.first()?, ps.last()?);
        let (du, dw) = (b.shift - a.shift, -(b.depth - a.depth));
        (dw < -1e-12 && du.abs() > 1e-9).then_some((du, dw))
    };
    let all: Vec<&Pass> = passes.iter().map(|(_, p)| *p).collect();
    let odd: Vec<&Pass> = all.iter().copied().step_by(2).collect();
    let even: Vec<&Pass> = all.iter().copied().skip(1).step_by(2).collect();
    let flank = |side: f64| (side * tool.t, -1.0);
    let mut arrows: Vec<((f64, f64), (f64, f64))> = Vec::new(); // (through point, direction)
    let key = match t.infeed {
        Infeed::Radial => "infeed_radial",
        Infeed::Left => "infeed_left",
        Infeed::Right => "infeed_right",
        Infeed::Alternating => "infeed_alternating",
        Infeed::Programmed => "infeed_programmed",
    };
    match t.infeed {
        Infeed::Alternating => {
            for group in [&odd, &even] {
                if let Some(first) = group.first() {
                    let d = direction(group).unwrap_or(flank(if first.shift <= 0.0 { 1.0 } else { -1.0 }));
                    arrows.push((tip(first), d));
                }
            }
        }
        _ => {
            if let Some(first) = all.first() {
                let d = direction(&all).unwrap_or((0.0, -1.0));
                arrows.push((tip(first), d));
            }
        }
    }
    let (y0, y1) = (top + 0.55 * h, top + 0.1 * h);
    for (k, ((pu, pw), (du, dw))) in arrows.into_iter().enumerate() {
        // Where the line through the first tip along the infeed crosses y0 and y1.
        let at = |y: f64| -> Pt { [pu + du * (y - pw) / dw, y * flip] };
        let item = Item::new(Shape::Arrow { from: at(y0), to: at(y1) }, Style::Infeed).lines([t.line]).of(ti, None);
        scene.push(item, true);
        if k == 0 {
            let label = Label::new(key, "");
            let text = Shape::Text { at: at(y0), label, anchor: Anchor::Middle, dx: 0.0, dy: 8.0 * flip };
            scene.push(Item::new(text, Style::Infeed).lines([t.line]).of(ti, None), true);
        }
    }
}

/// The insert at pass `p` (the last drawn): its nose, tangent to the flanks
/// of the tool's V, its flanks up to the top of the drawing and, for a full
/// profile, the edges that form the crest (a basic crest flat, P/8, either
/// side); and a note naming it.
fn insert_items(
    form: &crate::figures::InsertForm,
    p: &Pass,
    tool: Tool,
    pitch: f64,
    (top, bottom, l): (f64, f64, f64),
    flip: f64,
) -> Vec<Item> {
    let pt = |u: f64, w: f64| -> Pt { [u, w * flip] };
    let (d, s) = (p.depth, p.shift);
    let theta = tool.t.atan(); // half the tool angle
    let r = form.nose_radius.max(0.0);
    // The nose's centre lies r / sin θ above the V's apex; it meets the flanks r·cos θ either side.
    let cy = -d + r / theta.sin();
    let mut outline = vec![pt(s - tool.flat - (top + d) * tool.t, top)];
    if r > 0.0 {
        // The nose from the left flank's tangent point (at π + θ) round the bottom to the right one (2π − θ).
        let n = 16;
        for k in 0..=n {
            let phi = std::f64::consts::PI + theta + (std::f64::consts::PI - 2.0 * theta) * f64::from(k) / f64::from(n);
            outline.push(pt(s + r * phi.cos(), cy + r * phi.sin()));
        }
    } else {
        outline.push(pt(s, -d));
    }
    outline.push(pt(s + tool.flat + (top + d) * tool.t, top));
    let mut items = vec![Item::new(Shape::Polyline { points: outline.into() }, Style::Tool)];
    if form.full {
        let w = d * tool.t; // the flanks cross the crest line this far either side
        for side in [-1.0, 1.0] {
            let from = s + side * (tool.flat + w);
            let ear = vec![pt(from, 0.0), pt(from + side * pitch / 8.0, 0.0)];
            items.push(Item::new(Shape::Polyline { points: ear.into() }, Style::Tool));
        }
    }
    let key = if form.full { "insert_full" } else { "insert_partial" };
    let label = Label::new(key, format!("{} r {}", form.name, num(r)));
    // Below the material at the right, a row under the pitch dimension and the tool angle's note.
    let at = pt(l, bottom);
    items.push(Item::new(Shape::Text { at, label, anchor: Anchor::End, dx: 0.0, dy: -52.0 * flip }, Style::Note));
    items
}
