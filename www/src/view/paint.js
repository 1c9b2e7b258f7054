// The canvas painter: executes a display list made by the core
// (src/draw/, packed by src/wasm/views.rs) on a 2D context. It decides
// nothing — pens, texts, places, greyed and highlighted styles all come in
// the list; the SVG writer (src/svg.rs) writes the same list.

const ALIGN = ['left', 'center', 'right'];

/** Paints display list `list` on `ctx` (already scaled to CSS pixels). */
export function paint(ctx, list) {
  const { ops, nums, spans, texts, pens } = list;
  ctx.save();
  ctx.lineJoin = 'round';
  ctx.lineCap = 'butt';
  ctx.font = list.font;
  ctx.textBaseline = 'middle';
  for (let o = 0; o < ops.length; o += 7) {
    const pen = pens[ops[o + 1]];
    const n = ops[o + 3];
    switch (ops[o]) {
      case 0: {
        const closed = ops[o + 2] === 1;
        const end = n + ops[o + 4];
        const first = ops[o + 5];
        const count = ops[o + 6];
        ctx.beginPath();
        for (let s = 0; s < count; s++) {
          const a = spans[first + s];
          const b = s + 1 < count ? spans[first + s + 1] : end;
          ctx.moveTo(nums[a], nums[a + 1]);
          for (let k = a + 2; k < b; k += 2) ctx.lineTo(nums[k], nums[k + 1]);
          if (closed) ctx.closePath();
        }
        finish(ctx, pen, closed);
        break;
      }
      case 1:
        ctx.beginPath();
        ctx.arc(nums[n], nums[n + 1], nums[n + 2], 0, Math.PI * 2);
        finish(ctx, pen, true);
        break;
      case 2:
        text(ctx, nums[n], nums[n + 1], nums[n + 2], texts[ops[o + 6]], ALIGN[ops[o + 2]], pen, pens[ops[o + 5]]);
        break;
      default:
        break;
    }
  }
  ctx.restore();
}

/** Fills (closed shapes) and strokes the current path with `pen`. */
function finish(ctx, pen, closed) {
  ctx.globalAlpha = pen.alpha;
  if (closed && pen.fill) {
    ctx.fillStyle = pen.fill;
    ctx.fill();
  }
  if (pen.stroke) {
    ctx.setLineDash(pen.dash);
    ctx.strokeStyle = pen.stroke;
    ctx.lineWidth = pen.width;
    ctx.stroke();
  }
}

/** A line of text at (x, y), rotated by `angle` degrees, over its halo. */
function text(ctx, x, y, angle, s, align, pen, halo) {
  ctx.save();
  ctx.translate(x, y);
  if (angle) ctx.rotate((angle * Math.PI) / 180);
  ctx.textAlign = align;
  ctx.globalAlpha = pen.alpha;
  ctx.setLineDash([]);
  ctx.lineWidth = halo.width;
  ctx.strokeStyle = halo.stroke;
  ctx.strokeText(s, 0, 0);
  ctx.fillStyle = pen.fill;
  ctx.fillText(s, 0, 0);
  ctx.restore();
}
