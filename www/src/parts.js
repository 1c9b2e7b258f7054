// The parts of a planner answer kept by the page: `update` (src/wasm.rs)
// sends a part (threads, passes, side, tooth, starts) only when its content
// key differs from the one the caller says it has.

/** The parts, in the order of `update`'s `known` keys. */
export const PARTS = ['threads', 'passes', 'side', 'tooth', 'starts'];

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
        this.keys[i] = key;
        this.values[i] = r[part];
      }
    });
    return r;
  }
}
