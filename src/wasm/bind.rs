//! The functions JavaScript calls: the tables the app's panels show (dialects,
//! settings, style and shape names, the scene record layout), planning
//! without a session, and the default session of pages that keep one.
//!
//! Nothing here may panic: a panic aborts the wasm instance and the page
//! loses its planner. Inputs are validated and errors come back as values
//! (`Err` becomes a thrown JS `Error` with a message; setting errors are
//! listed in the result).
//!
//! Bulk geometry crosses as typed arrays ([`super::pack`]); the rest
//! (diagnostics, threads, setting tables) through serde-wasm-bindgen.

use js_sys::{Float64Array, Object};
use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::js::{dialect, set, settings_from, to_js};
use super::session::Session;
use crate::dialect::Dialect;
use crate::settings::{Kind, Settings};

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
/// `[{name, kind: int|float|bool|choice|text, choices, default, min, max, unit, help, help_zh}]`
/// (a text setting's `max` is its longest value in bytes; its default is empty).
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
    // The text settings (a designation, an insert, macro variables): free text up to their length.
    let texts = s.text_entries().map(|(d, _)| SettingInfo {
        name: d.name,
        kind: "text",
        choices: &[],
        default: 0.0,
        min: 0.0,
        max: d.max_len as f64,
        unit: "",
        help: d.help,
        help_zh: d.help_zh,
    });
    let list: Vec<SettingInfo> = list.into_iter().chain(texts).collect();
    to_js(&list)
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

thread_local! {
    /// The default session, for pages that plan one program.
    static DEFAULT: Session = Session::new();
}

/// [`Session::update`] on the default session.
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
    DEFAULT.with(|s| {
        s.update(Some(text.into()), dialect_name, settings, thread, start, known_diagnostics, known, false, false)
    })
}

/// [`Session::thread_scenes`] on the default session.
#[wasm_bindgen]
pub fn thread_scenes(thread: i32, start: u32) -> Result<JsValue, JsValue> {
    DEFAULT.with(|s| s.thread_scenes(thread, start))
}

/// [`Session::moves`] on the default session.
#[wasm_bindgen]
pub fn moves() -> Float64Array {
    DEFAULT.with(Session::moves)
}

/// A copy of the scene view `view` of the default session shows (for tests).
#[cfg(test)]
pub(crate) fn default_scene(view: &str) -> Option<crate::diagram::Scene> {
    DEFAULT.with(|s| s.shown_scene(view))
}
