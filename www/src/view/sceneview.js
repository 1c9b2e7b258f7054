// A view of one drawing on a canvas — an OffscreenCanvas in the drawing
// worker, or a page canvas where there is none — without touching the DOM:
// its size, pointer and keys come from whoever shows it (input.js binds a
// page canvas; the worker gets them as messages). What it draws is the
// core's display list for its size, transform and mark (`session.draw`),
// painted as given (paint.js); it keeps only the numbers of the view: size,
// zoom and pan, the mark, whether it follows the fit.

import { paint } from './paint.js';

/** The next frame: the window's or the worker's animation frame, else a timer. */
const nextFrame = (f) => (typeof globalThis.requestAnimationFrame === 'function' ? globalThis.requestAnimationFrame(f) : setTimeout(f, 16));

export class SceneView {
  /**
   * @param {HTMLCanvasElement | OffscreenCanvas} canvas
   * @param {{session: object, name: string, stretch?: boolean, onDrawn?: Function}} opts
   *   `session`: the wasm Session whose scenes it shows; `onDrawn(view)` is called after each draw.
   */
  constructor(canvas, opts) {
    this.canvas = canvas;
    this.opts = opts;
    this.name = opts.name;
    this.key = null; // the key of the scene shown (null: none)
    this.stale = false;
    this.xf = null; // [sx, sy, tx, ty]; null: fit at the next draw
    this.auto = true; // refit on every new scene until the user pans or zooms
    this.stretch = !!opts.stretch;
    this.mark = { thread: -1, pass: -1, lines: [], light: false };
    this.hovered = null;
    this.cssW = 1;
    this.cssH = 1;
    this.lastDraw = 0;
    this.lastPaint = 0; // of lastDraw, the milliseconds the canvas calls took (the rest: the core's display list)
    this.drawTime = 0; // milliseconds spent drawing since the owner last zeroed it
    this.list = null; // the display list of the last draw
  }

  /** The size shown, in CSS pixels, and the device pixel ratio. */
  setSize(cssW, cssH, dpr = 1) {
    const w = Math.max(1, Math.round(cssW * dpr));
    const h = Math.max(1, Math.round(cssH * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
    this.cssW = Math.max(cssW, 1);
    this.cssH = Math.max(cssH, 1);
    if (this.auto) this.xf = null;
    this.draw();
  }

  /** The session shows another scene in this view (`key`, null for none; `stale`: greyed); the same again draws nothing. */
  setShown(key, stale) {
    if (key === this.key && !!stale === this.stale) return;
    const first = this.key === null;
    this.key = key;
    this.stale = !!stale;
    if (this.auto || first) this.xf = null;
    this.hovered = null;
    this.draw();
  }

  /** The labels' words or the chosen thread changed: a fit makes room for them. */
  relabel() {
    if (this.auto) this.xf = null;
    this.draw();
  }

  fit() {
    this.auto = true;
    this.xf = null;
    this.draw();
  }

  toggleStretch() {
    this.stretch = !this.stretch;
    this.fit();
    return this.stretch;
  }

  /** The transform shown (`{sx, sy, tx, ty}`), drawn first if a fit is pending; null with nothing shown. */
  transform() {
    if (!this.xf && this.key !== null) this.drawNow();
    const t = this.xf;
    return t ? { sx: t[0], sy: t[1], tx: t[2], ty: t[3] } : null;
  }

  /** Moves the drawing by (dx, dy) CSS pixels. */
  pan(dx, dy) {
    if (!this.transform()) return;
    this.xf[2] += dx;
    this.xf[3] += dy;
    this.auto = false;
    this.draw();
  }

  /** Zooms by `k` around (px, py) in CSS pixels; without a point, around the list's anchor (what is marked, else the drawing's middle). */
  zoomAt(px, py, k) {
    if (!this.transform() || !(k > 0) || !Number.isFinite(k)) return;
    if (!Number.isFinite(px) || !Number.isFinite(py)) [px, py] = this.list ? this.list.anchor : [this.cssW / 2, this.cssH / 2];
    const t = this.xf;
    t[2] = px - (px - t[2]) * k;
    t[3] = py - (py - t[3]) * k;
    t[0] *= k;
    t[1] *= k;
    this.auto = false;
    this.draw();
  }

  /** Marks a pass (`{thread, pass}`) or source lines (`{lines}`), `light` for the editor cursor's mark; the same again draws nothing. */
  setMark(m, light = false) {
    const next = { thread: m && m.pass >= 0 ? m.thread : -1, pass: m && m.pass >= 0 ? m.pass : -1, lines: m && !(m.pass >= 0) ? m.lines || [] : [], light };
    const same = (a, b) => a.thread === b.thread && a.pass === b.pass && a.light === b.light && a.lines.length === b.lines.length && a.lines.every((l, i) => l === b.lines[i]);
    if (same(next, this.mark)) return;
    this.mark = next;
    this.draw();
  }

  /** Draws at the next frame (several changes in one task draw once). */
  draw() {
    if (this.queued) return;
    this.queued = true;
    nextFrame(() => {
      if (!this.queued) return; // drawn already by flush()
      this.queued = false;
      this.drawNow();
    });
  }

  /** Draws now what draw() queued (a worker's canvas shows it when the task ends). */
  flush() {
    if (!this.queued) return;
    this.queued = false;
    this.drawNow();
  }

  /** The core's display list of this view at `scale` (its mark left out when `bare`). */
  displayList(bare = false) {
    const m = bare ? { thread: -1, pass: -1, lines: [], light: false } : this.mark;
    return this.opts.session.draw(this.name, this.cssW, this.cssH, this.xf ? Float64Array.from(this.xf) : undefined, this.stretch, m.thread, m.pass, Uint32Array.from(m.lines), m.light);
  }

  /**
   * Draws the view's display list now. A session that cannot answer (after
   * a planner failure) leaves what is on the canvas as it is.
   */
  drawNow() {
    const t0 = performance.now();
    let list = null;
    try {
      list = this.key === null ? null : this.displayList();
    } catch {
      this.opts.onDrawn?.(this);
      return;
    }
    const ctx = this.canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.list = list;
    if (list) {
      this.xf = Array.from(list.transform);
      const dpr = this.canvas.width / this.cssW;
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const t1 = performance.now();
      paint(ctx, list);
      this.lastPaint = performance.now() - t1;
    }
    this.lastDraw = performance.now() - t0;
    this.drawTime += this.lastDraw;
    this.opts.onDrawn?.(this);
  }

  /** The labels of the last draw as placed (boxes in CSS pixels), how many were left out, and the view's size. */
  labels() {
    if (this.queued || (!this.list && this.key !== null)) this.drawNow();
    return { size: [this.cssW, this.cssH], placed: this.list ? this.list.labels : [], dropped: this.list ? this.list.dropped : 0 };
  }

  /** The SVG document of what the view shows (the same display list, without the mark). */
  svg() {
    if (!this.transform()) return null;
    return this.opts.session.svg(this.name, this.cssW, this.cssH, Float64Array.from(this.xf), this.stretch);
  }

  /** What the view shows as a PNG blob at `scale` × the shown size (without the mark). */
  async toPNG(scale = 2) {
    if (!this.transform()) return null;
    const w = Math.round(this.cssW * scale);
    const h = Math.round(this.cssH * scale);
    const c = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(w, h) : Object.assign(document.createElement('canvas'), { width: w, height: h });
    const ctx = c.getContext('2d');
    ctx.fillStyle = 'white';
    ctx.fillRect(0, 0, w, h);
    ctx.setTransform(scale, 0, 0, scale, 0, 0);
    paint(ctx, this.displayList(true));
    if (c.convertToBlob) return c.convertToBlob({ type: 'image/png' });
    return new Promise((resolve) => c.toBlob((b) => resolve(b), 'image/png'));
  }

  /** What is under (x, y) in CSS pixels: `{thread, pass, lines, style}`, or null. */
  pick(x, y) {
    if (this.key === null || this.stale || !this.transform()) return null;
    return this.opts.session.pick(this.name, Float64Array.from(this.xf), x, y);
  }
}
