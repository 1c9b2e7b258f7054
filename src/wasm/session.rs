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

use std::rc::Rc;

use super::js::{SettingProblem, ThreadSummary, dialect, err, passes_to_js, set, settings_from, to_js};
use super::keys::{PlanKeys, combine, js_key, packed_key};
use super::listed::DiagnosticsSent;
use super::memo::SideMemo;
use super::pack::pack;
use super::parts::{Known, Part, ThreadsSent, keyed};
use super::shown::{Scenes, Shown};
use crate::diagram::{self, Scene};
use crate::message::Lang;
use crate::plan::Plan;
use crate::planner::Planner;

/// What a session keeps between calls.
pub(super) struct State {
    pub(super) planner: Planner,
    side: SideMemo,
    threads: ThreadsSent,
    /// The scenes the views show (the last good drawing's policy).
    pub(super) shown: Shown,
    /// The chosen thread (its dimensions are drawn when the side section has many).
    pub(super) thread: usize,
    /// Another program compared with this one (`Session::compare`): its plan and number.
    pub(super) compare: Option<(Plan, u64)>,
    /// The diagnostics list answered last (an answer may send only its change).
    diagnostics: DiagnosticsSent,
    /// Each view's last fit (by [`super::shown::Which`]): kept while typing leaves the focus and labels as they were.
    pub(super) fits: [crate::draw::FitMemo; 3],
    /// Each view's source lines by part of its items (the cursor line's mark reads only the parts that reach it).
    pub(super) line_ranges: [crate::draw::pick::LineRanges; 3],
    /// The keys of the planner's last plan and its number (the next plan's
    /// keys take from them what the planner kept).
    keys: Option<(u64, PlanKeys)>,
}

/// The text of an update, put back as the text the session keeps when the
/// update ends (by an answer or an error).
struct Kept<'a> {
    cell: &'a Cell<Option<String>>,
    text: String,
}

impl Drop for Kept<'_> {
    fn drop(&mut self) {
        self.cell.set(Some(std::mem::take(&mut self.text)));
    }
}

/// A planning session of one view (see the module documentation).
#[wasm_bindgen]
#[derive(Default)]
pub struct Session {
    state: Cell<Option<State>>,
    /// The language of the messages and notes it answers with.
    lang: Cell<Lang>,
    /// Whether its drawings show the roughing cuts of G71/G72 (on demand).
    roughing: Cell<bool>,
    /// The text of the last update with the edits made to it since
    /// ([`Session::edit`]): the next update may plan it without the text
    /// crossing into wasm again.
    kept: Cell<Option<String>>,
}

#[wasm_bindgen]
impl Session {
    /// A session with nothing planned yet.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Session {
        Session::default()
    }

    /// Plans `text` as `dialect_name` with `settings` (`NAME=VALUE` lines),
    /// keeps the scenes of the plan for the views to draw ([`Session::draw`])
    /// and returns what the page lists:
    /// `{dialect, units, alarms, warnings, notes, moves, timeS (threading time, s; null without S), good, settingErrors,
    /// diagnostics, diagnosticsKey, threads, threadsKey, thread, passes,
    /// passesKey, shown: [side, tooth, starts keys], stale, plan, goodPlan, resumedAt}`:
    /// `threads` are summaries (a pass count instead of the passes), `passes` are
    /// the chosen thread's. `diagnostics` is null when its key equals
    /// `known_diagnostics` (the key of the list the caller already has); so is
    /// each of `threads` and `passes` when its key is in `known`
    /// (`[threads, passes]` keys; omitted: none known). With `known` given,
    /// `threads` may come as `{changes: [[index, summary]...], length}` to a
    /// caller holding the list last answered. `thread` and `start` choose the
    /// thread (−1: none) and start drawn in the tooth and starts views.
    /// `good` is true when the plan draws something (threads or motions) and
    /// has no alarm. `shown` are the keys of the scenes the views show and
    /// `stale` whether they are the last good drawing, greyed; `plan` numbers
    /// this plan and `goodPlan` the plan of the good drawing kept (null: none;
    /// a page shows that plan's lists while the drawing is greyed) (see
    /// [`super::shown`]: `fresh`, the text is another program's; `keep`, the
    /// drawing on screen before this edit was left).
    ///
    /// The program is re-read only from the last planner snapshot before the
    /// first byte that differs from the last call's text; `resumedAt` is the
    /// line reading resumed at (1: the whole program was read).
    ///
    /// `text` omitted (`undefined`): the text kept from the last update, with
    /// the edits made since ([`Session::edit`]); an error when none is kept.
    #[allow(clippy::too_many_arguments)] // the JavaScript call's positional arguments
    pub fn update(
        &self,
        text: Option<String>,
        dialect_name: &str,
        settings: &str,
        thread: i32,
        start: u32,
        known_diagnostics: f64,
        known: Option<Vec<f64>>,
        fresh: bool,
        keep: bool,
    ) -> Result<JsValue, JsValue> {
        let Some(text) = text.or_else(|| self.kept.take()) else {
            return Err(err("no text kept: the update needs the whole text"));
        };
        // Kept for the next update however this one ends.
        let kept = Kept { cell: &self.kept, text };
        let text = kept.text.as_str();
        let d = dialect(dialect_name)?;
        let (s, problems) = settings_from(d, settings);
        let known = Known(known.unwrap_or_default());
        let mut session = match self.state.take() {
            Some(mut session) => {
                session.planner.set_settings(s);
                session
            }
            None => State {
                planner: Planner::new(s),
                side: SideMemo::new(),
                threads: ThreadsSent::default(),
                shown: Shown::default(),
                thread: 0,
                compare: None,
                fits: Default::default(),
                line_ranges: Default::default(),
                diagnostics: DiagnosticsSent::default(),
                keys: None,
            },
        };
        session.planner.plan(text);
        let settings = session.planner.settings().clone();
        if let Some(plan) = session.planner.last_mut() {
            crate::hint::add(text, &settings, plan, crate::hint::MAX_BYTES_LIVE);
        }
        let State { planner, side, threads, shown, thread: chosen, compare, diagnostics, keys: last_keys, .. } =
            &mut session;
        let lang = self.lang.get();
        let out = match planner.last() {
            Some(plan) => {
                let keys = match (last_keys.take(), planner.changed()) {
                    (Some((n, k)), Some(c)) if n + 1 == planner.plans() => PlanKeys::after(Some((&k, c)), plan),
                    _ => PlanKeys::of(plan),
                };
                let picked = pick(plan, thread);
                *chosen = picked.unwrap_or(0);
                let (tooth, starts) = thread_scenes_of(plan, picked, start);
                let side_scene = Rc::new(side.side(plan, &keys));
                let scenes = Scenes {
                    plan: planner.plans(),
                    scenes: [Some(side_scene), tooth.0, starts.0],
                    keys: [js_key(keys.side), tooth.1, starts.1],
                };
                let drawable = !plan.has_alarm() && (!plan.threads.is_empty() || !plan.moves.is_empty());
                shown.planned(scenes, drawable, plan.has_alarm(), fresh, keep);
                let compared = compare.as_ref().map(|(b, id)| {
                    shown.set_overlay(Some((*id, super::compared::overlay_items(b, *chosen))));
                    crate::compare::compare(plan, b)
                });
                let sent = (threads, diagnostics);
                let answered =
                    answer(text, plan, &keys, sent, &problems, (picked, start, lang), known_diagnostics, &known);
                *last_keys = Some((planner.plans(), keys));
                answered.map(|o| {
                    if let Some(c) = &compared {
                        set(&o, "comparison", &super::compared::comparison_js(c));
                    }
                    set(&o, "shown", &Float64Array::from(&shown.keys()[..]).into());
                    set(&o, "stale", &shown.stale().into());
                    set(&o, "plan", &(planner.plans() as f64).into());
                    set(&o, "goodPlan", &shown.good_plan().map_or(JsValue::NULL, |g| (g as f64).into()));
                    set(&o, "resumedAt", &planner.resumed_at().into());
                    o.into()
                })
            }
            None => Err(err("the planner kept no plan")),
        };
        self.state.set(Some(session));
        out
    }

    /// The text kept for the next update (none before the first).
    pub fn kept_text(&self) -> Option<String> {
        let text = self.kept.take();
        self.kept.set(text.clone());
        text
    }

    /// Makes the change a browser editor states (UTF-16 units `from..to`
    /// replaced with `inserted`) to the text kept for the next update.
    /// Returns false when no text is kept or the change does not fit it:
    /// the next update then needs the whole text.
    pub fn edit(&self, from: u32, to: u32, inserted: &str) -> bool {
        let Some(mut text) = self.kept.take() else { return false };
        let fits = super::text::replace_utf16(&mut text, from as usize, to as usize, inserted);
        self.kept.set(Some(text));
        fits
    }

    /// Frees the scenes no longer shown (call it after the drawing is on
    /// screen; else they are freed when the next plan arrives).
    pub fn tidy(&self) {
        let _ = self.with_state_mut(|st| {
            st.shown.tidy();
            Ok(())
        });
    }

    /// Shows (or hides) the roughing cuts of G71/G72 in the drawings from now on (hidden at first).
    pub fn set_roughing(&self, on: bool) {
        self.roughing.set(on);
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
        let mut state = self.state.take();
        let out = match state.as_mut() {
            Some(State { planner, diagnostics, .. }) => match planner.last() {
                Some(plan) => {
                    let o = Object::new();
                    // The whole list: the caller is known to hold none in this language.
                    diagnostics.answer(&o, planner.text(), plan, lang, -1.0)?;
                    Ok(o.into())
                }
                None => Err(err("nothing planned yet")),
            },
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }

    /// Another thread or start of the last plan: the tooth and starts views
    /// show it. `{thread, passes, passesKey, shown, stale}` (the passes always
    /// sent; the keys are those [`Session::update`] uses).
    pub fn thread_scenes(&self, thread: i32, start: u32) -> Result<JsValue, JsValue> {
        let mut state = self.state.take();
        let out = match state.as_mut() {
            Some(st) => match st.planner.last() {
                Some(plan) => {
                    let keys = match &st.keys {
                        Some((n, k)) if *n == st.planner.plans() => k.clone(),
                        _ => PlanKeys::of(plan),
                    };
                    let picked = pick(plan, thread);
                    st.thread = picked.unwrap_or(0);
                    let (tooth, starts) = thread_scenes_of(plan, picked, start);
                    st.shown.select(tooth.0, starts.0, [tooth.1, starts.1]);
                    if let Some((b, id)) = &st.compare {
                        st.shown.set_overlay(Some((*id, super::compared::overlay_items(b, st.thread))));
                    }
                    let o = Object::new();
                    let r = thread_parts(&o, plan, &keys, picked, &Known(Vec::new()));
                    set(&o, "shown", &Float64Array::from(&st.shown.keys()[..]).into());
                    set(&o, "stale", &st.shown.stale().into());
                    r.map(|()| o.into())
                }
                None => Err(err("nothing planned yet")),
            },
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }

    /// The motions of the last plan, seven numbers each:
    /// `[kind, x0, z0, x1, z1, line, cw]` with kind 0 rapid, 1 feed, 2 arc,
    /// 3 thread, 4 run-out, 5 screw-in, 6 a roughing cut and `cw` 1 for
    /// clockwise arcs (X as a diameter).
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
                    Rough => 6.0,
                };
                let cw = m.arc.map_or(0.0, |a| if a.cw { 1.0 } else { 0.0 });
                out.extend_from_slice(&[kind, m.from.x, m.from.z, m.to.x, m.to.z, m.line as f64, cw]);
            }
            Ok(())
        });
        Float64Array::from(&out[..])
    }
}

impl Session {
    /// Runs `f` on the session's state, changing it; an error when nothing was planned yet.
    pub(super) fn with_state_mut<R>(&self, f: impl FnOnce(&mut State) -> Result<R, JsValue>) -> Result<R, JsValue> {
        let mut state = self.state.take();
        let out = match state.as_mut() {
            Some(s) => f(s),
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }

    /// Runs `f` on the session's state; an error when nothing was planned yet.
    pub(super) fn with_state<R>(&self, f: impl FnOnce(&State) -> Result<R, JsValue>) -> Result<R, JsValue> {
        let state = self.state.take();
        let out = match state.as_ref() {
            Some(s) => f(s),
            None => Err(err("nothing planned yet")),
        };
        self.state.set(state);
        out
    }

    /// A copy of the scene view `view` shows (for tests).
    #[cfg(test)]
    pub(crate) fn shown_scene(&self, view: &str) -> Option<Scene> {
        let w = super::shown::Which::parse(view)?;
        self.with_state(|st| Ok(st.shown.scene(w).cloned())).ok().flatten()
    }

    /// Whether the drawings show the roughing cuts.
    pub(super) fn roughing(&self) -> bool {
        self.roughing.get()
    }

    /// The language of the session's answers and labels.
    pub(super) fn lang(&self) -> Lang {
        self.lang.get()
    }

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

/// The tooth and starts scenes of thread `chosen` (start `start`) with their keys.
type Keyed = (Option<Rc<Scene>>, f64);
fn thread_scenes_of(plan: &Plan, chosen: Option<usize>, start: u32) -> (Keyed, Keyed) {
    let Some(t) = chosen else { return ((None, 0.0), (None, 0.0)) };
    let start = start.clamp(1, plan.threads[t].starts.max(1));
    // The small scenes are keyed by what they draw: an edit that leaves one as it was redraws nothing.
    let keyed = |s: Option<Scene>| match s {
        Some(s) => {
            let key = js_key(packed_key(&pack(&s)));
            (Some(Rc::new(s)), key)
        }
        None => (None, 0.0),
    };
    (keyed(diagram::tooth(plan, t, start)), keyed(diagram::starts(plan, t)))
}

/// Sets the chosen thread and its passes on `o`.
fn thread_parts(o: &Object, plan: &Plan, keys: &PlanKeys, chosen: Option<usize>, known: &Known) -> Result<(), JsValue> {
    set(o, "thread", &chosen.map_or(JsValue::NULL, |t| (t as u32).into()));
    let Some(t) = chosen else {
        return keyed(o, known, Part::Passes, 0, || Ok(Array::new().into()));
    };
    let listed_key = keys.listed[t];
    keyed(o, known, Part::Passes, combine(&[listed_key, t as u64]), || Ok(passes_to_js(&plan.threads[t])))
}

/// The object [`update`] returns, for `plan` of `text`.
#[allow(clippy::too_many_arguments)]
fn answer(
    text: &str,
    plan: &Plan,
    keys: &PlanKeys,
    (sent, diagnostics): (&mut ThreadsSent, &mut DiagnosticsSent),
    problems: &[SettingProblem],
    (chosen, _start, lang): (Option<usize>, u32, Lang),
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
    diagnostics.answer(&o, text, plan, lang, known_diagnostics)?;
    let all = keys.all_listed;
    keyed(&o, known, Part::Threads, all, || {
        sent.answer(known, all, &keys.listed, |i| to_js(&ThreadSummary::of(&plan.threads[i])))
    })?;
    thread_parts(&o, plan, keys, chosen, known)?;
    Ok(o)
}
