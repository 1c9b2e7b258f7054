// A view of one scene on a canvas — an OffscreenCanvas in the drawing
// worker, or a page canvas where there is none — without touching the DOM:
// its size, pointer and keys come from whoever shows it (input.js binds a
// page canvas; the worker gets them as messages). HiDPI-crisp drawing, pan,
// zoom around a point, fit, an optional radial stretch, hit-testing, PNG
// export of what it shows, and what the core's SVG writer needs to draw it
// the same: the transform and the labels of its last draw (`svgLayout`).

import { drawScene, fitScene, prepare, itemsOfLine, itemsOfPass, itemDistance, itemInfo } from './render.js';
import { canvasPainter } from './canvas.js';

/** The next frame: the window's or the worker's animation frame, else a timer. */
const nextFrame = (f) => (typeof globalThis.requestAnimationFrame === 'function' ? globalThis.requestAnimationFrame(f) : setTimeout(f, 16));

export class SceneView {
  /**
   * @param {HTMLCanvasElement | OffscreenCanvas} canvas
   * @param {{styleNames: string[], tr: Function, name: string, stretch?: boolean, onDrawn?: Function}} opts
   *   `onDrawn(view)` is called after each draw, in the same frame.
   */
  constructor(canvas, opts) {
    this.canvas = canvas;
    this.opts = opts;
    this.scene = null;
    this.stale = false;
    this.xf = null;
    this.auto = true; // refit on every new scene until the user pans or zooms
    this.stretch = !!opts.stretch;
    this.highlight = null;
    this.hovered = -1;
    this.thread = 0;
    this.cssW = 1;
    this.cssH = 1;
    this.lastDraw = 0;
    this.drawTime = 0; // milliseconds spent drawing since the owner last zeroed it
    this.placed = { placed: [], dropped: [] }; // the labels of the last draw
    this.drawnWith = null; // the transform of the last draw
    this.fitFor = ''; // the language the fit made room for
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

  /** Shows a new scene (`stale`: the last good one, greyed); the same one again draws nothing. */
  setScene(scene, stale) {
    if (scene === this.scene && !!stale === this.stale) return;
    if (scene) prepare(scene, this.opts.styleNames);
    const first = !this.scene;
    this.scene = scene;
    this.stale = !!stale;
    if (this.auto || first) this.xf = null;
    this.hovered = -1;
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

  /**
   * The world→screen transform: until the user pans or zooms, the fit of the
   * scene with room for its labels (made again when the labels' language changes).
   */
  transform() {
    if (!this.scene) return this.xf;
    const lang = this.language();
    if (this.auto && this.xf && this.fitFor !== lang) this.xf = null;
    if (!this.xf) {
      this.xf = fitScene(this.scene, this.cssW, this.cssH, this.stretch, this.drawOptions(null, false, false));
      this.fitFor = lang;
    }
    return this.xf;
  }

  /** What tells the languages of labels apart: two labels as `tr` words them. */
  language() {
    return `${this.opts.tr('dia_minor', '')}|${this.opts.tr('axial_offsets', '')}`;
  }

  /** The labels of the last draw as placed (boxes in CSS pixels) and those dropped, with the view's size. */
  labels() {
    return { size: [this.cssW, this.cssH], ...this.placed };
  }

  /** Moves the drawing by (dx, dy) CSS pixels. */
  pan(dx, dy) {
    const xf = this.transform();
    if (!xf) return;
    xf.tx += dx;
    xf.ty += dy;
    this.auto = false;
    this.draw();
  }

  /** Zooms by `k` around (px, py) in CSS pixels. */
  zoomAt(px, py, k) {
    const xf = this.transform();
    if (!xf || !(k > 0) || !Number.isFinite(k)) return;
    xf.tx = px - (px - xf.tx) * k;
    xf.ty = py - (py - xf.ty) * k;
    xf.sx *= k;
    xf.sy *= k;
    this.auto = false;
    this.draw();
  }

  /** The chosen thread (its dimensions are drawn when the scene has many threads). */
  setThread(t) {
    if (t !== this.thread) {
      this.thread = t;
      // Its labels are others: a fit makes room for them.
      if (this.auto) this.xf = null;
      this.draw();
    }
  }

  /** Highlights items: a Set of item indices, or null; `light` for the editor cursor's mark. The same again draws nothing. */
  setHighlight(set, light = false) {
    const old = this.highlight;
    const same = (!old || !old.size) && (!set || !set.size) ? true : !!old && !!set && old.size === set.size && [...set].every((i) => old.has(i));
    this.highlight = set;
    const changed = this.light !== light;
    this.light = light;
    if (!same || (changed && set && set.size)) this.draw();
  }

  /** Item indices drawn from source `line`. */
  itemsOfLine(line) {
    return this.scene ? itemsOfLine(this.scene, line) : [];
  }

  /** Item indices of pass `pass` of thread `thread`. */
  itemsOfPass(thread, pass) {
    return this.scene ? itemsOfPass(this.scene, thread, pass) : [];
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

  drawNow() {
    const ctx = this.canvas.getContext('2d');
    const dpr = this.canvas.width / this.cssW;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    if (this.scene) {
      const t0 = performance.now();
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const xf = this.transform();
      this.placed = drawScene(canvasPainter(ctx), this.scene, xf, this.drawOptions(this.highlight, this.stale, true));
      this.drawnWith = { sx: xf.sx, sy: xf.sy, tx: xf.tx, ty: xf.ty };
      this.lastDraw = performance.now() - t0;
      this.drawTime += this.lastDraw;
    }
    this.opts.onDrawn?.(this);
  }

  drawOptions(highlight, stale, cull) {
    return {
      tr: this.opts.tr,
      styleNames: this.opts.styleNames,
      highlight,
      light: this.light,
      thread: this.thread,
      stale,
      width: this.cssW,
      height: this.cssH,
      cull,
    };
  }

  /**
   * What the SVG writer (src/svg.rs, through `Session::svg`) draws this view
   * with, so that the export is what it shows: `{transform, labels}`, the
   * transform and the labels as placed of the last draw (drawn now if a draw
   * is pending). A greyed view shows an older scene than the plan the writer
   * draws: its labels are left to the writer to place. Null without a scene.
   */
  svgLayout() {
    if (!this.scene) return null;
    if (this.queued || !this.drawnWith) this.drawNow();
    if (!this.drawnWith) return null;
    return { transform: { ...this.drawnWith }, labels: this.stale ? null : this.placed.placed };
  }

  /** The scene as a PNG blob at `scale` × the shown size. */
  async toPNG(scale = 2) {
    if (!this.scene) return null;
    const w = Math.round(this.cssW * scale);
    const h = Math.round(this.cssH * scale);
    const c = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(w, h) : Object.assign(document.createElement('canvas'), { width: w, height: h });
    const ctx = c.getContext('2d');
    ctx.fillStyle = 'white';
    ctx.fillRect(0, 0, w, h);
    ctx.setTransform(scale, 0, 0, scale, 0, 0);
    drawScene(canvasPainter(ctx), this.scene, this.transform(), this.drawOptions(null, false, false));
    if (c.convertToBlob) return c.convertToBlob({ type: 'image/png' });
    return new Promise((resolve) => c.toBlob((b) => resolve(b), 'image/png'));
  }

  /** The item under (x, y) in CSS pixels: nearest within 7 px, passes first; -1 for none. */
  pick(x, y) {
    if (!this.scene || this.stale) return -1;
    const xf = this.transform();
    const n = this.scene.prepared.count;
    const info = this.scene.items;
    const { stride, thread: fThread, pass: fPass, line_len: fLines } = this.scene.prepared.layout;
    let best = -1;
    let bestD = 7;
    let bestPass = false;
    for (let i = 0; i < n; i++) {
      const o = i * stride;
      const hasPass = info[o + fPass] > 0;
      if (!hasPass && info[o + fLines] === 0 && info[o + fThread] === 0) continue;
      const d = itemDistance(this.scene, i, xf, x, y);
      if (d > 7) continue;
      if ((hasPass && !bestPass) || (hasPass === bestPass && d < bestD) || best < 0) {
        best = i;
        bestD = d;
        bestPass = hasPass;
      }
    }
    return best;
  }

  /** Facts about item `i` (thread, pass, lines, style). */
  info(i) {
    return this.scene && i >= 0 ? itemInfo(this.scene, i) : null;
  }
}
