//! The program-writing tools through the binding: the wizard's targets and
//! programs, and a plan expanded to blocks for another controller.

use js_sys::{Object, Reflect};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

/// A JS object of `(key, value)` pairs.
fn object(fields: &[(&str, JsValue)]) -> JsValue {
    let o = Object::new();
    for (k, v) in fields {
        Reflect::set(&o, &JsValue::from_str(k), v).unwrap();
    }
    o.into()
}

/// Plans `text` as `dialect` in a fresh session.
fn plan(text: &str, dialect: &str) -> JsValue {
    wasm::Session::new().update(Some(text.into()), dialect, "", 0, 1, -1.0, None, false, false).unwrap()
}

#[wasm_bindgen_test]
fn the_wizard_lists_each_controllers_forms() {
    let list = array(&wasm::wizard_forms(None).unwrap());
    let forms = |d: &str| -> Vec<String> {
        let entry = list.iter().find(|e| get(e, "dialect").as_string().as_deref() == Some(d)).unwrap();
        array(&get(entry, "forms")).iter().map(|f| get(f, "name").as_string().unwrap()).collect()
    };
    // G78 is GSK's own cycle (GSK980TDc manual §3.5); LinuxCNC has G33 and its G76.
    assert!(forms("gsk980tdc").contains(&"g78".to_string()));
    assert!(!forms("fanuc0i").contains(&"g78".to_string()));
    assert_eq!(forms("linuxcnc"), ["g33", "linuxcnc_g76"]);
    // The titles in the page's language.
    let title = |lang: &str| {
        let list = array(&wasm::wizard_forms(Some(lang.into())).unwrap());
        let gsk = list.iter().find(|e| get(e, "dialect").as_string().as_deref() == Some("gsk980tdc")).unwrap();
        let forms = array(&get(gsk, "forms"));
        let g92 = forms.iter().find(|f| get(f, "name").as_string().as_deref() == Some("g92")).unwrap();
        get(g92, "title").as_string().unwrap()
    };
    assert_eq!((title("en"), title("zh")), ("G92 simple cycle".into(), "G92 简单螺纹循环".into()));
}

/// M30×2-6g, 30 mm, GSK G76: the program names its designation in a comment,
/// plans without an alarm, and the thread check reads it and passes it
/// (d2 28.493…28.663, ISO 965-2).
#[wasm_bindgen_test]
fn the_wizards_program_plans_and_gauges() {
    let req = object(&[
        ("designation", "M30x2-6g".into()),
        ("length", 30.0.into()),
        ("dialect", "gsk980tdc".into()),
        ("form", "g76".into()),
    ]);
    let g = wasm::wizard_generate(req).unwrap();
    let program = get(&g, "program").as_string().unwrap();
    assert!(program.contains("(M30x2-6g") && program.contains("G76"), "{program}");
    assert!(close(num(&get(&g, "spec"), "lead"), 2.0));
    let r = plan(&program, "gsk980tdc");
    assert_eq!(num(&r, "alarms"), 0.0, "{program}");
    let threads = array(&get(&r, "threads"));
    assert_eq!(threads.len(), 1);
    let gauge = get(&get(&threads[0], "shop"), "gauge");
    assert_eq!(get(&gauge, "ok").as_bool(), Some(true), "{program}");
    let d2 = num(&gauge, "pitch_diameter");
    assert!((28.493..=28.663).contains(&d2), "d2 {d2}");
    // The notes in the request's language; the program is the same.
    let notes =
        |g: &JsValue| -> Vec<String> { array(&get(g, "notes")).iter().map(|n| n.as_string().unwrap()).collect() };
    let mut zh_req = Vec::from([("designation", "M30x2-6g".into()), ("length", 30.0.into())]);
    zh_req.extend([("dialect", "gsk980tdc".into()), ("form", "g76".into()), ("lang", "zh".into())]);
    let zh = wasm::wizard_generate(object(&zh_req)).unwrap();
    assert_eq!(get(&zh, "program").as_string().unwrap(), program);
    assert!(notes(&g).iter().any(|n| n.starts_with("the last pass puts the pitch diameter")), "{:?}", notes(&g));
    assert!(notes(&zh).iter().any(|n| n.starts_with("最后一刀使中径落在公差带中间")), "{:?}", notes(&zh));
}

#[wasm_bindgen_test]
fn a_bad_wizard_request_is_named() {
    let bad = |fields: &[(&str, JsValue)]| message(wasm::wizard_generate(object(fields)).unwrap_err());
    let e = bad(&[("designation", "M30x2".into()), ("length", "abc".into())]);
    assert!(e.contains("length: not a number"), "{e}");
    let e = bad(&[
        ("designation", "M30x2".into()),
        ("length", 30.0.into()),
        ("dialect", "fanuc0i".into()),
        ("form", "g78".into()),
    ]);
    assert!(e.contains("has no") && e.contains("G78"), "{e}");
    let e = bad(&[("designation", "M30x2".into()), ("dialect", "fanuc0i".into()), ("lang", "zh".into())]);
    assert_eq!(e, "请给出螺纹终点 Z 或螺纹长度");
    let e = bad(&[("designation", "M30x2".into()), ("length", 30.0.into()), ("starts", 0.5.into())]);
    assert!(e.contains("starts"), "{e}");
    let e = bad(&[("designation", "x".repeat(300).into()), ("length", 30.0.into())]);
    assert!(e.contains("200 characters"), "{e}");
}

/// O1006 (seed 004) expanded to LinuxCNC G33 blocks plans again as LinuxCNC
/// with the same five passes: X47.1 … X45.4, Z70 to Z13.
#[wasm_bindgen_test]
fn a_plan_expands_to_blocks_for_another_controller() {
    let e = wasm::expand(O1006, "gsk980tdc", "", "linuxcnc", None).unwrap();
    let program = get(&e, "program").as_string().unwrap();
    assert!(program.contains("G33 X47.1 Z13 K2"), "{program}");
    let r = plan(&program, "linuxcnc");
    assert_eq!(num(&r, "alarms"), 0.0, "{program}");
    let passes = get(&r, "passes");
    let x: Vec<f64> = js_sys::Float64Array::from(get(&passes, "x")).to_vec();
    assert_close(&x, &[47.1, 46.5, 45.9, 45.5, 45.4]);
    let z: Vec<f64> = js_sys::Float64Array::from(get(&passes, "zEnd")).to_vec();
    assert_close(&z, &[13.0; 5]);
    assert!(message(wasm::expand(O1006, "gsk980tdc", "", "bogus", None).unwrap_err()).contains("unknown dialect"));
    assert!(message(wasm::expand(O1006, "bogus", "", "linuxcnc", None).unwrap_err()).contains("unknown dialect"));
    // Notes in the language asked for: Renhe has no G96 and writes a G30 tail.
    let css = "G00 X58 Z70\nG96 S120 M03\nG00 X47.1\nG32 Z13 F2\nG00 X58\nZ70\nM30\n";
    let notes = |lang: Option<&str>| -> Vec<String> {
        let e = wasm::expand(css, "gsk980tdc", "", "gsk980tdc", lang.map(String::from)).unwrap();
        array(&get(&e, "notes")).iter().map(|n| n.as_string().unwrap()).collect()
    };
    let en = notes(None);
    assert!(en.iter().any(|n| n.starts_with("constant surface speed (G96) is not written")), "{en:?}");
    let zh = notes(Some("zh"));
    assert!(zh.iter().any(|n| n.starts_with("恒线速（G96）没有写出")), "{zh:?}");
}

/// The settings given are the plan's: O1006 read with X as a radius
/// (`x_mode=radius`, the controllers' DIA parameter) cuts twice the
/// diameter, X94.2 for X47.1 (what `screwcut expand --set x_mode=radius`
/// writes).
#[wasm_bindgen_test]
fn an_expansion_plans_with_the_settings_given() {
    let program = |settings: &str| -> String {
        let e = wasm::expand(O1006, "gsk980tdc", settings, "linuxcnc", None).unwrap();
        get(&e, "program").as_string().unwrap()
    };
    assert!(program("").contains("G33 X47.1 Z13 K2"));
    let radius = program("x_mode=radius");
    assert!(radius.contains("G33 X94.2 Z13 K2") && !radius.contains("X47.1"), "{radius}");
}
