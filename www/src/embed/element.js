// <screwcut-preview>: a live thread diagram for documentation pages.
//
//   <script type="module" src="screwcut-preview.js"></script>
//   <screwcut-preview dialect="gsk980tdc" view="side table" height="300">
//     G00 X58 Z70
//     X47.1
//     G32 Z13 F2
//     ...
//   </screwcut-preview>
//
// Attributes: `dialect` (gsk980tdc, fanuc0i, renhe), `view` (any of side, tooth, starts, table),
// `height` (px per drawing), `thread` (1-based), `settings` ("NAME=VALUE; ..."), `src` (load the
// program from a URL instead of the text content), `editable` (a plain editor that re-plans as you
// type; without it the program is listed read-only, unless `hide-code`), `app` (the full app the "Open
// in editor" link goes to; default: a <meta name="screwcut-app" content="..."> of the page, else the
// app next to this script; only http(s) and relative URLs), `lang` (en, zh). `src` is fetched without
// credentials, at most 1 MiB, within 15 s. Whatever the element cannot use (an unknown dialect, a
// settings entry the planner refuses, an app URL that is not http(s)) is listed under the drawing and
// in `problems`. Every element on a page shares one wasm instance, loaded when the first element comes
// into view, and plans in a session of its own; each element plans and draws when it is scrolled near.
// An element whose static drawings (`<svg>` inside, as mdbook-screwcut writes them) show each of its
// views waits for the reader instead: it loads the planner when pointed at, touched or focused (`live`
// makes it start when scrolled near all the same). Properties: `program` (get/set), `result` (the
// planner's last answer), `start()`. Event `screwcut-plan` after every plan, with counts in `detail`.

import { HeldParts } from '../engine/parts.js';
import { DEFAULT_DIALECT, jsonFragment, knownDialect } from '../shared/fragment.js';
import { textIn } from '../shared/i18n.js';
import { passHead, passObjects, passRow, threadName, VirtualRows } from '../shared/lists.js';
import { esc, num } from '../shared/table.js';
import { bindCanvas } from '../view/input.js';
import { SceneView } from '../view/sceneview.js';
import { dedent, parseHeight, parseThread, parseViews, readSettings, safeUrl, settingsLines } from './attrs.js';
import { fetchProgram, forget, HERE, loadCore, startWhenVisible } from './core.js';
import { STYLE } from './style.js';

/** Most diagnostics listed under an embedded drawing. */
const MAX_LISTED = 6;

/** The elements inside a `<screwcut-preview>` that are its static parts, not its program. */
const STATIC_PARTS = new Set(['svg', 'table', 'ul']);

/** What the reader does to an element waiting with its static drawings that makes it live. */
const READER_EVENTS = ['pointerenter', 'focusin', 'touchstart'];

/** Attributes that change the layout (the rest only re-plan). */
const LAYOUT = new Set(['view', 'height', 'editable', 'hide-code', 'lang']);

export class ScrewcutPreview extends HTMLElement {
  static observedAttributes = ['dialect', 'view', 'height', 'editable', 'hide-code', 'src', 'app', 'settings', 'thread', 'lang', 'live'];

  constructor() {
    super();
    this.attachShadow({ mode: 'open' });
    this._text = null; // the program, once read
    this._staticOld = false; // the program or an attribute changed since the static drawing inside
    this._state = 'idle'; // idle → loading → ready | error
    this._views = {}; // name → SceneView
    this._result = null;
    this._lastGood = null;
    this._thread = null; // chosen in the bar; null: the `thread` attribute
    this._queued = false;
    this._hover = null;
    this._held = new HeldParts(); // parts of the planner's answers, by key
    this._diagList = []; // the last plan's diagnostics
    this._dialectProblem = null;
    this._appProblem = null;
  }

  connectedCallback() {
    // Static drawings inside (an <svg> per drawn view, as `screwcut svg` writes it) are the
    // fallback shown until the live ones, each in its view's place; a static pass table (a
    // <table>, as `screwcut embed` writes it) is copied into the element (_build), where it
    // takes the live table's style.
    this.querySelectorAll(':scope > svg').forEach((svg, i) => {
      svg.slot = `fallback-${i}`;
    });
    if (!this._built) this._build();
    if (this._state === 'idle') {
      this.dataset.state = 'idle';
      this._arm();
    }
  }

  disconnectedCallback() {
    if (this._state === 'idle') forget(this);
  }

  /**
   * Whether the element waits for the reader before it loads the planner:
   * its static parts show every view it has (one drawing per drawn view, a
   * table for the pass table), the program is its text, not being edited,
   * and no `live`.
   */
  _waitsForReader() {
    if (this._staticOld || this._text !== null || ['live', 'editable', 'src'].some((a) => this.hasAttribute(a))) return false;
    const views = this._viewNames || parseViews(this.getAttribute('view'));
    const drawn = views.filter((v) => v !== 'table').length;
    if (views.includes('table') && !this.querySelector(':scope > table')) return false;
    return this.querySelectorAll(':scope > svg').length >= drawn;
  }

  /**
   * An idle element starts when scrolled near, or — when its static
   * drawings show it all — at the reader's first pointer, touch or focus
   * on it (the static drawing until then says so).
   */
  _arm() {
    if (this._state !== 'idle') return;
    if (!this._waitsForReader()) {
      this._unlistenReader();
      if (this.isConnected) startWhenVisible(this);
      return;
    }
    forget(this);
    if (this._sum) this._sum.textContent = this._t('static_hint');
    if (this._wake) return;
    this._wake = () => this.start();
    for (const type of READER_EVENTS) this.addEventListener(type, this._wake, { passive: true });
  }

  _unlistenReader() {
    if (!this._wake) return;
    for (const type of READER_EVENTS) this.removeEventListener(type, this._wake);
    this._wake = null;
  }

  attributeChangedCallback(name, old, value) {
    if (!this._built || old === value) return;
    if (!['app', 'lang', 'live'].includes(name)) this._edited();
    if (name === 'live') {
      this._arm();
    } else if (LAYOUT.has(name)) {
      this._build();
      if (this._state === 'ready') this._plan();
      else this._arm();
    } else if (name === 'src') {
      if (this._state !== 'idle') this._load();
      else this._arm();
    } else if (name === 'app') {
      this._updateLink();
    } else if (name === 'thread') {
      this._thread = null;
      this._schedule();
    } else if (this._state === 'ready') {
      this._schedule();
    } else {
      this._arm();
    }
  }

  /**
   * The box's classes: `static` while a static drawing placed inside shows
   * in place of the live one; `printable` while that drawing is still of
   * the program and attributes shown (print uses it, crisp at any scale).
   */
  _boxClasses() {
    if (!this.querySelector(':scope > svg, :scope > table')) return '';
    const table = this.querySelector(':scope > table') ? ' static-table' : '';
    return (this._drawn ? '' : ' static') + (this._staticOld ? '' : ' printable') + table;
  }

  /** The program or an attribute it was drawn with changed: the static drawing no longer shows it. */
  _edited() {
    this._staticOld = true;
    this._box?.classList.remove('printable');
  }

  /** The G-code shown (the text content, without the static parts inside — drawings, table, list — or `src` until set). */
  get program() {
    if (this._text !== null) return this._text;
    let text = '';
    for (const n of this.childNodes) if (!(n.nodeType === 1 && STATIC_PARTS.has(n.localName))) text += n.textContent;
    return dedent(text);
  }

  set program(text) {
    this._text = String(text);
    this._edited();
    if (this._editor && this._editor.value !== this._text) this._editor.value = this._text;
    this._renderListing();
    if (this._state === 'ready') this._schedule();
    else this._arm();
  }

  /** The planner's last answer (see `update` in src/wasm.rs), or null. */
  get result() {
    return this._result;
  }

  /**
   * What the element could not use, as `[{attribute, message}]`: a
   * `dialect` it does not know, `settings` entries that are not NAME=VALUE
   * or that the planner refused, an `app` URL that is not http(s) or
   * relative. Listed under the drawing too.
   */
  get problems() {
    const out = [];
    if (this._dialectProblem) out.push({ attribute: 'dialect', message: this._dialectProblem });
    for (const p of readSettings(this.getAttribute('settings')).problems) out.push({ attribute: 'settings', message: p.message });
    for (const e of (this._result && this._result.settingErrors) || []) out.push({ attribute: 'settings', message: e.message });
    if (this._appProblem) out.push({ attribute: 'app', message: this._appProblem });
    return out;
  }

  /** Starts now, without waiting to be scrolled into view. */
  start() {
    if (this._state !== 'idle') return this._started;
    forget(this);
    this._unlistenReader();
    this._started = this._load();
    return this._started;
  }

  // ---- layout ----

  _t(key, vars) {
    return textIn(this._lang(), key, vars);
  }

  _lang() {
    return this.getAttribute('lang') === 'zh' ? 'zh' : 'en';
  }

  _build() {
    this._built = true;
    for (const b of this._bindings || []) b.destroy();
    this._bindings = [];
    this._rows = null;
    this._views = {};
    const views = parseViews(this.getAttribute('view'));
    this._viewNames = views;
    const h = parseHeight(this.getAttribute('height'));
    const editable = this.hasAttribute('editable');
    const staticTable = this.querySelector(':scope > table');
    const panes = views
      .map((v) =>
        v === 'table'
          ? `<div class="view table" data-view="table"><span class="cap">${esc(this._t('passes'))}</span><table><thead></thead><tbody></tbody></table></div>`
          : `<div class="view" data-view="${v}"><canvas role="img" aria-label="${esc(this._t(v))}"></canvas><span class="cap">${esc(this._t(v))}</span></div>`,
      )
      .join('');
    this.shadowRoot.innerHTML =
      `<style>${STYLE}</style><div class="box${this._boxClasses()}" part="box" style="--h:${h}px">` +
      `<div class="views live">${panes}</div>${this._fallbackHtml(views, staticTable)}` +
      (editable ? `<textarea spellcheck="false" autocapitalize="off" autocomplete="off" aria-label="G-code"></textarea>` : this.hasAttribute('hide-code') ? '' : `<pre class="code" part="code"></pre>`) +
      `<div class="bar"><span class="sum">${esc(this._t(this._state === 'idle' && this._waitsForReader() ? 'static_hint' : 'loading'))}</span><select class="thread" hidden aria-label="${esc(this._t('thread'))}"></select>` +
      `<a class="open" target="_blank" rel="noopener" part="open">${esc(this._t('open_in_editor'))} ↗</a></div>` +
      `<ul class="diags"${editable ? ' data-editable' : ''}></ul><div class="tip" hidden></div></div>`;
    const $ = (sel) => this.shadowRoot.querySelector(sel);
    this._sum = $('.sum');
    this._select = $('.thread');
    this._link = $('.open');
    this._diags = $('.diags');
    this._tip = $('.tip');
    this._box = $('.box');
    this._table = $('.views.live .view.table table');
    this._editor = $('textarea');
    this._listing = $('pre.code');
    if (staticTable) $('.views.fallback .view.table').append(staticTable.cloneNode(true));
    this._renderListing();
    this._select.addEventListener('change', () => {
      this._thread = Number(this._select.value);
      this._plan();
    });
    if (this._editor) {
      this._editor.value = this.program;
      this._editor.addEventListener('input', () => {
        this._text = this._editor.value;
        this._edited();
        this._schedule();
      });
    }
    this._diags.addEventListener('click', (e) => {
      const li = e.target.closest('li[data-line]');
      if (li && this._editor) this._gotoLine(Number(li.dataset.line));
    });
    this._updateLink();
    this._renderDiagnostics(this._diagList);
    if (this._state === 'ready') this._makeViews();
  }

  /**
   * The static parts inside the element — its `<svg>` drawings (slotted one
   * per drawn view, in view order) and a copy of its `<table>` — laid out as
   * the live views are, with their captions: shown until the live views are
   * drawn, and in print while they are of the program shown. Empty without
   * static parts.
   */
  _fallbackHtml(views, staticTable) {
    if (!staticTable && !this.querySelector(':scope > svg')) return '';
    let i = 0;
    const cap = (key) => `<span class="cap">${esc(this._t(key))}</span>`;
    const panes = views.map((v) => {
      if (v !== 'table') return `<div class="view" data-view="${v}"><slot name="fallback-${i++}"></slot>${cap(v)}</div>`;
      return staticTable ? `<div class="view table" data-view="table">${cap('passes')}</div>` : '';
    });
    return `<div class="views fallback" part="fallback">${panes.join('')}</div>`;
  }

  _makeViews() {
    for (const name of this._viewNames) {
      if (name === 'table') continue;
      const canvas = this.shadowRoot.querySelector(`.views.live .view[data-view="${name}"] canvas`);
      const view = new SceneView(canvas, { session: this._session, name, stretch: name === 'side' });
      this._views[name] = view;
      const binding = bindCanvas(
        canvas,
        {
          resize: (w, h, dpr) => view.setSize(w, h, dpr),
          pan: (dx, dy) => view.pan(dx, dy),
          zoom: (x, y, k) => view.zoomAt(x, y, k),
          fit: () => view.fit(),
          hover: (x, y, clientX, clientY) => {
            const info = view.pick(x, y);
            const key = info ? JSON.stringify(info) : null;
            if (key !== view.hovered) {
              view.hovered = key;
              this._onHover(info ? { ...info, x: clientX, y: clientY } : null);
            } else if (info) this._moveTip(clientX, clientY);
          },
          leave: () => {
            if (view.hovered !== null) {
              view.hovered = null;
              this._onHover(null);
            }
          },
          pick: (x, y) => {
            const info = view.pick(x, y);
            if (info && this._editor && info.lines.length) this._gotoLine(info.lines[0]);
          },
        },
        { wheel: 'ctrl' },
      );
      this._bindings.push(binding);
    }
  }

  // ---- planning ----

  async _load() {
    this._setState('loading');
    this._sum.textContent = this._t('loading');
    try {
      const src = this.getAttribute('src');
      let fetched = null;
      if (src) {
        const url = safeUrl(src, document.baseURI);
        if (!url) throw new Error(`src="${src.slice(0, 80)}" is not an http(s) or relative URL: not loaded`);
        fetched = fetchProgram(url, { label: src.slice(0, 80) });
      }
      const [core, text] = await Promise.all([loadCore(), fetched]);
      if (text !== null) this._text = text;
      this._renderListing();
      this._core = core;
      this._session ||= new core.Session();
      if (this._editor) this._editor.value = this.program;
      this._setState('ready');
      this._makeViews();
      this._plan();
    } catch (e) {
      this._fail(e);
    }
  }

  _schedule() {
    if (this._queued || this._state !== 'ready') return;
    this._queued = true;
    requestAnimationFrame(() => {
      this._queued = false;
      this._plan();
    });
  }

  _settings() {
    return readSettings(this.getAttribute('settings')).values;
  }

  /** The `dialect` attribute as the planner spells it; an unknown one is planned as GSK980TDc and said. */
  _dialect() {
    const asked = (this.getAttribute('dialect') || '').trim();
    this._dialectProblem = null;
    if (!asked) return DEFAULT_DIALECT;
    const known = this._core && this._core.dialects;
    if (!known) return asked;
    const d = knownDialect(asked, known);
    if (d) return d;
    this._dialectProblem = `dialect="${asked.slice(0, 40)}" is not one of ${known.map((x) => x.name).join(', ')}: planned as ${DEFAULT_DIALECT}`;
    return DEFAULT_DIALECT;
  }

  _plan() {
    if (this._state !== 'ready') return;
    const text = this.program;
    const thread = this._thread ?? parseThread(this.getAttribute('thread'));
    let r;
    try {
      this._session.set_lang(this._lang());
      // Every good plan is kept as the drawing shown greyed while a later text has an alarm.
      r = this._held.fill(this._session.update(text, this._dialect(), settingsLines(this._settings()), thread, 1, -1, this._held.known(), false, true));
    } catch (e) {
      this._held.clear();
      this._fail(e, true);
      return;
    }
    // The planner sends the passes as columns; the element's `result` keeps one object per pass.
    if (r.passes && !Array.isArray(r.passes)) {
      r.passColumns = r.passes;
      r.passes = passObjects(r.passes);
    }
    this._result = r;
    const stale = r.stale && this._lastGood;
    if (r.good) this._lastGood = r;
    const shown = stale ? this._lastGood : r;
    const keys = { side: r.shown[0], tooth: r.shown[1], starts: r.shown[2] };
    const relabel = this._drawnLang !== this._lang();
    for (const [name, view] of Object.entries(this._views)) {
      view.setShown(keys[name] || null, r.stale);
      if (relabel || (name === 'side' && shown.thread !== this._drawnThread)) view.relabel();
    }
    this._drawnThread = shown.thread;
    this._drawnLang = this._lang();
    // The live drawing takes the static one's place.
    this._drawn = true;
    this._box?.classList.remove('static');
    this._renderTable(shown, !!stale);
    this._renderBar(r, !!stale);
    this._renderDiagnostics(r.diagnostics);
    this._updateLink();
    this.dispatchEvent(
      new CustomEvent('screwcut-plan', {
        detail: { threads: r.threads.length, passes: (r.passes || []).length, alarms: r.alarms, warnings: r.warnings, notes: r.notes },
      }),
    );
  }

  _fail(e, keep = false) {
    const msg = String(e && e.message ? e.message : e);
    if (!keep) this._setState('error');
    this._sum.textContent = msg;
    this._sum.classList.add('stale');
    this.dispatchEvent(new CustomEvent('screwcut-error', { detail: { message: msg } }));
  }

  _setState(s) {
    this._state = s;
    this.dataset.state = s;
  }

  // ---- parts ----

  /** The read-only listing: one numbered line per program line. */
  _renderListing() {
    if (!this._listing) return;
    const lines = this.program.replace(/\n$/, '').split('\n');
    this._listing.innerHTML = lines.map((l, i) => `<span data-line="${i + 1}">${esc(l)}</span>`).join('');
  }

  /** Marks the listing's lines of what the pointer is over. */
  _markLines(lines) {
    if (!this._listing) return;
    for (const el of this._listing.querySelectorAll('span.hot')) el.classList.remove('hot');
    for (const l of lines) this._listing.querySelector(`span[data-line="${l}"]`)?.classList.add('hot');
  }

  _renderTable(r, stale) {
    if (!this._table) return;
    const t = (key) => this._t(key);
    const shown = r.threads.length > 0 ? r.threads[r.thread ?? 0] : null;
    const head = passHead(t, (shown && shown.units) || r.units);
    if (this._table.tHead.dataset.html !== head) {
      this._table.tHead.innerHTML = head;
      this._table.tHead.dataset.html = head;
    }
    this._rows ||= new VirtualRows(this._table.closest('.view.table'), this._table.tBodies[0], {
      rowHeight: 21,
      spacer: (h) => `<tr class="spacer" aria-hidden="true" style="height:${h}px"><td colspan="10"></td></tr>`,
    });
    const c = r.passColumns;
    this._rows.set(c ? c.n : 0, (i, hot) => passRow(c, i, t, hot, stale));
  }

  _renderBar(r, stale) {
    const th = r.threads.length > 0 ? r.threads[r.thread ?? 0] : null;
    let sum = this._t('embed_summary', { threads: r.threads.length, passes: th ? th.passes : 0, alarms: r.alarms, warnings: r.warnings });
    if (stale) sum += ` · ${this._t('stale')}`;
    this._sum.textContent = sum;
    this._sum.classList.toggle('stale', stale || r.alarms > 0);
    const options = r.threads.map((x, i) => `<option value="${i}">${i + 1}: ${esc(threadName(x, (k) => this._t(k)))} · ${esc(this._t('lead_of', { v: num(x.lead) }))} · L${x.line}–${x.end_line}</option>`).join('');
    if (this._select.dataset.html !== options) {
      this._select.innerHTML = options;
      this._select.dataset.html = options;
    }
    this._select.hidden = r.threads.length < 2;
    if (r.thread !== null && r.thread !== undefined) this._select.value = String(r.thread);
  }

  _renderDiagnostics(list) {
    this._diagList = list || [];
    const problems = this.problems.map((p) => `<li class="warning problem" data-attribute="${esc(p.attribute)}"><b>${esc(p.attribute)}</b> ${esc(p.message)}</li>`);
    const shown = this._diagList.filter((d) => d.severity !== 'info');
    const times = (d) => (d.repeats > 1 ? ` <i>${esc(this._t('raised_times', { n: d.repeats }))}</i>` : '');
    const row = (d) => `<li class="${d.severity}" data-line="${d.line}"><b>${d.line}:${d.column} ${esc(this._t(d.severity))}</b> <code>[${esc(d.code)}]</code> ${esc(d.message)}${times(d)}</li>`;
    const items = shown.slice(0, MAX_LISTED).map(row);
    if (shown.length > MAX_LISTED) items.push(`<li>${esc(this._t('more', { n: shown.length - MAX_LISTED }))}</li>`);
    const html = problems.concat(items).join('');
    // Until the live plan, the alarms and warnings listed inside the element (`screwcut embed`'s).
    const listed = this._drawn ? null : this.querySelector(':scope > ul[data-screwcut="diagnostics"]');
    if (listed) {
      this._diags.innerHTML = html;
      for (const li of listed.children) this._diags.append(li.cloneNode(true));
      this._diags.dataset.html = '(static)';
    } else if (this._diags.dataset.html !== html) {
      this._diags.innerHTML = html;
      this._diags.dataset.html = html;
    }
  }

  /** Points "Open in editor" at the app, carrying the program, dialect and settings. */
  _updateLink() {
    const dialect = this._result ? this._result.dialect : this._dialect();
    const state = { dialect, settings: { [dialect]: this._settings() }, program: this.program };
    this._link.href = this._appUrl().href + jsonFragment(state);
  }

  /**
   * The app "Open in editor" opens: `app`, else the page's
   * `<meta name="screwcut-app">`, else the app next to this script. Only
   * http(s) and relative URLs are used; another (`javascript:`, `data:`, …)
   * falls back to the next choice and is listed under the drawing.
   */
  _appUrl() {
    const attr = this.getAttribute('app');
    const meta = document.querySelector('meta[name="screwcut-app"]');
    const content = meta && meta.getAttribute('content');
    let problem = null;
    let url = null;
    for (const [what, value] of [
      ['app', attr],
      ['<meta name="screwcut-app">', content],
    ]) {
      if (url || value === null || value === undefined || !value.trim()) continue;
      url = safeUrl(value, document.baseURI);
      if (!url) problem ||= `${what}="${value.slice(0, 60)}" is not an http(s) or relative URL: "Open in editor" opens the default app`;
    }
    url ||= new URL(HERE);
    url.hash = '';
    if (problem !== this._appProblem) {
      this._appProblem = problem;
      if (this._diags) this._renderDiagnostics(this._diagList);
    }
    return url;
  }

  _gotoLine(line) {
    const ed = this._editor;
    const lines = ed.value.split('\n');
    let at = 0;
    for (let i = 0; i < Math.min(line - 1, lines.length); i++) at += lines[i].length + 1;
    ed.focus();
    ed.setSelectionRange(at, at + (lines[line - 1] || '').length);
  }

  _onHover(info) {
    const tip = this._tip;
    const r = this._result;
    for (const view of Object.values(this._views)) {
      view.setMark(info && info.pass >= 0 ? info : null);
    }
    this._rows?.mark(info && info.thread === r?.thread ? info.pass : -1);
    if (!info) {
      tip.hidden = true;
      this._markLines([]);
      return;
    }
    const p = info.pass >= 0 && r && info.thread === r.thread && r.passes ? r.passes[info.pass] : null;
    this._markLines(p ? p.lines : info.lines);
    let text = `${this._t('col_lines')} ${info.lines.join(', ')}`;
    if (p) {
      text =
        `${this._t('col_pass')} ${p.index}` +
        (r.threads[r.thread]?.starts > 1 ? ` · ${this._t('col_start')} ${p.start}` : '') +
        ` · X${num(p.from[0])} Z${num(p.from[1])}→${num(p.to[1])} · ${this._t('col_depth')} ${num(p.depth)} · ${this._t(p.role)} · ${text}`;
    }
    tip.textContent = text;
    tip.hidden = false;
    this._moveTip(info.x, info.y);
  }

  _moveTip(x, y) {
    const box = this._box.getBoundingClientRect();
    const tip = this._tip;
    const left = Math.max(4, Math.min(x - box.left + 12, box.width - tip.offsetWidth - 4));
    tip.style.left = `${left}px`;
    tip.style.top = `${y - box.top + 14}px`;
  }
}

if (!customElements.get('screwcut-preview')) customElements.define('screwcut-preview', ScrewcutPreview);
