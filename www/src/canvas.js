// A painter on a 2D canvas context: what drawScene (render.js) draws with.

import { FONT, textWidth } from './pens.js';

/** A painter on a 2D canvas context (already scaled for devicePixelRatio). */
export function canvasPainter(ctx) {
  return {
    begin(stale) {
      ctx.save();
      ctx.lineJoin = 'round';
      ctx.lineCap = 'butt';
      ctx.font = FONT;
      // A stale drawing is faded here and drawn with grey pens (greyPen):
      // the same pixels as a grayscale filter, without its cost per draw call.
      if (stale) ctx.globalAlpha = 0.35;
    },
    end() {
      ctx.restore();
    },
    paths(buf, spans, closed, pen) {
      ctx.beginPath();
      for (let j = 0; j < spans.length; j += 2) {
        const s = spans[j];
        const e = s + spans[j + 1];
        if (e - s < 4) continue;
        ctx.moveTo(buf[s], buf[s + 1]);
        for (let k = s + 2; k < e; k += 2) ctx.lineTo(buf[k], buf[k + 1]);
        if (closed) ctx.closePath();
      }
      this.finish(closed, pen);
    },
    finish(closed, pen) {
      const a = ctx.globalAlpha;
      if (pen.alpha) ctx.globalAlpha = a * pen.alpha;
      if (closed && pen.fill) {
        ctx.fillStyle = pen.fill;
        ctx.fill();
      }
      if (pen.stroke) {
        ctx.setLineDash(pen.dash || []);
        ctx.strokeStyle = pen.stroke;
        ctx.lineWidth = pen.width || 1;
        ctx.stroke();
      }
      ctx.globalAlpha = a;
    },
    path(pts, closed, pen) {
      if (pts.length < 4) return;
      ctx.beginPath();
      if (pen.segments) {
        for (let k = 0; k + 3 < pts.length; k += 4) {
          ctx.moveTo(pts[k], pts[k + 1]);
          ctx.lineTo(pts[k + 2], pts[k + 3]);
        }
      } else {
        ctx.moveTo(pts[0], pts[1]);
        for (let k = 2; k < pts.length; k += 2) ctx.lineTo(pts[k], pts[k + 1]);
        if (closed) ctx.closePath();
      }
      this.finish(closed, pen);
    },
    circle(x, y, r, pen) {
      ctx.beginPath();
      ctx.arc(x, y, Math.max(r, 0), 0, Math.PI * 2);
      this.finish(true, pen);
    },
    text(x, y, s, pen, anchor, baseline, angle = 0) {
      ctx.save();
      ctx.translate(x, y);
      if (angle) ctx.rotate((angle * Math.PI) / 180);
      ctx.textAlign = anchor === 'middle' ? 'center' : anchor === 'end' ? 'right' : 'left';
      ctx.textBaseline = baseline;
      if (pen.halo) {
        ctx.lineWidth = 3;
        ctx.strokeStyle = typeof pen.halo === 'string' ? pen.halo : 'rgba(255,255,255,0.85)';
        ctx.setLineDash([]);
        ctx.strokeText(s, 0, 0);
      }
      ctx.fillStyle = pen.text || pen.stroke || '#111827';
      ctx.fillText(s, 0, 0);
      ctx.restore();
    },
    measure(s) {
      return textWidth(s);
    },
  };
}
