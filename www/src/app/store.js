// The programs kept in this browser: entries in localStorage (one key per
// entry and a small index), the open entry per tab, the preferences, and
// the move of the one program earlier versions kept into the list. No DOM:
// the header's Programs menu is programs.js. See programs.js for why
// localStorage.

import { DEFAULT_DIALECT } from './share.js';

export const INDEX = 'screwcut.programs.v1';
export const ENTRY = 'screwcut.program.v1.';
const CURRENT = 'screwcut.current.v1';
const PREFS = 'screwcut.prefs.v1';
/** Where versions before the list kept their one program. */
export const LEGACY = 'screwcut.state.v1';

/** Most programs kept. */
export const MAX_PROGRAMS = 50;
/** Most characters of stored entries in all (localStorage holds about 5 million per site). */
export const MAX_STORED_CHARS = 3 * 1024 * 1024;

const NAME_MAX = 60;

/**
 * A program's name: its first comment or O number, whichever comes first
 * (an O number with a comment on its line gives both); '' when it has
 * neither (shown as "Untitled" and the date).
 */
export function programName(program) {
  const lines = String(program).slice(0, 8192).split('\n', 200);
  for (const line of lines) {
    const o = /^\s*(?:%\s*)?([OoＯ])\s*(\d{1,8})/.exec(line);
    const c = /\(([^()\n]*)\)/.exec(line);
    const comment = c ? c[1].replace(/\s+/g, ' ').trim() : '';
    const number = o ? `O${o[2]}` : '';
    const name = number && comment ? `${number} ${comment}` : number || comment;
    if (name) return name.length > NAME_MAX ? `${name.slice(0, NAME_MAX - 1)}…` : name;
  }
  return '';
}

/** A Storage-like map for a tab without storage. */
class MemoryStorage {
  constructor() {
    this.m = new Map();
  }
  getItem(k) {
    return this.m.has(k) ? this.m.get(k) : null;
  }
  setItem(k, v) {
    this.m.set(k, String(v));
  }
  removeItem(k) {
    this.m.delete(k);
  }
  key(i) {
    return [...this.m.keys()][i] ?? null;
  }
  get length() {
    return this.m.size;
  }
}

/** `get()` (window.localStorage, …) if it can be written, else null. */
function usable(get) {
  try {
    const s = get();
    const k = 'screwcut.probe';
    s.setItem(k, '1');
    s.removeItem(k);
    return s;
  } catch {
    return null;
  }
}

const newId = () => (globalThis.crypto && crypto.randomUUID ? crypto.randomUUID() : `${Date.now().toString(36)}-${Math.random().toString(36).slice(2, 10)}`);

const sameSettings = (a, b) => JSON.stringify(a || {}) === JSON.stringify(b || {});

/** The stored list: entries by id, the index, the open entry, preferences. */
export class Programs {
  constructor({ local = usable(() => window.localStorage), session = usable(() => window.sessionStorage) } = {}) {
    this.persistent = !!local;
    this.local = local || new MemoryStorage();
    this.session = session || new MemoryStorage();
    this.recover();
    this.migrate();
  }

  read(key) {
    try {
      const s = this.local.getItem(key);
      return s ? JSON.parse(s) : null;
    } catch {
      return null;
    }
  }

  /** The index: [{id, name, dialect, created, updated, size}], most recent first. */
  list() {
    const raw = this.read(INDEX);
    const list = Array.isArray(raw) ? raw.filter((i) => i && typeof i.id === 'string') : [];
    return list.sort((a, b) => (b.updated || 0) - (a.updated || 0));
  }

  /** Entry `id` as stored, or null. */
  get(id) {
    const e = this.read(ENTRY + id);
    if (!e || typeof e !== 'object' || typeof e.program !== 'string') return null;
    return {
      id,
      name: typeof e.name === 'string' ? e.name : programName(e.program),
      dialect: typeof e.dialect === 'string' ? e.dialect : DEFAULT_DIALECT,
      settings: e.settings && typeof e.settings === 'object' ? e.settings : {},
      program: e.program,
      created: Number(e.created) || Date.now(),
      updated: Number(e.updated) || Date.now(),
    };
  }

  /** Total characters the list keeps, and its count, leaving out entry `except`. */
  usage(except = null) {
    const others = this.list().filter((i) => i.id !== except);
    return { count: others.length, chars: others.reduce((a, i) => a + (Number(i.size) || 0), 0) };
  }

  /**
   * Writes entry `e` (a new one or a later version) and its index line.
   * `{ok: true}`, or `{ok: false, reason: 'full' | 'quota', ...usage}`.
   */
  put(e) {
    const record = { name: programName(e.program), dialect: e.dialect, settings: e.settings, program: e.program, created: e.created, updated: e.updated };
    const json = JSON.stringify(record);
    const use = this.usage(e.id);
    if (use.count >= MAX_PROGRAMS || use.chars + json.length > MAX_STORED_CHARS) return { ok: false, reason: 'full', ...use, size: json.length };
    try {
      this.local.setItem(ENTRY + e.id, json);
      const index = this.list().filter((i) => i.id !== e.id);
      index.push({ id: e.id, name: record.name, dialect: e.dialect, created: e.created, updated: e.updated, size: json.length });
      this.local.setItem(INDEX, JSON.stringify(index));
    } catch {
      return { ok: false, reason: 'quota', ...use, size: json.length };
    }
    e.name = record.name;
    return { ok: true };
  }

  /** Removes entry `id`; returns what it was (for an undo), or null. */
  remove(id) {
    const e = this.get(id);
    try {
      this.local.setItem(INDEX, JSON.stringify(this.list().filter((i) => i.id !== id)));
      this.local.removeItem(ENTRY + id);
    } catch {
      // Storage gone meanwhile: nothing more to do.
    }
    return e;
  }

  /** A kept entry with the same dialect, settings and program, or null. */
  findSame(s) {
    for (const i of this.list()) {
      if (i.dialect !== s.dialect) continue;
      const e = this.get(i.id);
      if (e && e.program === s.program && sameSettings(e.settings, s.settings)) return e;
    }
    return null;
  }

  /** The entry this tab had open, else the one last open in any tab. */
  currentId() {
    try {
      return this.session.getItem(CURRENT) || this.local.getItem(CURRENT);
    } catch {
      return null;
    }
  }

  setCurrent(id) {
    try {
      this.session.setItem(CURRENT, id);
      this.local.setItem(CURRENT, id);
    } catch {
      // Not kept: the tab still knows it.
    }
  }

  prefs() {
    const p = this.read(PREFS);
    return p && typeof p === 'object' ? p : {};
  }

  savePrefs(p) {
    try {
      this.local.setItem(PREFS, JSON.stringify(p));
    } catch {
      // Not kept.
    }
  }

  /** Entries whose index line was lost (a write cut short) go back into the index. */
  recover() {
    const listed = new Set(this.list().map((i) => i.id));
    const lost = [];
    try {
      for (let i = 0; i < this.local.length; i++) {
        const k = this.local.key(i);
        if (k && k.startsWith(ENTRY) && !listed.has(k.slice(ENTRY.length))) lost.push(k.slice(ENTRY.length));
      }
    } catch {
      return;
    }
    for (const id of lost) {
      const e = this.get(id);
      if (e) this.put(e);
    }
  }

  /** The one program of earlier versions becomes an entry (once kept, the old key goes). */
  migrate() {
    const old = this.read(LEGACY);
    if (!old || typeof old !== 'object') return;
    const prefs = this.prefs();
    if ((old.lang === 'zh' || old.lang === 'en') && !prefs.lang) this.savePrefs({ ...prefs, lang: old.lang });
    if (typeof old.program !== 'string') return;
    const s = { dialect: typeof old.dialect === 'string' ? old.dialect : DEFAULT_DIALECT, settings: old.settings && typeof old.settings === 'object' ? old.settings : {}, program: old.program };
    let e = this.findSame(s);
    if (!e) {
      const now = Date.now();
      e = { id: newId(), ...s, created: now, updated: now };
      if (!this.put(e).ok) return; // kept where it is until there is room
    }
    if (!this.currentId()) this.setCurrent(e.id);
    try {
      this.local.removeItem(LEGACY);
    } catch {
      // Stays readable; migrated again (as the same entry) next time.
    }
  }
}

/**
 * The programs as the app uses them: the open entry, the header menu,
 * messages, and opening links, examples and new programs as new entries.
 *
 * `getState()` gives the app's {dialect, settings, program}; `show(state)`
 * puts one in the editor (async); `dialects` is the planner's list and
 * `limits()` resolves to the `limits.*` rows of the settings table.
 */
/** An id no kept entry has. */
export function newIdFor(programs) {
  let id = newId();
  while (programs.get(id)) id = newId();
  return id;
}
