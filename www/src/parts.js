// The parts of a planner answer kept by the page: `update` (src/wasm.rs)
// sends a part (threads, passes, side, tooth, starts) only when its content
// key differs from the one the caller says it has; the thread list may come
// as the entries that changed. The side section comes as
// pieces (each thread's band and dimensions, runs of passes, blocks of other
// motions) of which only those the page does not hold are sent; the page
// puts the packed scene together (src/wasm/pack.rs, src/wasm/memo.rs).

import { layout } from './render.js';

/** The parts, in the order of `update`'s `known` keys. */
export const PARTS = ['threads', 'passes', 'side', 'tooth', 'starts'];

/** What a page holds of the planner's parts, by key. */
export class HeldParts {
  constructor() {
    this.keys = PARTS.map(() => -1);
    this.values = PARTS.map(() => null);
    this.pieces = new Map(); // key → piece of the side section held
  }

  /** The keys for `update`'s `known` argument. */
  known() {
    return new Float64Array(this.keys);
  }

  /** Forgets every part (the next answer sends them all). */
  clear() {
    this.keys.fill(-1);
    this.values.fill(null);
    this.pieces = new Map();
  }

  /**
   * Fills the parts answer `r` did not send (their keys are the held ones)
   * and holds the ones it sent; parts without a key in `r` are left alone.
   */
  fill(r) {
    PARTS.forEach((part, i) => {
      const key = r[`${part}Key`];
      if (key === undefined) return;
      if (key === this.keys[i]) {
        r[part] = this.values[i];
      } else {
        if (r[part] && r[part].pieces) r[part] = this.assemble(r[part]);
        if (r[part] && r[part].changes) r[part] = patchList(this.values[i], r[part]);
        this.keys[i] = key;
        this.values[i] = r[part];
      }
    });
    return r;
  }

  /** The packed side section from pieces `a`: those sent and those held; holds the ones it uses. */
  assemble(a) {
    const L = layout();
    const fresh = new Map();
    const e = a.ends;
    let s = [0, 0, 0, 0, 0];
    for (let j = 0; j < a.keys.length; j++) {
      const end = [e[5 * j], e[5 * j + 1], e[5 * j + 2], e[5 * j + 3], e[5 * j + 4]];
      fresh.set(a.keys[j], {
        coords: a.coords.subarray(s[0], end[0]),
        items: a.items.subarray(s[1], end[1]),
        lines: a.lines.subarray(s[2], end[2]),
        labels: a.labels.slice(s[3], end[3]),
        count: end[4] - s[4],
      });
      s = end;
    }
    const pieces = [];
    let nc = a.headCoords.length;
    let ni = a.headItems.length;
    let nl = 0;
    for (const k of a.order) {
      const p = fresh.get(k) ?? this.pieces.get(k);
      if (!p) throw new Error('a piece of the side section is neither sent nor held');
      pieces.push(p);
      nc += p.coords.length;
      ni += p.items.length;
      nl += p.lines.length;
    }
    const coords = new Float64Array(nc);
    const items = new Uint32Array(ni);
    const lines = new Uint32Array(nl);
    const labels = [];
    coords.set(a.headCoords);
    items.set(a.headItems);
    let c = a.headCoords.length;
    let i = a.headItems.length;
    let l = 0;
    let count = 0;
    const held = new Map();
    a.order.forEach((k, j) => {
      const p = pieces[j];
      held.set(k, p);
      coords.set(p.coords, c);
      items.set(p.items, i);
      lines.set(p.lines, l);
      // Offsets and label numbers of a piece are its own: move them to the scene's.
      for (let o = i, end = i + p.items.length; o < end; o += L.stride) {
        items[o + L.coord_start] += c;
        items[o + L.line_start] += l;
        if (items[o + L.label] > 0) items[o + L.label] += count;
      }
      if (p.count > 0) {
        labels.push(p.labels);
        count += p.count;
      }
      c += p.coords.length;
      i += p.items.length;
      l += p.lines.length;
    });
    this.pieces = held;
    return { view: a.view, bounds: a.bounds, focus: a.focus, coords, items, lines, labels: labels.join('\u001e') };
  }
}

/**
 * The list `held` with the entries `d.changes` (`[index, entry]`) replaced,
 * cut or grown to `d.length`: a new list (the engine's parts, and the page's
 * thread list the engine sends as changes).
 */
export function patchList(held, d) {
  if (!Array.isArray(held)) throw new Error('a list changed entry by entry that is not held');
  const list = held.slice(0, d.length);
  for (const [i, entry] of d.changes) list[i] = entry;
  if (list.length !== d.length || list.some((e) => e === undefined)) throw new Error('a list changed entry by entry has gaps');
  return list;
}
