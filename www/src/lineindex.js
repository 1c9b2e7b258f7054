// The drawing's lines, which labels prefer not to cross, in a grid of world
// cells built once per scene, and the segment tests placement uses.

const sx = (xf, x) => xf.tx + xf.sx * x;
const sy = (xf, y) => xf.ty - xf.sy * y;

/**
 * The drawing's lines, which labels prefer not to cross, in a grid of world
 * cells built once per scene (`lineIndex`): a label's box on screen is taken
 * back to world coordinates to find the lines near it.
 */
class LineIndex {
  /** `world`: x0 y0 x1 y1 of each segment; `rect`: [x0, y0, x1, y1] the grid spans (64 × 64 cells). */
  constructor(world, rect) {
    this.world = world;
    const [x0, y0, x1, y1] = rect;
    this.x0 = x0;
    this.y0 = y0;
    this.cw = Math.max((x1 - x0) / 64, 1e-9);
    this.ch = Math.max((y1 - y0) / 64, 1e-9);
    // Cells −1 … 64 on each axis (the outer ones hold what lies beyond), as
    // compressed rows: the segments of cell c are list[start[c] … start[c + 1]).
    const N = 66;
    const count = new Int32Array(N * N + 1);
    this.wide = []; // segments across more than 256 cells, tested every time
    let fill = null;
    for (let pass = 0; pass < 2; pass++) {
      for (let k = 0; k + 3 < world.length; k += 4) {
        const a = world[k];
        const b = world[k + 1];
        const c = world[k + 2];
        const d = world[k + 3];
        if (!Number.isFinite(a + b + c + d)) continue;
        const i0 = this.col(a < c ? a : c) + 1;
        const i1 = this.col(a < c ? c : a) + 1;
        const j0 = this.row(b < d ? b : d) + 1;
        const j1 = this.row(b < d ? d : b) + 1;
        if ((i1 - i0 + 1) * (j1 - j0 + 1) > 256) {
          if (pass === 0) this.wide.push(k);
          continue;
        }
        for (let i = i0; i <= i1; i++)
          for (let j = j0; j <= j1; j++) {
            if (pass === 0) count[i * N + j + 1]++;
            else this.list[fill[i * N + j]++] = k;
          }
      }
      if (pass === 0) {
        for (let c = 1; c <= N * N; c++) count[c] += count[c - 1];
        this.start = count;
        this.list = new Int32Array(count[N * N]);
        fill = count.slice();
      }
    }
  }
  col(x) {
    return Math.max(-1, Math.min(64, Math.floor((x - this.x0) / this.cw)));
  }
  row(y) {
    return Math.max(-1, Math.min(64, Math.floor((y - this.y0) / this.ch)));
  }
  /** Whether a line crosses the screen box `b` under transform `xf`. */
  hits(b, xf) {
    const w = this.world;
    const test = (k) =>
      segmentHitsBox([sx(xf, w[k]), sy(xf, w[k + 1])], [sx(xf, w[k + 2]), sy(xf, w[k + 3])], b);
    for (const k of this.wide) if (test(k)) return true;
    const i0 = this.col((b[0] - xf.tx) / xf.sx);
    const i1 = this.col((b[2] - xf.tx) / xf.sx);
    const j0 = this.row((xf.ty - b[3]) / xf.sy);
    const j1 = this.row((xf.ty - b[1]) / xf.sy);
    const N = 66;
    for (let i = i0 + 1; i <= i1 + 1; i++)
      for (let j = j0 + 1; j <= j1 + 1; j++) {
        const c = i * N + j;
        for (let e = this.start[c]; e < this.start[c + 1]; e++) if (test(this.list[e])) return true;
      }
    return false;
  }
}

/**
 * An index of the drawing's lines for `placeLabels` and `fitLabels`:
 * `world` holds x0 y0 x1 y1 of each segment in world coordinates, `rect` the
 * region it is finest over (the scene's focus). Build it once per scene.
 */
export function lineIndex(world, rect) {
  return new LineIndex(world, rect);
}

/** Whether segment p→q crosses box b. */
export function segmentHitsBox(p, q, b) {
  let t0 = 0;
  let t1 = 1;
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  for (const [pp, qq] of [
    [-dx, p[0] - b[0]],
    [dx, b[2] - p[0]],
    [-dy, p[1] - b[1]],
    [dy, b[3] - p[1]],
  ]) {
    if (pp === 0) {
      if (qq < 0) return false;
    } else {
      const r = qq / pp;
      if (pp < 0) t0 = Math.max(t0, r);
      else t1 = Math.min(t1, r);
      if (t0 > t1) return false;
    }
  }
  return true;
}

/** Whether segments p→q and r→s run along each other (nearly parallel, within 5 px, side by side). */
export function segmentsClash(p, q, r, s) {
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  const L = Math.hypot(dx, dy);
  const ex = s[0] - r[0];
  const ey = s[1] - r[1];
  const M = Math.hypot(ex, ey);
  if (!(L > 0) || !(M > 0)) return false;
  if (Math.abs(dx * ey - dy * ex) > 0.17 * L * M) return false;
  const across = (w) => Math.abs((w[0] - p[0]) * dy - (w[1] - p[1]) * dx) / L;
  if (across(r) > 5 || across(s) > 5) return false;
  const along = (w) => ((w[0] - p[0]) * dx + (w[1] - p[1]) * dy) / L;
  const a = along(r);
  const b = along(s);
  return Math.max(a, b) > 0 && Math.min(a, b) < L;
}
