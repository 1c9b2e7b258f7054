// The page's side of the engine (engine.js): a Worker drawing on the views'
// OffscreenCanvases when the browser has them, else the same engine on the
// page. Either way the page sends the same messages and gets the same
// answers; canvases' sizes and what a person does to them (input.js) are
// forwarded as operations.

import { bindCanvas } from '../view/input.js';
import { afterFrame } from './task.js';

/** Whether this browser can draw the app in a worker. */
export function canDrawInWorker() {
  return typeof Worker === 'function' && typeof OffscreenCanvas === 'function' && typeof HTMLCanvasElement !== 'undefined' && 'transferControlToOffscreen' in HTMLCanvasElement.prototype;
}

/** A started engine: `send`, `request` (answered by a reply), `bindView`, `mode`. */
class Client {
  constructor(mode, send, onMessage) {
    this.mode = mode; // 'worker' or 'page'
    this.rawSend = send;
    this.onMessage = onMessage;
    this.next = 1;
    this.waiting = new Map();
  }

  send(m, transfer) {
    this.rawSend(m, transfer);
  }

  /** Sends `m` with an id; resolves with the reply's data. */
  request(type, m = {}) {
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.waiting.set(id, { resolve, reject });
      this.send({ ...m, type, id });
    });
  }

  receive(m) {
    if ((m.type === 'reply' || m.type === 'error') && m.id && this.waiting.has(m.id)) {
      const w = this.waiting.get(m.id);
      this.waiting.delete(m.id);
      if (m.type === 'reply') w.resolve(m.data);
      else w.reject(new Error(m.message));
      return;
    }
    this.onMessage(m);
  }

  /** Gives the engine `canvas` as view `name` and forwards its size and input. */
  bindView(name, canvas, opts = {}) {
    if (this.mode === 'worker') {
      const off = canvas.transferControlToOffscreen();
      this.send({ type: 'view', name, canvas: off, stretch: !!opts.stretch }, [off]);
    } else {
      this.send({ type: 'view', name, canvas, stretch: !!opts.stretch });
    }
    const input = (op, rest) => this.send({ type: 'input', name, op, ...rest });
    return bindCanvas(
      canvas,
      {
        resize: (w, h, dpr) => this.send({ type: 'size', name, w, h, dpr }),
        pan: (dx, dy) => input('pan', { dx, dy }),
        zoom: (x, y, k) => input('zoom', { x, y, k }),
        fit: () => input('fit'),
        hover: (x, y, clientX, clientY) => input('hover', { x, y, clientX, clientY }),
        leave: () => input('leave'),
        pick: (x, y) => input('pick', { x, y }),
      },
      opts,
    );
  }
}

/**
 * Starts the engine: in a Worker (`workerUrl`) when the browser can draw
 * there and `mode` is not 'page', else on the page. Resolves once the
 * planner is loaded, with the client and the dialect list.
 */
export async function startEngine({ wasmUrl, workerUrl, mode, onMessage }) {
  if (mode !== 'page' && canDrawInWorker()) {
    try {
      return await startWorker(wasmUrl, workerUrl, onMessage);
    } catch (e) {
      onMessage({ type: 'note', message: `drawing on the page: ${e.message}` });
    }
  }
  const { glue, Engine, toolsLoader } = await import(new URL('page-engine.js', import.meta.url).href);
  await glue.default({ module_or_path: wasmUrl });
  let client = null;
  const engine = new Engine(glue, (m) => client.receive(m), afterFrame, { loadTools: toolsLoader(wasmUrl) });
  client = new Client('page', (m) => queueMicrotask(() => engine.handle(m)), onMessage);
  return { client, dialects: glue.dialects() };
}

function startWorker(wasmUrl, workerUrl, onMessage) {
  return new Promise((resolve, reject) => {
    const worker = new Worker(workerUrl, { type: 'module' });
    const client = new Client('worker', (m, transfer) => worker.postMessage(m, transfer || []), onMessage);
    const timer = setTimeout(() => reject(new Error('the drawing worker did not start')), 20_000);
    worker.onerror = (e) => {
      clearTimeout(timer);
      reject(new Error(e.message || 'the drawing worker failed'));
    };
    worker.onmessage = (e) => {
      const m = e.data;
      if (m.type === 'ready') {
        clearTimeout(timer);
        worker.onmessage = (ev) => client.receive(ev.data);
        resolve({ client, dialects: m.dialects });
      } else if (m.type === 'error' && m.fatal) {
        clearTimeout(timer);
        worker.terminate();
        reject(new Error(m.message));
      }
    };
    worker.postMessage({ type: 'init', wasm: String(wasmUrl) });
  });
}
