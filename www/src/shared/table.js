// Small formatting helpers shared by the app and the embedded preview.

/** A number as the tables show it: at most four decimals, '' for none. */
export const num = (v) => (v === undefined || v === null ? '' : String(Math.round(v * 1e4) / 1e4));

/** Text escaped for HTML content and attribute values. */
export const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
