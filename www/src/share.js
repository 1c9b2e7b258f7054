// Keeping the program: localStorage across reloads, and a link whose
// fragment carries {dialect, settings, program} as base64url of deflated JSON
// (`#z=`) or of plain JSON (`#j=`, what embedded previews write: fragment.js).

import { deflateSync, inflateSync, strToU8, strFromU8 } from 'fflate';
import { toBase64Url, fromBase64Url } from './fragment.js';

const KEY = 'screwcut.state.v1';

export function load() {
  try {
    const s = localStorage.getItem(KEY);
    return s ? JSON.parse(s) : null;
  } catch {
    return null;
  }
}

export function save(state) {
  try {
    localStorage.setItem(KEY, JSON.stringify(state));
  } catch {
    // Private mode or full storage: nothing to keep.
  }
}

/** The fragment for a shared link: `#z=` + base64url(deflate(JSON)). */
export function encodeFragment(state) {
  const json = JSON.stringify({ dialect: state.dialect, settings: state.settings, program: state.program });
  return `#z=${toBase64Url(deflateSync(strToU8(json), { level: 9 }))}`;
}

/** The state in a link's fragment (`#z=` deflated or `#j=` plain JSON), or null. */
export function decodeFragment(hash) {
  try {
    if (hash.startsWith('#z=')) return JSON.parse(strFromU8(inflateSync(fromBase64Url(hash.slice(3)))));
    if (hash.startsWith('#j=')) return JSON.parse(strFromU8(fromBase64Url(hash.slice(3))));
  } catch {
    return null;
  }
  return null;
}
