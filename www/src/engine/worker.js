// The drawing worker: the wasm planner and the app's three views on
// OffscreenCanvases, so that planning and drawing never hold up typing.
// The first message is `{type: 'init', wasm}` (the wasm file's URL; the
// tools module is loaded from beside it when first used); the engine
// (engine.js) answers every other.

import init, * as core from '../../pkg/screwcut.js';
import { Engine, toolsLoader } from './engine.js';
import { afterFrame } from './task.js';

let engine = null;
const queue = [];
const post = (m, transfer) => self.postMessage(m, transfer || []);

self.onmessage = async (e) => {
  const m = e.data;
  if (m.type === 'init') {
    try {
      await init({ module_or_path: m.wasm });
      // A drawing goes on screen at the worker's next animation frame (task.js):
      // what follows it (the frame's report and its time) comes after that frame.
      engine = new Engine(core, post, afterFrame, { immediate: true, loadTools: toolsLoader(m.wasm) });
      post({ type: 'ready', dialects: core.dialects() });
      for (const q of queue.splice(0)) engine.handle(q);
    } catch (err) {
      post({ type: 'error', message: `the planner did not load: ${err && err.message ? err.message : err}`, fatal: true });
    }
    return;
  }
  if (engine) engine.handle(m);
  else queue.push(m);
};
