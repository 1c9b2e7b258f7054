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
// Boxes are [x0, y0, x1, y1] in CSS pixels of the view; the canvas and its
// PNG draw a label in the box placed here, and the SVG export is given the
// boxes (src/svg.rs, which ports these rules for the command line). A text
// wider than about half its view is wrapped (`wrap`) before it is placed.
// Each label's screen frame and candidates are candidates.js's, the index of
// the drawing's lines lineindex.js's.

import { LINE, EDGE, dimFrame, textFrame, boxAt, dimCandidates, textCandidates, stackTexts } from './candidates.js';
import { lineIndex, segmentHitsBox, segmentsClash } from './lineindex.js';

export { LINE, EDGE, lineIndex };

/** The geometry keeps this far from the view's edges. */
export const GEOMETRY_PAD = 16;

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
