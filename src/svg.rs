//! A scene as a standalone SVG document (`screwcut svg`), drawn as the web
//! app draws it (`www/src/render.js`: the same pens, dashes, widths, role
//! colours, dimensions, markers and text placement), so that the app's SVG
//! export and the command line give the same drawing.
//!
//! The scene's focus (what the app's Fit shows) is fitted into `width ×
//! height` less a padding (world → screen, +y up in the world, down on the
//! page), then the `viewBox` is grown to hold every label, whose extent is
//! estimated from the font size and the characters ([`measure`]); shapes are
//! clipped to it as the app's canvas clips them. Fonts are named by a family list that
//! covers Latin, Greek and CJK text; the background is white, the document
//! has a title: it prints as it shows.

use std::fmt::Write;

use crate::diagram::scene::{Anchor, Glyph, Item, Pt, Rect, Scene, Shape, Style, ViewKind};
use crate::thread::Role;

/// The font family list of every text.
pub const FONT_FAMILY: &str = "system-ui, -apple-system, 'Segoe UI', 'Noto Sans', 'Noto Sans CJK SC', 'Microsoft YaHei', 'DejaVu Sans', sans-serif";

/// Above this many threads with dimensions, only the chosen thread's are drawn (as in the app).
pub const MAX_ANNOTATED: usize = 6;

/// How to draw a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Width of the drawing area before labels are fitted in, in px.
    pub width: f64,
    /// Height of the drawing area, in px.
    pub height: f64,
    /// Space kept around the fitted scene, in px.
    pub pad: f64,
    /// Font size, px.
    pub font_size: f64,
    /// Stretch the vertical scale to fill the height (the app's radial stretch).
    pub stretch: bool,
    /// The world rectangle to fit (default: the scene's focus, as the app's Fit; the viewBox still grows to hold every item).
    pub view: Option<Rect>,
    /// The thread whose dimensions are drawn when the scene has many.
    pub thread: usize,
    /// Label templates by key (`"lead"` → `"Ph {}"`); missing keys use [`english`].
    pub labels: Vec<(String, String)>,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            width: 800.0,
            height: 500.0,
            pad: 56.0,
            font_size: 12.0,
            stretch: false,
            view: None,
            thread: 0,
            labels: Vec::new(),
        }
    }
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
        "moves_capped" => "drawing stops after {} moves",
        "square_tool" => "0° tool: width {} assumed",
        _ => return None,
    })
}

/// A pen: what `render.js` calls by the style's name.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pen {
    stroke: Option<&'static str>,
    width: f64,
    dash: &'static [f64],
    fill: Option<&'static str>,
    text: Option<&'static str>,
    alpha: Option<f64>,
}

const NONE: Pen = Pen { stroke: None, width: 1.0, dash: &[], fill: None, text: None, alpha: None };

const fn line(stroke: &'static str, width: f64, dash: &'static [f64]) -> Pen {
    Pen { stroke: Some(stroke), width, dash, ..NONE }
}

/// The pens of `render.js` (`PENS`).
fn pen(style: Style) -> Pen {
    match style {
        Style::Axis => line("#8a94a6", 1.0, &[14.0, 3.0, 2.0, 3.0]),
        Style::Outline => line("#1f2937", 1.6, &[]),
        Style::Crest => line("#1f2937", 1.3, &[7.0, 3.0]),
        Style::Root => line("#64748b", 1.0, &[2.0, 3.0]),
        Style::ThreadZone => Pen { fill: Some("rgba(100,116,139,0.14)"), ..NONE },
        Style::Rapid => line("#dc2626", 1.0, &[5.0, 4.0]),
        Style::Cut => line("#2563eb", 2.0, &[]),
        Style::Runout => line("#ea580c", 2.0, &[2.0, 2.0]),
        Style::ScrewIn => line("#b45309", 2.0, &[2.0, 2.0]),
        Style::OtherRapid => line("#a3a9b5", 1.0, &[3.0, 4.0]),
        Style::Delta1 => Pen { fill: Some("rgba(234,179,8,0.22)"), text: Some("#854d0e"), ..NONE },
        Style::Delta2 => Pen { fill: Some("rgba(249,115,22,0.20)"), text: Some("#9a3412"), ..NONE },
        Style::Dimension | Style::Diameter => Pen { text: Some("#111827"), ..line("#374151", 1.0, &[]) },
        Style::Note => Pen { text: Some("#374151"), ..line("#4b5563", 1.0, &[]) },
        Style::Material => Pen { fill: Some("rgba(148,163,184,0.38)"), ..NONE },
        Style::Profile => line("#111827", 1.8, &[]),
        Style::Tool => Pen { alpha: Some(0.75), ..line("#1d4ed8", 1.1, &[]) },
        Style::Area => Pen { fill: Some("#93c5fd"), ..line("rgba(30,64,175,0.5)", 0.6, &[]) },
        Style::DepthTick => Pen { text: Some("#1f2937"), ..line("#374151", 1.0, &[]) },
        Style::Infeed => Pen { text: Some("#991b1b"), ..line("#dc2626", 1.6, &[]) },
        Style::Circle => line("#1f2937", 1.5, &[]),
        Style::Start => Pen { text: Some("#1e3a8a"), ..line("#2563eb", 1.6, &[]) },
        Style::Ruler => line("#374151", 1.2, &[]),
    }
}

/// The fill of pass `pass`'s area (distinct hues; finishing green, spring violet).
fn area_colour(pass: u32, role: Option<Role>) -> String {
    match role {
        Some(Role::Finish) => "rgba(16,185,129,0.65)".into(),
        Some(Role::Spring) => "rgba(139,92,246,0.5)".into(),
        _ => format!("hsla({},75%,62%,0.6)", (200 + pass as u64 * 47) % 360),
    }
}

/// The stroke of an item: finishing and spring passes have their own colour.
fn stroke_of(item: &Item, p: &Pen) -> Option<String> {
    let role = match item.shape {
        Shape::Polyline { .. } | Shape::Polygon { .. } | Shape::Circle { .. } | Shape::Arrow { .. } => item.role,
        _ => None,
    };
    p.stroke.map(|s| {
        match role {
            Some(Role::Finish) => "#059669",
            Some(Role::Spring) => "#7c3aed",
            _ => s,
        }
        .to_string()
    })
}

/// World → page: `X = tx + sx·x`, `Y = ty − sy·y`.
#[derive(Clone, Copy, Debug)]
struct Fit {
    sx: f64,
    sy: f64,
    tx: f64,
    ty: f64,
}

impl Fit {
    fn new(r: Rect, o: &Options) -> Fit {
        let w = r.width().max(1e-9);
        let h = r.height().max(1e-9);
        let aw = (o.width - 2.0 * o.pad).max(10.0);
        let ah = (o.height - 2.0 * o.pad).max(10.0);
        let sx = (aw / w).min(ah / h);
        let sy = if o.stretch { sx.max(ah / h) } else { sx };
        Fit { sx, sy, tx: o.width / 2.0 - sx * (r.x0 + r.x1) / 2.0, ty: o.height / 2.0 + sy * (r.y0 + r.y1) / 2.0 }
    }

    fn at(&self, p: Pt) -> (f64, f64) {
        (self.tx + self.sx * p[0], self.ty - self.sy * p[1])
    }
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

mod paint;
pub use paint::measure;

/// The scene as an SVG document.
pub fn svg(scene: &Scene, o: &Options) -> String {
    paint::document(scene, o)
}

/// The title of a view.
fn title(view: ViewKind) -> &'static str {
    match view {
        ViewKind::Side => "side section",
        ViewKind::Tooth => "tooth section",
        ViewKind::Starts => "starts",
    }
}

/// `"{}"` in a template replaced by the value.
fn fill(template: &str, value: &str) -> String {
    template.replacen("{}", value, 1)
}

/// Appends `s` to `out` (a `String` never fails).
fn push(out: &mut String, s: std::fmt::Arguments) {
    let _ = out.write_fmt(s);
}

impl Anchor {
    fn svg(self) -> &'static str {
        match self {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        }
    }
}

impl Glyph {
    fn code(self) -> u8 {
        match self {
            Glyph::Dot => 0,
            Glyph::Bar => 1,
            Glyph::Cross => 2,
        }
    }
}
