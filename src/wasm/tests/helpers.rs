//! Reading the binding's JS values back in Rust: properties, errors, the
//! serde-shaped lists (diagnostics, threads, passes) and the scenes a session shows.

use js_sys::{Array, Float64Array, JsString, Reflect, Uint32Array};
use serde::Deserialize;
use wasm_bindgen::{JsCast, JsValue};

use crate::wasm;

/// The seed and example programs, as the web app's examples menu has them.
pub const O1006: &str = include_str!("../../../examples/o1006.nc");
/// The GSK G32 taper thread (two passes).
pub const O0009: &str = include_str!("../../../examples/o0009.nc");
/// Two starts by the G32 start angle Q.
pub const G32_TWO_START: &str = include_str!("../../../examples/g32-multistart-q.nc");
/// GSK G92 with L2.
pub const G92_TWO_START: &str = include_str!("../../../examples/g92-two-start.nc");
/// G78 degressive, radial infeed.
pub const G78_M30X2: &str = include_str!("../../../examples/g78-m30x2.nc");
/// G78 equal depth, alternating flanks, screw-in.
pub const G78_ALTERNATING: &str = include_str!("../../../examples/g78-flank-alternating.nc");
/// Fanuc G76.
pub const G76_FANUC: &str = include_str!("../../../examples/g76-fanuc.nc");
/// Renhe G30 spiral tail and the standard tail.
pub const RENHE_TAILS: &str = include_str!("../../../examples/renhe-tails.nc");

/// Property `key` of `v` (undefined when missing).
pub fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
}

/// Number property `key` of `v`; fails when it is not a number.
pub fn num(v: &JsValue, key: &str) -> f64 {
    get(v, key).as_f64().unwrap_or_else(|| panic!("{key} is not a number: {:?}", get(v, key)))
}

/// The message of a thrown JS `Error`.
pub fn message(e: JsValue) -> String {
    match e.dyn_into::<js_sys::Error>() {
        Ok(e) => String::from(e.message()),
        Err(v) => panic!("not an Error: {v:?}"),
    }
}

/// Whether `a` and `b` agree to 1e-6 (the binding rounds to six decimals).
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// Asserts that two lists of numbers agree to 1e-6.
#[track_caller]
pub fn assert_close(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    assert!(got.iter().zip(want).all(|(a, b)| close(*a, *b)), "{got:?} vs {want:?}");
}

/// A diagnostic as the editor gets it.
#[derive(Clone, Debug, Deserialize)]
pub struct Diag {
    /// error, warning or info.
    pub severity: String,
    /// Stable code.
    pub code: String,
    /// Text.
    pub message: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column (characters).
    pub column: u32,
    /// 1-based end line.
    pub end_line: u32,
    /// 1-based end column.
    pub end_column: u32,
    /// UTF-16 start.
    pub from: u32,
    /// UTF-16 end.
    pub to: u32,
}

/// A thread summary as the pass table's selector gets it.
#[derive(Debug, Deserialize)]
pub struct ThreadInfo {
    /// First line.
    pub line: u32,
    /// Last line.
    pub end_line: u32,
    /// g32, renhe, g78, g92, g76.
    pub source: String,
    /// straight, taper, face.
    pub kind: String,
    /// Lead.
    pub lead: f64,
    /// Pitch.
    pub pitch: f64,
    /// Starts.
    pub starts: u32,
    /// Internal thread.
    pub internal: bool,
    /// radial, left, right, alternating, programmed.
    pub infeed: String,
    /// Tool angle in degrees.
    pub tool_angle: f64,
    /// Crest diameter.
    pub crest: f64,
    /// cycle, outline, assumed.
    pub crest_source: String,
    /// Thread height.
    pub height: f64,
    /// Number of passes.
    pub passes: u32,
}

/// One pass of the chosen thread.
#[derive(Debug, PartialEq)]
pub struct PassInfo {
    /// Start number.
    pub start: u32,
    /// Pass number within the start.
    pub index: u32,
    /// Start of the cut `[x, z]`.
    pub from: [f64; 2],
    /// End of the cut.
    pub to: [f64; 2],
    /// Depth from the crest.
    pub depth: f64,
    /// Depth added.
    pub infeed: f64,
    /// rough, finish, spring.
    pub role: String,
    /// Source lines.
    pub lines: Vec<u32>,
    /// Axial shift of a flank infeed.
    pub shift: f64,
    /// Start angle.
    pub angle: f64,
    /// Area removed.
    pub area: Option<f64>,
    /// End of the run-out.
    pub runout_to: Option<[f64; 2]>,
    /// Start of the screw-in.
    pub screw_in_from: Option<[f64; 2]>,
}

/// The passes of answer `v`'s property `key`, from their columns.
pub fn passes(v: &JsValue, key: &str) -> Vec<PassInfo> {
    let c = get(v, key);
    let n = num(&c, "n") as usize;
    let f = |name: &str| Float64Array::from(get(&c, name)).to_vec();
    let u = |name: &str| Uint32Array::from(get(&c, name)).to_vec();
    let (x, z, xe, ze, depth, infeed, area, shift, angle) =
        (f("x"), f("z"), f("xEnd"), f("zEnd"), f("depth"), f("infeed"), f("area"), f("shift"), f("angle"));
    let (rx, rz, sx, sz) = (f("runoutX"), f("runoutZ"), f("screwX"), f("screwZ"));
    let (start, index, line_start, lines) = (u("start"), u("index"), u("lineStart"), u("lines"));
    let role = js_sys::Uint8Array::from(get(&c, "role")).to_vec();
    let opt = |a: f64, b: f64| (!a.is_nan()).then_some([a, b]);
    (0..n)
        .map(|i| PassInfo {
            start: start[i],
            index: index[i],
            from: [x[i], z[i]],
            to: [xe[i], ze[i]],
            depth: depth[i],
            infeed: infeed[i],
            role: ["rough", "finish", "spring"][role[i] as usize].to_string(),
            lines: lines[line_start[i] as usize..line_start[i + 1] as usize].to_vec(),
            shift: shift[i],
            angle: angle[i],
            area: (!area[i].is_nan()).then_some(area[i]),
            runout_to: opt(rx[i], rz[i]),
            screw_in_from: opt(sx[i], sz[i]),
        })
        .collect()
}

/// A refused setting.
#[derive(Debug, Deserialize)]
pub struct SettingError {
    /// The name as written.
    pub setting: String,
    /// Why.
    pub message: String,
}

/// Deserialises property `key` of `v`.
pub fn field<T: serde::de::DeserializeOwned>(v: &JsValue, key: &str) -> T {
    serde_wasm_bindgen::from_value(get(v, key)).unwrap_or_else(|e| panic!("{key}: {e}"))
}

/// Plans `text` as `dialect` with `settings`, thread 0, start 1, no known diagnostics.
pub fn plan(text: &str, dialect: &str, settings: &str) -> JsValue {
    wasm::update(text, dialect, settings, 0, 1, -1.0, None).unwrap_or_else(|e| panic!("update failed: {}", message(e)))
}

/// One item of a packed scene, decoded.
#[derive(Debug, Clone)]
pub struct Item {
    /// Shape name.
    pub shape: String,
    /// Style name.
    pub style: String,
    /// The shape's numbers.
    pub coords: Vec<f64>,
    /// 0-based thread.
    pub thread: Option<u32>,
    /// 0-based pass (the start number's index in the starts view).
    pub pass: Option<u32>,
    /// Source lines.
    pub lines: Vec<u32>,
    /// `(key, value)` of a dimension or text.
    pub label: Option<(String, String)>,
    /// Role, anchor or glyph code.
    pub extra: u32,
}

/// A packed scene, decoded with the binding's style and shape names.
#[derive(Debug)]
pub struct Scene {
    /// side, tooth or starts.
    pub view: String,
    /// Extent of every item.
    pub bounds: Vec<f64>,
    /// Extent to fit first.
    pub focus: Vec<f64>,
    /// Items in drawing order.
    pub items: Vec<Item>,
}

/// The scene view `view` of the default session shows, decoded.
pub fn shown(view: &str) -> Scene {
    decode(&wasm::default_scene(view).unwrap_or_else(|| panic!("the {view} view shows nothing")))
}

/// The key of the scene view `k` (0 side, 1 tooth, 2 starts) shows after answer `r` (0: none).
pub fn shown_key(r: &JsValue, k: u32) -> f64 {
    Float64Array::from(get(r, "shown")).get_index(k)
}

/// A scene decoded through its packed form (`crate::wasm::pack`), with the style and shape names.
pub fn decode(sc: &crate::diagram::Scene) -> Scene {
    use crate::wasm::pack::{SHAPES, STRIDE, pack};
    let p = pack(sc);
    let styles: Vec<String> = crate::diagram::Style::ALL.iter().map(|s| s.name().to_string()).collect();
    let labels: Vec<(String, String)> = if p.labels.is_empty() {
        Vec::new()
    } else {
        p.labels
            .split('\u{1e}')
            .map(|r| {
                let (k, v) = r.split_once('\u{1f}').expect("a label record has a key and a value");
                (k.to_string(), v.to_string())
            })
            .collect()
    };
    let opt = |v: u32| v.checked_sub(1);
    let items = p
        .items
        .chunks_exact(STRIDE)
        .map(|r| {
            let (c, n) = (r[2] as usize, r[3] as usize);
            let (l, m) = (r[6] as usize, r[7] as usize);
            Item {
                shape: SHAPES[r[0] as usize].to_string(),
                style: styles[r[1] as usize].clone(),
                coords: p.coords[c..c + n].to_vec(),
                thread: opt(r[4]),
                pass: opt(r[5]),
                lines: p.lines[l..l + m].to_vec(),
                label: opt(r[8]).map(|k| labels[k as usize].clone()),
                extra: r[9],
            }
        })
        .collect();
    let view = match sc.view {
        crate::diagram::ViewKind::Side => "side",
        crate::diagram::ViewKind::Tooth => "tooth",
        crate::diagram::ViewKind::Starts => "starts",
    };
    Scene { view: view.to_string(), bounds: p.bounds.to_vec(), focus: p.focus.to_vec(), items }
}

impl Scene {
    /// Items of `style` (and `shape`, when given).
    pub fn of(&self, style: &str, shape: Option<&str>) -> Vec<&Item> {
        self.items.iter().filter(|i| i.style == style && shape.is_none_or(|s| i.shape == s)).collect()
    }

    /// Labels of the items of `style`, `(key, value)`.
    pub fn labels(&self, style: &str) -> Vec<(String, String)> {
        self.of(style, None).iter().filter_map(|i| i.label.clone()).collect()
    }
}

/// The UTF-16 offset of `needle` in the JS string `text` (−1 when absent).
pub fn js_index_of(text: &JsString, needle: &str) -> i32 {
    text.index_of(needle, 0)
}

/// The entries of a JS array.
pub fn array(v: &JsValue) -> Vec<JsValue> {
    Array::from(v).iter().collect()
}
