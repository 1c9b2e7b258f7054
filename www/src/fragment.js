// The link fragment that carries a program to the app, without a
// compression library: `#j=` + base64url of the UTF-8 JSON
// {dialect, settings, program}. The app also reads `#z=` (deflated, see
// share.js), which makes shorter links.

/** Bytes as base64url without padding. */
export function toBase64Url(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** base64url (padded or not) as bytes. */
export function fromBase64Url(text) {
  const b = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  const out = new Uint8Array(b.length);
  for (let i = 0; i < b.length; i++) out[i] = b.charCodeAt(i);
  return out;
}

/**
 * The `#j=` fragment for `{dialect, settings, program}`; `settings` maps a
 * dialect to `{name: value}` as the app keeps them.
 */
export function jsonFragment(state) {
  const json = JSON.stringify({ dialect: state.dialect, settings: state.settings || {}, program: state.program });
  return `#j=${toBase64Url(new TextEncoder().encode(json))}`;
}
