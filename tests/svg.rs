#![cfg(not(target_arch = "wasm32"))]
//! `svg`: every view of every example gives well-formed SVG (parsed by
//! roxmltree) whose viewBox is `0 0 width height`, with the shapes clipped
//! to it and every label inside it, none overlapping another (boxes from
//! the writer's own width estimate), in English and in Chinese, at the
//! default size and at 300 × 200. At a given transform (a view's zoom and
//! pan) the shapes are where the transform puts them and the labels are
//! placed inside the page; a stale view's pens are grey, a mark's halos lie
//! beneath the items.

mod common;
use common::plan_with;
use screwcut::Dialect;
use screwcut::diagram::scene::{Anchor, Item, Label, Scene, Shape, Style, ViewKind};
use screwcut::diagram::{side, starts, tooth};
use screwcut::draw::{LABEL_KEYS, Mark, Transform, View, display, english, label_text, measure};
use screwcut::message::Lang;
use screwcut::svg::{svg, write};

/// Height of a label's box (the app's `LINE`).
const LINE: f64 = 15.0;

/// A text of the document: its string, its box estimated as the writer estimates it, and its colour.
#[derive(Debug)]
struct Text {
    s: String,
    bounds: [f64; 4],
}

/// What a check found: the page, the texts and how many paths.
struct Checked {
    size: [f64; 2],
    texts: Vec<Text>,
    paths: usize,
}

fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().unwrap_or_else(|_| panic!("{t:?} in {s:?}")))
        .collect()
}

/// The box of a `<text>` element: the label box the writer centred it in (one line of it).
fn text_box(n: roxmltree::Node, s: &str) -> [f64; 4] {
    let a = |k| n.attribute(k).unwrap().parse::<f64>().unwrap();
    let (x, y) = (a("x"), a("y"));
    assert_eq!(n.attribute("dominant-baseline"), Some("central"));
    let w = measure(s, 12.0) + 4.0;
    if let Some(t) = n.attribute("transform") {
        assert!(t.starts_with("rotate(-90 "), "{t}");
        return [x - LINE / 2.0, y - w / 2.0, x + LINE / 2.0, y + w / 2.0];
    }
    let x0 = match n.attribute("text-anchor").unwrap() {
        "start" => x - 2.0,
        "end" => x + 2.0 - w,
        "middle" => x - w / 2.0,
        other => panic!("anchor {other}"),
    };
    [x0, y - LINE / 2.0, x0 + w, y + LINE / 2.0]
}

/// Parses `doc` and checks its structure: the page, the clip, finite numbers.
fn check(doc: &str) -> Checked {
    let xml = roxmltree::Document::parse(doc).unwrap_or_else(|e| panic!("not XML: {e}\n{doc}"));
    let root = xml.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.tag_name().namespace(), Some("http://www.w3.org/2000/svg"));
    let vb = numbers(root.attribute("viewBox").expect("a viewBox"));
    let [x, y, w, h] = vb[..] else { panic!("viewBox {vb:?}") };
    assert_eq!([x, y], [0.0, 0.0], "the viewBox is the page");
    assert!(w > 0.0 && h > 0.0);
    assert_eq!(numbers(root.attribute("width").unwrap()), [w]);
    assert_eq!(numbers(root.attribute("height").unwrap()), [h]);
    assert!(root.attribute("font-family").unwrap().ends_with("sans-serif"));
    assert_eq!(root.attribute("font-size"), Some("12"));
    assert!(root.children().any(|n| n.has_tag_name("title")));
    let clip = xml.descendants().find(|n| n.has_tag_name("clipPath")).expect("a clip path");
    let rect = clip.children().find(|n| n.has_tag_name("rect")).expect("a clip rectangle");
    let r = |k| rect.attribute(k).unwrap().parse::<f64>().unwrap();
    assert_eq!([r("x"), r("y"), r("width"), r("height")], [0.0, 0.0, w, h], "the clip is the page");
    let group = root.children().find(|n| n.has_tag_name("g")).expect("the drawing group");
    assert_eq!(group.attribute("clip-path"), Some(format!("url(#{})", clip.attribute("id").unwrap()).as_str()));
    let (mut texts, mut paths) = (Vec::new(), 0);
    for n in xml.descendants().filter(|n| n.is_element()) {
        match n.tag_name().name() {
            "path" => {
                let v = numbers(n.attribute("d").unwrap());
                assert!(v.len() >= 4 && v.len() % 2 == 0, "{:?}", n.attribute("d"));
                assert!(v.iter().all(|c| c.is_finite()));
                paths += 1;
            }
            "circle" => {
                let a = |k| n.attribute(k).unwrap().parse::<f64>().unwrap();
                assert!(a("cx").is_finite() && a("cy").is_finite() && a("r") >= 0.0);
            }
            "text" => {
                let s = n.text().unwrap_or_default().to_string();
                assert!(!s.is_empty());
                texts.push(Text { bounds: text_box(n, &s), s });
            }
            _ => {}
        }
    }
    Checked { size: [w, h], texts, paths }
}

/// What is wrong with the labels of a checked document: outside the page, overlapping.
fn faults(c: &Checked) -> Vec<String> {
    let [w, h] = c.size;
    let mut out = Vec::new();
    for t in &c.texts {
        let b = t.bounds;
        if b[0] < -0.01 || b[1] < -0.01 || b[2] > w + 0.01 || b[3] > h + 0.01 {
            out.push(format!("{:?} outside {w}×{h}: {b:?}", t.s));
        }
    }
    for (i, a) in c.texts.iter().enumerate() {
        for b in &c.texts[i + 1..] {
            let (p, q) = (a.bounds, b.bounds);
            if p[0] < q[2] - 0.5 && q[0] < p[2] - 0.5 && p[1] < q[3] - 0.5 && q[1] < p[3] - 0.5 {
                out.push(format!("{:?} overlaps {:?}", a.s, b.s));
            }
        }
    }
    out
}

const PROGRAMS: &[(&str, &str, Dialect)] = &[
    ("o1006", include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc),
    ("o0009", include_str!("../examples/o0009.nc"), Dialect::Gsk980tdc),
    ("g92-two-start", include_str!("../examples/g92-two-start.nc"), Dialect::Gsk980tdc),
    ("g78-m30x2", include_str!("../examples/g78-m30x2.nc"), Dialect::Gsk980tdc),
    ("g78-flank-alternating", include_str!("../examples/g78-flank-alternating.nc"), Dialect::Gsk980tdc),
    ("g76-fanuc", include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i),
    ("renhe-tails", include_str!("../examples/renhe-tails.nc"), Dialect::Renhe),
    ("g76-m12-g7", include_str!("linuxcnc/g76-m12-g7.ngc"), Dialect::LinuxCnc),
];

/// The scenes of a program: side, tooth and starts of its first thread.
fn scenes(src: &str, d: Dialect) -> Vec<(&'static str, Scene)> {
    let plan = plan_with(src, d, &[]);
    let mut out = vec![("side", side(&plan))];
    out.extend(tooth(&plan, 0, 1).map(|s| ("tooth", s)));
    out.extend(starts(&plan, 0).map(|s| ("starts", s)));
    out
}

#[test]
fn every_view_has_every_label_inside_and_none_overlapping() {
    let mut bad = Vec::new();
    for &(name, src, d) in PROGRAMS {
        for (view, scene) in scenes(src, d) {
            for item in &scene.items {
                if let Shape::Dim { label, .. } | Shape::Text { label, .. } = &item.shape {
                    assert!(
                        label.key.is_empty() || LABEL_KEYS.contains(&label.key),
                        "{name} {view}: key {}",
                        label.key
                    );
                }
            }
            for (lang, l) in [("en", Lang::En), ("zh", Lang::Zh)] {
                for (w, h, stretch) in [(800.0, 500.0, false), (800.0, 500.0, true), (300.0, 200.0, false)] {
                    let o = View { width: w, height: h, stretch, lang: l, ..View::default() };
                    let c = check(&svg(&scene, &o));
                    assert_eq!(c.size, [w, h]);
                    assert!(c.paths > 2, "{name} {view}");
                    let at = format!("{name} {view} {lang} {w}×{h}{}", if stretch { " stretched" } else { "" });
                    bad.extend(faults(&c).into_iter().map(|f| format!("{at}: {f}")));
                    // The chosen thread's major, minor and lead are always there.
                    let must: &[&str] = match (view, lang) {
                        ("side", "en") => &["major Ø", "minor Ø", "Ph "],
                        ("side", _) => &["大径 Ø", "小径 Ø", "导程 "],
                        ("tooth", "en") => &["h ", "P "],
                        ("tooth", _) => &["牙高 ", "螺距 "],
                        _ => &[],
                    };
                    for m in must {
                        assert!(c.texts.iter().any(|t| t.s.starts_with(m)), "{at}: no {m:?} in {:?}", c.texts);
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{} faults:\n{}", bad.len(), bad.join("\n"));
}

/// A scene of one cut, a long note at its end and the lead at its start.
fn small_scene(note: &str) -> Scene {
    let mut scene = Scene::new(ViewKind::Side);
    let line = Shape::Polyline { points: vec![[0.0, 0.0], [10.0, 5.0]].into() };
    scene.push(Item::new(line, Style::Cut), true);
    let text = Shape::Text { at: [10.0, 5.0], label: Label::new("", note), anchor: Anchor::Start, dx: 6.0, dy: 0.0 };
    scene.push(Item::new(text, Style::Note), true);
    let lead = Shape::Text { at: [0.0, 0.0], label: Label::new("lead", "2"), anchor: Anchor::End, dx: -4.0, dy: 0.0 };
    scene.push(Item::new(lead, Style::Dimension), true);
    scene.finish();
    scene
}

#[test]
fn labels_fit_in_the_page_wrapped_and_in_the_views_language() {
    let long = "a label far longer than the drawing is wide, at its right end, and longer still";
    let scene = small_scene(long);
    let o = View { width: 300.0, height: 200.0, ..View::default() };
    let c = check(&svg(&scene, &o));
    assert_eq!(c.size, [300.0, 200.0]);
    assert!(faults(&c).is_empty(), "{:?}", faults(&c));
    assert!(c.texts.iter().any(|t| t.s == "Ph 2"), "{:?}", c.texts);
    // The note is wrapped: its lines, in order, give it back.
    let lines: Vec<&str> = c.texts.iter().filter(|t| t.s != "Ph 2").map(|t| t.s.as_str()).collect();
    assert!(lines.len() >= 2, "{lines:?}");
    assert_eq!(lines.join(" "), long);
    let zh = View { lang: Lang::Zh, ..o };
    let doc = svg(&scene, &zh);
    check(&doc);
    assert!(doc.contains(">导程 2</text>"));
    // Text is escaped.
    let mut s2 = Scene::new(ViewKind::Side);
    let t = Shape::Text {
        at: [0.0, 0.0],
        label: Label::new("", "a < b & \"c\""),
        anchor: Anchor::Middle,
        dx: 0.0,
        dy: 0.0,
    };
    s2.push(Item::new(t, Style::Note), true);
    s2.finish();
    let texts: Vec<String> = check(&svg(&s2, &View::default())).texts.into_iter().map(|t| t.s).collect();
    assert_eq!(texts, ["a < b & \"c\""]);
}

#[test]
fn an_empty_plan_still_draws() {
    let plan = plan_with("", Dialect::Gsk980tdc, &[]);
    check(&svg(&side(&plan), &View::default()));
    assert!(tooth(&plan, 0, 1).is_none());
}

/// O1006 ends with `G00 X100 Z100` (a return far from the thread): the page
/// is the Fit of the threads, the far rapid is clipped, not fitted (it would
/// shrink the thread to a corner of the page).
#[test]
fn a_far_return_is_clipped_not_fitted() {
    let plan = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    let scene = side(&plan);
    assert!(scene.bounds.x1 > scene.focus.x1 + 20.0, "the far return lies outside the focus");
    let doc = svg(&scene, &View::default());
    let c = check(&doc);
    assert_eq!(c.size, [800.0, 500.0]);
    // The cuts (blue) span most of the page's width.
    let xml = roxmltree::Document::parse(&doc).unwrap();
    let cut = xml.descendants().find(|n| n.attribute("stroke") == Some("#2563eb")).expect("the cuts");
    let xs: Vec<f64> = numbers(cut.attribute("d").unwrap()).chunks(2).map(|p| p[0]).collect();
    let span = xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max) - xs.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(span > 0.7 * 800.0, "the cuts span {span} px of 800");
    // The far rapid leaves the page: it is there, clipped.
    let far =
        xml.descendants().filter_map(|n| n.attribute("d")).flat_map(numbers).any(|v| !(-50.0..=850.0).contains(&v));
    assert!(far, "a shape beyond the page");
}

#[test]
fn a_given_transform_draws_there_and_places_the_labels_inside() {
    let plan = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    let scene = side(&plan);
    let xf = Transform { sx: 10.0, sy: 10.0, tx: -50.0, ty: 400.0 };
    let o = View { width: 640.0, height: 360.0, transform: Some(xf), ..View::default() };
    o.validate().expect("a view");
    let list = display(&scene, &o);
    assert_eq!(list.transform, xf);
    let doc = write(&list);
    assert_eq!(doc, svg(&scene, &o), "the writer writes the display list");
    let c = check(&doc);
    assert_eq!(c.size, [640.0, 360.0]);
    // The cuts at the transform: Z70 → x 650, Z13 → x 80; radius 23.55 → y 164.5.
    assert!(doc.contains("M650 164.5L80 164.5"), "{doc}");
    assert!(faults(&c).is_empty() && !c.texts.is_empty(), "{:?}", c.texts);
    assert_eq!(c.texts.len(), list.labels.iter().map(|l| l.lines.len()).sum::<usize>());
    // Views that cannot be drawn as given are refused; drawn anyway, they fall back to a fit.
    assert!(View { transform: Some(Transform { sy: 0.0, ..xf }), ..o.clone() }.validate().is_err());
    assert!(View { width: f64::INFINITY, ..View::default() }.validate().is_err());
    let flat = display(&scene, &View { transform: Some(Transform { sy: 0.0, ..xf }), ..o.clone() });
    assert!(flat.transform.sy > 0.0);
}

#[test]
fn a_stale_view_is_grey_and_a_mark_lies_beneath() {
    let plan = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    let scene = side(&plan);
    let o = View { width: 640.0, height: 360.0, ..View::default() };
    let fresh = svg(&scene, &o);
    assert!(fresh.contains("stroke=\"#2563eb\""), "the cut pen");
    // Stale: the cut pen through a grayscale filter (0.2126·37 + 0.7152·99 + 0.0722·235 = 95.6), faded.
    let stale = svg(&scene, &View { stale: true, ..o.clone() });
    assert!(!stale.contains("#2563eb") && stale.contains("stroke=\"rgb(96,96,96)\""), "{stale}");
    assert!(stale.contains("opacity=\"0.35\""));
    // A mark on pass 3 of thread 1: halos in the highlight's colour, before (beneath) the cuts.
    let items = screwcut::draw::pick::items_of_pass(&scene, 0, 2);
    assert!(!items.is_empty());
    let marked = svg(&scene, &View { mark: Mark { items, light: false }, ..o.clone() });
    let halo = marked.find("stroke=\"#f59e0b\"").expect("a halo");
    assert!(halo < marked.find("stroke=\"#2563eb\"").unwrap(), "the halo is painted first");
    // A stale drawing shows no mark.
    let items = screwcut::draw::pick::items_of_pass(&scene, 0, 2);
    assert!(!svg(&scene, &View { stale: true, mark: Mark { items, light: false }, ..o }).contains("#f59e0b"));
}

#[test]
fn label_words_in_both_languages() {
    assert_eq!(english("lead"), Some("Ph {}"));
    assert_eq!(label_text(Lang::En, "dia_major", "48"), "major Ø48");
    assert_eq!(label_text(Lang::Zh, "dia_major", "48"), "大径 Ø48");
    // δ1 reads the same in both; a bare value is itself; an unknown key says itself.
    assert_eq!(label_text(Lang::Zh, "delta1", "3.2"), "δ1 3.2");
    assert_eq!(label_text(Lang::Zh, "", "X47.1"), "X47.1");
    assert_eq!(label_text(Lang::En, "nonsense", "1"), "nonsense 1");
    for k in LABEL_KEYS {
        assert!(english(k).is_some(), "{k}");
    }
}
