// Browser test: the program-writing tools in the app.
// node tools.test.mjs http://127.0.0.1:PORT/
//
// - The thread wizard writes M30×2-6g for GSK G76; "Open as a new program"
//   adds it to the program list beside O1006, and it plans with the thread
//   check passing (d2 28.493…28.663, ISO 965-2).
// - "Expand to blocks" writes O1006 (seed 004) for LinuxCNC as G33 blocks;
//   opened as a new program it plans the same five passes, X47.1 … X45.4.
// - In Chinese the wizard's form titles, notes and refusals are Chinese.
// - The tools are a wasm module of their own: the app's first diagram does
//   not fetch it; the first tool used fetches it once, in a worker as on the
//   page (`?engine=page`), where "Plan JSON" downloads O1006's five passes.
//   Nor does it fetch the bundles of the tools' glue, the dialogs and the
//   page's own planner: each is fetched when first needed, once.
// Screenshots of both dialogs in both languages go to tests/browser/screenshots/.

import { siteUrl, checker, guard, openApp, finish, shots } from './harness.mjs';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const url = siteUrl('tools.test.mjs');
const { check, counts } = checker();
const timer = guard(120, 'the tools test');
const problems = [];
const toolsWasm = [];
// The bundles fetched on first use (file name → requests).
const LAZY = ['screwcut_tools.js', 'wizard.js', 'page-engine.js'];
const lazy = new Map(LAZY.map((f) => [f, 0]));
const { page, close } = await openApp('screwcut-tools-', url, { width: 1440, height: 900 }, problems, (context) =>
  context.on('request', (r) => {
    const file = new URL(r.url()).pathname.split('/').pop();
    if (file === 'screwcut_tools_bg.wasm') toolsWasm.push(r.url());
    if (lazy.has(file)) lazy.set(file, lazy.get(file) + 1);
  }),
);
const fetched = () => JSON.stringify(Object.fromEntries(lazy));

try {
  const programs = () => page.evaluate(() => window.__screwcut.library.programs.list().map((i) => i.name));
  const xs = () => page.locator('#passes tbody tr[data-pass] td:nth-child(3)').allTextContents();
  const before = await programs();

  check('the first diagram loads no tools module', toolsWasm.length === 0, JSON.stringify(toolsWasm));
  check('… nor the tools\' glue, the dialogs or the page\'s own planner', LAZY.every((f) => lazy.get(f) === 0), fetched());

  // ---- the wizard ----
  await page.click('#wizard');
  const dlg = page.locator('dialog.wizard');
  await dlg.waitFor({ timeout: 10_000 });
  await dlg.locator('input[name="designation"]').fill('M30x2-6g');
  await dlg.locator('input[name="length"]').fill('30');
  await dlg.locator('select[name="dialect"]').selectOption('gsk980tdc');
  await dlg.locator('select[name="form"]').selectOption('g76');
  await page.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('G76'), null, { timeout: 10_000 }).catch(() => {});
  const written = await dlg.locator('.wz-program').textContent();
  const notes = await dlg.locator('.wz-notes li').allTextContents();
  check('the wizard writes M30x2-6g as a GSK G76 pair', written.includes('(M30x2-6g') && (written.match(/^G76 /gm) || []).length === 2, written.slice(0, 200));
  check('… with its notes', notes.some((n) => n.startsWith('the last pass puts the pitch diameter in the middle')), JSON.stringify(notes));
  await dlg.screenshot({ path: path.join(shots, 'tools-wizard-en.png') });
  await dlg.locator('button[value="open"]').click();
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('(M30x2-6g'), null, { timeout: 10_000 }).catch(() => {});
  await page.waitForFunction(() => document.querySelector('#check-verdict .verdict'), null, { timeout: 10_000 }).catch(() => {});
  const after = await programs();
  check('"Open as a new program" adds an entry and keeps O1006', after.length === before.length + 1 && before.every((n) => after.includes(n)), JSON.stringify([before, after]));
  const verdict = await page.locator('#check-verdict').textContent();
  const d2 = Number((verdict.match(/d2 ([\d.]+)/) || [])[1]);
  check('the written program plans and its thread check passes (d2 in 28.493…28.663)', verdict.includes('M30x2-6g') && verdict.includes('gauges') && d2 >= 28.493 && d2 <= 28.663, verdict);

  // ---- expand O1006 to LinuxCNC ----
  const o1006 = await page.evaluate(() => window.__screwcut.library.programs.list().find((i) => /O1006|1006/.test(i.name))?.id);
  await page.selectOption('#programs', o1006);
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('N200 G32'), null, { timeout: 10_000 }).catch(() => {});
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  await page.click('#expand');
  await dlg.waitFor({ timeout: 10_000 });
  await dlg.locator('select[name="to"]').selectOption('linuxcnc');
  await page.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('G33'), null, { timeout: 10_000 }).catch(() => {});
  const expanded = await dlg.locator('.wz-program').textContent();
  check('O1006 expands to LinuxCNC G33 blocks', expanded.includes('G33 X47.1 Z13 K2') && expanded.includes('G33 X45.4 Z13 K2'), expanded.slice(0, 300));
  await dlg.screenshot({ path: path.join(shots, 'tools-expand-en.png') });
  await dlg.locator('button[value="open"]').click();
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('G33 X47.1'), null, { timeout: 10_000 }).catch(() => {});
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  const dialect = await page.locator('#dialect').inputValue().catch(() => '');
  check('… opened as a new LinuxCNC program with the same five passes X47.1 … X45.4', dialect === 'linuxcnc' && JSON.stringify(await xs()) === JSON.stringify(['47.1', '46.5', '45.9', '45.5', '45.4']), `${dialect} ${JSON.stringify(await xs())}`);
  check('the list now holds O1006, the wizard\'s and the expanded program', (await programs()).length === before.length + 2, JSON.stringify(await programs()));

  // ---- in Chinese ----
  await page.click('#lang');
  await page.click('#wizard');
  await dlg.waitFor({ timeout: 10_000 });
  await dlg.locator('select[name="dialect"]').selectOption('gsk980tdc');
  await page.waitForFunction(() => document.querySelectorAll('dialog.wizard .wz-notes li').length > 0, null, { timeout: 10_000 }).catch(() => {});
  const titles = await dlg.locator('select[name="form"] option').allTextContents();
  check('the forms\' titles are Chinese', titles.includes('G76 复合螺纹循环') && titles.includes('G92 简单螺纹循环'), JSON.stringify(titles));
  const zhNotes = await dlg.locator('.wz-notes li').allTextContents();
  check('the wizard\'s notes are Chinese', zhNotes.some((n) => n.startsWith('最后一刀使中径落在公差带中间')) && zhNotes.every((n) => !/\bthe\b/.test(n)), JSON.stringify(zhNotes));
  await dlg.screenshot({ path: path.join(shots, 'tools-wizard-zh.png') });
  await dlg.locator('input[name="length"]').fill('');
  await page.waitForFunction(() => !document.querySelector('dialog.wizard .wz-error').hidden, null, { timeout: 10_000 }).catch(() => {});
  const refusal = await dlg.locator('.wz-error').textContent();
  check('a refusal is Chinese: no length', refusal === '请给出螺纹终点 Z 或螺纹长度', refusal);
  await dlg.locator('button[value="cancel"]').click();
  await page.click('#expand');
  await dlg.waitFor({ timeout: 10_000 });
  await page.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('G33'), null, { timeout: 10_000 }).catch(() => {});
  await dlg.screenshot({ path: path.join(shots, 'tools-expand-zh.png') });
  await dlg.locator('button[value="cancel"]').click();
  check('the tools module was fetched once for every tool used', toolsWasm.length === 1, JSON.stringify(toolsWasm));
  check('… its glue and the dialogs once each; the page\'s own planner not at all', lazy.get('screwcut_tools.js') === 1 && lazy.get('wizard.js') === 1 && lazy.get('page-engine.js') === 0, fetched());

  // ---- the engine on the page: the same tools module ----
  const onPage = await page.context().newPage();
  onPage.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await onPage.goto(`${url}?engine=page`);
  await onPage.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await onPage.selectOption('#programs', o1006);
  await onPage.waitForFunction(() => (window.__screwcut.text() || '').includes('N200 G32'), null, { timeout: 10_000 }).catch(() => {});
  const mode = await onPage.evaluate(() => window.__screwcut.mode);
  await onPage.click('#expand');
  const pageDlg = onPage.locator('dialog.wizard');
  await pageDlg.waitFor({ timeout: 10_000 });
  await pageDlg.locator('select[name="to"]').selectOption('linuxcnc');
  await onPage.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('G33'), null, { timeout: 10_000 }).catch(() => {});
  const onPageExpanded = await pageDlg.locator('.wz-program').textContent();
  await pageDlg.screenshot({ path: path.join(shots, 'tools-expand-page-engine.png') });
  check('?engine=page: O1006 expands to the same G33 blocks, the tools module fetched by the page', mode === 'page' && onPageExpanded === expanded && toolsWasm.length === 2, `${mode} ${toolsWasm.length} ${onPageExpanded.slice(0, 200)}`);
  check('… with the page\'s own planner fetched for it', lazy.get('page-engine.js') === 1, fetched());
  await pageDlg.locator('button[value="cancel"]').click();
  // The plan as JSON (the CLI's --json) from the same module: O1006's five passes.
  await onPage.click('#file-menu summary');
  const [download] = await Promise.all([onPage.waitForEvent('download', { timeout: 10_000 }), onPage.click('#plan-json')]);
  const json = JSON.parse(await readFile(await download.path(), 'utf8'));
  const firstX = json.threads?.[0]?.passes?.map((p) => p.from?.[0]);
  check('"Plan as JSON" downloads O1006\'s plan: five passes X47.1 … X45.4', json.dialect === 'gsk980tdc' && JSON.stringify(firstX) === JSON.stringify([47.1, 46.5, 45.9, 45.5, 45.4]), JSON.stringify([json.dialect, firstX, Object.keys(json.threads?.[0]?.passes?.[0] || {})]));
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the tools test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}
finish('tools', counts);
