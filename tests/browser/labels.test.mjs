// Browser test of the drawings' labels: node labels.test.mjs http://127.0.0.1:PORT/
//
// For every view (side, tooth, starts) of O1006, a G76, a taper thread with
// its length (O0009), a two-start thread (G92 L2) and the L99 program, in the
// app at its layout (1400×900) and at 390×844, and in an embed with all four
// views (on the docs page, 1280 and 390 wide), in English and in Chinese:
// every label's box is inside its view, no two boxes overlap, and the chosen
// thread's major, minor and lead are there. The app's SVG export of each view
// (the core's writer, given the view's transform and labels) holds every
// label inside its viewBox \`0 0 W H\`, where the canvas put it: one display
// list, made by the core, painted by both (the embed has
// no SVG export; its canvases are checked). The embed with four
// views leaves no empty cell and gives the table its width or its own row. The
// cursor on a G76/G78 line keeps the pass colours (pixels counted with and
// without the mark, on the page's own canvases: ?engine=page). Every embed of
// the docs page passes the label checks too. Screenshots (English and
// Chinese: app, docs page, embed with four views) go to
// tests/browser/screenshots/labels-*.png, to be looked at.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const base = siteUrl('labels.test.mjs');
const { check, counts } = checker();
const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const example = (f) => fs.readFileSync(path.join(root, 'examples', f), 'utf8');

const PROGRAMS = [
  { name: 'o1006', dialect: 'gsk980tdc', text: example('o1006.nc'), hot: 'N40 G32' },
  { name: 'g76', dialect: 'fanuc0i', text: example('g76-fanuc.nc'), hot: 'G76 X60.64' },
  { name: 'taper', dialect: 'gsk980tdc', text: example('o0009.nc'), hot: 'G32 X48.8571' },
  { name: 'two-start', dialect: 'gsk980tdc', text: example('g92-two-start.nc'), hot: 'G92 X23.2' },
  { name: 'l99', dialect: 'gsk980tdc', text: 'G00 X100 Z5\nG78 P1060 Q10 R0.01 L99\nG78 X40 Z-30 P9000 Q300 F2\n', hot: 'G78 X40' },
];
const VIEWS = ['side', 'tooth', 'starts'];
/** The label font of the display lists (src/draw.rs FONT_FAMILY). */
const FONT = "12px 'DejaVu Sans', 'Noto Sans CJK SC', 'Microsoft YaHei', system-ui, -apple-system, 'Segoe UI', sans-serif";
/** The height of a label's box (LINE in src/draw/labels.rs). */
const LINE = 15;

function fragment(state) {
  const z = zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 });
  return '#z=' + z.toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

const { context, close } = await launch('screwcut-labels-', { acceptDownloads: true, viewport: { width: 1400, height: 900 } });
const timer = guard(420, 'the labels test');
const problems = [];
context.on('page', (p) => {
  p.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  p.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
});

/** What is wrong with labels `l` ({size, placed, dropped}) of a view: outside, overlapping, a must missing. */
function faults(l, must) {
  const out = [];
  if (!l) return ['no labels reported'];
  if (!l.placed.length) return ['no label drawn'];
  const [w, h] = l.size;
  const eps = 0.5;
  for (const p of l.placed) {
    const [x0, y0, x1, y1] = p.box;
    if (x0 < -eps || y0 < -eps || x1 > w + eps || y1 > h + eps) out.push(`"${p.lines.join(' ')}" outside ${w}×${h}: ${p.box.join(',')}`);
  }
  for (let i = 0; i < l.placed.length; i++)
    for (let j = i + 1; j < l.placed.length; j++) {
      const a = l.placed[i].box;
      const b = l.placed[j].box;
      if (a[0] < b[2] - eps && b[0] < a[2] - eps && a[1] < b[3] - eps && b[1] < a[3] - eps) out.push(`"${l.placed[i].lines.join(' ')}" overlaps "${l.placed[j].lines.join(' ')}"`);
    }
  for (const key of must) if (!l.placed.some((p) => p.key === key)) out.push(`no ${key} label`);
  return out;
}

/** The labels each view must show: the chosen thread's major, minor and lead. */
const MUST = { side: ['dia_major', 'dia_minor', 'lead'], tooth: ['height', 'pitch'], starts: ['lead'] };

/** Widths of `texts` in the label font, measured in the page. */
const widths = (page, texts) =>
  page.evaluate(
    ([texts, font]) => {
      const ctx = document.createElement('canvas').getContext('2d');
      ctx.font = font;
      return texts.map((t) => ctx.measureText(t).width);
    },
    [texts, FONT],
  );

/** The texts of an SVG export: centre, angle and text. */
function svgTexts(svg) {
  const un = (s) => s.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&amp;/g, '&');
  const out = [];
  const re = /<text x="([-\d.e]+)" y="([-\d.e]+)" text-anchor="(\w+)" dominant-baseline="(\w+)"(?: transform="rotate\(([-\d.]+) [^)]*\)")?[^>]*>([^<]*)<\/text>/g;
  for (const m of svg.matchAll(re)) out.push({ x: Number(m[1]), y: Number(m[2]), anchor: m[3], baseline: m[4], angle: Number(m[5] || 0), text: un(m[6]) });
  const size = /viewBox="0 0 ([\d.]+) ([\d.]+)"/.exec(svg);
  return { texts: out, w: size ? Number(size[1]) : 0, h: size ? Number(size[2]) : 0, count: (svg.match(/<text /g) || []).length };
}

/** What is wrong with an SVG export against the canvas's labels `l`. */
async function svgFaults(page, svg, l) {
  const s = svgTexts(svg);
  const out = [];
  if (s.count !== s.texts.length) out.push(`${s.count - s.texts.length} texts not centred on their place`);
  const ws = await widths(page, s.texts.map((t) => t.text));
  s.texts.forEach((t, k) => {
    const [bw, bh] = t.angle ? [LINE, ws[k] + 4] : [ws[k] + 4, LINE];
    const cx = t.anchor === 'start' ? t.x - 2 + bw / 2 : t.anchor === 'end' ? t.x + 2 - bw / 2 : t.x;
    const box = [cx - bw / 2, t.y - bh / 2, cx + bw / 2, t.y + bh / 2];
    if (box[0] < -0.5 || box[1] < -0.5 || box[2] > s.w + 0.5 || box[3] > s.h + 0.5) out.push(`"${t.text}" outside the viewBox ${s.w}×${s.h}`);
  });
  if (l) {
    // A label wrapped on several lines is one text per line, a line apart.
    let lines = 0;
    for (const p of l.placed) {
      if (!p.lines.some(Boolean)) continue;
      const cx = (p.box[0] + p.box[2]) / 2;
      const cy = (p.box[1] + p.box[3]) / 2;
      const x = p.align === 'start' ? p.box[0] + 2 : p.align === 'end' ? p.box[2] - 2 : cx;
      p.lines.forEach((line, k) => {
        lines++;
        const y = cy + (k - (p.lines.length - 1) / 2) * LINE;
        if (!s.texts.some((t) => t.text === line && t.anchor === p.align && Math.abs(t.x - x) < 0.6 && Math.abs(t.y - y) < 0.6)) out.push(`"${line}" is not where the canvas put it`);
      });
    }
    if (s.texts.length !== lines) out.push(`${s.texts.length} texts in the SVG, ${lines} lines of labels on the canvas`);
  }
  return out;
}

const summary = (l) => `${l ? l.placed.length : 0} labels${l && l.dropped ? `, ${l.dropped} left out` : ''}`;

/** Opens the app with `prog` in a page of `size`, in `lang`. */
async function openApp(prog, size, lang, query = '') {
  const page = await context.newPage();
  await page.setViewportSize(size);
  await page.goto(base + query + fragment({ dialect: prog.dialect, settings: {}, program: prog.text }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForFunction(() => window.__screwcut.result && window.__screwcut.result.threads.length > 0, null, { timeout: 30_000 });
  if (lang === 'zh') await page.click('#lang');
  await page.waitForTimeout(500);
  return page;
}

try {
  // ---- the app, at its layout and at 390 × 844, English and Chinese ----
  for (const size of [
    { width: 1400, height: 900 },
    { width: 390, height: 844 },
  ]) {
    for (const prog of PROGRAMS) {
      for (const lang of ['en', 'zh']) {
        const page = await openApp(prog, size, lang);
        const where = `app ${size.width}×${size.height} ${lang} ${prog.name}`;
        for (const v of VIEWS) {
          const l = await page.evaluate((v) => window.__screwcut.inspect('labels', v), v);
          const bad = faults(l, MUST[v]);
          check(`${where} ${v}: ${summary(l)} inside the view, none overlapping`, bad.length === 0, bad.slice(0, 6).join('; '));
          if (size.width === 1400) {
            const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`#${v}-panel [data-act="svg"]`)]);
            const svg = fs.readFileSync(await dl.path(), 'utf8');
            const sbad = await svgFaults(page, svg, l);
            check(`${where} ${v}: the SVG export has every label inside its viewBox, where the canvas has it`, sbad.length === 0, sbad.slice(0, 6).join('; '));
          }
        }
        if (size.width === 1400) await page.screenshot({ path: path.join(shots, `labels-app-${prog.name}-${lang}.png`) });
        else {
          for (const v of VIEWS) {
            await page.locator(`#${v}-panel`).scrollIntoViewIfNeeded();
            await page.locator(`#${v}-panel`).screenshot({ path: path.join(shots, `labels-app-390-${prog.name}-${lang}-${v}.png`) });
          }
        }
        await page.close();
      }
    }
  }

  // ---- zoomed and panned: labels still inside the view, none overlapping ----
  {
    const page = await openApp(PROGRAMS[1], { width: 1400, height: 900 }, 'zh');
    for (const v of VIEWS) {
      const box = await page.locator(`#${v}`).boundingBox();
      await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.55);
      await page.mouse.wheel(0, -200);
      await page.waitForTimeout(100);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width * 0.4 + 30, box.y + box.height * 0.55 - 20, { steps: 4 });
      await page.mouse.up();
      await page.waitForTimeout(300);
      const l = await page.evaluate((v) => window.__screwcut.inspect('labels', v), v);
      const xf = await page.evaluate(async (v) => (await window.__screwcut.inspect('view', v)).transform, v);
      const bad = faults(l, []);
      check(`zoomed in ×${xf.sx.toFixed(1)} and panned, ${v}: ${summary(l)} inside the view, none overlapping`, bad.length === 0, bad.slice(0, 6).join('; '));
    }
    await page.screenshot({ path: path.join(shots, 'labels-zoomed-g76-zh.png') });
    await page.close();
  }

  // ---- the cursor line's mark keeps the pass colours ----
  for (const prog of PROGRAMS.filter((p) => ['g76', 'l99'].includes(p.name))) {
    const page = await openApp(prog, { width: 1400, height: 900 }, 'en', '?engine=page');
    /** Pixels of the pass colours (cut blue, finish green; in the tooth every saturated hue but the mark's amber) and of the mark. */
    const colours = () =>
      page.evaluate(() => {
        const out = {};
        for (const name of ['side', 'tooth']) {
          const c = document.getElementById(name);
          const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          let pass = 0;
          let mark = 0;
          for (let i = 0; i < d.length; i += 4) {
            if (d[i + 3] < 128) continue;
            const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
            const max = Math.max(r, g, b);
            const min = Math.min(r, g, b);
            const sat = max ? (max - min) / max : 0;
            let hue = 0;
            if (max > min) {
              if (max === r) hue = (60 * (g - b)) / (max - min);
              else if (max === g) hue = 120 + (60 * (b - r)) / (max - min);
              else hue = 240 + (60 * (r - g)) / (max - min);
              hue = (hue + 360) % 360;
            }
            const amber = sat > 0.35 && hue >= 25 && hue <= 55;
            if (amber) mark++;
            if (name === 'side') {
              if (Math.hypot(r - 37, g - 99, b - 235) < 70 || Math.hypot(r - 5, g - 150, b - 105) < 70) pass++;
            } else if (sat > 0.3 && !amber) pass++;
          }
          out[name] = { pass, mark };
        }
        return out;
      });
    await page.locator('.cm-line').last().click();
    await page.waitForTimeout(300);
    const plain = await colours();
    await page.locator('.cm-line', { hasText: prog.hot }).first().click();
    await page.waitForTimeout(300);
    const marked = await colours();
    const mark = await page.evaluate(async () => (await window.__screwcut.inspect('view', 'side')).mark);
    check(`${prog.name}: the cursor on its ${prog.hot.split(' ')[0]} line (${mark.lines.join(',')}) marks the side section`, mark.light && mark.lines.length === 1 && marked.side.mark > plain.side.mark, JSON.stringify({ plain, marked }));
    for (const v of ['side', 'tooth']) {
      const kept = marked[v].pass / Math.max(plain[v].pass, 1);
      check(`${prog.name} ${v}: the mark keeps the pass colours (${plain[v].pass} → ${marked[v].pass} pixels, ${(100 * kept).toFixed(0)} %)`, plain[v].pass > 200 && kept >= 0.9, JSON.stringify({ plain: plain[v], marked: marked[v] }));
    }
    await page.screenshot({ path: path.join(shots, `labels-cursor-${prog.name}.png`) });
    // What the pointer is over (a row of the table) keeps them too.
    await page.locator('#passes tbody tr[data-pass]').first().hover();
    await page.waitForTimeout(300);
    const hovered = await colours();
    const keptHover = hovered.side.pass / Math.max(plain.side.pass, 1);
    check(`${prog.name}: hovering pass 1 keeps the pass colours (${(100 * keptHover).toFixed(0)} %)`, keptHover >= 0.9, JSON.stringify(hovered));
    await page.close();
  }

  // ---- embeds: four views of each program, and every embed of the docs page ----
  for (const width of [1280, 390]) {
    const page = await context.newPage();
    await page.setViewportSize({ width, height: 900 });
    await page.goto(`${base}docs.html`);
    await page.evaluate(() => customElements.whenDefined('screwcut-preview'));
    await page.evaluate((programs) => {
      const at = document.querySelector('main h1');
      for (const lang of ['zh', 'en'])
        for (const p of [...programs].reverse()) {
          const el = document.createElement('screwcut-preview');
          el.id = `four-${p.name}-${lang}`;
          el.setAttribute('view', 'side tooth starts table');
          el.setAttribute('dialect', p.dialect);
          el.setAttribute('lang', lang);
          el.setAttribute('hide-code', '');
          el.textContent = p.text;
          at.after(el);
        }
    }, PROGRAMS);
    const ids = await page.evaluate(() => [...document.querySelectorAll('screwcut-preview')].map((e) => e.id));
    for (const id of ids) {
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      await page.waitForFunction((id) => ['ready', 'error'].includes(document.getElementById(id).dataset.state), id, { timeout: 20_000 });
      await page.waitForTimeout(250);
      const got = await page.evaluate((id) => {
        const el = document.getElementById(id);
        const out = { views: {}, cells: [] };
        for (const [name, v] of Object.entries(el._views)) out.views[name] = v.labels();
        const grid = el.shadowRoot.querySelector('.views').getBoundingClientRect();
        for (const cell of el.shadowRoot.querySelectorAll('.views > .view')) {
          const r = cell.getBoundingClientRect();
          out.cells.push({ view: cell.dataset.view, x: r.left - grid.left, y: r.top - grid.top, w: r.width, h: r.height });
        }
        out.grid = { w: grid.width, h: grid.height };
        const t = el.shadowRoot.querySelector('.view.table');
        out.table = t && { shown: t.clientWidth, needs: t.querySelector('table').scrollWidth, row: t.getBoundingClientRect().width };
        return out;
      }, id);
      const four = id.startsWith('four-');
      const where = `embed ${width} ${id}`;
      for (const [name, l] of Object.entries(got.views)) {
        // The docs' embeds show the first thread; its dimensions must be there.
        const bad = faults(l, four ? MUST[name] : []);
        check(`${where} ${name}: ${summary(l)} inside the view, none overlapping`, bad.length === 0, bad.slice(0, 6).join('; '));
      }
      // The grid: its cells tile it (no empty cell), the table in a row of its own or wide enough.
      const area = got.cells.reduce((a, c) => a + (c.w + 1) * (c.h + 1), 0);
      const gridArea = (got.grid.w + 1) * (got.grid.h + 1);
      check(`${where}: the views fill the grid, no empty cell (${got.cells.map((c) => `${c.view} ${Math.round(c.w)}×${Math.round(c.h)}`).join(', ')})`, Math.abs(area - gridArea) / gridArea < 0.02, `${area} of ${gridArea}`);
      if (got.table) {
        const ownRow = Math.abs(got.table.row - got.grid.w) < 2;
        check(`${where}: the table has a row of its own or the width of its columns (${got.table.shown} of ${got.table.needs} px)`, ownRow || got.table.shown >= got.table.needs, JSON.stringify(got.table));
      }
      if (four) {
        if (id.endsWith('two-start-en') || id.endsWith('two-start-zh') || id.endsWith('l99-zh')) await page.locator(`#${id}`).screenshot({ path: path.join(shots, `labels-embed-${width}-${id}.png`) });
      } else await page.locator(`#${id}`).screenshot({ path: path.join(shots, `labels-docs-${width}-en-${id}.png`) });
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.screenshot({ path: path.join(shots, `labels-docs-${width}-en.png`) });
    // The docs page's embeds in Chinese.
    await page.evaluate(() => {
      for (const el of document.querySelectorAll('screwcut-preview')) el.setAttribute('lang', 'zh');
    });
    for (const id of ids.filter((i) => !i.startsWith('four-'))) {
      await page.locator(`#${id}`).scrollIntoViewIfNeeded();
      await page.waitForTimeout(200);
      const views = await page.evaluate((id) => Object.fromEntries(Object.entries(document.getElementById(id)._views).map(([n, v]) => [n, v.labels()])), id);
      for (const [name, l] of Object.entries(views)) {
        const bad = faults(l, []);
        check(`embed ${width} ${id} zh ${name}: ${summary(l)} inside the view, none overlapping`, bad.length === 0, bad.slice(0, 6).join('; '));
      }
      await page.locator(`#${id}`).screenshot({ path: path.join(shots, `labels-docs-${width}-zh-${id}.png`) });
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.screenshot({ path: path.join(shots, `labels-docs-${width}-zh.png`) });
    await page.close();
  }
  check('no console or page errors', problems.length === 0, JSON.stringify(problems.slice(0, 5)));
} catch (e) {
  check('the labels test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}

finish('labels', counts);
