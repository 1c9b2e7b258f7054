// The link fragment that carries a program to the app, without a
// compression library: `#j=` + base64url of the UTF-8 JSON
// {dialect, settings, program}. The app also reads `#z=` (deflated, see
// share.js), which makes shorter links.

/** The controller of a link, program or element whose own is unknown. */
export const DEFAULT_DIALECT = 'gsk980tdc';

/**
 * Other spellings the planner accepts (src/dialect.rs `NAMES`), after
 * dropping case, '-', '_' and spaces; a spelling of a dialect this build
 * does not have finds nothing. An xtask test keeps it in step with `NAMES`.
 */
const DIALECT_ALIASES = {
  gsk: 'gsk980tdc',
  gsk980: 'gsk980tdc',
  gsk980tdi: 'gsk980tdc',
  fanuc: 'fanuc0i',
  fanuc0it: 'fanuc0i',
  fanuc0itf: 'fanuc0i',
  lcnc: 'linuxcnc',
  emc2: 'linuxcnc',
  rs274ngc: 'linuxcnc',
};

/**
 * `name` as one of `dialects` (the planner's `[{name, title}]`), spelled
 * as the planner spells it, or null when it is not a known controller.
 */
export function knownDialect(name, dialects) {
  if (typeof name !== 'string') return null;
  const bare = name.trim().toLowerCase().replace(/[-_ ]/g, '');
  const n = Object.hasOwn(DIALECT_ALIASES, bare) ? DIALECT_ALIASES[bare] : bare;
  return dialects.some((d) => d.name === n) ? n : null;
}

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
