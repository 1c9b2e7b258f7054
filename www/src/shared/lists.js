// Lists of any length that stay fast: only the rows in view are in the
// DOM (a spacer above and below keeps the scroll height), rows of a fixed
// height. The pass table reads the chosen thread's passes as columns
// (src/wasm/js.rs `passes_to_js`); the diagnostics list reads the planner's list.

import { esc, num } from './table.js';

const ROLE_NAMES = ['rough', 'finish', 'spring'];

/** The command of each thread source (src/thread.rs `Source`), the same in every language. */
const SOURCE_CODES = { g32: 'G32', renhe: 'G32/G33', g78: 'G78', g92: 'G92', g76: 'G76', linuxcnc_g33: 'G33', linuxcnc_g76: 'G76' };

/** A thread summary's command and kind in language `t`: `G32 straight`, `G76 锥螺纹`. */
export function threadName(th, t) {
  return `${SOURCE_CODES[th.source] || String(th.source).toUpperCase()} ${t(`kind_${th.kind}`)}`;
}

/** A virtual list in `scroller`: `body` holds the rows; `row(i)` gives one row's HTML. */
export class VirtualRows {
  /**
   * @param {HTMLElement} scroller the element that scrolls
   * @param {HTMLElement} body the element the rows go in (a tbody or a list)
   * @param {{rowHeight: number, spacer: (h: number) => string}} opts
   */
  constructor(scroller, body, opts) {
    this.scroller = scroller;
    this.body = body;
    this.opts = opts;
    this.count = 0;
    this.row = () => '';
    this.shown = '';
    this.hot = -1;
    this.first = 0;
    this.last = 0;
    scroller.addEventListener('scroll', () => this.render(), { passive: true });
    new ResizeObserver(() => this.render()).observe(scroller);
  }

  /** Shows `count` rows made by `row(i)`; `keep` keeps the scroll position. */
  set(count, row) {
    this.count = count;
    this.row = row;
    this.shown = '';
    this.render();
  }

  /** Marks row `i` (-1: none) and scrolls it into view when asked; the rows stay in place. */
  mark(i, reveal = false) {
    if (i === this.hot && !reveal) return;
    this.rowAt(this.hot)?.classList.remove('hot');
    this.hot = i;
    if (reveal && i >= 0) {
      const h = this.opts.rowHeight;
      const top = this.scroller.scrollTop;
      const view = this.scroller.clientHeight - h;
      if (i * h < top || i * h > top + view) this.scroller.scrollTop = Math.max(0, i * h - view / 2);
      this.render();
    }
    this.rowAt(i)?.classList.add('hot');
  }

  /** The element of row `i`, when it is in the DOM. */
  rowAt(i) {
    if (i < this.first || i >= this.last) return null;
    return this.body.children[i - this.first + (this.first > 0 ? 1 : 0)] || null;
  }

  render() {
    const h = this.opts.rowHeight;
    const top = this.scroller.scrollTop;
    const height = this.scroller.clientHeight || 400;
    const first = Math.max(0, Math.floor(top / h) - 10);
    const last = Math.min(this.count, Math.ceil((top + height) / h) + 10);
    const key = `${first}:${last}:${this.count}`;
    if (key === this.shown) return;
    this.shown = key;
    this.first = first;
    this.last = last;
    let html = first > 0 ? this.opts.spacer(first * h) : '';
    for (let i = first; i < last; i++) html += this.row(i, i === this.hot);
    if (last < this.count) html += this.opts.spacer((this.count - last) * h);
    this.body.innerHTML = html;
  }
}

/** The pass table's header; units where the column has one. */
export function passHead(t, units) {
  const u = units === 'inch' ? 'in' : 'mm';
  const th = (key, unit, cls = '') => `<th${cls}>${esc(t(key))}${unit ? ` <span class="unit">(${unit})</span>` : ''}</th>`;
  return `<tr>${th('col_pass')}${th('col_start')}${th('col_x', u)}${th('col_z', u)}${th('col_z_end', u)}${th('col_depth', u)}${th('col_infeed', u)}${th('col_area', `${u}²`)}${th('col_even', `${u}²`)}${th('col_time', 's')}${th('col_role', '', ' class="role"')}${th('col_lines', '', ' class="role"')}</tr>`;
}

/** Row `i` of pass columns `c` (rows `order[i]`), as HTML. */
export function passRow(c, i, t, hot, stale) {
  const via = passVia(c, i);
  const lines = Array.from(c.lines.subarray(c.lineStart[i], c.lineStart[i + 1])).join(',') + (via.length ? ` ← ${via.join(' ← ')}` : '');
  const role = ROLE_NAMES[c.role[i]] || 'rough';
  const opt = (col) => (!col || Number.isNaN(col[i]) ? '' : num(col[i]));
  const area = opt(c.area);
  const cls = `${role}${hot ? ' hot' : ''}${stale ? ' stale' : ''}`;
  return `<tr data-pass="${i}" class="${cls}" tabindex="-1"><td>${c.index[i]}</td><td>${c.start[i]}</td><td>${num(c.x[i])}</td><td>${num(c.z[i])}</td><td>${num(c.zEnd[i])}</td><td>${num(c.depth[i])}</td><td>${num(c.infeed[i])}</td><td>${area}</td><td>${opt(c.evenArea)}</td><td>${opt(c.time)}</td><td class="role">${esc(t(role))}</td><td class="lines">${lines}</td></tr>`;
}

/** Pass `i` of columns `c` in words (what a screen reader reads for the row). */
export function passText(c, i, t) {
  const role = ROLE_NAMES[c.role[i]] || 'rough';
  return `${t('col_pass')} ${c.index[i]}, ${t('col_start')} ${c.start[i]}: X${num(c.x[i])}, Z${num(c.z[i])} → ${num(c.zEnd[i])}, ${t('col_depth')} ${num(c.depth[i])}, ${t(role)}, ${t('col_lines')} ${passLines(c, i).join(', ')}${viaText(passVia(c, i), t)}`;
}

/** The lines of the calls that cut pass `i` of columns `c`, innermost first (none in the main program). */
export function passVia(c, i) {
  return c && c.via ? Array.from(c.via.subarray(c.viaStart[i], c.viaStart[i + 1])) : [];
}

/** `, called from line 8 ← 4` for a call chain, or nothing. */
function viaText(via, t) {
  return via && via.length ? `, ${t('called_from', { lines: via.join(' ← ') })}` : '';
}

/** The source lines of pass `i` of columns `c`. */
export function passLines(c, i) {
  return c ? Array.from(c.lines.subarray(c.lineStart[i], c.lineStart[i + 1])) : [];
}

/** One diagnostic as a list item (`i` its index in the full list). */
export function diagnosticRow(d, i, t, hot) {
  return `<li data-i="${i}" class="${d.severity}${hot ? ' hot' : ''}" tabindex="-1"><span class="pos">${d.line}:${d.column}</span><span class="sev">${esc(t(d.severity))}</span><span><span class="code">[${esc(d.code)}]</span> ${esc(d.message)}${d.via ? `<span class="via">${esc(t('called_from', { lines: d.via.join(' ← ') }))}</span>` : ''}${d.repeats > 1 ? `<span class="repeats">${esc(t('raised_times', { n: d.repeats }))}</span>` : ''}${d.switch_to ? ` <button type="button" class="switch" data-dialect="${esc(d.switch_to)}" data-title="${esc(d.switch_title)}">${esc(t('switch_to', { title: d.switch_title }))}</button>` : ''}</span></li>`;
}

/** The diagnostics' rows last written, by what they show (`diagnosticRows`). */
let rowsByContent = new Map();

/**
 * The rows of `shown` (`[diagnostic, index]`) in language `t` (`lang`): a row
 * written last time for the same diagnostic at the same place is written
 * again as it was, so an edit that changes one diagnostic builds one row.
 */
export function diagnosticRows(shown, t, lang) {
  const before = rowsByContent;
  rowsByContent = new Map();
  return shown.map(([d, i]) => {
    const key = `${i}|${lang}|${d.severity}|${d.line}:${d.column}|${d.code}|${d.message}|${d.via || ''}|${d.repeats || 1}|${d.switch_to || ''}|${d.switch_title || ''}`;
    const html = before.get(key) ?? diagnosticRow(d, i, t, false);
    rowsByContent.set(key, html);
    return html;
  });
}

/** Each thread summary's option as last written, by entry, with its place and language (`threadOptions`). */
const optionOf = new WeakMap();

/**
 * The thread list's options in language `t` (`lang`), one HTML string each:
 * a summary the engine did not send again keeps its identity, and so its option.
 */
export function threadOptions(threads, t, lang) {
  return threads.map((th, i) => {
    const kept = optionOf.get(th);
    if (kept && kept.i === i && kept.lang === lang) return kept.html;
    const time = th.shop && th.shop.time_s != null ? ` · ${th.shop.time_s.toFixed(1)} s` : '';
    const text = `${i + 1}: ${threadName(th, t)} · ${t('lead_of', { v: num(th.lead) })} · L${th.line}–${th.end_line} · ${th.passes}×${time}`;
    const html = `<option value="${i}">${esc(text)}</option>`;
    optionOf.set(th, { i, lang, html });
    return html;
  });
}

/** The options' HTML each list was last given (`setOptions`). */
const optionsShown = new WeakMap();

/**
 * Gives `select` the options `htmls` (one HTML string each). With as many
 * as it holds, only the options whose HTML changed are written again: an
 * edit of one thread of 2,000 re-parses one option, not the list.
 */
export function setOptions(select, htmls) {
  const before = optionsShown.get(select);
  optionsShown.set(select, htmls);
  if (before && before.length === htmls.length && select.options.length === htmls.length) {
    for (let i = 0; i < htmls.length; i++) if (htmls[i] !== before[i]) select.options[i].outerHTML = htmls[i];
    return;
  }
  select.innerHTML = htmls.join('');
}

/** Pass columns as one object per pass (`{start, index, from, to, depth, infeed, area, evenArea, time, role, lines, shift, angle}`). */
export function passObjects(c) {
  if (!c) return [];
  const out = new Array(c.n);
  for (let i = 0; i < c.n; i++) {
    out[i] = {
      start: c.start[i],
      index: c.index[i],
      from: [c.x[i], c.z[i]],
      to: [c.xEnd[i], c.zEnd[i]],
      depth: c.depth[i],
      infeed: c.infeed[i],
      area: Number.isNaN(c.area[i]) ? null : c.area[i],
      evenArea: !c.evenArea || Number.isNaN(c.evenArea[i]) ? null : c.evenArea[i],
      time: !c.time || Number.isNaN(c.time[i]) ? null : c.time[i],
      role: ROLE_NAMES[c.role[i]] || 'rough',
      lines: passLines(c, i),
      via: passVia(c, i),
      shift: c.shift[i],
      angle: c.angle[i],
    };
  }
  return out;
}

/** The tooltip of a drawn item `info` ({thread, pass, lines}): its pass in numbers when it is one of the chosen thread's, else its lines. */
export function tipText(info, result, thread, t) {
  const c = result && result.passes;
  if (!(info.pass >= 0 && info.thread === thread && c && info.pass < c.n)) return `${t('col_lines')} ${info.lines.join(', ')}`;
  const i = info.pass;
  const multi = result.threads[thread] && result.threads[thread].starts > 1;
  return (
    `${t('thread')} ${info.thread + 1} · ${t('col_pass')} ${c.index[i]}` +
    (multi ? ` · ${t('col_start')} ${c.start[i]}` : '') +
    ` · X${num(c.x[i])} Z${num(c.z[i])}→${num(c.zEnd[i])} · ${t('col_depth')} ${num(c.depth[i])} · ${t(ROLE_NAMES[c.role[i]] || 'rough')} · ${t('col_lines')} ${passLines(c, i).join(', ')}${viaText(passVia(c, i), t)}`
  );
}

/** The rows last written into each list by `patchRows`. */
const written = new WeakMap();

/**
 * Writes `rows` (each an `<li>`, as HTML) and `tail` into `ul`. An edit
 * changes a few diagnostics of a long list: when the list keeps its length,
 * only the rows that changed are replaced (a 1,000-row list is not laid out
 * again for each keystroke).
 */
export function patchRows(ul, rows, tail) {
  const old = written.get(ul);
  const same = old && old.rows.length === rows.length && old.tail === tail && ul.children.length === rows.length + (tail ? 1 : 0);
  if (same) {
    for (let i = 0; i < rows.length; i++) if (rows[i] !== old.rows[i]) ul.children[i].outerHTML = rows[i];
  } else {
    ul.innerHTML = rows.join('') + tail;
  }
  written.set(ul, { rows, tail });
}
