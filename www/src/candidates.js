// Where a label may go: its frame on the screen under a transform and its
// candidate places, best first (labels.js places each at the first clean one).
// A dimension's label goes beside its line on the preferred side, the other
// side, along the line, past its ends, or with the line stacked further
// out; a diameter's (a half dimension) past its arrowhead or beside its
// line towards the axis; a text beside its point, shifted up or down a line,
// mirrored about its point, slid into the view; a stack of texts beside one
// edge (as pass depths) keeps its order.

/** Height of a label's box: 12 px text and its halo. */
export const LINE = 15;
/** Space between a dimension line and its text. */
export const GAP = 3;
/** How much further out a stacked dimension line goes. */
export const STEP = LINE + 3;
/** Labels keep this far from the view's edges. */
export const EDGE = 3;
/** Length of a dimension's arrowhead. */
export const HEAD = 7;

export const sx = (xf, x) => xf.tx + xf.sx * x;
export const sy = (xf, y) => xf.ty - xf.sy * y;

/** Box width and height of a label of text width `w` at `angle` (0 or −90). */
function boxSize(w, vertical) {
  return vertical ? [LINE, w + 4] : [w + 4, LINE];
}

/** Screen frame of a dimension: its ends, direction u (a→b), left normal n, and the box. */
export function dimFrame(lab, xf) {
  const A = [sx(xf, lab.a[0]), sy(xf, lab.a[1])];
  const B = [sx(xf, lab.b[0]), sy(xf, lab.b[1])];
  const dx = B[0] - A[0];
  const dy = B[1] - A[1];
  const len = Math.hypot(dx, dy);
  if (!(len > 1e-9)) return null;
  const u = [dx / len, dy / len];
  // Left of a→b in world terms is (dy, −dx) on screen (y points down).
  const n = [u[1], -u[0]];
  const vertical = Math.abs(n[0]) > 0.7;
  const [bw, bh] = boxSize(lab.w, vertical);
  const sgn = lab.offset >= 0 ? 1 : -1;
  // Half extents of the box across and along the line.
  const en = (bw / 2) * Math.abs(n[0]) + (bh / 2) * Math.abs(n[1]);
  const eu = (bw / 2) * Math.abs(u[0]) + (bh / 2) * Math.abs(u[1]);
  return { A, B, len, u, n, vertical, bw, bh, sgn, en, eu };
}

/**
 * Where the line of a dimension at offset `o` is inside the view: [t0, t1]
 * of a→b, or null; all of it without a view (`view.all`, for the fit).
 */
function visibleRange(fr, o, view) {
  if (view.all) return [0, 1];
  const x0 = fr.A[0] + fr.n[0] * o;
  const y0 = fr.A[1] + fr.n[1] * o;
  const dx = fr.B[0] - fr.A[0];
  const dy = fr.B[1] - fr.A[1];
  const m = EDGE + 4;
  let t0 = 0;
  let t1 = 1;
  const clip = (p, q) => {
    if (p === 0) return q >= 0;
    const r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      if (r > t0) t0 = r;
    } else {
      if (r < t0) return false;
      if (r < t1) t1 = r;
    }
    return true;
  };
  if (clip(-dx, x0 - m) && clip(dx, view.w - m - x0) && clip(-dy, y0 - m) && clip(dy, view.h - m - y0) && t1 > t0) return [t0, t1];
  return null;
}

/** The box of a candidate centred at (cx, cy). */
export const boxAt = (c, bw, bh) => [c.cx - bw / 2, c.cy - bh / 2, c.cx + bw / 2, c.cy + bh / 2];

/**
 * The candidates of a dimension's label, best first: {cx, cy, off, S?, len?}.
 * A half dimension (of a diameter) has its arrowhead at b and its line
 * towards the axis a: its text goes past the arrowhead, in line with it, or
 * along the line; the line runs to the axis when the axis is in view, else as
 * far as the text needs (`len` pixels from S, its end at b).
 */
export function* dimCandidates(lab, fr, view) {
  const { A, n, u, sgn, en, eu } = fr;
  if (lab.kind === 'half') {
    const axisShown = !view.all && A[0] >= 0 && A[0] <= view.w && A[1] >= 0 && A[1] <= view.h;
    const stub = (reach) => (axisShown ? fr.len : Math.min(fr.len, Math.max(reach + 6, 28)));
    for (let k = 0; k < 3; k++) {
      const off = lab.offset + sgn * k * STEP;
      const S = [fr.B[0] + n[0] * off, fr.B[1] + n[1] * off];
      // Past the arrowhead, beyond b.
      for (let j = 0; j < 2; j++) {
        const q = GAP + eu + j * STEP;
        yield { cx: S[0] + u[0] * q, cy: S[1] + u[1] * q, off, S, len: stub(0) };
      }
      // Beside the line, from the arrowhead towards the axis.
      for (let j = 0; j < 3; j++) {
        const along = HEAD + GAP + eu + j * STEP;
        for (const side of [1, -1]) {
          const d = sgn * side * (GAP + en);
          yield { cx: S[0] - u[0] * along + n[0] * d, cy: S[1] - u[1] * along + n[1] * d, off, S, len: stub(along + eu) };
        }
      }
    }
    return;
  }
  const ts = [0.5, 0.35, 0.65, 0.2, 0.8, 0.08, 0.92];
  for (let k = 0; k < 4; k++) {
    const off = lab.offset + sgn * k * STEP;
    const range = visibleRange(fr, off, view);
    if (!range) continue;
    const [t0, t1] = range;
    const sides = k === 0 ? [1, -1] : [1];
    for (const side of sides) {
      const d = off + sgn * side * (GAP + en);
      for (const f of ts) {
        const t = t0 + (t1 - t0) * f;
        yield { cx: A[0] + (fr.B[0] - A[0]) * t + n[0] * d, cy: A[1] + (fr.B[1] - A[1]) * t + n[1] * d, off };
      }
    }
    // Past either end of the line, in line with it.
    for (const [P, s] of [
      [fr.B, 1],
      [A, -1],
    ]) {
      const q = HEAD + GAP + eu;
      yield { cx: P[0] + n[0] * off + u[0] * s * q, cy: P[1] + n[1] * off + u[1] * s * q, off };
    }
  }
}

/** Screen anchor and preferred box centre of a text. */
export function textFrame(lab, xf) {
  const X = sx(xf, lab.p[0]);
  const Y = sy(xf, lab.p[1]);
  const n = lab.lines ? lab.lines.length : 1;
  const bw = lab.w + 4;
  const bh = n * LINE;
  const px = X + lab.dx;
  // A text of several lines grows away from its point.
  const py = Y - lab.dy - Math.sign(lab.dy) * ((n - 1) * LINE) / 2;
  const half = lab.anchor === 'start' ? bw / 2 : lab.anchor === 'end' ? -bw / 2 : 0;
  return { X, Y, px, py, half, bw, bh };
}

/** The candidates of a text, best first: {cx, cy}. */
export function* textCandidates(lab, fr, view) {
  const { X, px, py, half, bw, bh } = fr;
  if (lab.slot !== undefined) {
    // A text of a stack goes to its slot in the stack, or nowhere (it would leave the stack's order).
    if (lab.slot !== null) yield { cx: px + half, cy: lab.slot };
    return;
  }
  const bases = [px + half];
  // Mirrored about its point: a text after its point goes before it, and back.
  if (lab.anchor !== 'middle') bases.push(X - lab.dx - half);
  const shifts = [0, -1, 1, -2, 2];
  for (const cx of bases) {
    for (const k of shifts) {
      const cy = py + k * (LINE + 1);
      yield { cx, cy };
      // Slid into the view, by at most its width (it stays by its point).
      const x = Math.min(Math.max(cx, EDGE + bw / 2), view.w - EDGE - bw / 2);
      const y = Math.min(Math.max(cy, EDGE + bh / 2), view.h - EDGE - bh / 2);
      if ((x !== cx || y !== cy) && Math.abs(x - cx) <= bw && Math.abs(y - cy) <= LINE) yield { cx: x, cy: y };
    }
  }
}

/**
 * Stacks: three or more texts beside their points (no vertical offset) that
 * start or end at one x, as the depth of each pass beside the tooth. Their
 * order down the stack is kept: the stack keeps as many as fit in the view
 * (dropping the least important, from where they crowd most) and moves each
 * as little as it can (least squares, one line apart: pool-adjacent-violators).
 * Sets `slot` (the centre y, or null when left out) on the stacked labels.
 */
export function stackTexts(labels, xf, view) {
  const groups = new Map();
  for (const lab of labels) {
    delete lab.slot;
    if (lab.kind !== 'text' || lab.anchor === 'middle' || Math.abs(lab.dy) > 1e-9 || lab.lines) continue;
    const fr = textFrame(lab, xf);
    const key = `${lab.anchor}:${Math.round(fr.px)}`;
    let g = groups.get(key);
    if (!g) groups.set(key, (g = []));
    g.push([lab, fr.py]);
  }
  const s = LINE + 1;
  const top = EDGE + LINE / 2;
  const bottom = view.h - EDGE - LINE / 2;
  for (const group of groups.values()) {
    if (group.length < 3) continue;
    for (const [lab] of group) lab.slot = null;
    // Those beside the view are left out; the rest in order down the view.
    let g = group.filter(([, y]) => y >= 0 && y <= view.h).sort((p, q) => p[1] - q[1] || p[0].i - q[0].i);
    const room = Math.max(0, Math.floor((bottom - top) / s) + 1);
    while (g.length > room) {
      let worst = -1;
      for (let k = 0; k < g.length; k++) {
        if (g[k][0].must) continue;
        const gap = (j) => Math.min(j > 0 ? g[j][1] - g[j - 1][1] : Infinity, j + 1 < g.length ? g[j + 1][1] - g[j][1] : Infinity);
        if (worst < 0) worst = k;
        else {
          const a = g[k][0];
          const b = g[worst][0];
          if (a.prio > b.prio || (a.prio === b.prio && (gap(k) < gap(worst) || (gap(k) === gap(worst) && a.i > b.i)))) worst = k;
        }
      }
      if (worst < 0) break;
      g = g.filter((_, k) => k !== worst);
    }
    if (!g.length) continue;
    // Least squares with y[k] ≥ y[k−1] + s: isotonic regression of y[k] − k·s.
    const blocks = [];
    g.forEach(([, y], k) => {
      blocks.push({ sum: y - k * s, n: 1 });
      while (blocks.length > 1 && blocks.at(-2).sum / blocks.at(-2).n > blocks.at(-1).sum / blocks.at(-1).n) {
        const b = blocks.pop();
        blocks.at(-1).sum += b.sum;
        blocks.at(-1).n += b.n;
      }
    });
    const y = [];
    for (const b of blocks) for (let k = 0; k < b.n; k++) y.push(b.sum / b.n + y.length * s);
    // Inside the view, one line apart.
    for (let k = 0; k < y.length; k++) y[k] = Math.max(y[k], k ? y[k - 1] + s : top);
    for (let k = y.length - 1; k >= 0; k--) y[k] = Math.min(y[k], k + 1 < y.length ? y[k + 1] - s : bottom);
    g.forEach(([lab], k) => (lab.slot = y[k]));
  }
}
