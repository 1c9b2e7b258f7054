// The page's side of planning: one plan in flight at a time (while it is,
// only the latest text follows it), the keystroke each plan answers (for
// measuring keystroke → drawing), whether the drawing on screen was left
// (the session keeps it as the good one, shown greyed while a later text has
// an alarm: src/wasm/shown.rs), and the lists of the plans the session
// names: the latest and the good one; and whether the drawing is behind the
// text (a plan that takes longer than a moment). Its state is one value,
// changed only by the methods below.

/** A drawing shown this long before the next edit was one the user left (not a keystroke on the way). */
export const LEFT_MS = 1000;

/** A text not planned this long after it was sent: the drawing is behind it, and the page says so. */
export const BEHIND_MS = 400;

export class Planning {
  /**
   * @param send `send(message)` to the engine
   * @param onBehind `onBehind(since)`: the drawing on screen is behind the
   *   text since `since` (a performance.now() time), or caught up (`null`)
   */
  constructor(send, onBehind = () => {}) {
    this.send = send;
    this.onBehind = onBehind;
    this.timer = null;
    this.s = {
      behindSince: null, // when the first text not yet drawn was sent (null: the drawing is of the text)
      behind: false, // the page says the drawing is behind
      seq: 0,
      inFlight: null, // {seq, doc, t0, typed} of the plan the engine is working on
      wanted: false, // the text changed while a plan was in flight
      pendingInput: null, // timeStamp of the keystroke the next plan answers
      inputs: new Map(), // seq → timeStamp of its keystroke
      fresh: false, // the next plan is another program's: no good drawing of this one yet
      shownAt: 0, // when the last answer without alarm was shown (0: an edit followed it)
      shownTyped: false, // whether a keystroke made it (else a setting, a file, a program opened)
      kept: new Map(), // plan number → its answer: the latest and the good one
      last: null, // the latest answer
    };
  }

  /** A keystroke (or input event) at `timeStamp`: the next plan answers it. */
  input(timeStamp, first = false) {
    if (!first || this.s.pendingInput === null) this.s.pendingInput = timeStamp;
  }

  /** The next text is another program's: forget the good drawing and the lists kept. */
  another() {
    this.s.fresh = true;
    this.s.shownAt = 0;
    this.s.kept.clear();
  }

  /**
   * Sends a plan of `request()` (`{text or edits, dialect, settings, thread,
   * start}`, asked for only when it is sent) of document `doc`, unless one
   * is in flight (then it follows that one). Returns whether it was sent.
   */
  plan(request, doc) {
    const s = this.s;
    if (s.inFlight) {
      s.wanted = true;
      return false;
    }
    s.wanted = false;
    s.seq += 1;
    s.inFlight = { seq: s.seq, doc, t0: performance.now(), typed: s.pendingInput !== null };
    // The good plan on screen becomes the one kept for alarms when it was left a while (or is the first).
    const keep = s.shownAt > 0 && (s.last?.goodPlan == null || !s.shownTyped || performance.now() - s.shownAt >= LEFT_MS);
    s.shownAt = 0;
    if (s.pendingInput !== null) {
      s.inputs.set(s.seq, s.pendingInput);
      s.pendingInput = null;
    }
    this.send({ type: 'plan', seq: s.seq, ...request(), input: s.inputs.get(s.seq) ?? null, fresh: s.fresh, keep });
    s.fresh = false;
    if (s.behindSince === null) s.behindSince = s.inFlight.t0;
    this.armBehind();
    return true;
  }

  /** Says "behind" once the text sent first has waited BEHIND_MS without an answer that caught up. */
  armBehind() {
    if (this.timer !== null || this.s.behind) return;
    const wait = Math.max(0, BEHIND_MS - (performance.now() - this.s.behindSince));
    this.timer = setTimeout(() => {
      this.timer = null;
      if (this.s.behindSince === null) return;
      this.s.behind = true;
      this.onBehind(this.s.behindSince);
    }, wait);
  }

  /** The drawing is of the text: no longer behind. */
  caughtUp() {
    const s = this.s;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    s.behindSince = null;
    if (s.behind) {
      s.behind = false;
      this.onBehind(null);
    }
  }

  /**
   * Answer `r` of plan `seq` arrived (its lists already filled in). Returns
   * `{shown, stale, again, t0}`: the lists to show with the drawing (the good
   * plan's while it is greyed), whether the plan in flight ended with the
   * document changed since (`again`: plan again), and when it was sent.
   */
  answered(r, seq, doc) {
    const s = this.s;
    const mine = s.inFlight && s.inFlight.seq === seq;
    if (r.good) {
      s.shownAt = performance.now();
      s.shownTyped = !!(mine && s.inFlight.typed);
    }
    s.last = r;
    s.kept.set(r.plan, r);
    for (const k of s.kept.keys()) if (k !== r.plan && k !== r.goodPlan) s.kept.delete(k);
    const good = r.stale ? s.kept.get(r.goodPlan) : null;
    const stale = !!good && good !== r;
    const t0 = mine ? s.inFlight.t0 : null;
    let again = false;
    if (mine) {
      // The document is immutable: another one is another text (no walk of a long program to compare).
      again = s.wanted || doc !== s.inFlight.doc;
      s.inFlight = null;
      if (!again) this.caughtUp();
    }
    return { shown: stale ? good : r, stale, again, t0 };
  }

  /** The lists to show now with the drawing, and whether they are the good plan's (greyed). */
  shown() {
    const r = this.s.last;
    const good = r && r.stale ? this.s.kept.get(r.goodPlan) : null;
    const stale = !!good && good !== r;
    return { shown: stale ? good : r, stale };
  }

  /** Whether no plan is in flight and none is to follow (the last answer is of the text last sent). */
  idle() {
    return this.s.inFlight === null && !this.s.wanted;
  }

  /** The engine failed: nothing is in flight any more. */
  failed() {
    this.s.inFlight = null;
    this.caughtUp();
  }

  /** The keystroke a drawn plan `seq` answered (or `input`), once: null when none. */
  frameInput(seq, input) {
    const v = input ?? this.s.inputs.get(seq);
    this.s.inputs.delete(seq);
    return v ?? null;
  }
}
