// What every <screwcut-preview> on a page shares: one wasm instance,
// loaded the first time an element starts, and one IntersectionObserver
// that starts each element when it comes near the viewport.

import init, { Session, style_names as styleNamesOf, scene_layout as sceneLayout } from '../../pkg/screwcut.js';
import { setLayout } from '../render.js';

/** The directory of this script: the wasm and, by default, the app are next to it. */
export const HERE = new URL('./', import.meta.url);

let loading = null;
let styleNames = null;

/**
 * Loads the planner once for the whole page; resolves to `{Session,
 * styleNames}`. Each element plans in a `Session` of its own (src/wasm/session.rs).
 */
export function loadCore() {
  loading ||= init({ module_or_path: new URL('screwcut_bg.wasm', HERE) }).then(() => {
    styleNames = styleNamesOf();
    setLayout(sceneLayout());
    return { Session, styleNames };
  });
  return loading;
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
