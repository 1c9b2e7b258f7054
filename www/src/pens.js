// The pens of the drawings: colours, widths and dashes by style name, the
// colours of finishing and spring passes and of each pass's area, the
// highlight, greyed pens of a stale drawing, and the label font with the
// width of a text in it. The SVG writer (src/svg/pens.rs) draws with the same pens.
/** Pens by style name; `role` colours (finish, spring) apply to pass items. */
export const PENS = {
  axis: { stroke: '#8a94a6', width: 1, dash: [14, 3, 2, 3] },
  outline: { stroke: '#1f2937', width: 1.6 },
  crest: { stroke: '#1f2937', width: 1.3, dash: [7, 3] },
  root: { stroke: '#64748b', width: 1, dash: [2, 3] },
  thread_zone: { fill: 'rgba(100,116,139,0.14)' },
  rapid: { stroke: '#dc2626', width: 1, dash: [5, 4] },
  cut: { stroke: '#2563eb', width: 2 },
  runout: { stroke: '#ea580c', width: 2, dash: [2, 2] },
  screw_in: { stroke: '#b45309', width: 2, dash: [2, 2] },
  other_rapid: { stroke: '#a3a9b5', width: 1, dash: [3, 4] },
  delta1: { fill: 'rgba(234,179,8,0.22)', text: '#854d0e' },
  delta2: { fill: 'rgba(249,115,22,0.20)', text: '#9a3412' },
  dimension: { stroke: '#374151', width: 1, text: '#111827' },
  diameter: { stroke: '#374151', width: 1, text: '#111827' },
  note: { stroke: '#4b5563', width: 1, text: '#374151' },
  material: { fill: 'rgba(148,163,184,0.38)' },
  profile: { stroke: '#111827', width: 1.8 },
  tool: { stroke: '#1d4ed8', width: 1.1, alpha: 0.75 },
  area: { fill: '#93c5fd', stroke: 'rgba(30,64,175,0.5)', width: 0.6 },
  depth_tick: { stroke: '#374151', width: 1, text: '#1f2937' },
  infeed: { stroke: '#dc2626', width: 1.6, text: '#991b1b' },
  circle: { stroke: '#1f2937', width: 1.5 },
  start: { stroke: '#2563eb', width: 1.6, text: '#1e3a8a' },
  ruler: { stroke: '#374151', width: 1.2 },
};
export const ROLE_STROKE = [null, null, '#059669', '#7c3aed']; // none, rough, finish, spring
export const HIGHLIGHT = '#f59e0b';
/** The halo of a highlighted label's text (strong, light). */
export const HIGHLIGHT_HALO = ['#fcd34d', '#fde68a'];
export const FAMILY = 'system-ui, -apple-system, "Segoe UI", "Noto Sans CJK SC", "Microsoft YaHei", sans-serif';
export const FONT = `12px ${FAMILY}`;

/** Widths of label texts in FONT, measured once each. */
const WIDTHS = new Map();
let measurer;

/**
 * The width of `s` in the label font, in CSS pixels: measured on a canvas
 * (an OffscreenCanvas in a worker), else estimated. Every painter places
 * labels with these widths, so a canvas, its PNG and its SVG agree.
 */
export function textWidth(s) {
  let w = WIDTHS.get(s);
  if (w !== undefined) return w;
  if (measurer === undefined) {
    measurer = null;
    try {
      const c = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(1, 1) : typeof document !== 'undefined' ? document.createElement('canvas') : null;
      measurer = (c && c.getContext('2d')) || null;
    } catch {
      measurer = null;
    }
  }
  if (measurer) {
    measurer.font = FONT;
    w = measurer.measureText(s).width;
  } else {
    // No canvas: wide glyphs (CJK) at a full em, the rest at about 0.6 em.
    w = 0;
    for (const ch of s) w += ch.codePointAt(0) > 0x2e80 ? 12 : 7;
  }
  if (WIDTHS.size > 4096) WIDTHS.clear();
  WIDTHS.set(s, w);
  return w;
}

/** Area fill colour of pass `i` (distinct hues, finishing passes green). */
export function areaColour(pass, role) {
  if (role === 2) return 'rgba(16,185,129,0.65)';
  if (role === 3) return 'rgba(139,92,246,0.5)';
  const hue = (200 + pass * 47) % 360;
  return `hsla(${hue},75%,62%,0.6)`;
}

const GREYS = new Map();
const GREY_PENS = new WeakMap();

/**
 * `colour` (#rgb, #rrggbb, rgb(a)() or hsl(a)()) through the grayscale(1)
 * filter: every channel becomes 0.2126 R + 0.7152 G + 0.0722 B, alpha kept.
 */
export function grey(colour) {
  let g = GREYS.get(colour);
  if (g !== undefined) return g;
  const rgba = parseColour(colour);
  if (!rgba) return colour;
  const [r, gr, b, a] = rgba;
  const v = Math.round(0.2126 * r + 0.7152 * gr + 0.0722 * b);
  g = a === 1 ? `rgb(${v},${v},${v})` : `rgba(${v},${v},${v},${a})`;
  GREYS.set(colour, g);
  return g;
}

/** `[r, g, b, a]` (0–255, alpha 0–1) of a CSS colour in one of the forms the pens use, else null. */
function parseColour(c) {
  let m = /^#([0-9a-f]{3}|[0-9a-f]{6})$/i.exec(c);
  if (m) {
    const h = m[1].length === 3 ? [...m[1]].map((x) => x + x).join('') : m[1];
    return [0, 2, 4].map((k) => parseInt(h.slice(k, k + 2), 16)).concat(1);
  }
  m = /^(rgb|hsl)a?\(([^)]*)\)$/.exec(c);
  if (!m) return null;
  const v = m[2].split(',').map((x) => parseFloat(x));
  const a = v.length > 3 ? v[3] : 1;
  if (m[1] === 'rgb') return [v[0], v[1], v[2], a];
  // hsl → rgb (CSS Color 4).
  const h = (((v[0] % 360) + 360) % 360) / 30;
  const sat = v[1] / 100;
  const l = v[2] / 100;
  const f = (n) => {
    const k = (n + h) % 12;
    return 255 * (l - sat * Math.min(l, 1 - l) * Math.max(-1, Math.min(k - 3, 9 - k, 1)));
  };
  return [f(0), f(8), f(4), a];
}

/** A pen with its colours greyed (kept per pen object). */
export function greyPen(pen) {
  let g = GREY_PENS.get(pen);
  if (!g) {
    g = { ...pen };
    for (const k of ['stroke', 'fill', 'text']) if (typeof pen[k] === 'string') g[k] = grey(pen[k]);
    GREY_PENS.set(pen, g);
  }
  return g;
}
