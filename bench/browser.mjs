// In headless Chromium (the system package, software rendering), what a
// person typing feels, measured by the browser itself:
// - Event Timing: keystroke to the next paint (`PerformanceEventTiming`, the
//   interaction's longest entry), p50 and p95, typing and deleting a digit in
//   the first pass of a 5,000- and a 50,000-line program, and in a 5,000-line
//   Fanuc 0i program of subprograms and macro loops (LOOPS_5000, written by
//   `cargo bench --bench throughput`): in its main program's first thread
//   and in the body of its common threading macro O9010;
// - the app's marks: keystroke to the committed drawing that includes it
//   (`performance.mark('screwcut:frame', {detail: {input}})`);
// - long tasks on the page's thread while typing; the worker's re-plan and
//   its drawing of the views (display lists and canvas calls);
// - the 3-line L99 program (334,125 motions) opened from a link: the page
//   ready, a click answered, a keystroke's Event Timing;
// - one block-by-block thread of many passes put into the editor at 0.5, 1,
//   2 and 5 MB: the change to its plan on the page (cost in proportion);
// - the wasm planner's rate on the 20 MB program, on the page;
// - the floor: the project's own editor alone (bench/editor-alone.js) and the
//   app typed into alternately, the same keys at the same line of the same
//   5,000- and 50,000-line program: keystroke to next paint on the bare
//   editor, keystroke to the diagram on screen in the app (the later of the
//   next paint and the committed drawing that includes the keystroke),
//   and their ratio;
// - a first load's transferred bytes by file (Resource Timing, the site's
//   precompressed files served as a static host serves them): the app and a
//   page with one embedded diagram.
// Usage: node browser.mjs SITE_DIR PKG_DIR PROGRAM_20MB LOOPS_5000
// Prints figures, and `FIG name value` lines for `cargo xtask bench`;
// asserts nothing.
import { chromium } from 'playwright-core';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

const [site, pkg, big, loops] = process.argv.slice(2);
const here = path.dirname(new URL(import.meta.url).pathname);
const www = path.join(here, '..', 'www');
/** The bare editor's page and bundle (esbuild from www's packages), and the texts it opens. */
const alone = {
  html: '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>editor alone</title><link rel="stylesheet" href="style.css"></head>' +
    '<body><section id="code" style="position:fixed;left:0;top:0"><div id="editor"></div></section><script type="module" src="editor-alone.js"></script></body></html>',
  js: execFileSync(path.join(www, 'node_modules', '.bin', 'esbuild'), [path.join(here, 'editor-alone.js'), '--bundle', '--format=esm', '--target=es2022', '--minify'], { cwd: www, maxBuffer: 1 << 26 }),
  texts: new Map(),
};
/** The embedded diagram's program. */
const embedProgram = 'G00 X58 Z70\nG92 X47.1 Z13 F2\nX46.5\nX45.9\nX45.5\nX45.4\nG00 X100 Z100\nM30\n';
/** A page with one embedded diagram: `element` in its body. */
const embedPageWith = (element) =>
  '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>one diagram</title><script type="module" src="screwcut-preview.js"></script></head><body>' +
  `${element}</body></html>`;
/** The pages the bench serves itself, by path: the embed pages are added by the step that loads them. */
const pages = {
  '/blank.html': '<!doctype html><title>screwcut bench</title>',
  '/editor-alone.html': alone.html,
  // The element as the element's README shows it.
  '/embed-bench.html': embedPageWith(`<screwcut-preview dialect="gsk980tdc" view="side">${embedProgram}</screwcut-preview>`),
};
const encodings = [['br', '.br'], ['gzip', '.gz']];
/** The site's files served, with the bytes sent (a first load reads it). */
const served = [];
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json', '.svg': 'image/svg+xml', '.nc': 'text/plain' };
/** The site, the wasm-bindgen glue under /pkg/, the 20 MB program as /bench-20mb.nc. */
const server = http.createServer((req, res) => {
  const url = decodeURIComponent(req.url.split('?')[0]);
  let file;
  const page = pages[url];
  if (page) {
    // An embed page is sent compressed, as a host would send it, and counted in its first load
    // (the static drawing inside is part of what the page costs).
    if (url.startsWith('/embed') && String(req.headers['accept-encoding'] || '').includes('br')) {
      const packed = zlib.brotliCompressSync(page, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } });
      res.writeHead(200, { 'content-type': 'text/html', 'content-encoding': 'br' });
      served.push({ name: url.slice(1), bytes: packed.length, encoding: 'br' });
      return res.end(packed);
    }
    res.writeHead(200, { 'content-type': 'text/html' });
    return res.end(page);
  }
  if (url === '/editor-alone.js') {
    res.writeHead(200, { 'content-type': 'text/javascript' });
    return res.end(alone.js);
  }
  if (alone.texts.has(url)) {
    res.writeHead(200, { 'content-type': 'text/plain' });
    return res.end(alone.texts.get(url));
  }
  if (url === '/bench-20mb.nc') file = big;
  else if (url.startsWith('/pkg/')) file = path.join(pkg, url.slice(5));
  else file = path.join(site, url.endsWith('/') ? url + 'index.html' : url);
  const inside = file === big || file.startsWith(path.resolve(site)) || file.startsWith(path.resolve(pkg));
  if (!inside || !fs.existsSync(file)) {
    res.writeHead(404);
    return res.end();
  }
  // The site's precompressed files, as a static host serves them (`cargo xtask serve` does the same).
  const accepted = String(req.headers['accept-encoding'] || '');
  const packed = file.startsWith(path.resolve(site)) && encodings.find(([name, suffix]) => accepted.includes(name) && fs.existsSync(file + suffix));
  const headers = { 'content-type': types[path.extname(file)] || 'application/octet-stream', 'cache-control': 'no-cache' };
  if (packed) headers['content-encoding'] = packed[0];
  res.writeHead(200, headers);
  const sent = packed ? file + packed[1] : file;
  served.push({ name: path.basename(file), bytes: fs.statSync(sent).size, encoding: packed ? packed[0] : 'none' });
  fs.createReadStream(sent).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const url = `http://127.0.0.1:${server.address().port}/`;

/** The browser test's program: O1006-style threads between turning moves, `lines` long. */
function program(lines) {
  const out = ['O2000', 'G50 X100 Z100', 'S300 M03 T0101'];
  let n = 0;
  while (out.length < lines - 1) {
    const d = 30 + (n % 20);
    out.push(`G00 X${d + 10} Z70`, `G01 X${d} F0.2`, `Z20`, `X${d + 5}`, `G00 Z70`);
    for (const x of [0.9, 1.5, 2.1, 2.5, 2.6]) out.push(`X${(d - x).toFixed(1)}`, 'G32 Z13 F2', `G00 X${d + 10}`, 'Z70');
    n++;
  }
  out.push('M30');
  return out.slice(0, lines).join('\n') + '\n';
}
const fragment = (state) =>
  '#z=' + zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 }).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
/** The q-quantile of `a` (nearest rank). */
const quantile = (a, q) => {
  const s = [...a].sort((x, y) => x - y);
  return s.length ? s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))] : NaN;
};
const fig = (name, value) => console.log(`FIG ${name} ${Number.isFinite(value) ? value.toFixed(2) : 'NaN'}`);

/** Observers on the page's thread from its first script: Event Timing (every entry of 16 ms and more, the API's floor) and long tasks. */
function observe() {
  self.__events = [];
  self.__long = [];
  new PerformanceObserver((l) => {
    for (const e of l.getEntries()) if (e.interactionId) self.__events.push({ id: e.interactionId, name: e.name, start: e.startTime, d: e.duration });
  }).observe({ type: 'event', durationThreshold: 16, buffered: true });
  new PerformanceObserver((l) => self.__long.push(...l.getEntries().map((e) => ({ start: e.startTime, d: e.duration })))).observe({ type: 'longtask', buffered: true });
  // Next paint as a page sees it: a frame callback, then a task after that frame.
  // `k.frame`: the frame's time (the frame callback's argument); `k.callback`: when that callback ran.
  const afterPaint = (f, k) => requestAnimationFrame((frame) => {
    k.frame = frame;
    k.callback = performance.now();
    const c = new MessageChannel();
    c.port1.onmessage = () => f(performance.now());
    c.port2.postMessage(0);
  });
  // Each key pressed, and the paint after it; each drawing committed (the app's mark).
  self.__keys = [];
  self.__drawn = [];
  addEventListener('keydown', (e) => {
    const k = { t: e.timeStamp, paint: NaN };
    self.__keys.push(k);
    afterPaint((t) => (k.paint = t), k);
  }, true);
  // The app marks a drawing once its frame is committed (after the worker's next animation frame, which pushes its canvases).
  const mark = performance.mark.bind(performance);
  performance.mark = (name, options) => {
    const entry = mark(name, options);
    if (name === 'screwcut:frame') self.__drawn.push({ input: options.detail.input, shown: entry.startTime });
    return entry;
  };
}

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'screwcut-bench-'));
const LAUNCH = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'];
const ctx = await chromium.launchPersistentContext(dir, {
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: LAUNCH,
  viewport: { width: 1400, height: 900 },
});
await ctx.addInitScript(observe);

/** Puts the cursor at the end of line `line` (0-based) as a person would: from the top, or from the end when nearer. */
async function cursorTo(page, text, line, tag) {
  await page.locator('.cm-line').first().click();
  const last = text.split('\n').length - 1;
  if (line <= last / 2) for (let i = 0; i < line; i++) await page.keyboard.press('ArrowDown');
  else {
    await page.keyboard.press('Control+End');
    for (let i = last; i > line; i--) await page.keyboard.press('ArrowUp');
  }
  await page.keyboard.press('End');
  const at = await page.evaluate(() => document.querySelector('.cm-activeLineGutter')?.textContent);
  if (Number(at) !== line + 1) throw new Error(`${tag}: the cursor is on line ${at}, not ${line + 1}`);
}

/** A new page with `text` opened from a link, once planned (more than 100 threads, as both long programs have). */
async function openPlanned(text, dialect) {
  const page = await ctx.newPage();
  await page.goto(url + fragment({ dialect, settings: {}, program: text }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 120_000 });
  await page.waitForFunction(() => window.__screwcut.result && window.__screwcut.result.threads.length > 100, null, { timeout: 120_000 });
  return page;
}

/**
 * How long a key is held down. A person's key comes up tens of milliseconds
 * after it went down; Playwright's `press` lets it up at once. Chromium
 * defers a page's ordinary tasks after a discrete input event until the next
 * frame (`DeferRendererTasksAfterInput`, enabled by default): a keyup that
 * lands while the keystroke's frame is being made holds the task this bench
 * reads the paint by (and the page's own tasks) until the frame after, a
 * whole frame late although the keystroke was already on screen. A trace
 * showed it on both pages, more often on the app, whose frame begins sooner.
 */
const HOLD_MS = 60;

/** Types and deletes a digit at the cursor `keys` times, 150 ms apart (each held HOLD_MS), then waits 1.5 s; returns when it began (page time). */
async function typeDigits(page, keys) {
  const t0 = await page.evaluate(() => performance.now());
  for (let i = 0; i < keys; i++) {
    await page.keyboard.press(i % 2 ? 'Backspace' : String(1 + ((i / 2) % 9)), { delay: HOLD_MS });
    await page.waitForTimeout(150 - HOLD_MS);
  }
  await page.waitForTimeout(1500);
  return t0;
}

/**
 * The floor: the bare editor and the app, the same `text` at the same line,
 * typed into alternately, `rounds` rounds of `keys` keystrokes each (a digit
 * typed and deleted, 150 ms apart). On the bare editor a keystroke counts to
 * its next paint; in the app to the diagram on screen: the later of its next
 * paint and the first committed drawing that includes it (the app's mark). Prints
 * p50/p95 of both and their ratio; long tasks in the app while typing; of
 * the app's, its own next paint and its drawing apart (which one the figure
 * waited for); where the next paint goes in both (the frame's time, its
 * callbacks, the task after it); and the page alone: the app with its edits
 * not planned (`hold`), to its next paint, against the same floor.
 */
async function versus({ text, dialect, line, rounds, keys, tag, what }) {
  const app = await openPlanned(text, dialect);
  const pane = await app.evaluate(() => {
    const r = document.getElementById('code').getBoundingClientRect();
    return { w: Math.round(r.width), h: Math.round(r.height) };
  });
  const name = `/text-${tag}.nc`;
  alone.texts.set(name, text);
  const bare = await ctx.newPage();
  await bare.goto(`${url}editor-alone.html?program=${encodeURIComponent(name)}&w=${pane.w}&h=${pane.h}`);
  await bare.waitForSelector('body[data-ready="true"]', { timeout: 120_000 });
  await cursorTo(app, text, line, `${tag} app`);
  await cursorTo(bare, text, line, `${tag} bare`);
  const floor = [];
  const screen = [];
  const held = [];
  const split = []; // the app's keystrokes: its own next paint and its drawing
  const long = [];
  const phases = { bare: [], app: [] }; // each keystroke's frame, its callback and the task after it, from the key
  const work = { bare: [], app: [] }; // from the frame's beginning to the figure (the paint, or the app's diagram on screen)
  for (let r = 0; r < rounds; r++) {
    for (const [page, into] of [[bare, floor], [app, screen], [app, held]]) {
      await page.bringToFront();
      // The page alone: the app with its edits held (not planned), to its next paint.
      if (into === held) await app.evaluate(() => (window.__screwcut.hold = true));
      await page.waitForTimeout(600);
      const t0 = await typeDigits(page, keys);
      if (into === held) await app.evaluate(() => (window.__screwcut.hold = false));
      const m = await page.evaluate((t0) => ({ keys: self.__keys.filter((k) => k.t > t0), drawn: self.__drawn, long: self.__long.filter((e) => e.start > t0) }), t0);
      for (const k of m.keys) {
        if (into !== held) phases[page === bare ? 'bare' : 'app'].push({ frame: k.frame - k.t, callback: k.callback - k.t, paint: k.paint - k.t });
        if (page === bare) work.bare.push(k.paint - k.frame);
        if (page === bare || into === held) into.push(k.paint - k.t);
        else {
          const shown = Math.min(...m.drawn.filter((d) => d.input >= k.t).map((d) => d.shown));
          into.push(Math.max(k.paint, shown) - k.t);
          work.app.push(Math.max(k.paint, shown) - k.frame);
          split.push({ paint: k.paint - k.t, drawn: shown - k.t });
        }
      }
      if (page === app) long.push(...m.long);
    }
  }
  await app.close();
  await bare.close();
  alone.texts.delete(name);
  const q = (a, p) => quantile(a, p);
  const ratio = (p) => q(screen, p) / q(floor, p);
  console.log(
    `  ${what}: the editor alone and the app typed into alternately (${rounds} rounds of ${keys} keystrokes each, code pane ${pane.w}×${pane.h}): ` +
      `bare editor keystroke → next paint p50 ${q(floor, 0.5).toFixed(1)} ms, p95 ${q(floor, 0.95).toFixed(1)} ms (${floor.length}); ` +
      `app keystroke → diagram on screen p50 ${q(screen, 0.5).toFixed(1)} ms, p95 ${q(screen, 0.95).toFixed(1)} ms (${screen.filter(Number.isFinite).length} of ${screen.length} drawn); ` +
      `ratio p50 ${ratio(0.5).toFixed(2)}×, p95 ${ratio(0.95).toFixed(2)}×; app long tasks ${long.length} (longest ${Math.max(0, ...long.map((e) => e.d)).toFixed(0)} ms); ` +
      `the page alone (the app with its edits not planned) keystroke → next paint p50 ${q(held, 0.5).toFixed(1)} ms, p95 ${q(held, 0.95).toFixed(1)} ms, ` +
      `ratio p50 ${(q(held, 0.5) / q(floor, 0.5)).toFixed(2)}×, p95 ${(q(held, 0.95) / q(floor, 0.95)).toFixed(2)}×`,
  );
  // Which of the two the figure waited for: the page's own paint, or the worker's drawing.
  const later = split.filter((x) => x.drawn > x.paint + 1).length;
  const paint = q(split.map((x) => x.paint), 0.5);
  const drawn = q(split.map((x) => x.drawn), 0.5);
  console.log(`    … of which the app's own next paint p50 ${paint.toFixed(1)} ms, its drawing committed p50 ${drawn.toFixed(1)} ms; the drawing after the paint in ${later} of ${split.length}`);
  // Where the page's paint goes: its frame's time after the key (when the frame began: the display's
  // cadence), when the frame callbacks ran (later when the page's thread was busy), and the task after the frame.
  const phase = (who, part) => q(phases[who].map((x) => x[part]), 0.5);
  const show = (part) => `${phase('bare', part).toFixed(1)} / ${phase('app', part).toFixed(1)}`;
  console.log(
    `    … where the next paint goes, p50 from the key, bare editor / app: the frame begins ${show('frame')} ms, ` +
      `its frame callbacks run ${show('callback')} ms, the task after the frame ${show('paint')} ms`,
  );
  // From the frame's beginning: the figure without the wait for the display's cadence, which is
  // the same for both pages on average but, at a random phase, the largest part of each one's spread.
  const w = (who, p) => q(work[who], p).toFixed(1);
  console.log(`    … from the frame's beginning to the figure, bare editor / app: p50 ${w('bare', 0.5)} / ${w('app', 0.5)} ms, p95 ${w('bare', 0.95)} / ${w('app', 0.95)} ms`);
  fig(`${tag}_bare_work_p50`, q(work.bare, 0.5));
  fig(`${tag}_app_work_p50`, q(work.app, 0.5));
  fig(`${tag}_callback_gap_p50`, phase('app', 'callback') - phase('bare', 'callback'));
  fig(`${tag}_after_callback_gap_p50`, phase('app', 'paint') - phase('app', 'callback') - (phase('bare', 'paint') - phase('bare', 'callback')));
  fig(`${tag}_apppaint_p50`, paint);
  fig(`${tag}_drawn_p50`, drawn);
  fig(`${tag}_drawn_later`, later / Math.max(1, split.length));
  fig(`${tag}_alone_p50`, q(held, 0.5));
  fig(`${tag}_alone_ratio_p50`, q(held, 0.5) / q(floor, 0.5));
  fig(`${tag}_alone_ratio_p95`, q(held, 0.95) / q(floor, 0.95));
  fig(`${tag}_bare_p50`, q(floor, 0.5));
  fig(`${tag}_bare_p95`, q(floor, 0.95));
  fig(`${tag}_screen_p50`, q(screen, 0.5));
  fig(`${tag}_screen_p95`, q(screen, 0.95));
  fig(`${tag}_ratio_p50`, ratio(0.5));
  fig(`${tag}_ratio_p95`, ratio(0.95));
  fig(`${tag}_vs_long_max`, Math.max(0, ...long.map((e) => e.d)));
}

/**
 * A first load's transferred bytes by file, the page's and its worker's (the
 * site's files as the server sent them, compressed where the browser
 * accepted it; headers not counted): the page at `where`, once `ready`
 * holds, with a cold cache.
 */
async function firstLoad(where, ready, tag, what, then = null) {
  const fresh = fs.mkdtempSync(path.join(os.tmpdir(), 'screwcut-load-'));
  const cold = await chromium.launchPersistentContext(fresh, { executablePath: '/usr/bin/chromium', headless: true, args: LAUNCH, viewport: { width: 1400, height: 900 } });
  try {
    const page = await cold.newPage();
    served.length = 0;
    await page.goto(url + where);
    await page.waitForFunction(ready, null, { timeout: 120_000 });
    await page.waitForTimeout(1000);
    const files = [...served];
    const sum = files.reduce((s, f) => s + f.bytes, 0);
    const by = files.sort((a, b) => b.bytes - a.bytes).map((f) => `${f.name} ${(f.bytes / 1024).toFixed(1)} (${f.encoding})`);
    console.log(`  ${what}, first load transferred: ${(sum / 1024).toFixed(1)} KiB in all — KiB by file (encoding): ${by.join(', ')}`);
    fig(`${tag}_kib`, sum / 1024);
    if (then) await then(page, files);
  } finally {
    await cold.close();
    fs.rmSync(fresh, { recursive: true, force: true });
  }
}

/**
 * Opens `text` from a link (and waits for its plan: more than 100 threads,
 * which both 5,000-line programs have), puts the cursor at the end of its line `line`
 * (0-based; from the top with ArrowDown, or from the end with ArrowUp when
 * nearer the end, as a person would), types and deletes a digit there `keys`
 * times, 150 ms apart (a quick typist), and prints what the browser measured.
 */
async function typing({ text, dialect, line, keys, tag, what }) {
  const page = await openPlanned(text, dialect);
  await cursorTo(page, text, line, tag);
  await page.waitForTimeout(1000);
  const t0 = await typeDigits(page, keys);
  const m = await page.evaluate((t0) => {
    const marks = performance.getEntriesByName('screwcut:frame', 'mark').filter((e) => e.startTime > t0 && e.detail && e.detail.input > t0);
    return {
      events: self.__events.filter((e) => e.start > t0),
      long: self.__long.filter((e) => e.start > t0),
      marks: marks.map((e) => e.startTime - e.detail.input),
      plans: window.__screwcut.updates.filter((u) => u.sent > t0).map((u) => ({ plan: u.plan, views: u.views, draw: u.draw })),
    };
  }, t0);
  await page.close();
  // One interaction per keystroke: its longest entry (keydown, keyup). A keystroke that
  // painted within 16 ms has no entry (the API's floor): it counts as under 16 ms.
  const byId = new Map();
  for (const e of m.events) byId.set(e.id, Math.max(byId.get(e.id) || 0, e.d));
  const durations = [...byId.values()];
  while (durations.length < keys) durations.push(0);
  const p50 = quantile(durations, 0.5);
  const p95 = quantile(durations, 0.95);
  const show = (v) => (v < 16 ? '<16' : v.toFixed(0));
  const longSum = m.long.reduce((s, e) => s + e.d, 0);
  const longMax = Math.max(0, ...m.long.map((e) => e.d));
  console.log(
    `  ${what}, ${keys} keystrokes typing and deleting a digit: keystroke to next paint (Event Timing) ` +
      `p50 ${show(p50)} ms, p95 ${show(p95)} ms, max ${show(Math.max(...durations))} ms (${byId.size} of ${keys} keystrokes took 16 ms or more); ` +
      `keystroke to the committed drawing (marks, ${m.marks.length}) p50 ${quantile(m.marks, 0.5).toFixed(1)} ms, p95 ${quantile(m.marks, 0.95).toFixed(1)} ms; ` +
      `page long tasks: ${m.long.length} (${longSum.toFixed(0)} ms in all, longest ${longMax.toFixed(0)} ms); ` +
      `in the worker (${m.plans.length} plans) re-plan p50 ${quantile(m.plans.map((u) => u.plan), 0.5).toFixed(1)} ms, ` +
      `the answer given to the views p50 ${quantile(m.plans.map((u) => u.views), 0.5).toFixed(1)} ms, ` +
      `the views drawn (display lists and canvas calls) p50 ${quantile(m.plans.map((u) => u.draw), 0.5).toFixed(1)} ms`,
  );
  fig(`${tag}_replan_p50`, quantile(m.plans.map((u) => u.plan), 0.5));
  fig(`${tag}_draw_p50`, quantile(m.plans.map((u) => u.draw), 0.5));
  fig(`${tag}_event_p50`, p50);
  fig(`${tag}_event_p95`, p95);
  fig(`${tag}_mark_p50`, quantile(m.marks, 0.5));
  fig(`${tag}_long_max`, longMax);
  fig(`${tag}_long_sum`, longSum);
}

/** The 3-line L99 program from a link: the page ready, a click answered, one keystroke. */
async function l99() {
  const page = await ctx.newPage();
  const text = 'G00 X100 Z5\nG78 P1060 Q10 R0.01 L99\nG78 X40 Z-30 P9000 Q300 F2\n';
  const t0 = Date.now();
  await page.goto(url + fragment({ dialect: 'gsk980tdc', settings: {}, program: text }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  const ready = Date.now() - t0;
  const clicked = await page.evaluate(
    () =>
      new Promise((resolve) => {
        const t = performance.now();
        const b = document.getElementById('settings-toggle');
        b.addEventListener('click', () => requestAnimationFrame(() => resolve(performance.now() - t)), { once: true });
        b.click();
      }),
  );
  await page.locator('.cm-line').nth(2).click();
  await page.keyboard.press('End');
  await page.waitForTimeout(500);
  const k0 = await page.evaluate(() => performance.now());
  await page.keyboard.press('0');
  await page.waitForFunction((k0) => performance.getEntriesByName('screwcut:frame', 'mark').some((e) => e.startTime > k0), k0, { timeout: 60_000 });
  await page.waitForTimeout(500);
  const m = await page.evaluate((k0) => {
    const ev = self.__events.filter((e) => e.start > k0 - 1);
    const mark = performance.getEntriesByName('screwcut:frame', 'mark').find((e) => e.startTime > k0);
    return { event: Math.max(0, ...ev.map((e) => e.d)), mark: mark ? mark.startTime - mark.detail.input : NaN, long: self.__long.filter((e) => e.start > k0 - 1), plan: window.__screwcut.updates.at(-1).plan };
  }, k0);
  await page.close();
  console.log(
    `  L99 (3 lines, 66,825 passes, 334,125 motions) from a link: page ready ${ready} ms; a click answered to the next frame in ${clicked.toFixed(1)} ms; ` +
      `a keystroke to next paint ${m.event < 16 ? '<16' : m.event.toFixed(0)} ms, to the committed drawing ${m.mark.toFixed(0)} ms (re-plan in the worker ${m.plan.toFixed(0)} ms); ` +
      `page long tasks after the keystroke: ${m.long.length} (longest ${Math.max(0, ...m.long.map((e) => e.d)).toFixed(0)} ms)`,
  );
  fig('l99_ready', ready);
  fig('l99_click', clicked);
  fig('l99_key_event', m.event);
  fig('l99_key_mark', m.mark);
}

/**
 * One block-by-block thread of many passes (the four lines `X47.1 / G32
 * Z13.0 F2.0 / G00 X58.0 / Z70.0` repeated) put into the app's editor in one
 * change at 0.5, 1, 2 and 5 MB: the time from the change to the plan's
 * answer on the page (the work in proportion to the text: ms per MB).
 */
async function pasted() {
  const page = await ctx.newPage();
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
  const block = 'X47.1\nG32 Z13.0 F2.0\nG00 X58.0\nZ70.0\n';
  const parts = [];
  for (const mb of [0.5, 1, 2, 5]) {
    const text = `G00 X58.0 Z70.0\n${block.repeat(Math.ceil((mb * 1e6) / block.length))}`;
    const lines = text.split('\n').length;
    await page.evaluate(() => {
      const v = window.__screwcut.editor().view;
      v.dispatch({ changes: { from: 0, to: v.state.doc.length, insert: 'G00 X58 Z70\n' } });
    });
    await page.waitForFunction(() => window.__screwcut.updates.some((u) => u.lines === 2), null, { timeout: 60_000 });
    const ms = await page.evaluate(async ([text, lines]) => {
      const t = performance.now();
      const v = window.__screwcut.editor().view;
      v.dispatch({ changes: { from: 0, to: v.state.doc.length, insert: text } });
      while (!window.__screwcut.updates.some((u) => u.lines === lines)) await new Promise((r) => setTimeout(r, 5));
      return performance.now() - t;
    }, [text, lines]);
    const tag = String(mb).replace('.', '_');
    fig(`paste_${tag}mb`, ms);
    parts.push(`${mb} MB ${ms.toFixed(0)} ms (${(ms / mb).toFixed(0)} ms/MB)`);
  }
  await page.close();
  console.log(`  one thread of many passes put into the editor, to its plan on the page: ${parts.join(', ')}`);
}

/** The wasm planner on the 20 MB program, on a page of its own (glue from /pkg/, the site's optimised wasm). */
async function wasmRate() {
  const page = await ctx.newPage();
  await page.goto(url + 'blank.html');
  const r = await page.evaluate(async (base) => {
    const glue = await import(base + 'pkg/screwcut.js');
    await glue.default({ module_or_path: base + 'screwcut_bg.wasm' });
    const text = await (await fetch(base + 'bench-20mb.nc')).text();
    let best = Infinity;
    for (let i = 0; i < 3; i++) {
      const t = performance.now();
      glue.plan_summary(text, 'gsk980tdc', '');
      best = Math.min(best, performance.now() - t);
    }
    return { bytes: new TextEncoder().encode(text).length, best };
  }, url);
  await page.close();
  const rate = r.bytes / r.best / 1000;
  console.log(`  wasm planner on the page, 20 MB (${r.bytes} bytes): best of 3 ${r.best.toFixed(0)} ms = ${rate.toFixed(1)} MB/s`);
  fig('wasm_20mb_rate', rate);
}

// BENCH_ONLY=name,name runs only those steps (for working on one of them).
const only = process.env.BENCH_ONLY ? process.env.BENCH_ONLY.split(',') : null;
/** Steps that are parts of another step: run only when named. */
const PARTS = ['v5', 'v50'];
const gsk = { dialect: 'gsk980tdc', line: 8, keys: 20 };
const steps = {
  k5: () => typing({ ...gsk, text: program(5000), tag: 'k5', what: '5000 lines, in the first pass' }),
  // The same 20 keystrokes in the Fanuc program with subprograms and loops: at the end of the
  // main program's first `#1=` (the first thread's diameter) and of the macro O9010's `#10=#2*1.227`.
  loops: async () => {
    const text = fs.readFileSync(loops, 'utf8');
    const lines = text.split('\n');
    const fanuc = { dialect: 'fanuc0i', keys: 20, text };
    await typing({ ...fanuc, line: lines.findIndex((l) => l.startsWith('#1=')), tag: 'k5loop', what: '5000 lines with loops and subprograms, in the main program' });
    await typing({ ...fanuc, line: lines.indexOf('#10=#2*1.227'), tag: 'k5loopsub', what: '5000 lines with loops and subprograms, in the macro O9010' });
  },
  k50: () => typing({ ...gsk, text: program(50000), tag: 'k50', what: '50000 lines, in the first pass' }),
  versus: async () => {
    await steps.v5();
    await steps.v50();
  },
  // The two halves of `versus`, each alone (BENCH_ONLY=v5 or v50; not run when all steps run).
  v5: () => versus({ dialect: 'gsk980tdc', line: 8, rounds: 12, keys: 10, text: program(5000), tag: 'v5', what: '5000 lines, in the first pass' }),
  v50: () => versus({ dialect: 'gsk980tdc', line: 8, rounds: 8, keys: 10, text: program(50000), tag: 'v50', what: '50000 lines, in the first pass' }),
  l99,
  pasted,
  wasmRate,
  load: async () => {
    await firstLoad('', () => document.body.dataset.ready === 'true', 'load_app', 'the app with its example', async (page, files) => {
      // A first visit's first diagram is the example's, in the page itself: what its first paint
      // waited for is the page and what blocked its rendering (the stylesheet), not the script or the wasm.
      const m = await page.evaluate(() => ({
        blocking: performance.getEntriesByType('resource').filter((e) => e.renderBlockingStatus === 'blocking').map((e) => new URL(e.name).pathname.slice(1)),
        fcp: performance.getEntriesByType('paint').find((e) => e.name === 'first-contentful-paint')?.startTime,
        live: performance.getEntriesByName('screwcut:first-live', 'mark')[0]?.startTime,
      }));
      const needed = files.filter((f) => f.name === 'index.html' || m.blocking.includes(f.name));
      const kib = needed.reduce((s, f) => s + f.bytes, 0) / 1024;
      console.log(`  … its first diagram (the example's drawings in the page) painted at ${m.fcp?.toFixed(0)} ms with ${kib.toFixed(1)} KiB (${needed.map((f) => `${f.name} ${(f.bytes / 1024).toFixed(1)}`).join(', ')}); the app's own drawing at ${m.live?.toFixed(0)} ms`);
      fig('load_app_first_kib', kib);
      fig('load_app_first_ms', m.fcp);
      fig('load_app_live_ms', m.live);
    });
    await firstLoad('embed-bench.html', () => document.querySelector('screwcut-preview')?.result?.threads?.length > 0, 'load_embed', 'a page with one embedded diagram');
    // The same written by `screwcut embed` (a release build of the command line, made here),
    // its static drawing inside: it waits for the reader; then the pointer comes.
    const element = execFileSync('cargo', ['run', '--release', '--quiet', '--bin', 'screwcut', '--', 'embed', '-', '--width', '800'], {
      cwd: path.join(here, '..'),
      input: embedProgram,
      maxBuffer: 1 << 24,
    }).toString();
    pages['/embed-static-bench.html'] = embedPageWith(element);
    const shown = () => {
      const el = document.querySelector('screwcut-preview');
      return el?.dataset.state === 'idle' && el.querySelector('svg')?.getBoundingClientRect().height > 100;
    };
    await firstLoad('embed-static-bench.html', shown, 'load_embed_static', 'a page with one embedded diagram and its static drawing', async (page) => {
      served.length = 0;
      const t0 = Date.now();
      await page.hover('screwcut-preview');
      await page.waitForFunction(() => document.querySelector('screwcut-preview')?.result?.threads?.length > 0, null, { timeout: 120_000 });
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const ms = Date.now() - t0;
      const kib = served.reduce((s, f) => s + f.bytes, 0) / 1024;
      console.log(`  … pointed at: the live drawing on screen after ${ms} ms, ${kib.toFixed(1)} KiB more (${served.map((f) => f.name).join(', ')})`);
      fig('embed_pointed_ms', ms);
    });
  },
};
try {
  for (const [name, step] of Object.entries(steps)) if (only ? only.includes(name) : !PARTS.includes(name)) await step();
} finally {
  await ctx.close();
  server.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
