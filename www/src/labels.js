// Label placement and a fit that makes room for labels.
//
// A scene's dimensions and texts are anchored in world coordinates but sized
// in pixels: a dimension line sits `offset` pixels beside its two points, a
// text `dx`, `dy` pixels from its point, and a label is as wide as its text.
// This module knows nothing of the packed record layout (render.js walks the
// scene and hands it label records); it does two things with them:
//
// - `placeLabels`: at a given transform, a place for each label among its
//   candidates (the preferred side of its dimension line, the other side,
//   along the line, past its ends, the line stacked further out; a text
//   shifted up or down a line, mirrored about its point, slid into the view;
//   a stack of texts beside one edge, as pass depths, kept in order) so that
//   no two labels overlap and every label lies inside the view, crossing no
//   dimension line and none of the drawing's lines where it can. Greedy in a
//   stable priority order: the chosen thread's dimensions first. A label
//   that fits nowhere is dropped, never the chosen thread's major, minor or
//   lead; another thread's label is also dropped where it would cross a
//   dimension.
// - `fitLabels`: the world→screen transform whose scale leaves room, inside
//   the view, for the geometry and for every label where placement puts it
//   in a view without bounds. World extents grow with the scale, pixel
//   margins do not, so the largest scale is solved per axis (a bisection on
//   a convex function), a few rounds since the places depend on the scale.
//
// Boxes are [x0, y0, x1, y1] in CSS pixels of the view; every painter (canvas,
// SVG, PNG) draws a label in the box placed here, so they agree. A text
// wider than about half its view is wrapped (`wrap`) before it is placed.

/** Height of a label's box: 12 px text and its halo. */
export const LINE = 15;
/** Space between a dimension line and its text. */
const GAP = 3;
/** How much further out a stacked dimension line goes. */
const STEP = LINE + 3;
/** Labels keep this far from the view's edges. */
export const EDGE = 3;
/** The geometry keeps this far from the view's edges. */
export const GEOMETRY_PAD = 16;
/** Length of a dimension's arrowhead. */
const HEAD = 7;

/**
 * The order labels are placed in (lower first) by label key; dimensions of
 * the chosen thread come before everything else.
 */
const RANK = {
  dia_major: 0,
  dia_minor: 1,
  lead: 2,
  pitch: 3,
  height: 4,
  length: 5,
  taper: 6,
  detail_passes: 7,
  detail_starts: 7,
  detail_starts_passes: 7,
  moves_capped: 7,
  starts_capped: 7,
  start_of: 8,
  pass_depth_finish: 9,
  pass_depth_spring: 9,
  tool_angle: 10,
  infeed_radial: 10,
  infeed_left: 10,
  infeed_right: 10,
  infeed_alternating: 10,
  infeed_programmed: 10,
  square_tool: 10,
  delta1: 11,
  delta2: 11,
  one_rev: 12,
  axial_offsets: 12,
  start_angle: 13,
  '': 14,
  pass_depth: 15,
};

/** Labels never dropped for the chosen thread. */
const MUST = new Set(['dia_major', 'dia_minor', 'lead']);

/**
 * A label record for `placeLabels` and `fitLabels`.
 * `kind`: 'dim' (a: [x, y], b: [x, y] world, offset px), 'half' (a
 * dimension of a diameter from the axis `a`: one arrowhead at `b`), or
 * 'text' (p: [x, y] world, dx, dy px, dy up, anchor 'start' | 'middle' | 'end';
 * `lines`: the text wrapped, when it is, one line apart).
 * `w`: the text's measured width (of its widest line). `chosen`: whether it belongs to the chosen thread.
 */
export function label(fields) {
  const rank = RANK[fields.key] ?? 20;
  const dim = fields.kind !== 'text';
  const chosen = fields.chosen !== false;
  return {
    ...fields,
    // Dimensions before texts of the same rank; another thread's after all of the chosen one's.
    prio: (chosen ? 0 : 1000) + rank * 2 + (dim ? 0 : 1),
    must: chosen && dim && MUST.has(fields.key),
    at: null,
  };
}

/**
 * `text` broken into lines at most `max` pixels wide (by `width`), where a
 * line may break: after a space or a colon or comma, before a parenthesis,
 * between two CJK characters; a piece wider than `max` keeps its own line.
 * Null when it fits on one line.
 */
export function wrap(text, max, width) {
  if (!(width(text) > max)) return null;
  const pieces = [];
  let piece = '';
  const chars = [...text];
  let depth = 0; // no break inside parentheses
  chars.forEach((ch, k) => {
    const next = chars[k + 1] ?? '';
    piece += ch;
    if (/[(（]/.test(ch)) depth++;
    if (/[)）]/.test(ch)) depth = Math.max(0, depth - 1);
    const cjk = (c) => c.codePointAt(0) >= 0x2e80 && !/[：，、（）()]/.test(c);
    const after = /[\s:：,，、]/.test(ch) && !/[\s:：,，、]/.test(next);
    if (!next || (depth === 0 && (after || /[(（]/.test(next) || (cjk(ch) && (cjk(next) || /\s/.test(next)))))) {
      pieces.push(piece);
      piece = '';
    }
  });
  const lines = [];
  let line = '';
  for (const p of pieces) {
    if (line && width((line + p).trimEnd()) > max) {
      lines.push(line.trimEnd());
      line = p.trimStart();
    } else line += p;
  }
  if (line.trim()) lines.push(line.trimEnd());
  return lines.length > 1 ? lines : null;
}

// ---------------------------------------------------------------------------
// Screen geometry of one label under a transform.

const sx = (xf, x) => xf.tx + xf.sx * x;
const sy = (xf, y) => xf.ty - xf.sy * y;

/** Box width and height of a label of text width `w` at `angle` (0 or −90). */
function boxSize(w, vertical) {
  return vertical ? [LINE, w + 4] : [w + 4, LINE];
}

/** Screen frame of a dimension: its ends, direction u (a→b), left normal n, and the box. */
function dimFrame(lab, xf) {
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
const boxAt = (c, bw, bh) => [c.cx - bw / 2, c.cy - bh / 2, c.cx + bw / 2, c.cy + bh / 2];

/**
 * The candidates of a dimension's label, best first: {cx, cy, off, S?, len?}.
 * A half dimension (of a diameter) has its arrowhead at b and its line
 * towards the axis a: its text goes past the arrowhead, in line with it, or
 * along the line; the line runs to the axis when the axis is in view, else as
 * far as the text needs (`len` pixels from S, its end at b).
 */
function* dimCandidates(lab, fr, view) {
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
function textFrame(lab, xf) {
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
function* textCandidates(lab, fr, view) {
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
function stackTexts(labels, xf, view) {
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

// ---------------------------------------------------------------------------
// Placement.

const overlaps = (a, b) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
const inside = (b, view) => b[0] >= EDGE - 0.01 && b[1] >= EDGE - 0.01 && b[2] <= view.w - EDGE + 0.01 && b[3] <= view.h - EDGE + 0.01;

/** Placed boxes in a coarse grid of the view, for overlap tests in about constant time. */
class Boxes {
  constructor() {
    this.cells = new Map();
    this.all = [];
  }
  static key(i, j) {
    return i * 65536 + j;
  }
  range(b) {
    const C = 64;
    return [Math.floor(b[0] / C), Math.floor(b[1] / C), Math.floor(b[2] / C), Math.floor(b[3] / C)];
  }
  hits(b) {
    const [i0, j0, i1, j1] = this.range(b);
    for (let i = i0; i <= i1; i++)
      for (let j = j0; j <= j1; j++) {
        const list = this.cells.get(Boxes.key(i, j));
        if (list) for (const o of list) if (overlaps(b, o)) return true;
      }
    return false;
  }
  /** Area of `b` covered by placed boxes (for a label that must go somewhere). */
  cover(b) {
    let a = 0;
    for (const o of this.all) if (overlaps(b, o)) a += (Math.min(b[2], o[2]) - Math.max(b[0], o[0])) * (Math.min(b[3], o[3]) - Math.max(b[1], o[1]));
    return a;
  }
  add(b) {
    this.all.push(b);
    const [i0, j0, i1, j1] = this.range(b);
    for (let i = i0; i <= i1; i++)
      for (let j = j0; j <= j1; j++) {
        const k = Boxes.key(i, j);
        let list = this.cells.get(k);
        if (!list) this.cells.set(k, (list = []));
        list.push(b);
      }
  }
}

/**
 * The drawing's lines, which labels prefer not to cross, in a grid of world
 * cells built once per scene (`lineIndex`): a label's box on screen is taken
 * back to world coordinates to find the lines near it.
 */
class LineIndex {
  /** `world`: x0 y0 x1 y1 of each segment; `rect`: [x0, y0, x1, y1] the grid spans (64 × 64 cells). */
  constructor(world, rect) {
    this.world = world;
    const [x0, y0, x1, y1] = rect;
    this.x0 = x0;
    this.y0 = y0;
    this.cw = Math.max((x1 - x0) / 64, 1e-9);
    this.ch = Math.max((y1 - y0) / 64, 1e-9);
    // Cells −1 … 64 on each axis (the outer ones hold what lies beyond), as
    // compressed rows: the segments of cell c are list[start[c] … start[c + 1]).
    const N = 66;
    const count = new Int32Array(N * N + 1);
    this.wide = []; // segments across more than 256 cells, tested every time
    let fill = null;
    for (let pass = 0; pass < 2; pass++) {
      for (let k = 0; k + 3 < world.length; k += 4) {
        const a = world[k];
        const b = world[k + 1];
        const c = world[k + 2];
        const d = world[k + 3];
        if (!Number.isFinite(a + b + c + d)) continue;
        const i0 = this.col(a < c ? a : c) + 1;
        const i1 = this.col(a < c ? c : a) + 1;
        const j0 = this.row(b < d ? b : d) + 1;
        const j1 = this.row(b < d ? d : b) + 1;
        if ((i1 - i0 + 1) * (j1 - j0 + 1) > 256) {
          if (pass === 0) this.wide.push(k);
          continue;
        }
        for (let i = i0; i <= i1; i++)
          for (let j = j0; j <= j1; j++) {
            if (pass === 0) count[i * N + j + 1]++;
            else this.list[fill[i * N + j]++] = k;
          }
      }
      if (pass === 0) {
        for (let c = 1; c <= N * N; c++) count[c] += count[c - 1];
        this.start = count;
        this.list = new Int32Array(count[N * N]);
        fill = count.slice();
      }
    }
  }
  col(x) {
    return Math.max(-1, Math.min(64, Math.floor((x - this.x0) / this.cw)));
  }
  row(y) {
    return Math.max(-1, Math.min(64, Math.floor((y - this.y0) / this.ch)));
  }
  /** Whether a line crosses the screen box `b` under transform `xf`. */
  hits(b, xf) {
    const w = this.world;
    const test = (k) =>
      segmentHitsBox([sx(xf, w[k]), sy(xf, w[k + 1])], [sx(xf, w[k + 2]), sy(xf, w[k + 3])], b);
    for (const k of this.wide) if (test(k)) return true;
    const i0 = this.col((b[0] - xf.tx) / xf.sx);
    const i1 = this.col((b[2] - xf.tx) / xf.sx);
    const j0 = this.row((xf.ty - b[3]) / xf.sy);
    const j1 = this.row((xf.ty - b[1]) / xf.sy);
    const N = 66;
    for (let i = i0 + 1; i <= i1 + 1; i++)
      for (let j = j0 + 1; j <= j1 + 1; j++) {
        const c = i * N + j;
        for (let e = this.start[c]; e < this.start[c + 1]; e++) if (test(this.list[e])) return true;
      }
    return false;
  }
}

/**
 * An index of the drawing's lines for `placeLabels` and `fitLabels`:
 * `world` holds x0 y0 x1 y1 of each segment in world coordinates, `rect` the
 * region it is finest over (the scene's focus). Build it once per scene.
 */
export function lineIndex(world, rect) {
  return new LineIndex(world, rect);
}

/** Whether segment p→q crosses box b. */
function segmentHitsBox(p, q, b) {
  let t0 = 0;
  let t1 = 1;
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  for (const [pp, qq] of [
    [-dx, p[0] - b[0]],
    [dx, b[2] - p[0]],
    [-dy, p[1] - b[1]],
    [dy, b[3] - p[1]],
  ]) {
    if (pp === 0) {
      if (qq < 0) return false;
    } else {
      const r = qq / pp;
      if (pp < 0) t0 = Math.max(t0, r);
      else t1 = Math.min(t1, r);
      if (t0 > t1) return false;
    }
  }
  return true;
}

/** Whether segments p→q and r→s run along each other (nearly parallel, within 5 px, side by side). */
function segmentsClash(p, q, r, s) {
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  const L = Math.hypot(dx, dy);
  const ex = s[0] - r[0];
  const ey = s[1] - r[1];
  const M = Math.hypot(ex, ey);
  if (!(L > 0) || !(M > 0)) return false;
  if (Math.abs(dx * ey - dy * ex) > 0.17 * L * M) return false;
  const across = (w) => Math.abs((w[0] - p[0]) * dy - (w[1] - p[1]) * dx) / L;
  if (across(r) > 5 || across(s) > 5) return false;
  const along = (w) => ((w[0] - p[0]) * dx + (w[1] - p[1]) * dy) / L;
  const a = along(r);
  const b = along(s);
  return Math.max(a, b) > 0 && Math.min(a, b) < L;
}

/** The segments a placed dimension draws (its line and extension lines), in pixels. */
function dimSegments(lab, fr, c) {
  const { A, B, n, u } = fr;
  if (lab.kind === 'half') {
    const S = c.S;
    return [[S, [S[0] - u[0] * c.len, S[1] - u[1] * c.len]]];
  }
  const o = c.off;
  return [[[A[0] + n[0] * o, A[1] + n[1] * o], [B[0] + n[0] * o, B[1] + n[1] * o]]];
}

/**
 * Places `labels` (records of `label()`) at transform `xf` in a view of
 * `view.w` × `view.h` CSS pixels (`view.all`: without bounds, as the fit
 * does). Sets each label's `at` to its place ({cx, cy, off?, S?, len?, box,
 * angle, lead?}) or null when dropped; returns the placed ones. `drawing`: the
 * drawing's lines that labels avoid (`lineIndex`), or null.
 *
 * A place must keep the label inside the view and off every label placed
 * before. Among those, the first candidate that is clean wins: its text
 * crosses no dimension line, its own line crosses no label and runs along
 * no other dimension's line, and its text crosses none of the drawing's
 * lines; else the first that is clean of dimension lines; else the first.
 */
export function placeLabels(labels, xf, view, drawing = null) {
  if (!view.all) stackTexts(labels, xf, view);
  const order = labels.map((l, k) => [l, k]).sort((p, q) => p[0].prio - q[0].prio || p[1] - q[1]);
  const boxes = new Boxes();
  const lines = [];
  const placed = [];
  const within = view.all ? () => true : (b) => inside(b, view);
  for (const [lab] of order) {
    lab.at = null;
    const dim = lab.kind !== 'text';
    const fr = dim ? dimFrame(lab, xf) : textFrame(lab, xf);
    if (!fr) continue;
    const { bw, bh } = fr;
    let best = null;
    let bestScore = Infinity;
    let least = null;
    let leastCover = Infinity;
    const cands = dim ? dimCandidates(lab, fr, view) : textCandidates(lab, fr, view);
    for (const c of cands) {
      const box = boxAt(c, bw, bh);
      if (!within(box)) continue;
      if (boxes.hits(box)) {
        if (lab.must) {
          const cov = boxes.cover(box);
          if (cov < leastCover) {
            leastCover = cov;
            least = { ...c, box };
          }
        }
        continue;
      }
      const cand = { ...c, box };
      let score = 0;
      let crossing = lines.some(([p, q]) => segmentHitsBox(p, q, box));
      if (!crossing && dim) {
        const own = dimSegments(lab, fr, cand);
        crossing = own.some(([p, q]) => placed.some((o) => segmentHitsBox(p, q, o.at.box)) || lines.some(([r, t]) => segmentsClash(p, q, r, t)));
      }
      if (crossing) score += 2;
      if (drawing && score < bestScore && drawing.hits(shrink(box), xf)) score += 1;
      if (score < bestScore) {
        best = cand;
        bestScore = score;
        if (score === 0) break;
      }
    }
    // Another thread's label goes only where it crosses no dimension: else it is left out.
    const at = (best && (lab.chosen || bestScore < 2) ? best : null) || (lab.must ? least : null);
    if (!at) continue;
    at.angle = dim && fr.vertical ? -90 : 0;
    if (!dim && Math.hypot(lab.dx, lab.dy) < LINE && Math.abs(at.cy - fr.py) >= (lab.slot !== undefined ? 2 : LINE / 2)) {
      // A text that sits beside its point, moved off its line, gets a leader from the point to the box.
      const lx = Math.min(Math.max(fr.X, at.box[0]), at.box[2]);
      const ly = Math.min(Math.max(fr.Y, at.box[1]), at.box[3]);
      at.lead = [fr.X, fr.Y, lx, ly];
    }
    lab.at = at;
    boxes.add(at.box);
    if (dim) lines.push(...dimSegments(lab, fr, at));
    placed.push(lab);
  }
  return placed;
}

/** A label's box less its halo and padding: the drawing may touch that much. */
const shrink = (b) => [b[0] + 2, b[1] + 2, b[2] - 2, b[3] - 2];

/** The screen frame of a dimension label (for drawing its line where it was placed). */
export function frameOf(lab, xf) {
  return lab.kind === 'text' ? textFrame(lab, xf) : dimFrame(lab, xf);
}

// ---------------------------------------------------------------------------
// Fit.

/**
 * What a label placed at `lab.at` (under transform `at`, translation 0) asks
 * of the fit: world points with pixel boxes around them, {x, y, l, r, t, b}
 * (screen x from sx·x + l to sx·x + r, screen y from −sy·y + t to −sy·y + b,
 * before translation): its box and, for a dimension, the ends of its lines.
 */
function fitElements(lab, at, out) {
  const anchor = lab.kind === 'text' ? lab.p : lab.kind === 'half' ? lab.b : [(lab.a[0] + lab.b[0]) / 2, (lab.a[1] + lab.b[1]) / 2];
  const X = at.sx * anchor[0];
  const Y = -at.sy * anchor[1];
  const rel = (x0, y0, x1, y1) => out.push({ x: anchor[0], y: anchor[1], l: x0 - X, r: x1 - X, t: y0 - Y, b: y1 - Y });
  rel(...lab.at.box);
  if (lab.kind === 'text') return;
  // The line's ends, with room for arrowheads and extension lines.
  for (const [p, q] of dimSegments(lab, dimFrame(lab, at), lab.at)) for (const e of [p, q]) rel(e[0] - 4, e[1] - 4, e[0] + 4, e[1] + 4);
}

/**
 * The largest scale s ≥ 0 at which every element, at coordinate c·s plus its
 * pixel extent [lo, hi], spans at most `avail` pixels; 0 when even s = 0 does
 * not fit. The span is a convex function of s, so the scales that fit are an
 * interval from 0.
 */
function maxScale(els, c, lo, hi, avail) {
  const span = (s) => {
    let a = Infinity;
    let b = -Infinity;
    for (const e of els) {
      const v = s * c(e);
      if (v + lo(e) < a) a = v + lo(e);
      if (v + hi(e) > b) b = v + hi(e);
    }
    return b - a;
  };
  if (span(0) > avail) return 0;
  let cmin = Infinity;
  let cmax = -Infinity;
  for (const e of els) {
    cmin = Math.min(cmin, c(e));
    cmax = Math.max(cmax, c(e));
  }
  let top = avail / Math.max(cmax - cmin, 1e-12);
  if (span(top) <= avail) return top;
  let bottom = 0;
  for (let k = 0; k < 48; k++) {
    const m = (bottom + top) / 2;
    if (span(m) <= avail) bottom = m;
    else top = m;
  }
  return bottom;
}

/**
 * The world→screen transform {sx, sy, tx, ty} (X = tx + sx·x, Y = ty − sy·y)
 * that fits the world rectangle `focus` [x0, y0, x1, y1] and every label of
 * `labels` (those anchored near the focus) into `width` × `height`, each
 * label where placement would put it in a view without bounds (so away from
 * the drawing's lines (`lineIndex`) where it can be). With `stretch`, the vertical
 * scale may exceed the horizontal one to fill the height.
 */
export function fitLabels(focus, labels, width, height, stretch, lines = null) {
  const [x0, y0, x1, y1] = focus;
  const w = Math.max(x1 - x0, 1e-9);
  const h = Math.max(y1 - y0, 1e-9);
  const P = GEOMETRY_PAD;
  const geometry = [
    { x: x0, y: y0, l: -P, r: P, t: -P, b: P },
    { x: x1, y: y1, l: -P, r: P, t: -P, b: P },
  ];
  const aw = Math.max(width - 2 * EDGE, 10);
  const ah = Math.max(height - 2 * EDGE, 10);
  const iso = Math.max(Math.min((aw - 2 * P) / w, (ah - 2 * P) / h), 1e-12);
  // Labels whose point is far from the focus (a note at the end of distant motions) do not widen the fit.
  const gx = 0.25 * Math.max(w, h);
  const near = (p) => p[0] >= x0 - gx && p[0] <= x1 + gx && p[1] >= y0 - gx && p[1] <= y1 + gx;
  let set = labels
    .filter((l) => (l.kind === 'text' ? near(l.p) : l.kind === 'half' ? near(l.b) : near([(l.a[0] + l.b[0]) / 2, (l.a[1] + l.b[1]) / 2])))
    .map((l) => ({ ...l }))
    .sort((p, q) => p.prio - q.prio);
  let xf = { sx: iso, sy: stretch ? Math.max(iso, (ah - 2 * P) / h) : iso, tx: 0, ty: 0 };
  const elements = () => {
    const els = [...geometry];
    placeLabels(set, xf, { all: true }, lines);
    for (const l of set) if (l.at) fitElements(l, xf, els);
    return els;
  };
  for (let round = 0; round < 4; round++) {
    const els = elements();
    const sxh = maxScale(els, (e) => e.x, (e) => e.l, (e) => e.r, aw);
    const syv = maxScale(els, (e) => -e.y, (e) => e.t, (e) => e.b, ah);
    let s = Math.min(sxh, syv);
    // Labels that would shrink the drawing below a third of its size are
    // left to placement (which moves or drops them), the least important first.
    if (s < iso / 3 && set.some((l) => !l.must)) {
      const drop = set.findLastIndex((l) => !l.must);
      set = set.filter((_, k) => k !== drop);
      round--;
      continue;
    }
    s = Math.max(s, iso / 3);
    xf = { sx: s, sy: stretch ? Math.max(s, syv) : s, tx: 0, ty: 0 };
  }
  // Centre the whole: geometry and labels.
  const els = elements();
  let xa = Infinity;
  let xb = -Infinity;
  let ya = Infinity;
  let yb = -Infinity;
  for (const e of els) {
    xa = Math.min(xa, xf.sx * e.x + e.l);
    xb = Math.max(xb, xf.sx * e.x + e.r);
    ya = Math.min(ya, -xf.sy * e.y + e.t);
    yb = Math.max(yb, -xf.sy * e.y + e.b);
  }
  xf.tx = (width - xa - xb) / 2;
  xf.ty = (height - ya - yb) / 2;
  return xf;
}
