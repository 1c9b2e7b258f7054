import { chromium } from 'playwright-core';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';
const site = path.resolve('../target/site-new');
const server = http.createServer((req, res) => {
  let u = decodeURIComponent(req.url.split('?')[0]);
  if (u.endsWith('/')) u += 'index.html';
  const f = path.join(site, u);
  if (!fs.existsSync(f)) { res.writeHead(404); return res.end(); }
  const ty = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json' }[path.extname(f)] || 'application/octet-stream';
  res.writeHead(200, { 'content-type': ty });
  res.end(fs.readFileSync(f));
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const url = `http://127.0.0.1:${server.address().port}/`;
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
const lines = Number(process.argv[2] || 50000);
const frag = '#z=' + zlib.deflateRawSync(Buffer.from(JSON.stringify({ dialect: 'gsk980tdc', settings: {}, program: program(lines) })), { level: 9 }).toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'] });
const ctx = await browser.newContext({ viewport: { width: 1440, height: 900 } });
await ctx.addInitScript(() => {
  self.__log = [];
  const W = self.Worker;
  self.Worker = class extends W {
    constructor(...a) {
      super(...a);
      this.addEventListener('message', (e) => self.__log.push(['recv', e.data && e.data.type, performance.now(), e.data && e.data.timing ? JSON.stringify(e.data.timing) : '']));
    }
    postMessage(m, t) {
      const t0 = performance.now();
      const r = super.postMessage(m, t);
      self.__log.push(['post', m && m.type, t0, (performance.now() - t0).toFixed(1)]);
      return r;
    }
  };
  document.addEventListener('keydown', (e) => self.__log.push(['key', e.key, e.timeStamp]), true);
  new PerformanceObserver((l) => { for (const e of l.getEntries()) self.__log.push(['mark', e.name, e.startTime]); }).observe({ type: 'mark', buffered: true });
});
const page = await ctx.newPage();
await page.goto(url + frag);
await page.waitForSelector('body[data-ready="true"]', { timeout: 120000 });
await page.waitForFunction(() => window.__screwcut.result && window.__screwcut.result.threads.length > 100, null, { timeout: 120000 });
await page.click('.cm-content');
await page.keyboard.press('Control+Home');
for (let i = 0; i < 8; i++) await page.keyboard.press('ArrowDown');
await page.keyboard.press('End');
await page.waitForTimeout(1500);
for (let k = 0; k < 6; k++) {
  await page.evaluate(() => (self.__log = []));
  await page.keyboard.press(k % 2 ? 'Backspace' : '1');
  await page.waitForTimeout(1500);
  const log = await page.evaluate(() => self.__log);
  const t0 = log.find((l) => l[0] === 'key')?.[2] ?? 0;
  console.log(log.map((l) => `${l[0]}:${l[1]}@${(l[2] - t0).toFixed(1)}${l[3] ? ' ' + l[3] : ''}`).join(' | '));
}
await browser.close();
server.close();
