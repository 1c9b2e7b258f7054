// Browser test: a program with subprograms in the app.
// node calls.test.mjs http://127.0.0.1:PORT/
//
// A Fanuc 0i main program calls a one-pass subprogram three times
// (`M98 P1000 L3`) and another subprogram that holds a warning. Checks:
// - the pass table has the three passes, each pointing at the
//   subprogram's lines and at the call (`10,11,12,13 ← 4`);
// - hovering a pass row marks the subprogram's lines in the editor and the
//   calling line in the call colour;
// - the diagnostic inside the second subprogram names its line there and
//   the call chain ("called from line 5"), in English and in Chinese;
// - a macro loop that runs a bad block fifty times lists its alarm once,
//   "raised 50 times" (出现 50 次 in Chinese), and the editor's marker
//   says it once, ×50.
// Screenshots go to tests/browser/screenshots/calls-*.png.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import path from 'node:path';
import zlib from 'node:zlib';

const url = siteUrl('calls.test.mjs');
const { check, counts } = checker();
const timer = guard(90, 'the calls test');

const PROGRAM = [
  'O0001 (M48X2 BY A SUBPROGRAM)',
  'G97 S300 M03',
  'G00 X58. Z70.',
  'M98 P1000 L3',
  'M98 P2000',
  'G00 X100. Z100.',
  'M30',
  'O1000 (ONE PASS)',
  '#1=#1+1',
  'G00 X[47.7-0.6*#1]',
  'G32 Z13. F2.',
  'G00 X58.',
  'Z70.',
  'M99',
  'O2000 (RETURN)',
  'G00 X100',
  'M99',
  '',
].join('\n');

function fragment(state) {
  const z = zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 });
  return '#z=' + z.toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

const problems = [];
const { context, close } = await launch('screwcut-calls-', { viewport: { width: 1440, height: 900 } });
try {
  const page = context.pages()[0] || (await context.newPage());
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  await page.goto(url + fragment({ dialect: 'fanuc0i', program: PROGRAM }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 3, null, { timeout: 30_000 }).catch(() => {});
  const rows = page.locator('#passes tbody tr[data-pass]');
  const xs = await page.locator('#passes tbody tr[data-pass] td:nth-child(3)').allTextContents();
  check('three passes from M98 P1000 L3: X47.1, X46.5, X45.9', JSON.stringify(xs) === JSON.stringify(['47.1', '46.5', '45.9']), JSON.stringify(xs));
  const lines = await page.locator('#passes tbody tr[data-pass] td.lines').allTextContents();
  check('each pass points at the subprogram\'s lines and the call', lines.length === 3 && lines.every((l) => l === '10,11,12,13 ← 4'), JSON.stringify(lines));

  await rows.nth(1).hover();
  await page.waitForFunction(() => document.querySelectorAll('.cm-marked').length >= 4, null, { timeout: 10_000 }).catch(() => {});
  const marked = await page.evaluate(() => {
    const view = window.__screwcut.editor().view;
    const no = (el) => view.state.doc.lineAt(view.posAtDOM(el)).number;
    return {
      own: [...document.querySelectorAll('.cm-line.cm-marked')].map(no),
      calls: [...document.querySelectorAll('.cm-line.cm-call')].map(no),
    };
  });
  check('hovering a pass marks the subprogram\'s lines 10–13', JSON.stringify(marked.own) === '[10,11,12,13]', JSON.stringify(marked.own));
  check('… and the call on line 4 in the call colour', JSON.stringify(marked.calls) === '[4]', JSON.stringify(marked.calls));
  await page.screenshot({ path: path.join(shots, 'calls-hover-en.png') });

  const diag = page.locator('#diagnostics li', { hasText: 'no-decimal-point' });
  await diag.first().waitFor({ timeout: 10_000 }).catch(() => {});
  const text = (await diag.first().textContent().catch(() => '')) || '';
  check('the warning in O2000 is at its own line 16, called from line 5', text.startsWith('16:5') && text.includes('called from line 5'), text);
  await diag.first().scrollIntoViewIfNeeded().catch(() => {});
  await diag.first().screenshot({ path: path.join(shots, 'calls-diagnostics-en.png') });

  await page.click('#lang');
  await page.waitForFunction(() => (document.querySelector('#diagnostics li .via')?.textContent || '').includes('调用自'), null, { timeout: 10_000 }).catch(() => {});
  const zh = (await page.locator('#diagnostics li .via').first().textContent().catch(() => '')) || '';
  check('in Chinese: 调用自第 5 行', zh === '调用自第 5 行', zh);
  await page.locator('#diagnostics li', { hasText: 'no-decimal-point' }).first().screenshot({ path: path.join(shots, 'calls-diagnostics-zh.png') });
  await page.click('#lang');

  // A WHILE loop runs a G01 with a Q word fifty times: one row with the count.
  const loop = ['O0002', 'G99 S500 M03', 'G00 X40. Z5.', '#1=0', 'WHILE[#1LT50]DO1', 'G01 W-1. F0.2', 'G01 X40. Q3', '#1=#1+1', 'END1', 'M30', ''].join('\n');
  await page.goto(url + fragment({ dialect: 'fanuc0i', program: loop }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  const alarm = page.locator('#diagnostics li', { hasText: 'unexpected-word' });
  await alarm.first().waitFor({ timeout: 10_000 }).catch(() => {});
  const alarms = await alarm.allTextContents();
  check('the loop\'s alarm is one row at 7:10, raised 50 times', alarms.length === 1 && alarms[0].startsWith('7:10') && alarms[0].includes('raised 50 times'), JSON.stringify(alarms));
  await alarm.first().screenshot({ path: path.join(shots, 'calls-repeats-en.png') });
  await page.waitForFunction(() => (document.querySelector('.cm-diag-marker-error')?.title || '').includes('×'), null, { timeout: 10_000 }).catch(() => {});
  const marker = await page.evaluate(() => document.querySelector('.cm-diag-marker-error')?.title || '');
  check('… and the editor\'s gutter marker says it once, ×50', marker === 'G01 does not take Q3 ×50 (unexpected-word)', marker);
  await page.click('#lang');
  await page.waitForFunction(() => (document.querySelector('#diagnostics li .repeats')?.textContent || '') === '出现 50 次', null, { timeout: 10_000 }).catch(() => {});
  const times = (await page.locator('#diagnostics li .repeats').first().textContent().catch(() => '')) || '';
  check('in Chinese: 出现 50 次', times === '出现 50 次', times);
  await page.click('#lang');
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the calls test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}
finish('calls', counts);
