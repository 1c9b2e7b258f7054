//! Plans, diagnostics and settings through the binding.

use js_sys::{Float64Array, JSON, JsString};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

#[wasm_bindgen_test]
fn dialects_are_listed_with_titles() {
    let list = array(&wasm::dialects().unwrap());
    let names: Vec<String> = list.iter().map(|d| get(d, "name").as_string().unwrap()).collect();
    assert_eq!(names, ["gsk980tdc", "fanuc0i", "renhe", "linuxcnc"]);
    for d in &list {
        let title = get(d, "title").as_string().unwrap();
        assert!(title.len() > 3, "{title}");
    }
}

#[wasm_bindgen_test]
fn settings_tables_follow_the_dialect() {
    let find = |dialect: &str, name: &str| {
        array(&wasm::settings_table(dialect).unwrap())
            .into_iter()
            .find(|s| get(s, "name").as_string().as_deref() == Some(name))
    };
    let a = find("gsk980tdc", "No.058").expect("GSK has No.058");
    assert_eq!(get(&a, "kind").as_string().as_deref(), Some("int"));
    assert_eq!((num(&a, "default"), num(&a, "min"), num(&a, "max")), (60.0, 0.0, 99.0));
    assert!(get(&a, "help").as_string().unwrap().contains("Tool (thread) angle"));
    assert!(!get(&a, "help_zh").as_string().unwrap().is_empty());
    let x = find("gsk980tdc", "x_mode").unwrap();
    assert_eq!(get(&x, "kind").as_string().as_deref(), Some("choice"));
    let choices: Vec<String> = array(&get(&x, "choices")).iter().map(|c| c.as_string().unwrap()).collect();
    assert_eq!(choices, ["diameter", "radius"]);
    assert!(find("fanuc0i", "3401#0").is_some() && find("fanuc0i", "5130").is_some());
    assert!(find("fanuc0i", "No.058").is_none(), "GSK parameters are not Fanuc's");
    assert!(find("renhe", "renhe.runout").is_some());
    // The text settings too: the insert is free text up to 40 bytes.
    let insert = find("fanuc0i", "tool.insert").expect("the insert setting");
    assert_eq!((get(&insert, "kind").as_string().as_deref(), num(&insert, "max")), (Some("text"), 40.0));
    let e = message(wasm::settings_table("bogus").unwrap_err());
    assert!(e.contains("unknown dialect 'bogus'") && e.contains("gsk980tdc"), "{e}");
}

#[wasm_bindgen_test]
fn o1006_plans_five_passes_to_the_last_digit() {
    let r = plan(O1006, "gsk980tdc", "");
    assert_eq!(get(&r, "dialect").as_string().as_deref(), Some("gsk980tdc"));
    assert_eq!(get(&r, "units").as_string().as_deref(), Some("mm"));
    assert_eq!((num(&r, "alarms"), num(&r, "warnings"), num(&r, "notes"), num(&r, "moves")), (0.0, 0.0, 2.0, 21.0));
    assert_eq!(get(&r, "good").as_bool(), Some(true));
    assert_eq!(num(&r, "thread"), 0.0);
    let threads: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!(threads.len(), 1);
    let t = &threads[0];
    assert_eq!((t.line, t.end_line, t.source.as_str(), t.kind.as_str()), (5, 24, "g32", "straight"));
    assert_eq!((t.lead, t.pitch, t.starts, t.internal, t.passes), (2.0, 2.0, 1, false, 5));
    assert_eq!((t.crest, t.crest_source.as_str(), t.height), (48.0, "assumed", 1.3));
    let passes: Vec<PassInfo> = passes(&r, "passes");
    let xs: Vec<f64> = passes.iter().map(|p| p.from[0]).collect();
    assert_close(&xs, &[47.1, 46.5, 45.9, 45.5, 45.4]);
    assert_close(&passes.iter().map(|p| p.depth).collect::<Vec<_>>(), &[0.45, 0.75, 1.05, 1.25, 1.3]);
    assert_close(&passes.iter().map(|p| p.infeed).collect::<Vec<_>>(), &[0.45, 0.3, 0.3, 0.2, 0.05]);
    let roles: Vec<&str> = passes.iter().map(|p| p.role.as_str()).collect();
    assert_eq!(roles, ["rough", "rough", "rough", "rough", "finish"]);
    for (k, p) in passes.iter().enumerate() {
        assert_eq!((p.start, p.index), (1, k as u32 + 1));
        assert_eq!((p.from[1], p.to[1], p.to[0]), (70.0, 13.0, p.from[0]));
        let first = 5 + 4 * k as u32;
        assert_eq!(p.lines, [first, first + 1, first + 2, first + 3]);
        assert!(p.area.unwrap() > 0.0 && p.shift == 0.0 && p.angle == 0.0);
    }
    // The per-pass figures are the table's columns, not repeated in the thread summary.
    let shop = get(&array(&get(&r, "threads"))[0], "shop");
    assert_eq!((array(&get(&shop, "chip")).len(), array(&get(&shop, "pass_time_s")).len()), (0, 0));
    assert!((num(&shop, "cut_time_s") - 28.5).abs() < 1e-9, "O1006 at S300: 5 × 57 mm at 600 mm/min");
    let diags: Vec<Diag> = field(&r, "diagnostics");
    let codes: Vec<&str> = diags.iter().map(|d| d.code.as_str()).collect();
    assert_eq!(codes, ["crest-assumed", "infeed-guidance"]);
    assert!(diags.iter().all(|d| d.severity == "info" && d.line == 5 && d.column == 1));
}

#[wasm_bindgen_test]
fn cycles_plan_their_passes() {
    // G76 on Fanuc: Δd·√n, clamped at k − d, finishing at k.
    let r = plan(G76_FANUC, "fanuc0i", "");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!(
        (t[0].source.as_str(), t[0].lead, t[0].height, t[0].crest, t[0].crest_source.as_str()),
        ("g76", 6.0, 3.68, 68.0, "cycle")
    );
    let p: Vec<PassInfo> = passes(&r, "passes");
    assert_close(&p.iter().map(|p| p.depth).collect::<Vec<_>>(), &[1.8, 2.545584, 3.117691, 3.48, 3.68]);
    assert_eq!(p.last().unwrap().role, "finish");
    // G78 degressive: 0.4, 0.4√2, 0.4√3, 0.8, then steps of Δdmin 0.1 to 1.25, finish 1.3 and a spring pass.
    let r = plan(G78_M30X2, "gsk980tdc", "");
    let p: Vec<PassInfo> = passes(&r, "passes");
    let depths: Vec<f64> = p.iter().map(|p| p.depth).collect();
    assert_close(&depths, &[0.4, 0.565685, 0.69282, 0.8, 0.9, 1.0, 1.1, 1.2, 1.25, 1.3, 1.3]);
    let roles: Vec<&str> = p.iter().map(|p| p.role.as_str()).collect();
    assert_eq!(&roles[8..], ["rough", "finish", "spring"]);
    assert!(p.iter().all(|p| p.runout_to.is_some()), "No.019 gives every pass a run-out");
    // G78 alternating flanks: the shift changes side every pass; the screw-in starts E = 0.3 further out.
    let r = plan(G78_ALTERNATING, "gsk980tdc", "");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!(t[0].infeed, "alternating");
    let p: Vec<PassInfo> = passes(&r, "passes");
    let shifts: Vec<f64> = p.iter().map(|p| p.shift).collect();
    assert!(shifts[..4].windows(2).all(|w| w[0] * w[1] < 0.0), "{shifts:?}");
    let tan30 = 30f64.to_radians().tan();
    assert!(close(shifts[0].abs(), (1.3 - 0.3) * tan30), "{shifts:?}");
    let s = p[0].screw_in_from.expect("a screw-in");
    assert!(close(s[0], p[0].from[0] + 0.6), "{s:?} from {:?}", p[0].from);
    // G92 two starts: every pass twice, 180° apart.
    let r = plan(G92_TWO_START, "gsk980tdc", "");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!((t[0].source.as_str(), t[0].starts, t[0].lead, t[0].pitch, t[0].passes), ("g92", 2, 3.0, 1.5, 8));
    let p: Vec<PassInfo> = passes(&r, "passes");
    let starts: Vec<(u32, f64)> = p.iter().map(|p| (p.start, p.angle)).collect();
    assert_eq!(starts[..2], [(1, 0.0), (2, 180.0)]);
    assert_close(&p.iter().step_by(2).map(|p| p.from[0]).collect::<Vec<_>>(), &[23.2, 22.6, 22.2, 22.05]);
}

#[wasm_bindgen_test]
fn renhe_tails_and_moves() {
    let r = plan(RENHE_TAILS, "renhe", "");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!(t.len(), 2);
    assert_eq!((t[0].source.as_str(), t[0].pitch, t[1].pitch), ("renhe", 1.5, 2.0));
    // moves(): seven numbers per motion of the last plan.
    let m = wasm::moves().to_vec();
    assert_eq!(m.len(), 7 * num(&r, "moves") as usize);
    let rows: Vec<&[f64]> = m.chunks_exact(7).collect();
    // The spiral tail G30 U10 W2: the thread from X34 to Z-28, then retracting 10 on the diameter over the last 2.
    let tail = rows.iter().find(|m| m[0] == 4.0).expect("a run-out");
    assert_eq!(tail[1..6], [34.0, -28.0, 44.0, -30.0, 5.0]);
    let cut = rows.iter().find(|m| m[0] == 3.0).unwrap();
    assert_eq!(cut[1..6], [34.0, 10.0, 34.0, -28.0, 5.0]);
    // The second thread has the standard tail: 1.2 mm radial at 45°.
    let tails: Vec<&&[f64]> = rows.iter().filter(|m| m[0] == 4.0).collect();
    assert_eq!(tails.len(), 2);
    assert!(close(tails[1][3] - tails[1][1], 2.4) && close(tails[1][2] - tails[1][4], 1.2), "{:?}", tails[1]);
}

#[wasm_bindgen_test]
fn diagnostics_carry_utf16_positions() {
    // O1006's first diagnostic is at line 5 column 1; its UTF-16 offset is
    // smaller than its byte offset (Chinese comments above it).
    let r = plan(O1006, "gsk980tdc", "");
    let d: Vec<Diag> = field(&r, "diagnostics");
    let js = JsString::from(O1006);
    assert_eq!(d[0].from as i32, js_index_of(&js, "N30 X47.1"));
    assert_eq!(d[0].from, 69);
    assert!(O1006.find("N30 X47.1").unwrap() > 69);
    // A malformed number after full-width letters and characters outside the BMP.
    let text = "(注释 😀😀)\nＧ００ X10 Z5\nG00 X1.2.3 Z5 (🔩)\n";
    let r = plan(text, "gsk980tdc", "");
    let d: Vec<Diag> = field(&r, "diagnostics");
    let bad = d.iter().find(|d| d.code == "malformed-number").expect("a malformed number");
    assert_eq!((bad.severity.as_str(), bad.line, bad.column), ("error", 3, 6));
    let js = JsString::from(text);
    let at = js_index_of(&js, "1.2.3") as u32;
    assert_eq!((bad.from, bad.to), (at, at + 5));
    assert_eq!(String::from(js.slice(bad.from, bad.to)), "1.2.3");
    let full = d.iter().find(|d| d.code == "full-width").expect("full-width input is noted");
    assert_eq!((full.line, full.from), (2, js_index_of(&js, "Ｇ") as u32));
    assert_eq!(num(&r, "alarms"), 1.0);
    assert_eq!(get(&r, "good").as_bool(), Some(false));
}

#[wasm_bindgen_test]
fn lone_surrogates_keep_positions_aligned() {
    // A JS string that is not valid UTF-16: the conversion replaces each lone
    // surrogate by U+FFFD, one unit for one, so the offsets still index the editor's text.
    let mut units: Vec<u16> = "(".encode_utf16().collect();
    units.extend([0xD800, 0x41, 0xDC00, 0xDBFF]);
    units.extend(")\nG00 X10 Z5\nG32 Z-20 F2 X1.2.3\n".encode_utf16());
    let js = JsString::from_char_code(&units);
    assert!(!js.is_valid_utf16());
    let text = JsValue::from(js.clone()).as_string().unwrap();
    assert_eq!(text.encode_utf16().count(), units.len());
    assert_eq!(text.matches('\u{FFFD}').count(), 3);
    let r = plan(&text, "gsk980tdc", "");
    let d: Vec<Diag> = field(&r, "diagnostics");
    let bad = d.iter().find(|d| d.code == "malformed-number").expect("a malformed number");
    assert_eq!(String::from(js.slice(bad.from, bad.to)), "1.2.3");
    assert_eq!((bad.line, bad.column), (3, 14));
}

#[wasm_bindgen_test]
fn unchanged_diagnostics_are_not_sent_again() {
    let r = plan(O1006, "gsk980tdc", "");
    let key = num(&r, "diagnosticsKey");
    assert!(key >= 0.0 && key < 2f64.powi(52) && key.fract() == 0.0);
    let again = wasm::update(O1006, "gsk980tdc", "", 0, 1, key, None).unwrap();
    assert!(get(&again, "diagnostics").is_null());
    // A comment edit moves offsets but not lines and columns: the key stays.
    let edited = O1006.replace("N15 S300 M03 T0101;", "N15 S300 M03 T0101; (spindle)");
    let r2 = wasm::update(&edited, "gsk980tdc", "", 0, 1, key, None).unwrap();
    assert!(get(&r2, "diagnostics").is_null());
    // A new alarm changes it: the caller holds the list answered last, so it is sent the change.
    let broken = O1006.replace("X46.5", "X46..5");
    let r3 = wasm::update(&broken, "gsk980tdc", "", 0, 1, key, None).unwrap();
    assert_ne!(num(&r3, "diagnosticsKey"), key);
    assert!(get(&r3, "diagnostics").is_null());
    let d: Vec<Diag> = field(&get(&r3, "diagnosticsSplice"), "items");
    assert!(d.iter().any(|d| d.code == "malformed-number" && d.line == 9));
}

#[wasm_bindgen_test]
fn settings_are_applied_or_refused_with_a_reason() {
    // d = D − 1.2·P instead of 1.3·P: the assumed crest moves and every depth with it.
    let r = plan(O1006, "gsk980tdc", "textbook.depth_factor=1.2");
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert!(close(t[0].crest, 47.8));
    let p: Vec<PassInfo> = passes(&r, "passes");
    assert!(close(p[0].depth, 0.35) && close(p[4].depth, 1.2));
    assert!(array(&get(&r, "settingErrors")).is_empty());
    // Refused lines are listed, the rest applies.
    let lines = "No.999=1\nx_mode=sideways\n  No.058=200  \nfoo\n=3\n\ntextbook.depth_factor=1.2";
    let r = plan(O1006, "gsk980tdc", lines);
    let errors: Vec<SettingError> = field(&r, "settingErrors");
    let names: Vec<&str> = errors.iter().map(|e| e.setting.as_str()).collect();
    assert_eq!(names, ["No.999", "x_mode", "No.058", "foo", ""]);
    assert!(errors[0].message.contains("unknown setting"), "{}", errors[0].message);
    assert!(errors[1].message.contains("'sideways' is not a valid value"), "{}", errors[1].message);
    assert!(errors[2].message.contains("outside 0..99"), "{}", errors[2].message);
    assert!(errors[3].message.contains("NAME=VALUE"), "{}", errors[3].message);
    let t: Vec<ThreadInfo> = field(&r, "threads");
    assert!(close(t[0].crest, 47.8), "the good line still applies");
    // A parameter of another controller is refused; names are per dialect.
    let r = plan("G32 Z1\n", "fanuc0i", "No.058=55\n5143=200\nx_mode=radius");
    let errors: Vec<SettingError> = field(&r, "settingErrors");
    assert_eq!(errors.iter().map(|e| e.setting.as_str()).collect::<Vec<_>>(), ["No.058", "5143"]);
    // A parameter changes a cycle: No.058 gives G78 its angle when P has only m and r.
    let g78 = "G00 X35 Z5\nG78 Q100 R0.05 D1\nG78 X27.4 Z-30 P1300 Q400 F2\n";
    let a: Vec<ThreadInfo> = field(&plan(g78, "gsk980tdc", "No.058=55"), "threads");
    let b: Vec<ThreadInfo> = field(&plan(g78, "gsk980tdc", ""), "threads");
    assert_eq!((a[0].tool_angle, b[0].tool_angle), (55.0, 60.0));
}

#[wasm_bindgen_test]
fn limits_are_alarms_with_numbers() {
    let r = plan(G78_M30X2, "gsk980tdc", "limits.passes_per_start=3");
    let d: Vec<Diag> = field(&r, "diagnostics");
    let limit = d.iter().find(|d| d.code == "pass-limit").expect("a pass-limit alarm");
    assert_eq!(limit.severity, "error");
    assert!(limit.message.contains('3'), "{}", limit.message);
    assert_eq!(get(&r, "good").as_bool(), Some(false));
    let big = O1006.repeat(10);
    let r = plan(&big, "gsk980tdc", "limits.program_bytes=1000");
    let d: Vec<Diag> = field(&r, "diagnostics");
    assert!(d.iter().any(|d| d.code == "program-too-large" && d.severity == "error"), "{d:?}");
}

#[wasm_bindgen_test]
fn plan_json_is_the_cli_schema() {
    let v = wasm::plan_value(O0009, "gsk980tdc", "").unwrap();
    // The same document the CLI writes with --json, value for value.
    let cli = JSON::parse(&crate::plan(O0009, &crate::Settings::new(crate::Dialect::Gsk980tdc)).to_json()).unwrap();
    assert_eq!(JSON::stringify(&v).unwrap(), JSON::stringify(&cli).unwrap());
    assert_eq!(get(&v, "dialect").as_string().as_deref(), Some("gsk980tdc"));
    let threads = array(&get(&v, "threads"));
    assert_eq!(get(&threads[0], "kind").as_string().as_deref(), Some("taper"));
    let passes = array(&get(&threads[0], "passes"));
    assert_eq!(passes.len(), 2);
    let from = Float64Array::new(&get(&passes[0], "from")).to_vec();
    let to = Float64Array::new(&get(&passes[0], "to")).to_vec();
    assert_close(&from, &[27.4286, 3.0]);
    assert_close(&to, &[48.8571, -72.0]);
    assert!(!array(&get(&v, "moves")).is_empty());
    assert!(message(wasm::plan_value("G32", "nope", "").unwrap_err()).contains("unknown dialect"));
    // Pasted LinuxCNC code under Fanuc (tests/diagnostics.rs): the plan names the dialect that
    // reads it, as `screwcut plan --json` does (src/hint.rs).
    let pasted = "G18 G21 G90\nM3 S500\nG0 X30 Z5\nG76 P2 Z-30 I-1 J0.3 K1.23\nM2\n";
    let v = wasm::plan_value(pasted, "fanuc0i", "").unwrap();
    let codes: Vec<String> =
        array(&get(&v, "diagnostics")).iter().map(|d| get(d, "code").as_string().unwrap_or_default()).collect();
    assert!(codes.iter().any(|c| c == "dialect-hint"), "{codes:?}");
}

#[wasm_bindgen_test]
fn embeds_sharing_one_instance_do_not_see_each_other() {
    // Two previews on a page plan in turn on one instance: each result is its own.
    let a1 = plan(O1006, "gsk980tdc", "");
    let b = plan(G76_FANUC, "fanuc0i", "");
    let a2 = plan(O1006, "gsk980tdc", "");
    assert_eq!(shown_key(&a1, 0), shown_key(&a2, 0));
    assert_ne!(shown_key(&a1, 0), shown_key(&b, 0));
    let pa: Vec<PassInfo> = passes(&a2, "passes");
    let pb: Vec<PassInfo> = passes(&b, "passes");
    assert_eq!((pa.len(), pb.len()), (5, 5));
    assert!(close(pb[0].depth, 1.8));
    // thread_scenes works on the last plan (O1006 again).
    let s = wasm::thread_scenes(0, 1).unwrap();
    let p: Vec<PassInfo> = passes(&s, "passes");
    assert!(close(p[0].from[0], 47.1));
}
