//! Incremental updates: the kept planner re-reads only from the last
//! snapshot before an edit and must answer exactly as a plan from scratch;
//! parts the caller has (by key) are not sent again.

use js_sys::Float64Array;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

/// `threads` O1006-style threads of two passes, each turned first on its own
/// diameter: 13 lines each, 4 more around them.
fn program(threads: usize) -> String {
    crate::wasm::memo::tests::turned_threads("O2000\nG50 X100 Z100\nS300 M03 T0101\n", threads, 20)
}

/// `text` with its line `n` (1-based; negative: from the end, −1 the last) changed by `f`.
fn edit_line(text: &str, n: isize, f: impl Fn(&str) -> String) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let i = if n < 0 { lines.len() - n.unsigned_abs() } else { n as usize - 1 };
    lines[i] = f(&lines[i]);
    lines.join("\n") + "\n"
}

/// Every key and value of an answer that the app reads, and the scenes
/// session `s` (the default one when none) shows, decoded for comparison.
fn snapshot_in(r: &JsValue, s: Option<&wasm::Session>) -> String {
    let diags: Vec<Diag> = field(r, "diagnostics");
    let threads: Vec<ThreadInfo> = field(r, "threads");
    let passes: Vec<PassInfo> = passes(r, "passes");
    let scene_text = |view: &str| {
        let sc = match s {
            Some(s) => s.shown_scene(view),
            None => wasm::default_scene(view),
        };
        sc.map_or("null".to_string(), |sc| format!("{:?}", decode(&sc)))
    };
    let keys: Vec<f64> = ["diagnosticsKey", "threadsKey", "passesKey"].iter().map(|k| num(r, k)).collect();
    let shown = Float64Array::from(get(r, "shown")).to_vec();
    format!(
        "{:?}|{diags:?}|{threads:?}|{passes:?}|{}|{}|{}|{keys:?}|{shown:?}|{}",
        [num(r, "alarms"), num(r, "warnings"), num(r, "notes"), num(r, "moves")],
        scene_text("side"),
        scene_text("tooth"),
        scene_text("starts"),
        get(r, "thread").as_f64().unwrap_or(-1.0),
    )
}

/// [`snapshot_in`] of the default session.
fn snapshot(r: &JsValue) -> String {
    snapshot_in(r, None)
}

/// Plans `text` from scratch: another text first, so that nothing is reused.
fn from_scratch(text: &str, dialect: &str, settings: &str) -> JsValue {
    plan("%", dialect, settings);
    let r = plan(text, dialect, settings);
    assert_eq!(num(&r, "resumedAt"), 1.0);
    r
}

#[wasm_bindgen_test]
fn incremental_updates_equal_full_ones() {
    // 784 lines; the planner keeps snapshots at blocks 257, 513 and 769.
    let base = program(60);
    assert_eq!(base.lines().count(), 784);
    let last_pass_x = -9; // the last thread's first pass: X48.1
    assert_eq!(base.lines().nth(784 - 9), Some("X48.1"));
    let edits: Vec<(String, bool)> = vec![
        // (text, whether the edit is late enough to resume past the top)
        (edit_line(&base, last_pass_x, |_| "X48.0".into()), true),
        (edit_line(&base, -1, |l| format!("G00 X60 Z80\n{l}")), true),
        (edit_line(&base, 2, |l| format!("{l} (top)")), false),
        (edit_line(&base, 9, |_| "X29.2".into()), false),
        (edit_line(&base, -1, |_| "G00 X70\nX66.1\nG32 Z40 F3\nG00 X72\nM30".into()), true),
        (base[..base.len() / 2].to_string(), true),
        (base.replacen("G32 Z13 F2", "G32 Z13 F2.5", 50), false),
        (edit_line(&base, last_pass_x, |_| "X48..1".into()), true), // an alarm near the end
        (edit_line(&base, 400, |_| String::new()), true),           // a line emptied
        (edit_line(&base, 300, |l| format!("{l}\n\n")), true),      // lines inserted
    ];
    for (k, (text, late)) in edits.iter().enumerate() {
        plan(&base, "gsk980tdc", "");
        let inc = plan(text, "gsk980tdc", "");
        let resumed = num(&inc, "resumedAt");
        assert_eq!(resumed > 1.0, *late, "edit {k} resumed at line {resumed}");
        let inc = snapshot(&inc);
        let full = snapshot(&from_scratch(text, "gsk980tdc", ""));
        assert_eq!(inc, full, "edit {k}");
    }
    // An alarm near the end is in the incremental answer too.
    plan(&base, "gsk980tdc", "");
    let r = plan(&edits[7].0, "gsk980tdc", "");
    assert_eq!(num(&r, "alarms"), 1.0);
    let d: Vec<Diag> = field(&r, "diagnostics");
    assert!(d.iter().any(|d| d.code == "malformed-number" && d.line == 776), "{d:?}");
}

#[wasm_bindgen_test]
fn a_settings_change_plans_from_the_top() {
    let text = program(40);
    plan(&text, "gsk980tdc", "");
    let r = plan(&text, "gsk980tdc", "No.058=55");
    assert_eq!(num(&r, "resumedAt"), 1.0);
    assert_eq!(snapshot(&r), snapshot(&from_scratch(&text, "gsk980tdc", "No.058=55")));
    let threads: Vec<ThreadInfo> = field(&r, "threads");
    assert_eq!(threads[0].tool_angle, 55.0);
    // The same settings again: a late edit resumes.
    let r = plan(&format!("{text}G00 X80\n"), "gsk980tdc", "No.058=55");
    assert!(num(&r, "resumedAt") > 1.0);
    // Another dialect plans from the top as well.
    let r = plan(&text, "fanuc0i", "");
    assert_eq!(num(&r, "resumedAt"), 1.0);
    assert_eq!(snapshot(&r), snapshot(&from_scratch(&text, "fanuc0i", "")));
}

/// `update` with everything the last answer `r` carried as known.
fn again(text: &str, r: &JsValue, thread: i32, start: u32) -> JsValue {
    let known = ["threadsKey", "passesKey"].iter().map(|k| num(r, k)).collect();
    wasm::update(text, "gsk980tdc", "", thread, start, num(r, "diagnosticsKey"), Some(known))
        .unwrap_or_else(|e| panic!("{}", message(e)))
}

const PARTS: [&str; 2] = ["threads", "passes"];

fn sent(r: &JsValue) -> Vec<&'static str> {
    PARTS.iter().copied().filter(|p| !get(r, p).is_null()).collect()
}

/// The views whose scene changed from answer `a` to answer `b` (their keys differ).
fn redrawn(a: &JsValue, b: &JsValue) -> Vec<&'static str> {
    let views = ["side", "tooth", "starts"];
    (0..3).filter(|&k| shown_key(a, k) != shown_key(b, k)).map(|k| views[k as usize]).collect()
}

#[wasm_bindgen_test]
fn parts_the_caller_has_are_not_sent_again() {
    let text = program(30);
    let r = plan(&text, "gsk980tdc", "");
    assert_eq!(sent(&r), PARTS);
    // The same text: nothing is sent, every key is the same.
    let same = again(&text, &r, 0, 1);
    assert_eq!(sent(&same), [] as [&str; 0]);
    assert!(get(&same, "diagnostics").is_null());
    for k in ["threadsKey", "passesKey"] {
        assert_eq!(num(&same, k), num(&r, k), "{k}");
    }
    assert_eq!(redrawn(&r, &same), [] as [&str; 0]);
    // A comment at the top: no motion or thread changed.
    let commented = text.replacen("G50 X100 Z100", "G50 X100 Z100 (datum)", 1);
    let c = again(&commented, &r, 0, 1);
    assert_eq!((sent(&c), redrawn(&r, &c)), (vec![], vec![]));
    // A pass of the last thread: the thread list and the side section; the
    // first thread's passes, tooth and starts are the same.
    assert_eq!(text.lines().nth(394 - 9), Some("X38.1"));
    let late = edit_line(&text, -9, |_| "X38.0".into());
    let r2 = again(&late, &r, 0, 1);
    assert_eq!(sent(&r2), ["threads"]);
    assert_eq!(redrawn(&r, &r2), ["side"]);
    // The thread list comes as the one entry that changed.
    let changes = array(&get(&get(&r2, "threads"), "changes"));
    assert_eq!((changes.len(), num(&get(&r2, "threads"), "length")), (1, 30.0));
    let change = array(&changes[0]);
    assert_eq!(change[0].as_f64(), Some(29.0));
    let t: ThreadInfo = serde_wasm_bindgen::from_value(change[1].clone()).unwrap();
    assert_eq!((t.line, t.passes), (386, 2));
    // A caller whose list is not the one last answered gets it whole.
    let whole = wasm::update(&late, "gsk980tdc", "", 0, 1, -1.0, Some(vec![7.0, -1.0])).unwrap();
    let list: Vec<ThreadInfo> = field(&whole, "threads");
    assert_eq!(list.len(), 30);
    let r2 = again(&late, &r, 0, 1);
    // Choosing the changed thread sends its passes and draws its tooth and starts.
    let last = num(&r2, "threadsKey");
    let r3 = again(&late, &r2, 29, 1);
    assert_eq!(sent(&r3), ["passes"]);
    assert_eq!(redrawn(&r2, &r3), ["tooth", "starts"]);
    assert_eq!(num(&r3, "threadsKey"), last);
    let passes: Vec<PassInfo> = passes(&r3, "passes");
    assert!(close(passes[0].from[0], 38.0), "{:?}", passes[0].from);
    // Another edit to that pass: its start angles stay as they were, so the starts view is not redrawn.
    let later = edit_line(&late, -9, |_| "X38.05".into());
    let r4 = again(&later, &r3, 29, 1);
    assert_eq!((sent(&r4), redrawn(&r3, &r4)), (vec!["threads", "passes"], vec!["side", "tooth"]));
    // A motion outside every thread: the side section alone.
    let r5 = again(&edit_line(&late, -1, |l| format!("G00 X90 Z90\n{l}")), &r3, 29, 1);
    assert_eq!((sent(&r5), redrawn(&r3, &r5)), (vec![], vec!["side"]));
    // A caller that passes no keys gets everything.
    let r6 = wasm::update(&late, "gsk980tdc", "", 29, 1, -1.0, None).unwrap();
    assert_eq!(sent(&r6), PARTS);
    assert!(!get(&r6, "diagnostics").is_null());
}

#[wasm_bindgen_test]
fn thread_scenes_carry_the_keys_update_uses() {
    let text = program(5);
    let r = plan(&text, "gsk980tdc", "");
    let s = wasm::thread_scenes(3, 1).unwrap();
    assert_eq!(num(&s, "thread"), 3.0);
    let r3 = again(&text, &r, 3, 1);
    assert_eq!(num(&s, "passesKey"), num(&r3, "passesKey"));
    assert_eq!(redrawn(&s, &r3), [] as [&str; 0]);
    assert_eq!(redrawn(&r, &s), ["tooth", "starts"]);
    // With thread 3's keys known, choosing it again sends nothing of it.
    let known = vec![num(&r, "threadsKey"), num(&s, "passesKey")];
    let r4 = wasm::update(&text, "gsk980tdc", "", 3, 1, num(&r, "diagnosticsKey"), Some(known)).unwrap();
    assert_eq!(sent(&r4), [] as [&str; 0]);
}

#[wasm_bindgen_test]
fn plan_summary_counts_without_drawing() {
    let s = wasm::plan_summary(O1006, "gsk980tdc", "").unwrap();
    assert_eq!(
        [num(&s, "moves"), num(&s, "threads"), num(&s, "passes"), num(&s, "diagnostics"), num(&s, "alarms")],
        [21.0, 1.0, 5.0, 2.0, 0.0]
    );
    let s = wasm::plan_summary(&O1006.replace("X46.5", "X46..5"), "gsk980tdc", "").unwrap();
    assert_eq!(num(&s, "alarms"), 1.0);
    let s = wasm::plan_summary(G92_TWO_START, "gsk980tdc", "").unwrap();
    assert_eq!((num(&s, "threads"), num(&s, "passes")), (1.0, 8.0));
    for text in ["", "\u{0}(((", "G32 Z1e999 F0", "😀\n%\n%"] {
        let s = wasm::plan_summary(text, "renhe", "No.058=abc").unwrap();
        assert_eq!(num(&s, "threads"), 0.0, "{text:?}");
    }
    assert!(message(wasm::plan_summary(O1006, "bogus", "").unwrap_err()).contains("unknown dialect"));
    // It keeps nothing: the last plan is still the one update made.
    plan(G76_FANUC, "fanuc0i", "");
    wasm::plan_summary(O1006, "gsk980tdc", "").unwrap();
    let p: Vec<PassInfo> = passes(&wasm::thread_scenes(0, 1).unwrap(), "passes");
    assert!(close(p[0].depth, 1.8));
}

/// Every view keeps its own session: two programs planned in turn by two
/// sessions each resume from their own snapshot after a late edit, where
/// one shared planner would have re-read the whole program on every switch.
#[wasm_bindgen_test]
fn each_view_keeps_its_own_session() {
    let (a, b) = (wasm::Session::new(), wasm::Session::new());
    let text_a = program(40);
    let text_b = program(30).replace("G32 Z13 F2", "G32 Z14 F2");
    let up =
        |s: &wasm::Session, t: &str| s.update(Some(t.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    up(&a, &text_a);
    up(&b, &text_b);
    // A late edit to each, alternating: both resume near the end.
    let a2 = edit_line(&text_a, -3, |l| l.replace("Z70", "Z71"));
    let b2 = edit_line(&text_b, -3, |l| l.replace("Z70", "Z71"));
    let ra = up(&a, &a2);
    let rb = up(&b, &b2);
    let lines_a = text_a.lines().count() as f64;
    assert!(num(&ra, "resumedAt") > lines_a / 2.0, "a resumed at {}", num(&ra, "resumedAt"));
    assert!(num(&rb, "resumedAt") > 100.0, "b resumed at {}", num(&rb, "resumedAt"));
    // Each answers as a plan from scratch would.
    let fresh = wasm::Session::new();
    let full = fresh.update(Some(a2.clone()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    assert_eq!(snapshot_in(&ra, Some(&a)), snapshot_in(&full, Some(&fresh)));
}

/// `held` changed by the answer's `diagnosticsSplice` (as `spliceList` in
/// www/src/engine/parts.js does it).
fn spliced(held: &[Diag], r: &JsValue) -> Vec<Diag> {
    let s = get(r, "diagnosticsSplice");
    let (at, remove) = (num(&s, "at") as usize, num(&s, "remove") as usize);
    let items: Vec<Diag> = field(&s, "items");
    let offsets = js_sys::Uint32Array::from(get(&s, "offsets")).to_vec();
    let mut list: Vec<Diag> = held.to_vec();
    list.splice(at..at + remove, items);
    assert_eq!(offsets.len(), 2 * list.len());
    for (d, o) in list.iter_mut().zip(offsets.chunks_exact(2)) {
        (d.from, d.to) = (o[0], o[1]);
    }
    list
}

#[wasm_bindgen_test]
fn a_caller_holding_the_last_list_is_sent_its_change() {
    let text = program(30);
    let r = plan(&text, "gsk980tdc", "");
    let held: Vec<Diag> = field(&r, "diagnostics");
    // Line 9 is the first thread's first pass: its infeed changes that thread's notes only.
    let edited = edit_line(&text, 9, |_| "X29.05".into());
    let r2 = again(&edited, &r, 0, 1);
    assert!(get(&r2, "diagnostics").is_null());
    let items: Vec<Diag> = field(&get(&r2, "diagnosticsSplice"), "items");
    assert!(!items.is_empty() && items.len() < held.len() / 10, "{} of {}", items.len(), held.len());
    let full: Vec<Diag> = field(&from_scratch(&edited, "gsk980tdc", ""), "diagnostics");
    let got = spliced(&held, &r2);
    assert_eq!(format!("{got:?}"), format!("{full:?}"));
    // A comment typed above moves every offset and changes no entry: nothing is sent.
    let commented = edit_line(&edited, 2, |l| format!("{l} (spindle)"));
    let r3 = again(&commented, &r2, 0, 1);
    assert!(get(&r3, "diagnostics").is_null() && get(&r3, "diagnosticsSplice").is_undefined());
    // A caller holding another list (not the last answered) is sent the whole list.
    let other = edit_line(&text, 9, |_| "X29.0".into());
    let r4 = again(&other, &r, 0, 1);
    assert!(get(&r4, "diagnosticsSplice").is_undefined());
    let whole: Vec<Diag> = field(&r4, "diagnostics");
    let full: Vec<Diag> = field(&from_scratch(&other, "gsk980tdc", ""), "diagnostics");
    assert_eq!(format!("{whole:?}"), format!("{full:?}"));
}

/// The editor's changes made to the kept text (`Session::edit`) plan as the
/// whole edited text does: a digit typed into the first pass, a line pasted
/// over a full-width word; a change that does not fit is refused and the
/// kept text stays as it was, as it does through a failed update; with no
/// text kept an update needs the text.
#[wasm_bindgen_test]
fn edits_to_the_kept_text_plan_as_the_whole_text() {
    let up = |s: &wasm::Session, t: Option<String>| s.update(t, "gsk980tdc", "", 0, 1, -1.0, None, false, false);
    let text = format!("(Ｇ32 螺纹)\n{}", program(30));
    let s = wasm::Session::new();
    assert!(up(&s, None).is_err(), "no text kept yet");
    assert!(!s.edit(0, 0, "X"), "no text to edit yet");
    up(&s, Some(text.clone())).unwrap();
    // Line 10 is the first pass (`X29.1`): typed at its end by UTF-16 offset, after a comment of 9 units (17 bytes).
    let at = text.encode_utf16().count() - program(30).encode_utf16().count();
    let pass = program(30).lines().take(8).map(|l| l.len() + 1).sum::<usize>() + "X29.1".len();
    assert!(s.edit((at + pass) as u32, (at + pass) as u32, "5"));
    // The comment's full-width Ｇ (one unit, three bytes) replaced.
    assert!(s.edit(1, 2, "G"));
    let edited = text.replacen("X29.1\n", "X29.15\n", 1).replacen('Ｇ', "G", 1);
    // Refused: inside nothing (past the end) and reversed.
    assert!(!s.edit(1_000_000, 1_000_001, ""));
    assert!(!s.edit(3, 2, ""));
    // An update that fails keeps the text for the next.
    assert!(s.update(None, "no-such-controller", "", 0, 1, -1.0, None, false, false).is_err());
    let kept = up(&s, None).unwrap();
    let fresh = wasm::Session::new();
    let whole = up(&fresh, Some(edited.clone())).unwrap();
    assert_eq!(snapshot_in(&kept, Some(&s)), snapshot_in(&whole, Some(&fresh)));
    let first: Vec<PassInfo> = passes(&kept, "passes");
    assert_eq!(first.first().map(|p| p.from[0]), Some(29.15), "the typed digit is planned");
}

/// The cursor line's mark drawn after each edit (the side sections share
/// the pieces that did not change, and the session reads only the pieces
/// that reach the marked lines) is the one a session planning the text anew
/// draws at the same transform.
#[wasm_bindgen_test]
fn marked_lines_after_edits_are_a_fresh_sessions() {
    let base = program(30);
    let typed = wasm::Session::new();
    let update = |s: &wasm::Session, text: &str| {
        s.update(Some(text.into()), "gsk980tdc", "", 0, 1, -1.0, None, false, false).unwrap();
    };
    update(&typed, &base);
    let first = typed.draw("side", 640.0, 360.0, None, false, -1, -1, vec![], false).unwrap();
    let xf = Float64Array::from(get(&first, "transform")).to_vec();
    let list = |s: &wasm::Session, lines: &[u32]| {
        let d = s.draw("side", 640.0, 360.0, Some(xf.clone()), false, -1, -1, lines.to_vec(), true).unwrap();
        (js_sys::Uint32Array::from(get(&d, "ops")).to_vec(), Float64Array::from(get(&d, "nums")).to_vec())
    };
    let mut marked = 0;
    // Line 9 is the first thread's first pass (X29.1), 22 the second's, 300 and 301 a pass in the middle.
    for (k, text) in [
        edit_line(&base, 9, |_| "X29.15".into()),
        edit_line(&base, 9, |_| "X29.1".into()),
        edit_line(&base, 22, |_| "X30.2".into()),
        edit_line(&base, 300, |l| format!("{l}\n")),
        base.clone(),
    ]
    .iter()
    .enumerate()
    {
        update(&typed, text);
        let fresh = wasm::Session::new();
        update(&fresh, text);
        let plain = list(&fresh, &[]);
        assert_eq!(list(&typed, &[]), plain, "edit {k}");
        for lines in [&[9][..], &[22, 23], &[9, 300, 301]] {
            let got = list(&typed, lines);
            assert_eq!(got, list(&fresh, lines), "edit {k}, lines {lines:?}");
            marked += usize::from(got != plain);
        }
    }
    assert_eq!(marked, 15, "every mark shows");
}
