// In headless Chromium (the system package): time from an edit to the
// finished frame for a 5,000-line program (to the commit of the frame, which
// rasterises the canvases), and the wasm plan time of the 20 MB generated
// program. Usage: node browser.mjs SITE_DIR PROGRAM_20MB
// Prints figures; asserts nothing.
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

const [site, big] = process.argv.slice(2);
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json', '.svg': 'image/svg+xml', '.nc': 'text/plain' };
const server = http.createServer((req, res) => {
  const url = decodeURIComponent(req.url.split('?')[0]);
  if (url === '/bench-20mb.nc') {
    res.writeHead(200, { 'content-type': 'text/plain' });
    return fs.createReadStream(big).pipe(res);
  }
  const file = path.join(site, url.endsWith('/') ? url + 'index.html' : url);
  if (!file.startsWith(path.resolve(site)) || !fs.existsSync(file)) {
    res.writeHead(404);
    return res.end();
  }
  res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const url = `http://127.0.0.1:${server.address().port}/`;

/** The same 5,000-line program the browser test uses: O1006-style threads between turning moves. */
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
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'screwcut-bench-'));
const ctx = await chromium.launchPersistentContext(dir, {
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  viewport: { width: 1400, height: 900 },
});
const page = ctx.pages()[0] || (await ctx.newPage());
try {
  await page.goto(url + fragment({ dialect: 'gsk980tdc', settings: {}, program: program(5000) }));
  await page.waitForFunction(() => window.__screwcut.ready && window.__screwcut.result && window.__screwcut.result.threads.length > 100, null, { timeout: 60_000 });
  const lines = await page.evaluate(() => window.__screwcut.updates.at(-1).lines);
  /**
   * Types `keys` (a list of key names) at the end of line `at` ('first',
   * 'first-pass': the first pass's X rapid on line 9, or 'near-end': the
   * last pass's X rapid) and prints the medians: from the
   * keystroke to the frame committed (canvases rasterised), and its parts.
   */
  const measure = async (what, at, keys) => {
    await page.locator('.cm-line').first().click();
    if (at === 'first-pass') for (let i = 0; i < 8; i++) await page.keyboard.press('ArrowDown');
    if (at === 'near-end') {
      await page.keyboard.press('Control+End');
      for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowUp');
    }
    await page.keyboard.press('End');
    await page.waitForTimeout(300);
    await page.evaluate(() => { window.__screwcut.frames.length = 0; window.__screwcut.updates.length = 0; });
    for (const key of keys) {
      await page.keyboard.press(key);
      await page.waitForTimeout(100);
    }
    await page.waitForTimeout(300);
    const m = await page.evaluate(() => ({ frames: window.__screwcut.frames, updates: window.__screwcut.updates }));
    const f = (a, k) => median(a.map((x) => x[k] || 0)).toFixed(1);
    console.log(
      `  edit-to-frame, ${lines} lines, ${what}: median ${f(m.frames, 'frame')} ms from the keystroke to the committed frame ` +
        `(${m.frames.length} keystrokes, max ${Math.max(...m.frames.map((x) => x.frame)).toFixed(1)}; keystroke to re-plan ${f(m.frames, 'editor')} ms, ` +
        `plan+transfer ${f(m.updates, 'plan')} ms, lists and editor ${f(m.updates, 'draw')} ms, keystroke to frame callbacks done ${f(m.frames, 'raf')} ms, ` +
        `canvas drawing ${f(m.frames, 'canvas')} ms, commit and rasterisation ${f(m.frames, 'commit')} ms)`,
    );
  };
  const comment = [...' (edit-to-frame)'].map((c) => (c === ' ' ? 'Space' : c));
  await measure('typing a comment at the top', 'first', comment);
  // A digit typed and deleted, in turn: every keystroke changes a pass.
  const digits = Array.from({ length: 16 }, (_, i) => (i % 2 ? 'Backspace' : String(1 + (i / 2) % 9)));
  await measure('typing and deleting a digit in the first pass', 'first-pass', digits);
  await measure('typing and deleting a digit in a pass near the end', 'near-end', digits);
  const big20 = await page.evaluate(async () => {
    const text = await (await fetch('bench-20mb.nc')).text();
    const core = window.__screwcut.core;
    const f = core.plan_summary ? () => core.plan_summary(text, 'gsk980tdc', '') : () => core.update(text, 'gsk980tdc', '', -1, 1, -1);
    let best = Infinity;
    let out;
    for (let i = 0; i < 3; i++) {
      const t = performance.now();
      out = f();
      best = Math.min(best, performance.now() - t);
    }
    return { bytes: text.length, best, what: core.plan_summary ? 'plan' : 'plan and side scene (update)' };
  });
  console.log(`  wasm in Chromium, 20 MB (${big20.bytes} bytes): ${big20.what} best of 3 ${big20.best.toFixed(0)} ms = ${(big20.bytes / big20.best / 1000).toFixed(1)} MB/s`);
} finally {
  await ctx.close();
  server.close();
  fs.rmSync(dir, { recursive: true, force: true });
}
