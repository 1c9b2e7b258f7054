//! A scene as a standalone SVG document (`screwcut svg`, and the web app's
//! SVG export through `Session::svg`), drawn as the app's canvas draws it
//! (`www/src/render.js`: the same pens, dashes, widths, role colours, area
//! fills, dimensions, markers, arrowheads and label halos).
//!
//! The page is `width × height` px and the `viewBox` is `0 0 width height`:
//! shapes are clipped to it, every label is inside it.
//!
//! - With a [`Layout`] (what the app passes: the view's transform and the
//!   labels as its canvas placed them), shapes are drawn with that transform
//!   and every label exactly where it is given, so the export is what the
//!   view shows.
//! - With a transform and no labels, labels are placed at that transform
//!   ([`place`]).
//! - Without a layout (the command line), the drawing and its labels are
//!   fitted to the page ([`fit`]) and the labels placed ([`place`]) by the
//!   rules of `www/src/labels.js`, with text widths estimated from a table of
//!   a sans-serif's advances ([`measure`]).
//!
//! Fonts are named by the app's family list, covering Latin, Greek and CJK;
//! the background is white and the document has a title: it prints as it shows.

use std::fmt::Write;

use serde::{Deserialize, Serialize};

use crate::diagram::scene::{Anchor, Pt, Scene, Shape, ViewKind};

mod fit;
mod labels;
mod lines;
mod paint;
mod pens;
mod place;
mod text;

pub use text::{measure, wrap};

/// The font family list of every text (the app's label font).
pub const FONT_FAMILY: &str = "system-ui, -apple-system, 'Segoe UI', 'Noto Sans CJK SC', 'Microsoft YaHei', sans-serif";

/// The font size of every text, px (the app's label font).
pub const FONT_SIZE: f64 = 12.0;

/// Above this many threads with dimensions, only the chosen thread's are drawn (as in the app).
pub const MAX_ANNOTATED: usize = 6;

/// The largest page side accepted, px.
pub const MAX_SIZE: f64 = 100_000.0;

/// How to draw a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Width of the page, px.
    pub width: f64,
    /// Height of the page, px.
    pub height: f64,
    /// Stretch the vertical scale to fill the height (the app's radial stretch; without a layout).
    pub stretch: bool,
    /// The thread whose dimensions are drawn when the scene has many.
    pub thread: usize,
    /// Label templates by key (`"lead"` → `"Ph {}"`); missing keys use [`english`].
    pub labels: Vec<(String, String)>,
    /// The view's transform and its labels as placed (the app's export); `None`: fitted and placed here.
    pub layout: Option<Layout>,
}

impl Default for Options {
    fn default() -> Options {
        Options { width: 800.0, height: 500.0, stretch: false, thread: 0, labels: Vec::new(), layout: None }
    }
}

/// World → page: `X = tx + sx·x`, `Y = ty − sy·y` (y down on the page), as
/// the app's views keep it.
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
    pub fn at(&self, p: Pt) -> Pt {
        [self.tx + self.sx * p[0], self.ty - self.sy * p[1]]
    }
}

/// A label where it is drawn: what the app's `drawScene` reports of each
/// placed label (other fields of its records are ignored).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Placed {
    /// Index of the scene item (a dimension or a text) the label belongs to.
    pub item: usize,
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
    #[serde(default)]
    pub off: f64,
    /// A half dimension's line: its length from the arrowhead towards the axis, px.
    #[serde(default)]
    pub len: f64,
    /// A leader from a text's point to its box, `[x0, y0, x1, y1]` on the page.
    #[serde(default)]
    pub lead: Option<[f64; 4]>,
}

/// The view a drawing is made for: its transform and, optionally, its labels as placed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Layout {
    /// World → page.
    pub transform: Transform,
    /// The labels as placed; `None`: placed at `transform` by the writer.
    #[serde(default)]
    pub labels: Option<Vec<Placed>>,
}

/// The English template of a label key, as the app shows it.
pub fn english(key: &str) -> Option<&'static str> {
    Some(match key {
        "dia_major" => "major Ø{}",
        "dia_minor" => "minor Ø{}",
        "lead" => "Ph {}",
        "pitch" => "P {}",
        "length" => "L {}",
        "taper" => "taper {}",
        "delta1" => "δ1 {}",
        "delta2" => "δ2 {}",
        "height" => "h {}",
        "tool_angle" => "tool angle {}",
        "start_of" => "start {}",
        "pass_depth" => "{}",
        "pass_depth_finish" => "{} finish",
        "pass_depth_spring" => "{} spring",
        "infeed_radial" => "radial infeed",
        "infeed_left" => "left flank infeed",
        "infeed_right" => "right flank infeed",
        "infeed_alternating" => "alternating flanks",
        "infeed_programmed" => "infeed as programmed",
        "one_rev" => "one-rev signal {}",
        "axial_offsets" => "axial offsets lead·θ/360",
        "start_angle" => "{}",
        "starts_capped" => "{} starts: the first 360 are drawn",
        "moves_capped" => "motions outside the threads: only the first {} are drawn",
        "square_tool" => "0° tool: width {} assumed",
        "detail_passes" => "every n-th pass drawn (n/all): {}",
        "detail_starts" => "one start drawn, the others cut the same path (1/starts): {}",
        "detail_starts_passes" => "one start and every n-th pass drawn (1/starts n/all): {}",
        _ => return None,
    })
}

/// The Chinese template of a label key, as the app shows it.
pub fn chinese(key: &str) -> Option<&'static str> {
    Some(match key {
        "dia_major" => "大径 Ø{}",
        "dia_minor" => "小径 Ø{}",
        "lead" => "导程 {}",
        "pitch" => "螺距 {}",
        "length" => "长 {}",
        "taper" => "锥度 {}",
        "height" => "牙高 {}",
        "tool_angle" => "刀尖角 {}",
        "start_of" => "第 {} 头",
        "pass_depth_finish" => "{} 精车",
        "pass_depth_spring" => "{} 光刀",
        "infeed_radial" => "径向进刀(中线)",
        "infeed_left" => "左侧面进刀",
        "infeed_right" => "右侧面进刀",
        "infeed_alternating" => "左右交替进刀",
        "infeed_programmed" => "按程序进刀",
        "one_rev" => "一转信号 {}",
        "axial_offsets" => "轴向偏移 导程·θ/360",
        "starts_capped" => "{} 头：只画前 360 头",
        "moves_capped" => "螺纹以外的运动只画前 {} 段",
        "square_tool" => "0° 刀：假定刀宽 {}",
        "detail_passes" => "每隔 n 次走刀画一次(n/总数)：{}",
        "detail_starts" => "只画一头，其余各头路径相同(1/头数)：{}",
        "detail_starts_passes" => "只画一头、每隔 n 次走刀画一次(1/头数 n/总数)：{}",
        // δ1, δ2 and the bare values read the same in both languages.
        key => return english(key),
    })
}

/// The label keys a scene uses.
pub const LABEL_KEYS: [&str; 28] = [
    "dia_major",
    "dia_minor",
    "lead",
    "pitch",
    "length",
    "taper",
    "delta1",
    "delta2",
    "height",
    "tool_angle",
    "start_of",
    "pass_depth",
    "pass_depth_finish",
    "pass_depth_spring",
    "infeed_radial",
    "infeed_left",
    "infeed_right",
    "infeed_alternating",
    "infeed_programmed",
    "one_rev",
    "axial_offsets",
    "start_angle",
    "starts_capped",
    "moves_capped",
    "square_tool",
    "detail_passes",
    "detail_starts",
    "detail_starts_passes",
];

/// The label templates of language `lang` (`en`, `zh`) for [`Options::labels`]; `None` for another language.
pub fn templates(lang: &str) -> Option<Vec<(String, String)>> {
    let table: fn(&str) -> Option<&'static str> = match lang {
        "en" => english,
        "zh" => chinese,
        _ => return None,
    };
    Some(LABEL_KEYS.iter().filter_map(|k| table(k).map(|t| (k.to_string(), t.to_string()))).collect())
}

impl Options {
    /// The text of a label: its key's template (the options', else English)
    /// with the value in place of `{}`; a key without a template as the app
    /// shows it (the key and the value).
    pub fn label_text(&self, key: &str, value: &str) -> String {
        if key.is_empty() {
            return value.to_string();
        }
        let own = self.labels.iter().find(|(k, _)| k == key).map(|(_, t)| t.as_str());
        match own.or_else(|| english(key)) {
            Some(t) => t.replacen("{}", value, 1),
            None if value.is_empty() => key.to_string(),
            None => format!("{key} {value}"),
        }
    }

    /// Whether the options can draw `scene`: a page size within [`MAX_SIZE`],
    /// finite numbers, a transform that maps, and labels that name
    /// dimensions and texts of the scene (at most one each). The error says
    /// what is wrong. [`svg`] never fails: it skips what this refuses.
    pub fn validate(&self, scene: &Scene) -> Result<(), String> {
        for (what, v) in [("width", self.width), ("height", self.height)] {
            if !(v.is_finite() && v > 0.0 && v <= MAX_SIZE) {
                return Err(format!("the page {what} {v} is not a size in px (0 to {MAX_SIZE})"));
            }
        }
        let Some(layout) = &self.layout else { return Ok(()) };
        let t = layout.transform;
        if ![t.sx, t.sy, t.tx, t.ty].iter().all(|v| v.is_finite()) || t.sx <= 0.0 || t.sy <= 0.0 {
            return Err(format!("the transform {t:?} needs finite numbers and positive scales"));
        }
        let Some(labels) = &layout.labels else { return Ok(()) };
        let mut seen = vec![false; scene.items.len()];
        for (k, p) in labels.iter().enumerate() {
            check_placed(scene, p).map_err(|e| format!("label {k}: {e}"))?;
            if std::mem::replace(&mut seen[p.item], true) {
                return Err(format!("label {k}: item {} is placed twice", p.item));
            }
        }
        Ok(())
    }
}

/// Most lines of one label, and most characters of one line.
const MAX_LINES: usize = 64;
const MAX_LINE: usize = 4096;

/// What is wrong with one placed label of `scene`, if anything.
fn check_placed(scene: &Scene, p: &Placed) -> Result<(), String> {
    match scene.items.get(p.item).map(|i| &i.shape) {
        Some(Shape::Dim { .. } | Shape::Text { .. }) => {}
        Some(_) => return Err(format!("item {} is neither a dimension nor a text", p.item)),
        None => return Err(format!("item {} is not in the scene ({} items)", p.item, scene.items.len())),
    }
    if p.lines.is_empty() || p.lines.len() > MAX_LINES || p.lines.iter().any(|l| l.chars().count() > MAX_LINE) {
        return Err(format!("1 to {MAX_LINES} lines of at most {MAX_LINE} characters"));
    }
    let numbers = p.bounds.iter().chain(p.lead.iter().flatten()).chain([&p.angle, &p.off, &p.len]);
    if !numbers.into_iter().all(|v| v.is_finite()) {
        return Err("a number that is not finite".into());
    }
    if !(p.bounds[0] <= p.bounds[2] && p.bounds[1] <= p.bounds[3]) {
        return Err(format!("the box {:?} is upside down", p.bounds));
    }
    Ok(())
}

/// The scene as an SVG document (see the module documentation).
pub fn svg(scene: &Scene, o: &Options) -> String {
    let (w, h) = page_size(o);
    let (xf, placed) = match &o.layout {
        Some(Layout { transform, labels: Some(given) }) => {
            (*transform, given.iter().filter(|p| check_placed(scene, p).is_ok()).cloned().collect())
        }
        Some(Layout { transform, labels: None }) => (*transform, place::placed(scene, o, transform, (w, h))),
        None => {
            let xf = fit::fit(scene, o, (w, h));
            (xf, place::placed(scene, o, &xf, (w, h)))
        }
    };
    paint::document(scene, &xf, &placed, (w, h))
}

/// The page size of `o`, bounded (a size [`Options::validate`] refuses becomes 800 × 500).
fn page_size(o: &Options) -> (f64, f64) {
    let ok = |v: f64, d: f64| if v.is_finite() && v > 0.0 { v.min(MAX_SIZE) } else { d };
    (ok(o.width, 800.0), ok(o.height, 500.0))
}

/// Two decimals, trimmed.
fn f(v: f64) -> String {
    let v = if v.is_finite() { (v * 100.0).round() / 100.0 } else { 0.0 };
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.to_string() }
}

/// Text for XML content and attributes.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && c != '\t' && c != '\n' => out.push('\u{fffd}'),
            c => out.push(c),
        }
    }
    out
}

/// The title of a view.
fn title(view: ViewKind) -> &'static str {
    match view {
        ViewKind::Side => "side section",
        ViewKind::Tooth => "tooth section",
        ViewKind::Starts => "starts",
    }
}

/// Appends `s` to `out` (a `String` never fails).
fn push(out: &mut String, s: std::fmt::Arguments) {
    let _ = out.write_fmt(s);
}

impl Anchor {
    /// The SVG `text-anchor` value.
    fn svg(self) -> &'static str {
        match self {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        }
    }
}
