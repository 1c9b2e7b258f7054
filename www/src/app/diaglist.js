// The diagnostics list, written as it is read: the first STEP rows of the
// diagnostics shown, and STEP more each time the list is scrolled near its
// end, its last row ("… 500 more") is clicked, or the keyboard goes past
// it. A program with hundreds of notes keeps a short list in the page:
// every frame of the page (each keystroke's) styles, lays out, pre-paints
// and hit-tests what is in the DOM, and the rows of 600 notes were three
// quarters of the page's elements.

import { diagnosticRows, patchRows } from '../shared/lists.js';
import { esc } from '../shared/table.js';

/** How many rows are written at first, and added at a time. */
export const STEP = 100;
/** How near its end (CSS px) a scroll writes more rows. */
const NEAR_END = 400;

export class DiagnosticsList {
  /**
   * @param {HTMLElement} ul the list (inside its scroller, `.scroll`)
   * @param {{t: Function, lang: () => string}} opts the page's texts and language
   */
  constructor(ul, opts) {
    this.ul = ul;
    this.scroller = ul.closest('.scroll') || ul;
    this.opts = opts;
    this.limit = STEP;
    this.shown = [];
    this.scroller.addEventListener(
      'scroll',
      () => {
        const s = this.scroller;
        if (s.scrollHeight - s.scrollTop - s.clientHeight < NEAR_END) this.more();
      },
      { passive: true },
    );
    ul.addEventListener('click', (e) => {
      if (e.target.closest('li.more')) this.more();
    });
  }

  /** Shows `shown` (`[diagnostic, index]`): as many rows as were written before, at least STEP. */
  show(shown) {
    this.shown = shown;
    this.write();
  }

  /** Another program: back to the first STEP rows. */
  reset() {
    this.limit = STEP;
  }

  /** How many rows are written. */
  written() {
    return Math.min(this.shown.length, this.limit);
  }

  /** Writes STEP more rows, if there are more. */
  more() {
    if (this.limit >= this.shown.length) return;
    this.limit += STEP;
    this.write();
  }

  /** The element of row `k`, written first when it is not yet (the keyboard's row). */
  row(k) {
    if (k >= this.limit && k < this.shown.length) {
      this.limit = k + STEP;
      this.write();
    }
    return k >= 0 && k < this.written() ? this.ul.children[k] : null;
  }

  write() {
    const { t, lang } = this.opts;
    const n = this.written();
    const rows = diagnosticRows(this.shown.slice(0, n), t, lang());
    const rest = this.shown.length - n;
    const tail = rest > 0 ? `<li class="more">${esc(t('more_rows', { n: rest }))}</li>` : '';
    patchRows(this.ul, rows, tail);
  }
}
