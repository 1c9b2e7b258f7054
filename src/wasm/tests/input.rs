//! Bad input: it comes back as values (diagnostics, refused settings,
//! thrown errors), never as a trap that would kill the page's planner.

use js_sys::JsString;
use wasm_bindgen_test::wasm_bindgen_test;

use super::helpers::*;
use crate::wasm;

/// Checks the invariants of any result: counts match the list, every
/// position lies inside the text, every item references valid data.
fn sane(text: &str, r: &wasm_bindgen::JsValue) {
    let d: Vec<Diag> = field(r, "diagnostics");
    let units = text.encode_utf16().count() as u32;
    // `\n`, `\r\n` and a lone `\r` end a line.
    let lines = text.replace("\r\n", "\n").split(['\n', '\r']).count() as u32;
    for x in &d {
        assert!(["error", "warning", "info"].contains(&x.severity.as_str()), "{x:?}");
        assert!(x.from <= x.to && x.to <= units, "{x:?} in {units} units");
        assert!(x.line >= 1 && x.line <= lines.max(1) && x.column >= 1, "{x:?}");
        assert!((x.end_line, x.end_column) >= (x.line, x.column), "{x:?}");
        assert!(!x.message.is_empty() && !x.code.is_empty());
    }
    let count = |s: &str| d.iter().filter(|x| x.severity == s).count() as f64;
    assert_eq!(num(r, "alarms"), count("error"));
    assert_eq!(num(r, "warnings"), count("warning"));
    assert_eq!(num(r, "notes"), count("info"));
    let side = shown("side");
    for i in &side.items {
        assert!(i.coords.iter().all(|v| v.is_finite()), "{i:?}");
    }
    assert!(side.bounds.iter().all(|v| v.is_finite()) && side.focus.iter().all(|v| v.is_finite()));
}

#[wasm_bindgen_test]
fn empty_program() {
    for text in ["", "\n", "   \n\t\n", "%\n%\n", ";"] {
        let r = plan(text, "gsk980tdc", "");
        sane(text, &r);
        assert_eq!(get(&r, "good").as_bool(), Some(false), "{text:?} draws nothing");
        assert_eq!((num(&r, "alarms"), num(&r, "moves")), (0.0, 0.0), "{text:?}");
        assert!(array(&get(&r, "threads")).is_empty());
        assert!(get(&r, "thread").is_null() && shown_key(&r, 1) == 0.0 && shown_key(&r, 2) == 0.0);
        let side = shown("side");
        assert!(side.of("cut", None).is_empty() && side.of("rapid", None).is_empty());
    }
    assert!(wasm::moves().to_vec().is_empty());
    let s = wasm::thread_scenes(0, 1).unwrap();
    assert!(get(&s, "thread").is_null() && shown_key(&s, 1) == 0.0);
}

#[wasm_bindgen_test]
fn unknown_dialect_is_an_error_value() {
    for name in ["", "fanuc16i", "mazak", "renhe\0", "гск"] {
        let e = wasm::update(O1006, name, "", 0, 1, -1.0, None).unwrap_err();
        let m = message(e);
        assert!(m.starts_with("unknown dialect") && m.contains("fanuc0i"), "{name:?}: {m}");
    }
    // Names are matched as the CLI does: case, spaces and dashes do not count.
    for (name, is) in [("GSK", "gsk980tdc"), (" Fanuc 0i ", "fanuc0i"), ("gsk-980tdc", "gsk980tdc"), ("RENHE", "renhe")]
    {
        let r = wasm::update(O1006, name, "", 0, 1, -1.0, None).unwrap();
        assert_eq!(get(&r, "dialect").as_string().as_deref(), Some(is), "{name:?}");
    }
}

#[wasm_bindgen_test]
fn huge_and_odd_numbers() {
    let cases = [
        "G00 X1e400 Z5\n",
        "G00 X99999999999999999999 Z5\n",
        "G00 X-0.000000000000001 Z1.7976931348623157\n",
        "G00 X58 Z70\nX47.1\nG32 Z-99999999 F0.0001\n",
        "G00 X58 Z70\nX47.1\nG32 Z13 F99999999\n",
        "G00 X58 Z70\nG32 Z13 F2 Q99999999\n",
        "G00 X35 Z5\nG78 P1060 Q1 R0 D99\nG78 X27.4 Z-30 P1300 Q1 F2 L99\n",
        "G00 X35 Z5\nG78 P0060 Q0 R0\nG78 X27.4 Z-30 P99999999 Q1 F2\n",
        "G00 X80. Z130.\nG76 P999999 Q0 R0\nG76 X60.64 Z25. P99999999 Q1 F6.\n",
        "G00 X30 Z5\nG92 X23.2 Z-30 F3 L65535\n",
        "G00 X30 Z5\nG92 X23.2 Z-30 F0.000001\n",
        "N99999999999 G00 X--1 Z+-2 F.\n",
        "G00 X. Z.. G32 F-0 Z0\n",
        "G0 X58 Z70\nG32 X58 Z70 F2\n",
    ];
    for (k, text) in cases.iter().enumerate() {
        for dialect in ["gsk980tdc", "fanuc0i", "renhe"] {
            let r = wasm::update(text, dialect, "", 0, 1, -1.0, None)
                .unwrap_or_else(|e| panic!("case {k} on {dialect}: {}", message(e)));
            sane(text, &r);
        }
    }
    // Too many digits is an alarm at the number, not a misread value.
    let r = plan(cases[1], "gsk980tdc", "");
    let d: Vec<Diag> = field(&r, "diagnostics");
    assert!(d.iter().any(|d| d.code == "too-many-digits" && d.column == 6 && d.to - d.from == 20), "{d:?}");
    // A G78 that would need more than 999 passes is an alarm with the numbers.
    let r = plan(cases[7], "gsk980tdc", "");
    let d: Vec<Diag> = field(&r, "diagnostics");
    assert!(d.iter().any(|d| d.severity == "error"), "{d:?}");
}

/// A small deterministic generator (xorshift) for garbage programs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn pick<'a>(&mut self, from: &[&'a str]) -> &'a str {
        from[(self.next() % from.len() as u64) as usize]
    }
}

#[wasm_bindgen_test]
fn garbage_never_traps() {
    let pieces = [
        "G", "G32", "G33", "G30", "G76", "G78", "G92", "G00", "G01", "G02", "G03", "G20", "G50", "M30", "X", "Z", "U",
        "W", "F", "I", "J", "K", "P", "Q", "R", "L", "E", "D", "S", "N", "O", "T", "1", "0", "-", ".", "9.99", "1e9",
        "65535", " ", " ", "\n", "\n", "\r\n", "\t", ";", "(", ")", "%", "/", "#", "Ｇ", "３２", "；", "（", "）",
        "😀", "\u{0}", "\u{7f}", "\u{FFFD}", "é", "中", "\u{200B}",
    ];
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for k in 0..150 {
        let len = 1 + (rng.next() % 300) as usize;
        let text: String = (0..len).map(|_| rng.pick(&pieces)).collect();
        let dialect = ["gsk980tdc", "fanuc0i", "renhe"][k % 3];
        let thread = (rng.next() % 4) as i32 - 1;
        let r = wasm::update(&text, dialect, "", thread, (rng.next() % 3) as u32, -1.0, None)
            .unwrap_or_else(|e| panic!("program {k}: {}\n{text:?}", message(e)));
        sane(&text, &r);
        assert!(wasm::thread_scenes(thread + 1, 1).is_ok());
    }
    // Random bytes as text (the lossy conversion a browser makes from a bad file).
    for _ in 0..30 {
        let bytes: Vec<u8> = (0..400).map(|_| rng.next() as u8).collect();
        let text = String::from_utf8_lossy(&bytes).into_owned();
        sane(&text, &plan(&text, "gsk980tdc", ""));
    }
}

#[wasm_bindgen_test]
fn odd_settings_text_never_traps() {
    let lines = [
        "=",
        "==",
        "No.058==5",
        "No.058=",
        "No.058=1e999",
        "No.058=NaN",
        "No.058=-inf",
        "limits.moves=0",
        "limits.passes_per_start=-1",
        "x_mode=radius=diameter",
        "\u{0}=\u{0}",
        "😀=😀",
    ];
    for l in lines {
        let r = plan(G78_M30X2, "gsk980tdc", l);
        sane(G78_M30X2, &r);
    }
    let r = plan(G78_M30X2, "gsk980tdc", &lines.join("\n"));
    let errors: Vec<SettingError> = field(&r, "settingErrors");
    assert!(errors.len() >= 8, "{errors:?}");
    assert!(errors.iter().all(|e| !e.message.is_empty()));
}

#[wasm_bindgen_test]
fn large_program_plans() {
    // 2,000 passes of O1006's pattern on 400 threads.
    let mut text = String::from("G50 X100 Z100\n");
    for k in 0..400 {
        let z0 = 70 + (k % 40) * 80;
        text.push_str(&format!("G00 X58 Z{z0}\n"));
        for x in [47.1, 46.5, 45.9, 45.5, 45.4] {
            text.push_str(&format!("X{x}\nG32 Z{} F2\nG00 X58\nZ{z0}\n", z0 - 57));
        }
    }
    let r = plan(&text, "gsk980tdc", "");
    sane(&text, &r);
    assert_eq!(array(&get(&r, "threads")).len(), 400);
    let side = shown("side");
    assert_eq!(side.of("cut", Some("polyline")).len(), 2000);
    // A long line of one word repeated: an alarm at the block, no trap.
    let long = format!("G00 {}\n", "X1 ".repeat(10_000));
    let r = plan(&long, "gsk980tdc", "");
    sane(&long, &r);
    let d: Vec<Diag> = field(&r, "diagnostics");
    assert!(d.iter().any(|d| d.code == "block-too-long"), "{:?}", d.iter().map(|d| &d.code).collect::<Vec<_>>());
    let js = JsString::from(long.as_str());
    assert_eq!(js.length(), long.len() as u32);
}
