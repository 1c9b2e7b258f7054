//! The wasm-bindgen binding layer: plans a program for the web app and hands
//! back diagnostics (with editor positions), threads and the scenes.
//!
//! Nothing here may panic: a panic aborts the wasm instance and the page
//! loses its planner. Inputs are validated and errors come back as values
//! (`Err` becomes a thrown JS `Error` with a message; setting errors are
//! listed in the result). The planner is kept in a `Cell` (taken and put
//! back, never borrowed), so even a trap in one call leaves later calls working.
//!
//! The planner is incremental ([`crate::planner::Planner`]): an edit re-reads
//! the program from the last snapshot before it. Each part of the answer
//! (threads, passes, scenes) carries a content key; a part whose key the
//! caller says it has is not built or sent again, and the side section is
//! put together from the pieces of the last one that did not change
//! ([`crate::diagram::memo`]).
//!
//! Bulk geometry crosses as typed arrays (see [`crate::diagram::packed`]);
//! the rest (diagnostics, threads, setting tables) through serde-wasm-bindgen.

use std::cell::Cell;

use js_sys::{Array, Float64Array, Object, Reflect, Uint32Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::diagram::fingerprint::{PlanKeys, combine, js_key, key_of, packed_key};
use crate::diagram::memo::{SideMemo, SidePieces};
use crate::diagram::{self, Packed};
use crate::dialect::Dialect;
use crate::plan::Plan;
use crate::planner::Planner;
use crate::settings::{Kind, Settings};
use crate::thread::{Axis, CrestSource, Infeed, Source, Thread, ThreadKind};

/// What is kept between calls: the planner (with the last plan) and the
/// pieces of the last side section.
struct Session {
    planner: Planner,
    side: SideMemo,
    threads: ThreadsSent,
}

thread_local! {
    /// The session; `None` before the first plan.
    static SESSION: Cell<Option<Session>> = const { Cell::new(None) };
}

/// Runs `f` on the last plan; an error when nothing was planned yet.
fn with_last<R>(f: impl FnOnce(&Plan) -> Result<R, JsValue>) -> Result<R, JsValue> {
    let session = SESSION.with(Cell::take);
    let out = match session.as_ref().and_then(|s| s.planner.last()) {
        Some(plan) => f(plan),
        None => Err(err("nothing planned yet")),
    };
    SESSION.with(|c| c.set(session));
    out
}

fn err(msg: impl std::fmt::Display) -> JsValue {
    js_sys::Error::new(&msg.to_string()).into()
}

fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true)).map_err(err)
}

fn set(obj: &Object, key: &str, value: &JsValue) {
    // Setting a property on a plain object cannot fail.
    let _ = Reflect::set(obj, &JsValue::from_str(key), value);
}

fn dialect(name: &str) -> Result<Dialect, JsValue> {
    Dialect::parse(name).ok_or_else(|| err(format!("unknown dialect '{name}' ({})", Dialect::names())))
}

/// A dialect for the selector.
#[derive(Serialize)]
struct DialectInfo {
    name: &'static str,
    title: &'static str,
}

/// The dialects: `[{name, title}]`.
#[wasm_bindgen]
pub fn dialects() -> Result<JsValue, JsValue> {
    let list: Vec<DialectInfo> =
        Dialect::ALL.iter().map(|d| DialectInfo { name: d.name(), title: d.title() }).collect();
    to_js(&list)
}

/// One setting for the settings panel.
#[derive(Serialize)]
struct SettingInfo {
    name: &'static str,
    kind: &'static str,
    choices: &'static [&'static str],
    default: f64,
    min: f64,
    max: f64,
    unit: &'static str,
    help: &'static str,
    help_zh: &'static str,
}

/// The settings of a dialect with their defaults, units, ranges and help:
/// `[{name, kind: int|float|bool|choice, choices, default, min, max, unit, help, help_zh}]`.
#[wasm_bindgen]
pub fn settings_table(dialect_name: &str) -> Result<JsValue, JsValue> {
    let s = Settings::new(dialect(dialect_name)?);
    let list: Vec<SettingInfo> = s
        .entries()
        .map(|(d, v)| {
            let (kind, choices): (&str, &'static [&'static str]) = match d.kind {
                Kind::Int => ("int", &[]),
                Kind::Float => ("float", &[]),
                Kind::Bool => ("bool", &[]),
                Kind::Choice(c) => ("choice", c),
            };
            SettingInfo {
                name: d.name,
                kind,
                choices,
                default: v,
                min: d.min,
                max: d.max,
                unit: d.unit,
                help: d.help,
                help_zh: d.help_zh,
            }
        })
        .collect();
    to_js(&list)
}

/// The style names, indexed by the packed style code.
#[wasm_bindgen]
pub fn style_names() -> Array {
    diagram::Style::ALL.iter().map(|s| JsValue::from_str(s.name())).collect()
}

/// The shape names, indexed by the packed shape code.
#[wasm_bindgen]
pub fn shape_names() -> Array {
    diagram::packed::SHAPES.iter().map(|s| JsValue::from_str(s)).collect()
}

/// A setting that could not be applied.
#[derive(Serialize)]
struct SettingProblem {
    setting: String,
    message: String,
}

/// Settings of `dialect` from `NAME=VALUE` lines; lines that fail are reported, not applied.
fn settings_from(d: Dialect, lines: &str) -> (Settings, Vec<SettingProblem>) {
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

/// A diagnostic with its range in the editor's UTF-16 offsets.
#[derive(Serialize)]
struct EditorDiagnostic<'a> {
    severity: crate::Severity,
    code: crate::Code,
    message: &'a str,
    line: u32,
    column: u32,
    end_line: u32,
    end_column: u32,
    from: u32,
    to: u32,
}

fn editor_diagnostics<'a>(text: &str, plan: &'a Plan) -> Vec<EditorDiagnostic<'a>> {
    let bytes: Vec<u32> = plan.diagnostics.iter().flat_map(|d| [d.span.start, d.span.end]).collect();
    let units = diagram::editor::utf16_offsets(text, &bytes);
    plan.diagnostics
        .iter()
        .zip(units.chunks_exact(2))
        .map(|(d, u)| EditorDiagnostic {
            severity: d.severity,
            code: d.code,
            message: &d.message,
            line: d.line,
            column: d.column,
            end_line: d.end_line,
            end_column: d.end_column,
            from: u[0],
            to: u[1].max(u[0]),
        })
        .collect()
}

/// A thread without its passes (the pass table shows one thread at a time).
#[derive(Serialize)]
struct ThreadSummary {
    line: u32,
    end_line: u32,
    source: Source,
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
}

impl ThreadSummary {
    fn of(t: &Thread) -> ThreadSummary {
        let r = crate::num::round_out;
        ThreadSummary {
            line: t.line,
            end_line: t.end_line,
            source: t.source,
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
        }
    }
}

/// A packed scene as a JS object with typed arrays:
/// `{view, bounds, focus, coords: Float64Array, items: Uint32Array, lines: Uint32Array, labels}`.
fn packed_to_js(p: &Packed) -> JsValue {
    let o = Object::new();
    let view = match p.view {
        diagram::ViewKind::Side => "side",
        diagram::ViewKind::Tooth => "tooth",
        diagram::ViewKind::Starts => "starts",
    };
    set(&o, "view", &JsValue::from_str(view));
    set(&o, "bounds", &Float64Array::from(&p.bounds[..]).into());
    set(&o, "focus", &Float64Array::from(&p.focus[..]).into());
    set(&o, "coords", &Float64Array::from(&p.coords[..]).into());
    set(&o, "items", &Uint32Array::from(&p.items[..]).into());
    set(&o, "lines", &Uint32Array::from(&p.lines[..]).into());
    set(&o, "labels", &JsValue::from_str(&p.labels));
    o.into()
}

/// The side section as pieces (see [`SidePieces`]): `{view, pieces: true,
/// bounds, focus, headCoords, headItems, order, keys, coords, items, lines,
/// labels, ends}`, keys as JS numbers, `ends` five numbers per sent piece.
fn pieces_to_js(p: &SidePieces) -> JsValue {
    let o = Object::new();
    let keys = |k: &[u64]| Float64Array::from(&k.iter().map(|k| js_key(*k)).collect::<Vec<f64>>()[..]);
    set(&o, "view", &JsValue::from_str("side"));
    set(&o, "pieces", &JsValue::TRUE);
    set(&o, "bounds", &Float64Array::from(&p.head.bounds[..]).into());
    set(&o, "focus", &Float64Array::from(&p.head.focus[..]).into());
    set(&o, "headCoords", &Float64Array::from(&p.head.coords[..]).into());
    set(&o, "headItems", &Uint32Array::from(&p.head.items[..]).into());
    set(&o, "order", &keys(&p.order).into());
    set(&o, "keys", &keys(&p.keys).into());
    set(&o, "coords", &Float64Array::from(&p.sent.coords[..]).into());
    set(&o, "items", &Uint32Array::from(&p.sent.items[..]).into());
    set(&o, "lines", &Uint32Array::from(&p.sent.lines[..]).into());
    set(&o, "labels", &JsValue::from_str(&p.sent.labels));
    set(&o, "ends", &Uint32Array::from(&p.ends.concat()[..]).into());
    o.into()
}

/// The thread index to draw in detail: `thread` clamped to the plan, none when negative or no threads.
fn pick(plan: &Plan, thread: i32) -> Option<usize> {
    let n = plan.threads.len();
    (thread >= 0 && n > 0).then(|| (thread as usize).min(n - 1))
}

/// The key of the diagnostics by position (line and column, not offset): when
/// it is unchanged the editor's own diagnostics, mapped through the edit, are current.
fn diagnostics_key(plan: &Plan) -> f64 {
    let fields: Vec<(u8, &str, &str, u32, u32, u32, u32)> = plan
        .diagnostics
        .iter()
        .map(|d| (d.severity as u8, d.code.as_str(), d.message.as_str(), d.line, d.column, d.end_line, d.end_column))
        .collect();
    js_key(key_of(&fields))
}

/// Sets the chosen thread, its passes and its tooth and starts scenes on `o`.
fn thread_parts(
    o: &Object,
    plan: &Plan,
    keys: &PlanKeys,
    chosen: Option<usize>,
    start: u32,
    known: &Known,
) -> Result<(), JsValue> {
    set(o, "thread", &chosen.map_or(JsValue::NULL, |t| (t as u32).into()));
    let Some(t) = chosen else {
        for part in [Part::Passes, Part::Tooth, Part::Starts] {
            keyed(o, known, part, 0, || {
                Ok(if matches!(part, Part::Passes) { Array::new().into() } else { JsValue::NULL })
            })?;
        }
        return Ok(());
    };
    let thread_key = keys.threads[t];
    let start = start.clamp(1, plan.threads[t].starts.max(1));
    keyed(o, known, Part::Passes, combine(&[thread_key, t as u64]), || to_js(&plan.threads[t].passes))?;
    // The small scenes are keyed by what they draw: an edit that leaves one as it was redraws nothing.
    for (part, scene) in [(Part::Tooth, diagram::tooth(plan, t, start)), (Part::Starts, diagram::starts(plan, t))] {
        let packed = scene.map(|s| diagram::pack(&s));
        let key = packed.as_ref().map_or(0, packed_key);
        keyed(o, known, part, key, || Ok(packed.as_ref().map_or(JsValue::NULL, packed_to_js)))?;
    }
    Ok(())
}

/// Plans `text` as `dialect_name` with `settings` (`NAME=VALUE` lines) and
/// returns everything the app shows:
/// `{dialect, units, alarms, warnings, notes, moves, good, settingErrors,
/// diagnostics, diagnosticsKey, threads, threadsKey, thread, passes,
/// passesKey, side, sideKey, tooth, toothKey, starts, startsKey, resumedAt}`:
/// `threads` are summaries (a pass count instead of the passes), `passes` are
/// the chosen thread's. `diagnostics` is null when its key equals
/// `known_diagnostics` (the key of the list the caller already has); so is
/// each of `threads`, `passes`, `side`, `tooth` and `starts` when its key is
/// in `known` (`[threads, passes, side, tooth, starts]` keys; omitted: none
/// known). With `known` given, `threads` may come as `{changes: [[index,
/// summary]...], length}` (to a caller holding the list last answered) and `side` as pieces (see `pieces_to_js`):
/// only those the caller lacks when it holds the pieces of the last side
/// section answered, else all; without it, as one packed scene. `thread` and
/// `start` choose the thread (−1: none) and start drawn in the tooth and starts views. `good` is true when the plan draws
/// something (threads or motions) and has no alarm.
///
/// The program is re-read only from the last planner snapshot before the
/// first byte that differs from the last call's text; `resumedAt` is the
/// line reading resumed at (1: the whole program was read).
#[wasm_bindgen]
pub fn update(
    text: &str,
    dialect_name: &str,
    settings: &str,
    thread: i32,
    start: u32,
    known_diagnostics: f64,
    known: Option<Vec<f64>>,
) -> Result<JsValue, JsValue> {
    let d = dialect(dialect_name)?;
    let (s, problems) = settings_from(d, settings);
    let known = Known(known.unwrap_or_default());
    let mut session = match SESSION.with(Cell::take) {
        Some(mut session) => {
            session.planner.set_settings(s);
            session
        }
        None => Session { planner: Planner::new(s), side: SideMemo::new(), threads: ThreadsSent::default() },
    };
    session.planner.plan(text);
    let Session { planner, side, threads } = &mut session;
    let out = match planner.last() {
        Some(plan) => {
            answer(text, plan, (side, threads), &problems, (thread, start), known_diagnostics, &known).map(|o| {
                set(&o, "resumedAt", &planner.resumed_at().into());
                o.into()
            })
        }
        None => Err(err("the planner kept no plan")),
    };
    SESSION.with(|c| c.set(Some(session)));
    out
}

/// The object [`update`] returns, for `plan` of `text`.
fn answer(
    text: &str,
    plan: &Plan,
    (memo, sent): (&mut SideMemo, &mut ThreadsSent),
    problems: &[SettingProblem],
    (thread, start): (i32, u32),
    known_diagnostics: f64,
    known: &Known,
) -> Result<Object, JsValue> {
    let o = Object::new();
    let count = |sev: crate::Severity| plan.diagnostics.iter().filter(|x| x.severity == sev).count() as u32;
    set(&o, "dialect", &JsValue::from_str(plan.dialect.name()));
    set(&o, "units", &to_js(&plan.units)?);
    set(&o, "alarms", &count(crate::Severity::Error).into());
    set(&o, "warnings", &count(crate::Severity::Warning).into());
    set(&o, "notes", &count(crate::Severity::Info).into());
    set(&o, "moves", &(plan.moves.len() as u32).into());
    let good = !plan.has_alarm() && (!plan.threads.is_empty() || !plan.moves.is_empty());
    set(&o, "good", &good.into());
    set(&o, "settingErrors", &to_js(problems)?);
    let key = diagnostics_key(plan);
    set(&o, "diagnosticsKey", &key.into());
    let diagnostics = if key == known_diagnostics { JsValue::NULL } else { to_js(&editor_diagnostics(text, plan))? };
    set(&o, "diagnostics", &diagnostics);
    let keys = PlanKeys::of(plan);
    keyed(&o, known, Part::Threads, keys.all_threads, || {
        sent.answer(known, keys.all_threads, &keys.threads, |i| to_js(&ThreadSummary::of(&plan.threads[i])))
    })?;
    keyed(&o, known, Part::Side, keys.side, || {
        if !known.keeps() {
            return Ok(packed_to_js(&memo.side(plan, &keys.threads)));
        }
        let holds = memo.last().map(js_key) == known.key(Part::Side);
        Ok(pieces_to_js(&memo.pieces(plan, &keys.threads, keys.side, holds)))
    })?;
    thread_parts(&o, plan, &keys, pick(plan, thread), start, known)?;
    Ok(o)
}

/// The counts of a plan of `text` (planned from scratch, nothing drawn or
/// kept): `{moves, threads, passes, diagnostics, alarms}`. For timing the planner.
#[wasm_bindgen]
pub fn plan_summary(text: &str, dialect_name: &str, settings: &str) -> Result<JsValue, JsValue> {
    let (s, _) = settings_from(dialect(dialect_name)?, settings);
    let plan = crate::plan(text, &s);
    let o = Object::new();
    set(&o, "moves", &(plan.moves.len() as u32).into());
    set(&o, "threads", &(plan.threads.len() as u32).into());
    set(&o, "passes", &(plan.threads.iter().map(|t| t.passes.len()).sum::<usize>() as u32).into());
    set(&o, "diagnostics", &(plan.diagnostics.len() as u32).into());
    let alarms = plan.diagnostics.iter().filter(|d| d.severity == crate::Severity::Error).count();
    set(&o, "alarms", &(alarms as u32).into());
    Ok(o.into())
}

/// The tooth and starts scenes of another thread or start of the last plan:
/// `{thread, passes, passesKey, tooth, toothKey, starts, startsKey}` (every
/// part sent; the keys are those [`update`] uses).
#[wasm_bindgen]
pub fn thread_scenes(thread: i32, start: u32) -> Result<JsValue, JsValue> {
    with_last(|plan| {
        let keys = PlanKeys::of(plan);
        let o = Object::new();
        thread_parts(&o, plan, &keys, pick(plan, thread), start, &Known(Vec::new()))?;
        Ok(o.into())
    })
}

/// The whole plan of `text` as JSON (the CLI's `--json`), for download.
#[wasm_bindgen]
pub fn plan_json(text: &str, dialect_name: &str, settings: &str) -> Result<String, JsValue> {
    let (s, _) = settings_from(dialect(dialect_name)?, settings);
    Ok(crate::plan(text, &s).to_json())
}

/// The motions of the last plan, seven numbers each:
/// `[kind, x0, z0, x1, z1, line, cw]` with kind 0 rapid, 1 feed, 2 arc,
/// 3 thread, 4 run-out, 5 screw-in and `cw` 1 for clockwise arcs (X as a diameter).
#[wasm_bindgen]
pub fn moves() -> Float64Array {
    let mut out = Vec::new();
    let _ = with_last(|p| {
        out.reserve(p.moves.len() * 7);
        for m in &p.moves {
            use crate::motion::MoveKind::*;
            let kind = match m.kind {
                Rapid => 0.0,
                Feed => 1.0,
                Arc => 2.0,
                Thread => 3.0,
                Runout => 4.0,
                ScrewIn => 5.0,
            };
            let cw = m.arc.map_or(0.0, |a| if a.cw { 1.0 } else { 0.0 });
            out.extend_from_slice(&[kind, m.from.x, m.from.z, m.to.x, m.to.z, m.line as f64, cw]);
        }
        Ok(())
    });
    Float64Array::from(&out[..])
}

/// The side scene of the last plan in another encoding, for comparing
/// transfer costs: `"packed"` (typed arrays, what [`update`] returns),
/// `"objects"` (serde-wasm-bindgen objects, one per item and point) or
/// `"json"` (a JSON string).
#[wasm_bindgen]
pub fn side_scene_as(format: &str) -> Result<JsValue, JsValue> {
    with_last(|plan| {
        let scene = diagram::side(plan);
        match format {
            "packed" => Ok(packed_to_js(&diagram::pack(&scene))),
            "objects" => to_js(&scene),
            "json" => serde_json::to_string(&scene).map(|s| JsValue::from_str(&s)).map_err(err),
            _ => Err(err(format!("unknown format '{format}' (packed, objects, json)"))),
        }
    })
}

/// The threads of the last plan as serde-wasm-bindgen objects or as a JSON
/// string (`"objects"` or `"json"`), for comparing transfer costs.
#[wasm_bindgen]
pub fn threads_as(format: &str) -> Result<JsValue, JsValue> {
    with_last(|plan| match format {
        "objects" => to_js(&plan.threads),
        "json" => serde_json::to_string(&plan.threads).map(|s| JsValue::from_str(&s)).map_err(err),
        _ => Err(err(format!("unknown format '{format}' (objects, json)"))),
    })
}

mod parts;
use parts::{Known, Part, ThreadsSent, keyed};

/// The binding's tests (wasm-bindgen-test), run in Node and in headless
/// Chromium by `cargo xtask test`.
#[cfg(test)]
mod tests;
