// The parts of a planner answer kept by the page: `update`
// (src/wasm/session.rs) sends a part (threads, passes) only when its content
// key differs from the one the caller says it has; the thread list may come
// as the entries that changed. The scenes stay in the session: the views
// ask it for their display lists.

/** The parts, in the order of `update`'s `known` keys. */
export const PARTS = ['threads', 'passes'];

/** What a page holds of the planner's parts, by key. */
export class HeldParts {
  constructor() {
    this.keys = PARTS.map(() => -1);
    this.values = PARTS.map(() => null);
  }

  /** The keys for `update`'s `known` argument. */
  known() {
    return new Float64Array(this.keys);
  }

  /** Forgets every part (the next answer sends them all). */
  clear() {
    this.keys.fill(-1);
    this.values.fill(null);
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
        if (r[part] && r[part].changes) r[part] = patchList(this.values[i], r[part]);
        this.keys[i] = key;
        this.values[i] = r[part];
      }
    });
    return r;
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

/**
 * The diagnostics list `held` changed by `s` (`update`'s
 * `diagnosticsSplice`, src/wasm/listed.rs): `s.remove` entries from `s.at`
 * replaced by `s.items`, every entry at its offsets from `s.offsets`
 * (`[from, to]` each). A new list; an entry whose offsets did not move is
 * the same object.
 */
export function spliceList(held, s) {
  if (!Array.isArray(held)) throw new Error('a list changed in place that is not held');
  const n = held.length - s.remove + s.items.length;
  if (s.at + s.remove > held.length || s.offsets.length !== 2 * n) throw new Error('a list change that does not fit the list held');
  const list = new Array(n);
  const after = s.at + s.items.length;
  for (let i = 0; i < n; i++) {
    const d = i < s.at ? held[i] : i < after ? s.items[i - s.at] : held[i - s.items.length + s.remove];
    const from = s.offsets[2 * i];
    const to = s.offsets[2 * i + 1];
    list[i] = d.from === from && d.to === to ? d : { ...d, from, to };
  }
  return list;
}
