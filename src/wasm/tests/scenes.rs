//! The scenes as the renderer gets them, checked by their numbers.

use js_sys::JSON;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

#[wasm_bindgen_test]
fn style_and_shape_names_index_the_codes() {
    let shapes: Vec<String> = wasm::shape_names().iter().map(|s| s.as_string().unwrap()).collect();
    assert_eq!(shapes, ["polyline", "polygon", "circle", "arrow", "dim", "text", "marker"]);
    let styles: Vec<String> = wasm::style_names().iter().map(|s| s.as_string().unwrap()).collect();
    for s in
        ["axis", "outline", "crest", "root", "rapid", "cut", "runout", "screw_in", "area", "tool", "start", "dimension"]
    {
        assert!(styles.iter().any(|x| x == s), "style {s} in {styles:?}");
    }
}

#[wasm_bindgen_test]
fn o1006_side_scene_has_five_pass_paths() {
    let r = plan(O1006, "gsk980tdc", "");
    let s = scene(&get(&r, "side"));
    assert_eq!(s.view, "side");
    let cuts = s.of("cut", Some("polyline"));
    assert_eq!(cuts.len(), 5);
    let radii = [23.55, 23.25, 22.95, 22.75, 22.7];
    for (k, c) in cuts.iter().enumerate() {
        assert_close(&c.coords, &[70.0, radii[k], 13.0, radii[k]]);
        assert_eq!((c.thread, c.pass), (Some(0), Some(k as u32)));
        assert_eq!(c.lines, [6 + 4 * k as u32]);
    }
    // The finishing pass is marked by its role (2 = finish).
    assert_eq!(cuts.iter().map(|c| c.extra).collect::<Vec<_>>(), [1, 1, 1, 1, 2]);
    // Each pass: infeed, retract and return as rapids of that pass.
    for k in 0..5u32 {
        let rapids: Vec<&Item> = s.items.iter().filter(|i| i.style == "rapid" && i.pass == Some(k)).collect();
        assert_eq!(rapids.len(), 3, "pass {k}");
        assert_close(&rapids[0].coords, &[70.0, 29.0, 70.0, radii[k as usize]]);
    }
    // Dimensions in program units: major Ø48 (assumed), minor Ø45.4 (diameters), lead 2, thread length 57.
    let mut dims = s.labels("dimension");
    dims.extend(s.labels("diameter"));
    for want in [("dia_major", "48"), ("dia_minor", "45.4"), ("lead", "2"), ("length", "57")] {
        assert!(dims.iter().any(|(k, v)| k == want.0 && v == want.1), "{want:?} in {dims:?}");
    }
    // The bounds hold every pass and the focus is within them.
    let [x0, y0, x1, y1] = s.bounds[..] else { panic!("bounds") };
    assert!(x0 <= 13.0 && x1 >= 70.0 && y0 <= 0.0 && y1 >= 29.0, "{:?}", s.bounds);
    let f = &s.focus;
    assert!(f[0] >= x0 && f[2] <= x1 && f[0] < f[2] && f[1] < f[3], "{f:?}");
}

#[wasm_bindgen_test]
fn o1006_tooth_scene_shows_each_depth() {
    let r = plan(O1006, "gsk980tdc", "");
    let s = scene(&get(&r, "tooth"));
    assert_eq!(s.view, "tooth");
    // The tool tip of every pass: radial infeed (no shift), depth downward.
    let tips = s.of("tool", Some("marker"));
    let depths = [0.45, 0.75, 1.05, 1.25, 1.3];
    assert_eq!(tips.len(), 5);
    for (k, m) in tips.iter().enumerate() {
        assert_close(&m.coords, &[0.0, -depths[k]]);
        assert_eq!(m.pass, Some(k as u32));
    }
    // Rough passes are dots (glyph 0), the finishing pass a cross (2).
    assert_eq!(tips.iter().map(|m| m.extra).collect::<Vec<_>>(), [0, 0, 0, 0, 2]);
    let labels = s.labels("depth_tick");
    let want = [
        ("pass_depth", "1: 0.45"),
        ("pass_depth", "2: 0.75"),
        ("pass_depth", "3: 1.05"),
        ("pass_depth", "4: 1.25"),
        ("pass_depth_finish", "5: 1.3"),
    ];
    assert_eq!(labels, want.map(|(k, v)| (k.to_string(), v.to_string())));
    // One area per pass; together they are the thread space down to 1.3.
    let areas = s.of("area", Some("polygon"));
    let mut passes: Vec<u32> = areas.iter().filter_map(|a| a.pass).collect();
    passes.dedup();
    assert_eq!(passes, [0, 1, 2, 3, 4]);
    let p: Vec<PassInfo> = super::helpers::passes(&r, "passes");
    let total: f64 = p.iter().map(|p| p.area.unwrap()).sum();
    let v = 1.3 * 1.3 * 30f64.to_radians().tan();
    assert!((total - v).abs() < 1e-3, "area {total} vs V of depth 1.3: {v}");
    let dims = s.labels("dimension");
    assert!(
        dims.contains(&("height".into(), "1.3".into())) && dims.contains(&("pitch".into(), "2".into())),
        "{dims:?}"
    );
    let notes = s.labels("note");
    assert!(notes.contains(&("tool_angle".into(), "60°".into())), "{notes:?}");
}

#[wasm_bindgen_test]
fn flank_infeed_moves_the_tool_along_a_flank() {
    let r = plan(G78_ALTERNATING, "gsk980tdc", "");
    let s = scene(&get(&r, "tooth"));
    let p: Vec<PassInfo> = passes(&r, "passes");
    let tips = s.of("tool", Some("marker"));
    assert_eq!(tips.len(), p.len());
    for (m, p) in tips.iter().zip(&p) {
        assert_close(&m.coords, &[p.shift, -p.depth]);
    }
    let xs: Vec<f64> = tips.iter().map(|m| m.coords[0]).collect();
    assert!(xs[0] < 0.0 && xs[1] > 0.0 && xs[2] < 0.0, "alternating sides: {xs:?}");
    assert!(s.items.iter().any(|i| i.label == Some(("infeed_alternating".into(), String::new()))));
    // The side scene draws the screw-in of every pass.
    let side = scene(&get(&r, "side"));
    assert_eq!(side.of("screw_in", Some("polyline")).len(), p.len());
}

/// The start angles drawn in a starts scene: the direction of each start's
/// ray from the centre, 0° at the top, clockwise.
fn start_angles(s: &Scene) -> Vec<f64> {
    s.of("start", Some("polyline"))
        .iter()
        .filter(|i| i.coords[..2] == [0.0, 0.0])
        .map(|i| {
            let a = i.coords[2].atan2(i.coords[3]).to_degrees();
            if a < -1e-9 { a + 360.0 } else { a }
        })
        .collect()
}

#[wasm_bindgen_test]
fn two_start_g32_has_starts_at_0_and_180_degrees() {
    let r = plan(G32_TWO_START, "gsk980tdc", "");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!((t[0].starts, t[0].lead, t[0].pitch), (2, 4.0, 2.0));
    let s = scene(&get(&r, "starts"));
    assert_eq!(s.view, "starts");
    assert_close(&start_angles(&s), &[0.0, 180.0]);
    let labels = s.labels("start");
    let angle_labels: Vec<&str> = labels.iter().filter(|(k, _)| k == "start_angle").map(|(_, v)| v.as_str()).collect();
    assert_eq!(angle_labels, ["1: 0°", "2: 180°"]);
    // Axial offsets lead·θ/360: 0 and 2 on the ruler.
    let offsets: Vec<&str> = labels.iter().filter(|(k, _)| k.is_empty()).map(|(_, v)| v.as_str()).collect();
    assert_eq!(offsets, ["1: 0", "2: 2"]);
    let dims = s.labels("dimension");
    assert!(dims.contains(&("lead".into(), "4".into())) && dims.contains(&("pitch".into(), "2".into())), "{dims:?}");
    // The tooth view of the second start is one call away.
    let other = wasm::thread_scenes(0, 2).unwrap();
    let tooth = scene(&get(&other, "tooth"));
    assert!(tooth.labels("note").contains(&("start_of".into(), "2/2".into())));
    let tips = tooth.of("tool", Some("marker"));
    assert_eq!(tips.len(), 2);
    assert_close(&tips.iter().map(|m| -m.coords[1]).collect::<Vec<_>>(), &[1.0, 1.3]);
}

#[wasm_bindgen_test]
fn two_start_g92_by_l() {
    let r = plan(G92_TWO_START, "gsk980tdc", "");
    let s = scene(&get(&r, "starts"));
    assert_close(&start_angles(&s), &[0.0, 180.0]);
    let offsets: Vec<String> = s.labels("start").into_iter().filter(|(k, _)| k.is_empty()).map(|(_, v)| v).collect();
    assert_eq!(offsets, ["1: 0", "2: 1.5"]);
    let side = scene(&get(&r, "side"));
    assert_eq!(side.of("cut", Some("polyline")).len(), 8, "four passes of two starts");
    assert_eq!(side.of("runout", Some("polyline")).len(), 8, "each with the No.019 run-out");
}

#[wasm_bindgen_test]
fn taper_thread_runs_along_its_cone() {
    let r = plan(O0009, "gsk980tdc", "");
    let s = scene(&get(&r, "side"));
    let cuts = s.of("cut", Some("polyline"));
    assert_eq!(cuts.len(), 2);
    assert_close(&cuts[0].coords, &[3.0, 27.4286 / 2.0, -72.0, 48.8571 / 2.0]);
    assert_close(&cuts[1].coords, &[3.0, 26.4286 / 2.0, -72.0, 47.4286 / 2.0]);
    let d: Vec<Diag> = field(&r, "diagnostics");
    let w = d.iter().find(|d| d.severity == "warning").expect("the 1 mm infeed is too large");
    assert_eq!((w.code.as_str(), w.line), ("infeed-too-large", 6));
}

#[wasm_bindgen_test]
fn thread_and_start_choices_are_clamped() {
    let r = wasm::update(G32_TWO_START, "gsk980tdc", "", 99, 99, -1.0, None).unwrap();
    assert_eq!(num(&r, "thread"), 0.0);
    let tooth = scene(&get(&r, "tooth"));
    assert!(tooth.labels("note").contains(&("start_of".into(), "2/2".into())), "start 99 is the last start");
    let r = wasm::update(G32_TWO_START, "gsk980tdc", "", 0, 0, -1.0, None).unwrap();
    assert!(scene(&get(&r, "tooth")).labels("note").contains(&("start_of".into(), "1/2".into())));
    let r = wasm::update(G32_TWO_START, "gsk980tdc", "", -1, 1, -1.0, None).unwrap();
    assert!(get(&r, "thread").is_null() && get(&r, "tooth").is_null() && get(&r, "starts").is_null());
    assert!(array(&get(&r, "passes")).is_empty());
    assert!(get(&r, "side").is_object(), "the side view draws every thread");
    // Renhe's two threads: the second one chosen.
    let r = wasm::update(RENHE_TAILS, "renhe", "", 1, 1, -1.0, None).unwrap();
    assert_eq!(num(&r, "thread"), 1.0);
    let p: Vec<PassInfo> = passes(&r, "passes");
    assert_eq!(p[0].lines, [10, 11, 12]);
}

/// The record layout is defined once in Rust and read by name: every field
/// of `pack::FIELDS` at its index, the names lists indexed by their codes.
#[wasm_bindgen_test]
fn scene_layout_names_every_field() {
    let l = wasm::scene_layout();
    assert_eq!(num(&l, "stride") as usize, crate::wasm::pack::STRIDE);
    let fields = get(&l, "fields");
    for (i, name) in crate::wasm::pack::FIELDS.iter().enumerate() {
        assert_eq!(num(&fields, name) as usize, i, "{name}");
    }
    let styles = array(&get(&l, "styles"));
    assert_eq!(styles[crate::diagram::Style::Cut.code() as usize].as_string().as_deref(), Some("cut"));
    let shapes = array(&get(&l, "shapes"));
    assert_eq!(shapes[4].as_string().as_deref(), Some("dim"));
}

/// The layout the app's SVG export passes (`SceneView.svgLayout()`), as JSON.
fn layout_json(item: usize) -> String {
    format!(
        r#"{{"transform":{{"sx":9.5,"sy":14.25,"tx":-60,"ty":420}},
            "labels":[{{"item":{item},"key":"dia_major","text":"大径 Ø48","lines":["大径 Ø48"],"align":"middle",
                        "box":[20.5,100,35.5,160.25],"angle":-90,"must":true,"off":-24,"len":40,"lead":null}}]}}"#
    )
}

#[wasm_bindgen_test]
fn the_svg_export_is_the_core_writer_at_the_views_transform_and_labels() {
    use crate::diagram::scene::Style;
    use crate::svg::{Layout, Options, svg};
    let s = wasm::Session::new();
    s.update(O1006, "gsk980tdc", "", 0, 1, -1.0, None).unwrap();
    let scene = crate::diagram::side(&crate::plan(O1006, &crate::Settings::new(crate::Dialect::Gsk980tdc)));
    let major = scene.items.iter().position(|i| i.style == Style::Diameter).expect("a diameter");
    // Without a layout: fitted to the page as the command line does.
    let fitted = s.svg("side", 0, 1, vec![640.0, 360.0], true, Vec::new(), JsValue::UNDEFINED).unwrap();
    assert_eq!(fitted, svg(&scene, &Options { width: 640.0, height: 360.0, stretch: true, ..Options::default() }));
    assert!(fitted.contains("viewBox=\"0 0 640 360\""));
    // With the view's layout: its transform, its labels where given, in its words.
    let json = layout_json(major);
    let given = JSON::parse(&json).unwrap();
    let drawn = s.svg("side", 0, 1, vec![640.0, 360.0], true, Vec::new(), given).unwrap();
    let layout: Layout = serde_json::from_str(&json).unwrap();
    let o = Options { width: 640.0, height: 360.0, stretch: true, layout: Some(layout), ..Options::default() };
    assert_eq!(drawn, svg(&scene, &o));
    assert!(drawn.contains("transform=\"rotate(-90 28 130.13)\" fill=\"#111827\""), "{drawn}");
    assert!(drawn.contains(">大径 Ø48</text>") && drawn.matches("<text ").count() == 1);
    // A layout that does not fit the scene is an error, never a trap.
    let cut = scene.items.iter().position(|i| i.style == Style::Cut).unwrap();
    let bad = [
        (layout_json(cut), "neither a dimension nor a text"),
        (layout_json(1 << 20), "not in the scene"),
        (json.replace("\"sx\":9.5", "\"sx\":0"), "positive scales"),
        (json.replace("\"middle\"", "\"sideways\""), "the SVG layout"),
        (json.replace("[\"大径 Ø48\"]", "[]"), "lines"),
        (r#"{"labels":[]}"#.to_string(), "the SVG layout"),
        ("\"side\"".to_string(), "the SVG layout"),
    ];
    for (text, want) in bad {
        let e = s.svg("side", 0, 1, vec![640.0, 360.0], false, Vec::new(), JSON::parse(&text).unwrap()).unwrap_err();
        assert!(message(e).contains(want), "{text}: {want}");
    }
    for size in [vec![640.0], vec![f64::NAN, 360.0], vec![-1.0, 360.0], vec![1e9, 360.0]] {
        let e = s.svg("side", 0, 1, size.clone(), false, Vec::new(), JsValue::NULL).unwrap_err();
        assert!(!message(e).is_empty(), "{size:?}");
    }
}
