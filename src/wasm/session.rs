//! A planning session: one per view. The app and every embedded element
//! keep their own planner (with its snapshots and last plan), the pieces of
//! their last side section and the thread list they were sent, so switching
//! between embeds never re-plans another's program.
//!
//! The planner is kept in a `Cell` (taken and put back, never borrowed), so
//! even a trap in one call leaves later calls working.

use std::cell::Cell;

use js_sys::{Array, Float64Array, Object};
use wasm_bindgen::prelude::*;

use super::js::{
    SettingProblem, ThreadSummary, dialect, editor_diagnostics, err, packed_to_js, passes_to_js, pieces_to_js, set,
    settings_from, to_js,
};
use super::keys::{PlanKeys, combine, js_key, key_of, packed_key};
use super::memo::SideMemo;
use super::pack::pack;
use super::parts::{Known, Part, ThreadsSent, keyed};
use crate::diagram;
use crate::message::Lang;
use crate::plan::Plan;
use crate::planner::Planner;

/// What a session keeps between calls.
struct State {
    planner: Planner,
    side: SideMemo,
    threads: ThreadsSent,
}

/// A planning session of one view (see the module documentation).
#[wasm_bindgen]
#[derive(Default)]
pub struct Session {
    state: Cell<Option<State>>,
    /// The language of the messages and notes it answers with.
    lang: Cell<Lang>,
}

#[wasm_bindgen]
impl Session {
    /// A session with nothing planned yet.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Session {
        Session::default()
    }

    /// Plans `text` as `dialect_name` with `settings` (`NAME=VALUE` lines) and
    /// returns everything the app shows:
    /// `{dialect, units, alarms, warnings, notes, moves, timeS (threading time, s; null without S), good, settingErrors,
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
    #[allow(clippy::too_many_arguments)] // the JavaScript call's positional arguments
    pub fn update(
        &self,
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
        let mut session = match self.state.take() {
            Some(mut session) => {
                session.planner.set_settings(s);
                session
            }
            None => State { planner: Planner::new(s), side: SideMemo::new(), threads: ThreadsSent::default() },
        };
        session.planner.plan(text);
        let settings = session.planner.settings().clone();
        if let Some(plan) = session.planner.last_mut() {
            crate::hint::add(text, &settings, plan, crate::hint::MAX_BYTES_LIVE);
        }
        let State { planner, side, threads } = &mut session;
        let lang = self.lang.get();
        let out = match planner.last() {
            Some(plan) => {
                answer(text, plan, (side, threads), &problems, (thread, start, lang), known_diagnostics, &known).map(
                    |o| {
                        set(&o, "resumedAt", &planner.resumed_at().into());
                        o.into()
                    },
                )
            }
            None => Err(err("the planner kept no plan")),
        };
        self.state.set(Some(session));
        out
    }

    /// Sets the language (`en` or `zh`; anything else is English) of the
    /// diagnostics' messages in the answers from now on. Their key carries
    /// the language, so a caller holding the other language's list is sent
    /// a new one.
    pub fn set_lang(&self, lang: &str) {
        self.lang.set(Lang::parse(lang).unwrap_or_default());
    }

    /// The last plan's diagnostics in the language set last, without
    /// planning again: `{diagnostics, diagnosticsKey}` (keyed as
    /// [`Session::update`] keys them). Thread summaries need no relabelling:
    /// they carry their notes in every language.
    pub fn relabel(&self) -> Result<JsValue, JsValue> {
        let lang = self.lang.get();
        let state = self.state.take();
        let answer = |s: &State, plan: &Plan| -> Result<JsValue, JsValue> {
            let o = Object::new();
            set(&o, "diagnosticsKey", &diagnostics_key(plan, lang).into());
            set(&o, "diagnostics", &to_js(&editor_diagnostics(s.planner.text(), plan, lang))?);
            Ok(o.into())
        };
        let out = match state.as_ref().and_then(|s| s.planner.last().map(|plan| (s, plan))) {
            Some((s, plan)) => answer(s, plan),
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }

    /// The tooth and starts scenes of another thread or start of the last plan:
    /// `{thread, passes, passesKey, tooth, toothKey, starts, startsKey}` (every
    /// part sent; the keys are those [`Session::update`] uses).
    pub fn thread_scenes(&self, thread: i32, start: u32) -> Result<JsValue, JsValue> {
        self.with_last(|plan| {
            let keys = PlanKeys::of(plan);
            let o = Object::new();
            thread_parts(&o, plan, &keys, pick(plan, thread), start, &Known(Vec::new()))?;
            Ok(o.into())
        })
    }

    /// The last plan as a JSON-compatible value (what the CLI's `--json`
    /// writes: `JSON.stringify` it), for download. The wasm carries no JSON
    /// writer of its own.
    pub fn plan_value(&self) -> Result<JsValue, JsValue> {
        self.with_last(json_value)
    }

    /// View `view` (`side`, `tooth`, `starts`) of the last plan as a
    /// standalone SVG document, written by the same writer as the command
    /// line's `screwcut svg` ([`crate::svg`]) on a `size` page (`[width,
    /// height]` px, the view's size on screen), with thread `thread` (its
    /// dimensions when many threads are drawn; the tooth and starts views'
    /// thread), start `start` and the label templates `labels` (`[key,
    /// template, key, template…]`, the page's language; missing keys in
    /// English).
    ///
    /// `layout` is what the view shows: `{transform: {sx, sy, tx, ty},
    /// labels: [{item, lines, align, box, angle, off, len, lead}…]}` (see
    /// [`crate::svg::Layout`]); the drawing is then made with that transform
    /// and each label drawn where it is given (without `labels`, placed at
    /// the transform). Without a layout (undefined or null), the drawing
    /// and its labels are fitted to the page as the view's Fit does, with
    /// the radial `stretch`. A layout that does not fit the scene (a label
    /// naming an item that is not a label, numbers that are not finite) is
    /// an error.
    #[allow(clippy::too_many_arguments)] // the JavaScript call's positional arguments
    pub fn svg(
        &self,
        view: &str,
        thread: i32,
        start: u32,
        size: Vec<f64>,
        stretch: bool,
        labels: Vec<String>,
        layout: JsValue,
    ) -> Result<String, JsValue> {
        let layout: Option<crate::svg::Layout> = if layout.is_undefined() || layout.is_null() {
            None
        } else {
            Some(serde_wasm_bindgen::from_value(layout).map_err(|e| err(format!("the SVG layout: {e}")))?)
        };
        self.with_last(|plan| {
            let t = pick(plan, thread);
            let scene = match view {
                "side" => Some(diagram::side(plan)),
                "tooth" => t.and_then(|t| diagram::tooth(plan, t, start.max(1))),
                "starts" => t.and_then(|t| diagram::starts(plan, t)),
                _ => return Err(err(format!("unknown view '{view}': side, tooth or starts"))),
            };
            let scene = scene.ok_or_else(|| err(format!("no thread to draw the {view} view of")))?;
            let [width, height] = size[..] else {
                return Err(err(format!("the page size is [width, height], not {} numbers", size.len())));
            };
            let pairs = labels.chunks_exact(2).map(|kv| (kv[0].clone(), kv[1].clone())).collect();
            let opts = crate::svg::Options { width, height, stretch, thread: t.unwrap_or(0), labels: pairs, layout };
            opts.validate(&scene).map_err(err)?;
            Ok(crate::svg::svg(&scene, &opts))
        })
    }

    /// The last plan written block by block for dialect `to` (every pass
    /// with its approach, cut, run-out, retract and return; see
    /// [`crate::expand`]): `{program, notes}`, the notes in the session's
    /// language. Planned again, the program gives the same passes.
    pub fn expand(&self, to: &str) -> Result<JsValue, JsValue> {
        let to = dialect(to)?;
        let lang = self.lang.get();
        self.with_last(|plan| {
            let e = crate::expand::expand(plan, to);
            to_js(&super::tools::Written::<()>::new(&e.program, &e.notes, lang, None))
        })
    }

    /// The motions of the last plan, seven numbers each:
    /// `[kind, x0, z0, x1, z1, line, cw]` with kind 0 rapid, 1 feed, 2 arc,
    /// 3 thread, 4 run-out, 5 screw-in and `cw` 1 for clockwise arcs (X as a diameter).
    pub fn moves(&self) -> Float64Array {
        let mut out = Vec::new();
        let _ = self.with_last(|p| {
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
    /// transfer costs: `"packed"` (typed arrays, what [`Session::update`]
    /// returns), `"objects"` (serde-wasm-bindgen objects, one per item and
    /// point) or `"json"` (a JSON string).
    pub fn side_scene_as(&self, format: &str) -> Result<JsValue, JsValue> {
        self.with_last(|plan| {
            let scene = diagram::side(plan);
            match format {
                "packed" => Ok(packed_to_js(&pack(&scene))),
                "objects" => to_js(&scene),
                "json" => json_string(&scene),
                _ => Err(err(format!("unknown format '{format}' (packed, objects, json)"))),
            }
        })
    }

    /// The threads of the last plan as serde-wasm-bindgen objects or as a JSON
    /// string (`"objects"` or `"json"`), for comparing transfer costs.
    pub fn threads_as(&self, format: &str) -> Result<JsValue, JsValue> {
        self.with_last(|plan| match format {
            "objects" => to_js(&plan.threads),
            "json" => json_string(&plan.threads),
            _ => Err(err(format!("unknown format '{format}' (objects, json)"))),
        })
    }
}

/// `v` as a JSON-compatible JavaScript value (`None` as null, maps as objects).
fn json_value<T: serde::Serialize + ?Sized>(v: &T) -> Result<JsValue, JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible()).map_err(err)
}

/// `v` as a JSON string, written by the browser's `JSON.stringify`.
fn json_string<T: serde::Serialize + ?Sized>(v: &T) -> Result<JsValue, JsValue> {
    let value = json_value(v)?;
    js_sys::JSON::stringify(&value).map(JsValue::from).map_err(|_| err("JSON.stringify failed"))
}

impl Session {
    /// Runs `f` on the last plan; an error when nothing was planned yet.
    fn with_last<R>(&self, f: impl FnOnce(&Plan) -> Result<R, JsValue>) -> Result<R, JsValue> {
        let state = self.state.take();
        let out = match state.as_ref().and_then(|s| s.planner.last()) {
            Some(plan) => f(plan),
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }
}

/// The thread index to draw in detail: `thread` clamped to the plan, none when negative or no threads.
fn pick(plan: &Plan, thread: i32) -> Option<usize> {
    let n = plan.threads.len();
    (thread >= 0 && n > 0).then(|| (thread as usize).min(n - 1))
}

/// The key of the diagnostics by position (line and column, not offset) and
/// language: when it is unchanged the editor's own diagnostics, mapped
/// through the edit, are current.
fn diagnostics_key(plan: &Plan, lang: Lang) -> f64 {
    let fields: Vec<(u8, &str, &str, u32, u32, u32, u32)> = plan
        .diagnostics
        .iter()
        .map(|d| (d.severity as u8, d.code.as_str(), d.message.as_str(), d.line, d.column, d.end_line, d.end_column))
        .collect();
    js_key(key_of(&(lang.name(), fields)))
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
    let listed_key = keys.listed[t];
    let start = start.clamp(1, plan.threads[t].starts.max(1));
    keyed(o, known, Part::Passes, combine(&[listed_key, t as u64]), || Ok(passes_to_js(&plan.threads[t])))?;
    // The small scenes are keyed by what they draw: an edit that leaves one as it was redraws nothing.
    for (part, scene) in [(Part::Tooth, diagram::tooth(plan, t, start)), (Part::Starts, diagram::starts(plan, t))] {
        let packed = scene.map(|s| pack(&s));
        let key = packed.as_ref().map_or(0, packed_key);
        keyed(o, known, part, key, || Ok(packed.as_ref().map_or(JsValue::NULL, packed_to_js)))?;
    }
    Ok(())
}

/// The object [`update`] returns, for `plan` of `text`.
fn answer(
    text: &str,
    plan: &Plan,
    (memo, sent): (&mut SideMemo, &mut ThreadsSent),
    problems: &[SettingProblem],
    (thread, start, lang): (i32, u32, Lang),
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
    set(&o, "timeS", &plan.time_s.map_or(JsValue::NULL, |t| crate::num::round_out(t).into()));
    let good = !plan.has_alarm() && (!plan.threads.is_empty() || !plan.moves.is_empty());
    set(&o, "good", &good.into());
    set(&o, "settingErrors", &to_js(problems)?);
    let key = diagnostics_key(plan, lang);
    set(&o, "diagnosticsKey", &key.into());
    let diagnostics =
        if key == known_diagnostics { JsValue::NULL } else { to_js(&editor_diagnostics(text, plan, lang))? };
    set(&o, "diagnostics", &diagnostics);
    let keys = PlanKeys::of(plan);
    let all = keys.all_listed;
    keyed(&o, known, Part::Threads, all, || {
        sent.answer(known, all, &keys.listed, |i| to_js(&ThreadSummary::of(&plan.threads[i])))
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
