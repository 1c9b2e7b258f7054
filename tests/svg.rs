#![cfg(not(target_arch = "wasm32"))]
//! `svg`: every view gives well-formed SVG (parsed by roxmltree) whose
//! viewBox holds the fitted drawing area and the estimated box of every
//! label, with the shapes clipped to it.

mod common;
use common::plan_with;
use screwcut::Dialect;
use screwcut::diagram::scene::{Anchor, Item, Label, Scene, Shape, Style, ViewKind};
use screwcut::diagram::{side, starts, tooth};
use screwcut::svg::{Options, measure, svg};

/// What a check found: the viewBox and how many texts and paths it holds.
struct Checked {
    view_box: [f64; 4],
    texts: Vec<String>,
    paths: usize,
}

fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse::<f64>().unwrap_or_else(|_| panic!("{t:?} in {s:?}")))
        .collect()
}

/// Parses `doc` and checks its structure and extents.
fn check(doc: &str) -> Checked {
    let xml = roxmltree::Document::parse(doc).unwrap_or_else(|e| panic!("not XML: {e}\n{doc}"));
    let root = xml.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.tag_name().namespace(), Some("http://www.w3.org/2000/svg"));
    let vb = numbers(root.attribute("viewBox").expect("a viewBox"));
    assert_eq!(vb.len(), 4);
    let [x, y, w, h] = [vb[0], vb[1], vb[2], vb[3]];
    assert!(w > 0.0 && h > 0.0);
    assert_eq!(numbers(root.attribute("width").unwrap()), [w]);
    assert_eq!(numbers(root.attribute("height").unwrap()), [h]);
    assert!(root.attribute("font-family").unwrap().ends_with("sans-serif"));
    let font = numbers(root.attribute("font-size").unwrap())[0];
    assert!(root.children().any(|n| n.has_tag_name("title")));
    let inside = |px: f64, py: f64, what: &str| {
        assert!(
            px >= x - 1e-6 && px <= x + w + 1e-6 && py >= y - 1e-6 && py <= y + h + 1e-6,
            "{what} at ({px}, {py}) is outside the viewBox {vb:?}"
        );
    };
    // The fitted drawing area (0, 0)–(width, height) is on the page, and the shapes are clipped to the page.
    inside(0.0, 0.0, "the drawing area");
    let clip = xml.descendants().find(|n| n.has_tag_name("clipPath")).expect("a clip path");
    let rect = clip.children().find(|n| n.has_tag_name("rect")).expect("a clip rectangle");
    let r = |k| rect.attribute(k).unwrap().parse::<f64>().unwrap();
    assert_eq!([r("x"), r("y"), r("width"), r("height")], [x, y, w, h], "the clip is the page");
    let id = clip.attribute("id").unwrap();
    let group = root.children().find(|n| n.has_tag_name("g")).expect("the drawing group");
    assert_eq!(group.attribute("clip-path"), Some(format!("url(#{id})").as_str()));
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
                let (cx, cy, r) = (a("cx"), a("cy"), a("r"));
                assert!(cx.is_finite() && cy.is_finite() && r >= 0.0);
            }
            "text" => {
                let s = n.text().unwrap_or_default().to_string();
                assert!(!s.is_empty());
                let a = |k| n.attribute(k).unwrap().parse::<f64>().unwrap();
                let (tx, ty) = (a("x"), a("y"));
                let tw = measure(&s, font);
                let th = font * 1.25;
                let (a0, a1) = match n.attribute("text-anchor").unwrap() {
                    "start" => (0.0, tw),
                    "end" => (-tw, 0.0),
                    _ => (-tw / 2.0, tw / 2.0),
                };
                let (b0, b1) = match n.attribute("dominant-baseline").unwrap() {
                    "hanging" => (0.0, th),
                    "text-after-edge" => (-th, 0.0),
                    "central" => (-th / 2.0, th / 2.0),
                    other => panic!("baseline {other}"),
                };
                if n.attribute("transform").is_some() {
                    inside(tx + b0, ty - a1, &format!("label {s:?}"));
                    inside(tx + b1, ty - a0, &format!("label {s:?}"));
                } else {
                    inside(tx + a0, ty + b0, &format!("label {s:?}"));
                    inside(tx + a1, ty + b1, &format!("label {s:?}"));
                }
                texts.push(s);
            }
            _ => {}
        }
    }
    Checked { view_box: [x, y, w, h], texts, paths }
}

const PROGRAMS: &[(&str, &str, Dialect)] = &[
    ("o1006", include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc),
    ("g92-two-start", include_str!("../examples/g92-two-start.nc"), Dialect::Gsk980tdc),
    ("g78-flank-alternating", include_str!("../examples/g78-flank-alternating.nc"), Dialect::Gsk980tdc),
    ("g76-fanuc", include_str!("../examples/g76-fanuc.nc"), Dialect::Fanuc0i),
    ("renhe-tails", include_str!("../examples/renhe-tails.nc"), Dialect::Renhe),
    ("g76-m12-g7", include_str!("linuxcnc/g76-m12-g7.ngc"), Dialect::LinuxCnc),
];

#[test]
fn every_view_is_valid_svg_with_every_label_inside() {
    for &(name, src, d) in PROGRAMS {
        let plan = plan_with(src, d, &[]);
        let s = check(&svg(&side(&plan), &Options::default()));
        assert!(s.paths > 3, "{name}");
        assert!(s.texts.iter().any(|t| t.starts_with("Ph ")), "{name}: {:?}", s.texts);
        let t = check(&svg(&tooth(&plan, 0, 1).unwrap(), &Options::default()));
        assert!(t.texts.iter().any(|t| t.starts_with("h ")), "{name}: {:?}", t.texts);
        let st = check(&svg(&starts(&plan, 0).unwrap(), &Options::default()));
        assert!(st.texts.iter().any(|t| t.starts_with("one-rev signal")), "{name}: {:?}", st.texts);
    }
}

#[test]
fn labels_widen_the_page_and_take_the_callers_words() {
    let mut scene = Scene::new(ViewKind::Side);
    let line = Shape::Polyline { points: vec![[0.0, 0.0], [10.0, 5.0]] };
    scene.push(Item::new(line, Style::Cut), true);
    let long = "a label far longer than the drawing is wide, at its right end";
    let text = Shape::Text { at: [10.0, 5.0], label: Label::new("", long), anchor: Anchor::Start, dx: 6.0, dy: 0.0 };
    scene.push(Item::new(text, Style::Note), true);
    let lead = Shape::Text { at: [0.0, 0.0], label: Label::new("lead", "2"), anchor: Anchor::End, dx: -4.0, dy: 0.0 };
    scene.push(Item::new(lead, Style::Dimension), true);
    scene.finish();
    let o = Options { width: 300.0, height: 200.0, ..Options::default() };
    let c = check(&svg(&scene, &o));
    assert!(c.view_box[0] + c.view_box[2] > 300.0 + 100.0, "{:?}", c.view_box);
    assert!(c.texts.contains(&"Ph 2".to_string()), "{:?}", c.texts);
    let zh = Options { labels: vec![("lead".into(), "导程 {}".into())], ..o };
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
    assert_eq!(check(&svg(&s2, &Options::default())).texts, ["a < b & \"c\""]);
}

#[test]
fn an_empty_plan_still_draws() {
    let plan = plan_with("", Dialect::Gsk980tdc, &[]);
    check(&svg(&side(&plan), &Options::default()));
    assert!(tooth(&plan, 0, 1).is_none());
}

/// O1006 ends with `G00 X100 Z100` (a return far from the thread): the page
/// is the app's Fit of the threads at the size asked for, the far rapid is
/// clipped, not fitted (it would shrink the thread to a corner of the page).
#[test]
fn a_far_return_is_clipped_not_fitted() {
    let plan = plan_with(include_str!("../examples/o1006.nc"), Dialect::Gsk980tdc, &[]);
    let scene = side(&plan);
    assert!(scene.bounds.x1 > scene.focus.x1 + 20.0, "the far return lies outside the focus");
    let c = check(&svg(&scene, &Options { width: 800.0, height: 500.0, ..Options::default() }));
    let [x, y, w, h] = c.view_box;
    assert!(x <= 0.0 && y <= 0.0 && x + w >= 800.0 && y + h >= 500.0, "{:?}", c.view_box);
    // Only labels widen it, by less than a label's length.
    assert!(w < 800.0 + 200.0 && h < 500.0 + 100.0, "{:?}", c.view_box);
}
