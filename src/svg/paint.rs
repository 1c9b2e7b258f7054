//! The painter: scene items → SVG elements, as `render.js` draws them, with
//! the page extent for the viewBox: the fitted drawing area grown to hold
//! every label (estimated). Shapes are clipped to the viewBox, as the app's
//! canvas clips them: motions far from the threads (a return to a tool
//! change point) do not shrink the drawing to a corner of the page.

use super::{FONT_FAMILY, Fit, MAX_ANNOTATED, Options, Pen, english, escape, f, fill, pen, push, stroke_of, title};
use crate::diagram::scene::{Item, Label, Rect, Scene, Shape, Style};

/// Average advance of a character as a share of the font size (Latin, digits).
const CHAR_WIDTH: f64 = 0.6;

/// Estimated width of text `s` at `font_size` px: a full em for CJK and
/// other wide characters (U+2E80 and above), [`CHAR_WIDTH`] for the rest.
pub fn measure(s: &str, font_size: f64) -> f64 {
    s.chars().map(|c| if c >= '\u{2E80}' { 1.0 } else { CHAR_WIDTH }).sum::<f64>() * font_size
}

struct Painter<'a> {
    o: &'a Options,
    fit: Fit,
    out: String,
    /// Page extent of everything drawn.
    extent: Rect,
    /// Boxes of the texts placed so far (a text that would overprint one is skipped).
    placed: Vec<[f64; 4]>,
}

/// The document: background, paths by pen, the other shapes, texts.
pub(super) fn document(scene: &Scene, o: &Options) -> String {
    let fit = if scene.focus.is_empty() { scene.bounds } else { scene.focus };
    let view = o.view.unwrap_or(fit).or_unit();
    let mut p = Painter { o, fit: Fit::new(view, o), out: String::new(), extent: Rect::EMPTY, placed: Vec::new() };
    p.extent.add([0.0, 0.0]);
    p.extent.add([o.width, o.height]);
    p.paths(scene);
    let annotated = {
        let mut threads: Vec<u32> = scene
            .items
            .iter()
            .filter(|i| matches!(i.shape, Shape::Dim { .. } | Shape::Text { .. }))
            .filter_map(|i| i.thread)
            .collect();
        threads.sort_unstable();
        threads.dedup();
        threads.len()
    };
    for item in &scene.items {
        let text_like = matches!(item.shape, Shape::Dim { .. } | Shape::Text { .. });
        if annotated > MAX_ANNOTATED && text_like && item.thread.is_some_and(|t| t as usize != o.thread) {
            continue;
        }
        p.item(item);
    }
    let m = 4.0;
    let e = p.extent;
    let (x, y, w, h) = (e.x0 - m, e.y0 - m, e.width() + 2.0 * m, e.height() + 2.0 * m);
    let mut doc = String::with_capacity(p.out.len() + 512);
    doc.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    push(
        &mut doc,
        format_args!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"{} {} {} {}\" font-family=\"{FONT_FAMILY}\" font-size=\"{}\">\n",
            f(w),
            f(h),
            f(x),
            f(y),
            f(w),
            f(h),
            f(o.font_size)
        ),
    );
    push(&mut doc, format_args!("<title>screwcut: {}</title>\n", title(scene.view)));
    push(
        &mut doc,
        format_args!("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n", f(x), f(y), f(w), f(h)),
    );
    // Shapes beyond the page are clipped; the id names the rectangle, so that
    // several drawings inlined in one HTML page never take another's clip.
    let id = format!("screwcut-page-{}-{}-{}-{}", f(x), f(y), f(w), f(h)).replace(['.', ' '], "_");
    push(
        &mut doc,
        format_args!(
            "<defs><clipPath id=\"{id}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath></defs>\n",
            f(x),
            f(y),
            f(w),
            f(h)
        ),
    );
    push(&mut doc, format_args!("<g stroke-linejoin=\"round\" clip-path=\"url(#{id})\">\n"));
    doc.push_str(&p.out);
    doc.push_str("</g>\n</svg>\n");
    doc
}

/// The pen of a batch of paths: style, role, closed, and the pass of an area.
type BatchKey = (u32, u8, bool, u32);

/// The batch a path goes in: its pen (style, role, shape; an area per pass).
fn batch_key(item: &Item, closed: bool) -> BatchKey {
    let role = match item.role {
        None => 0,
        Some(crate::thread::Role::Rough) => 1,
        Some(crate::thread::Role::Finish) => 2,
        Some(crate::thread::Role::Spring) => 3,
    };
    let pass = if item.style == Style::Area { item.pass.unwrap_or(0) + 1 + 1000 * item.thread.unwrap_or(0) } else { 0 };
    (item.style.code(), role, closed, pass)
}

impl Painter<'_> {
    /// Every polyline and polygon, one path per pen in the order the pens first appear.
    fn paths(&mut self, scene: &Scene) {
        let mut batches: Vec<(BatchKey, usize, String)> = Vec::new();
        for (i, item) in scene.items.iter().enumerate() {
            let (points, closed) = match &item.shape {
                Shape::Polyline { points } => (points, false),
                Shape::Polygon { points } => (points, true),
                _ => continue,
            };
            if points.len() < 2 {
                continue;
            }
            let mut d = String::new();
            for (k, p) in points.iter().enumerate() {
                let (x, y) = self.fit.at(*p);
                push(&mut d, format_args!("{}{} {}", if k == 0 { 'M' } else { 'L' }, f(x), f(y)));
            }
            if closed {
                d.push('Z');
            }
            let key = batch_key(item, closed);
            match batches.iter_mut().find(|b| b.0 == key) {
                Some(b) => b.2.push_str(&d),
                None => batches.push((key, i, d)),
            }
        }
        for (key, first, d) in batches {
            let item = &scene.items[first];
            let attrs = self.style(item, key.2);
            push(&mut self.out, format_args!("<path d=\"{d}\" {attrs}/>\n"));
        }
    }

    /// Whether page point (x, y) is in the fitted drawing area: a label anchored outside it is not drawn (the app's canvas would not show it).
    fn in_frame(&self, x: f64, y: f64) -> bool {
        (0.0..=self.o.width).contains(&x) && (0.0..=self.o.height).contains(&y)
    }

    /// The fill and stroke attributes of an item's pen.
    fn style(&self, item: &Item, closed: bool) -> String {
        let p = pen(item.style);
        let fill = if item.style == Style::Area {
            Some(super::area_colour(item.pass.unwrap_or(0), item.role))
        } else {
            p.fill.map(str::to_string)
        };
        attrs(&p, fill.filter(|_| closed), stroke_of(item, &p))
    }

    fn item(&mut self, item: &Item) {
        let p = pen(item.style);
        let stroke = stroke_of(item, &p);
        match &item.shape {
            Shape::Polyline { .. } | Shape::Polygon { .. } => {}
            Shape::Circle { center, radius } => {
                let (x, y) = self.fit.at(*center);
                let r = (radius * self.fit.sx).max(0.0);
                let a = self.style(item, true);
                push(&mut self.out, format_args!("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {a}/>\n", f(x), f(y), f(r)));
            }
            Shape::Arrow { from, to } => {
                let (a, b) = (self.fit.at(*from), self.fit.at(*to));
                self.arrow(a, b, &p, stroke.as_deref().unwrap_or("#374151"));
            }
            Shape::Dim { a, b, offset, label } => {
                let text = self.label(label);
                let (a, b) = (self.fit.at(*a), self.fit.at(*b));
                self.dimension(a, b, *offset, &text, &p);
            }
            Shape::Text { at, label, anchor, dx, dy } => {
                let s = self.label(label);
                if s.is_empty() {
                    return;
                }
                let (x, y) = self.fit.at(*at);
                if !self.in_frame(x, y) {
                    return;
                }
                let (x, y) = (x + dx, y - dy);
                let w = self.measure(&s);
                let x0 = match anchor.svg() {
                    "start" => x,
                    "end" => x - w,
                    _ => x - w / 2.0,
                };
                let bx = [x0, y - 7.0, x0 + w, y + 7.0];
                if self.placed.iter().any(|b| bx[0] < b[2] && b[0] < bx[2] && bx[1] < b[3] && b[1] < bx[3]) {
                    return;
                }
                self.placed.push(bx);
                let colour = p.text.or(p.stroke).unwrap_or("#111827");
                self.text(x, y, &s, colour, false, anchor.svg(), "middle", 0.0);
            }
            Shape::Marker { at, glyph } => {
                let (x, y) = self.fit.at(*at);
                self.marker(x, y, glyph.code(), stroke.as_deref().unwrap_or("#374151"));
            }
        }
    }

    /// A label's text: its key's template (the options', else English) with the value.
    fn label(&self, l: &Label) -> String {
        if l.key.is_empty() {
            return l.value.clone();
        }
        let own = self.o.labels.iter().find(|(k, _)| k == l.key).map(|(_, t)| t.as_str());
        match own.or_else(|| english(l.key)) {
            Some(t) => fill(t, &l.value),
            None => l.value.clone(),
        }
    }

    fn measure(&self, s: &str) -> f64 {
        measure(s, self.o.font_size)
    }

    /// A text and its estimated extent (rotated by `angle`, −90 or 0).
    #[allow(clippy::too_many_arguments)]
    fn text(&mut self, x: f64, y: f64, s: &str, colour: &str, halo: bool, anchor: &str, baseline: &str, angle: f64) {
        let (w, h) = (self.measure(s), self.o.font_size * 1.25);
        let (ax0, ax1) = match anchor {
            "start" => (0.0, w),
            "end" => (-w, 0.0),
            _ => (-w / 2.0, w / 2.0),
        };
        let (by0, by1, dominant) = match baseline {
            "top" => (0.0, h, "hanging"),
            "bottom" => (-h, 0.0, "text-after-edge"),
            _ => (-h / 2.0, h / 2.0, "central"),
        };
        if angle == 0.0 {
            self.extent.add([x + ax0, y + by0]);
            self.extent.add([x + ax1, y + by1]);
        } else {
            // Rotated −90°: the text runs upward from its anchor.
            self.extent.add([x + by0, y - ax1]);
            self.extent.add([x + by1, y - ax0]);
        }
        let halo = if halo { " stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\"" } else { "" };
        let rot =
            if angle != 0.0 { format!(" transform=\"rotate({} {} {})\"", f(angle), f(x), f(y)) } else { String::new() };
        push(
            &mut self.out,
            format_args!(
                "<text x=\"{}\" y=\"{}\" text-anchor=\"{anchor}\" dominant-baseline=\"{dominant}\"{rot} fill=\"{colour}\"{halo}>{}</text>\n",
                f(x),
                f(y),
                escape(s)
            ),
        );
    }

    fn line(&mut self, pts: &[(f64, f64)], closed: bool, a: &str) {
        let mut d = String::new();
        for (k, (x, y)) in pts.iter().enumerate() {
            push(&mut d, format_args!("{}{} {}", if k == 0 { 'M' } else { 'L' }, f(*x), f(*y)));
        }
        if closed {
            d.push('Z');
        }
        push(&mut self.out, format_args!("<path d=\"{d}\" {a}/>\n"));
    }

    fn arrow(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), p: &Pen, stroke: &str) {
        self.line(&[(x0, y0), (x1, y1)], false, &attrs(p, None, Some(stroke.to_string())));
        let a = (y1 - y0).atan2(x1 - x0);
        let (l, s) = (9.0, 0.42);
        let head = [
            (x1 - l * (a - s).cos(), y1 - l * (a - s).sin()),
            (x1, y1),
            (x1 - l * (a + s).cos(), y1 - l * (a + s).sin()),
        ];
        self.line(&head, true, &format!("fill=\"{stroke}\" stroke=\"{stroke}\" stroke-width=\"{}\"", f(p.width)));
    }

    fn marker(&mut self, x: f64, y: f64, glyph: u8, stroke: &str) {
        match glyph {
            0 => {
                push(
                    &mut self.out,
                    format_args!("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{stroke}\"/>\n", f(x), f(y)),
                );
            }
            1 => self.line(
                &[(x, y - 6.0), (x, y + 6.0)],
                false,
                &format!("fill=\"none\" stroke=\"{stroke}\" stroke-width=\"2\""),
            ),
            _ => {
                let a = format!("fill=\"none\" stroke=\"{stroke}\" stroke-width=\"1.6\"");
                self.line(&[(x - 4.0, y - 4.0), (x + 4.0, y + 4.0)], false, &a);
                self.line(&[(x - 4.0, y + 4.0), (x + 4.0, y - 4.0)], false, &a);
            }
        }
    }

    /// An aligned dimension: extension lines, the dimension line with its heads, the text.
    fn dimension(&mut self, (ax, ay): (f64, f64), (bx, by): (f64, f64), offset: f64, text: &str, p: &Pen) {
        let (dx, dy) = (bx - ax, by - ay);
        let len = dx.hypot(dy);
        if len.is_nan() || len <= 0.5 {
            return;
        }
        let stroke = p.stroke.unwrap_or("#374151");
        // Left of a→b in world terms is (dy, −dx) on the page (y down).
        let (nx, ny) = (dy / len, -dx / len);
        let sgn = if offset >= 0.0 { 1.0 } else { -1.0 };
        let thin = format!("fill=\"none\" stroke=\"{stroke}\" stroke-width=\"0.8\"");
        if offset.abs() > 3.0 {
            for (x, y) in [(ax, ay), (bx, by)] {
                let ext = [
                    (x + nx * 2.0 * sgn, y + ny * 2.0 * sgn),
                    (x + nx * (offset + 4.0 * sgn), y + ny * (offset + 4.0 * sgn)),
                ];
                self.line(&ext, false, &thin);
            }
        }
        let (x0, y0, x1, y1) = (ax + nx * offset, ay + ny * offset, bx + nx * offset, by + ny * offset);
        self.line(&[(x0, y0), (x1, y1)], false, &attrs(p, None, Some(stroke.to_string())));
        let (ux, uy) = (dx / len, dy / len);
        let mut head = |x: f64, y: f64, dir: f64| {
            let (l, w) = (7.0, 2.6);
            let (hx, hy) = (x - ux * l * dir, y - uy * l * dir);
            let pts = [(x, y), (hx + nx * w, hy + ny * w), (hx - nx * w, hy - ny * w)];
            self.line(&pts, true, &format!("fill=\"{stroke}\" stroke=\"none\""));
        };
        let out = if len > 20.0 { 1.0 } else { -1.0 };
        head(x0, y0, -out);
        head(x1, y1, out);
        if text.is_empty() {
            return;
        }
        // The text sits at the middle of the part of the line on the page (as the app puts it in its view).
        let (cx, cy) = visible_middle((x0, y0), (x1, y1), (self.o.width, self.o.height));
        let colour = p.text.or(p.stroke).unwrap_or("#111827");
        if nx.abs() > 0.7 {
            // A vertical dimension: the text runs along its line, reading upward.
            let baseline = if nx * sgn > 0.0 { "top" } else { "bottom" };
            self.text(cx + nx * 4.0 * sgn, cy, text, colour, true, "middle", baseline, -90.0);
        } else {
            let baseline = if ny * sgn < 0.0 { "bottom" } else { "top" };
            self.text(cx + nx * 7.0 * sgn, cy + ny * 7.0 * sgn, text, colour, true, "middle", baseline, 0.0);
        }
    }
}

/// The middle of the part of segment (x0, y0)–(x1, y1) inside the page
/// `0..w × 0..h` less a 14 px margin (the segment's middle when none of it is).
fn visible_middle((x0, y0): (f64, f64), (x1, y1): (f64, f64), (w, h): (f64, f64)) -> (f64, f64) {
    const M: f64 = 14.0;
    let (dx, dy) = (x1 - x0, y1 - y0);
    // Parametric clip: each side bounds t to one side of q / p.
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, x0 - M), (dx, w - M - x0), (-dy, y0 - M), (dy, h - M - y0)] {
        if p == 0.0 {
            if q < 0.0 {
                return ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
            }
            continue;
        }
        let r = q / p;
        if p < 0.0 {
            t0 = t0.max(r);
        } else {
            t1 = t1.min(r);
        }
    }
    if t0 > t1 {
        return ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    }
    let t = (t0 + t1) / 2.0;
    (x0 + dx * t, y0 + dy * t)
}

/// Fill, stroke, dashes and opacity of a pen.
fn attrs(p: &Pen, fill: Option<String>, stroke: Option<String>) -> String {
    let mut a = format!("fill=\"{}\"", fill.as_deref().unwrap_or("none"));
    if let Some(s) = stroke {
        push(&mut a, format_args!(" stroke=\"{s}\" stroke-width=\"{}\"", f(p.width)));
        if !p.dash.is_empty() {
            let d: Vec<String> = p.dash.iter().map(|v| f(*v)).collect();
            push(&mut a, format_args!(" stroke-dasharray=\"{}\"", d.join(" ")));
        }
    }
    if let Some(o) = p.alpha {
        push(&mut a, format_args!(" opacity=\"{}\"", f(o)));
    }
    a
}
