// Scene rendering shared by the canvas views and the PNG export.
//
// A scene comes from the wasm core as typed arrays (see src/wasm/pack.rs):
// `items` holds one record of `stride` u32s per item, `coords` the numbers of
// each shape, `lines` the source lines, `labels` the label records. The
// record layout is defined once in Rust and read here by name
// (`setLayout(core.scene_layout())` before the first scene). Rendering walks
// the arrays directly; a painter (canvas.js) draws screen-space primitives.
// Label placement is labels.js's, the pens are pens.js's. The SVG export is
// the core's writer (src/svg.rs), given the transform and the labels as
// drawScene placed them.

import { label as labelRecord, placeLabels, fitLabels, frameOf, lineIndex, wrap, LINE } from './labels.js';
import { PENS, ROLE_STROKE, HIGHLIGHT, HIGHLIGHT_HALO, textWidth, areaColour, greyPen } from './pens.js';

export { textWidth };

/** The record layout: `stride`, field offsets by name, shape codes by name, anchor names. */
let STRIDE = 10;
let F = null;
let SHAPE = null;
let ANCHORS = null;

/** Takes the scene record layout served by the core (`scene_layout()`). */
export function setLayout(layout) {
  STRIDE = layout.stride;
  F = { ...layout.fields };
  SHAPE = Object.fromEntries(layout.shapes.map((name, i) => [name, i]));
  ANCHORS = [...layout.anchors];
}

/** The layout taken by `setLayout` (field offsets by name and the stride). */
export function layout() {
  if (!F) throw new Error('render.js: setLayout(core.scene_layout()) was not called');
  return { stride: STRIDE, ...F };
}
/** Above this many threads with dimensions, only the chosen thread's are drawn. */
export const MAX_ANNOTATED = 6;


/** Decodes the label records once per scene. */
export function prepare(scene, styleNames) {
  if (scene.prepared) return scene;
  layout();
  const labels = scene.labels.length ? scene.labels.split('\u001e').map((r) => r.split('\u001f')) : [];
  const n = scene.items.length / STRIDE;
  const styles = new Array(n);
  for (let i = 0; i < n; i++) styles[i] = styleNames[scene.items[i * STRIDE + F.style]];
  // Threads that carry dimensions and texts: many of them are drawn for the chosen thread only.
  const annotated = new Set();
  for (let i = 0; i < n; i++) {
    const o = i * STRIDE;
    const shape = scene.items[o + F.shape];
    if ((shape === SHAPE.dim || shape === SHAPE.text) && scene.items[o + F.thread]) annotated.add(scene.items[o + F.thread]);
  }
  scene.prepared = { labels, styles, count: n, annotated: annotated.size, layout: layout() };
  return scene;
}

/** Indices of the items drawn from source `line` (a scan of the typed arrays). */
export function itemsOfLine(scene, line) {
  const it = scene.items;
  const lines = scene.lines;
  const out = [];
  for (let o = 0, i = 0; o < it.length; o += STRIDE, i++) {
    for (let k = it[o + F.line_start], e = k + it[o + F.line_len]; k < e; k++) {
      if (lines[k] === line) {
        out.push(i);
        break;
      }
    }
  }
  return out;
}

/** Indices of the items of pass `pass` of thread `thread`. */
export function itemsOfPass(scene, thread, pass) {
  const it = scene.items;
  const out = [];
  for (let o = 0, i = 0; o < it.length; o += STRIDE, i++) if (it[o + F.thread] === thread + 1 && it[o + F.pass] === pass + 1) out.push(i);
  return out;
}

/** Facts about item `i`: thread, pass (or -1), role and source lines. */
export function itemInfo(scene, i) {
  const it = scene.items;
  const o = i * STRIDE;
  const lines = Array.from(scene.lines.subarray(it[o + F.line_start], it[o + F.line_start] + it[o + F.line_len]));
  return { thread: it[o + F.thread] - 1, pass: it[o + F.pass] - 1, lines, style: scene.prepared.styles[i] };
}

/**
 * The world→screen transform (X = tx + sx·x, Y = ty − sy·y) that fits the
 * scene's focus and the labels drawn with `opts` (tr, styleNames, thread)
 * into `width` × `height`; `stretch` lets the vertical scale exceed the horizontal.
 */
export function fitScene(scene, width, height, stretch, opts) {
  return fitLabels(scene.focus, sceneLabels(scene, opts), width, height, stretch, sceneLines(scene));
}

/** Most of the drawing's segments labels keep off (those of threads and passes first). */
const MAX_AVOIDED = 20000;
/** Styles whose lines labels may cross: centre lines and filled zones. */
const CROSSABLE = new Set(['axis', 'thread_zone', 'delta1', 'delta2']);

/**
 * The drawing's lines that labels keep off (paths, arrows and circles), as an
 * index (labels.js `lineIndex`) kept with the scene.
 */
export function sceneLines(scene) {
  const pr = scene.prepared;
  if (pr.lines) return pr.lines;
  const { items, coords } = scene;
  // Segments of each item (polygons closed, circles as 24 chords), threads' items first.
  const segments = (i) => {
    const o = i * STRIDE;
    if (CROSSABLE.has(pr.styles[i])) return 0;
    const shape = items[o + F.shape];
    const n = items[o + F.coord_len];
    if (shape === SHAPE.polyline || shape === SHAPE.arrow) return Math.max(0, n / 2 - 1);
    if (shape === SHAPE.polygon) return n >= 6 ? n / 2 : Math.max(0, n / 2 - 1);
    return shape === SHAPE.circle ? 24 : 0;
  };
  const order = [];
  for (const ofThreads of [true, false]) for (let i = 0; i < pr.count; i++) if (!items[i * STRIDE + F.thread] === !ofThreads) order.push(i);
  let total = 0;
  for (const i of order) total += segments(i);
  const out = new Float64Array(4 * Math.min(total, MAX_AVOIDED));
  let m = 0;
  const put = (a, b, c, d) => {
    if (m + 4 > out.length) return false;
    out[m++] = a;
    out[m++] = b;
    out[m++] = c;
    out[m++] = d;
    return true;
  };
  for (const i of order) {
    if (!segments(i)) continue;
    const o = i * STRIDE;
    const shape = items[o + F.shape];
    const c = items[o + F.coord_start];
    const n = items[o + F.coord_len];
    let room = true;
    if (shape === SHAPE.circle) {
      const [x, y, r] = [coords[c], coords[c + 1], coords[c + 2]];
      for (let k = 0; k < 24 && room; k++) room = put(x + r * Math.cos((k * Math.PI) / 12), y + r * Math.sin((k * Math.PI) / 12), x + r * Math.cos(((k + 1) * Math.PI) / 12), y + r * Math.sin(((k + 1) * Math.PI) / 12));
    } else {
      for (let k = 0; k + 3 < n && room; k += 2) room = put(coords[c + k], coords[c + k + 1], coords[c + k + 2], coords[c + k + 3]);
      if (room && shape === SHAPE.polygon && n >= 6) room = put(coords[c + n - 2], coords[c + n - 1], coords[c], coords[c + 1]);
    }
    if (!room) break;
  }
  pr.lines = lineIndex(out.subarray(0, m), scene.focus);
  return pr.lines;
}

/**
 * The label records (labels.js) of the dimensions and texts drawn of
 * `scene` with `opts`: with many threads, only the chosen thread's.
 */
export function sceneLabels(scene, opts) {
  prepare(scene, opts.styleNames);
  const { items, coords } = scene;
  const { styles, count, annotated } = scene.prepared;
  const chosen = (opts.thread ?? 0) + 1;
  const only = annotated > MAX_ANNOTATED ? chosen : 0;
  const wrapAt = opts.width > 0 ? Math.max(0.45 * opts.width, 160) : Infinity;
  const out = [];
  for (let i = 0; i < count; i++) {
    const o = i * STRIDE;
    const shape = items[o + F.shape];
    if (shape !== SHAPE.dim && shape !== SHAPE.text) continue;
    const thread = items[o + F.thread];
    if (only && thread && thread !== only) continue;
    const idx = items[o + F.label];
    const text = labelText(scene, idx, opts.tr);
    if (!text && shape === SHAPE.text) continue;
    const key = scene.prepared.labels[idx - 1]?.[0] ?? '';
    const c = items[o + F.coord_start];
    const common = { i, key, text, w: text ? textWidth(text) : 0, chosen: !thread || annotated <= 1 || thread === chosen };
    if (shape === SHAPE.dim) {
      out.push(
        labelRecord({
          ...common,
          kind: styles[i] === 'diameter' ? 'half' : 'dim',
          a: [coords[c], coords[c + 1]],
          b: [coords[c + 2], coords[c + 3]],
          offset: coords[c + 4],
        }),
      );
    } else {
      // A text wider than about half the view goes on several lines.
      const lines = wrap(text, wrapAt, textWidth);
      if (lines) common.w = Math.max(...lines.map(textWidth));
      out.push(labelRecord({ ...common, lines, kind: 'text', p: [coords[c], coords[c + 1]], dx: coords[c + 2], dy: coords[c + 3], anchor: ANCHORS[items[o + F.extra]] || 'start' }));
    }
  }
  return out;
}

function labelText(scene, idx, tr) {
  const rec = scene.prepared.labels[idx - 1];
  if (!rec) return '';
  const [key, value] = rec;
  return key ? tr(key, value) : value;
}

/** Buffers kept between draws: screen points, the table of kept paths (cleared) and each path's batch. */
const kept = { screen: new Float64Array(1024), slots: new Int32Array(1024), batchOf: new Int32Array(512) };

/** The kept buffers, grown to `coords` numbers and `count` items, the table cleared. */
function scratch(coords, count) {
  if (kept.screen.length < coords) kept.screen = new Float64Array(Math.max(coords, 2 * kept.screen.length));
  if (kept.batchOf.length < count) kept.batchOf = new Int32Array(Math.max(count, 2 * kept.batchOf.length));
  let size = 1024;
  while (size < 2 * count) size *= 2;
  if (kept.slots.length < size) kept.slots = new Int32Array(size);
  else kept.slots.fill(0, 0, size);
  return { screen: kept.screen, slots: size === kept.slots.length ? kept.slots : kept.slots.subarray(0, size), batchOf: kept.batchOf };
}

/**
 * Draws `scene` with `painter` under transform `xf`.
 * opts: { tr(key, value), styleNames, highlight: Set<item index> | null, light
 *   (the cursor line's lighter mark), thread (the chosen one), stale, width,
 *   height, cull (skip paths outside width × height) }
 * Returns the labels as placed: {placed: [{item, key, text, lines (as drawn), align (of the lines in the box), box, angle, must,
 *   off (a dimension line's offset), len (a half dimension's line), lead (a text's leader)}], dropped: [{item, key, text}]}
 *   (what the SVG writer takes as the labels of a layout, src/svg.rs `Placed`).
 */
export function drawScene(painter, scene, xf, opts) {
  prepare(scene, opts.styleNames);
  const { items, coords } = scene;
  const { styles, count } = scene.prepared;
  const X = (x) => xf.tx + xf.sx * x;
  const Y = (y) => xf.ty - xf.sy * y;
  const hi = opts.highlight && opts.highlight.size && !opts.stale ? opts.highlight : null;
  // The cursor line's mark is lighter than what the pointer is over.
  const haloAlpha = opts.light ? 0.3 : 0.5;
  // Labels first: where each goes, or whether it is dropped, at this transform.
  const labels = sceneLabels(scene, opts);
  placeLabels(labels, xf, { w: opts.width || 1e6, h: opts.height || 1e6 }, sceneLines(scene));
  const labelOf = new Map();
  for (const l of labels) labelOf.set(l.i, l);
  const colourPen = (i) => {
    const o = i * STRIDE;
    const shape = items[o + F.shape];
    const base = PENS[styles[i]] || PENS.note;
    const role = shape <= SHAPE.arrow ? items[o + F.extra] : 0;
    if (styles[i] === 'area') return { ...base, fill: areaColour(items[o + F.pass] - 1, role) };
    if (role >= 2 && ROLE_STROKE[role] && base.stroke) return { ...base, stroke: ROLE_STROKE[role] };
    return base;
  };
  const penOf = opts.stale ? (i) => greyPen(colourPen(i)) : colourPen;
  const haloPen = (pen) => ({ stroke: HIGHLIGHT, width: (pen.width || 1) + (opts.light ? 4 : 6), alpha: haloAlpha });
  /** The screen points of a path item. */
  const pathPoints = (c, n) => {
    const pts = new Float64Array(n);
    for (let k = 0; k < n; k += 2) {
      pts[k] = X(coords[c + k]);
      pts[k + 1] = Y(coords[c + k + 1]);
    }
    return pts;
  };
  /**
   * Highlights: halos beneath the items, which keep their own colours on
   * top. The halos of one width are one stroke (their union, at one alpha):
   * halos of close lines do not pile up into a solid colour between them.
   */
  const drawHalos = (set) => {
    const groups = new Map();
    const add = (closed, width, pts) => {
      const key = `${closed}:${width}`;
      let g = groups.get(key);
      if (!g) groups.set(key, (g = { closed, width, pts: [], spans: [] }));
      g.spans.push(g.pts.length, pts.length);
      for (const v of pts) g.pts.push(v);
    };
    const fills = [];
    for (const i of set) {
      if (i >= count) continue;
      const o = i * STRIDE;
      const shape = items[o + F.shape];
      const pen = penOf(i);
      const c = items[o + F.coord_start];
      const n = items[o + F.coord_len];
      const width = haloPen(pen).width;
      switch (shape) {
        case SHAPE.polyline:
        case SHAPE.polygon:
          add(shape === SHAPE.polygon, width, pathPoints(c, n));
          break;
        case SHAPE.arrow:
          add(false, width, [X(coords[c]), Y(coords[c + 1]), X(coords[c + 2]), Y(coords[c + 3])]);
          break;
        case SHAPE.circle:
          painter.circle(X(coords[c]), Y(coords[c + 1]), coords[c + 2] * xf.sx, haloPen(pen));
          break;
        case SHAPE.marker:
          fills.push([X(coords[c]), Y(coords[c + 1])]);
          break;
        case SHAPE.dim:
        case SHAPE.text: {
          const l = labelOf.get(i);
          if (!l || !l.at) break;
          const [x0, y0, x1, y1] = l.at.box;
          painter.path(new Float64Array([x0 - 1, y0, x1 + 1, y0, x1 + 1, y1, x0 - 1, y1]), true, { fill: HIGHLIGHT, alpha: haloAlpha });
          if (shape === SHAPE.dim) for (const [p, q] of dimLines(l, xf)) add(false, width, [p[0], p[1], q[0], q[1]]);
          break;
        }
      }
    }
    for (const g of groups.values()) painter.paths(Float64Array.from(g.pts), g.spans, g.closed, { stroke: HIGHLIGHT, width: g.width, alpha: haloAlpha });
    for (const [x, y] of fills) painter.circle(x, y, 6, { fill: HIGHLIGHT, alpha: haloAlpha });
  };
  const drawItem = (i) => {
    const o = i * STRIDE;
    const shape = items[o + F.shape];
    const pen = penOf(i);
    const c = items[o + F.coord_start];
    switch (shape) {
      case SHAPE.polyline:
      case SHAPE.polygon:
        painter.path(pathPoints(c, items[o + F.coord_len]), shape === SHAPE.polygon, pen);
        break;
      case SHAPE.circle:
        painter.circle(X(coords[c]), Y(coords[c + 1]), coords[c + 2] * xf.sx, pen);
        break;
      case SHAPE.arrow:
        arrow(painter, X(coords[c]), Y(coords[c + 1]), X(coords[c + 2]), Y(coords[c + 3]), pen);
        break;
      case SHAPE.dim:
      case SHAPE.text: {
        const l = labelOf.get(i);
        if (!l || !l.at) break;
        const halo = hi && hi.has(i) ? HIGHLIGHT_HALO[opts.light ? 1 : 0] : true;
        if (shape === SHAPE.dim) dimension(painter, l, xf, pen);
        else if (l.at.lead) painter.path(new Float64Array(l.at.lead), false, { stroke: pen.stroke || pen.text, width: 0.7, alpha: 0.8 });
        if (l.lines) {
          // Lines of a wrapped text line up on the side of its point.
          const [x0, , x1] = l.at.box;
          const x = l.anchor === 'start' ? x0 + 2 : l.anchor === 'end' ? x1 - 2 : l.at.cx;
          l.lines.forEach((line, k) => painter.text(x, l.at.cy + (k - (l.lines.length - 1) / 2) * LINE, line, { ...pen, halo }, l.anchor, 'middle', 0));
        }
        else if (l.text) painter.text(l.at.cx, l.at.cy, l.text, { ...pen, halo }, 'middle', 'middle', l.at.angle);
        break;
      }
      case SHAPE.marker:
        marker(painter, X(coords[c]), Y(coords[c + 1]), items[o + F.extra], pen);
        break;
    }
  };
  painter.begin(opts.stale);
  // Highlights go beneath everything: they mark without covering.
  if (hi) drawHalos(hi);
  // Paths of one pen are drawn together (one stroke or fill per pen), in the
  // order the pens first appear; the other shapes follow, in item order.
  // A path that repeats one already in its batch (to 1/8 px on screen) adds
  // no ink and is dropped: a stroke or fill of one path covers its pixels
  // once, and a dash pattern restarts on every subpath. With `opts.cull`,
  // paths wholly outside the view (plus a margin for pens) are dropped too.
  const batches = new Map();
  const order = [];
  const rest = [];
  const cull = opts.cull && opts.width > 0 && opts.height > 0;
  const M = 12;
  const right = opts.width + M;
  const bottom = opts.height + M;
  // Screen points of every path, in one buffer; a batch lists [start, length] spans of it.
  // Kept paths are found again through an open-addressing table of item indices.
  const tables = scratch(coords.length, count);
  const buf = tables.screen;
  const { slots, batchOf } = tables;
  const mask = slots.length - 1;
  for (let i = 0; i < count; i++) {
    const o = i * STRIDE;
    const shape = items[o + F.shape];
    if (shape !== SHAPE.polyline && shape !== SHAPE.polygon) {
      rest.push(i);
      continue;
    }
    const c = items[o + F.coord_start];
    const n = items[o + F.coord_len];
    let x0 = Infinity;
    let y0 = Infinity;
    let x1 = -Infinity;
    let y1 = -Infinity;
    let h = 0x811c9dc5;
    for (let k = 0; k < n; k += 2) {
      const x = X(coords[c + k]);
      const y = Y(coords[c + k + 1]);
      buf[c + k] = x;
      buf[c + k + 1] = y;
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
      h = Math.imul(h ^ Math.round(x * 8), 0x01000193);
      h = Math.imul(h ^ Math.round(y * 8), 0x01000193);
    }
    if (cull && (x1 < -M || y1 < -M || x0 > right || y0 > bottom)) continue;
    const style = styles[i];
    const role = items[o + F.extra];
    // A pen per style, role and shape; area fills also per pass (a colour each).
    const key = style === 'area' ? `area:${items[o + F.thread]}:${items[o + F.pass]}:${role}` : (items[o + F.style] * 8 + role) * 8 + shape;
    let b = batches.get(key);
    if (!b) {
      b = { id: order.length, first: i, spans: [] };
      batches.set(key, b);
      order.push(b);
    }
    batchOf[i] = b.id;
    // A repeat is a path of the same batch with the same points to 1/8 px; the hash finds candidates.
    let slot = (h ^ Math.imul(b.id + 1, 0x9e3779b1)) & mask;
    let repeat = false;
    for (let j = slots[slot]; j !== 0; slot = (slot + 1) & mask, j = slots[slot]) {
      const q = (j - 1) * STRIDE;
      if (batchOf[j - 1] === b.id && items[q + F.coord_len] === n && samePoints(buf, items[q + F.coord_start], c, n)) {
        repeat = true;
        break;
      }
    }
    if (repeat) continue;
    slots[slot] = i + 1;
    b.spans.push(c, n);
  }
  for (const b of order) {
    const o = b.first * STRIDE;
    painter.paths(buf, b.spans, items[o + F.shape] === SHAPE.polygon, penOf(b.first));
  }
  for (const i of rest) drawItem(i);
  if (hi && !opts.light) {
    // What the pointer is over also comes to the front: its lines in their
    // own pens, a filled area outlined (a second fill would change its colour).
    for (const i of hi) {
      if (i >= count) continue;
      const o = i * STRIDE;
      const shape = items[o + F.shape];
      if (shape === SHAPE.polygon) painter.path(pathPoints(items[o + F.coord_start], items[o + F.coord_len]), true, { stroke: HIGHLIGHT, width: 1.5 });
      else if (shape === SHAPE.polyline || shape === SHAPE.arrow || shape === SHAPE.marker) drawItem(i);
    }
  }
  painter.end();
  const placed = [];
  const dropped = [];
  for (const l of labels) {
    if (l.at) placed.push({ item: l.i, key: l.key, text: l.text, lines: l.lines || [l.text], align: l.lines ? l.anchor : 'middle', box: l.at.box.map((v) => Math.round(v * 100) / 100), angle: l.at.angle, must: l.must, off: l.at.off ?? 0, len: l.at.len ?? 0, lead: l.at.lead ?? null });
    else dropped.push({ item: l.i, key: l.key, text: l.text });
  }
  return { placed, dropped };
}

/** Whether the `n` numbers at `a` and at `c` of `buf` agree to 1/8 px. */
function samePoints(buf, a, c, n) {
  for (let k = 0; k < n; k++) if (Math.round(buf[a + k] * 8) !== Math.round(buf[c + k] * 8)) return false;
  return true;
}

function arrow(p, x0, y0, x1, y1, pen) {
  p.path(new Float64Array([x0, y0, x1, y1]), false, pen);
  const a = Math.atan2(y1 - y0, x1 - x0);
  const L = 9;
  const s = 0.42;
  p.path(new Float64Array([x1 - L * Math.cos(a - s), y1 - L * Math.sin(a - s), x1, y1, x1 - L * Math.cos(a + s), y1 - L * Math.sin(a + s)]), true, { ...pen, fill: pen.stroke, dash: null });
}

function marker(p, x, y, glyph, pen) {
  const stroke = pen.stroke || '#374151';
  if (glyph === 0) p.circle(x, y, 3, { fill: stroke });
  else if (glyph === 1) p.path(new Float64Array([x, y - 6, x, y + 6]), false, { stroke, width: 2 });
  else p.path(new Float64Array([x - 4, y - 4, x + 4, y + 4, x - 4, y + 4, x + 4, y - 4]), false, { stroke, width: 1.6, segments: true });
}

/** The lines a placed dimension label `l` draws: [[p, q], …] in pixels (its line first). */
function dimLines(l, xf) {
  const fr = frameOf(l, xf);
  const { A, B, n, u, sgn } = fr;
  const o = l.at.off;
  const ext = (P) => [
    [P[0] + n[0] * 2 * sgn, P[1] + n[1] * 2 * sgn],
    [P[0] + n[0] * (o + 4 * sgn), P[1] + n[1] * (o + 4 * sgn)],
  ];
  if (l.kind === 'half') {
    const S = l.at.S;
    const line = [S, [S[0] - u[0] * l.at.len, S[1] - u[1] * l.at.len]];
    return Math.abs(o) > 3 ? [line, ext(B)] : [line];
  }
  const line = [
    [A[0] + n[0] * o, A[1] + n[1] * o],
    [B[0] + n[0] * o, B[1] + n[1] * o],
  ];
  return Math.abs(o) > 3 ? [line, ext(A), ext(B)] : [line];
}

/**
 * A dimension placed by labels.js: extension lines, its line with arrows.
 * A half dimension (of a diameter, from the axis) has one arrowhead, at the
 * feature, and its line runs towards the axis as far as its text needs.
 */
function dimension(p, l, xf, pen) {
  const fr = frameOf(l, xf);
  const [line, ...exts] = dimLines(l, xf);
  const thin = { stroke: pen.stroke, width: 0.8 };
  for (const [a, b] of exts) p.path(new Float64Array([a[0], a[1], b[0], b[1]]), false, thin);
  const [[x0, y0], [x1, y1]] = line;
  p.path(new Float64Array([x0, y0, x1, y1]), false, pen);
  const { n, u } = fr;
  const head = (x, y, dir) => {
    const L = 7;
    const W = 2.6;
    const bx2 = x - u[0] * L * dir;
    const by2 = y - u[1] * L * dir;
    p.path(new Float64Array([x, y, bx2 + n[0] * W, by2 + n[1] * W, bx2 - n[0] * W, by2 - n[1] * W]), true, { fill: pen.stroke });
  };
  if (l.kind === 'half') {
    head(x0, y0, 1);
    return;
  }
  if (Math.hypot(x1 - x0, y1 - y0) > 20) {
    head(x0, y0, -1);
    head(x1, y1, 1);
  } else {
    head(x0, y0, 1);
    head(x1, y1, -1);
  }
}

/** Distance from (px, py) to the nearest part of item `i`, in screen pixels (Infinity if far). */
export function itemDistance(scene, i, xf, px, py) {
  const { items, coords } = scene;
  const o = i * STRIDE;
  const shape = items[o + F.shape];
  const c = items[o + F.coord_start];
  const n = items[o + F.coord_len];
  const X = (x) => xf.tx + xf.sx * x;
  const Y = (y) => xf.ty - xf.sy * y;
  if (shape === SHAPE.polyline || shape === SHAPE.polygon) {
    let best = Infinity;
    let inside = false;
    const m = n / 2;
    for (let k = 0; k < m; k++) {
      const j = shape === SHAPE.polygon ? (k + 1) % m : k + 1;
      if (j >= m) break;
      const x0 = X(coords[c + 2 * k]);
      const y0 = Y(coords[c + 2 * k + 1]);
      const x1 = X(coords[c + 2 * j]);
      const y1 = Y(coords[c + 2 * j + 1]);
      best = Math.min(best, segDist(px, py, x0, y0, x1, y1));
      if (shape === SHAPE.polygon && (y0 > py) !== (y1 > py) && px < ((x1 - x0) * (py - y0)) / (y1 - y0) + x0) inside = !inside;
    }
    return inside ? 0 : best;
  }
  if (shape === SHAPE.marker) return Math.hypot(px - X(coords[c]), py - Y(coords[c + 1]));
  if (shape === SHAPE.arrow) return segDist(px, py, X(coords[c]), Y(coords[c + 1]), X(coords[c + 2]), Y(coords[c + 3]));
  return Infinity;
}

function segDist(px, py, x0, y0, x1, y1) {
  const dx = x1 - x0;
  const dy = y1 - y0;
  const l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((px - x0) * dx + (py - y0) * dy) / l2 : 0;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(px - (x0 + t * dx), py - (y0 + t * dy));
}
