// A canvas view of one scene: HiDPI-crisp drawing, pan (drag), zoom (wheel,
// around the pointer), fit (double-click or the Fit button), an optional
// radial stretch, hover hit-testing and SVG/PNG export of what it shows.
// Used by the app and by the embeddable <screwcut-preview> element.

import { drawScene, canvasPainter, svgPainter, fitTransform, prepare, itemsOfLine, itemsOfPass, itemDistance, itemInfo } from './render.js';

const PAD = 56;

export class SceneView {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{styleNames: string[], tr: Function, onHover?: Function, onPick?: Function, onMove?: Function,
   *   name: string, stretch?: boolean, wheel?: 'always' | 'ctrl'}} opts
   *   `wheel: 'ctrl'` zooms only with Ctrl (or ⌘) held, so that a page with
   *   embedded views still scrolls under the wheel.
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
    this.thread = 0;
    this.hovered = -1;
    this.lastDraw = 0;
    this.drawTime = 0; // milliseconds spent drawing since the owner last zeroed it
    this.ro = new ResizeObserver(() => this.resize());
    this.ro.observe(canvas);
    this.resize();
    this.bindPointer();
  }

  /** Stops watching the canvas size (the view is no longer shown). */
  destroy() {
    this.ro.disconnect();
    this.scene = null;
  }

  resize() {
    const r = this.canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(r.width * dpr));
    const h = Math.max(1, Math.round(r.height * dpr));
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
    this.cssW = r.width;
    this.cssH = r.height;
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

  transform() {
    if (!this.xf && this.scene) {
      const rect = this.scene.focus;
      this.xf = fitTransform(rect, this.cssW, this.cssH, PAD, this.stretch);
    }
    return this.xf;
  }

  /** The chosen thread (its dimensions are drawn when the scene has many threads). */
  setThread(t) {
    if (t !== this.thread) {
      this.thread = t;
      this.draw();
    }
  }

  /** Highlights items: a Set of item indices, or null; the same items again draw nothing. */
  setHighlight(set) {
    const old = this.highlight;
    const same = (!old || !old.size) && (!set || !set.size) ? true : !!old && !!set && old.size === set.size && [...set].every((i) => old.has(i));
    this.highlight = set;
    if (!same) this.draw();
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
    requestAnimationFrame(() => {
      this.queued = false;
      this.drawNow();
    });
  }

  drawNow() {
    const ctx = this.canvas.getContext('2d');
    const dpr = this.canvas.width / Math.max(this.cssW, 1);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    if (!this.scene) return;
    const t0 = performance.now();
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawScene(canvasPainter(ctx), this.scene, this.transform(), {
      tr: this.opts.tr,
      styleNames: this.opts.styleNames,
      highlight: this.highlight,
      thread: this.thread,
      stale: this.stale,
      width: this.cssW,
      height: this.cssH,
      cull: true,
    });
    this.lastDraw = performance.now() - t0;
    this.drawTime += this.lastDraw;
  }

  /** The scene as an SVG document, as currently shown. */
  toSVG() {
    if (!this.scene) return null;
    const p = svgPainter(Math.round(this.cssW), Math.round(this.cssH));
    drawScene(p, this.scene, this.transform(), {
      tr: this.opts.tr,
      styleNames: this.opts.styleNames,
      highlight: null,
      thread: this.thread,
      stale: false,
      width: this.cssW,
      height: this.cssH,
    });
    return p.svg();
  }

  /** The scene as a PNG blob at `scale` × the shown size. */
  toPNG(scale = 2) {
    return new Promise((resolve) => {
      if (!this.scene) return resolve(null);
      const c = document.createElement('canvas');
      c.width = Math.round(this.cssW * scale);
      c.height = Math.round(this.cssH * scale);
      const ctx = c.getContext('2d');
      ctx.fillStyle = 'white';
      ctx.fillRect(0, 0, c.width, c.height);
      ctx.setTransform(scale, 0, 0, scale, 0, 0);
      drawScene(canvasPainter(ctx), this.scene, this.transform(), {
        tr: this.opts.tr,
        styleNames: this.opts.styleNames,
        highlight: null,
        stale: false,
        width: this.cssW,
        height: this.cssH,
      });
      c.toBlob((b) => resolve(b), 'image/png');
    });
  }

  /** The item under (x, y) in CSS pixels: nearest within 7 px, passes first. */
  pick(x, y) {
    if (!this.scene || this.stale) return -1;
    const xf = this.transform();
    const n = this.scene.prepared.count;
    let best = -1;
    let bestD = 7;
    let bestPass = false;
    for (let i = 0; i < n; i++) {
      const info = this.scene.items;
      const o = i * 10;
      const hasPass = info[o + 5] > 0;
      if (!hasPass && info[o + 7] === 0) continue;
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

  bindPointer() {
    const c = this.canvas;
    let drag = null;
    c.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      drag = { x: e.clientX, y: e.clientY, moved: false };
      c.setPointerCapture(e.pointerId);
    });
    c.addEventListener('pointermove', (e) => {
      const r = c.getBoundingClientRect();
      if (drag) {
        const dx = e.clientX - drag.x;
        const dy = e.clientY - drag.y;
        if (Math.abs(dx) + Math.abs(dy) > 2 || drag.moved) {
          const xf = this.transform();
          if (xf) {
            xf.tx += dx;
            xf.ty += dy;
            this.auto = false;
            drag.x = e.clientX;
            drag.y = e.clientY;
            drag.moved = true;
            this.draw();
          }
        }
        return;
      }
      const i = this.pick(e.clientX - r.left, e.clientY - r.top);
      if (i !== this.hovered) {
        this.hovered = i;
        c.style.cursor = i >= 0 ? 'pointer' : 'grab';
        this.opts.onHover?.(i >= 0 ? { ...itemInfo(this.scene, i), x: e.clientX, y: e.clientY } : null);
      } else if (i >= 0 && this.opts.onMove) {
        this.opts.onMove(e.clientX, e.clientY);
      }
    });
    c.addEventListener('pointerup', (e) => {
      const r = c.getBoundingClientRect();
      if (drag && !drag.moved) {
        const i = this.pick(e.clientX - r.left, e.clientY - r.top);
        if (i >= 0) this.opts.onPick?.(itemInfo(this.scene, i));
      }
      drag = null;
    });
    c.addEventListener('pointerleave', () => {
      if (this.hovered >= 0) {
        this.hovered = -1;
        this.opts.onHover?.(null);
      }
    });
    c.addEventListener('dblclick', () => this.fit());
    c.addEventListener(
      'wheel',
      (e) => {
        if (this.opts.wheel === 'ctrl' && !(e.ctrlKey || e.metaKey)) return;
        e.preventDefault();
        const xf = this.transform();
        if (!xf) return;
        const r = c.getBoundingClientRect();
        const px = e.clientX - r.left;
        const py = e.clientY - r.top;
        const k = Math.exp(-e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.0015));
        xf.tx = px - (px - xf.tx) * k;
        xf.ty = py - (py - xf.ty) * k;
        xf.sx *= k;
        xf.sy *= k;
        this.auto = false;
        this.draw();
      },
      { passive: false },
    );
  }
}
