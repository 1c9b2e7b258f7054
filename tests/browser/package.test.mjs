// Browser test of the element installed from its npm package: the xtask
// packs dist's element folder (`npm pack`), installs the tarball into a
// scratch page (`npm install`) served at pkg-scratch/, and this opens it:
// node package.test.mjs http://127.0.0.1:PORT/
//
// The installed element must draw (inked canvas, the table's passes), its
// "Open in editor" link must open the app the package carries, and the
// package's files must be what package.json's `exports` and `types` name.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import path from 'node:path';

const base = new URL('pkg-scratch/', siteUrl('package.test.mjs')).href;
const { check, counts } = checker();
const timer = guard(90, 'the package test');
const { context, close } = await launch('screwcut-pkg-', { viewport: { width: 1000, height: 800 } });
const problems = [];

try {
  const page = context.pages()[0] || (await context.newPage());
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  context.on('response', (r) => r.status() >= 400 && problems.push(`${r.status()}: ${r.url()}`));
  const meta = await (await fetch(`${base}node_modules/screwcut-preview/package.json`)).json();
  check(
    'the installed package.json names its entry, its types and its licence',
    meta.name === 'screwcut-preview' && meta.exports['.'].types === './screwcut-preview.d.ts' && meta.exports['.'].default === './screwcut-preview.js' && meta.license === 'MIT OR Apache-2.0',
    JSON.stringify(meta.exports),
  );
  const served = await Promise.all(['screwcut-preview.d.ts', 'LICENSE-MIT', 'LICENSE-APACHE', 'README.md', 'index.html'].map(async (f) => (await fetch(`${base}node_modules/screwcut-preview/${f}`)).status));
  check('… and carries them', served.every((s) => s === 200), JSON.stringify(served));
  await page.goto(`${base}index.html`);
  await page.waitForFunction(() => ['ready', 'error'].includes(document.getElementById('pkg').dataset.state), null, { timeout: 30_000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const seen = await page.evaluate(() => {
    const el = document.getElementById('pkg');
    const c = el.shadowRoot.querySelector('.view canvas');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235)) n++;
    return { state: el.dataset.state, ink: n, xs: el.result.passes.map((p) => p.from[0]), link: el.shadowRoot.querySelector('a.open').href };
  });
  check('the installed element plans and draws: three G92 passes X47.1, 46.5, 45.9', seen.state === 'ready' && seen.ink > 400 && JSON.stringify(seen.xs) === '[47.1,46.5,45.9]', JSON.stringify(seen));
  check('"Open in editor" opens the app the package carries', /^node_modules\/screwcut-preview\/(index\.html)?#j=/.test(seen.link.slice(base.length)), seen.link);
  const app = await context.newPage();
  await app.goto(seen.link);
  await app.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await app.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length > 0, null, { timeout: 10_000 }).catch(() => {});
  const rows = await app.locator('#passes tbody tr[data-pass]').count();
  check('… and the app shows the same three passes', rows === 3, String(rows));
  await page.screenshot({ path: path.join(shots, 'package-page.png') });
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the package test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}

finish('npm package', counts);
