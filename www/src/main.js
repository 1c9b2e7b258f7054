// screwcut web app: the editor, the three views, the pass table, the
// diagnostics list and the settings panel over the wasm planner. Every edit
// re-plans at once; a program with an alarm keeps the last good drawing
// visible, greyed.

import init, * as core from '../pkg/screwcut.js';
import { createEditor } from './editor.js';
import { SceneView } from './view.js';
import { t, label, setLang, getLang } from './i18n.js';
import { load, save, encodeFragment, decodeFragment } from './share.js';
import { num, esc, passTableHead, passTableRowList } from './table.js';
import { HeldParts } from './parts.js';

const $ = (id) => document.getElementById(id);
/** Sets an element's text unless it already reads so (a new text node means a new layout). */
const setText = (el, text) => {
  if (el.textContent !== text) el.textContent = text;
};

/** What the test and the curious can look at: timings and state. */
const probe = { ready: false, updates: [], frames: [], errors: [], result: null, editorAt: null };
window.__screwcut = probe;

const state = {
  dialect: 'gsk980tdc',
  settings: {}, // dialect → {name: value}
  program: '',
  lang: 'en',
};

let editor;
let views;
let styleNames;
let settingsTable = [];
let result = null; // the last update
let lastGood = null; // the last update without alarm that drew something
let thread = 0;
let start = 1;
let pendingInput = null;
let planQueued = false;
let hover = null;
let diagnosticsKey = -1; // key of the diagnostics the editor and the list show
const held = new HeldParts(); // parts of the answers, by key: the planner sends a part only when its key changes

function settingsText() {
  const s = state.settings[state.dialect] || {};
  return Object.entries(s)
    .map(([k, v]) => `${k}=${v}`)
    .join('\n');
}

let saveTimer = 0;
function persist() {
  clearTimeout(saveTimer);
  saveTimer = setTimeout(() => save(state), 300);
}

// ---- planning ----

function replan() {
  planQueued = false;
  const text = editor.text();
  state.program = text;
  persist();
  const t0 = performance.now();
  let r;
  try {
    r = held.fill(core.update(text, state.dialect, settingsText(), thread, start, diagnosticsKey, held.known()));
  } catch (e) {
    // A planner failure (which must not happen) keeps the page and the last drawing.
    diagnosticsKey = -1;
    held.clear();
    probe.errors.push(String(e && e.message ? e.message : e));
    showCrash();
    return;
  }
  const t1 = performance.now();
  for (const v of Object.values(views)) v.drawTime = 0;
  apply(r);
  const t2 = performance.now();
  probe.updates.push({ plan: t1 - t0, draw: t2 - t1, total: t2 - t0, lines: editor.view.state.doc.lines, ...probe.parts });
  if (probe.updates.length > 200) probe.updates.shift();
  setText($('timing'), t('timing', { plan: (t1 - t0).toFixed(1), draw: (t2 - t1).toFixed(1) }));
  if (pendingInput !== null) {
    const input = pendingInput;
    pendingInput = null;
    const editorAt = probe.editorAt;
    probe.editorAt = null;
    requestAnimationFrame(() => {
      // The views drew in this frame's callbacks; the canvases are rasterised
      // when the frame is committed, after the callbacks, in the same task.
      const canvas = views.side.drawTime + views.tooth.drawTime + views.starts.drawTime;
      const raf = performance.now() - input;
      afterTask(() => {
        const frame = performance.now() - input;
        probe.frames.push({ drawn: t2 - input, raf, frame, commit: frame - raf, canvas, editor: editorAt });
      });
    });
  }
}

/** Runs `f` in a new task: after a frame callback, once the frame is committed. */
function afterTask(f) {
  const ch = new MessageChannel();
  ch.port1.onmessage = () => {
    ch.port1.close();
    f();
  };
  ch.port2.postMessage(0);
}

function queuePlan() {
  if (pendingInput !== null && probe.editorAt === null) probe.editorAt = performance.now() - pendingInput;
  if (planQueued) return;
  planQueued = true;
  queueMicrotask(replan);
}

function apply(r) {
  const t0 = performance.now();
  result = r;
  probe.result = r;
  thread = r.thread ?? 0;
  const changed = r.diagnostics !== null;
  if (!changed) {
    // Unchanged by line and column: the editor has mapped its own through the edit.
    r.diagnostics = lastDiagnostics;
  } else {
    lastDiagnostics = r.diagnostics;
    diagnosticsKey = r.diagnosticsKey;
    editor.setDiagnosticsSoon(r.diagnostics);
  }
  const t1 = performance.now();
  if (changed) renderDiagnostics(r.diagnostics);
  renderThreads(r);
  renderSettingErrors(r.settingErrors);
  const t2 = performance.now();
  setText($('summary'), t('summary', {
    threads: r.threads.length,
    moves: r.moves,
    alarms: r.alarms,
    warnings: r.warnings,
    notes: r.notes,
  }));
  if (r.alarms > 0 && lastGood) {
    views.side.setScene(lastGood.side, true);
    views.tooth.setScene(lastGood.tooth, true);
    views.starts.setScene(lastGood.starts, true);
    banner(t('stale'));
  } else {
    if (r.good) lastGood = r;
    views.side.setScene(r.side, false);
    views.tooth.setScene(r.tooth, false);
    views.starts.setScene(r.starts, false);
    banner(null);
  }
  const t3 = performance.now();
  views.side.setThread(thread);
  refreshHighlight();
  probe.parts = { lint: t1 - t0, lists: t2 - t1, views: t3 - t2, highlight: performance.now() - t3 };
  if (!probe.ready) {
    probe.ready = true;
    document.body.dataset.ready = 'true';
  }
}

function showCrash() {
  if (lastGood) {
    views.side.setScene(lastGood.side, true);
    views.tooth.setScene(lastGood.tooth, true);
    views.starts.setScene(lastGood.starts, true);
  }
  banner(t('crashed'));
}

function banner(text) {
  const b = $('stale');
  b.hidden = !text;
  b.textContent = text || '';
}

/** Chooses the thread (and start) the tooth and starts views and the table show. */
function selectThread(ti, st = 1) {
  if (!result || ti === null || ti < 0 || ti >= result.threads.length) return;
  if (ti === thread && st === start && result.passes) return;
  thread = ti;
  start = st;
  let s;
  try {
    s = core.thread_scenes(ti, st);
  } catch (e) {
    probe.errors.push(String(e && e.message ? e.message : e));
    return;
  }
  held.fill(s);
  result.thread = s.thread;
  result.passes = s.passes;
  result.tooth = s.tooth;
  result.starts = s.starts;
  views.side.setThread(ti);
  renderThreads(result);
  if (!(result.alarms > 0 && lastGood)) {
    views.tooth.setScene(s.tooth, false);
    views.starts.setScene(s.starts, false);
  }
  refreshHighlight();
}

// ---- lists ----

let lastTable = ''; // the table head shown
let lastRows = []; // the rows shown
let shownThreads = null; // what the selector and the table were last rendered from
const options = new WeakMap(); // thread summary → {i, lang, html} of its option
/** The selector's option of thread summary `th` at index `i` (kept per summary: an unchanged one is not formatted again). */
function optionOf(th, i, lang) {
  const o = options.get(th);
  if (o && o.i === i && o.lang === lang) return o.html;
  const text = `${i + 1}: ${th.source.toUpperCase()} ${th.kind} · ${label('lead', num(th.lead))} · L${th.line}–${th.end_line} · ${th.passes}×`;
  const html = `<option value="${i}">${esc(text)}</option>`;
  options.set(th, { i, lang, html });
  return html;
}

function renderThreads(r) {
  const shown = { threads: r.threads, thread: r.thread, passes: r.passes, start, lang: getLang() };
  if (shownThreads && Object.keys(shown).every((k) => shown[k] === shownThreads[k])) return;
  shownThreads = shown;
  const sel = $('thread');
  const lang = getLang();
  const options = r.threads.map((th, i) => optionOf(th, i, lang)).join('');
  if (sel.dataset.html !== options) {
    sel.innerHTML = options;
    sel.dataset.html = options;
  }
  sel.value = r.thread ?? '';
  const th = r.threads[r.thread];
  const pick = $('start-pick');
  pick.hidden = !th || th.starts <= 1;
  if (th && th.starts > 1) {
    const s = $('start');
    const opts = Array.from({ length: Math.min(th.starts, 360) }, (_, i) => `<option value="${i + 1}">${i + 1}</option>`).join('');
    if (s.dataset.html !== opts) {
      s.innerHTML = opts;
      s.dataset.html = opts;
    }
    s.value = String(Math.min(start, th.starts));
  }
  $('no-threads').hidden = r.threads.length > 0;
  const head = passTableHead(t);
  if (head !== lastTable) {
    lastTable = head;
    $('passes').tHead.innerHTML = head;
  }
  // Row by row: an edit usually changes a row or two.
  const rows = passTableRowList(r.passes, t);
  const body = $('passes').tBodies[0];
  if (body.rows.length !== lastRows.length || Math.abs(rows.length - lastRows.length) > 50) {
    body.innerHTML = rows.join('');
  } else {
    const n = Math.min(rows.length, lastRows.length);
    for (let i = 0; i < n; i++) if (rows[i] !== lastRows[i]) body.rows[i].outerHTML = rows[i];
    for (let i = lastRows.length - 1; i >= rows.length; i--) body.rows[i].remove();
    if (rows.length > n) body.insertAdjacentHTML('beforeend', rows.slice(n).join(''));
  }
  lastRows = rows;
}

let lastDiags = []; // signatures of the entries the list shows
let lastDiagnostics = [];
const diagHtml = (d, i) =>
  `<li data-i="${i}" class="${d.severity}"><span class="pos">${d.line}:${d.column}</span><span class="sev">${t(d.severity)}</span><span><span class="code">[${esc(d.code)}]</span> ${esc(d.message)}</span></li>`;
/** Updates the list item by item: an edit usually changes a few entries of many. */
function renderDiagnostics(list) {
  const ul = $('diagnostics');
  const sigs = list.map((d) => `${d.severity}|${d.line}|${d.column}|${d.code}|${d.message}`);
  if (ul.children.length !== lastDiags.length) lastDiags = [];
  if (lastDiags.length === 0 || Math.abs(sigs.length - lastDiags.length) > 200) {
    ul.innerHTML = list.map(diagHtml).join('');
  } else {
    const n = Math.min(sigs.length, lastDiags.length);
    for (let i = 0; i < n; i++) if (sigs[i] !== lastDiags[i]) ul.children[i].outerHTML = diagHtml(list[i], i);
    for (let i = lastDiags.length - 1; i >= sigs.length; i--) ul.children[i].remove();
    if (sigs.length > n) ul.insertAdjacentHTML('beforeend', list.slice(n).map((d, k) => diagHtml(d, n + k)).join(''));
  }
  lastDiags = sigs;
  $('no-diagnostics').hidden = list.length > 0;
}

// ---- highlighting between editor, drawings and table ----

/** Highlights what `hover` points at, else what the cursor line draws. */
function refreshHighlight() {
  const sets = { side: new Set(), tooth: new Set(), starts: new Set() };
  let lines = [];
  if (hover && hover.pass >= 0) {
    for (const k of Object.keys(sets)) for (const i of views[k].itemsOfPass(hover.thread, hover.pass)) sets[k].add(i);
    const p = result && hover.thread === thread && result.passes ? result.passes[hover.pass] : null;
    lines = p ? p.lines : hover.lines;
    document.querySelectorAll('#passes tbody tr.hot').forEach((tr) => tr.classList.remove('hot'));
    if (hover.thread === thread) $('passes').tBodies[0].rows[hover.pass]?.classList.add('hot');
  } else {
    lines = hover ? hover.lines : [editor.cursorLine()];
    for (const k of Object.keys(sets)) for (const l of lines) for (const i of views[k].itemsOfLine(l)) sets[k].add(i);
    document.querySelectorAll('#passes tbody tr.hot').forEach((tr) => tr.classList.remove('hot'));
  }
  for (const k of Object.keys(sets)) views[k].setHighlight(sets[k]);
  editor.markLines(hover ? lines : []);
}

function onHover(info) {
  hover = info;
  refreshHighlight();
  tip(info);
}

/** A tooltip for what the pointer is over in a drawing. */
function tip(info) {
  const el = $('tip');
  if (!info || info.x === undefined) {
    el.hidden = true;
    return;
  }
  let text = `${t('col_lines')} ${info.lines.join(', ')}`;
  const p = info.pass >= 0 && info.thread === thread && result && result.passes ? result.passes[info.pass] : null;
  if (p) {
    text =
      `${t('thread')} ${info.thread + 1} · ${t('col_pass')} ${p.index}` +
      (p.start > 1 || (result.threads[thread] && result.threads[thread].starts > 1) ? ` · ${t('col_start')} ${p.start}` : '') +
      ` · X${num(p.from[0])} Z${num(p.from[1])}→${num(p.to[1])} · ${t('col_depth')} ${num(p.depth)} · ${t(p.role)} · ${text}`;
  }
  el.textContent = text;
  el.hidden = false;
  moveTip(info.x, info.y);
}

function moveTip(x, y) {
  const el = $('tip');
  el.style.left = `${Math.min(x + 14, window.innerWidth - el.offsetWidth - 8)}px`;
  el.style.top = `${y + 16}px`;
}

function onPick(info) {
  if (info.thread >= 0 && info.thread !== thread) selectThread(info.thread);
  const line = info.lines.length ? info.lines[0] : null;
  if (line) editor.goto(line);
}

function onCursor(line) {
  if (result) {
    const ti = result.threads.findIndex((th) => line >= th.line && line <= th.end_line);
    if (ti >= 0 && ti !== thread) selectThread(ti);
  }
  if (!hover) refreshHighlight();
}

// ---- settings ----

function buildSettings() {
  settingsTable = core.settings_table(state.dialect);
  const values = state.settings[state.dialect] || {};
  const zh = getLang() === 'zh';
  const html = settingsTable
    .map((s) => {
      const id = `set-${s.name.replace(/[^a-z0-9]/gi, '_')}`;
      const v = values[s.name];
      let input;
      if (s.kind === 'choice') {
        input = `<select id="${id}" data-name="${esc(s.name)}">${s.choices
          .map((c, i) => `<option value="${esc(c)}"${(v ?? s.choices[s.default]) === c ? ' selected' : ''}>${esc(c)}${i === s.default ? ' *' : ''}</option>`)
          .join('')}</select>`;
      } else if (s.kind === 'bool') {
        const on = v === undefined ? s.default !== 0 : v === '1';
        input = `<input type="checkbox" id="${id}" data-name="${esc(s.name)}"${on ? ' checked' : ''}>`;
      } else {
        const step = s.kind === 'int' ? '1' : 'any';
        input = `<input type="number" id="${id}" data-name="${esc(s.name)}" step="${step}" min="${s.min}" max="${s.max}" value="${esc(v ?? s.default)}">`;
      }
      const range = `${t('default')} ${num(s.default)} · ${t('range')} ${num(s.min)}…${num(s.max)}`;
      return `<div class="setting${v !== undefined ? ' changed' : ''}" data-name="${esc(s.name)}"><label for="${id}">${esc(s.name)} ${input} <span class="unit">${esc(s.unit)}</span></label><div class="help" title="${esc(range)}">${esc(zh ? s.help_zh : s.help)} <span class="unit">(${esc(range)})</span></div><div class="err"></div></div>`;
    })
    .join('');
  $('settings-form').innerHTML = html;
}

function onSettingInput(e) {
  const el = e.target;
  const name = el.dataset.name;
  if (!name) return;
  const def = settingsTable.find((s) => s.name === name);
  let value;
  if (el.type === 'checkbox') value = el.checked ? '1' : '0';
  else value = el.value.trim();
  const mine = (state.settings[state.dialect] ||= {});
  const isDefault =
    def && ((def.kind === 'choice' && def.choices[def.default] === value) || (def.kind !== 'choice' && value !== '' && Number(value) === def.default));
  if (isDefault || value === '') delete mine[name];
  else mine[name] = value;
  el.closest('.setting').classList.toggle('changed', !isDefault && value !== '');
  persist();
  replan();
}

function renderSettingErrors(list) {
  for (const el of document.querySelectorAll('.setting .err')) el.textContent = '';
  for (const e of list || []) {
    const row = [...document.querySelectorAll('.setting')].find((d) => d.dataset.name.toLowerCase() === e.setting.toLowerCase());
    if (row) row.querySelector('.err').textContent = e.message;
  }
}

// ---- examples, sharing, export ----

async function loadExamples() {
  try {
    const res = await fetch('examples/index.json');
    const list = await res.json();
    const sel = $('examples');
    sel.dataset.list = JSON.stringify(list);
    renderExamples();
    return list;
  } catch (e) {
    probe.errors.push(`examples: ${e}`);
    return [];
  }
}

function renderExamples() {
  const sel = $('examples');
  const list = JSON.parse(sel.dataset.list || '[]');
  const zh = getLang() === 'zh';
  sel.innerHTML =
    `<option value="">${esc(t('example_pick'))}</option>` +
    list.map((e, i) => `<option value="${i}">${esc(zh && e.title_zh ? e.title_zh : e.title)}</option>`).join('');
}

async function openExample(entry) {
  const res = await fetch(`examples/${encodeURIComponent(entry.file)}`);
  const text = await res.text();
  if (entry.dialect) setDialect(entry.dialect, false);
  editor.setText(text);
}

function setDialect(name, plan = true) {
  state.dialect = name;
  $('dialect').value = name;
  buildSettings();
  persist();
  if (plan) replan();
}

function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 5000);
}

function toast(text) {
  const el = $('toast');
  el.textContent = text;
  setTimeout(() => {
    if (el.textContent === text) el.textContent = '';
  }, 2500);
}

async function share() {
  const url = `${location.origin}${location.pathname}${encodeFragment(state)}`;
  history.replaceState(null, '', url);
  try {
    await navigator.clipboard.writeText(url);
    toast(t('shared'));
  } catch {
    toast(t('share_failed'));
  }
}

function bindViewBar(panelId, view, name) {
  const panel = $(panelId);
  panel.querySelector('.bar').addEventListener('click', async (e) => {
    const act = e.target.dataset && e.target.dataset.act;
    if (act === 'fit') view.fit();
    if (act === 'stretch') e.target.setAttribute('aria-pressed', String(view.toggleStretch()));
    if (act === 'svg') {
      const svg = view.toSVG();
      if (svg) download(`screwcut-${name}.svg`, new Blob([svg], { type: 'image/svg+xml' }));
    }
    if (act === 'png') {
      const png = await view.toPNG(2);
      if (png) download(`screwcut-${name}.png`, png);
    }
  });
}

// ---- start ----

async function main() {
  window.addEventListener('error', (e) => probe.errors.push(String(e.message)));
  await init({ module_or_path: new URL('screwcut_bg.wasm', document.baseURI) });
  styleNames = core.style_names();
  probe.core = core;
  probe.text = () => (editor ? editor.text() : null);
  probe.editor = () => editor;
  probe.dialect = () => state.dialect;
  const linked = decodeFragment(location.hash);
  const saved = linked || load();
  if (saved) {
    if (typeof saved.dialect === 'string') state.dialect = saved.dialect;
    if (saved.settings && typeof saved.settings === 'object') state.settings = saved.settings;
    if (typeof saved.program === 'string') state.program = saved.program;
    if (saved.lang === 'zh' || saved.lang === 'en') state.lang = saved.lang;
  } else if (navigator.language && navigator.language.startsWith('zh')) {
    state.lang = 'zh';
  }
  if (!core.dialects().some((d) => d.name === state.dialect)) state.dialect = 'gsk980tdc';
  if (linked) {
    // The link's program becomes the kept one; a reload shows later edits, not the link again.
    save(state);
    history.replaceState(null, '', location.pathname + location.search);
  }
  setLang(state.lang);
  $('lang').textContent = state.lang === 'zh' ? 'English' : '中文';
  $('dialect').innerHTML = core
    .dialects()
    .map((d) => `<option value="${d.name}">${esc(d.title)}</option>`)
    .join('');
  $('dialect').value = state.dialect;
  buildSettings();

  const tr = (key, value) => label(key, value);
  const mk = (id, name) =>
    new SceneView($(id), { styleNames, tr, onHover, onPick, onMove: moveTip, name, stretch: name === 'side' });
  views = { side: mk('side', 'side'), tooth: mk('tooth', 'tooth'), starts: mk('starts', 'starts') };
  probe.views = views;
  bindViewBar('side-panel', views.side, 'side');
  document.querySelector('#side-panel [data-act="stretch"]').setAttribute('aria-pressed', 'true');
  bindViewBar('tooth-panel', views.tooth, 'tooth');
  bindViewBar('starts-panel', views.starts, 'starts');

  editor = createEditor($('editor'), { doc: state.program, onChange: queuePlan, onCursor });
  editor.view.dom.addEventListener('keydown', (e) => (pendingInput = e.timeStamp), true);
  editor.view.dom.addEventListener('beforeinput', (e) => {
    if (pendingInput === null) pendingInput = e.timeStamp;
  }, true);

  const list = await loadExamples();
  if (!saved) {
    const o1006 = list.find((e) => e.file === 'o1006.nc') || list[0];
    if (o1006) {
      await openExample(o1006);
      return finishSetup();
    }
  }
  replan();
  finishSetup();
}

function finishSetup() {
  $('dialect').addEventListener('change', (e) => setDialect(e.target.value));
  $('examples').addEventListener('change', async (e) => {
    const list = JSON.parse(e.target.dataset.list || '[]');
    const entry = list[Number(e.target.value)];
    e.target.value = '';
    if (entry) await openExample(entry);
  });
  $('settings-form').addEventListener('change', onSettingInput);
  $('settings-form').addEventListener('submit', (e) => e.preventDefault());
  $('settings-reset').addEventListener('click', () => {
    state.settings[state.dialect] = {};
    buildSettings();
    persist();
    replan();
  });
  $('settings-toggle').addEventListener('click', () => {
    $('settings').hidden = !$('settings').hidden;
    $('settings-toggle').setAttribute('aria-pressed', String(!$('settings').hidden));
  });
  $('share').addEventListener('click', share);
  $('plan-json').addEventListener('click', () => {
    const json = core.plan_json(editor.text(), state.dialect, settingsText());
    download('screwcut-plan.json', new Blob([json], { type: 'application/json' }));
  });
  $('lang').addEventListener('click', () => {
    state.lang = getLang() === 'zh' ? 'en' : 'zh';
    setLang(state.lang);
    $('lang').textContent = state.lang === 'zh' ? 'English' : '中文';
    renderExamples();
    buildSettings();
    persist();
    lastTable = '';
    lastRows = [];
    lastDiags = [];
    renderDiagnostics(lastDiagnostics);
    replan();
  });
  $('thread').addEventListener('change', (e) => selectThread(Number(e.target.value), 1));
  $('start').addEventListener('change', (e) => selectThread(thread, Number(e.target.value)));
  const tbody = $('passes').tBodies[0];
  tbody.addEventListener('mouseover', (e) => {
    const tr = e.target.closest('tr');
    if (!tr || !result || !result.passes) return;
    const i = Number(tr.dataset.pass);
    const p = result.passes[i];
    if (p) onHover({ thread, pass: i, lines: p.lines });
    $('tip').hidden = true;
  });
  tbody.addEventListener('mouseleave', () => onHover(null));
  tbody.addEventListener('click', (e) => {
    const tr = e.target.closest('tr');
    const p = tr && result && result.passes ? result.passes[Number(tr.dataset.pass)] : null;
    if (p) editor.goto(p.lines[0]);
  });
  $('diagnostics').addEventListener('click', (e) => {
    const li = e.target.closest('li');
    const d = li && result ? result.diagnostics[Number(li.dataset.i)] : null;
    if (d) editor.goto(d.line, d.column);
  });
  window.addEventListener('hashchange', () => {
    const s = decodeFragment(location.hash);
    if (s && typeof s.program === 'string') {
      if (typeof s.dialect === 'string') setDialect(s.dialect, false);
      if (s.settings) state.settings = s.settings;
      buildSettings();
      editor.setText(s.program);
      history.replaceState(null, '', location.pathname + location.search);
    }
  });
}

main().catch((e) => {
  probe.errors.push(String(e && e.stack ? e.stack : e));
  document.body.dataset.ready = 'failed';
  console.error(e);
});
