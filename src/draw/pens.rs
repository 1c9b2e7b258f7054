//! The pens of the drawings: what each style is drawn with, the colours of
//! finishing and spring passes and of each pass's area, and the highlight.

use super::list::Pen;
use crate::diagram::scene::{Item, Shape, Style};
use crate::thread::Role;

/// The highlight's colour (what the pointer or the cursor line marks).
pub(super) const HIGHLIGHT: &str = "#f59e0b";
/// The halo of a highlighted label's text: strong, light.
pub(super) const HIGHLIGHT_HALO: [&str; 2] = ["#fcd34d", "#fde68a"];
/// The halo behind a label's text.
pub(super) const HALO: &str = "rgba(255,255,255,0.85)";

/// A style's pen as constants, with the colour of its texts.
#[derive(Clone, Copy)]
struct Def {
    stroke: Option<&'static str>,
    width: f64,
    dash: &'static [f64],
    fill: Option<&'static str>,
    text: Option<&'static str>,
    alpha: Option<f64>,
}
const NONE: Def = Def { stroke: None, width: 1.0, dash: &[], fill: None, text: None, alpha: None };

const fn line(stroke: &'static str, width: f64, dash: &'static [f64]) -> Def {
    Def { stroke: Some(stroke), width, dash, ..NONE }
}

/// The pen of a style.
fn def(style: Style) -> Def {
    match style {
        Style::Axis => line("#8a94a6", 1.0, &[14.0, 3.0, 2.0, 3.0]),
        Style::Outline => line("#1f2937", 1.6, &[]),
        Style::Crest => line("#1f2937", 1.3, &[7.0, 3.0]),
        Style::Root => line("#64748b", 1.0, &[2.0, 3.0]),
        Style::ThreadZone => Def { fill: Some("rgba(100,116,139,0.14)"), ..NONE },
        Style::Rapid => line("#dc2626", 1.0, &[5.0, 4.0]),
        Style::Cut => line("#2563eb", 2.0, &[]),
        Style::Runout => line("#ea580c", 2.0, &[2.0, 2.0]),
        Style::ScrewIn => line("#b45309", 2.0, &[2.0, 2.0]),
        Style::OtherRapid => line("#a3a9b5", 1.0, &[3.0, 4.0]),
        Style::Delta1 => Def { fill: Some("rgba(234,179,8,0.22)"), text: Some("#854d0e"), ..NONE },
        Style::Delta2 => Def { fill: Some("rgba(249,115,22,0.20)"), text: Some("#9a3412"), ..NONE },
        Style::Dimension | Style::Diameter => Def { text: Some("#111827"), ..line("#374151", 1.0, &[]) },
        Style::Note => Def { text: Some("#374151"), ..line("#4b5563", 1.0, &[]) },
        Style::Material => Def { fill: Some("rgba(148,163,184,0.38)"), ..NONE },
        Style::Profile => line("#111827", 1.8, &[]),
        Style::Tool => Def { alpha: Some(0.75), ..line("#1d4ed8", 1.1, &[]) },
        Style::Area => Def { fill: Some("#93c5fd"), ..line("rgba(30,64,175,0.5)", 0.6, &[]) },
        Style::DepthTick => Def { text: Some("#1f2937"), ..line("#374151", 1.0, &[]) },
        Style::Infeed => Def { text: Some("#991b1b"), ..line("#dc2626", 1.6, &[]) },
        Style::Circle => line("#1f2937", 1.5, &[]),
        Style::Start => Def { text: Some("#1e3a8a"), ..line("#2563eb", 1.6, &[]) },
        Style::Ruler => line("#374151", 1.2, &[]),
        Style::Compare => Def { alpha: Some(0.9), ..line("#f97316", 1.6, &[6.0, 3.0]) },
        Style::Collision => Def { text: Some("#b91c1c"), ..line("#dc2626", 3.0, &[]) },
        Style::Roughing => Def { alpha: Some(0.8), ..line("#a5b4c8", 0.8, &[]) },
        Style::Break => Def { text: Some("#4b5563"), ..line("#6b7280", 1.0, &[]) },
    }
}

/// The fill of pass `pass`'s area (distinct hues; finishing green, spring
/// violet); `pass` is −1 for an area of no pass.
pub(super) fn area_colour(pass: i64, role: Option<Role>) -> String {
    match role {
        Some(Role::Finish) => "rgba(16,185,129,0.65)".into(),
        Some(Role::Spring) => "rgba(139,92,246,0.5)".into(),
        _ => format!("hsla({},75%,62%,0.6)", (200 + pass * 47).rem_euclid(360)),
    }
}

/// An item's pen and the colour of its text.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ItemPen {
    pub pen: Pen,
    pub text: String,
}

/// The pen of `item`: its style's, an area filled by its pass, a finishing
/// or spring pass's lines in their own colour.
pub(super) fn pen_of(item: &Item) -> ItemPen {
    let d = def(item.style);
    let mut p = Pen {
        stroke: d.stroke.map(str::to_string),
        width: d.width,
        dash: d.dash.to_vec(),
        fill: d.fill.map(str::to_string),
        alpha: d.alpha.unwrap_or(1.0),
    };
    let role = match item.shape {
        Shape::Polyline { .. } | Shape::Polygon { .. } | Shape::Circle { .. } | Shape::Arrow { .. } => item.role,
        _ => None,
    };
    if item.style == Style::Area {
        p.fill = Some(area_colour(item.pass.map_or(-1, i64::from), role));
    } else if p.stroke.is_some() {
        match role {
            Some(Role::Finish) => p.stroke = Some("#059669".into()),
            Some(Role::Spring) => p.stroke = Some("#7c3aed".into()),
            _ => {}
        }
    }
    let text = d.text.or(d.stroke).unwrap_or("#111827").to_string();
    ItemPen { pen: p, text }
}

impl ItemPen {
    /// The stroke colour, else the text colour.
    pub fn colour(&self) -> &str {
        self.pen.stroke.as_deref().unwrap_or(&self.text)
    }
}
