// A task of its own, on the page or in a worker: what runs after the
// current task, or after the next frame was committed.

/** Runs `f` in a new task, after the current one. */
export function afterTask(f) {
  const ch = new MessageChannel();
  ch.port1.onmessage = () => {
    ch.port1.close();
    f();
  };
  ch.port2.postMessage(0);
}

/**
 * Runs `f` once the next frame is committed: in a task after the next
 * animation frame's callbacks (the page's or a worker's), or after the
 * current task where there are no animation frames.
 *
 * In a worker this is when what was drawn on its OffscreenCanvases is on
 * its way to the screen: a Chromium trace shows the canvases rasterised
 * and pushed at the worker's next animation frame, after its callbacks
 * (2–3 ms after the task that drew them, 5,000-line program, 2 cores),
 * not when that task ends.
 */
export function afterFrame(f) {
  if (typeof globalThis.requestAnimationFrame === 'function') globalThis.requestAnimationFrame(() => afterTask(f));
  else afterTask(f);
}
