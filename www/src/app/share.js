// Links that carry a program: the fragment holds {dialect, settings,
// program} as base64url of deflated JSON (`#z=`) or of plain JSON (`#j=`,
// what embedded previews write: fragment.js). Keeping programs in the
// browser is programs.js.
//
// A link is input from anyone, so reading one is bounded and checked:
// - the fragment is at most LINK_MAX_CHARS long (refused before decoding);
// - `#z=` is inflated as a stream and refused as soon as its output passes
//   LINK_MAX_BYTES (8 MiB), so a small link that inflates to hundreds of MB
//   never does;
// - the JSON must be an object with a string `program`;
// - `sanitizeLinked` then checks the dialect against the planner's list
//   (unknown: GSK980TDc), keeps only well-formed settings (names without `=`
//   or line breaks, short scalar values, known dialects) and clamps every
//   `limits.*` setting to its default or lower: a link may lower the
//   planner's limits, never raise them.
// Every refusal and change is said in words for the page to show.

import { deflateSync, Inflate, strToU8 } from 'fflate';
import { DEFAULT_DIALECT, fromBase64Url, knownDialect, toBase64Url } from '../shared/fragment.js';

export { DEFAULT_DIALECT, knownDialect };

/** Most bytes of JSON a link may carry once decoded (and inflated): 8 MiB. */
export const LINK_MAX_BYTES = 8 * 1024 * 1024;

/** Longest fragment read: the base64url of LINK_MAX_BYTES, and the `#z=`. */
export const LINK_MAX_CHARS = Math.ceil(LINK_MAX_BYTES / 3) * 4 + 3;

/** Input pushed to the inflater at a time: at most ~1 MB of output each (deflate's ratio is below 1032:1). */
const INFLATE_STEP = 1024;

const MiB = (n) => `${(n / 1048576).toFixed(n % 1048576 ? 1 : 0)} MiB`;

/** The fragment for a shared link: `#z=` + base64url(deflate(JSON)). */
export function encodeFragment(state) {
  const json = JSON.stringify({ dialect: state.dialect, settings: state.settings, program: state.program });
  return `#z=${toBase64Url(deflateSync(strToU8(json), { level: 9 }))}`;
}

/**
 * Inflates raw deflate `bytes`, stopping as soon as the output passes `cap`
 * bytes. Returns the output, or throws an Error whose `reason` is
 * 'too-large' or 'malformed'.
 */
export function inflateCapped(bytes, cap = LINK_MAX_BYTES) {
  const chunks = [];
  let total = 0;
  let over = false;
  const inflater = new Inflate((chunk) => {
    if (over) return;
    total += chunk.length;
    if (total > cap) over = true;
    else if (chunk.length) chunks.push(chunk);
  });
  try {
    for (let i = 0; i < bytes.length && !over; i += INFLATE_STEP) {
      inflater.push(bytes.subarray(i, i + INFLATE_STEP), i + INFLATE_STEP >= bytes.length);
    }
    if (!bytes.length) inflater.push(new Uint8Array(0), true);
  } catch (e) {
    if (!over) throw Object.assign(new Error(`the link's data is damaged (${e.message})`), { reason: 'malformed' });
  }
  if (over) throw Object.assign(new Error(`the link unpacks to more than ${MiB(cap)}`), { reason: 'too-large' });
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

/**
 * Reads a link's fragment: null when it carries no program (`#z=`/`#j=`),
 * else `{state}` (the parsed object, not yet checked: see sanitizeLinked) or
 * `{error, reason}` with what was wrong, in words.
 */
export function readFragment(hash, cap = LINK_MAX_BYTES) {
  const kind = typeof hash === 'string' ? hash.slice(0, 3) : '';
  if (kind !== '#z=' && kind !== '#j=') return null;
  const maxChars = Math.ceil(cap / 3) * 4 + 3;
  if (hash.length > maxChars) {
    return { reason: 'too-large', error: `the link is ${hash.length.toLocaleString('en')} characters long; links may carry at most ${MiB(cap)} of program` };
  }
  let bytes;
  try {
    bytes = fromBase64Url(hash.slice(3));
  } catch {
    return { reason: 'malformed', error: 'the link is damaged (not base64url)' };
  }
  try {
    if (kind === '#z=') bytes = inflateCapped(bytes, cap);
    else if (bytes.length > cap) throw Object.assign(new Error(`the link carries more than ${MiB(cap)}`), { reason: 'too-large' });
  } catch (e) {
    return { reason: e.reason || 'malformed', error: e.message };
  }
  let state;
  try {
    state = JSON.parse(new TextDecoder().decode(bytes));
  } catch {
    return { reason: 'malformed', error: 'the link is damaged (not JSON)' };
  }
  if (!state || typeof state !== 'object' || Array.isArray(state) || typeof state.program !== 'string') {
    return { reason: 'malformed', error: 'the link carries no program' };
  }
  return { state };
}

const MAX_SETTING_NAME = 64;
const MAX_SETTING_VALUE = 256;
const MAX_SETTINGS = 400;

/**
 * Settings as the app keeps them (`{dialect: {name: value}}`) from untrusted
 * input: unknown dialects, names with `=` or line breaks (they would become
 * other `NAME=VALUE` lines), non-scalar or long values are dropped and said
 * in `notes`. With `limits` (`[{name, default}]`), a `limits.*` value above
 * its default (or not a number) becomes the default: `clamped` lists them.
 */
export function cleanSettings(settings, dialects, limits = null) {
  const out = {};
  const notes = [];
  const clamped = [];
  if (settings === undefined || settings === null) return { settings: out, notes, clamped };
  if (typeof settings !== 'object' || Array.isArray(settings)) {
    notes.push('its settings are not a table of NAME=VALUE: ignored');
    return { settings: out, notes, clamped };
  }
  let count = 0;
  for (const [d, values] of Object.entries(settings)) {
    const dialect = knownDialect(d, dialects);
    if (!dialect || !values || typeof values !== 'object' || Array.isArray(values)) {
      notes.push(`settings for '${String(d).slice(0, 40)}' ignored (not a known controller)`);
      continue;
    }
    out[dialect] ||= {};
    const mine = out[dialect];
    for (const [name, raw] of Object.entries(values)) {
      if (++count > MAX_SETTINGS) {
        notes.push(`more than ${MAX_SETTINGS} settings: the rest ignored`);
        return { settings: out, notes, clamped };
      }
      const scalar = typeof raw === 'string' || typeof raw === 'number' || typeof raw === 'boolean';
      const value = scalar ? String(raw).trim() : '';
      if (!name.trim() || name.length > MAX_SETTING_NAME || /[=\r\n]/.test(name) || !scalar || value.length > MAX_SETTING_VALUE || /[\r\n]/.test(value)) {
        notes.push(`setting '${name.slice(0, 40)}' ignored (not a valid NAME=VALUE)`);
        continue;
      }
      const key = name.trim().toLowerCase();
      const limit = limits && key.startsWith('limits.') ? limits.find((l) => l.name === key) : null;
      if (limit) {
        const n = Number(value);
        if (!(Number.isFinite(n) && n <= limit.default)) {
          clamped.push({ name: limit.name, asked: value.slice(0, 40), value: limit.default });
          mine[name] = String(limit.default);
          continue;
        }
      }
      mine[name] = value;
    }
  }
  return { settings: out, notes, clamped };
}

/**
 * A linked state made safe to open: `{state: {dialect, settings, program},
 * notes, clamped}`; `notes` says in words what was changed or dropped.
 */
export function sanitizeLinked(raw, dialects, limits) {
  const notes = [];
  let dialect = knownDialect(raw.dialect, dialects);
  if (!dialect) {
    if (raw.dialect !== undefined) notes.push(`unknown controller '${String(raw.dialect).slice(0, 40)}': opened as ${titleOf(DEFAULT_DIALECT, dialects)}`);
    dialect = DEFAULT_DIALECT;
  }
  const s = cleanSettings(raw.settings, dialects, limits);
  notes.push(...s.notes);
  return { state: { dialect, settings: s.settings, program: raw.program }, notes, clamped: s.clamped };
}

/** The title of dialect `name` ("GSK980TDc"), else the name. */
export function titleOf(name, dialects) {
  const d = dialects.find((x) => x.name === name);
  return d ? d.title : name;
}
