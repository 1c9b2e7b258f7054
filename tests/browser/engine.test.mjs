// Browser test of the drawing engine's two paths and of a program too big
// to draw whole: node engine.test.mjs http://127.0.0.1:PORT/
//
// - The app in a worker (OffscreenCanvas) and on the page (`?engine=page`,
//   what a browser without OffscreenCanvas gets) draw the same scenes,
//   highlight the same items and follow the same edits; a keystroke, a
//   change in three places, undo and redo reach the engine as changes and
//   the wasm session as changes to its own copy of the text (the text is
//   not passed whole), which stays the editor's.
// - In a program of 80 threads, an edit of one thread changes its entry of
//   the thread menu and no other (both paths; the engine sends the page the
//   summaries that changed).
// - The 3-line L99 program (99 starts × 675 passes, 334,125 motions) leaves
//   the page responsive: the pass table keeps a few dozen rows in the DOM,
//   the drawings are summarised, a button answers while the engine works,
//   and no long task holds the page. Timings are printed, not asserted.
// - 10 MB of one thread put in at once: while it plans, the side section,
//   the faded drawings and the footer say that they show an earlier text;
//   once planned, they no longer do.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import path from 'node:path';
import zlib from 'node:zlib';

const base = siteUrl('engine.test.mjs');
const { check, counts } = checker();
const { context, close } = await launch('screwcut-engine-', { viewport: { width: 1440, height: 900 } });
const timer = guard(180, 'the engine test');
const problems = [];
context.on('page', (p) => p.on('pageerror', (e) => problems.push(e.message)));

function fragment(state) {
  const z = zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 });
  return '#z=' + z.toString('base64').replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

async function open(query) {
  const page = await context.newPage();
  page.on('pageerror', (e) => problems.push(`${query}: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`${query}: ${m.text()}`));
  await page.goto(base + query);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForTimeout(400);
  return page;
}

/** What a page shows: mode, table rows, each view's display list (a digest), its mark and inked pixels. */
const state = (page) =>
  page.evaluate(async () => {
    const p = window.__screwcut;
    const out = { mode: p.mode, rows: [...document.querySelectorAll('#passes tbody tr[data-pass]')].map((tr) => tr.children[2].textContent) };
    for (const name of ['side', 'tooth', 'starts']) {
      const v = await p.inspect('view', name);
      const px = await p.inspect('pixels', name);
      out[name] = { digest: v.digest, marked: v.mark.pass >= 0 || (!v.mark.light && v.mark.lines.length > 0), px: px.n };
    }
    return out;
  });

try {
  // ---- the worker and the page draw the same ----
  const worker = await open('');
  const onPage = await open('?engine=page');
  const [a, b] = [await state(worker), await state(onPage)];
  check('the app draws in a worker', a.mode === 'worker', a.mode);
  check('?engine=page draws on the page (the path without OffscreenCanvas)', b.mode === 'page', b.mode);
  for (const name of ['side', 'tooth', 'starts']) {
    check(`${name}: the same display list both ways`, a[name].digest === b[name].digest && a[name].digest.length > 10);
    check(`${name}: drawn both ways`, a[name].px > 500 && b[name].px > 500, `${a[name].px} / ${b[name].px} pixels`);
  }
  check('the same table both ways', JSON.stringify(a.rows) === JSON.stringify(b.rows) && a.rows.length === 5, JSON.stringify([a.rows, b.rows]));
  // The same edit and the same hover on both.
  for (const page of [worker, onPage]) {
    await page.locator('.cm-line', { hasText: 'N200 G32' }).click();
    await page.keyboard.press('End');
    await page.keyboard.type('\nN201 G00 X58.0;\nN202 Z70.0;\nN203 X45.3;\nN204 G32 Z13.0 F2.0;', { delay: 5 });
    // Not the first 6 rows seen: "… G32 Z13.0 F" (no value) is an alarm, and the table is back to 5 until "F2".
    await page.waitForFunction(() => window.__screwcut.settled() && window.__screwcut.text().includes('F2.0;\nN210'), null, { timeout: 10_000 }).catch(() => {});
    await page.locator('#passes tbody tr[data-pass]').last().hover();
    await page.waitForTimeout(300);
  }
  const [a2, b2] = [await state(worker), await state(onPage)];
  check('an edit gives the same sixth pass both ways', a2.rows.at(-1) === '45.3' && JSON.stringify(a2.rows) === JSON.stringify(b2.rows), JSON.stringify([a2.rows, b2.rows]));
  // Hovering pass 6 marks it: the halos are in the display list, the same both ways.
  check('hovering pass 6 marks it, the same display lists both ways', a2.side.marked && a2.side.digest === b2.side.digest && a2.tooth.digest === b2.tooth.digest, `${a2.side.marked} / ${b2.side.marked}`);
  // Keystrokes go to the engine as changes to the text it holds; edits of every kind leave it the editor's text.
  for (const page of [worker, onPage]) {
    const mode = await page.evaluate(() => window.__screwcut.mode);
    const engineText = () => page.evaluate(() => window.__screwcut.inspect('text'));
    const same = async (what) => {
      await page.waitForFunction(() => window.__screwcut.result && document.body.dataset.behind !== 'true', null, { timeout: 10_000 }).catch(() => {});
      await page.waitForTimeout(300);
      const [held, text] = [await engineText(), await page.evaluate(() => window.__screwcut.text())];
      check(`${mode}: ${what}: the engine plans the editor's text, sent as changes`, held.text === text && held.sentAs === 'edits', `${held.sentAs}, ${held.text?.length} / ${text.length} characters`);
      check(`${mode}: ${what}: … made to the session's own copy, the text not passed whole`, held.kept === text && held.crossed === 'edits', `${held.crossed}, ${held.kept?.length} / ${text.length} characters`);
    };
    await same('after typing a pass');
    // One change in three places (several cursors, a paste of lines), undone, redone and undone again.
    await page.evaluate(() => {
      const v = window.__screwcut.editor().view;
      const l2 = v.state.doc.line(2);
      const l4 = v.state.doc.line(4);
      v.dispatch({ changes: [{ from: l2.to, insert: ' (a)' }, { from: l4.from, to: l4.from + 1, insert: 'N' }, { from: v.state.doc.length, insert: 'G00 X60\nZ80\n' }] });
    });
    await same('after one change in three places');
    await page.keyboard.press('Control+z');
    await same('after undo');
    await page.keyboard.press('Control+Shift+z');
    await same('after redo');
    await page.keyboard.press('Control+z');
    await same('after undo again');
  }
  await worker.close();
  await onPage.close();

  // ---- 80 threads: an edit of one changes its entry of the thread menu, and only it ----
  // (past 64 threads the engine sends the page the summaries that changed, not the list)
  const many = ['O0080', 'S300 M03'];
  for (let k = 0; k < 80; k++) many.push('G00 X60 Z70', 'X47.1', 'G32 Z13 F2', 'G00 X60', 'G01 Z70 F0.2');
  for (const mode of ['', '?engine=page']) {
    const p = await open(mode + fragment({ dialect: 'gsk980tdc', settings: {}, program: many.join('\n') + '\n' }));
    await p.waitForFunction(() => document.querySelectorAll('#thread option').length === 80, null, { timeout: 30_000 }).catch(() => {});
    const menu = () => p.locator('#thread option').allTextContents();
    const before = await menu();
    // Each option element marked (a property, not in the page's HTML): the ones not written again keep it.
    await p.evaluate(() => document.querySelectorAll('#thread option').forEach((o, i) => (o.__mark = i)));
    await p.locator('.cm-line').nth(14).click(); // line 15: the third thread's G32
    await p.keyboard.press('End');
    await p.keyboard.press('Backspace');
    await p.keyboard.type('3');
    await p.waitForFunction(() => /Ph 3\b/.test(document.querySelectorAll('#thread option')[2]?.textContent || ''), null, { timeout: 10_000 }).catch(() => {});
    const after = await menu();
    const others = after.every((o, i) => i === 2 || o === before[i]);
    check(`${mode || 'worker'}: editing thread 3 of 80 to F3 changes its menu entry to Ph 3, and no other`, after.length === 80 && /Ph 3\b/.test(after[2]) && /Ph 2\b/.test(before[2]) && others, JSON.stringify([before[2], after[2], after.length]));
    const kept = await p.evaluate(() => Array.from(document.querySelectorAll('#thread option'), (o, i) => o.__mark === i));
    check(`${mode || 'worker'}: … only that option is written again, the other 79 are the same elements`, kept.length === 80 && !kept[2] && kept.filter(Boolean).length === 79, JSON.stringify(kept.map(Number).join('')));
    await p.close();
  }

  // ---- L99: 99 starts of 675 passes, from a link ----
  const program = 'G00 X100 Z5\nG78 P1060 Q10 R0.01 L99\nG78 X40 Z-30 P9000 Q300 F2\n';
  const page = await context.newPage();
  page.on('pageerror', (e) => problems.push(`L99: ${e.message}`));
  await page.addInitScript(() => {
    // Long tasks on the page's thread, from the start.
    self.__long = [];
    new PerformanceObserver((l) => self.__long.push(...l.getEntries().map((e) => e.duration))).observe({ type: 'longtask', buffered: true });
  });
  const t0 = Date.now();
  await page.goto(base + fragment({ dialect: 'gsk980tdc', settings: {}, program }));
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  const readyMs = Date.now() - t0;
  const l99 = await page.evaluate(async () => {
    const p = window.__screwcut;
    const side = await p.inspect('items', 'side', '*');
    const tooth = await p.inspect('items', 'tooth', '*');
    return {
      passes: p.result.passes.n,
      domRows: document.querySelectorAll('#passes tbody tr').length,
      sideItems: side.length,
      toothItems: tooth.length,
      note: side.some((i) => i.key === 'detail_starts_passes'),
    };
  });
  check('L99 plans 66,825 passes', l99.passes === 66825, String(l99.passes));
  check('… the pass table keeps only the rows in view in the DOM', l99.domRows < 100, `${l99.domRows} rows`);
  check('… the side section is summarised (one start, every n-th pass) and says so', l99.sideItems < 2000 && l99.note, `${l99.sideItems} items`);
  check('… the tooth section too', l99.toothItems < 2000, `${l99.toothItems} items`);
  // The page answers a click while the engine re-plans after a keystroke.
  await page.locator('.cm-line').nth(2).click();
  await page.keyboard.press('End');
  await page.keyboard.type('0');
  const clicked = await page.evaluate(
    () =>
      new Promise((resolve) => {
        const t = performance.now();
        const b = document.getElementById('settings-toggle');
        b.addEventListener('click', () => requestAnimationFrame(() => resolve(performance.now() - t)), { once: true });
        b.click();
      }),
  );
  await page.waitForFunction(() => window.__screwcut.updates.length >= 2, null, { timeout: 30_000 });
  const after = await page.evaluate(() => ({ long: self.__long, last: window.__screwcut.updates.at(-1) }));
  check('… a button answers while the engine re-plans', Number.isFinite(clicked) && !(await page.locator('#settings').isHidden()));
  console.log(
    `L99: page ready ${readyMs} ms after navigation; a click answered to the next frame in ${clicked.toFixed(1)} ms; ` +
      `re-plan in the worker ${after.last.plan.toFixed(0)} ms; page long tasks: ${after.long.length} (longest ${Math.max(0, ...after.long).toFixed(0)} ms)`,
  );
  await page.screenshot({ path: path.join(shots, 'engine-l99.png') });

  // ---- the picture behind the text: 10 MB of one thread put in at once ----
  const block = 'X47.1\nG32 Z13.0 F2.0\nG00 X58.0\nZ70.0\n';
  const big = `G00 X58.0 Z70.0\n${block.repeat(Math.ceil(10e6 / block.length))}`;
  const bigLines = big.split('\n').length;
  await page.evaluate((text) => {
    const v = window.__screwcut.editor().view;
    v.dispatch({ changes: { from: 0, to: v.state.doc.length, insert: text } });
  }, big);
  const seen = {};
  await page.waitForSelector('body[data-behind="true"]', { timeout: 20_000 }).catch(() => {});
  Object.assign(
    seen,
    await page.evaluate(() => {
      const b = document.getElementById('behind');
      return {
        banner: b.hidden ? '' : b.textContent,
        faded: getComputedStyle(document.getElementById('side')).opacity,
        footer: getComputedStyle(document.getElementById('summary'), '::before').content,
      };
    }),
  );
  await page.screenshot({ path: path.join(shots, 'engine-behind.png') });
  await page.waitForFunction((lines) => window.__screwcut.updates.some((u) => u.lines === lines), bigLines, { timeout: 60_000 }).catch(() => {});
  await page.evaluate(() => new Promise((r) => setTimeout(r, 100)));
  seen.after = await page.evaluate(() => ({ behind: document.body.dataset.behind ?? null, hidden: document.getElementById('behind').hidden }));
  check(
    'while 10 MB plans, the side section says the drawing is of an earlier text, faded, and the footer too',
    /^Planning the text as it is now \([\d.]+ s\)… the drawings and the table show an earlier text\.$/.test(seen.banner || '') && Number(seen.faded) < 0.5 && seen.footer === '"Earlier text: "',
    JSON.stringify(seen),
  );
  check('… and once it is planned, they no longer do', seen.after.behind === null && seen.after.hidden === true, JSON.stringify(seen.after));
  check('no page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the engine test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}

finish('engine', counts);
