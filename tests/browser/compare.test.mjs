// Browser test: "Compare with…" in the app.
// node compare.test.mjs http://127.0.0.1:PORT/
//
// - The Fanuc G76 example and its expansion to GSK G32 blocks ("Expand to
//   blocks…", opened as a new program) compare equal: the strip says the
//   same passes, and the other program's five cuts lie over the side section
//   in their own pen (the core's display list: the `compare` style).
// - One pass edited (the second pass 0.05 deeper on the diameter) differs
//   there: the strip lists that pass's X and depth.
// - "Stop comparing" takes the overlay off.
// - The part checks in the app: M48×2 ending 0.3 before a shoulder turned
//   up to X56 (tool-shoulder: the tool's outline and the face it cuts, in
//   red, in the side section), and the insert 16ER 2.0 ISO in the tooth
//   section (its nose, r 0.25).
// Screenshots (English, Chinese) go to tests/browser/screenshots/compare-*.png
// and part-*.png.

import { siteUrl, checker, guard, openApp, finish, shots } from './harness.mjs';
import path from 'node:path';
import zlib from 'node:zlib';

function fragment(state) {
  const z = zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 });
  return '#z=' + z.toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

const url = siteUrl('compare.test.mjs');
const { check, counts } = checker();
const timer = guard(150, 'the compare test');
const problems = [];
const { page, close } = await openApp('screwcut-compare-', url, { width: 1440, height: 900 }, problems);

try {
  const rows = () => page.locator('#passes tbody tr[data-pass]').count();
  // The G76 example, then its expansion for GSK as a new program.
  const opts = await page.locator('#examples option').allTextContents();
  const example = opts.find((o) => /G76/.test(o) && /Fanuc/i.test(o));
  await page.selectOption('#examples', { label: example });
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('G76 X60.64'), null, { timeout: 10_000 });
  await page.click('#expand');
  const dlg = page.locator('dialog.wizard');
  await dlg.waitFor({ timeout: 10_000 });
  await dlg.locator('select[name="to"]').selectOption('gsk980tdc');
  await page.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('G32'), null, { timeout: 10_000 });
  await dlg.locator('button[value="open"]').click();
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('G32') && window.__screwcut.dialect() === 'gsk980tdc', null, { timeout: 10_000 });
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  check('the expansion opens as a GSK program of 5 passes', (await rows()) === 5, String(await rows()));

  // Compare it with the G76 example.
  await page.click('#side-panel [data-act="compare"]');
  const cd = page.locator('dialog.wizard');
  await cd.waitFor({ timeout: 10_000 });
  const names = await cd.locator('select[name="other"] option').allTextContents();
  const g76 = names.find((n) => /O0076|G76/.test(n));
  check('the dialog lists the other programs of the list', !!g76, JSON.stringify(names));
  await cd.locator('select[name="other"]').selectOption({ label: g76 });
  await cd.screenshot({ path: path.join(shots, 'compare-dialog-en.png') });
  await cd.locator('button[value="compare"]').click();
  await page.waitForSelector('#compare:not([hidden])', { timeout: 10_000 });
  const same = await page.locator('#compare .cmp-head').textContent();
  check('a G76 and its G32 expansion cut the same passes', same.includes('the same passes (5)'), same);
  await page.waitForTimeout(300);
  const over = await page.evaluate(() => window.__screwcut.inspect('items', 'side', 'compare'));
  // Five cuts and their five run-outs (G76's chamfer J/K written back as the run-out words).
  check(`the other program's cuts lie over the side section (${over.length} items in the compare pen)`, over.length === 10, String(over.length));
  const toothOver = await page.evaluate(() => window.__screwcut.inspect('items', 'tooth', 'compare'));
  check('… and over the tooth section', toothOver.length >= 5, String(toothOver.length));
  await page.screenshot({ path: path.join(shots, 'compare-same-en.png') });

  // The second pass 0.05 deeper on the diameter (X62.9088 → X62.8588, in its approach and its cut): that pass differs.
  await page.evaluate(() => {
    const ed = window.__screwcut.editor();
    const doc = ed.view.state.doc.toString();
    const changes = [];
    for (let at = doc.indexOf('X62.9088'); at >= 0; at = doc.indexOf('X62.9088', at + 1)) changes.push({ from: at, to: at + 8, insert: 'X62.8588' });
    ed.view.dispatch({ changes });
  });
  await page.waitForFunction(() => /differences/.test(document.querySelector('#compare .cmp-head')?.textContent || ''), null, { timeout: 10_000 }).catch(() => {});
  const differ = await page.locator('#compare .cmp-head').textContent();
  check('an edited pass differs', /\d+ differences/.test(differ), differ);
  await page.locator('#compare details summary').click();
  const cells = await page.locator('#compare tbody tr').allTextContents();
  check('… the table names the pass, its X and its depth', cells.some((c) => c.includes('pass') && c.includes('X')) && cells.some((c) => c.includes('depth')), JSON.stringify(cells));
  await page.screenshot({ path: path.join(shots, 'compare-differ-en.png') });
  await page.click('#lang');
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(shots, 'compare-differ-zh.png') });
  await page.click('#lang');

  // Stop.
  await page.click('#compare [data-act="compare-stop"]');
  await page.waitForSelector('#compare[hidden]', { timeout: 5000 }).catch(() => {});
  await page.waitForTimeout(300);
  const gone = await page.evaluate(() => window.__screwcut.inspect('items', 'side', 'compare'));
  check('"Stop comparing" takes the overlay off', gone.length === 0 && (await page.locator('#compare').isHidden()), String(gone.length));

  // ---- the part checks in the app ----
  let program = 'G00 X60 Z2\nG01 X48 F0.2\nZ-40\nX56\nZ-60\nG00 X60\nZ5\n';
  for (const x of [47.1, 46.5, 45.9, 45.5, 45.4]) program += `X${x}\nG32 Z-39.7 F2\nG00 X60\nZ5\n`;
  await page.goto('about:blank');
  await page.goto(url + fragment({ dialect: 'gsk980tdc', settings: { gsk980tdc: { 'tool.insert': '16ER 2.0 ISO' } }, program }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForFunction(() => document.querySelectorAll('#diagnostics li').length > 0, null, { timeout: 10_000 }).catch(() => {});
  const diags = await page.locator('#diagnostics li').allTextContents();
  check('a thread ending 0.3 before a shoulder: tool-shoulder, 2.76 into it', diags.some((d) => d.includes('tool-shoulder') && d.includes('2.76')), JSON.stringify(diags));
  const red = await page.evaluate(() => window.__screwcut.inspect('items', 'side', 'collision'));
  check('… the face it cuts drawn in red in the side section, with the depth', red.length === 2, String(red.length));
  const outline = await page.evaluate(() => window.__screwcut.inspect('items', 'side', 'tool'));
  check('… and the tool outline at that pass', outline.length === 1 && outline[0].pass === 4, JSON.stringify(outline.map((o) => o.pass)));
  const insert = await page.evaluate(() => window.__screwcut.inspect('labels', 'tooth'));
  check('the tooth section names the insert (16ER 2.0 ISO, r 0.25)', insert.placed.some((l) => l.key === 'insert_full' && l.lines.join(' ').includes('16ER 2.0 ISO r 0.25')), JSON.stringify(insert.placed.map((l) => l.lines)));
  await page.locator('#side-panel').screenshot({ path: path.join(shots, 'part-shoulder-en.png') });
  await page.locator('#tooth-panel').screenshot({ path: path.join(shots, 'part-insert-en.png') });

  // ---- a two-start thread by axial offset (LinuxCNC has no start angle word) ----
  let twoStart = 'G18 G21 G90 G7\nM3 S300\nG0 X42 Z5\n';
  for (const x of [38.8, 38.2, 37.8]) twoStart += `G0 X${x}\nG33 Z-30 K3\nG0 X42\nZ5\nG0 X${x} Z6.5\nG33 Z-30 K3\nG0 X42\nZ5\n`;
  twoStart += 'M2\n';
  await page.goto('about:blank');
  await page.goto(url + fragment({ dialect: 'linuxcnc', settings: {}, program: twoStart }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  const summary = await page.evaluate(() => ({ threads: window.__screwcut.result.threads.length, starts: window.__screwcut.result.threads[0].starts }));
  check('passes half a lead further back are the second start: one thread of two starts', summary.threads === 1 && summary.starts === 2, JSON.stringify(summary));
  const startLabels = await page.evaluate(() => window.__screwcut.inspect('labels', 'starts'));
  const said = startLabels.placed.map((l) => l.lines.join(' '));
  check('… the starts view puts the second at 180°, 1.5 along the lead', said.some((t) => t.includes('2: 180°')) && said.some((t) => t.includes('1: 0°')), JSON.stringify(said));
  await page.locator('#starts-panel').screenshot({ path: path.join(shots, 'starts-axial-en.png') });
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the compare test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}
finish('compare', counts);
