//! JavaScript values of the core's data: errors, serde-wasm-bindgen
//! objects, scenes as typed arrays, diagnostics with UTF-16 positions,
//! thread summaries, settings read from `NAME=VALUE` lines.

use js_sys::{Float64Array, Object, Reflect, Uint32Array};
use serde::Serialize;
use wasm_bindgen::JsValue;

use crate::dialect::Dialect;
use crate::figures::Shop;
use crate::message::Lang;
use crate::plan::Plan;
use crate::settings::Settings;
use crate::thread::{Axis, CrestSource, Infeed, Source, Thread, ThreadKind, Units};

/// A JavaScript `Error` with `msg`.
pub fn err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&msg.to_string()).into()
}

/// `v` as a plain JavaScript value (maps as objects).
pub fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true)).map_err(err)
}

/// Sets `obj[key] = value`.
pub fn set(obj: &Object, key: &str, value: &JsValue) {
    // Setting a property on a plain object cannot fail.
    let _ = Reflect::set(obj, &JsValue::from_str(key), value);
}

/// The dialect named `name`, or an error listing the names.
pub fn dialect(name: &str) -> Result<Dialect, JsValue> {
    Dialect::parse(name).ok_or_else(|| err(format!("unknown dialect '{name}' ({})", Dialect::names())))
}

/// A setting that could not be applied.
#[derive(Serialize)]
pub struct SettingProblem {
    /// The setting's name as given.
    pub setting: String,
    /// Why it was refused.
    pub message: String,
}

/// Settings of `dialect` from `NAME=VALUE` lines; lines that fail are reported, not applied.
pub fn settings_from(d: Dialect, lines: &str) -> (Settings, Vec<SettingProblem>) {
    let mut s = Settings::new(d);
    let mut problems = Vec::new();
    for line in lines.lines().map(str::trim).filter(|l| !l.is_empty()) {
        if let Err(e) = s.assign(line) {
            let setting = line.split('=').next().unwrap_or(line).trim().to_string();
            problems.push(SettingProblem { setting, message: e.to_string() });
        }
    }
    (s, problems)
}

/// A diagnostic with its range in the editor's UTF-16 offsets and its message in the page's language.
#[derive(Serialize)]
pub struct EditorDiagnostic<'a> {
    severity: crate::Severity,
    code: crate::Code,
    message: std::borrow::Cow<'a, str>,
    line: u32,
    column: u32,
    end_line: u32,
    end_column: u32,
    from: u32,
    to: u32,
    /// Inside a subprogram or macro: the lines of the calls that led here, innermost first.
    #[serde(skip_serializing_if = "<[u32]>::is_empty")]
    via: &'a [u32],
    /// How many times the program raised it, when more than once.
    #[serde(skip_serializing_if = "Option::is_none")]
    repeats: Option<u32>,
    /// A `dialect-hint`: the dialect the program reads better as (for a switch).
    #[serde(skip_serializing_if = "Option::is_none")]
    switch_to: Option<&'static str>,
    /// Its title.
    #[serde(skip_serializing_if = "Option::is_none")]
    switch_title: Option<&'static str>,
}

/// The UTF-16 offsets in `text` of the plan's diagnostics, `[from, to]`
/// each (`to` never before `from`).
pub fn editor_offsets(text: &str, plan: &Plan) -> Vec<u32> {
    let bytes: Vec<u32> = plan.diagnostics.iter().flat_map(|d| [d.span.start, d.span.end]).collect();
    let mut units = super::text::utf16_offsets(text, &bytes);
    units.chunks_exact_mut(2).for_each(|u| u[1] = u[1].max(u[0]));
    units
}

/// The plan's diagnostics `range` with their offsets from `units` (all the
/// plan's, [`editor_offsets`]), their messages in `lang`.
pub fn editor_diagnostics_of<'a>(
    plan: &'a Plan,
    units: &[u32],
    lang: Lang,
    range: std::ops::Range<usize>,
) -> Vec<EditorDiagnostic<'a>> {
    plan.diagnostics[range.clone()]
        .iter()
        .zip(units[2 * range.start..2 * range.end].chunks_exact(2))
        .map(|(d, u)| EditorDiagnostic {
            severity: d.severity,
            code: d.code,
            message: d.render(lang),
            line: d.line,
            column: d.column,
            end_line: d.end_line,
            end_column: d.end_column,
            from: u[0],
            to: u[1],
            via: &d.via,
            repeats: (d.repeats > 1).then_some(d.repeats),
            switch_to: hinted(d).map(crate::Dialect::name),
            switch_title: hinted(d).map(crate::Dialect::title),
        })
        .collect()
}

/// The dialect a `dialect-hint` names.
fn hinted(d: &crate::diagnostic::Diagnostic) -> Option<crate::Dialect> {
    match (d.code, d.args.get("dialect")) {
        (crate::Code::DialectHint, Some(crate::message::Arg::Text(name))) => crate::Dialect::parse(name),
        _ => None,
    }
}

/// A thread without its passes (the pass table shows one thread at a time).
#[derive(Serialize)]
pub struct ThreadSummary {
    line: u32,
    end_line: u32,
    source: Source,
    /// The units of the thread's words and figures.
    units: Units,
    kind: ThreadKind,
    long_axis: Axis,
    lead: f64,
    pitch: f64,
    starts: u32,
    internal: bool,
    infeed: Infeed,
    tool_angle: f64,
    crest: f64,
    crest_source: CrestSource,
    height: f64,
    taper: f64,
    passes: u32,
    /// The shop-floor figures (cycle time, speeds, clearances, the thread check without its notes; the
    /// per-pass chip loads and times are the pass table's columns instead).
    shop: crate::figures::Shop,
    /// The thread check's notes in both languages (a greyed thread list
    /// stays readable when the language changes with no new good plan).
    notes: Notes,
}

/// The thread check's notes rendered in each language the page offers.
#[derive(Serialize)]
struct Notes {
    en: Vec<String>,
    zh: Vec<String>,
}

/// A thread's shop-floor figures without the per-pass ones (chip loads,
/// pass times): the page gets those as the pass table's columns, and a
/// summary of 66,825 passes must not copy them again.
fn thread_figures(s: &Shop) -> Shop {
    // Every field named: a figure added to `Shop` is a decision here.
    let Shop {
        cut_time_s,
        time_s,
        pass_time_s: _,
        rpm,
        thread_feed,
        rpm_limit,
        lead_in_needed,
        run_out_needed,
        lead_in,
        run_out,
        clearance_source,
        pitch_diameter,
        helix_angle_deg,
        chip: _,
        gauge,
        shoulder,
        insert,
    } = s;
    Shop {
        cut_time_s: *cut_time_s,
        time_s: *time_s,
        pass_time_s: Vec::new(),
        rpm: *rpm,
        thread_feed: *thread_feed,
        rpm_limit: *rpm_limit,
        lead_in_needed: *lead_in_needed,
        run_out_needed: *run_out_needed,
        lead_in: *lead_in,
        run_out: *run_out,
        clearance_source: *clearance_source,
        pitch_diameter: *pitch_diameter,
        helix_angle_deg: *helix_angle_deg,
        shoulder: *shoulder,
        insert: insert.clone(),
        chip: Vec::new(),
        gauge: gauge.clone(),
    }
}

impl ThreadSummary {
    /// The summary of `t`, its notes in every language.
    pub fn of(t: &Thread) -> ThreadSummary {
        let r = crate::num::round_out;
        let mut shop = thread_figures(&t.shop);
        let kept = shop.gauge.as_mut().map(|g| std::mem::take(&mut g.notes)).unwrap_or_default();
        let render = |lang: Lang| kept.iter().map(|n| n.render(lang)).collect();
        let notes = Notes { en: render(Lang::En), zh: render(Lang::Zh) };
        ThreadSummary {
            line: t.line,
            end_line: t.end_line,
            source: t.source,
            units: t.units,
            kind: t.kind,
            long_axis: t.long_axis,
            lead: r(t.lead),
            pitch: r(t.pitch),
            starts: t.starts,
            internal: t.internal,
            infeed: t.infeed,
            tool_angle: r(t.tool_angle),
            crest: r(t.crest),
            crest_source: t.crest_source,
            height: r(t.height),
            taper: r(t.taper),
            passes: t.passes.len() as u32,
            shop,
            notes,
        }
    }
}

/// A thread's passes as columns of typed arrays (one array per field, no object per
/// pass): `{n, start, index: Uint32Array, x, z, xEnd, zEnd, depth, infeed,
/// area, shift, angle, runoutX, runoutZ, screwX, screwZ, time (s, with the
/// rapids), evenArea (the constant-area schedule's): Float64Array (NaN:
/// none), role: Uint8Array (0 rough, 1 finish, 2 spring), lineStart:
/// Uint32Array (n + 1), lines: Uint32Array, viaStart: Uint32Array (n + 1),
/// via: Uint32Array (the lines of the calls that cut each pass, innermost
/// first)}`; X as a diameter, (x, z) where the cut starts, (xEnd, zEnd)
/// where it ends.
pub fn passes_to_js(thread: &Thread) -> JsValue {
    use crate::num::round_out as r;
    use crate::thread::Role;
    let passes = &thread.passes;
    let shop = &thread.shop;
    let n = passes.len();
    let (mut start, mut index, mut line_start) =
        (Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n + 1));
    let mut cols: [Vec<f64>; 15] = std::array::from_fn(|_| Vec::with_capacity(n));
    let (mut role, mut lines) = (Vec::with_capacity(n), Vec::new());
    let (mut via_start, mut via) = (Vec::with_capacity(n + 1), Vec::new());
    for (i, p) in passes.iter().enumerate() {
        start.push(p.start);
        index.push(p.index);
        let (run, screw) =
            (p.runout_to.map_or([f64::NAN; 2], |q| [q.x, q.z]), p.screw_in_from.map_or([f64::NAN; 2], |q| [q.x, q.z]));
        let values = [
            p.from.x,
            p.from.z,
            p.to.x,
            p.to.z,
            p.depth,
            p.infeed,
            p.area.unwrap_or(f64::NAN),
            p.shift,
            p.angle,
            run[0],
            run[1],
            screw[0],
            screw[1],
            shop.pass_time_s.get(i).copied().unwrap_or(f64::NAN),
            shop.chip.get(i).and_then(|c| c.even_area).unwrap_or(f64::NAN),
        ];
        for (c, v) in cols.iter_mut().zip(values) {
            c.push(if v.is_nan() { v } else { r(v) });
        }
        role.push(match p.role {
            Role::Rough => 0u8,
            Role::Finish => 1,
            Role::Spring => 2,
        });
        line_start.push(lines.len() as u32);
        lines.extend_from_slice(&p.lines);
        via_start.push(via.len() as u32);
        via.extend_from_slice(&p.via);
    }
    line_start.push(lines.len() as u32);
    via_start.push(via.len() as u32);
    let o = Object::new();
    set(&o, "n", &(n as u32).into());
    set(&o, "start", &Uint32Array::from(&start[..]).into());
    set(&o, "index", &Uint32Array::from(&index[..]).into());
    let names = [
        "x", "z", "xEnd", "zEnd", "depth", "infeed", "area", "shift", "angle", "runoutX", "runoutZ", "screwX",
        "screwZ", "time", "evenArea",
    ];
    for (name, c) in names.iter().zip(&cols) {
        set(&o, name, &Float64Array::from(&c[..]).into());
    }
    set(&o, "role", &js_sys::Uint8Array::from(&role[..]).into());
    set(&o, "lineStart", &Uint32Array::from(&line_start[..]).into());
    set(&o, "lines", &Uint32Array::from(&lines[..]).into());
    set(&o, "viaStart", &Uint32Array::from(&via_start[..]).into());
    set(&o, "via", &Uint32Array::from(&via[..]).into());
    o.into()
}
