// A task of its own, on the page or in a worker: what runs after the
// current task (and, after a frame callback, after the frame it drew was
// committed).

/** Runs `f` in a new task, after the current one. */
export function afterTask(f) {
  const ch = new MessageChannel();
  ch.port1.onmessage = () => {
    ch.port1.close();
    f();
  };
  ch.port2.postMessage(0);
}
