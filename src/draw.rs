//! Drawing, decided once: a [`Scene`] and a [`View`] (page size, transform
//! or fit, language, chosen thread, stale, highlight) become a
//! [`DisplayList`] — the pens, the paths in page pixels, the labels placed —
//! that the canvas painter and the SVG writer (`svg`) execute
//! without deciding anything. The app's canvas, its SVG export and
//! `screwcut svg` of one view at one size show the same labels at the same places.
//!
//! - Labels: each dimension and text of the scene with its candidate places
//!   ([`labels`]), the drawing's lines in a grid of world cells ([`lines`]),
//!   greedy placement by priority without overlaps ([`place`]), text widths
//!   from one table of a sans-serif's advances ([`measure`]) and long notes wrapped.
//! - Fit: the transform whose scale leaves room for the scene's focus and its labels ([`fit`]).
//! - Pens: one table by style ([`pens`]); a stale drawing's pens greyed and
//!   faded, the highlight's halos beneath the items: styles in the list.
//! - Hit testing and what a hover marks ([`pick`]).

use serde::{Deserialize, Serialize};

use crate::diagram::scene::{Anchor, Scene};
use crate::message::Lang;

mod fit;
mod held;
mod kept;
mod labels;
mod lines;
pub mod list;
mod paint;
mod pens;
pub mod pick;
mod place;
mod text;
mod visit;
pub mod words;

pub use kept::FitMemo;

pub use list::{DisplayList, Op, Pen};
pub use text::{measure, wrap};
pub use words::{LABEL_KEYS, chinese, english, label_text};

/// The font family list of every text: DejaVu Sans first (the advances of
/// [`measure`] are its), then faces covering Greek and CJK.
pub const FONT_FAMILY: &str =
    "'DejaVu Sans', 'Noto Sans CJK SC', 'Microsoft YaHei', system-ui, -apple-system, 'Segoe UI', sans-serif";

/// The font size of every text, px.
pub const FONT_SIZE: f64 = 12.0;

/// Above this many threads with dimensions, only the chosen thread's are drawn.
pub const MAX_ANNOTATED: usize = 6;

/// The largest page side accepted, px.
pub const MAX_SIZE: f64 = 100_000.0;

/// World → page: `X = tx + sx·x`, `Y = ty − sy·y` (y down on the page).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Transform {
    /// Horizontal scale, px per world unit.
    pub sx: f64,
    /// Vertical scale, px per world unit.
    pub sy: f64,
    /// Page x of the world origin.
    pub tx: f64,
    /// Page y of the world origin.
    pub ty: f64,
}

impl Transform {
    /// The page point of world point `p`.
    pub fn at(&self, p: [f64; 2]) -> [f64; 2] {
        [self.tx + self.sx * p[0], self.ty - self.sy * p[1]]
    }

    /// The world point of page point `p`.
    pub fn world(&self, p: [f64; 2]) -> [f64; 2] {
        [(p[0] - self.tx) / self.sx, (self.ty - p[1]) / self.sy]
    }

    /// Whether the numbers are finite and the scales positive.
    pub fn is_valid(&self) -> bool {
        [self.sx, self.sy, self.tx, self.ty].iter().all(|v| v.is_finite()) && self.sx > 0.0 && self.sy > 0.0
    }
}

/// A label where it is drawn.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Placed {
    /// Index of the scene item (a dimension or a text) the label belongs to.
    pub item: usize,
    /// The label's key (`dia_major`, `lead`; empty for a bare value).
    pub key: String,
    /// The text as drawn, one entry per line.
    pub lines: Vec<String>,
    /// How the lines line up in the box (`middle` for a one-line label).
    pub align: Anchor,
    /// The label's box `[x0, y0, x1, y1]` on the page; the text is centred in it.
    #[serde(rename = "box")]
    pub bounds: [f64; 4],
    /// Rotation of the text, degrees (−90: a vertical dimension's text reads upward).
    pub angle: f64,
    /// A dimension's line: its offset from the dimension's points, px.
    pub off: f64,
    /// A half dimension's line: its length from the arrowhead towards the axis, px.
    pub len: f64,
    /// A leader from a text's point to its box, `[x0, y0, x1, y1]` on the page.
    pub lead: Option<[f64; 4]>,
}

/// What a view marks: scene items (what the pointer or the table points at,
/// or, `light`, what the cursor line draws: a lighter mark).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mark {
    /// The items marked.
    pub items: Vec<usize>,
    /// The cursor line's lighter mark (halos only).
    pub light: bool,
}

/// How to draw a scene: the page, the transform (else fitted), the
/// language and chosen thread of the labels, and the styles of the moment.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// Width of the page, px.
    pub width: f64,
    /// Height of the page, px.
    pub height: f64,
    /// When fitted, the vertical scale may exceed the horizontal one to fill the height.
    pub stretch: bool,
    /// The thread whose dimensions are drawn when the scene has many.
    pub thread: usize,
    /// The language of the labels.
    pub lang: Lang,
    /// World → page; `None`: fitted to the page ([`fit_of`]).
    pub transform: Option<Transform>,
    /// The last good drawing kept while the text has an alarm: greyed.
    pub stale: bool,
    /// What is highlighted.
    pub mark: Mark,
    /// Draw the roughing cuts of G71/G72 (off: on demand).
    pub roughing: bool,
}

impl Default for View {
    fn default() -> View {
        View {
            width: 800.0,
            height: 500.0,
            stretch: false,
            thread: 0,
            lang: Lang::En,
            transform: None,
            stale: false,
            mark: Mark::default(),
            roughing: false,
        }
    }
}

impl View {
    /// The text of a label in the view's language.
    pub fn label_text(&self, key: &str, value: &str) -> String {
        label_text(self.lang, key, value)
    }

    /// The page size, bounded (a size that is not one becomes 800 × 500).
    pub fn page(&self) -> (f64, f64) {
        let ok = |v: f64, d: f64| if v.is_finite() && v > 0.0 { v.min(MAX_SIZE) } else { d };
        (ok(self.width, 800.0), ok(self.height, 500.0))
    }

    /// Whether the view can be drawn as given: a page size within [`MAX_SIZE`]
    /// and a transform that maps. [`display`] never fails: it draws what this refuses with defaults.
    pub fn validate(&self) -> Result<(), String> {
        for (what, v) in [("width", self.width), ("height", self.height)] {
            if !(v.is_finite() && v > 0.0 && v <= MAX_SIZE) {
                return Err(format!("the page {what} {v} is not a size in px (0 to {MAX_SIZE})"));
            }
        }
        match self.transform {
            Some(t) if !t.is_valid() => Err(format!("the transform {t:?} needs finite numbers and positive scales")),
            _ => Ok(()),
        }
    }
}

/// What a drawing reads of its scene for the labels: the drawing's lines,
/// which labels keep off, and the items with labels (with their indices).
struct Read<'s> {
    lines: lines::LineIndex,
    labelled: Vec<(usize, &'s crate::diagram::Item)>,
}

impl<'s> Read<'s> {
    /// Read from the whole of `scene`.
    fn of(scene: &'s Scene) -> Read<'s> {
        Read { lines: lines::scene_lines(scene), labelled: labels::labelled(scene) }
    }
}

/// The transform that fits `scene`'s focus and its labels into the view's page.
pub fn fit_of(scene: &Scene, view: &View) -> Transform {
    fit::fit(scene, view, view.page(), &Read::of(scene))
}

/// The display list of `scene` in `view`: fitted when the view gives no
/// (valid) transform, labels placed, painted.
pub fn display(scene: &Scene, view: &View) -> DisplayList {
    let read = Read::of(scene);
    let xf = view.transform.filter(Transform::is_valid).unwrap_or_else(|| fit::fit(scene, view, view.page(), &read));
    let mut sets = visit::PathSets::default();
    let parts: Vec<visit::PartPaint> =
        scene.items.parts().map(|(_, part)| visit::PartPaint::of(part, &mut sets)).collect();
    let visit: Vec<_> =
        scene.items.parts().zip(&parts).map(|((start, items), part)| (start, items.as_slice(), part)).collect();
    display_at(scene, view, xf, &read, &visit)
}

/// [`display`] with the fit and what was read of the scene's parts kept in
/// `memo` between drawings of one view ([`FitMemo`]: a scene whose focus and
/// labels did not change keeps its transform; the parts it shares with the
/// last scene are not read again, `draw::held`).
pub fn display_kept(scene: &Scene, view: &View, memo: &mut FitMemo) -> DisplayList {
    let read = memo.read(scene);
    let xf = view.transform.filter(Transform::is_valid).unwrap_or_else(|| memo.fit_with(scene, view, &read));
    display_at(scene, view, xf, &read, &memo.visit(scene))
}

/// The display list of `scene` in `view` at transform `xf`, its labels as
/// `read` found them, its parts visited as `visit` gives them.
fn display_at(scene: &Scene, view: &View, xf: Transform, read: &Read, visit: &visit::Visit) -> DisplayList {
    let page = view.page();
    let (placed, dropped) = place::placed(read, view, &xf, page);
    let mut b = list::Builder::new(scene.view, page, xf, view.stale);
    paint::paint(&mut b, scene, visit, &xf, &placed, view);
    b.list.labels = placed;
    b.list.dropped = dropped;
    b.list.anchor = xf.at(anchor(scene, &view.mark));
    b.list
}

/// Where a zoom without a pointer centres: the middle of the marked items, else of the scene's focus.
fn anchor(scene: &Scene, mark: &Mark) -> [f64; 2] {
    let mut r = crate::diagram::Rect::EMPTY;
    for it in mark.items.iter().filter_map(|&i| scene.items.get(i)) {
        it.each_point(|p| r.add(p));
    }
    let r = if r.is_empty() { scene.focus.or_unit() } else { r };
    [(r.x0 + r.x1) / 2.0, (r.y0 + r.y1) / 2.0]
}
