//! The drawing model shared by every view: a scene is a list of items in
//! world coordinates, each with a shape, a style and the source lines,
//! thread and pass it comes from. Renderers (canvas, SVG) only map world to
//! screen and styles to pens; sizes given in pixels (dimension offsets, text
//! offsets, arrow heads, markers) stay constant while the view zooms.

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use crate::thread::Role;

/// A point in world coordinates: `[horizontal, vertical]`.
pub type Pt = [f64; 2];

/// Whether two lists of points are the same, bit for bit.
pub fn same_points(a: &[Pt], b: &[Pt]) -> bool {
    a.len() == b.len() && a.iter().flatten().zip(b.iter().flatten()).all(|(u, v)| u.to_bits() == v.to_bits())
}

/// Feeds `pts` (their number, then every coordinate's bits) into `h`.
pub fn hash_points(h: &mut impl std::hash::Hasher, pts: &[Pt]) {
    h.write_usize(pts.len());
    pts.iter().flatten().for_each(|v| h.write_u64(v.to_bits()));
}

/// Which view a scene is for; it fixes what the world axes mean.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ViewKind {
    /// Side section: horizontal = Z, vertical = radius (X / 2), upper half.
    Side,
    /// Tooth section: horizontal = axial offset from the thread middle,
    /// vertical = radial position from the crest (depth grows downward for
    /// an external thread, upward for an internal one).
    Tooth,
    /// Starts: end view on a unit circle (0° at the top, clockwise) and a
    /// ruler of axial offsets to its right.
    Starts,
}

/// An axis-aligned rectangle in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Rect {
    /// Smallest horizontal coordinate.
    pub x0: f64,
    /// Smallest vertical coordinate.
    pub y0: f64,
    /// Largest horizontal coordinate.
    pub x1: f64,
    /// Largest vertical coordinate.
    pub y1: f64,
}

impl Rect {
    /// The empty rectangle (grows with [`Rect::add`]).
    pub const EMPTY: Rect = Rect { x0: f64::INFINITY, y0: f64::INFINITY, x1: f64::NEG_INFINITY, y1: f64::NEG_INFINITY };

    /// Whether nothing was added.
    pub fn is_empty(&self) -> bool {
        !(self.x0 <= self.x1 && self.y0 <= self.y1)
    }

    /// Whether `p` is inside (edges included).
    pub fn contains(&self, p: Pt) -> bool {
        p[0] >= self.x0 && p[0] <= self.x1 && p[1] >= self.y0 && p[1] <= self.y1
    }

    /// Grows to include `p` (non-finite points are ignored).
    pub fn add(&mut self, p: Pt) {
        use crate::num::{max, min};
        // By comparison: wasm calls `fmin`/`fmax` for `f64::min`/`max` (every point of a scene comes here).
        if p[0].is_finite() && p[1].is_finite() {
            self.x0 = min(self.x0, p[0]);
            self.y0 = min(self.y0, p[1]);
            self.x1 = max(self.x1, p[0]);
            self.y1 = max(self.y1, p[1]);
        }
    }

    /// Grows to include `o`.
    pub fn union(&mut self, o: &Rect) {
        if !o.is_empty() {
            self.add([o.x0, o.y0]);
            self.add([o.x1, o.y1]);
        }
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.x1 - self.x0
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.y1 - self.y0
    }

    /// This rectangle, or a unit square around the origin when empty, with
    /// degenerate sides widened so that a fit never divides by zero.
    pub fn or_unit(self) -> Rect {
        if self.is_empty() {
            return Rect { x0: -1.0, y0: -1.0, x1: 1.0, y1: 1.0 };
        }
        let mut r = self;
        let span = r.width().max(r.height()).max(1e-6);
        if r.width() < span * 1e-3 {
            r.x0 -= span * 0.05;
            r.x1 += span * 0.05;
        }
        if r.height() < span * 1e-3 {
            r.y0 -= span * 0.05;
            r.y1 += span * 0.05;
        }
        r
    }
}

/// Text shown in a scene: a translation key and a language-neutral value.
/// The renderer looks the key up in its language table (`"lead"` → `"Ph {}"`
/// or `"导程 {}"`) and puts the value in; an empty key shows the value alone.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Label {
    /// Translation key, or empty.
    pub key: &'static str,
    /// Value, already formatted (numbers in program units; shared, like
    /// the points: a scene put together again copies no text).
    pub value: Arc<str>,
}

impl Label {
    /// A label with a key and a value.
    pub fn new(key: &'static str, value: impl Into<String>) -> Label {
        Label { key, value: Arc::from(value.into()) }
    }
}

/// Where text sits relative to its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Anchor {
    /// Text starts at the point.
    Start,
    /// Text is centred on the point.
    Middle,
    /// Text ends at the point.
    End,
}

/// A small screen-sized symbol at a world point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Glyph {
    /// A filled dot.
    Dot,
    /// A short bar across the path (run-out and screw-in ends).
    Bar,
    /// A small cross.
    Cross,
}

/// The geometry of an item.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum Shape {
    /// An open path.
    Polyline {
        /// Vertices (shared: a scene built again from kept pieces copies no points).
        points: Arc<[Pt]>,
    },
    /// A closed, filled path.
    Polygon {
        /// Vertices (the last joins the first; shared).
        points: Arc<[Pt]>,
    },
    /// A circle of world radius.
    Circle {
        /// Centre.
        center: Pt,
        /// Radius (world units).
        radius: f64,
    },
    /// An arrow from `from` to `to` (head at `to`, screen-sized).
    Arrow {
        /// Tail.
        from: Pt,
        /// Head.
        to: Pt,
    },
    /// An aligned dimension between `a` and `b`, its line drawn `offset`
    /// pixels to the left of a→b (positive: left, as seen walking from a to b).
    /// Renderers may move the line further out and its text along or beside
    /// it, so that labels do not overlap.
    Dim {
        /// First end.
        a: Pt,
        /// Second end.
        b: Pt,
        /// Offset of the dimension line in pixels.
        offset: f64,
        /// Text.
        label: Label,
    },
    /// Text at a world point, moved by `dx`, `dy` pixels (dy up).
    Text {
        /// Anchor point.
        at: Pt,
        /// Text.
        label: Label,
        /// Horizontal alignment.
        anchor: Anchor,
        /// Pixel offset to the right.
        dx: f64,
        /// Pixel offset upward.
        dy: f64,
    },
    /// A symbol at a world point.
    Marker {
        /// Where.
        at: Pt,
        /// Which symbol.
        glyph: Glyph,
    },
}

/// What an item is, which decides how it is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Style {
    /// Spindle axis or a centre line (dash-dot).
    Axis,
    /// Part outline: the program's turning feed moves.
    Outline,
    /// Thread crest line when the program turns no outline.
    Crest,
    /// Thread root line (deepest pass).
    Root,
    /// The band between crest and root over the threaded length.
    ThreadZone,
    /// A pass's rapid moves (infeed, retract, return): dashed.
    Rapid,
    /// A pass's synchronised cut: solid.
    Cut,
    /// A pass's run-out: marked.
    Runout,
    /// A pass's screw-in: marked.
    ScrewIn,
    /// A rapid move that belongs to no pass.
    OtherRapid,
    /// Lead-in zone δ1.
    Delta1,
    /// Run-out zone δ2.
    Delta2,
    /// Dimension lines and their text.
    Dimension,
    /// Notes and captions.
    Note,
    /// Material in the tooth section.
    Material,
    /// The finished thread profile.
    Profile,
    /// A tool outline at one pass.
    Tool,
    /// The area one pass removes.
    Area,
    /// Depth tick and text of one pass.
    DepthTick,
    /// Direction of infeed.
    Infeed,
    /// The end-view circle.
    Circle,
    /// One start's angle in the end view, or its offset on the ruler.
    Start,
    /// The ruler of axial offsets.
    Ruler,
    /// A diameter in the side section: a dimension from the spindle axis to
    /// the diameter, drawn as a half-section's half dimension (one arrowhead,
    /// at the diameter; its line runs towards the axis).
    Diameter,
    /// Where the side section's radial scale is broken, and its note.
    Break,
    /// A roughing cut of a stock-removal cycle (drawn faintly).
    Roughing,
    /// Where the tool cuts into the part (a shoulder), in red.
    Collision,
    /// Another program's passes laid over these (Compare with…).
    Compare,
}

impl Style {
    /// Every style, in the order of their packed codes.
    pub const ALL: [Style; 28] = [
        Style::Axis,
        Style::Outline,
        Style::Crest,
        Style::Root,
        Style::ThreadZone,
        Style::Rapid,
        Style::Cut,
        Style::Runout,
        Style::ScrewIn,
        Style::OtherRapid,
        Style::Delta1,
        Style::Delta2,
        Style::Dimension,
        Style::Note,
        Style::Material,
        Style::Profile,
        Style::Tool,
        Style::Area,
        Style::DepthTick,
        Style::Infeed,
        Style::Circle,
        Style::Start,
        Style::Ruler,
        Style::Diameter,
        Style::Break,
        Style::Roughing,
        Style::Collision,
        Style::Compare,
    ];

    /// The name renderers know the style by (as serialised).
    pub fn name(self) -> &'static str {
        match self {
            Style::Axis => "axis",
            Style::Outline => "outline",
            Style::Crest => "crest",
            Style::Root => "root",
            Style::ThreadZone => "thread_zone",
            Style::Rapid => "rapid",
            Style::Cut => "cut",
            Style::Runout => "runout",
            Style::ScrewIn => "screw_in",
            Style::OtherRapid => "other_rapid",
            Style::Delta1 => "delta1",
            Style::Delta2 => "delta2",
            Style::Dimension => "dimension",
            Style::Note => "note",
            Style::Material => "material",
            Style::Profile => "profile",
            Style::Tool => "tool",
            Style::Area => "area",
            Style::DepthTick => "depth_tick",
            Style::Infeed => "infeed",
            Style::Circle => "circle",
            Style::Start => "start",
            Style::Ruler => "ruler",
            Style::Diameter => "diameter",
            Style::Break => "break",
            Style::Roughing => "roughing",
            Style::Collision => "collision",
            Style::Compare => "compare",
        }
    }

    /// The packed code: the index in [`Style::ALL`].
    pub fn code(self) -> u32 {
        Style::ALL.iter().position(|s| *s == self).unwrap_or(0) as u32
    }
}

/// One drawable thing with the source it comes from.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Item {
    /// Geometry.
    pub shape: Shape,
    /// Pen.
    pub style: Style,
    /// 1-based source lines this item draws (for editor highlighting).
    #[serde(skip_serializing_if = "<[u32]>::is_empty")]
    pub lines: Arc<[u32]>,
    /// Index of the thread in the plan.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thread: Option<u32>,
    /// Index of the pass in its thread's `passes`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pass: Option<u32>,
    /// What the pass does, for items of a pass (finishing and spring passes are marked).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub role: Option<Role>,
}

impl Item {
    /// An item with no source attached.
    pub fn new(shape: Shape, style: Style) -> Item {
        Item { shape, style, lines: Arc::from([]), thread: None, pass: None, role: None }
    }

    /// Attaches source lines.
    pub fn lines(mut self, lines: impl IntoIterator<Item = u32>) -> Item {
        self.lines = lines.into_iter().collect();
        self
    }

    /// Attaches a thread and, optionally, a pass.
    pub fn of(mut self, thread: usize, pass: Option<usize>) -> Item {
        self.thread = Some(thread as u32);
        self.pass = pass.map(|p| p as u32);
        self
    }

    /// Marks the item with the role of its pass.
    pub fn role(mut self, role: Role) -> Item {
        self.role = Some(role);
        self
    }

    /// Calls `f` with every world point the item covers (for bounds).
    pub fn each_point(&self, mut f: impl FnMut(Pt)) {
        match &self.shape {
            Shape::Polyline { points } | Shape::Polygon { points } => points.iter().for_each(|p| f(*p)),
            Shape::Circle { center, radius } => {
                f([center[0] - radius, center[1] - radius]);
                f([center[0] + radius, center[1] + radius]);
            }
            Shape::Arrow { from: a, to: b } | Shape::Dim { a, b, .. } => {
                f(*a);
                f(*b);
            }
            Shape::Text { at, .. } | Shape::Marker { at, .. } => f(*at),
        }
    }

    /// The world points the item covers.
    pub fn points(&self) -> Vec<Pt> {
        let mut v = Vec::new();
        self.each_point(|p| v.push(p));
        v
    }
}

/// A scene's items, back to front, in parts a scene may share with others ([`crate::parts`]).
pub type Items = crate::parts::Parts<Item>;

/// A view's drawing.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Scene {
    /// Which view.
    pub view: ViewKind,
    /// The items, back to front.
    pub items: Items,
    /// Extent of every item.
    pub bounds: Rect,
    /// Extent the view fits to first (the threads, without far-away rapids).
    pub focus: Rect,
}

impl Scene {
    /// An empty scene.
    pub fn new(view: ViewKind) -> Scene {
        Scene { view, items: Items::new(), bounds: Rect::EMPTY, focus: Rect::EMPTY }
    }

    /// Adds an item, growing the bounds; `focus` also grows the focus.
    pub fn push(&mut self, item: Item, focus: bool) {
        let (bounds, f) = (&mut self.bounds, &mut self.focus);
        item.each_point(|p| {
            bounds.add(p);
            if focus {
                f.add(p);
            }
        });
        self.items.push(item);
    }

    /// Makes `bounds` and `focus` usable for a fit (never empty or flat).
    pub fn finish(&mut self) {
        if self.focus.is_empty() {
            self.focus = self.bounds;
        }
        self.bounds = self.bounds.or_unit();
        self.focus = self.focus.or_unit();
    }

    /// Items that belong to `thread` and `pass`.
    pub fn of_pass(&self, thread: usize, pass: usize) -> impl Iterator<Item = &Item> {
        self.items.iter().filter(move |i| i.thread == Some(thread as u32) && i.pass == Some(pass as u32))
    }
}

/// Formats a length or angle for a label (up to four decimals).
pub fn num(v: f64) -> String {
    crate::num::fmt(v)
}
