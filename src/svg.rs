//! A display list as a standalone SVG document: `screwcut svg` and the web
//! app's SVG export write what the view shows ([`crate::draw`] decides it;
//! this only writes it down).
//!
//! The page is `width × height` px with `viewBox="0 0 width height"`; shapes
//! are clipped to it. Fonts are named by the drawings' family list, covering
//! Latin, Greek and CJK; the background is white and the document has a
//! title: it prints as it shows.

use std::fmt::Write;

use crate::diagram::scene::{Anchor, Scene, ViewKind};
use crate::draw::{DisplayList, FONT_FAMILY, FONT_SIZE, Op, Pen, View, display};

/// The scene drawn in `view` as an SVG document.
pub fn svg(scene: &Scene, view: &View) -> String {
    write(&display(scene, view))
}

/// The display list as an SVG document.
pub fn write(list: &DisplayList) -> String {
    let mut body = String::new();
    for op in &list.ops {
        match op {
            Op::Paths { pen, closed, points, starts } => {
                let mut d = String::new();
                for (k, &s) in starts.iter().enumerate() {
                    let e = starts.get(k + 1).copied().unwrap_or(points.len());
                    for (j, p) in points[s..e].iter().enumerate() {
                        push(&mut d, format_args!("{}{} {}", if j == 0 { 'M' } else { 'L' }, f(p[0]), f(p[1])));
                    }
                    if *closed {
                        d.push('Z');
                    }
                }
                push(&mut body, format_args!("<path d=\"{d}\" {}/>\n", attrs(&list.pens[*pen], *closed)));
            }
            Op::Circle { pen, center, r } => {
                let a = attrs(&list.pens[*pen], true);
                push(
                    &mut body,
                    format_args!("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {a}/>\n", f(center[0]), f(center[1]), f(*r)),
                );
            }
            Op::Text { pen, halo, at, text, anchor, angle } => {
                let (fill, halo) = (&list.pens[*pen], &list.pens[*halo]);
                let rot = if *angle != 0.0 {
                    format!(" transform=\"rotate({} {} {})\"", f(*angle), f(at[0]), f(at[1]))
                } else {
                    String::new()
                };
                let opacity = if fill.alpha < 1.0 { format!(" opacity=\"{}\"", f(fill.alpha)) } else { String::new() };
                push(
                    &mut body,
                    format_args!(
                        "<text x=\"{}\" y=\"{}\" text-anchor=\"{}\" dominant-baseline=\"central\"{rot}{opacity} fill=\"{}\" stroke=\"{}\" stroke-width=\"{}\" paint-order=\"stroke\">{}</text>\n",
                        f(at[0]),
                        f(at[1]),
                        anchor_name(*anchor),
                        fill.fill.as_deref().unwrap_or("#111827"),
                        halo.stroke.as_deref().unwrap_or("none"),
                        f(halo.width),
                        escape(text)
                    ),
                );
            }
        }
    }
    document(list, &body)
}

/// The document around `body`: background, title, clip.
fn document(list: &DisplayList, body: &str) -> String {
    let (ws, hs) = (f(list.width), f(list.height));
    let mut doc = String::with_capacity(body.len() + 768);
    doc.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    push(
        &mut doc,
        format_args!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{ws}\" height=\"{hs}\" viewBox=\"0 0 {ws} {hs}\" font-family=\"{}\" font-size=\"{}\">\n",
            FONT_FAMILY.replace('"', "'"),
            f(FONT_SIZE)
        ),
    );
    push(&mut doc, format_args!("<title>screwcut: {}</title>\n", title(list.view)));
    push(&mut doc, format_args!("<rect x=\"0\" y=\"0\" width=\"{ws}\" height=\"{hs}\" fill=\"white\"/>\n"));
    // The id names the drawing, so that several inlined in one HTML page never take another's clip.
    let id = format!("screwcut-{}-{:016x}", title(list.view).replace(' ', "-"), fnv(body));
    push(
        &mut doc,
        format_args!(
            "<defs><clipPath id=\"{id}\"><rect x=\"0\" y=\"0\" width=\"{ws}\" height=\"{hs}\"/></clipPath></defs>\n"
        ),
    );
    push(&mut doc, format_args!("<g stroke-linejoin=\"round\" clip-path=\"url(#{id})\">\n"));
    doc.push_str(body);
    doc.push_str("</g>\n</svg>\n");
    doc
}

/// Fill (of closed shapes only), stroke, dashes and opacity as SVG attributes.
fn attrs(pen: &Pen, closed: bool) -> String {
    let fill = pen.fill.as_deref().filter(|_| closed).unwrap_or("none");
    let mut a = format!("fill=\"{fill}\"");
    if let Some(s) = &pen.stroke {
        push(&mut a, format_args!(" stroke=\"{s}\" stroke-width=\"{}\"", f(pen.width)));
        if !pen.dash.is_empty() {
            let d: Vec<String> = pen.dash.iter().map(|v| f(*v)).collect();
            push(&mut a, format_args!(" stroke-dasharray=\"{}\"", d.join(" ")));
        }
    }
    if pen.alpha < 1.0 {
        push(&mut a, format_args!(" opacity=\"{}\"", f(pen.alpha)));
    }
    a
}

/// FNV-1a of `s`.
fn fnv(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
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

/// The SVG `text-anchor` value.
fn anchor_name(a: Anchor) -> &'static str {
    match a {
        Anchor::Start => "start",
        Anchor::Middle => "middle",
        Anchor::End => "end",
    }
}

/// Appends `s` to `out` (a `String` never fails).
fn push(out: &mut String, s: std::fmt::Arguments) {
    let _ = out.write_fmt(s);
}
