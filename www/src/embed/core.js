// What every <screwcut-preview> on a page shares: one wasm instance,
// loaded the first time an element starts, and one IntersectionObserver
// that starts each element when it comes near the viewport.

import init, { dialects as dialectsOf, Session } from '../../pkg/screwcut.js';

/**
 * The directory of this script: the wasm and, by default, the app are next
 * to it (on the site, and in the element folder `cargo xtask dist` writes,
 * which carries the app too).
 */
export const HERE = new URL('./', import.meta.url);

/** Most bytes a `src` program may have: 1 MiB (documented in the element's README). */
export const SRC_MAX_BYTES = 1024 * 1024;
/** How long a `src` fetch may take: 15 s. */
export const SRC_TIMEOUT_MS = 15_000;

let loading = null;

/**
 * Loads the planner once for the whole page; resolves to `{Session,
 * dialects}`. Each element plans and draws in a `Session` of its own (src/wasm/session.rs).
 */
export function loadCore() {
  loading ||= init({ module_or_path: new URL('screwcut_bg.wasm', HERE) }).then(() => ({ Session, dialects: dialectsOf() }));
  return loading;
}

/**
 * Fetches the program at `url` (an http(s) URL, checked by the caller):
 * without cookies or HTTP authentication (`credentials: 'omit'`), read as
 * a stream that stops at `cap` bytes, given up after `timeout` ms. Throws
 * an Error that says which of these failed.
 */
export async function fetchProgram(url, { cap = SRC_MAX_BYTES, timeout = SRC_TIMEOUT_MS, label = String(url) } = {}) {
  const ctl = new AbortController();
  let timedOut = false;
  const timer = setTimeout(() => {
    timedOut = true;
    ctl.abort();
  }, timeout);
  const tooLarge = () => new Error(`src="${label}" is larger than ${cap / 1048576} MiB: not loaded`);
  try {
    const r = await fetch(url, { credentials: 'omit', signal: ctl.signal, redirect: 'follow' });
    if (!r.ok) throw new Error(`src="${label}": ${r.status} ${r.statusText}`.trim());
    const declared = Number(r.headers.get('content-length'));
    if (Number.isFinite(declared) && declared > cap) {
      ctl.abort();
      throw tooLarge();
    }
    const chunks = [];
    let total = 0;
    if (r.body && r.body.getReader) {
      const reader = r.body.getReader();
      for (;;) {
        const { done, value } = await reader.read();
        if (done) break;
        total += value.length;
        if (total > cap) {
          reader.cancel().catch(() => {});
          throw tooLarge();
        }
        chunks.push(value);
      }
    } else {
      const all = new Uint8Array(await r.arrayBuffer());
      if (all.length > cap) throw tooLarge();
      chunks.push(all);
      total = all.length;
    }
    const bytes = new Uint8Array(total);
    let at = 0;
    for (const c of chunks) {
      bytes.set(c, at);
      at += c.length;
    }
    return new TextDecoder().decode(bytes);
  } catch (e) {
    if (timedOut) throw new Error(`src="${label}": no answer within ${timeout / 1000} s`);
    if (e && e.name === 'TypeError') throw new Error(`src="${label}": cannot be fetched (${e.message})`);
    throw e;
  } finally {
    clearTimeout(timer);
  }
}

/** How far below the viewport an element starts, so that it is drawn when scrolled to. */
const MARGIN = '300px 0px';
let observer = null;

/** Calls `el.start()` once `el` is near the viewport (at once without IntersectionObserver). */
export function startWhenVisible(el) {
  if (typeof IntersectionObserver === 'undefined') {
    el.start();
    return;
  }
  observer ||= new IntersectionObserver(
    (entries) => {
      for (const e of entries) {
        if (e.isIntersecting) {
          observer.unobserve(e.target);
          e.target.start();
        }
      }
    },
    { rootMargin: MARGIN },
  );
  observer.observe(el);
}

/** Stops watching `el` (it left the document before it started). */
export function forget(el) {
  observer?.unobserve(el);
}
