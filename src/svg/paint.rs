//! The painter: scene items → SVG elements at a transform, as `drawScene`
//! in `www/src/render.js` draws them on the canvas: paths of one pen
//! together (one element per pen, in the order the pens first appear; a
//! path that repeats one of its pen adds no ink and is left out, as is one
//! wholly off the page), then the other shapes in item order, each label
//! where it was placed, with its dimension line, arrowheads and halo.

use std::collections::{HashMap, HashSet};

use super::labels::LINE;
use super::pens::{Pen, pen_of};
use super::{FONT_FAMILY, FONT_SIZE, Placed, Transform, escape, f, push, title};
use crate::diagram::scene::{Anchor, Glyph, Item, Pt, Scene, Shape, Style};

/// Paths wholly this far off the page are left out.
const CULL: f64 = 12.0;
/// The halo behind a label's text.
const HALO: &str = "rgba(255,255,255,0.85)";

struct Painter<'a> {
    xf: &'a Transform,
    out: String,
}

/// The document: background, clip, paths by pen, the other shapes and labels.
pub(super) fn document(scene: &Scene, xf: &Transform, placed: &[Placed], (w, h): (f64, f64)) -> String {
    let mut p = Painter { xf, out: String::new() };
    p.paths(scene, (w, h));
    let by_item: HashMap<usize, &Placed> = placed.iter().map(|l| (l.item, l)).collect();
    for (i, item) in scene.items.iter().enumerate() {
        p.item(item, by_item.get(&i).copied());
    }
    let (ws, hs) = (f(w), f(h));
    let mut doc = String::with_capacity(p.out.len() + 768);
    doc.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    push(
        &mut doc,
        format_args!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{ws}\" height=\"{hs}\" viewBox=\"0 0 {ws} {hs}\" font-family=\"{FONT_FAMILY}\" font-size=\"{}\">\n",
            f(FONT_SIZE)
        ),
    );
    push(&mut doc, format_args!("<title>screwcut: {}</title>\n", title(scene.view)));
    push(&mut doc, format_args!("<rect x=\"0\" y=\"0\" width=\"{ws}\" height=\"{hs}\" fill=\"white\"/>\n"));
    // The id names the drawing, so that several inlined in one HTML page never take another's clip.
    let id = format!("screwcut-{}-{:016x}", title(scene.view).replace(' ', "-"), fnv(&p.out));
    push(
        &mut doc,
        format_args!(
            "<defs><clipPath id=\"{id}\"><rect x=\"0\" y=\"0\" width=\"{ws}\" height=\"{hs}\"/></clipPath></defs>\n"
        ),
    );
    push(&mut doc, format_args!("<g stroke-linejoin=\"round\" clip-path=\"url(#{id})\">\n"));
    doc.push_str(&p.out);
    doc.push_str("</g>\n</svg>\n");
    doc
}

/// FNV-1a of `s`.
fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// The pen a path goes with: style, role and shape; an area's pass and thread too (a colour each).
type BatchKey = (u32, u8, bool, Option<(u32, u32)>);

fn batch_key(item: &Item, closed: bool) -> BatchKey {
    let role = match item.role {
        None => 0,
        Some(crate::thread::Role::Rough) => 1,
        Some(crate::thread::Role::Finish) => 2,
        Some(crate::thread::Role::Spring) => 3,
    };
    let area = (item.style == Style::Area).then(|| (item.thread.map_or(0, |t| t + 1), item.pass.map_or(0, |p| p + 1)));
    (item.style.code(), role, closed, area)
}

/// One pen's paths: the first item (its pen), the path data, the subpaths seen.
struct Batch {
    key: BatchKey,
    first: usize,
    d: String,
    seen: HashSet<String>,
}

impl Painter<'_> {
    /// Every polyline and polygon, one path element per pen.
    fn paths(&mut self, scene: &Scene, (w, h): (f64, f64)) {
        let mut batches: Vec<Batch> = Vec::new();
        for (i, item) in scene.items.iter().enumerate() {
            let (points, closed) = match &item.shape {
                Shape::Polyline { points } => (points, false),
                Shape::Polygon { points } => (points, true),
                _ => continue,
            };
            let pts: Vec<Pt> = points.iter().map(|p| self.xf.at(*p)).collect();
            let off = |k: usize, lo: f64, hi: f64| pts.iter().all(|p| p[k] < lo) || pts.iter().all(|p| p[k] > hi);
            if pts.len() < 2 || off(0, -CULL, w + CULL) || off(1, -CULL, h + CULL) {
                continue;
            }
            let d = path_data(&pts, closed);
            let key = batch_key(item, closed);
            let b = match batches.iter().position(|b| b.key == key) {
                Some(k) => &mut batches[k],
                None => {
                    batches.push(Batch { key, first: i, d: String::new(), seen: HashSet::new() });
                    batches.last_mut().expect("just pushed")
                }
            };
            if b.seen.insert(d.clone()) {
                b.d.push_str(&d);
            }
        }
        for b in batches {
            let attrs = pen_of(&scene.items[b.first]).attrs(b.key.2);
            push(&mut self.out, format_args!("<path d=\"{}\" {attrs}/>\n", b.d));
        }
    }

    fn item(&mut self, item: &Item, placed: Option<&Placed>) {
        let pen = pen_of(item);
        match &item.shape {
            Shape::Polyline { .. } | Shape::Polygon { .. } => {}
            Shape::Circle { center, radius } => {
                let [x, y] = self.xf.at(*center);
                let r = (radius * self.xf.sx).max(0.0);
                let a = pen.attrs(true);
                push(&mut self.out, format_args!("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {a}/>\n", f(x), f(y), f(r)));
            }
            Shape::Arrow { from, to } => self.arrow(self.xf.at(*from), self.xf.at(*to), &pen),
            Shape::Marker { at, glyph } => self.marker(self.xf.at(*at), *glyph, &pen),
            Shape::Dim { a, b, .. } => {
                if let Some(l) = placed {
                    self.dimension(self.xf.at(*a), self.xf.at(*b), item.style == Style::Diameter, l, &pen);
                    self.label(l, &pen);
                }
            }
            Shape::Text { .. } => {
                if let Some(l) = placed {
                    if let Some([x0, y0, x1, y1]) = l.lead {
                        let stroke = pen.stroke.clone().unwrap_or_else(|| pen.text_colour().to_string());
                        let lead = Pen { alpha: Some(0.8), ..Pen::thin(&stroke, 0.7) };
                        self.path(&[[x0, y0], [x1, y1]], false, &lead);
                    }
                    self.label(l, &pen);
                }
            }
        }
    }

    /// A path element of page points.
    fn path(&mut self, pts: &[Pt], closed: bool, pen: &Pen) {
        let d = path_data(pts, closed);
        push(&mut self.out, format_args!("<path d=\"{d}\" {}/>\n", pen.attrs(closed)));
    }

    /// An arrow: its line in the pen, a filled head of the pen's stroke at `b`.
    fn arrow(&mut self, a: Pt, b: Pt, pen: &Pen) {
        self.path(&[a, b], false, pen);
        let t = (b[1] - a[1]).atan2(b[0] - a[0]);
        let (l, s) = (9.0, 0.42);
        let head = [
            [b[0] - l * (t - s).cos(), b[1] - l * (t - s).sin()],
            b,
            [b[0] - l * (t + s).cos(), b[1] - l * (t + s).sin()],
        ];
        let head_pen = Pen { fill: pen.stroke.clone(), dash: &[], ..pen.clone() };
        self.path(&head, true, &head_pen);
    }

    fn marker(&mut self, [x, y]: Pt, glyph: Glyph, pen: &Pen) {
        let stroke = pen.stroke.as_deref().unwrap_or("#374151");
        match glyph {
            Glyph::Dot => {
                let a = Pen::filled(stroke).attrs(true);
                push(&mut self.out, format_args!("<circle cx=\"{}\" cy=\"{}\" r=\"3\" {a}/>\n", f(x), f(y)));
            }
            Glyph::Bar => self.path(&[[x, y - 6.0], [x, y + 6.0]], false, &Pen::thin(stroke, 2.0)),
            Glyph::Cross => {
                let d = format!(
                    "{}{}",
                    path_data(&[[x - 4.0, y - 4.0], [x + 4.0, y + 4.0]], false),
                    path_data(&[[x - 4.0, y + 4.0], [x + 4.0, y - 4.0]], false)
                );
                push(&mut self.out, format_args!("<path d=\"{d}\" {}/>\n", Pen::thin(stroke, 1.6).attrs(false)));
            }
        }
    }

    /// A placed dimension: extension lines, its line and arrowheads. A half
    /// dimension (of a diameter, from the axis `a`) has one arrowhead, at the
    /// diameter `b`; its line runs towards the axis as far as it was placed.
    fn dimension(&mut self, a: Pt, b: Pt, half: bool, l: &Placed, pen: &Pen) {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = dx.hypot(dy);
        if len.is_nan() || len <= 1e-9 {
            return;
        }
        let u = [dx / len, dy / len];
        let n = [u[1], -u[0]];
        let o = l.off;
        let sgn = if o >= 0.0 { 1.0 } else { -1.0 };
        let at = |p: Pt, k: f64| [p[0] + n[0] * k, p[1] + n[1] * k];
        let (line, ends): ((Pt, Pt), &[Pt]) = if half {
            let s = at(b, o);
            ((s, [s[0] - u[0] * l.len, s[1] - u[1] * l.len]), &[b])
        } else {
            ((at(a, o), at(b, o)), &[a, b])
        };
        let stroke = pen.stroke.clone().unwrap_or_else(|| "#374151".into());
        if o.abs() > 3.0 {
            for &p in ends {
                self.path(&[at(p, 2.0 * sgn), at(p, o + 4.0 * sgn)], false, &Pen::thin(&stroke, 0.8));
            }
        }
        let (p, q) = line;
        self.path(&[p, q], false, pen);
        let head_pen = Pen::filled(&stroke);
        let mut head = |x: Pt, dir: f64| {
            let (lh, wh) = (7.0, 2.6);
            let base = [x[0] - u[0] * lh * dir, x[1] - u[1] * lh * dir];
            self.path(&[x, at(base, wh), at(base, -wh)], true, &head_pen);
        };
        if half {
            head(p, 1.0);
        } else if (q[0] - p[0]).hypot(q[1] - p[1]) > 20.0 {
            head(p, -1.0);
            head(q, 1.0);
        } else {
            head(p, 1.0);
            head(q, -1.0);
        }
    }

    /// A label's text in its box, with a halo: one line centred (rotated by
    /// its angle), or several lines a line apart, lined up as placed.
    fn label(&mut self, l: &Placed, pen: &Pen) {
        let [x0, y0, x1, y1] = l.bounds;
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        let x = match l.align {
            Anchor::Start => x0 + 2.0,
            Anchor::End => x1 - 2.0,
            Anchor::Middle => cx,
        };
        let n = l.lines.len() as f64;
        let colour = pen.text_colour().to_string();
        for (k, line) in l.lines.iter().enumerate() {
            if line.is_empty() {
                continue;
            }
            let y = cy + (k as f64 - (n - 1.0) / 2.0) * LINE;
            let rot = if l.angle != 0.0 {
                format!(" transform=\"rotate({} {} {})\"", f(l.angle), f(x), f(y))
            } else {
                String::new()
            };
            push(
                &mut self.out,
                format_args!(
                    "<text x=\"{}\" y=\"{}\" text-anchor=\"{}\" dominant-baseline=\"central\"{rot} fill=\"{colour}\" stroke=\"{HALO}\" stroke-width=\"3\" paint-order=\"stroke\">{}</text>\n",
                    f(x),
                    f(y),
                    l.align.svg(),
                    escape(line)
                ),
            );
        }
    }
}

/// SVG path data of page points (`Z` closing a polygon).
fn path_data(pts: &[Pt], closed: bool) -> String {
    let mut d = String::new();
    for (k, p) in pts.iter().enumerate() {
        push(&mut d, format_args!("{}{} {}", if k == 0 { 'M' } else { 'L' }, f(p[0]), f(p[1])));
    }
    if closed {
        d.push('Z');
    }
    d
}
