//! The display list: what a view shows, resolved — pens, paths in page
//! coordinates, circles and texts with their halos, in painting order. The
//! canvas painter (`www/src/view/paint.js`) and the SVG writer
//! (`svg`) execute it and decide nothing.

use std::collections::HashMap;
use std::hash::Hasher;

use serde::Serialize;

use super::{Placed, Transform};
use crate::diagram::scene::{Anchor, Pt, ViewKind};
use crate::hash::{BuildKeyHasher, KeyHasher};

/// A resolved pen: a stroke (colour, width, dashes), a fill of closed shapes and an opacity.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Pen {
    /// Stroke colour (CSS), none for a fill only.
    pub stroke: Option<String>,
    /// Stroke width, px.
    pub width: f64,
    /// Dash pattern, px (empty: solid).
    pub dash: Vec<f64>,
    /// Fill colour of closed shapes and text (CSS).
    pub fill: Option<String>,
    /// Opacity, 0 to 1.
    pub alpha: f64,
}

impl Pen {
    /// A solid stroke of `colour` and `width`.
    pub fn stroke(colour: &str, width: f64) -> Pen {
        Pen { stroke: Some(colour.to_string()), width, dash: Vec::new(), fill: None, alpha: 1.0 }
    }

    /// A fill of `colour`.
    pub fn fill(colour: &str) -> Pen {
        Pen { stroke: None, width: 1.0, dash: Vec::new(), fill: Some(colour.to_string()), alpha: 1.0 }
    }

    /// The same pen at opacity `alpha` times its own.
    pub fn faded(mut self, alpha: f64) -> Pen {
        self.alpha *= alpha;
        self
    }
}

/// One painting operation, in page pixels.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "op", rename_all = "snake_case")]
pub enum Op {
    /// Subpaths drawn as one path with one pen: `points[starts[k]..starts[k + 1]]`
    /// is subpath `k`; each closed when `closed` (and then filled).
    Paths { pen: usize, closed: bool, points: Vec<Pt>, starts: Vec<usize> },
    /// A circle (filled when its pen fills).
    Circle { pen: usize, center: Pt, r: f64 },
    /// A line of text centred vertically on `at`, lined up by `anchor`,
    /// rotated by `angle` degrees about `at`, filled with its pen's fill over
    /// a halo stroked with pen `halo`.
    Text { pen: usize, halo: usize, at: Pt, text: String, anchor: Anchor, angle: f64 },
}

/// A view, resolved: paint `ops` in order with `pens` on a `width × height` page.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DisplayList {
    /// Which drawing it is.
    pub view: ViewKind,
    /// Page width, px.
    pub width: f64,
    /// Page height, px.
    pub height: f64,
    /// The world → page transform it was made at.
    pub transform: Transform,
    /// Whether it is the last good drawing shown greyed (its pens are grey and faded).
    pub stale: bool,
    /// The pens the operations name by index.
    pub pens: Vec<Pen>,
    /// The operations, in painting order.
    pub ops: Vec<Op>,
    /// The labels as placed (the scene item each belongs to, its text and box).
    pub labels: Vec<Placed>,
    /// The scene items whose labels found no place.
    pub dropped: Vec<usize>,
    /// Where a zoom without a pointer (the keyboard's) centres, on the page:
    /// the middle of what is marked, else of the drawing's focus.
    pub anchor: Pt,
}

/// Builds a display list: pens kept once each; a stale list's pens greyed and faded.
pub(super) struct Builder {
    pub list: DisplayList,
    /// The first pen of each [`pen_key`].
    index: HashMap<u64, usize, BuildKeyHasher>,
}

/// A hash of every field of `pen` (numbers by their bits).
fn pen_key(pen: &Pen) -> u64 {
    let Pen { stroke, width, dash, fill, alpha } = pen;
    let mut h = KeyHasher::default();
    let mut text = |t: &Option<String>| match t {
        Some(t) => {
            h.write_u8(1);
            h.write(t.as_bytes());
        }
        None => h.write_u8(0),
    };
    text(stroke);
    text(fill);
    for v in [*width, *alpha].iter().chain(dash) {
        h.write_u64(v.to_bits());
    }
    h.write_usize(dash.len());
    h.finish()
}

/// How much a stale drawing's pens are faded.
const STALE_ALPHA: f64 = 0.35;

impl Builder {
    pub fn new(view: ViewKind, (width, height): (f64, f64), transform: Transform, stale: bool) -> Builder {
        let list = DisplayList {
            view,
            width,
            height,
            transform,
            stale,
            pens: Vec::new(),
            ops: Vec::new(),
            labels: Vec::new(),
            dropped: Vec::new(),
            anchor: [width / 2.0, height / 2.0],
        };
        Builder { list, index: HashMap::default() }
    }

    /// The index of `pen` (greyed and faded in a stale list).
    pub fn pen(&mut self, pen: Pen) -> usize {
        let pen = if self.list.stale {
            Pen {
                stroke: pen.stroke.as_deref().map(grey),
                fill: pen.fill.as_deref().map(grey),
                alpha: pen.alpha * STALE_ALPHA,
                ..pen
            }
        } else {
            pen
        };
        let key = pen_key(&pen);
        if let Some(&k) = self.index.get(&key) {
            if self.list.pens[k] == pen {
                return k;
            }
        }
        self.list.pens.push(pen);
        let k = self.list.pens.len() - 1;
        self.index.entry(key).or_insert(k);
        k
    }

    /// Adds one path of page points.
    pub fn path(&mut self, pts: &[Pt], closed: bool, pen: Pen) {
        if pts.len() < 2 {
            return;
        }
        let pen = self.pen(pen);
        self.list.ops.push(Op::Paths { pen, closed, points: pts.to_vec(), starts: vec![0] });
    }

    /// Adds a circle.
    pub fn circle(&mut self, center: Pt, r: f64, pen: Pen) {
        let pen = self.pen(pen);
        self.list.ops.push(Op::Circle { pen, center, r: r.max(0.0) });
    }

    /// Adds a line of text over a halo of `halo` (a colour).
    pub fn text(&mut self, at: Pt, text: &str, colour: &str, halo: &str, anchor: Anchor, angle: f64) {
        let pen = self.pen(Pen::fill(colour));
        let halo = self.pen(Pen::stroke(halo, 3.0));
        self.list.ops.push(Op::Text { pen, halo, at, text: text.to_string(), anchor, angle });
    }
}

/// `colour` (`#rgb`, `#rrggbb`, `rgb(a)()`, `hsl(a)()`) through a grayscale
/// filter: each channel 0.2126 R + 0.7152 G + 0.0722 B, alpha kept; another form as it is.
pub fn grey(colour: &str) -> String {
    let Some([r, g, b, a]) = rgba(colour) else { return colour.to_string() };
    let v = (0.2126 * r + 0.7152 * g + 0.0722 * b).round();
    if a >= 1.0 { format!("rgb({v},{v},{v})") } else { format!("rgba({v},{v},{v},{a})") }
}

/// `[r, g, b, a]` (0–255, alpha 0–1) of a colour in one of the forms the pens use.
fn rgba(c: &str) -> Option<[f64; 4]> {
    if let Some(hex) = c.strip_prefix('#') {
        let full: String = match hex.len() {
            3 => hex.chars().flat_map(|ch| [ch, ch]).collect(),
            6 => hex.to_string(),
            _ => return None,
        };
        let ch = |k: usize| u8::from_str_radix(full.get(k..k + 2)?, 16).ok().map(f64::from);
        return Some([ch(0)?, ch(2)?, ch(4)?, 1.0]);
    }
    let (kind, rest) = c.split_once('(')?;
    let v: Vec<f64> = rest
        .strip_suffix(')')?
        .split(',')
        .map(|x| x.trim().trim_end_matches('%').parse().ok())
        .collect::<Option<_>>()?;
    if v.len() < 3 {
        return None;
    }
    let a = v.get(3).copied().unwrap_or(1.0);
    match kind.trim_end_matches('a') {
        "rgb" => Some([v[0], v[1], v[2], a]),
        "hsl" => {
            // CSS Color 4's hsl → rgb.
            let h = v[0].rem_euclid(360.0) / 30.0;
            let (s, l) = (v[1] / 100.0, v[2] / 100.0);
            let f = |n: f64| {
                let k = (n + h) % 12.0;
                255.0 * (l - s * l.min(1.0 - l) * (k - 3.0).min(9.0 - k).clamp(-1.0, 1.0))
            };
            Some([f(0.0), f(8.0), f(4.0), a])
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::grey;

    #[test]
    fn greys_are_the_luminance_of_the_colour() {
        // 0.2126·37 + 0.7152·99 + 0.0722·235 = 95.6 (#2563eb, the cut pen).
        assert_eq!(grey("#2563eb"), "rgb(96,96,96)");
        assert_eq!(grey("#fff"), "rgb(255,255,255)");
        assert_eq!(grey("rgba(234,179,8,0.22)"), "rgba(178,178,178,0.22)");
        // hsl(200,75%,62%) is rgb(85.5,181.4,231.3): 0.2126·85.5 + 0.7152·181.4 + 0.0722·231.3 = 164.6.
        assert_eq!(grey("hsla(200,75%,62%,0.6)"), "rgba(165,165,165,0.6)");
        assert_eq!(grey("red"), "red");
    }
}
