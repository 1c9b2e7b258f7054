// Browser test of the documentation page built from <screwcut-preview>
// elements: node docs.test.mjs http://127.0.0.1:PORT/
//
// Drives the system Chromium (/usr/bin/chromium) with playwright-core: loads
// docs.html, checks that embeds below the fold wait (lazy start), scrolls
// through so every embed starts, checks that every embed drew (inked canvas
// pixels, table rows) and planned what the page says (pass counts, infeed
// modes, starts, dialects), that one wasm instance served them all, that the
// element leaked no global and no style into the page, that the wheel still
// scrolls the page over a drawing, that hovering a pass shows its numbers,
// that the editable embed re-plans as one types (a warning goes, an alarm
// comes), and that "Open in editor" opens the app with the same program and
// dialect. No console or page error may happen. Screenshots go to
// tests/browser/screenshots/.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import http from 'node:http';
import path from 'node:path';

const base = siteUrl('docs.test.mjs');
const { check, counts } = checker();

const { context, close } = await launch('screwcut-docs-', { viewport: { width: 1280, height: 900 } });
const timer = guard(150, 'the docs test');

const problems = [];
const watch = (p) => {
  p.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console (${p.url().slice(0, 60)}): ${m.text()}`);
  });
  p.on('pageerror', (e) => problems.push(`pageerror (${p.url().slice(0, 60)}): ${e.message}`));
};
context.on('page', watch);
const wasmRequests = [];
context.on('request', (r) => {
  if (r.url().endsWith('.wasm')) wasmRequests.push(r.url());
});

const page = context.pages()[0] || (await context.newPage());
watch(page);

/** State, program, result summary and drawn pixels of embed `id`. */
const inspect = (id) =>
  page.evaluate((id) => {
    const el = document.getElementById(id);
    const root = el.shadowRoot;
    const canvases = [...root.querySelectorAll('.view canvas')].map((c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 0 && (d[i] < 235 || d[i + 1] < 235 || d[i + 2] < 235)) n++;
      return { view: c.parentElement.dataset.view, n, w: c.width, h: c.height };
    });
    const r = el.result;
    return {
      state: el.dataset.state,
      program: el.program,
      canvases,
      rows: [...root.querySelectorAll('.view.table tbody tr')].map((tr) => [...tr.cells].map((td) => td.textContent)),
      diagnostics: [...root.querySelectorAll('ul.diags li')].map((li) => li.className + ' ' + li.textContent),
      summary: root.querySelector('.sum').textContent,
      listing: [...root.querySelectorAll('pre.code span')].map((l) => l.textContent).join('\n'),
      link: root.querySelector('a.open').href,
      result: r && {
        dialect: r.dialect,
        alarms: r.alarms,
        warnings: r.warnings,
        threads: r.threads.map((t) => ({ infeed: t.infeed, starts: t.starts, lead: t.lead, pitch: t.pitch, passes: t.passes })),
        passes: (r.passes || []).map((p) => ({ x: p.from[0], z: p.from[1], depth: p.depth, shift: p.shift, start: p.start })),
      },
    };
  }, id);

const waitReady = (id) =>
  page.waitForFunction((id) => ['ready', 'error'].includes(document.getElementById(id).dataset.state), id, { timeout: 20_000 });

/** The state an "Open in editor" link carries in its `#j=` fragment. */
function fromFragment(link) {
  const at = link.indexOf('#j=');
  return at < 0 ? null : JSON.parse(Buffer.from(link.slice(at + 3), 'base64url').toString('utf8'));
}

/** Two animation frames: the views draw on the next frame after a plan. */
const frames = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

try {
  await page.goto(`${base}docs.html`);
  await page.evaluate(() => customElements.whenDefined('screwcut-preview'));
  const ids = await page.evaluate(() => [...document.querySelectorAll('screwcut-preview')].map((e) => e.id));
  check(`docs.html has ${ids.length} embeds, every one with an id`, ids.length >= 10 && ids.every(Boolean), JSON.stringify(ids));

  // ---- lazy start: only embeds near the viewport start ----
  await page.waitForTimeout(500);
  const lazy = await page.evaluate(() =>
    [...document.querySelectorAll('screwcut-preview')].map((e) => ({ id: e.id, state: e.dataset.state, top: e.getBoundingClientRect().top, h: innerHeight })),
  );
  const far = lazy.filter((e) => e.top > e.h + 400);
  check(`the ${far.length} embeds far below the viewport have not started`, far.length >= 5 && far.every((e) => e.state === 'idle'), JSON.stringify(lazy));
  if (lazy.every((e) => e.state === 'idle')) check('no wasm is fetched before an embed comes near', wasmRequests.length === 0, JSON.stringify(wasmRequests));
  await page.locator(`#${ids[0]}`).scrollIntoViewIfNeeded();
  await waitReady(ids[0]);
  const after = await page.evaluate(() => [...document.querySelectorAll('screwcut-preview')].map((e) => e.dataset.state));
  check('scrolling to the first embed starts it, not the last', after[0] === 'ready' && after.at(-1) === 'idle', JSON.stringify(after));

  // ---- scroll through: every embed starts and draws ----
  const seen = {};
  for (const id of ids) {
    await page.locator(`#${id}`).scrollIntoViewIfNeeded();
    await waitReady(id).catch(() => {});
    await frames();
    const s = await inspect(id);
    seen[id] = s;
    const drawn = s.canvases.every((c) => c.n > 400 && c.w > 100 && c.h > 100);
    const table = s.rows.length > 0 || !(await page.evaluate((id) => !!document.getElementById(id).shadowRoot.querySelector('.view.table'), id));
    check(
      `${id}: ready and drawn (${s.canvases.map((c) => `${c.view} ${c.n} px`).join(', ')}${s.rows.length ? `, ${s.rows.length} table rows` : ''})`,
      s.state === 'ready' && drawn && s.canvases.length + (s.rows.length ? 1 : 0) > 0 && table,
      JSON.stringify({ state: s.state, summary: s.summary, canvases: s.canvases }),
    );
    check(`${id}: plans without an alarm`, s.result && s.result.alarms === 0, s.summary);
    const editable = await page.evaluate((id) => document.getElementById(id).hasAttribute('editable'), id);
    const hidden = await page.evaluate((id) => document.getElementById(id).hasAttribute('hide-code'), id);
    if (!editable && !hidden) check(`${id}: lists its program`, s.listing.length > 20 && s.listing + '\n' === s.program, JSON.stringify(s.listing.slice(0, 60)));
    await page.locator(`#${id}`).screenshot({ path: path.join(shots, `docs-${id}.png`) });
  }
  check('one wasm download served every embed', wasmRequests.length === 1, JSON.stringify(wasmRequests));

  // ---- what the page says each example does ----
  const loop = seen['macro-loop'];
  const lx = loop.result.passes.map((p) => p.x);
  check('the G65 macro loop: eleven passes, X29.4 … X28.05', lx.length === 11 && lx[0] === 29.4 && lx[10] === 28.05 && loop.rows.length === 11, JSON.stringify(lx));
  const o1006 = seen.o1006;
  check('O1006: five passes, the first at X47.1', o1006.rows.length === 5 && o1006.rows[0][2] === '47.1', JSON.stringify(o1006.rows[0]));
  check('the tooth-only O1006 embed has the same program, not listed', seen['o1006-tooth'].program === o1006.program && seen['o1006-tooth'].listing === '', seen['o1006-tooth'].listing);
  check('O1006: depths 0.45 … 1.3', JSON.stringify(o1006.result.passes.map((p) => p.depth)) === '[0.45,0.75,1.05,1.25,1.3]', JSON.stringify(o1006.result.passes));
  check('O0009: the 1 mm infeed warning is listed', seen.o0009.diagnostics.some((d) => d.startsWith('warning') && d.includes('infeed-too-large')), JSON.stringify(seen.o0009.diagnostics));
  const modes = ['g78-radial', 'g78-left', 'g78-right', 'g78-alternating'].map((id) => seen[id].result.threads[0].infeed);
  check('G78: radial, left, right and alternating infeed', JSON.stringify(modes) === '["radial","left","right","alternating"]', JSON.stringify(modes));
  const shifts = (id) => seen[id].result.passes.map((p) => p.shift);
  check('G78 r=1 shifts towards −Z, r=2 towards +Z, r=0 not at all', shifts('g78-left')[0] < -0.5 && shifts('g78-right')[0] > 0.5 && shifts('g78-radial').every((v) => v === 0), JSON.stringify([shifts('g78-left'), shifts('g78-right')]));
  const alt = shifts('g78-alternating');
  check('G78 r=3 alternates sides', alt[0] < 0 && alt[1] > 0 && alt[2] < 0 && alt[3] > 0, JSON.stringify(alt));
  check('G78 left flank: the Z start of pass 1 is 5 + 0.4·tan 30° (depth 0 at the start point)', seen['g78-left'].rows[0][3] === '5.2309', JSON.stringify(seen['g78-left'].rows[0]));
  const g76 = seen['g76-fanuc'].result;
  check('G76 planned as Fanuc: five passes to 3.68', g76.dialect === 'fanuc0i' && g76.passes.length === 5 && g76.passes[4].depth === 3.68, JSON.stringify(g76));
  const g92 = seen['g92-two-start'].result.threads[0];
  check('G92: two starts, lead 3, pitch 1.5', g92.starts === 2 && g92.lead === 3 && g92.pitch === 1.5, JSON.stringify(g92));
  check('Renhe: three threads, one per tail', seen['renhe-tails'].result.threads.length === 3, seen['renhe-tails'].summary);

  // ---- no global and no style leaked into the page ----
  // A fresh same-origin window (an about:blank frame) has the browser's own
  // globals and none of the page's: the difference is what scripts added.
  // No init script is involved, so it does not matter how often or where a
  // given Chromium runs them.
  const leak = await page.evaluate(() => {
    const frame = document.createElement('iframe');
    frame.style.display = 'none';
    document.body.append(frame);
    const before = new Set(Object.getOwnPropertyNames(frame.contentWindow));
    frame.remove();
    return {
      added: Object.getOwnPropertyNames(window).filter((k) => !before.has(k)),
      sheets: document.styleSheets.length,
      styleElements: document.querySelectorAll('style, link[rel="stylesheet"]').length,
      adopted: document.adoptedStyleSheets.length,
    };
  });
  check('the element adds no global', leak.added.length === 0, JSON.stringify(leak.added));
  check('the element adds no style to the page', leak.sheets === leak.styleElements && leak.adopted === 0, JSON.stringify(leak));

  // ---- the wheel scrolls the page over a drawing; hovering a pass shows it ----
  await page.locator('#o1006').scrollIntoViewIfNeeded();
  const canvasBox = await page.locator('#o1006 .view[data-view="side"] canvas').boundingBox();
  await page.mouse.move(canvasBox.x + canvasBox.width / 2, canvasBox.y + canvasBox.height / 2);
  const y0 = await page.evaluate(() => window.scrollY);
  await page.mouse.wheel(0, 240);
  await page.waitForTimeout(300);
  const y1 = await page.evaluate(() => window.scrollY);
  check('the wheel over a drawing scrolls the page', y1 > y0, `${y0} → ${y1}`);
  const before = await page.evaluate(() => document.getElementById('o1006')._views.side.transform().sx);
  // The drawing back in view (the scroll may have taken its middle out of it).
  await page.locator('#o1006 .view[data-view="side"] canvas').scrollIntoViewIfNeeded();
  await page.waitForTimeout(150);
  const y2 = await page.evaluate(() => window.scrollY);
  const box2 = await page.locator('#o1006 .view[data-view="side"] canvas').boundingBox();
  await page.mouse.move(box2.x + box2.width / 2, box2.y + box2.height / 2);
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -200);
  await page.keyboard.up('Control');
  await page.waitForTimeout(150);
  const zoom = await page.evaluate(() => ({ sx: document.getElementById('o1006')._views.side.transform().sx, y: window.scrollY }));
  check('Ctrl + wheel zooms the drawing instead', zoom.sx > before * 1.2 && zoom.y === y2, `${before} → ${zoom.sx}, scroll ${y2} → ${zoom.y}`);
  await page.evaluate(() => document.getElementById('o1006')._views.side.fit());
  await page.waitForTimeout(100);
  const at = await page.evaluate(() => {
    const el = document.getElementById('o1006');
    const v = el._views.side;
    const xf = v.transform();
    const q = el._session.locate('side', 'cut', new Float64Array([xf.sx, xf.sy, xf.tx, xf.ty]));
    const r = v.canvas.getBoundingClientRect();
    return { x: r.left + q[0], y: r.top + q[1] };
  });
  await page.mouse.move(at.x, at.y);
  await page.waitForTimeout(150);
  const tip = await page.evaluate(() => {
    const t = document.getElementById('o1006').shadowRoot.querySelector('.tip');
    return t.hidden ? '' : t.textContent;
  });
  check('hovering pass 1 shows its X and depth', tip.includes('X47.1') && tip.includes('0.45'), tip);
  const hot = await page.evaluate(() => [...document.getElementById('o1006').shadowRoot.querySelectorAll('tbody tr.hot')].map((tr) => tr.dataset.pass));
  check('and marks its row in the table', JSON.stringify(hot) === '["0"]', JSON.stringify(hot));
  const marked = await page.evaluate(() => [...document.getElementById('o1006').shadowRoot.querySelectorAll('pre.code span.hot')].map((s) => s.textContent));
  check('and its four blocks in the listing', marked.length === 4 && marked[0].startsWith('N30 X47.1') && marked[1].startsWith('N40 G32'), JSON.stringify(marked));
  await page.mouse.move(5, 5);

  // ---- attributes change a started embed ----
  const changed = await page.evaluate(async () => {
    const el = document.getElementById('g92-two-start');
    el.setAttribute('lang', 'zh');
    el.setAttribute('hide-code', '');
    el.setAttribute('view', 'starts table');
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const root = el.shadowRoot;
    return {
      captions: [...root.querySelectorAll('.cap')].map((c) => c.textContent),
      listing: !!root.querySelector('pre.code'),
      rows: root.querySelectorAll('tbody tr').length,
      link: root.querySelector('a.open').textContent,
    };
  });
  check('lang, hide-code and view apply to a started embed', JSON.stringify(changed.captions) === '["多头","走刀"]' && !changed.listing && changed.rows === 8 && changed.link.startsWith('在编辑器中打开'), JSON.stringify(changed));

  // ---- the editable embed re-plans as one types ----
  const editor = page.locator('#renhe-edit textarea');
  await editor.scrollIntoViewIfNeeded();
  check('renhe-edit: S1500 warns about the spindle speed', seen['renhe-edit'].diagnostics.some((d) => d.includes('spindle-speed') && d.includes('1473')), JSON.stringify(seen['renhe-edit'].diagnostics));
  const text = await editor.inputValue();
  check('the editor holds the program', text === seen['renhe-edit'].program && text.includes('G33 W-35 F1.5'), text.slice(0, 80));
  await editor.fill(text.replace('S1500', 'S1400'));
  await page.waitForFunction(() => document.getElementById('renhe-edit').result.warnings === 0, null, { timeout: 5000 }).catch(() => {});
  const calm = await inspect('renhe-edit');
  check('S1400 clears the warning', calm.result.warnings === 0 && calm.diagnostics.length === 0, JSON.stringify(calm.diagnostics));
  // Delete the line "G00 X34" (line 5), as the page suggests: no X feed before the thread.
  await editor.click();
  await page.keyboard.press('Control+Home');
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Home');
  await page.keyboard.press('Shift+End');
  await page.keyboard.press('Backspace');
  await page.keyboard.press('Backspace');
  await page.waitForFunction(() => document.getElementById('renhe-edit').result.alarms > 0, null, { timeout: 5000 }).catch(() => {});
  await frames();
  const alarm = await inspect('renhe-edit');
  check('without the X feed the G33, now on line 5, is alarm E18-05', !alarm.program.includes('G00 X34') && alarm.diagnostics.some((d) => d.startsWith('error') && d.includes('5:1') && d.includes('E18-05')), JSON.stringify(alarm.diagnostics));
  check('the last good drawing stays, greyed', alarm.canvases[0].n > 200 && alarm.summary.includes('Alarm'), `${alarm.canvases[0].n} px, ${alarm.summary}`);
  await page.locator('#renhe-edit').screenshot({ path: path.join(shots, 'docs-renhe-edit-alarm.png') });
  const carried = fromFragment(alarm.link);
  check('the link carries the edited program', carried && carried.program === (await editor.inputValue()) && carried.dialect === 'renhe', JSON.stringify(carried));

  // ---- "Open in editor" opens the app with the same program ----
  for (const id of ['o1006', 'g76-fanuc']) {
    const link = page.locator(`#${id} a.open`);
    await link.scrollIntoViewIfNeeded();
    const [app] = await Promise.all([context.waitForEvent('page'), link.click()]);
    await app.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
    const got = await app.evaluate(() => ({ text: window.__screwcut.text(), dialect: window.__screwcut.dialect(), rows: document.querySelectorAll('#passes tbody tr').length, url: location.href }));
    const want = seen[id];
    check(`${id}: "Open in editor" opens the app with the same program`, got.text === want.program, `${JSON.stringify(got.text.slice(0, 60))} vs ${JSON.stringify(want.program.slice(0, 60))}`);
    check(`${id}: … in the same dialect, planned the same`, got.dialect === want.result.dialect && got.rows === want.result.passes.length, JSON.stringify({ got: [got.dialect, got.rows], want: want.result.dialect }));
    check(`${id}: the app is the one next to the element script`, got.url.startsWith(base) && !got.url.includes('docs.html'), got.url);
    if (id === 'o1006') await app.screenshot({ path: path.join(shots, 'docs-open-in-editor.png') });
    await app.close();
  }

  // ---- a static drawing inside an element (screwcut svg's output) shows until the live one ----
  // It shows every view of the element (one side section): the element waits for the reader.
  await page.evaluate(() => {
    const svg =
      '<svg xmlns="http://www.w3.org/2000/svg" width="300" height="120" viewBox="0 0 300 120"><title>screwcut: side section</title><rect width="300" height="120" fill="#eee"/><text x="10" y="60">static</text></svg>';
    const program = 'G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\n';
    for (const [id, attrs] of [
      ['with-fallback', {}],
      ['with-fallback-live', { live: '' }],
      ['with-fallback-table', { view: 'side table' }],
    ]) {
      const el = document.createElement('screwcut-preview');
      el.id = id;
      el.setAttribute('view', 'side');
      for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
      el.innerHTML = program + svg;
      document.body.append(el);
    }
  });
  const staticBefore = await page.evaluate(() => {
    const el = document.getElementById('with-fallback');
    return { state: el.dataset.state, program: el.program, h: el.querySelector('svg').getBoundingClientRect().height };
  });
  check('before it starts, the static drawing placed inside shows', staticBefore.state === 'idle' && staticBefore.h > 100, JSON.stringify(staticBefore));
  check('… and is not read as G-code', staticBefore.program === 'G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\nX46.5\nG32 Z13\nG00 X58\n', JSON.stringify(staticBefore.program));
  const staticState = (id) =>
    page.evaluate((id) => {
      const el = document.getElementById(id);
      return { state: el.dataset.state, svgH: el.querySelector('svg').getBoundingClientRect().height, sum: el.shadowRoot.querySelector('.sum').textContent };
    }, id);
  for (const id of ['with-fallback-live', 'with-fallback-table']) {
    await page.locator(`#${id}`).scrollIntoViewIfNeeded();
    await waitReady(id).catch(() => {});
    check(`${id}: an element with \`live\`, or a view the static drawing lacks (the table), plans once scrolled near`, (await staticState(id)).state === 'ready', JSON.stringify(await staticState(id)));
  }
  await page.locator('#with-fallback').scrollIntoViewIfNeeded();
  await page.mouse.move(2, 2);
  await page.waitForTimeout(600);
  await frames();
  const waiting = await staticState('with-fallback');
  check(
    'scrolled to, an element whose static drawing shows all its views waits for the reader, and says so',
    waiting.state === 'idle' && waiting.svgH > 100 && waiting.sum === 'Static drawing · point at it for the live one',
    JSON.stringify(waiting),
  );
  await page.locator('#with-fallback').screenshot({ path: path.join(shots, 'docs-static-waiting.png') });
  await page.locator('#with-fallback').hover();
  await waitReady('with-fallback').catch(() => {});
  await frames();
  const staticAfter = await inspect('with-fallback');
  const hidden = await page.evaluate(() => document.getElementById('with-fallback').querySelector('svg').getBoundingClientRect().height);
  check('pointed at, it plans: the live drawing takes its place', staticAfter.state === 'ready' && staticAfter.canvases[0].n > 400 && hidden === 0, JSON.stringify({ state: staticAfter.state, px: staticAfter.canvases[0].n, hidden }));
  await page.evaluate(() => {
    const el = document.createElement('screwcut-preview');
    el.id = 'with-fallback-focus';
    el.innerHTML = 'G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\n<svg xmlns="http://www.w3.org/2000/svg" width="300" height="120" viewBox="0 0 300 120"><rect width="300" height="120" fill="#eee"/></svg>';
    document.body.append(el);
  });
  await page.locator('#with-fallback-focus').scrollIntoViewIfNeeded();
  await page.waitForTimeout(300);
  const beforeFocus = (await staticState('with-fallback-focus')).state;
  await page.locator('#with-fallback-focus').evaluate((el) => el.shadowRoot.querySelector('a.open').focus());
  await waitReady('with-fallback-focus').catch(() => {});
  check('… and so does one reached with the keyboard (focus on its link)', beforeFocus === 'idle' && (await staticState('with-fallback-focus')).state === 'ready', beforeFocus);

  // ---- the element's documentation exists once: the page links to its README ----
  const readme = await page.evaluate(() => document.getElementById('element-readme').href);
  const readmeText = await (await fetch(readme)).text();
  check("the page links to the element's README, which documents every attribute", readmeText.includes('## Attributes') && readmeText.includes('`hide-code`') && readmeText.includes('## In mdBook'), readme);

  // ---- the site as a static host serves it: precompressed, revalidated ----
  const wasmUrl = new URL('screwcut_bg.wasm', base).href;
  const plain = await fetch(wasmUrl, { headers: { 'accept-encoding': 'identity' } });
  const plainBytes = (await plain.arrayBuffer()).byteLength;
  const zipped = await fetch(wasmUrl, { headers: { 'accept-encoding': 'gzip' } });
  const zippedBytes = (await zipped.arrayBuffer()).byteLength;
  check(
    'the wasm is served gzip-encoded to a browser that accepts it, the same bytes decoded',
    zipped.headers.get('content-encoding') === 'gzip' && plain.headers.get('content-encoding') === null && zippedBytes === plainBytes && plainBytes > 100000,
    JSON.stringify({ enc: zipped.headers.get('content-encoding'), plainBytes, zippedBytes }),
  );
  const brotli = await fetch(wasmUrl, { headers: { 'accept-encoding': 'gzip, deflate, br' } });
  const brotliBytes = (await brotli.arrayBuffer()).byteLength;
  // The bytes on the wire, not decoded (node:http leaves the body as sent).
  const wire = (encoding) =>
    new Promise((resolve, reject) => {
      http.get(wasmUrl, { headers: { 'accept-encoding': encoding } }, (res) => {
        let n = 0;
        res.on('data', (c) => (n += c.length));
        res.on('end', () => resolve(n));
      }).on('error', reject);
    });
  const brotliLength = await wire('br');
  const gzipLength = await wire('gzip');
  check(
    '… and Brotli-encoded, preferred, to one that accepts both: smaller than the gzip, the same bytes decoded',
    brotli.headers.get('content-encoding') === 'br' && brotliBytes === plainBytes && brotliLength > 0 && brotliLength < gzipLength,
    JSON.stringify({ enc: brotli.headers.get('content-encoding'), brotliBytes, brotliLength, gzipLength }),
  );
  const tag = zipped.headers.get('etag');
  const tagged = await fetch(wasmUrl, { headers: { 'if-none-match': tag || '' } });
  check('… with an ETag: asked again with it, 304 and no body', Boolean(tag) && tagged.status === 304, JSON.stringify({ tag, status: tagged.status }));
  const date = zipped.headers.get('last-modified');
  const again = await fetch(wasmUrl, { headers: { 'if-modified-since': date || '' } });
  const againBytes = (await again.arrayBuffer()).byteLength;
  check(
    '… with its date (Last-Modified): asked again with it, 304 and no body',
    Boolean(date) && again.status === 304 && againBytes === 0,
    JSON.stringify({ date, status: again.status, againBytes }),
  );

  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(shots, 'docs-page.png'), fullPage: true });
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the docs test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}

finish('docs page', counts);
