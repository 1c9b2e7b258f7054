// Keyboard and text alternatives for what the mouse does elsewhere:
// - lists (the pass table, the diagnostics) are one tab stop each: the
//   arrow keys, Home/End and Page Up/Down choose a row (marked as the
//   mouse's hover marks it, its lines highlighted in the program and the
//   drawings), Enter goes to its line in the program, Escape lets go; a
//   polite live region reads the chosen row;
// - each drawing (a focusable canvas, operated by input.js) has role img
//   and a label saying what it shows, in numbers, and how to move it.

import { passLines, passText, passVia, threadName } from '../shared/lists.js';
import { num } from '../shared/table.js';

/** A live region for short announcements (created once, visually hidden). */
function liveRegion() {
  let el = document.getElementById('a11y-live');
  if (!el) {
    el = document.createElement('div');
    el.id = 'a11y-live';
    el.className = 'visually-hidden';
    el.setAttribute('aria-live', 'polite');
    document.body.append(el);
  }
  return el;
}

/**
 * Makes `scroller` a keyboard-operated list. `opts`: `count()` rows,
 * `text(i)` a row's text (announced), `move(i)` marks row i (−1: none)
 * and shows it, `enter(i)` acts on it, `label` the list's accessible name
 * with its keys.
 */
export function listKeys(scroller, opts) {
  let at = -1;
  scroller.tabIndex = 0;
  scroller.setAttribute('aria-label', opts.label());
  const go = (i) => {
    const n = opts.count();
    if (!n) return;
    at = Math.max(0, Math.min(n - 1, i));
    opts.move(at);
    liveRegion().textContent = opts.text(at);
  };
  scroller.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const page = Math.max(1, Math.floor(scroller.clientHeight / 24) - 1);
    const keys = {
      ArrowDown: () => go(at + 1),
      ArrowUp: () => go(at < 0 ? 0 : at - 1),
      PageDown: () => go(at + page),
      PageUp: () => go(at - page),
      Home: () => go(0),
      End: () => go(opts.count() - 1),
      Enter: () => at >= 0 && at < opts.count() && opts.enter(at),
      Escape: () => {
        at = -1;
        opts.move(-1);
      },
    };
    const k = keys[e.key];
    if (k) {
      e.preventDefault();
      k();
    }
  });
  scroller.addEventListener('blur', () => {
    if (at >= 0) opts.move(-1);
    at = -1;
  });
  return {
    /** The list's name again (after a language change). */
    relabel: () => scroller.setAttribute('aria-label', opts.label()),
  };
}

/** Sets each drawing's role and label: what result `r` draws there (thread `ti`, start `st`), in language `t`. */
export function labelViews(r, ti, st, t) {
  const th = r && r.threads ? r.threads[ti] : null;
  const keys = t('view_keys');
  const c = r && r.passes;
  const passes = c && c.n ? t('alt_passes', { n: c.n, x0: num(c.x[0]), x1: num(c.x[c.n - 1]), z0: num(c.z[0]), z1: num(c.zEnd[0]) }) : '';
  const thread = th ? t('alt_thread', { i: ti + 1, kind: threadName(th, t), lead: num(th.lead), starts: th.starts }) : '';
  const side = r ? t('alt_side', { threads: r.threads.length, moves: r.moves, alarms: r.alarms }) : '';
  const labels = {
    side: `${t('side')}: ${side}${thread ? ` ${thread}${passes ? `, ${passes}` : ''}.` : ''} ${keys}`,
    tooth: th ? `${t('tooth')}: ${thread}, ${t('alt_tooth', { h: num(th.height), angle: num(th.tool_angle), n: th.passes })} ${keys}` : `${t('tooth')}: ${t('no_threads')}`,
    starts: th ? `${t('starts')}: ${thread}, ${t('alt_starts', { n: th.starts, st })} ${keys}` : `${t('starts')}: ${t('no_threads')}`,
  };
  for (const [id, text] of Object.entries(labels)) {
    const canvas = document.getElementById(id);
    if (!canvas) continue;
    canvas.setAttribute('role', 'img');
    if (canvas.getAttribute('aria-label') !== text) canvas.setAttribute('aria-label', text);
  }
}

/**
 * The pass table and the diagnostics list as keyboard lists. `ctx`:
 * `passes` (the table's scroller), `diagnostics` (the list), `rows` (the
 * table's VirtualRows, its `order` the shown passes), `result()`,
 * `thread()`, `shown()` (the diagnostics shown: [diagnostic, index]),
 * `diagnosticRow(k)` (row k's element, written if it is not yet),
 * `setHover(h)`, `goto(line, column)`, `t`. Returns the two lists.
 */
export function bindListKeys(ctx) {
  const { t } = ctx;
  const pass = (k) => ctx.rows.order[k];
  const passes = listKeys(ctx.passes, {
    label: () => t('list_passes'),
    count: () => (ctx.result() && ctx.result().passes ? ctx.rows.order.length : 0),
    text: (k) => passText(ctx.result().passes, pass(k), t),
    move: (k) => ctx.setHover(k >= 0 ? { thread: ctx.thread(), pass: pass(k), lines: passLines(ctx.result().passes, pass(k)), via: passVia(ctx.result().passes, pass(k)), fromView: true } : null),
    enter: (k) => ctx.goto(passLines(ctx.result().passes, pass(k))[0]),
  });
  const diag = (k) => ctx.shown()[k][0];
  const list = ctx.diagnostics;
  const diagnostics = listKeys(list.closest('.scroll'), {
    label: () => t('list_diagnostics'),
    count: () => (ctx.result() ? ctx.shown().length : 0),
    text: (k) => `${diag(k).line}:${diag(k).column} ${t(diag(k).severity)} [${diag(k).code}] ${diag(k).message}`,
    move: (k) => {
      for (const li of list.querySelectorAll('li.hot')) li.classList.remove('hot');
      const li = k >= 0 ? ctx.diagnosticRow(k) : null;
      li?.classList.add('hot');
      li?.scrollIntoView({ block: 'nearest' });
      ctx.setHover(k >= 0 ? { thread: -1, pass: -1, lines: [diag(k).line] } : null);
    },
    enter: (k) => ctx.goto(diag(k).line, diag(k).column),
  });
  return [passes, diagnostics];
}
