// What a person does to a drawing on the page, as operations on its view:
// resize, pan (drag, arrow keys), zoom (wheel or pinch around the pointer;
// + and − keys around the pointer when it is over the drawing, else around
// what is marked or the drawing's middle, as the view's display list says),
// fit (double-click, 0 or F), hover and pick (pointer, or Enter on the focused drawing). The target is a SceneView on the page or a
// stand-in that forwards the operations to the drawing worker.

/**
 * Binds `canvas`'s events to `target`: `{resize(w, h, dpr), pan(dx, dy),
 * zoom(px, py, k) (px, py null: the view's own anchor), fit(), hover(x, y,
 * clientX, clientY), leave(), pick(x, y)}`.
 * `opts.wheel: 'ctrl'` zooms only with Ctrl (or ⌘) held, so that a page of
 * embedded drawings still scrolls under the wheel. Returns `{destroy()}`.
 */
export function bindCanvas(canvas, target, opts = {}) {
  const dpr = () => (typeof devicePixelRatio === 'number' ? devicePixelRatio : 1);
  const size = () => {
    const r = canvas.getBoundingClientRect();
    target.resize(r.width, r.height, dpr());
  };
  const ro = new ResizeObserver(size);
  ro.observe(canvas);
  size();
  if (!canvas.hasAttribute('tabindex')) canvas.tabIndex = 0;
  let drag = null;
  let pointer = null; // where the pointer is over the drawing, for the keys' zoom
  const local = (e) => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  const on = (type, f, o) => canvas.addEventListener(type, f, o);
  on('pointerdown', (e) => {
    if (e.button !== 0) return;
    drag = { x: e.clientX, y: e.clientY, moved: false };
    canvas.setPointerCapture?.(e.pointerId);
  });
  on('pointermove', (e) => {
    if (drag) {
      const dx = e.clientX - drag.x;
      const dy = e.clientY - drag.y;
      if (Math.abs(dx) + Math.abs(dy) > 2 || drag.moved) {
        target.pan(dx, dy);
        drag.x = e.clientX;
        drag.y = e.clientY;
        drag.moved = true;
      }
      return;
    }
    const [x, y] = local(e);
    pointer = [x, y];
    target.hover(x, y, e.clientX, e.clientY);
  });
  on('pointerup', (e) => {
    if (drag && !drag.moved) {
      const [x, y] = local(e);
      target.pick(x, y);
    }
    drag = null;
  });
  on('pointercancel', () => {
    drag = null;
  });
  on('pointerleave', () => {
    pointer = null;
    target.leave();
  });
  on('dblclick', () => target.fit());
  on(
    'wheel',
    (e) => {
      if (opts.wheel === 'ctrl' && !(e.ctrlKey || e.metaKey)) return;
      e.preventDefault();
      const [x, y] = local(e);
      target.zoom(x, y, Math.exp(-e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.0015)));
    },
    { passive: false },
  );
  on('keydown', (e) => {
    const r = canvas.getBoundingClientRect();
    const step = e.shiftKey ? 80 : 24;
    const keys = {
      ArrowLeft: () => target.pan(step, 0),
      ArrowRight: () => target.pan(-step, 0),
      ArrowUp: () => target.pan(0, step),
      ArrowDown: () => target.pan(0, -step),
      '+': () => target.zoom(pointer?.[0] ?? null, pointer?.[1] ?? null, 1.25),
      '=': () => target.zoom(pointer?.[0] ?? null, pointer?.[1] ?? null, 1.25),
      '-': () => target.zoom(pointer?.[0] ?? null, pointer?.[1] ?? null, 0.8),
      0: () => target.fit(),
      f: () => target.fit(),
      F: () => target.fit(),
      Enter: () => target.pick(r.width / 2, r.height / 2),
    };
    const k = keys[e.key];
    if (k && !e.ctrlKey && !e.metaKey && !e.altKey) {
      e.preventDefault();
      k();
    }
  });
  return { destroy: () => ro.disconnect() };
}
