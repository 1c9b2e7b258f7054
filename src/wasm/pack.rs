//! Scenes as flat arrays, for moving bulk geometry across the wasm boundary
//! as typed arrays instead of one JS object per point.
//!
//! Every item is [`STRIDE`] `u32`s in `items`, named by [`FIELDS`] (the one
//! definition of the record: the JavaScript side reads the field offsets by
//! name from it):
//! `[shape, style, coord_start, coord_len, thread + 1, pass + 1, line_start, line_len, label + 1, extra]`
//! (0 for "none" in the thread, pass and label fields). `coords` holds the
//! numbers of each shape: polyline/polygon `x0 y0 x1 y1 …`; circle `cx cy r`;
//! arrow `x0 y0 x1 y1`; dim `ax ay bx by offset`; text `x y dx dy`; marker
//! `x y`. `extra` is the anchor of a text (0 start, 1 middle, 2 end) or the
//! glyph of a marker (0 dot, 1 bar, 2 cross). `lines` holds every item's
//! source lines; `labels` holds `key \u{1f} value` records separated by `\u{1e}`.

use serde::Serialize;

use crate::thread::Role;

use crate::diagram::scene::{Anchor, Glyph, Item, Rect, Scene, Shape, ViewKind};

/// The fields of an item record, in order.
pub const FIELDS: [&str; 10] =
    ["shape", "style", "coord_start", "coord_len", "thread", "pass", "line_start", "line_len", "label", "extra"];

/// Number of `u32`s per item.
pub const STRIDE: usize = FIELDS.len();

/// Anchor codes of texts, in the order of their numbers.
pub const ANCHORS: [&str; 3] = ["start", "middle", "end"];

/// Glyph codes of markers, in the order of their numbers.
pub const GLYPHS: [&str; 3] = ["dot", "bar", "cross"];

/// Role codes of pass items (0: no role), in the order of their numbers.
pub const ROLES: [&str; 4] = ["", "rough", "finish", "spring"];

/// Shape codes, in the order of their numbers.
pub const SHAPES: [&str; 7] = ["polyline", "polygon", "circle", "arrow", "dim", "text", "marker"];

/// Separates a label's key from its value.
pub const UNIT_SEP: char = '\u{1f}';
/// Separates labels.
pub const RECORD_SEP: char = '\u{1e}';

/// A scene as flat arrays.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Packed {
    /// Which view.
    pub view: ViewKind,
    /// `[x0, y0, x1, y1]` of every item.
    pub bounds: [f64; 4],
    /// `[x0, y0, x1, y1]` to fit first.
    pub focus: [f64; 4],
    /// Shape numbers.
    pub coords: Vec<f64>,
    /// Item records, [`STRIDE`] each.
    pub items: Vec<u32>,
    /// Source lines of all items.
    pub lines: Vec<u32>,
    /// Label records.
    pub labels: String,
}

fn rect(r: Rect) -> [f64; 4] {
    [r.x0, r.y0, r.x1, r.y1]
}

fn anchor_code(a: Anchor) -> u32 {
    match a {
        Anchor::Start => 0,
        Anchor::Middle => 1,
        Anchor::End => 2,
    }
}

fn glyph_code(g: Glyph) -> u32 {
    match g {
        Glyph::Dot => 0,
        Glyph::Bar => 1,
        Glyph::Cross => 2,
    }
}

/// Packs a scene.
pub fn pack(scene: &Scene) -> Packed {
    let mut p = Packed {
        view: scene.view,
        bounds: rect(scene.bounds),
        focus: rect(scene.focus),
        coords: Vec::with_capacity(scene.items.len() * 4),
        items: Vec::with_capacity(scene.items.len() * STRIDE),
        lines: Vec::with_capacity(scene.items.len()),
        labels: String::new(),
    };
    let mut label_count = 0u32;
    for item in &scene.items {
        push_item(&mut p, item, &mut label_count);
    }
    p
}

fn push_item(p: &mut Packed, item: &Item, label_count: &mut u32) {
    let start = p.coords.len() as u32;
    let mut label = 0u32;
    let mut extra = match item.role {
        None => 0,
        Some(Role::Rough) => 1,
        Some(Role::Finish) => 2,
        Some(Role::Spring) => 3,
    };
    let mut add_label = |p: &mut Packed, key: &str, value: &str| {
        if *label_count > 0 {
            p.labels.push(RECORD_SEP);
        }
        p.labels.push_str(key);
        p.labels.push(UNIT_SEP);
        p.labels.push_str(value);
        *label_count += 1;
        *label_count
    };
    let shape = match &item.shape {
        Shape::Polyline { points } | Shape::Polygon { points } => {
            for q in points.iter() {
                p.coords.extend_from_slice(q);
            }
            if matches!(item.shape, Shape::Polyline { .. }) { 0 } else { 1 }
        }
        Shape::Circle { center, radius } => {
            p.coords.extend_from_slice(&[center[0], center[1], *radius]);
            2
        }
        Shape::Arrow { from, to } => {
            p.coords.extend_from_slice(&[from[0], from[1], to[0], to[1]]);
            3
        }
        Shape::Dim { a, b, offset, label: l } => {
            p.coords.extend_from_slice(&[a[0], a[1], b[0], b[1], *offset]);
            label = add_label(p, l.key, &l.value);
            4
        }
        Shape::Text { at, label: l, anchor, dx, dy } => {
            p.coords.extend_from_slice(&[at[0], at[1], *dx, *dy]);
            label = add_label(p, l.key, &l.value);
            extra = anchor_code(*anchor);
            5
        }
        Shape::Marker { at, glyph } => {
            p.coords.extend_from_slice(at);
            extra = glyph_code(*glyph);
            6
        }
    };
    let line_start = p.lines.len() as u32;
    p.lines.extend_from_slice(&item.lines);
    p.items.extend_from_slice(&[
        shape,
        item.style.code(),
        start,
        p.coords.len() as u32 - start,
        item.thread.map_or(0, |t| t + 1),
        item.pass.map_or(0, |t| t + 1),
        line_start,
        item.lines.len() as u32,
        label,
        extra,
    ]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::{Style, side};
    use crate::{Dialect, plan::plan_default};

    #[test]
    fn packing_keeps_every_item() {
        let plan = plan_default(include_str!("../../examples/o1006.nc"), Dialect::Gsk980tdc);
        let scene = side(&plan);
        let p = pack(&scene);
        assert_eq!(p.items.len(), scene.items.len() * STRIDE);
        let labels = p.labels.split(RECORD_SEP).count();
        let labelled = scene.items.iter().filter(|i| matches!(i.shape, Shape::Dim { .. } | Shape::Text { .. })).count();
        assert_eq!(labels, labelled);
        // The first cut of the first pass: a polyline of 4 numbers with its thread, pass and line.
        let k = scene.items.iter().position(|i| i.style == Style::Cut).unwrap();
        let rec = &p.items[k * STRIDE..(k + 1) * STRIDE];
        let f = |name: &str| rec[FIELDS.iter().position(|n| *n == name).unwrap()];
        assert_eq!(SHAPES[f("shape") as usize], "polyline");
        assert_eq!(f("style"), Style::Cut.code());
        assert_eq!(
            &p.coords[f("coord_start") as usize..(f("coord_start") + f("coord_len")) as usize],
            &[70.0, 23.55, 13.0, 23.55]
        );
        assert_eq!((f("thread"), f("pass")), (1, 1));
        assert_eq!(&p.lines[f("line_start") as usize..(f("line_start") + f("line_len")) as usize], &[6]);
        assert_eq!(
            Style::ALL.iter().map(|s| s.code()).collect::<Vec<_>>(),
            (0..Style::ALL.len() as u32).collect::<Vec<_>>()
        );
        assert_eq!(ANCHORS[anchor_code(Anchor::End) as usize], "end");
        assert_eq!(GLYPHS[glyph_code(Glyph::Cross) as usize], "cross");
    }
}
