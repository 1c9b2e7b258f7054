// The programs kept in this browser, and the header's Programs menu.
//
// Opening a link, an example or "New" never overwrites a program: each
// becomes an entry of its own, and the one that was open stays in the list
// to be reopened. An entry is {id, name, dialect, settings, program,
// created, updated}; its name is the program's first comment or O number
// (else "Untitled" and the date it was made).
//
// Kept in localStorage, not IndexedDB: the app needs the open program
// before it makes its editor, and localStorage answers synchronously (no
// start-up round trip, and a save on `pagehide` completes before the page
// goes); it is where the one program of earlier versions was kept
// (`screwcut.state.v1`, moved into the list as its first entry); and the
// list is bounded well under its quota (MAX_PROGRAMS entries, MAX_STORED_CHARS
// in all). Each entry has its own key, so saving while typing rewrites one
// program and the small index, not the whole list. The open entry is
// remembered per tab (sessionStorage), so a reload reopens what the tab had
// open, and across tabs (localStorage) for a new tab.
//
// Where the browser refuses storage (private mode, blocked site data) the
// list lives in memory for the tab and the menu says the programs are not
// kept. A full list refuses to grow and says so; nothing is evicted.
// The storage itself is store.js.

import { setOptions } from '../shared/lists.js';
import { esc } from '../shared/table.js';
import { cleanSettings, DEFAULT_DIALECT, knownDialect, LINK_MAX_BYTES, readFragment, sanitizeLinked, titleOf } from './share.js';
import { INDEX, MAX_PROGRAMS, MAX_STORED_CHARS, newIdFor, Programs, programName } from './store.js';

const EN = {
  programs: 'Programs',
  programs_title: 'Programs kept in this browser: choose one to reopen it',
  new: 'New',
  new_title: 'Start an empty program (the open one stays in the list)',
  new_for: 'A new program for {title}: change the controller beside it if it is for another',
  delete: 'Delete',
  delete_title: 'Delete the open program from this browser (you can undo)',
  untitled: 'Untitled {date}',
  not_kept: 'not kept',
  storage_off: 'This browser does not let the page keep data (private mode or blocked site data): programs last until this tab closes. Use "Copy link" to keep one.',
  storage_off_short: 'not kept: no storage',
  full: 'Your programs are full ({count} of {max} programs, {size} of {maxSize}): “{name}” is open but not kept. Delete a program you no longer need (Programs menu) to keep it.',
  quota: 'The browser refused to store more: “{name}” is open but not kept. Delete a program you no longer need to make room.',
  kept_again: '“{name}” is kept now.',
  link_new: 'The link opened as a new program, “{name}”. Your other programs are in the Programs menu.',
  link_same: 'This link’s program is already kept as “{name}”: opened it.',
  link_refused: 'The link was not opened: {why}. Your programs are unchanged.',
  link_changed: 'The link was opened with changes: {what}.',
  clamped: 'Links may lower the planner’s limits but not raise them: {list}. Change them in Parameters if you trust this program.',
  deleted: 'Deleted “{name}”.',
  undo: 'Undo',
  close: 'Close',
  stored_dialect: '“{name}” was kept for controller ‘{dialect}’, which is not known: opened as {title}.',
};

const ZH = {
  programs: '程序',
  programs_title: '保存在此浏览器中的程序：选择一个重新打开',
  new: '新建',
  new_title: '新建空程序(当前程序保留在列表中)',
  new_for: '已为 {title} 新建程序：如果是为其他系统编写，请在旁边改选系统',
  delete: '删除',
  delete_title: '从此浏览器删除当前程序(可撤销)',
  untitled: '未命名 {date}',
  not_kept: '未保存',
  storage_off: '此浏览器不允许页面保存数据(隐私模式或已屏蔽网站数据)：程序只保留到关闭此标签页。可用“复制链接”保存。',
  storage_off_short: '未保存：无存储',
  full: '程序已满({count}/{max} 个，{size}/{maxSize})：“{name}”已打开但未保存。请在“程序”菜单中删除不需要的程序。',
  quota: '浏览器拒绝保存更多数据：“{name}”已打开但未保存。请删除不需要的程序。',
  kept_again: '“{name}”已保存。',
  link_new: '链接已作为新程序“{name}”打开。其他程序在“程序”菜单中。',
  link_same: '此链接的程序已保存为“{name}”：已打开。',
  link_refused: '链接未打开：{why}。您的程序未改变。',
  link_changed: '链接打开时有改动：{what}。',
  clamped: '链接可以降低规划器的限制，但不能提高：{list}。如信任此程序，可在“参数”中修改。',
  deleted: '已删除“{name}”。',
  undo: '撤销',
  close: '关闭',
  stored_dialect: '“{name}”保存时的控制器“{dialect}”未知：按 {title} 打开。',
};

const lang = () => ((document.documentElement.lang || '').startsWith('zh') ? 'zh' : 'en');

/** Text of `key` in the page's language, `{name}` fields filled from `vars`. */

export function tr(key, vars) {
  let s = (lang() === 'zh' ? ZH : EN)[key] ?? EN[key] ?? key;
  if (vars) s = s.replace(/\{(\w+)\}/g, (_, k) => (k in vars ? String(vars[k]) : `{${k}}`));
  return s;
}

const pad = (n) => String(n).padStart(2, '0');
/** "2025-03-01 14:05" in local time. */
/** Settings that describe one program, not the machine: a new program does not take them over. */
const OWN = ['thread.designation', 'program.main', 'program.main_repeats', 'macro.variables'];

/**
 * The settings a new program starts with: a copy of the open one's
 * controller and machine settings, without those that describe that
 * program (its designation, main program, macro variables).
 */
export function inherited(settings) {
  const out = {};
  for (const [d, s] of Object.entries(settings || {})) {
    if (!s || typeof s !== 'object') continue;
    out[d] = {};
    for (const [k, v] of Object.entries(s)) if (!OWN.includes(k.trim().toLowerCase())) out[d][k] = v;
  }
  return out;
}

export function stamp(ms) {
  const d = new Date(ms);
  return `${d.getFullYear()}-${pad(d.getMonth() + 1)}-${pad(d.getDate())} ${pad(d.getHours())}:${pad(d.getMinutes())}`;
}

/** A message's words: given, or from a function giving them in the page's language. */
const wordsOf = (w) => (typeof w === 'function' ? w() : w);
const sizeText = (chars) => (chars >= 1048576 ? `${(chars / 1048576).toFixed(1)} M` : `${Math.ceil(chars / 1024)} K`) + (lang() === 'zh' ? '字符' : ' characters');

/** The name shown for entry `e`. */
export const shownName = (e) => e.name || tr('untitled', { date: stamp(e.created) });

export class Library {
  constructor({ getState, show, dialects, limits, programs = new Programs() }) {
    this.programs = programs;
    this.getState = getState;
    this.show = show;
    this.dialects = dialects;
    this.limits = limits;
    this.noticeWords = new WeakMap(); // a message shown → {words, label}: what it says, as given to notify()
    this.current = null; // {id, name, created, kept: bool, why}
    this.unkept = new Map(); // id → entry the full list could not take: kept for this tab, saved once there is room
    this.timer = 0;
    this.$ = (id) => document.getElementById(id);
    this.bind();
    if (!programs.persistent) this.notify(() => tr('storage_off'), { kind: 'warning', sticky: true });
  }

  // ---- opening ----

  /**
   * The program to open at start: the link's (as a new entry; the fragment
   * is then taken off the address), else the entry this tab had open, else
   * the most recent; null when there is none.
   */
  async start(hash) {
    const link = readFragment(hash, LINK_MAX_BYTES);
    if (link) history.replaceState(null, '', location.pathname + location.search);
    if (link && link.state) return this.fromLink(link.state);
    if (link) this.notify(() => tr('link_refused', { why: link.error }), { kind: 'error' });
    const ids = [this.programs.currentId(), ...this.programs.list().map((i) => i.id)];
    for (const id of ids) {
      const e = id && this.programs.get(id);
      if (e) return this.enter(e);
    }
    return null;
  }

  /** A link opened while the app is open (hashchange): a new entry, shown. */
  async openLink(hash) {
    const link = readFragment(hash, LINK_MAX_BYTES);
    if (!link) return;
    history.replaceState(null, '', location.pathname + location.search);
    if (!link.state) {
      this.notify(() => tr('link_refused', { why: link.error }), { kind: 'error' });
      return;
    }
    this.saveNow();
    await this.show(await this.fromLink(link.state));
  }

  /** Checks a linked state, makes it an entry (or finds the same one) and says what happened. */
  async fromLink(raw) {
    let limits = [];
    try {
      limits = await this.limits();
    } catch {
      limits = null;
    }
    const { state, notes, clamped } = sanitizeLinked(raw, this.dialects, limits);
    if (limits === null) {
      // Without the table no limit can be checked: links keep the defaults.
      for (const d of Object.keys(state.settings)) for (const k of Object.keys(state.settings[d])) if (k.trim().toLowerCase().startsWith('limits.')) delete state.settings[d][k];
    }
    if (notes.length) this.notify(() => tr('link_changed', { what: notes.join('; ') }), { kind: 'warning' });
    if (clamped.length) {
      const list = clamped.map((c) => `${c.name} ${c.asked} → ${c.value}`).join(', ');
      this.notify(() => tr('clamped', { list }), { kind: 'warning' });
    }
    const had = this.programs.list().length > 0;
    const same = this.programs.findSame(state);
    if (same) {
      this.notify(() => tr('link_same', { name: shownName(same) }), { kind: 'info' });
      return this.enter(same);
    }
    const s = this.create(state);
    if (had && this.current.kept) this.notify(() => tr('link_new', { name: shownName(this.current) }), { kind: 'info' });
    return s;
  }

  /** Opens `state` (an example, "New") as a new entry, or the same kept one. */
  async openNew(state) {
    this.saveNow();
    const same = state.program.trim() ? this.programs.findSame(state) : null;
    await this.show(same ? this.enter(same) : this.create(state));
  }

  /** Makes `state` a new entry, open; returns the state to show. */
  create(state) {
    const now = Date.now();
    const e = { id: newIdFor(this.programs), ...state, created: now, updated: now };
    this.current = { id: e.id, name: programName(e.program), created: now, kept: false };
    this.programs.setCurrent(e.id);
    this.keep(e);
    return { dialect: e.dialect, settings: e.settings, program: e.program };
  }

  /** Makes entry `e` (kept, or held for this tab) the open one; returns its state, checked. */
  enter(e) {
    this.current = { id: e.id, name: programName(e.program), created: e.created, kept: !this.unkept.has(e.id), why: this.unkept.has(e.id) ? 'full' : null };
    this.programs.setCurrent(e.id);
    this.render();
    let dialect = knownDialect(e.dialect, this.dialects);
    if (!dialect) {
      this.notify(() => tr('stored_dialect', { name: shownName(e), dialect: String(e.dialect).slice(0, 40), title: titleOf(DEFAULT_DIALECT, this.dialects) }), { kind: 'warning' });
      dialect = DEFAULT_DIALECT;
    }
    return { dialect, settings: cleanSettings(e.settings, this.dialects).settings, program: e.program };
  }

  async openId(id) {
    if (this.current && id === this.current.id) return;
    this.saveNow();
    const e = this.unkept.get(id) || this.programs.get(id);
    if (e) await this.show(this.enter(e));
    else this.render();
  }

  async newProgram() {
    const s = this.getState();
    this.saveNow();
    await this.show(this.create({ dialect: s.dialect, settings: inherited(s.settings), program: '' }));
    // Say which controller it is for, and put the choice in reach.
    this.notify(() => tr('new_for', { title: titleOf(s.dialect, this.dialects) }), { kind: 'info' });
    document.getElementById('dialect')?.focus();
  }

  /** Deletes the open entry and opens the most recent other one (or a new empty one); an undo brings it back. */
  async deleteCurrent() {
    const cur = this.current;
    if (!cur) return;
    this.saveNow();
    const gone = cur.kept ? this.programs.remove(cur.id) : { ...this.getState(), id: cur.id, name: cur.name, created: cur.created, updated: Date.now() };
    this.unkept.delete(cur.id);
    this.current = null;
    this.retryUnkept();
    const next = this.programs.list()[0];
    const s = this.getState();
    await this.show(next ? this.enter(this.programs.get(next.id)) : this.create({ dialect: s.dialect, settings: inherited(s.settings), program: '' }));
    if (!gone) return;
    const note = this.notify(() => tr('deleted', { name: shownName(gone) }), {
      kind: 'info',
      action: {
        label: () => tr('undo'),
        run: async () => {
          this.saveNow();
          this.current = { id: gone.id, name: gone.name, created: gone.created, kept: false };
          this.programs.setCurrent(gone.id);
          this.keep(gone);
          await this.show({ dialect: knownDialect(gone.dialect, this.dialects) || DEFAULT_DIALECT, settings: cleanSettings(gone.settings, this.dialects).settings, program: gone.program });
        },
      },
      timeout: 20_000,
    });
    return note;
  }

  // ---- saving ----

  /** Saves the open program soon (typing saves once it pauses). */
  saveSoon() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.saveNow(), 300);
  }

  /** Saves the open program now (before another opens, and when the page goes). */
  saveNow() {
    clearTimeout(this.timer);
    this.timer = 0;
    const s = this.getState();
    if (!this.current) {
      if (!s.program.trim()) return;
      this.create(s);
      return;
    }
    const c = this.current;
    this.keep({ id: c.id, dialect: s.dialect, settings: s.settings, program: s.program, created: c.created, updated: Date.now() });
  }

  /** Saves the programs the list could not take, now that there may be room. */
  retryUnkept() {
    for (const e of [...this.unkept.values()]) {
      if (this.current && e.id === this.current.id) continue;
      if (this.programs.put(e).ok) {
        this.unkept.delete(e.id);
        this.notify(() => tr('kept_again', { name: shownName(e) }), { kind: 'info' });
      }
    }
  }

  /** Writes entry `e` (the open one) and says when it cannot be kept, or is kept again. */
  keep(e) {
    const c = this.current;
    const r = this.programs.put(e);
    if (r.ok) this.unkept.delete(e.id);
    else this.unkept.set(e.id, { ...e, name: programName(e.program) });
    if (c && c.id === e.id) {
      const was = c.kept;
      c.name = programName(e.program);
      c.kept = r.ok;
      if (!r.ok && (was || !c.why || c.why !== r.reason)) {
        const vars = { name: shownName(c), count: r.count, max: MAX_PROGRAMS, size: sizeText(r.chars + r.size), maxSize: sizeText(MAX_STORED_CHARS) };
        this.dismiss(this.fullNote);
        this.fullNote = this.notify(() => tr(r.reason === 'full' ? 'full' : 'quota', vars), { kind: 'warning', sticky: true });
      }
      if (r.ok && c.why) {
        this.dismiss(this.fullNote);
        this.notify(() => tr('kept_again', { name: shownName(c) }), { kind: 'info' });
      }
      c.why = r.ok ? null : r.reason;
    }
    this.render();
    return r;
  }

  savePrefs(p) {
    this.programs.savePrefs({ ...this.programs.prefs(), ...p });
  }

  prefs() {
    return this.programs.prefs();
  }

  // ---- the menu ----

  bind() {
    const sel = this.$('programs');
    if (!sel) return;
    sel.addEventListener('change', () => this.openId(sel.value));
    this.$('program-new').addEventListener('click', () => this.newProgram());
    this.$('program-delete').addEventListener('click', () => this.deleteCurrent());
    window.addEventListener('storage', (e) => {
      if (e.key === INDEX) this.render();
    });
    window.addEventListener('pagehide', () => this.saveNow());
    document.addEventListener('visibilitychange', () => {
      if (document.visibilityState === 'hidden') this.saveNow();
    });
    new MutationObserver(() => {
      this.render();
      this.relabelNotices();
    }).observe(document.documentElement, { attributes: true, attributeFilter: ['lang'] });
  }

  /** Lists the entries in the menu, the open one chosen; says when it is not kept. */
  render() {
    const sel = this.$('programs');
    if (!sel) return;
    const list = this.programs.list();
    const c = this.current;
    const options = list.map((i) => {
      const name = c && i.id === c.id ? shownName(c) : shownName(i);
      return `<option value="${esc(i.id)}" title="${esc(`${name} · ${titleOf(i.dialect, this.dialects)} · ${stamp(i.updated)}`)}">${esc(name)}</option>`;
    });
    const listed = new Set(list.map((i) => i.id));
    for (const e of [...this.unkept.values()].reverse()) {
      if (listed.has(e.id)) continue;
      const name = c && e.id === c.id ? shownName(c) : shownName(e);
      options.unshift(`<option value="${esc(e.id)}">${esc(`${name} (${tr('not_kept')})`)}</option>`);
      listed.add(e.id);
    }
    if (c && !listed.has(c.id)) options.unshift(`<option value="${esc(c.id)}">${esc(`${shownName(c)} (${tr('not_kept')})`)}</option>`);
    setOptions(sel, options);
    if (c) sel.value = c.id;
    sel.title = tr('programs_title');
    this.$('programs-label').textContent = tr('programs');
    const nb = this.$('program-new');
    nb.textContent = tr('new');
    nb.title = tr('new_title');
    const db = this.$('program-delete');
    db.textContent = tr('delete');
    db.title = tr('delete_title');
    const flag = this.$('programs-state');
    const text = !this.programs.persistent ? tr('storage_off_short') : c && !c.kept ? tr('not_kept') : '';
    flag.textContent = text;
    flag.hidden = !text;
    document.body.dataset.program = c ? c.id : '';
  }

  // ---- messages ----

  /**
   * Shows a message above the page (never blocking): `kind` info, warning
   * or error; an optional action button. Info goes by itself after
   * `timeout` ms (12 s), a warning after 30 s; errors and `sticky` ones
   * stay until closed. The same text twice is shown once. `text` (and the
   * action's `label`) may be a function giving it in the page's language:
   * a message shown then follows a change of language.
   */
  notify(words, { kind = 'info', action = null, sticky = false, timeout = kind === 'warning' ? 30_000 : 12_000 } = {}) {
    const box = this.$('notices');
    if (!box) return null;
    const text = wordsOf(words);
    for (const old of box.querySelectorAll('.notice')) if (old.querySelector('.text').textContent === text) old.remove();
    const colours = { info: '#eff6ff;#93c5fd', warning: '#fffbeb;#f59e0b', error: '#fef2f2;#f87171' }[kind].split(';');
    const el = document.createElement('div');
    el.className = `notice ${kind}`;
    el.dataset.kind = kind;
    el.setAttribute('role', kind === 'error' ? 'alert' : 'status');
    el.style.cssText = `display:flex;gap:8px;align-items:flex-start;padding:6px 8px;background:${colours[0]};border:1px solid ${colours[1]};border-radius:6px;color:#111827;font-size:12px;line-height:1.35;box-shadow:0 2px 8px rgba(0,0,0,.18)`;
    const span = document.createElement('span');
    span.className = 'text';
    span.style.flex = '1';
    span.textContent = text;
    el.append(span);
    this.noticeWords.set(el, { words, label: action && action.label });
    if (action) {
      const b = document.createElement('button');
      b.className = 'action';
      b.textContent = wordsOf(action.label);
      b.addEventListener('click', async () => {
        this.dismiss(el);
        await action.run();
      });
      el.append(b);
    }
    const x = document.createElement('button');
    x.className = 'close';
    x.textContent = '×';
    x.setAttribute('aria-label', tr('close'));
    x.addEventListener('click', () => this.dismiss(el));
    el.append(x);
    box.append(el);
    while (box.children.length > 6) box.firstElementChild.remove();
    if (kind !== 'error' && !sticky) setTimeout(() => this.dismiss(el), timeout);
    return el;
  }

  dismiss(el) {
    if (el && el.parentNode) el.remove();
  }

  /** The messages shown, their texts, actions and close buttons in the page's language now. */
  relabelNotices() {
    const box = this.$('notices');
    if (!box) return;
    for (const el of box.querySelectorAll('.notice')) {
      const w = this.noticeWords.get(el);
      if (!w) continue;
      el.querySelector('.text').textContent = wordsOf(w.words);
      const b = el.querySelector('.action');
      if (b && w.label) b.textContent = wordsOf(w.label);
      el.querySelector('.close')?.setAttribute('aria-label', tr('close'));
    }
  }
}
