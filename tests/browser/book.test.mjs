// Browser test of the example book (docs/book) built by mdBook with the
// mdbook-screwcut preprocessor and served under book/:
// node book.test.mjs http://127.0.0.1:PORT/
//
// Every ```screwcut block of every chapter must be a live <screwcut-preview>
// whose canvases are inked once started (a block whose static drawings show
// all its views waits for the reader's pointer before it loads the wasm); the same pages with JavaScript
// off must show each block's static SVG (the drawings the core wrote at
// build time) and its program as text; print media must show the static
// drawing in place of the canvases; mdBook's print page must carry every
// block. Screenshots (book-*.png) go to tests/browser/screenshots/.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import path from 'node:path';

const base = new URL('book/', siteUrl('book.test.mjs')).href;
const { check, counts } = checker();
const timer = guard(150, 'the book test');

/** The chapters and how many blocks each carries (docs/book/src). */
const CHAPTERS = { intro: 1, o1006: 1, gsk980tdc: 3, fanuc0i: 3, renhe: 1, linuxcnc: 2 };
const TOTAL = Object.values(CHAPTERS).reduce((a, b) => a + b, 0);

/** Each element of the page: state, inked pixels per canvas, static drawings and their size on the page. */
const elements = (page) =>
  page.evaluate(() =>
    [...document.querySelectorAll('screwcut-preview')].map((el) => {
      const canvases = el.shadowRoot
        ? [...el.shadowRoot.querySelectorAll('.view canvas')].map((c) => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235)) n++;
            const r = c.getBoundingClientRect();
            return { n, shownH: r.height };
          })
        : [];
      const svgs = [...el.querySelectorAll(':scope > svg')].map((s) => {
        const r = s.getBoundingClientRect();
        return { w: Math.round(r.width), h: Math.round(r.height), paths: s.querySelectorAll('path').length, texts: s.querySelectorAll('text').length };
      });
      const table = el.querySelector(':scope > table');
      const rows = table ? table.tBodies[0].rows.length : 0;
      const tableH = table ? Math.round(table.getBoundingClientRect().height) : 0;
      const shownTable = el.shadowRoot?.querySelector('.views.fallback .view.table');
      const shownTableH = shownTable ? Math.round(shownTable.getBoundingClientRect().height) : 0;
      const liveTable = el.shadowRoot?.querySelector('.views.live .view.table');
      const liveTableH = liveTable ? Math.round(liveTable.getBoundingClientRect().height) : 0;
      const diags = el.shadowRoot ? [...el.shadowRoot.querySelectorAll('ul.diags li')].map((li) => li.textContent) : [];
      return { state: el.dataset.state || null, view: el.getAttribute('view'), canvases, svgs, rows, tableH, shownTableH, liveTableH, diags, alarms: el.result ? el.result.alarms : null };
    }),
  );

let live;
try {
  // ---- live: every block an element that draws ----
  live = await launch('screwcut-book-', { viewport: { width: 1280, height: 900 } });
  const page = live.context.pages()[0] || (await live.context.newPage());
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  let seen = 0;
  for (const [chapter, n] of Object.entries(CHAPTERS)) {
    await page.goto(`${base}${chapter}.html`);
    await page.evaluate(() => customElements.whenDefined('screwcut-preview'));
    const count = await page.locator('screwcut-preview').count();
    {
      // Every block has static drawings and, with a pass table, a static table (screwcut embed's),
      // and the alarms and warnings of its program listed inside: it waits for the reader, and no
      // chapter loads the wasm before a reader points at a diagram.
      for (let i = 0; i < count; i++) await page.locator('screwcut-preview').nth(i).scrollIntoViewIfNeeded();
      await page.mouse.move(1270, 5);
      await page.waitForTimeout(1200);
      const waiting = await elements(page);
      const live = await page.evaluate(() => [...document.querySelectorAll('screwcut-preview')].map((e) => e.hasAttribute('live')));
      const wasm = await page.evaluate(() => performance.getEntriesByType('resource').filter((r) => r.name.endsWith('.wasm')).length);
      const want = Array(n).fill(false);
      check(
        `${chapter}: every block waits for the reader, and no wasm is fetched`,
        JSON.stringify(live) === JSON.stringify(want) &&
          waiting.every((e, i) => (live[i] ? e.state === 'ready' : e.state === 'idle' && e.svgs.length > 0 && e.svgs.every((s) => s.h > 100))) &&
          waiting.every((e, i) => live[i] || !e.view.includes('table') || (e.rows > 0 && e.shownTableH > 60)) &&
          (want.includes(true) || wasm === 0),
        JSON.stringify({ wasm, live, states: waiting.map((e) => e.state), rows: waiting.map((e) => e.rows) }),
      );
      if (chapter === 'o1006') {
        await page.locator('screwcut-preview').first().scrollIntoViewIfNeeded();
        await page.screenshot({ path: path.join(shots, 'book-o1006-static.png') });
        check('o1006: its static table lists the five passes', waiting[0].rows === 5, JSON.stringify(waiting[0].rows));
      }
      if (chapter === 'gsk980tdc') {
        // The first block plans with a warning: a 1° shim for a 2.38° helix. It is listed while the block waits.
        await page.locator('screwcut-preview').first().scrollIntoViewIfNeeded();
        await page.screenshot({ path: path.join(shots, 'book-gsk980tdc-static.png') });
        const shim = waiting[0].diags;
        check('gsk980tdc: the warning of the waiting block is listed under its static drawing', shim.length === 1 && shim[0].includes('[shim-rub]') && shim[0].startsWith('2:1 warning'), JSON.stringify(shim));
      }
      if (chapter === 'renhe' || chapter === 'o1006') {
        const height = () => page.evaluate(() => document.querySelector('screwcut-preview').getBoundingClientRect().height);
        const before = await height();
        await page.locator('screwcut-preview').first().hover();
        await page.waitForFunction(() => document.querySelector('screwcut-preview').dataset.state === 'ready', null, { timeout: 20_000 }).catch(() => {});
        await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
        const after = await height();
        // What is under the reader's pointer does not move: the live element takes the static one's room.
        check(`${chapter}: going live, the element keeps its height (${before.toFixed(1)} → ${after.toFixed(1)} px)`, Math.abs(after - before) <= 2, `${before} → ${after}`);
        const pointed = (await elements(page))[0];
        check(`${chapter}: … pointed at, it plans and draws live`, pointed.state === 'ready' && pointed.canvases.every((c) => c.n > 300) && pointed.shownTableH === 0, JSON.stringify(pointed));
        if (chapter === 'o1006') {
          // The static table is the live one: the same headers, the same cells, row by row.
          const same = await page.evaluate(() => {
            const root = document.querySelector('screwcut-preview').shadowRoot;
            const rows = (sel) => [...root.querySelectorAll(`${sel} tbody tr`)].filter((r) => !r.classList.contains('spacer')).map((r) => [...r.cells].map((c) => c.textContent));
            return {
              head: ['.views.fallback .view.table', '.views.live .view.table'].map((sel) => [...root.querySelectorAll(`${sel} thead th`)].map((c) => c.textContent).join(' | ')),
              rows: [rows('.views.fallback .view.table'), rows('.views.live .view.table')],
            };
          });
          check('o1006: the static pass table has the live table\'s headers and cells', same.head[0] === same.head[1] && JSON.stringify(same.rows[0]) === JSON.stringify(same.rows[1]), JSON.stringify(same));
        }
        await page.screenshot({ path: path.join(shots, `book-${chapter}-pointed.png`) });
      }
    }
    for (let i = 0; i < count; i++) {
      const el = page.locator('screwcut-preview').nth(i);
      await el.scrollIntoViewIfNeeded();
      await el.evaluate((e) => e.start && e.start());
      await page.waitForFunction((i) => ['ready', 'error'].includes(document.querySelectorAll('screwcut-preview')[i].dataset.state), i, { timeout: 20_000 });
    }
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const els = await elements(page);
    seen += els.length;
    const inked = els.every((e) => e.state === 'ready' && e.alarms === 0 && e.canvases.length > 0 && e.canvases.every((c) => c.n > 300));
    check(`${chapter}: ${n} block(s), each live with inked canvases and no alarm`, els.length === n && inked, JSON.stringify(els.map((e) => ({ s: e.state, a: e.alarms, c: e.canvases.map((c) => c.n) }))));
    if (chapter === 'o1006') {
      await page.locator('screwcut-preview').first().scrollIntoViewIfNeeded();
      await page.screenshot({ path: path.join(shots, 'book-o1006.png') });
      // ---- print media: the static drawing stands for the canvases ----
      await page.emulateMedia({ media: 'print' });
      const printed = await elements(page);
      const p = printed[0];
      check(
        'in print, the static drawings and pass table show and the canvases and live table do not',
        p.svgs.length === 2 && p.svgs.every((s) => s.h > 100) && p.canvases.every((c) => c.shownH === 0) && p.shownTableH > 100 && p.liveTableH === 0,
        JSON.stringify(p),
      );
      await page.screenshot({ path: path.join(shots, 'book-o1006-print.png') });
      await page.emulateMedia({ media: 'screen' });
    }
  }
  check(`the book has ${TOTAL} blocks in all`, seen === TOTAL, String(seen));
  const fetched = await page.evaluate(() => performance.getEntriesByType('resource').map((r) => r.name).filter((n) => n.includes('/screwcut/')));
  check('the element is loaded from the book\'s one copy (book/screwcut/)', fetched.some((n) => n.endsWith('/book/screwcut/screwcut-preview.js')), JSON.stringify(fetched));
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
  await live.close();
  live = null;

  // ---- JavaScript off: the static drawings and the program ----
  const off = await launch('screwcut-book-nojs-', { viewport: { width: 1280, height: 900 }, javaScriptEnabled: false });
  const p2 = off.context.pages()[0] || (await off.context.newPage());
  for (const [chapter, n] of Object.entries(CHAPTERS)) {
    await p2.goto(`${base}${chapter}.html`);
    const els = await elements(p2);
    const drawn = els.every((e) => e.svgs.length > 0 && e.svgs.every((s) => s.w > 300 && s.h > 100 && s.paths > 5 && s.texts > 2));
    const tables = els.every((e) => !e.view.includes('table') || (e.rows > 0 && e.tableH > 40));
    check(`${chapter} without JavaScript: ${n} static drawing(s) shown, and the pass tables`, els.length === n && drawn && tables, JSON.stringify(els.map((e) => [e.svgs, e.rows, e.tableH])));
  }
  await p2.goto(`${base}o1006.html`);
  const text = await p2.locator('screwcut-preview').first().innerText();
  check('… with the program as text, line by line', text.includes('N40 G32 Z13.0 F2.0;\nN50 G00 X58.0;'), JSON.stringify(text.slice(0, 200)));
  await p2.locator('screwcut-preview').first().scrollIntoViewIfNeeded();
  await p2.screenshot({ path: path.join(shots, 'book-o1006-nojs.png') });
  await p2.goto(`${base}print.html`);
  const all = await elements(p2);
  check(`mdBook's print page carries all ${TOTAL} blocks with their drawings`, all.length === TOTAL && all.every((e) => e.svgs.length > 0 && e.svgs[0].h > 100), JSON.stringify(all.length));
  await off.close();
} catch (e) {
  check('the book test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  if (live) await live.close();
}

finish('example book', counts);
