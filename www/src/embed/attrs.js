// Reading <screwcut-preview>'s attributes and text content.

/** The views an element can show, in the order they are laid out. */
export const VIEWS = ['side', 'tooth', 'starts', 'table'];

/** `view="side tooth"` (spaces, commas or bars) → the known views, default side. */
export function parseViews(attr) {
  const asked = String(attr || '')
    .toLowerCase()
    .split(/[\s,|]+/)
    .filter((v) => VIEWS.includes(v));
  return asked.length ? [...new Set(asked)] : ['side'];
}

/** `height="320"` (CSS pixels per drawing), clamped to 120–1200, default 320. */
export function parseHeight(attr) {
  const h = Number.parseFloat(attr);
  return Number.isFinite(h) ? Math.min(1200, Math.max(120, h)) : 320;
}

/** `thread="2"` (1-based) → 0-based index, default 0. */
export function parseThread(attr) {
  const n = Number.parseInt(attr, 10);
  return Number.isFinite(n) && n >= 1 ? n - 1 : 0;
}

/**
 * `settings="No.058=55; x_mode=radius"` (lines or `;` separate the entries) →
 * `{values: {name: value}, problems: [{setting, message}]}`:
 * an entry that is not NAME=VALUE is a problem to show, not dropped silently
 * (the planner reports unknown names and bad values: `settingErrors`).
 */
export function readSettings(attr) {
  const values = {};
  const problems = [];
  for (const part of String(attr || '').split(/[;\n]/)) {
    const text = part.trim();
    if (!text) continue;
    const eq = text.indexOf('=');
    const name = eq > 0 ? text.slice(0, eq).trim() : '';
    if (!name) {
      problems.push({ setting: text.slice(0, 40), message: `'${text.slice(0, 40)}' is not NAME=VALUE: ignored` });
      continue;
    }
    values[name] = text.slice(eq + 1).trim();
  }
  return { values, problems };
}

/** Schemes a link or a fetch of the element may use. */
const SAFE = new Set(['http:', 'https:']);

/**
 * `value` (an `app`, `src` or meta URL) resolved against `base`, if it is
 * http(s) or relative (a relative URL keeps the page's scheme), else null:
 * `javascript:`, `data:`, `blob:` and the like are never followed.
 */
export function safeUrl(value, base) {
  if (typeof value !== 'string' || !value.trim()) return null;
  // What the URL parser ignores: tabs and line breaks anywhere, controls and spaces at the ends.
  // (C0 controls and space: U+0000 to U+0020, as the URL standard strips them.)
  const c0 = (c) => c.charCodeAt(0) <= 0x20;
  let plain = value.replace(/[\t\n\r]/g, '');
  let a = 0;
  let b = plain.length;
  while (a < b && c0(plain[a])) a++;
  while (b > a && c0(plain[b - 1])) b--;
  plain = plain.slice(a, b);
  let url;
  try {
    url = new URL(value, base);
  } catch {
    return null;
  }
  if (SAFE.has(url.protocol)) return url;
  const relative = !/^[a-z][a-z0-9+.-]*:/i.test(plain);
  return relative && url.protocol === new URL(base).protocol ? url : null;
}

/** `{name: value}` as the planner's `NAME=VALUE` lines. */
export const settingsLines = (s) =>
  Object.entries(s)
    .map(([k, v]) => `${k}=${v}`)
    .join('\n');

/**
 * A program written inside the element, as the author meant it: the blank
 * first and last lines of the markup dropped and the common indentation
 * removed (so it can be indented with the page's HTML).
 */
export function dedent(text) {
  const lines = String(text).replace(/\r\n?/g, '\n').split('\n');
  while (lines.length && !lines[0].trim()) lines.shift();
  while (lines.length && !lines[lines.length - 1].trim()) lines.pop();
  let indent = Infinity;
  for (const l of lines) if (l.trim()) indent = Math.min(indent, l.match(/^[ \t]*/)[0].length);
  if (!Number.isFinite(indent)) indent = 0;
  return lines.map((l) => l.slice(indent)).join('\n') + (lines.length ? '\n' : '');
}
