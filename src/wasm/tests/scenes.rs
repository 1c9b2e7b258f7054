//! The scenes as the renderer gets them, checked by their numbers.

use js_sys::{Float64Array, Uint32Array};
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

#[wasm_bindgen_test]
fn o1006_side_scene_has_five_pass_paths() {
    let _r = plan(O1006, "gsk980tdc", "");
    let s = shown("side");
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
        // From the retract at X58 (r 29, drawn at 26.305 on the broken radial scale, diagram::radial) through the break at 24.65.
        assert_close(&rapids[0].coords, &[70.0, 26.305287, 70.0, 24.65, 70.0, radii[k as usize]]);
    }
    // Dimensions in program units: major Ø48 (assumed), minor Ø45.4 (diameters), lead 2, thread length 57.
    let mut dims = s.labels("dimension");
    dims.extend(s.labels("diameter"));
    for want in [("dia_major", "48"), ("dia_minor", "45.4"), ("lead", "2"), ("length", "57")] {
        assert!(dims.iter().any(|(k, v)| k == want.0 && v == want.1), "{want:?} in {dims:?}");
    }
    // The bounds hold every pass and the focus is within them.
    let [x0, y0, x1, y1] = s.bounds[..] else { panic!("bounds") };
    assert!(x0 <= 13.0 && x1 >= 70.0 && y0 <= 0.0 && y1 >= 26.3, "{:?}", s.bounds);
    let f = &s.focus;
    assert!(f[0] >= x0 && f[2] <= x1 && f[0] < f[2] && f[1] < f[3], "{f:?}");
}

#[wasm_bindgen_test]
fn o1006_tooth_scene_shows_each_depth() {
    let r = plan(O1006, "gsk980tdc", "");
    let s = shown("tooth");
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
    let s = shown("tooth");
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
    let side = shown("side");
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
    let s = shown("starts");
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
    wasm::thread_scenes(0, 2).unwrap();
    let tooth = shown("tooth");
    assert!(tooth.labels("note").contains(&("start_of".into(), "2/2".into())));
    let tips = tooth.of("tool", Some("marker"));
    assert_eq!(tips.len(), 2);
    assert_close(&tips.iter().map(|m| -m.coords[1]).collect::<Vec<_>>(), &[1.0, 1.3]);
}

#[wasm_bindgen_test]
fn two_start_g92_by_l() {
    let _r = plan(G92_TWO_START, "gsk980tdc", "");
    let s = shown("starts");
    assert_close(&start_angles(&s), &[0.0, 180.0]);
    let offsets: Vec<String> = s.labels("start").into_iter().filter(|(k, _)| k.is_empty()).map(|(_, v)| v).collect();
    assert_eq!(offsets, ["1: 0", "2: 1.5"]);
    let side = shown("side");
    assert_eq!(side.of("cut", Some("polyline")).len(), 8, "four passes of two starts");
    assert_eq!(side.of("runout", Some("polyline")).len(), 8, "each with the No.019 run-out");
}

#[wasm_bindgen_test]
fn taper_thread_runs_along_its_cone() {
    let r = plan(O0009, "gsk980tdc", "");
    let s = shown("side");
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
    let tooth = shown("tooth");
    assert!(tooth.labels("note").contains(&("start_of".into(), "2/2".into())), "start 99 is the last start");
    wasm::update(G32_TWO_START, "gsk980tdc", "", 0, 0, -1.0, None).unwrap();
    assert!(shown("tooth").labels("note").contains(&("start_of".into(), "1/2".into())));
    let r = wasm::update(G32_TWO_START, "gsk980tdc", "", -1, 1, -1.0, None).unwrap();
    assert!(get(&r, "thread").is_null() && shown_key(&r, 1) == 0.0 && shown_key(&r, 2) == 0.0);
    assert!(array(&get(&r, "passes")).is_empty());
    assert!(shown_key(&r, 0) != 0.0, "the side view draws every thread");
    // Renhe's two threads: the second one chosen.
    let r = wasm::update(RENHE_TAILS, "renhe", "", 1, 1, -1.0, None).unwrap();
    assert_eq!(num(&r, "thread"), 1.0);
    let p: Vec<PassInfo> = passes(&r, "passes");
    assert_eq!(p[0].lines, [10, 11, 12]);
}

/// A view's display list from the session: the core's labels placed at the
/// fit (or at the view's transform), the mark's halos, the pick under the
/// pointer, and the SVG export written from the same list.
#[wasm_bindgen_test]
fn views_draw_pick_and_export_the_sessions_scenes() {
    use crate::draw::{Transform, View};
    let s = wasm::Session::new();
    let none = Uint32Array::new_with_length(0);
    s.update(Some(O1006.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    let d = s.draw("side", 640.0, 360.0, None, true, -1, -1, none.to_vec(), false).unwrap();
    let xf = Float64Array::from(get(&d, "transform")).to_vec();
    assert_eq!(xf.len(), 4);
    let texts: Vec<String> = array(&get(&d, "texts")).iter().map(|t| t.as_string().unwrap()).collect();
    for want in ["major Ø48", "minor Ø45.4", "Ph 2", "L 57"] {
        assert!(texts.iter().any(|t| t == want), "{want} in {texts:?}");
    }
    assert_eq!(num(&d, "dropped"), 0.0);
    let ops = Uint32Array::from(get(&d, "ops")).to_vec();
    assert_eq!(ops.len() % 7, 0);
    // The same list, written: what `screwcut svg` writes at that transform.
    let t = Transform { sx: xf[0], sy: xf[1], tx: xf[2], ty: xf[3] };
    let scene = crate::diagram::side(&crate::plan(O1006, &crate::Settings::new(crate::Dialect::Gsk980tdc)));
    let v = View { width: 640.0, height: 360.0, transform: Some(t), ..View::default() };
    assert_eq!(s.svg("side", 640.0, 360.0, Some(xf.clone()), true).unwrap(), crate::svg::svg(&scene, &v));
    // In Chinese, the same drawing in the other words.
    s.set_lang("zh");
    let zh = s.draw("side", 640.0, 360.0, Some(xf.clone()), true, -1, -1, none.to_vec(), false).unwrap();
    let texts: Vec<String> = array(&get(&zh, "texts")).iter().map(|t| t.as_string().unwrap()).collect();
    assert!(texts.iter().any(|t| t == "大径 Ø48"), "{texts:?}");
    s.set_lang("en");
    // The pointer over the third cut (Z40, radius 22.95): that pass, its line.
    let (px, py) = (xf[2] + xf[0] * 40.0, xf[3] - xf[1] * 22.95);
    let hit = s.pick("side", xf.clone(), px, py).unwrap();
    assert_eq!((num(&hit, "thread"), num(&hit, "pass")), (0.0, 2.0));
    assert!(s.pick("side", xf.clone(), 1.0, 1.0).unwrap().is_null());
    // Marked, the pass's halos come first in the list (beneath the items).
    let marked = s.draw("side", 640.0, 360.0, Some(xf.clone()), true, 0, 2, none.to_vec(), false).unwrap();
    let pens = array(&get(&marked, "pens"));
    let first = Uint32Array::from(get(&marked, "ops")).get_index(1) as usize;
    assert_eq!(get(&pens[first], "stroke").as_string().as_deref(), Some("#f59e0b"));
    // Bad views are errors, never traps.
    for (w, h) in [(f64::NAN, 360.0), (-1.0, 360.0), (1e9, 360.0)] {
        assert!(s.draw("side", w, h, None, false, -1, -1, none.to_vec(), false).is_err(), "{w}×{h}");
    }
    assert!(
        message(s.draw("front", 640.0, 360.0, None, false, -1, -1, none.to_vec(), false).unwrap_err())
            .contains("unknown view")
    );
    assert!(
        message(
            s.draw("side", 640.0, 360.0, Some(vec![0.0, 1.0, 0.0, 0.0]), false, -1, -1, none.to_vec(), false)
                .unwrap_err()
        )
        .contains("positive")
    );
    assert!(s.pick("side", vec![1.0], 0.0, 0.0).is_err());
}

/// The last good drawing: shown greyed while the text has an alarm, once
/// the page said it was left (`keep`); another program (`fresh`) forgets it.
#[wasm_bindgen_test]
fn an_alarm_shows_the_drawing_left_greyed() {
    let s = wasm::Session::new();
    let none = Uint32Array::new_with_length(0).to_vec();
    let good = s.update(Some(O1006.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    let broken = O1006.replace("X46.5", "X46..5");
    let r = s.update(Some(broken.clone()), "gsk980tdc", "", 0, 1, -1.0, None, false, true).unwrap();
    assert_eq!(get(&r, "stale").as_bool(), Some(true));
    assert_eq!(shown_key(&r, 0), shown_key(&good, 0), "the good drawing's side section");
    let d = s.draw("side", 640.0, 360.0, None, false, -1, -1, none.clone(), false).unwrap();
    assert_eq!(get(&d, "stale").as_bool(), Some(true));
    let strokes: Vec<String> = array(&get(&d, "pens")).iter().filter_map(|p| get(p, "stroke").as_string()).collect();
    assert!(!strokes.iter().any(|c| c == "#2563eb"), "grey pens: {strokes:?}");
    assert!(s.pick("side", Float64Array::from(get(&d, "transform")).to_vec(), 320.0, 180.0).unwrap().is_null());
    // Another program with an alarm: nothing kept.
    let other = s.update(Some(broken.clone()), "gsk980tdc", "", 0, 1, -1.0, None, true, false).unwrap();
    assert_eq!(get(&other, "stale").as_bool(), Some(false));
}
