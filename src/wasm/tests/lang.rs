//! Messages in the page's language through a session: diagnostics and the
//! thread check's notes in Chinese after `set_lang("zh")`, their keys
//! changed with the language, and `relabel` switching without planning.

use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

/// The thread list of an answer, with each summary's notes.
fn notes(r: &JsValue) -> Vec<Vec<String>> {
    let list: Vec<serde_json::Value> = field(r, "threads");
    list.iter()
        .map(|t| {
            t["notes"].as_array().map_or(Vec::new(), |a| a.iter().map(|n| n.as_str().unwrap().to_string()).collect())
        })
        .collect()
}

const CHECKED: &str =
    "(M48x2-6g)\nG00 X58 Z70\nS300 M03\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX45.4\nG32 Z13\nG00 X58\nZ70\nM30\n";

#[wasm_bindgen_test]
fn diagnostics_and_notes_in_chinese() {
    let s = wasm::Session::new();
    let en = s.update(O1006, "gsk980tdc", "", 0, 1, -1.0, None).unwrap();
    let d: Vec<Diag> = field(&en, "diagnostics");
    assert!(d[0].message.starts_with("the program does not turn this thread's major diameter"), "{d:?}");
    s.set_lang("zh");
    let key = num(&en, "diagnosticsKey");
    let zh = s.update(O1006, "gsk980tdc", "", 0, 1, key, None).unwrap();
    assert_ne!(num(&zh, "diagnosticsKey"), key, "the language is part of the key");
    let d: Vec<Diag> = field(&zh, "diagnostics");
    assert_eq!(d[0].code, "crest-assumed");
    assert!(d[0].message.starts_with("程序没有车出这个螺纹的大径"), "{d:?}");
    assert_eq!((d[0].line, d[0].column), (5, 1));
    // The thread check's notes come in the session's language.
    let r = s.update(CHECKED, "gsk980tdc", "", 0, 1, -1.0, None).unwrap();
    let n = notes(&r);
    assert!(n[0].iter().any(|x| x.contains("程序没有车出大径")), "{n:?}");
    s.set_lang("en");
    let r = s.update(CHECKED, "gsk980tdc", "", 0, 1, -1.0, None).unwrap();
    assert!(notes(&r)[0].iter().any(|x| x.contains("does not turn the major diameter")), "{:?}", notes(&r));
}

#[wasm_bindgen_test]
fn relabel_switches_without_planning() {
    let s = wasm::Session::new();
    let known = Some(vec![-1.0; 5]);
    let en = s.update(CHECKED, "gsk980tdc", "", 0, 1, -1.0, known).unwrap();
    s.set_lang("zh");
    let zh = s.relabel().unwrap();
    assert_ne!(num(&zh, "diagnosticsKey"), num(&en, "diagnosticsKey"));
    assert_ne!(num(&zh, "threadsKey"), num(&en, "threadsKey"));
    let d: Vec<Diag> = field(&zh, "diagnostics");
    assert!(d.iter().any(|d| d.code == "gauge-fail" || d.code == "gauge-ok"), "{d:?}");
    assert!(d.iter().all(|d| !d.message.contains(" the ")), "{d:?}");
    assert!(notes(&zh)[0].iter().all(|x| !x.contains(" the ")), "{:?}", notes(&zh));
    // The next update of the same text in Chinese has the relabelled keys: nothing is sent again.
    let held = vec![num(&zh, "threadsKey"), -1.0, -1.0, -1.0, -1.0];
    let again = s.update(CHECKED, "gsk980tdc", "", 0, 1, num(&zh, "diagnosticsKey"), Some(held)).unwrap();
    assert!(get(&again, "diagnostics").is_null());
    assert!(get(&again, "threads").is_null());
    // Back to English: the English lists again.
    s.set_lang("en");
    let back = s.relabel().unwrap();
    assert_eq!(num(&back, "diagnosticsKey"), num(&en, "diagnosticsKey"));
    assert_eq!(num(&back, "threadsKey"), num(&en, "threadsKey"));
    assert!(wasm::Session::new().relabel().is_err());
}
