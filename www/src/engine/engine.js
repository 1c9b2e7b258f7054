// The planning and drawing engine of the app: the wasm planner's session
// and the three views, driven by messages. It runs in a Worker with the
// views on OffscreenCanvases (worker.js), so the page's thread keeps only
// the editor and the lists; where a browser has no OffscreenCanvas it runs
// on the page with the same messages (client.js).
//
// Messages in: view, size, input, plan, select, highlight, lang, export,
// json, tool, inspect. Messages out: result (after each plan: counts, lists and
// the chosen thread's passes as columns), frame (once the drawing that
// includes an edit is on screen, and when), hover, pick, reply, error.

import { SceneView } from '../view/sceneview.js';
import { HeldParts, spliceList } from './parts.js';

/** The views, in the order of the session's `shown` keys. */
const VIEWS = ['side', 'tooth', 'starts'];

export class Engine {
  /**
   * @param core the initialised wasm module (`Session`, `dialects`, …)
   * @param post `post(message, transfer)` to the page
   * @param afterCommit runs a function once the current frame is on screen
   * @param opts `{immediate, loadTools}`: `immediate` draws a plan's views
   *   at once rather than at the next animation frame (in a worker, whose
   *   canvases then go on screen at that frame, before the page's lists;
   *   pan and zoom still draw at animation frames); `loadTools` resolves
   *   to the initialised tools module (`toolsLoader`), called the first
   *   time a tool is used
   */
  constructor(core, post, afterCommit, opts = {}) {
    this.immediate = !!opts.immediate;
    this.loadTools = opts.loadTools || (() => Promise.reject(new Error('no tools module')));
    this.toolsLoading = null; // the tools module, once asked for
    this.core = core;
    this.post = post;
    this.afterCommit = afterCommit;
    this.session = new core.Session();
    this.views = {};
    this.held = new HeldParts();
    this.lang = 'en';
    this.result = null;
    this.diagnosticsKey = -1; // the key of the diagnostics list held (`diagnostics`)
    this.diagnostics = [];
    this.pageDiagnosticsKey = -1; // the key of the list the page holds
    this.lastSplice = null; // {base, key, splice}: the change the session answered last
    this.thread = 0;
    this.start = 1;
    this.hover = null;
    this.cursor = 1;
    this.pendingFrame = null; // {seq, input} of a plan whose drawing is awaited
    this.sentThreads = null;
    this.sentPasses = null;
    this.roughing = false; // the roughing cuts of G71/G72 are drawn on demand
    this.text = null; // the text last planned (a plan may come as changes to it)
    this.planned = null; // {text, dialect, settings} of the last plan: what the tools write
    this.sentAs = null; // how it came: 'text' or 'edits'
    this.crossed = null; // how it reached the session: 'text' (whole) or 'edits' (made to the text it kept)
    this.tidying = false; // a tidy of the session is queued
  }

  handle(m) {
    const fail = (e) => this.post({ type: 'error', message: String(e && e.message ? e.message : e), id: m.id });
    try {
      const f = this[`on_${m.type}`];
      if (!f) throw new Error(`unknown message '${m.type}'`);
      const out = f.call(this, m);
      // An async handler's failure is an answer too, not an unhandled rejection.
      if (out && typeof out.catch === 'function') return out.catch(fail);
      return out;
    } catch (e) {
      fail(e);
      return undefined;
    }
  }

  on_view({ name, canvas, stretch }) {
    this.views[name] = new SceneView(canvas, { session: this.session, name, stretch, onDrawn: () => this.drawn() });
  }

  on_size({ name, w, h, dpr }) {
    this.views[name]?.setSize(w, h, dpr);
  }

  on_input({ id, name, op, x, y, dx, dy, k, clientX, clientY }) {
    const v = this.views[name];
    if (!v) return;
    if (op === 'pan') v.pan(dx, dy);
    else if (op === 'zoom') v.zoomAt(x, y, k);
    else if (op === 'fit') v.fit();
    else if (op === 'stretch') this.post({ type: 'reply', id, data: v.toggleStretch() });
    else if (op === 'roughing') {
      // A display option of the session (its drawings), shown on demand.
      this.roughing = !this.roughing;
      this.session.set_roughing(this.roughing);
      for (const view of Object.values(this.views)) view.draw();
      this.post({ type: 'reply', id, data: this.roughing });
    } else if (op === 'leave') {
      if (v.hovered !== null) this.post({ type: 'hover', name, info: null });
      v.hovered = null;
    } else if (op === 'hover') {
      const info = v.pick(x, y);
      const key = info ? JSON.stringify(info) : null;
      if (key !== v.hovered) {
        v.hovered = key;
        this.post({ type: 'hover', name, info, clientX, clientY });
      }
    } else if (op === 'pick') {
      const info = v.pick(x, y);
      if (info) this.post({ type: 'pick', name, info });
    }
  }

  /** Another language: the drawings' labels and the last plan's diagnostics (no new plan; thread summaries carry both languages). */
  on_lang({ lang }) {
    this.lang = lang === 'zh' ? 'zh' : 'en';
    this.session.set_lang(this.lang);
    for (const v of Object.values(this.views)) v.relabel();
    if (!this.result) return;
    const r = this.held.fill(this.session.relabel());
    this.holdDiagnostics(r);
    Object.assign(this.result, { diagnostics: r.diagnostics, diagnosticsKey: r.diagnosticsKey });
    this.postResult(this.result, null, null);
  }

  /**
   * Plans `text` and shows it; answers with a result now and a frame once
   * drawn. `fresh`: the text is another program's, so an alarm in it shows
   * no greyed drawing of the program before; `keep`: the page says the
   * drawing on screen was left (the session keeps it as the good one).
   */
  on_plan({ seq, text, edits, length, dialect, settings, thread, start, input, fresh, keep }) {
    if (edits) {
      text = this.text === null ? null : applyEdits(this.text, edits);
      if (text === null || text.length !== length) {
        // Changes to a text not held (or not the page's): the page sends the whole text.
        this.text = null;
        this.post({ type: 'error', message: 'the text changes do not fit the text held', resync: true });
        return;
      }
    }
    // The session makes the same changes to the text it kept (last first, so
    // that each change's offsets still hold): the text then need not cross
    // into wasm whole. One that does not fit, or none kept: the whole text.
    let whole = true;
    if (edits) {
      whole = false;
      for (let i = edits.length - 1; i >= 0 && !whole; i--) whole = !this.session.edit(edits[i][0], edits[i][1], edits[i][2]);
    }
    this.text = text;
    this.planned = { text, dialect, settings };
    this.sentAs = edits ? 'edits' : 'text';
    this.crossed = whole ? 'text' : 'edits';
    if (thread !== undefined) this.thread = thread;
    if (start !== undefined) this.start = start;
    const t0 = performance.now();
    let r;
    try {
      r = this.held.fill(this.session.update(whole ? text : undefined, dialect, settings, this.thread, this.start, this.diagnosticsKey, this.held.known(), !!fresh, !!keep));
    } catch (e) {
      // A planner failure (which must not happen) leaves the drawings on screen as they are (the views cannot draw).
      this.diagnosticsKey = -1;
      this.lastSplice = null;
      this.held.clear();
      this.post({ type: 'error', message: String(e && e.message ? e.message : e), crashed: true });
      return;
    }
    const t1 = performance.now();
    this.apply(r);
    if (input !== undefined && input !== null) this.pendingFrame = { seq, input };
    const t2 = performance.now();
    // In a worker the drawings go on screen first: the page's lists follow them.
    if (this.immediate) for (const v of Object.values(this.views)) v.flush();
    this.maybeFrameNow();
    this.postResult(r, seq, { plan: t1 - t0, views: t2 - t1, draw: performance.now() - t2 });
    // The scenes no longer shown are freed after this task, once the drawing is on screen.
    if (!this.tidying) {
      this.tidying = true;
      setTimeout(() => {
        this.tidying = false;
        this.session.tidy();
      }, 0);
    }
  }

  /** Shows answer `r` in the views: what the session shows (the last good drawing, greyed, while the text has an alarm). */
  apply(r) {
    const before = this.thread;
    this.result = r;
    this.thread = r.thread ?? 0;
    this.holdDiagnostics(r);
    this.show(r.shown, r.stale);
    if (this.thread !== before) this.views.side?.relabel();
    this.refreshHighlight();
  }

  /** Holds answer `r`'s diagnostics (sent whole, unchanged or as a change) and sets the whole list on `r`. */
  holdDiagnostics(r) {
    if (r.diagnosticsSplice) {
      this.lastSplice = { base: this.diagnosticsKey, key: r.diagnosticsKey, splice: r.diagnosticsSplice };
      this.diagnostics = spliceList(this.diagnostics, r.diagnosticsSplice);
    } else if (r.diagnostics !== null) {
      this.lastSplice = null;
      this.diagnostics = r.diagnostics;
    }
    this.diagnosticsKey = r.diagnosticsKey;
    r.diagnostics = this.diagnostics;
  }

  /** The diagnostics for the page: null when it holds them, the change when it holds the list before it, else the list. */
  diagnosticsForPage(r) {
    const page = this.pageDiagnosticsKey;
    this.pageDiagnosticsKey = r.diagnosticsKey;
    if (r.diagnosticsKey === page) return { diagnostics: null };
    const s = this.lastSplice;
    if (s && s.base === page && s.key === r.diagnosticsKey) return { diagnostics: null, diagnosticsSplice: s.splice };
    return { diagnostics: r.diagnostics };
  }

  /** Each view shows the scene of its key (`shown`: side, tooth, starts). */
  show(shown, stale) {
    VIEWS.forEach((name, i) => {
      this.views[name]?.setShown(shown[i] || null, stale);
    });
  }

  /** Posts what the page's lists need; lists it already has are not sent again. */
  postResult(r, seq, timing) {
    // The thread list: nothing when the page holds it, else the entries that changed when they are few.
    const threads = r.threads === this.sentThreads ? undefined : listChanges(this.sentThreads, r.threads);
    this.sentThreads = r.threads;
    // The passes come from the planner as columns of typed arrays (copied, not moved: the engine keeps them).
    const passes = r.passes === this.sentPasses ? undefined : r.passes;
    this.sentPasses = r.passes;
    const out = {
      type: 'result',
      seq,
      timing,
      r: {
        dialect: r.dialect,
        units: r.units,
        alarms: r.alarms,
        warnings: r.warnings,
        notes: r.notes,
        moves: r.moves,
        timeS: r.timeS,
        good: r.good,
        stale: r.stale,
        plan: r.plan,
        goodPlan: r.goodPlan,
        comparison: r.comparison,
        settingErrors: r.settingErrors,
        ...this.diagnosticsForPage(r),
        diagnosticsKey: r.diagnosticsKey,
        threads,
        thread: r.thread,
        passes,
        resumedAt: r.resumedAt,
      },
    };
    this.post(out);
  }

  /** Another thread or start for the tooth and starts views and the table. */
  on_select({ thread, start, seq }) {
    if (!this.result) return;
    this.thread = thread;
    this.start = start ?? 1;
    const s = this.held.fill(this.session.thread_scenes(thread, this.start));
    Object.assign(this.result, { thread: s.thread, passes: s.passes, shown: s.shown, stale: s.stale });
    this.show(s.shown, s.stale);
    this.views.side?.relabel();
    this.refreshHighlight();
    this.postResult(this.result, seq, null);
  }

  /** The page's hover (a pass or lines, from a drawing or the table) and the editor's cursor line. */
  on_highlight({ hover, cursor }) {
    this.hover = hover || null;
    if (cursor) this.cursor = cursor;
    this.refreshHighlight();
  }

  /** What the pointer or the table points at, else what the cursor line draws (a lighter mark). */
  refreshHighlight() {
    const h = this.hover;
    for (const v of Object.values(this.views)) v.setMark(h || { lines: [this.cursor] }, !h);
  }

  /** After a draw: once every view that had to draw has, the awaited frame is reported. */
  drawn() {
    this.maybeFrameNow();
  }

  maybeFrameNow() {
    const f = this.pendingFrame;
    if (!f || Object.values(this.views).some((v) => v.queued)) return;
    this.pendingFrame = null;
    // `at`: when it was committed, on the clock the page and the worker share (their time origins differ).
    this.afterCommit(() => this.post({ type: 'frame', seq: f.seq, input: f.input, at: performance.timeOrigin + performance.now() }));
  }

  /**
   * A view as a file: SVG from the core's writer of the view's display list
   * (what `screwcut svg` writes), PNG as the canvas paints the same list:
   * either is what the view shows, at its size and transform.
   */
  async on_export({ id, name, format, scale }) {
    const v = this.views[name];
    // Only the tooth and starts views can show nothing: a program without a thread.
    if (v && v.key === null) throw new Error(`no thread to draw the ${name} view of`);
    let data = null;
    if (v && format === 'svg') data = v.svg();
    else if (v) data = await v.toPNG(scale || 2);
    this.post({ type: 'reply', id, data });
  }

  /** Compares the last plan with another program and lays its passes over the side and tooth sections; answers the comparison. */
  on_compare({ id, text, dialect, settings }) {
    const r = this.session.compare(text, dialect, settings || '');
    this.show(r.shown, r.stale);
    this.post({ type: 'reply', id, data: r.comparison });
  }

  /** Takes the compared program off the drawings. */
  on_compare_off({ id }) {
    const r = this.session.compare_off();
    this.show(r.shown, r.stale);
    this.post({ type: 'reply', id, data: true });
  }

  /** Tables the page's panels show: `what: 'settings'` of `dialect`. */
  on_table({ id, what, dialect }) {
    const data = what === 'settings' ? this.core.settings_table(dialect) : null;
    this.post({ type: 'reply', id, data });
  }

  /** The tools module, loaded the first time a tool is used (a failed load is tried again next time). */
  tools() {
    this.toolsLoading ||= this.loadTools().catch((e) => {
      this.toolsLoading = null;
      throw new Error(`the tools did not load: ${e && e.message ? e.message : e}`);
    });
    return this.toolsLoading;
  }

  /**
   * The program-writing tools, from the tools module: `what: 'forms'` (the
   * wizard's controllers and forms), `'generate'` (the wizard's program for
   * `request`), `'expand'` (the last plan block by block for dialect `to`),
   * their notes and refusals in the page's language. A wrong request is
   * answered with an error naming it.
   */
  async on_tool({ id, what, request, to }) {
    if (!['forms', 'generate', 'expand'].includes(what)) throw new Error(`unknown tool '${what}'`);
    // What is asked for is fixed now: a plan arriving while the tools load is not the one expanded.
    const { planned, lang } = this;
    if (what === 'expand' && !planned) throw new Error('nothing planned yet');
    const tools = await this.tools();
    let data;
    if (what === 'forms') data = tools.wizard_forms(lang);
    else if (what === 'generate') data = tools.wizard_generate({ ...request, lang });
    else data = tools.expand(planned.text, planned.dialect, planned.settings || '', to, lang);
    this.post({ type: 'reply', id, data });
  }

  /** The last plan as the CLI's JSON (`--json`), from the tools module. */
  async on_json({ id }) {
    const { planned } = this;
    if (!planned) throw new Error('nothing planned yet');
    const tools = await this.tools();
    this.post({ type: 'reply', id, data: JSON.stringify(tools.plan_value(planned.text, planned.dialect, planned.settings || '')) });
  }

  /**
   * For tests and benchmarks: `view` (what view `name` shows: key,
   * transform, stale, mark, size), `pixels` (the inked pixels of its
   * canvas), `draws` (each view's last drawing time, ms), `labels` (its
   * labels as placed), `svg` (its SVG export), `point` (where the first
   * item of style `format` is drawn in it, CSS px), `result` (keys and
   * thread list of the last answer), `items` (the items of style `format`
   * of the scene it shows, world coordinates).
   */
  on_inspect({ id, what, name, format }) {
    const v = this.views[name];
    const data = {
      view: () => {
        if (!v) return null;
        const l = v.labels() && v.list;
        // A digest of the display list: what is painted, to compare two pages.
        const digest = l ? `${l.ops.length}|${Array.from(l.nums, (x) => Math.round(x * 100)).join(',')}|${l.texts.join('|')}` : '';
        return { key: v.key, transform: v.transform(), stale: v.stale, mark: v.mark, size: [v.cssW, v.cssH], ops: l ? l.ops.length / 7 : 0, digest, texts: l ? l.texts : [] };
      },
      pixels: () => {
        if (!v) return null;
        const c = v.canvas;
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235)) n++;
        return { n, w: c.width, h: c.height };
      },
      draws: () => Object.fromEntries(Object.entries(this.views).map(([k, view]) => [k, view.lastDraw])),
      paints: () =>
        Object.fromEntries(
          Object.entries(this.views).map(([k, view]) => [k, { draw: view.lastDraw, paint: view.lastPaint, ops: view.list ? view.list.ops.length / 7 : 0, numbers: view.list ? view.list.nums.length : 0 }]),
        ),
      labels: () => v && v.labels(),
      // The text the engine planned last, how it came (whole or as changes),
      // the session's copy and how that reached it.
      text: () => ({ text: this.text, sentAs: this.sentAs, kept: this.session.kept_text(), crossed: this.crossed }),
      svg: () => v && v.svg(),
      items: () => this.session.items_of_style(name, format),
      point: () => {
        const xf = v && v.transform();
        return xf ? this.session.locate(name, format, new Float64Array([xf.sx, xf.sy, xf.tx, xf.ty])) : null;
      },
      result: () => {
        const r = this.result;
        return r && { threads: r.threads, thread: r.thread, shown: r.shown && Array.from(r.shown), stale: r.stale, resumedAt: r.resumedAt };
      },
    }[what];
    this.post({ type: 'reply', id, data: data ? data() : null });
  }
}

/**
 * `now` as the page needs it after `before`: `{changes: [[index, entry]],
 * length}` when few entries changed (a first-pass edit of a program of
 * 2,000 threads changes one summary: the other 1,999 are not copied to the
 * page again), else the whole list. Unchanged entries keep their identity
 * (the parts holder patches lists entry by entry).
 */
function listChanges(before, now) {
  if (!Array.isArray(before) || !Array.isArray(now) || now.length < 64) return now;
  const changes = [];
  for (let i = 0; i < now.length; i++) {
    if (now[i] !== before[i]) {
      changes.push([i, now[i]]);
      if (changes.length * 4 > now.length) return now;
    }
  }
  return { changes, length: now.length };
}

/** `text` with `edits` (`[from, to, inserted]`, in order, offsets in `text`) made. */
export function applyEdits(text, edits) {
  let out = '';
  let at = 0;
  for (const [from, to, inserted] of edits) {
    if (from < at || to < from || to > text.length) return null;
    out += text.slice(at, from) + inserted;
    at = to;
  }
  return out + text.slice(at);
}

/**
 * Loads the tools module (`screwcut_tools_bg.wasm` and its glue
 * `screwcut_tools.js`, beside the wasm at `wasmUrl`) and resolves to its
 * initialised glue: the thread wizard, a plan written block by block, the
 * plan as JSON. A page loads it only when one of them is first used.
 */
export function toolsLoader(wasmUrl) {
  return async () => {
    // The glue is a bundle of its own beside the wasm (`screwcut_tools.js`).
    const tools = await import(new URL('screwcut_tools.js', wasmUrl).href);
    await tools.default({ module_or_path: new URL('screwcut_tools_bg.wasm', wasmUrl) });
    return tools;
  };
}
