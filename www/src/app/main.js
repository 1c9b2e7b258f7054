// screwcut web app: the editor, the three views, the pass table, the
// diagnostics list and the settings panel. Planning and drawing run in the
// engine (engine.js) — in a worker drawing on OffscreenCanvases where the
// browser has them (client.js) — so typing never waits for them. A program
// with an alarm keeps the last good drawing and table, greyed.

import { createEditor } from '../editor/editor.js';
import { startEngine } from '../engine/client.js';
import { patchList, spliceList } from '../engine/parts.js';
import { afterFrame } from '../engine/task.js';
import { EDITOR_PHRASES_ZH, getLang, setLang, t } from '../shared/i18n.js';
import { passHead, passLines, passRow, passVia, setOptions, threadOptions, tipText, VirtualRows } from '../shared/lists.js';
import { esc } from '../shared/table.js';
import { bindListKeys, labelViews } from './a11y.js';
import { showBehind } from './behind.js';
import { bindDesignation, DESIGNATION, renderCheck } from './check.js';
import { Compare } from './compare.js';
import { DiagnosticsList } from './diaglist.js';
import { bindMenus, loadExamples, openExample, renderExamples } from './menus.js';
import { showBanner, showTip, toast } from './pageutil.js';
import { Planning } from './planning.js';
import { Library } from './programs.js';
import { SettingsPanel } from './settingspanel.js';
import { DEFAULT_DIALECT, knownDialect } from './share.js';
import { TextSync } from './textsync.js';
import { bindViewBar } from './viewbar.js';

const $ = (id) => document.getElementById(id);
/** Sets an element's text unless it already reads so (a new text node means a new layout). */
const setText = (el, text) => {
  if (el.textContent !== text) el.textContent = text;
};

/**
 * What the tests and the curious can look at: timings and state. `hold`:
 * while true, edits are not planned (the bench measures the page alone;
 * the next edit after it sends them).
 */
const probe = { ready: false, updates: [], frames: [], errors: [], result: null, mode: null, hold: false };
window.__screwcut = probe;

const state = {
  dialect: 'gsk980tdc',
  settings: {}, // dialect → {name: value}
  lang: 'en',
};
/** The program as last set (null: the editor's text, read when asked for: typing builds no text). */
let programSet = '';
Object.defineProperty(state, 'program', {
  enumerable: true,
  get: () => programSet ?? editor.text(),
  set: (text) => {
    programSet = text;
  },
});
/** What the engine holds of the editor's text (a keystroke sends the changes). */
const sync = new TextSync();

let client;
let settingsPanel;
let dialects = [];
let editor;
/**
 * What the page shows and points at, as one value changed only by `update`
 * (a new value each time): the lists of the last answer (threads, passes as
 * columns, diagnostics), the chosen thread and start, what is hovered, the
 * severities the diagnostics list shows and the rows it shows; the last plan's timing.
 */
let ui = Object.freeze({ result: null, thread: 0, start: 1, hover: null, severities: new Set(['error', 'warning', 'info']), diagnosticsShown: [], timing: null });
/** The next `ui`: the last one with the fields of `patch`. */
function update(patch) {
  ui = Object.freeze({ ...ui, ...patch });
}
let planning; // plans in flight, keystrokes, the good plan's lists (planning.js)
let compareUi = null; // Compare with… (compare.js)
let passRows;
const diagList = new DiagnosticsList($('diagnostics'), { t, lang: getLang });
const lists = []; // the keyboard-operated lists (a11y.js)

function settingsText() {
  const s = state.settings[state.dialect] || {};
  return Object.entries(s)
    .map(([k, v]) => `${k}=${v}`)
    .join('\n');
}

// ---- the programs kept in the browser (programs.js) ----

let library = null;

/** The language last written to the preferences (written again only when it changed). */
let savedLang = null;

/** Keeps the open program (and the language) once typing pauses. */
function persist() {
  if (!library) return;
  if (state.lang !== savedLang) {
    library.savePrefs({ lang: state.lang });
    savedLang = state.lang;
  }
  library.saveSoon();
}

/** Puts a program (another entry, a link, an example, a new one) in the editor and plans it. */
async function showProgram(s) {
  state.dialect = knownDialect(s.dialect, dialects) || DEFAULT_DIALECT;
  state.settings = s.settings && typeof s.settings === 'object' ? s.settings : {};
  state.program = s.program;
  $('dialect').value = state.dialect;
  planning.another();
  diagList.reset();
  // What was chosen in the last program (a thread, a start, a hovered pass) is not this one's.
  update({ thread: 0, start: 1, hover: null });
  makeEditor(state.program);
  await buildSettings();
  replan();
}

/** The editor's own words in the page's language. */
function editorWords() {
  return { phrases: getLang() === 'zh' ? EDITOR_PHRASES_ZH : {}, empty: t('empty_program') };
}

/**
 * A new editor for each program shown: undo never reaches into the
 * program that was open before.
 */
function makeEditor(doc) {
  if (editor) editor.view.destroy();
  const onChange = (changes, before, after) => {
    // The program is the editor's from now on.
    programSet = null;
    sync.changed(changes, before, after);
    if (probe.hold) persist();
    else replan(after);
  };
  editor = createEditor($('editor'), { doc, onChange, onCursor, words: editorWords() });
  editor.view.dom.addEventListener('keydown', (e) => planning.input(e.timeStamp), true);
  editor.view.dom.addEventListener('beforeinput', (e) => planning.input(e.timeStamp, true), true);
}

// ---- planning ----

/**
 * Sends the text (`doc`, the editor's document unless given) to the engine;
 * while a plan is in flight, only the latest text follows it.
 */
function replan(doc = editor.view.state.doc) {
  const request = () => ({ ...sync.take(doc), dialect: state.dialect, settings: settingsText(), thread: ui.thread, start: ui.start });
  if (!planning.plan(request, doc)) return;
  persist();
}

/** The engine's messages to the page (answers to requests go to their callers). */
const HANDLERS = {
  result: (m) => onResult(m),
  frame: (m) => onFrame(m),
  hover: (m) => onViewHover(m),
  pick: (m) => onPick(m.info),
  error: (m) => {
    probe.errors.push(m.message);
    if (m.resync) {
      // The engine could not follow the changes sent: the whole text goes next.
      sync.reset();
      planning.failed();
      replan();
      return;
    }
    if (m.crashed) {
      sync.reset();
      planning.failed();
      banner(t('crashed'));
    }
  },
  note: (m) => {
    probe.notes = [...(probe.notes || []), m.message];
  },
};

function onMessage(m) {
  HANDLERS[m.type]?.(m);
}

function onResult(m) {
  const r = m.r;
  if (r.threads === undefined) r.threads = ui.result ? ui.result.threads : [];
  else if (r.threads.changes) r.threads = patchList(ui.result ? ui.result.threads : [], r.threads);
  if (r.passes === undefined) r.passes = ui.result ? ui.result.passes : null;
  if (r.diagnosticsSplice) {
    r.diagnostics = spliceList(ui.result ? ui.result.diagnostics : [], r.diagnosticsSplice);
    delete r.diagnosticsSplice;
    editor.setDiagnosticsSoon(r.diagnostics);
  } else if (r.diagnostics === null) r.diagnostics = ui.result ? ui.result.diagnostics : [];
  else editor.setDiagnosticsSoon(r.diagnostics);
  const t0 = performance.now();
  update({ result: r, thread: r.thread ?? 0 });
  probe.result = r;
  const a = planning.answered(r, m.seq, editor.view.state.doc);
  if (r.comparison) compareUi?.show(r.comparison);
  const lines = editor.view.state.doc.lines;
  const lists = () => {
    const t1 = performance.now();
    renderLists(r);
    if (m.timing) {
      const total = a.t0 === null ? null : performance.now() - a.t0;
      probe.updates.push({ seq: m.seq, ...m.timing, lists: performance.now() - t1, total, lines, resumedAt: r.resumedAt, sent: a.t0 ?? undefined, received: t0 });
      if (probe.updates.length > 200) probe.updates.shift();
      update({ timing: m.timing });
      showTiming();
    }
  };
  // Once the page is up, the lists follow the drawing by a frame: rendering
  // them (and the layout that follows) before the page's next paint held up
  // the paint of the keystroke itself.
  if (probe.ready) listsAfterPaint(lists);
  else lists();
  if (a.again) replan();
  if (!probe.ready) {
    probe.ready = true;
    document.body.dataset.ready = 'true';
    dropFirstVisit();
  }
}

/** The example's program and drawings the page holds for a first visit (index.html) give way to the app's own. */
function dropFirstVisit() {
  performance.mark('screwcut:first-live');
  document.documentElement.classList.remove('first-visit', 'first-zh');
  for (const el of document.querySelectorAll('.first')) el.remove();
}

/** The drawing that includes an edit is on screen: mark it, at the time it was committed, for whoever measures. */
function onFrame(m) {
  const input = planning.frameInput(m.seq, m.input);
  if (input === null) return;
  // When the engine committed it (the page's thread may come to this message later).
  const at = Number.isFinite(m.at) ? Math.min(performance.now(), m.at - performance.timeOrigin) : performance.now();
  performance.mark('screwcut:frame', { startTime: at, detail: { input } });
  probe.frames.push({ seq: m.seq, frame: at - input, at });
  if (probe.frames.length > 200) probe.frames.shift();
}

// ---- lists ----

/** The footer's timing of the last plan (`ui.timing`: planning, drawing), in the page's language. */
const showTiming = (m = ui.timing) => m && setText($('timing'), t('timing', { plan: m.plan.toFixed(1), draw: m.views.toFixed(1) }));

/** The latest lists to render after the next paint (null: none waiting). */
let listsWaiting = null;

/** Runs `f` (the latest one given) after the page's next paint, or in 100 ms where frames are not drawn (a hidden page). */
function listsAfterPaint(f) {
  const first = listsWaiting === null;
  listsWaiting = f;
  if (!first) return;
  const run = () => {
    const g = listsWaiting;
    listsWaiting = null;
    g?.();
  };
  afterFrame(run);
  setTimeout(run, 100);
}

function renderLists(r) {
  const { shown, stale } = planning.shown();
  setText(
    $('summary'),
    t('summary', { threads: r.threads.length, moves: r.moves, alarms: r.alarms, warnings: r.warnings, notes: r.notes }) + (r.timeS != null ? ` · ${t('summary_time', { s: r.timeS.toFixed(1) })}` : ''),
  );
  banner(stale ? t('stale') : null);
  renderThreads(shown, stale);
  const problem = (r.settingErrors || []).find((e) => e.setting.toLowerCase() === DESIGNATION);
  const strip = { input: $('designation'), verdict: $('check-verdict'), figures: $('check-figures') };
  const shownThread = shown.threads[shown.thread];
  // A thread's figures are in the units its words were written in (the program may switch G20/G21).
  const units = (shownThread && shownThread.units) || shown.units;
  renderCheck(strip, shownThread, units, t, (state.settings[state.dialect] || {})[DESIGNATION], problem && problem.message);
  labelViews(shown, shown.thread ?? 0, ui.start, t);
  renderDiagnostics(r.diagnostics);
  renderSettingErrors(r.settingErrors);
}

function banner(text) {
  showBanner($('stale'), text);
}

function renderThreads(r, stale) {
  const sel = $('thread');
  setOptions(sel, threadOptions(r.threads, t, getLang()));
  sel.value = r.thread ?? '';
  // Greyed, the lists show the kept plan: another thread is chosen once the alarm is gone.
  sel.disabled = !!stale;
  const th = r.threads[r.thread];
  const pick = $('start-pick');
  pick.hidden = !th || th.starts <= 1;
  if (th && th.starts > 1) {
    const s = $('start');
    setOptions(
      s,
      Array.from({ length: Math.min(th.starts, 360) }, (_, i) => `<option value="${i + 1}">${i + 1}</option>`),
    );
    s.value = String(Math.min(ui.start, th.starts));
  }
  $('no-threads').hidden = r.threads.length > 0;
  const head = passHead(t, (th && th.units) || r.units);
  if ($('passes').tHead.dataset.html !== head) {
    $('passes').tHead.innerHTML = head;
    $('passes').tHead.dataset.html = head;
  }
  $('passes').classList.toggle('stale', !!stale);
  const c = r.passes;
  // The Start selector filters the table to one start of a multi-start thread.
  const order = [];
  if (c) for (let i = 0; i < c.n; i++) if (!th || th.starts <= 1 || c.start[i] === ui.start) order.push(i);
  passRows.order = order;
  passRows.set(order.length, (k, hot) => passRow(c, order[k], t, hot, stale));
}

/** The diagnostics list as last rendered: the same list, filter and language render nothing. */
let rendered = { list: null, severities: null, lang: null };

function renderDiagnostics(list) {
  if (list === rendered.list && ui.severities === rendered.severities && getLang() === rendered.lang) return;
  rendered = { list, severities: ui.severities, lang: getLang() };
  const shown = list.map((d, i) => [d, i]).filter(([d]) => ui.severities.has(d.severity));
  update({ diagnosticsShown: shown });
  diagList.show(shown);
  const counts = { error: 0, warning: 0, info: 0 };
  for (const d of list) counts[d.severity]++;
  for (const sev of Object.keys(counts)) setText(document.querySelector(`#sev-filter [data-sev="${sev}"] .n`), String(counts[sev]));
  $('no-diagnostics').hidden = list.length > 0;
}

// ---- highlighting between editor, drawings and table ----

/** Highlights what `hover` points at, else what the cursor line draws. */
function refreshHighlight() {
  const lines = ui.hover ? ui.hover.lines : [];
  client.send({ type: 'highlight', hover: ui.hover, cursor: editor.cursorLine() });
  editor.markLines(lines, (ui.hover && ui.hover.via) || []);
  const k = ui.hover && ui.hover.pass >= 0 && ui.hover.thread === ui.thread ? passRows.order.indexOf(ui.hover.pass) : -1;
  passRows.mark(k, ui.hover && ui.hover.fromView);
}

function onViewHover(m) {
  const info = m.info;
  update({ hover: info && (info.pass >= 0 || info.lines.length) ? { thread: info.thread, pass: info.pass, lines: passLinesOf(info), via: passViaOf(info), fromView: true } : null });
  refreshHighlight();
  tip(info, m.clientX, m.clientY);
}

/** The lines a hovered item stands for: its pass's four blocks when it is a pass of the chosen thread. */
function passLinesOf(info) {
  if (info.pass >= 0 && info.thread === ui.thread && ui.result && ui.result.passes) return passLines(ui.result.passes, info.pass);
  return info.lines;
}

/** The calls that cut a hovered pass of the chosen thread (marked apart from its own lines). */
function passViaOf(info) {
  return info.pass >= 0 && info.thread === ui.thread && ui.result && ui.result.passes ? passVia(ui.result.passes, info.pass) : [];
}

/** A tooltip for what the pointer is over in a drawing. */
function tip(info, x, y) {
  showTip($('tip'), info && x !== undefined ? tipText(info, ui.result, ui.thread, t) : null, x, y);
}

function onPick(info) {
  if (!info) return;
  if (info.thread >= 0 && info.thread !== ui.thread) selectThread(info.thread);
  const line = info.lines.length ? info.lines[0] : null;
  if (line) editor.goto(line);
}

/** Chooses the thread (and start) the tooth and starts views and the table show. */
function selectThread(ti, st = 1) {
  if (!ui.result || ti === null || ti < 0 || ti >= ui.result.threads.length) return;
  if (ti === ui.thread && st === ui.start && ui.result.passes) return;
  update({ thread: ti, start: st });
  client.send({ type: 'select', thread: ti, start: st });
}

function onCursor(line) {
  if (ui.result) {
    const ti = ui.result.threads.findIndex((th) => line >= th.line && line <= th.end_line);
    if (ti >= 0 && ti !== ui.thread) selectThread(ti);
  }
  if (!ui.hover) client.send({ type: 'highlight', hover: null, cursor: line });
}

// ---- settings (settingspanel.js) ----

async function buildSettings() {
  await settingsPanel.build(state.dialect, state.settings[state.dialect] || {});
}

function onSettingInput(e) {
  state.settings[state.dialect] ||= {};
  if (settingsPanel.change(e.target, state.settings[state.dialect])) {
    persist();
    replan();
  }
}

const renderSettingErrors = (list) => settingsPanel.showErrors(list);

// ---- the dialect ----

async function setDialect(name, plan = true) {
  state.dialect = dialects.some((d) => d.name === name) ? name : 'gsk980tdc';
  $('dialect').value = state.dialect;
  await buildSettings();
  persist();
  if (plan) replan();
}

// ---- start ----

async function main() {
  window.addEventListener('error', (e) => probe.errors.push(String(e.message)));
  const params = new URLSearchParams(location.search);
  const started = await startEngine({
    wasmUrl: new URL('screwcut_bg.wasm', document.baseURI),
    workerUrl: new URL('worker.js', document.baseURI),
    mode: params.get('engine'),
    onMessage,
  });
  client = started.client;
  planning = new Planning((m) => client.send(m), showBehind);
  settingsPanel = new SettingsPanel($('settings-form'), { table: (dialect) => client.request('table', { what: 'settings', dialect }), t, lang: getLang });
  dialects = started.dialects;
  probe.mode = client.mode;
  probe.inspect = (what, name, format) => client.request('inspect', { what, name, format });
  Object.assign(probe, { text: () => (editor ? editor.text() : null), editor: () => editor, dialect: () => state.dialect });
  // The lists show the plan of the editor's text: no plan in flight or to follow, none waiting for the paint.
  probe.settled = () => planning.idle() && listsWaiting === null;
  // A link opens as a new program (its fragment is then taken off the
  // address, so a reload shows later edits); else the program this tab had open.
  let limitRows = null;
  library = new Library({
    getState: () => ({ dialect: state.dialect, settings: state.settings, program: state.program }),
    show: showProgram,
    dialects,
    limits: async () => (limitRows ||= (await client.request('table', { what: 'settings', dialect: DEFAULT_DIALECT })).filter((s) => s.name.startsWith('limits.'))),
  });
  probe.library = library;
  const prefs = library.prefs();
  if (prefs.lang === 'zh' || prefs.lang === 'en') state.lang = prefs.lang;
  else if (navigator.language && navigator.language.startsWith('zh')) state.lang = 'zh';
  setLang(state.lang);
  const saved = await library.start(location.hash);
  if (saved) {
    state.dialect = saved.dialect;
    state.settings = saved.settings;
    state.program = saved.program;
  }
  library.render();
  client.send({ type: 'lang', lang: state.lang });
  $('lang').textContent = state.lang === 'zh' ? 'English' : '中文';
  $('dialect').innerHTML = dialects.map((d) => `<option value="${d.name}">${esc(d.title)}</option>`).join('');
  $('dialect').value = state.dialect;
  await buildSettings();

  client.bindView('side', $('side'), { stretch: true });
  client.bindView('tooth', $('tooth'));
  client.bindView('starts', $('starts'));
  document.querySelector('#side-panel [data-act="stretch"]').setAttribute('aria-pressed', 'true');
  compareUi = new Compare({ client, library, t, currentId: () => library.current?.id, strip: $('compare') });
  for (const name of ['side', 'tooth', 'starts']) bindViewBar($(`${name}-panel`), name, client, (act) => act === 'compare' && compareUi.open());

  const scroller = $('passes').closest('.scroll');
  passRows = new VirtualRows(scroller, $('passes').tBodies[0], {
    rowHeight: 22,
    spacer: (h) => `<tr class="spacer" aria-hidden="true" style="height:${h}px"><td colspan="12"></td></tr>`,
  });
  passRows.order = [];
  lists.push(
    ...bindListKeys({
      passes: scroller,
      diagnostics: $('diagnostics'),
      rows: passRows,
      result: () => ui.result,
      thread: () => ui.thread,
      shown: () => ui.diagnosticsShown,
      diagnosticRow: (k) => diagList.row(k),
      setHover: (h) => {
        update({ hover: h });
        refreshHighlight();
      },
      goto: (line, column) => editor.goto(line, column),
      t,
    }),
  );

  makeEditor(state.program);

  const list = await loadExamples(probe.errors);
  if (!saved) {
    const o1006 = list.find((e) => e.file === 'o1006.nc') || list[0];
    if (o1006) {
      await openExample({ state, library }, o1006);
      return finishSetup();
    }
  }
  replan();
  return finishSetup();
}

function finishSetup() {
  $('dialect').addEventListener('change', (e) => setDialect(e.target.value));
  bindMenus({ state, client, library, dialects, persist, buildSettings, editor: () => editor, result: () => ui.result, thread: () => ui.thread, replan: () => replan() });
  $('settings-form').addEventListener('change', onSettingInput);
  bindDesignation($('designation'), (v) => {
    state.settings[state.dialect] ||= {};
    const mine = state.settings[state.dialect];
    if (v) mine[DESIGNATION] = v;
    else delete mine[DESIGNATION];
    persist();
    replan();
  });
  $('lang').addEventListener('click', async () => {
    state.lang = getLang() === 'zh' ? 'en' : 'zh';
    setLang(state.lang);
    client.send({ type: 'lang', lang: state.lang });
    $('lang').textContent = state.lang === 'zh' ? 'English' : '中文';
    renderExamples();
    editor.setWords(editorWords());
    for (const l of lists) l.relabel();
    await buildSettings();
    persist();
    if (ui.result) renderLists(ui.result);
    showTiming();
  });
  $('thread').addEventListener('change', (e) => selectThread(Number(e.target.value), 1));
  $('start').addEventListener('change', (e) => {
    update({ start: Number(e.target.value) });
    selectThread(ui.thread, ui.start);
    if (ui.result) renderThreads(ui.result, false);
  });
  bindLists();
  // A link followed while the app is open: a new program, checked as at start.
  window.addEventListener('hashchange', () => library.openLink(location.hash));
}

/** The pass table and the diagnostics list: pointing, clicking, the severities shown. */
function bindLists() {
  const tbody = $('passes').tBodies[0];
  const rowPass = (e) => {
    const tr = e.target.closest('tr[data-pass]');
    return tr ? Number(tr.dataset.pass) : -1;
  };
  tbody.addEventListener('mouseover', (e) => {
    const i = rowPass(e);
    if (i < 0 || !ui.result || !ui.result.passes) return;
    update({ hover: { thread: ui.thread, pass: i, lines: passLines(ui.result.passes, i), via: passVia(ui.result.passes, i) } });
    refreshHighlight();
    $('tip').hidden = true;
  });
  tbody.addEventListener('mouseleave', () => {
    update({ hover: null });
    refreshHighlight();
  });
  tbody.addEventListener('click', (e) => {
    const i = rowPass(e);
    if (i >= 0 && ui.result && ui.result.passes) editor.goto(passLines(ui.result.passes, i)[0]);
  });
  $('diagnostics').addEventListener('click', (e) => {
    const to = e.target.closest('button.switch');
    if (to) {
      setDialect(to.dataset.dialect);
      toast(t('switched', { title: to.dataset.title }));
      return;
    }
    const li = e.target.closest('li[data-i]');
    const d = li && ui.result ? ui.result.diagnostics[Number(li.dataset.i)] : null;
    if (d) editor.goto(d.line, d.column);
  });
  $('sev-filter').addEventListener('change', (e) => {
    const sev = e.target.closest('[data-sev]')?.dataset.sev;
    if (!sev) return;
    const severities = new Set(ui.severities);
    if (e.target.checked) severities.add(sev);
    else severities.delete(sev);
    update({ severities });
    if (ui.result) renderDiagnostics(ui.result.diagnostics);
  });
}

main().catch((e) => {
  probe.errors.push(String(e && e.stack ? e.stack : e));
  document.body.dataset.ready = 'failed';
  dropFirstVisit(); // the example's drawing is not what a failed app shows
  console.error(e);
});
