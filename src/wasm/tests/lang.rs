//! Messages in the page's language through a session: diagnostics in
//! Chinese after `set_lang("zh")`, their key changed with the language,
//! `relabel` switching without planning, and the thread check's notes in
//! both languages in every thread summary.

use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

/// The thread list of an answer, with each summary's notes in `lang`.
fn notes(r: &JsValue, lang: &str) -> Vec<Vec<String>> {
    let list: Vec<serde_json::Value> = field(r, "threads");
    list.iter()
        .map(|t| {
            let a = t["notes"][lang].as_array();
            a.map_or(Vec::new(), |a| a.iter().map(|n| n.as_str().unwrap().to_string()).collect())
        })
        .collect()
}

const CHECKED: &str =
    "(M48x2-6g)\nG00 X58 Z70\nS300 M03\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\nM30\n";

#[wasm_bindgen_test]
fn diagnostics_and_notes_in_chinese() {
    let s = wasm::Session::new();
    let en = s.update(Some(O1006.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    let d: Vec<Diag> = field(&en, "diagnostics");
    assert!(d[0].message.starts_with("the program does not turn this thread's major diameter"), "{d:?}");
    s.set_lang("zh");
    let key = num(&en, "diagnosticsKey");
    let zh = s.update(Some(O1006.into()), "gsk980tdc", "", 0, 1, key, None, false, false).unwrap();
    assert_ne!(num(&zh, "diagnosticsKey"), key, "the language is part of the key");
    let d: Vec<Diag> = field(&zh, "diagnostics");
    assert_eq!(d[0].code, "crest-assumed");
    assert!(d[0].message.starts_with("程序没有车出这个螺纹的大径"), "{d:?}");
    assert_eq!((d[0].line, d[0].column), (5, 1));
    // The thread check's notes come in both languages, whatever the session's.
    for lang in ["zh", "en"] {
        s.set_lang(lang);
        let r = s.update(Some(CHECKED.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
        let (zh, en) = (notes(&r, "zh"), notes(&r, "en"));
        assert!(zh[0].iter().any(|x| x.contains("程序没有车出大径")), "{zh:?}");
        assert!(en[0].iter().any(|x| x.contains("does not turn the major diameter")), "{en:?}");
        assert!(zh[0].iter().all(|x| !x.contains(" the ")), "{zh:?}");
    }
}

#[wasm_bindgen_test]
fn relabel_switches_without_planning() {
    let s = wasm::Session::new();
    let known = Some(vec![-1.0; 2]);
    let en = s.update(Some(CHECKED.into()), "gsk980tdc", "", 0, 1, -1.0, known, false, false).unwrap();
    s.set_lang("zh");
    let zh = s.relabel().unwrap();
    assert_ne!(num(&zh, "diagnosticsKey"), num(&en, "diagnosticsKey"));
    assert!(get(&zh, "threads").is_undefined(), "thread summaries carry both languages: nothing to relabel");
    let d: Vec<Diag> = field(&zh, "diagnostics");
    assert!(d.iter().any(|d| d.code == "gauge-fail" || d.code == "gauge-ok"), "{d:?}");
    assert!(d.iter().all(|d| !d.message.contains(" the ")), "{d:?}");
    // The next update of the same text in Chinese has the relabelled key and
    // the threads' key of the English answer: nothing is sent again.
    let held = vec![num(&en, "threadsKey"), -1.0];
    let again = s
        .update(Some(CHECKED.into()), "gsk980tdc", "", 0, 1, num(&zh, "diagnosticsKey"), Some(held), false, false)
        .unwrap();
    assert!(get(&again, "diagnostics").is_null());
    assert!(get(&again, "threads").is_null());
    // Back to English: the English list again.
    s.set_lang("en");
    let back = s.relabel().unwrap();
    assert_eq!(num(&back, "diagnosticsKey"), num(&en, "diagnosticsKey"));
    assert!(wasm::Session::new().relabel().is_err());
}
