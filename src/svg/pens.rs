//! The pens of `www/src/render.js` (`PENS`, `ROLE_STROKE`, `areaColour`):
//! what each style is drawn with, as SVG attributes.

use super::{f, push};
use crate::diagram::scene::{Item, Shape, Style};
use crate::thread::Role;

/// A pen: stroke, width, dashes, fill (of closed shapes), text colour and opacity.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Pen {
    pub stroke: Option<String>,
    pub width: f64,
    pub dash: &'static [f64],
    pub fill: Option<String>,
    pub text: Option<&'static str>,
    pub alpha: Option<f64>,
}

/// A pen of `render.js` as constants.
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

/// The pen of a style (`PENS` in `render.js`).
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
    }
}

/// The fill of pass `pass`'s area (distinct hues; finishing green, spring
/// violet); `pass` is −1 for an area of no pass, as `render.js` computes it.
pub(super) fn area_colour(pass: i64, role: Option<Role>) -> String {
    match role {
        Some(Role::Finish) => "rgba(16,185,129,0.65)".into(),
        Some(Role::Spring) => "rgba(139,92,246,0.5)".into(),
        _ => format!("hsla({},75%,62%,0.6)", (200 + pass * 47).rem_euclid(360)),
    }
}

/// The pen of `item` (`colourPen` in `render.js`): its style's, an area
/// filled by its pass, a finishing or spring pass's lines in their own colour.
pub(super) fn pen_of(item: &Item) -> Pen {
    let d = def(item.style);
    let mut p = Pen {
        stroke: d.stroke.map(str::to_string),
        width: d.width,
        dash: d.dash,
        fill: d.fill.map(str::to_string),
        text: d.text,
        alpha: d.alpha,
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
    p
}

impl Pen {
    /// A plain stroke of `colour` and `width`.
    pub fn thin(colour: &str, width: f64) -> Pen {
        Pen { stroke: Some(colour.to_string()), width, dash: &[], fill: None, text: None, alpha: None }
    }

    /// A plain fill of `colour`.
    pub fn filled(colour: &str) -> Pen {
        Pen { stroke: None, width: 1.0, dash: &[], fill: Some(colour.to_string()), text: None, alpha: None }
    }

    /// The colour of the pen's text (`pen.text || pen.stroke` in `render.js`).
    pub fn text_colour(&self) -> &str {
        self.text.or(self.stroke.as_deref()).unwrap_or("#111827")
    }

    /// Fill, stroke, dashes and opacity as SVG attributes; a fill only for
    /// closed shapes, as the canvas fills them.
    pub fn attrs(&self, closed: bool) -> String {
        let fill = self.fill.as_deref().filter(|_| closed).unwrap_or("none");
        let mut a = format!("fill=\"{fill}\"");
        if let Some(s) = &self.stroke {
            push(&mut a, format_args!(" stroke=\"{s}\" stroke-width=\"{}\"", f(self.width)));
            if !self.dash.is_empty() {
                let d: Vec<String> = self.dash.iter().map(|v| f(*v)).collect();
                push(&mut a, format_args!(" stroke-dasharray=\"{}\"", d.join(" ")));
            }
        }
        if let Some(o) = self.alpha {
            push(&mut a, format_args!(" opacity=\"{}\"", f(o)));
        }
        a
    }
}
